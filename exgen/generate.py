"""Issue an assignment: a sheet, an answer form and a key per student, and a manifest.

Every sheet is drawn before anything is written, so a template that cannot be drawn stops
the run with nothing half-written. Student files and keys go to separate folders so the
`students/` folder can be handed out as it is.

    OUT/students/<id>/sheet.md, sheet.pdf, answers.yaml, q1.svg ...
    OUT/keys/<id>/key.md, key.pdf, q1.svg ...
    OUT/manifest.json
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

from .assignment import Assignment, Sheet, Student, build_sheet
from .bank import Bank
from .manifest import build_manifest, write_manifest

Progress = Callable[[Iterable, int, str], Iterable]


def _no_progress(items, total, label):
    return items


@dataclass(frozen=True)
class Issued:
    out: Path
    sheets: tuple[Sheet, ...]
    manifest: Path


def draw_sheets(assignment: Assignment, students: list[Student], bank: Bank, secret: bytes,
                progress: Progress = _no_progress) -> list[Sheet]:
    return [build_sheet(assignment, s, bank, secret) for s in progress(students, len(students), "drawing")]


def write_figures(sheet: Sheet, folder: Path) -> dict[str, str]:
    """Each question's figure as an SVG file in `folder`; returns slot -> file name."""
    from .figures import figure_svg

    files = {}
    for question in sheet.questions:
        svg = figure_svg(question.variant)
        if svg:
            name = f"{question.slot}.svg"
            (folder / name).write_text(svg, encoding="utf-8")
            files[question.slot] = name
    return files


def write_student(sheet: Sheet, out: Path, pdf: bool = True) -> None:
    """The student's folder (sheet, form, figures) and the instructor's key folder."""
    from graders.answers import answer_form

    from .render.markdown import key_markdown, sheet_markdown

    student_dir = out / "students" / sheet.student.id
    key_dir = out / "keys" / sheet.student.id
    for folder in (student_dir, key_dir):
        folder.mkdir(parents=True, exist_ok=True)
    figures = write_figures(sheet, student_dir)
    write_figures(sheet, key_dir)
    (student_dir / "sheet.md").write_text(sheet_markdown(sheet, figures), encoding="utf-8")
    (student_dir / "answers.yaml").write_text(answer_form(sheet), encoding="utf-8")
    (key_dir / "key.md").write_text(key_markdown(sheet, figures), encoding="utf-8")
    if pdf:
        from .render.pdf import key_pdf, sheet_pdf

        (student_dir / "sheet.pdf").write_bytes(sheet_pdf(sheet))
        (key_dir / "key.pdf").write_bytes(key_pdf(sheet))


def generate(assignment: Assignment, students: list[Student], bank: Bank, secret: bytes, out: Path,
             *, pdf: bool = True, progress: Progress = _no_progress) -> Issued:
    sheets = draw_sheets(assignment, students, bank, secret, progress)
    out.mkdir(parents=True, exist_ok=True)
    for sheet in progress(sheets, len(sheets), "writing"):
        write_student(sheet, out, pdf)
    manifest_path = out / "manifest.json"
    write_manifest(build_manifest(assignment, sheets, bank, secret), manifest_path)
    return Issued(out, tuple(sheets), manifest_path)
