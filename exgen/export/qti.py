"""IMS QTI 2.1 content package: a zip of one assessmentItem per variant, an assessmentTest that picks
one variant of each question per candidate, and imsmanifest.xml. Math is MathML (exgen.export.html);
the layouts qti_item.xml.j2, qti_test.xml.j2 and qti_manifest.xml.j2 hold every format detail."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .html import MATHML_XHTML, render
from .pool import Item, Pool, make_item
from .zips import write_zip

TEST = "test.xml"
ITEMS = "items/"
IMAGES = "images/"  # beside the items, so an item refers to its figure as images/NAME


@dataclass(frozen=True)
class GapRef:
    """A gap as the item writes it: its response identifier, points and mistake feedback identifiers."""

    part: object
    gap: object
    rid: str
    points: float
    choice_ids: dict
    wrong: tuple


@dataclass(frozen=True)
class WrongRef:
    wrong: object
    fid: str


def gap_refs(item: Item) -> list[GapRef]:
    out = []
    for part in item.exported_parts:
        for gap in part.gaps:
            rid = f"R_{part.id}" + (f"_{gap.key}" if gap.key else "")
            choice_ids = {c: f"{rid}_C{i}" for i, c in enumerate(getattr(gap, "choices", ()), start=1)}
            wrong = tuple(WrongRef(w, f"{rid}_{w.name}") for w in gap.wrong)
            out.append(GapRef(part, gap, rid, float(part.points * gap.share), choice_ids, wrong))
    return out


def item_xml(item: Item) -> str:
    return render("qti_item.xml.j2", item=item, gaps=gap_refs(item), src=IMAGES).lstrip()


def qti_files(pool: Pool) -> dict[str, bytes]:
    """Every file of the package, by its path in the zip."""
    files: dict[str, bytes] = {}
    sections, listed = [], []
    for question in pool.questions:
        items = [make_item(question, i, v, MATHML_XHTML, IMAGES) for i, v in enumerate(question.variants, 1)]
        items = [item for item in items if item.gaps]
        if not items:
            continue
        refs = []
        for item in items:
            href = f"{ITEMS}{item.ident}.xml"
            files[href] = item_xml(item).encode("utf-8")
            figures = ([item.figure] if item.figure else []) + list(item.key_figures)
            for figure in figures:
                files[f"{ITEMS}{IMAGES}{figure.name}"] = figure.data
            refs.append({"ident": item.ident, "href": href,
                         "files": [f"{ITEMS}{IMAGES}{f.name}" for f in figures]})
        sections.append({"ident": f"S-{items[0].ident.rsplit('-', 1)[0]}",
                         "title": f"{question.slot}: {question.template.title}", "refs": refs})
        listed += refs
    ident = f"exgen-{pool.scope}"
    files[TEST] = render("qti_test.xml.j2", ident=ident, title=pool.title, sections=sections).lstrip().encode("utf-8")
    manifest = render("qti_manifest.xml.j2", ident=ident, test_href=TEST, items=listed).lstrip()
    return {"imsmanifest.xml": manifest.encode("utf-8"), **files}


def write_qti(pool: Pool, path: Path) -> Path:
    return write_zip(qti_files(pool), path)
