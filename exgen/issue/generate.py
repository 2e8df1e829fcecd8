"""Issue an assignment: a sheet, an answer form and a key per student, and a manifest.

Every sheet is drawn before anything is written, and everything is written into a folder that
replaces the output folder only when complete, so an error or an interruption leaves the previous
output whole and no stale files (another roster's students, an old PDF) survive a rerun. Student
files and keys go to separate folders so the `students/` folder can be handed out as it is.

    OUT/students/<id>/sheet.md, sheet.pdf, answers.yaml, q1.svg ...
    OUT/keys/<id>/key.md, key.pdf, q1.svg ...
    OUT/manifest.json
    OUT/print/sheets.pdf, keys.pdf      (with print=True: every sheet and every key, in roster order)
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from ..load.bank import Bank
from ..render.answer_form import answer_form
from ..runtime import parallel
from ..runtime.allocator import faster_allocator
from ..runtime.outdir import check_target, replacing
from ..runtime.progress import Progress, silent
from .assignment import Assignment, Sheet, Student, build_sheet
from .manifest import MANIFEST, build_manifest, write_manifest

KIND = "generate"  # the marker an issued folder carries (exgen.runtime.outdir)


@dataclass(frozen=True)
class Issued:
    out: Path
    sheets: tuple[Sheet, ...]
    manifest: Path


def draw_sheets(assignment: Assignment, students: list[Student], bank: Bank, secret: bytes,
                progress: Progress = silent) -> list[Sheet]:
    return [build_sheet(assignment, s, bank, secret) for s in progress(students, len(students), "drawing")]


def write_figures(sheet: Sheet, student_dir: Path, key_dir: Path):
    """Each question's figures, drawn once: the sheet's figure as an SVG file in both folders, a
    key-only figure in the key's folder alone. Returns the drawn figures for the renderers."""
    from ..figures import draw_figures

    figures = draw_figures(sheet)
    for drawn in figures.values():
        if drawn.sheet:
            for folder in (student_dir, key_dir):
                (folder / drawn.sheet.name).write_text(drawn.sheet.svg, encoding="utf-8")
        for figure in drawn.key:
            (key_dir / figure.name).write_text(figure.svg, encoding="utf-8")
    return figures


def write_student(sheet: Sheet, out: Path, pdf: bool = True, key_pdf: bool = True) -> None:
    """The student's folder (sheet, form, figures) and the instructor's key folder; `key_pdf` False
    leaves the key in Markdown only (its PDF costs most of a sheet's time)."""
    from ..render.markdown import key_markdown, sheet_markdown

    student_dir = out / "students" / sheet.student.id
    key_dir = out / "keys" / sheet.student.id
    for folder in (student_dir, key_dir):
        folder.mkdir(parents=True, exist_ok=True)
    figures = write_figures(sheet, student_dir, key_dir)
    (student_dir / "sheet.md").write_text(sheet_markdown(sheet, figures), encoding="utf-8")
    (student_dir / "answers.yaml").write_text(answer_form(sheet), encoding="utf-8")
    (key_dir / "key.md").write_text(key_markdown(sheet, figures), encoding="utf-8")
    if pdf:
        from ..render.pdf import key_pdf as make_key_pdf, sheet_pdf

        (student_dir / "sheet.pdf").write_bytes(sheet_pdf(sheet, figures))
        if key_pdf:
            (key_dir / "key.pdf").write_bytes(make_key_pdf(sheet, figures))


def _write_in_worker(student: Student) -> str:
    """Rebuild one sheet from its inputs (drawing is pure and cheap) and write its files."""
    assignment, bank, secret, out, pdf, key_pdf = parallel.shared()
    write_student(build_sheet(assignment, student, bank, secret), out, pdf, key_pdf)
    return student.id


def default_jobs() -> int:
    return max(1, min(8, os.cpu_count() or 1))


def generate(assignment: Assignment, students: list[Student], bank: Bank, secret: bytes, out: Path,
             *, pdf: bool = True, key_pdf: bool = True, jobs: int = 1, progress: Progress = silent,
             secret_source: str = "", print_bundle: bool = False) -> Issued:
    """Draw every sheet, then write them into a folder beside `out` that replaces it only when complete
    (exgen.runtime.outdir); with jobs > 1 the PDFs are made in that many processes, which start first and rebuild
    their sheets themselves while this one draws every sheet for the manifest (Markdown alone is made in
    this one: starting processes would cost more than it saves)."""
    out = Path(out)
    check_target(out, KIND)  # before the slow part: a folder that cannot be replaced stops the run now
    with replacing(out, KIND) as folder:
        if pdf and jobs > 1 and len(students) > 1:
            with parallel.pool(min(jobs, len(students)), (assignment, bank, secret, folder, pdf, key_pdf),
                               preload=faster_allocator()) as workers:
                written = workers.map(_write_in_worker, students, chunksize=2)
                sheets = draw_sheets(assignment, students, bank, secret, progress)
                manifest = build_manifest(assignment, sheets, bank, secret, secret_source)
                for _ in progress(written, len(sheets), "writing"):
                    pass
        else:
            sheets = draw_sheets(assignment, students, bank, secret, progress)
            manifest = build_manifest(assignment, sheets, bank, secret, secret_source)
            for sheet in progress(sheets, len(sheets), "writing"):
                write_student(sheet, folder, pdf, key_pdf)
        if print_bundle and pdf:
            from ..render.bundle import write_bundles

            write_bundles(folder, [s.student.id for s in sheets], keys=key_pdf)
        write_manifest(manifest, folder / MANIFEST)
    return Issued(out, tuple(sheets), out / MANIFEST)
