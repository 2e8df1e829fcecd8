"""Gradebooks a learning system imports as they are, besides exgen's own: Canvas's gradebook CSV,
Moodle's grade import CSV, and a CSV with a column per part.

Students are matched by what the roster gives (id as the SIS user ID or Moodle ID number, email as
the login or email address). A student who handed nothing in, or whose file could not be graded, has
no row in the Canvas and Moodle gradebooks: both imports leave a student without a row as they were,
while a blank cell would clear a grade already there (Canvas posts it as a removal, Moodle stores it
as "no grade"). exgen's own gradebook.csv and parts.csv list everyone, blank where nothing was graded,
and the report says why.
"""
from __future__ import annotations

import csv
import re
from pathlib import Path

from .results import GRADED, BatchResult, SheetResult

CANVAS_STUDENT_COLUMNS = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
CANVAS_POINTS_ROW = "Points Possible"
MOODLE_COLUMNS = ["ID number", "Email address", "First name", "Last name"]
_SPREADSHEET_FORMULA = ("=", "+", "-", "@", "\t", "\r")
_DIGITS = re.compile(r"\A\d+\Z")


def cell(text: str) -> str:
    """Text a spreadsheet will not run as a formula."""
    return "'" + text if text.startswith(_SPREADSHEET_FORMULA) else text


def points(value: float) -> str:
    return f"{value:.2f}".rstrip("0").rstrip(".") if value else "0"


def mark(sheet: SheetResult) -> str:
    """The sheet's points, or blank when nothing was graded (no file, an unreadable or refused one)."""
    return points(sheet.points) if sheet.status == GRADED else ""


def graded(batch: BatchResult) -> list[SheetResult]:
    """The sheets a learning system's gradebook is given: those graded. Anyone else's row is left out,
    so that importing it keeps the grade they have."""
    return [sheet for sheet in batch.sheets if sheet.status == GRADED]


def canvas_column(title: str, canvas_id: str = "") -> str:
    """Canvas reads "Title (id)" as an existing assignment; a title alone makes a new one on import."""
    return f"{title} ({canvas_id})" if canvas_id else title


def write_canvas_gradebook(batch: BatchResult, path: Path, canvas_id: str = "") -> None:
    """Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID, Section, then the assignment,
    with a Points Possible row; a row per graded student. Canvas matches a row by its ID, else SIS User
    ID, else SIS Login ID."""
    if canvas_id and not _DIGITS.match(canvas_id):
        raise ValueError(f"a Canvas assignment id is a number, not {canvas_id!r}")
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(CANVAS_STUDENT_COLUMNS + [canvas_column(batch.assignment.title, canvas_id)])
        writer.writerow([CANVAS_POINTS_ROW, "", "", "", "", points(batch.max_points)])
        for sheet in graded(batch):
            s = sheet.student
            writer.writerow([cell(s.name or s.id), "", cell(s.id), cell(s.email), cell(s.section), mark(sheet)])


def write_moodle_grades(batch: BatchResult, path: Path) -> None:
    """Moodle's grade import (Grades > Import > CSV file), a row per graded student: map "ID number" to
    the user's ID number, or "Email address" to the email address, and the assignment's column to its
    grade item."""
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(MOODLE_COLUMNS + [batch.assignment.title])
        for sheet in graded(batch):
            s = sheet.student
            first, _, last = (s.name or "").partition(" ")
            writer.writerow([cell(s.id), cell(s.email), cell(first), cell(last), mark(sheet)])


def write_parts(batch: BatchResult, path: Path) -> None:
    """A column per part of every question ("q1 (a) /2"), the total and the status; blank where nothing
    was graded."""
    layout = []
    for column in batch.columns:
        sample = next((q for s in batch.sheets for q in s.questions if q.slot == column.slot), None)
        layout += [(column.slot, p.part_id, p.max_points) for p in (sample.parts if sample else ())]
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["student", "name"] + [f"{slot} ({part}) /{points(m)}" for slot, part, m in layout]
                        + [f"total /{points(batch.max_points)}", "status"])
        for sheet in batch.sheets:
            row = [cell(sheet.student.id), cell(sheet.student.name)]
            for slot, part_id, _ in layout:
                question = sheet.question(slot)
                part = next((p for p in question.parts if p.part_id == part_id), None) if question else None
                row.append(points(part.points) if part and sheet.status == GRADED else "")
            writer.writerow(row + [mark(sheet), sheet.status])
