"""Canvas: a QTI 1.2 zip as Canvas imports it (its qti_exporter reads the `question_type` metadata).

Classic Quizzes have no question with several numeric blanks, so each gap of each part is its own
question, carrying the whole statement, in a question group that draws one of the N variants per
student: a student answers each part from that part's own variant. The layouts canvas_*.j2 hold every
format detail.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from markupsafe import Markup

from .html import CANVAS_HTML, render
from .pool import Pool, make_item
from .zips import write_zip

IMAGES = "images/"
#: How Canvas's importer finds a file of the package from HTML (the token is URL-encoded in attributes).
FILEBASE = "%24IMS-CC-FILEBASE%24/"
#: A choice's identifier, unique within its question. Canvas's QTI 1.2 converter rewrites the idents of
#: choices (a '.' or ':' becomes '_', a trailing "_ans" or "_str" is cut) but not the values its response
#: conditions compare them with, so an ident must be one it leaves as it is: letters, digits and '-', and
#: no word canvas-lms reads as the question's own feedback ("correct", "wrong", "general_", "_all").
CHOICE_ID = "C{number}"


@dataclass(frozen=True)
class CanvasQuestion:
    ident: str
    title: str
    html: Markup
    solution: Markup
    gap: object
    answer_ids: list
    choice_ids: dict


@dataclass(frozen=True)
class Group:
    ident: str
    title: str
    points: float
    questions: list


def groups(pool: Pool) -> tuple[list[Group], dict[str, bytes]]:
    """The question groups, and the images (zip path -> bytes) their questions show."""
    out, images = [], {}
    for question in pool.questions:
        items = [make_item(question, i, v, CANVAS_HTML, FILEBASE + IMAGES) for i, v in enumerate(question.variants, 1)]
        items = [item for item in items if item.gaps]
        if not items:
            continue
        by_gap: dict[tuple[str, str], Group] = {}
        for item in items:
            for figure in ([item.figure] if item.figure else []) + list(item.key_figures):
                images[IMAGES + figure.name] = figure.data
            for part in item.exported_parts:
                for gap in part.gaps:
                    key = (part.id, gap.key)
                    suffix = f"{part.id}" + (f"-{gap.key}" if gap.key else "")
                    if key not in by_gap:
                        title = f"{question.slot} ({part.id}){' ' + gap.label if gap.label else ''}: {question.template.title}"
                        by_gap[key] = Group(f"{items[0].ident.rsplit('-', 1)[0]}-{suffix}", title,
                                            float(part.points * gap.share), [])
                    ident = f"{item.ident}-{suffix}"
                    choice_ids = {c: CHOICE_ID.format(number=i) for i, c in enumerate(getattr(gap, "choices", ()), start=1)}
                    answer_ids = list(choice_ids.values()) or [f"{ident}-A{i}" for i in range(1, len(gap.values) + 1)]
                    html = Markup(render("canvas_question.html.j2", item=item, part=part, gap=gap, src=FILEBASE + IMAGES))
                    by_gap[key].questions.append(CanvasQuestion(ident, f"{item.name} ({suffix})", html, item.solution,
                                                                gap, answer_ids, choice_ids))
        out += list(by_gap.values())
    return out, images


def canvas_files(pool: Pool) -> dict[str, bytes]:
    ident = f"exgen-{pool.scope}"
    found, images = groups(pool)
    points = sum(g.points for g in found)
    description = CANVAS_HTML.text(f"{pool.title}: problems drawn by exgen; each part comes from its own variant.")
    files = {
        "imsmanifest.xml": render("canvas_manifest.xml.j2", ident=ident, images=list(images)).lstrip().encode("utf-8"),
        "non_cc_assessments/": b"",
        f"{ident}/{ident}.xml": render("canvas_assessment.xml.j2", ident=ident, title=pool.title,
                                       groups=found).lstrip().encode("utf-8"),
        f"{ident}/assessment_meta.xml": render("canvas_meta.xml.j2", ident=ident, title=pool.title, points=points,
                                               description=description).lstrip().encode("utf-8"),
    }
    return {**files, **images}


def write_canvas(pool: Pool, path: Path) -> Path:
    return write_zip(canvas_files(pool), path)
