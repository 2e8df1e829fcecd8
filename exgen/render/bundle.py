"""One PDF of every sheet in roster order, and one of every key, for printing a class set.

The students' PDFs are joined as they are (pypdf), so a bundle's pages are the very pages each student
was given. For printing on both sides, a sheet with an odd number of pages is followed by a blank page,
so every student's sheet starts on a new leaf and no two students share one. A bundle is for printing:
the sheets' answer forms (every student's named alike, empty, printing nothing) are left out.
"""
from __future__ import annotations

from pathlib import Path

BUNDLE = "print"
SHEETS, KEYS = "sheets.pdf", "keys.pdf"


def join_pdfs(paths: list[Path], out: Path, duplex: bool = True) -> int:
    """`paths` joined into `out`, each padded to an even page count when `duplex`; the pages written."""
    from pypdf import PdfReader, PdfWriter

    writer = PdfWriter()
    for path in paths:
        reader = PdfReader(path)
        writer.append(reader)
        if duplex and len(reader.pages) % 2:
            box = reader.pages[-1].mediabox
            writer.add_blank_page(width=float(box.width), height=float(box.height))
    writer.remove_annotations(subtypes="/Widget")
    writer.root_object.pop("/AcroForm", None)
    with out.open("wb") as handle:
        writer.write(handle)
    return len(writer.pages)


def write_bundles(folder: Path, student_ids: list[str], keys: bool = True) -> dict[str, Path]:
    """print/sheets.pdf and print/keys.pdf of an issued folder, in the order of `student_ids`
    (no keys.pdf when the keys were made without PDFs, `keys` False)."""
    target = folder / BUNDLE
    target.mkdir(exist_ok=True)
    join_pdfs([folder / "students" / s / "sheet.pdf" for s in student_ids], target / SHEETS)
    if not keys:
        return {"sheets": target / SHEETS}
    join_pdfs([folder / "keys" / s / "key.pdf" for s in student_ids], target / KEYS)
    return {"sheets": target / SHEETS, "keys": target / KEYS}
