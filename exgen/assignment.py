"""Assignments, rosters and the per-student sheets they produce.

An assignment file names the problems (templates) in order; a roster lists students. Each
student's sheet draws every problem from a seed derived from the course secret, so the
same sheet can be rebuilt at grading time from the same three inputs.
"""
from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from .bank import Bank
from .errors import AssignmentError, ExgenError
from .seeds import derive_seed, sheet_code
from .variant import Variant, make_variant

ASSIGNMENT_KEYS = {"assignment", "title", "course", "due", "instructions", "secret_file", "questions", "roster"}
QUESTION_KEYS = {"template", "slot", "points"}
_SAFE_ID = re.compile(r"\A[A-Za-z0-9][A-Za-z0-9._-]{0,63}\Z")


@dataclass(frozen=True)
class QuestionSpec:
    slot: str
    template: str
    points: float | None = None  # None: the template's own part points


@dataclass(frozen=True)
class Assignment:
    id: str
    title: str
    questions: tuple[QuestionSpec, ...]
    course: str = ""
    due: str = ""
    instructions: str = ""
    secret_file: Path | None = None
    roster: Path | None = None
    path: Path | None = None


@dataclass(frozen=True)
class Student:
    id: str
    name: str = ""
    email: str = ""
    section: str = ""


@dataclass(frozen=True)
class Question:
    number: int
    slot: str
    variant: Variant
    points: float  # what the question is worth on this sheet

    @property
    def scale(self) -> float:
        """Factor from the template's part points to this sheet's points."""
        return self.points / self.variant.template.points


@dataclass(frozen=True)
class Sheet:
    assignment: Assignment
    student: Student
    code: str
    questions: tuple[Question, ...] = field(default=())

    @property
    def points(self) -> float:
        return sum(q.points for q in self.questions)


def load_assignment(path: Path, bank: Bank | None = None) -> Assignment:
    """Read an assignment file; with a bank, also check every template id exists."""
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise AssignmentError(path, "no such file") from None
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as exc:
        raise AssignmentError(path, f"cannot read: {exc}") from exc
    if not isinstance(data, dict):
        raise AssignmentError(path, "must be a mapping with `assignment:` and `questions:`")
    problems = [f"unknown key {k!r}" for k in data if k not in ASSIGNMENT_KEYS]
    assignment_id = str(data.get("assignment", ""))
    if not _SAFE_ID.match(assignment_id):
        problems.append("`assignment:` must be an id of letters, digits, '.', '_' or '-' (it seeds every sheet)")
    questions, slots = [], set()
    for i, item in enumerate(data.get("questions") or [], start=1):
        item = {"template": item} if isinstance(item, str) else item
        if not isinstance(item, dict) or "template" not in item:
            problems.append(f"questions[{i}]: needs `template:`")
            continue
        problems += [f"questions[{i}]: unknown key {k!r}" for k in item if k not in QUESTION_KEYS]
        slot = str(item.get("slot", f"q{i}"))
        if not _SAFE_ID.match(slot):
            problems.append(f"questions[{i}]: slot {slot[:40]!r} must be letters, digits, '.', '_' or '-', "
                            "starting with a letter or digit (it names the question's files)")
        if slot in slots:
            problems.append(f"questions[{i}]: slot {slot!r} used twice")
        slots.add(slot)
        points = item.get("points")
        if points is not None and not _positive_number(points):
            problems.append(f"questions[{i}]: points must be a positive, finite number (got {str(points)[:20]})")
            points = None
        if bank is not None:
            try:
                bank.get(str(item["template"]))
            except ExgenError as exc:
                problems.append(f"questions[{i}]: {exc}")
        questions.append(QuestionSpec(slot, str(item["template"]), float(points) if points else None))
    if not questions:
        problems.append("`questions:` lists no templates")
    if problems:
        raise AssignmentError(path, "; ".join(problems))
    base = path.parent
    return Assignment(
        id=assignment_id, title=str(data.get("title") or assignment_id), questions=tuple(questions),
        course=str(data.get("course", "")), due=str(data.get("due", "")),
        instructions=str(data.get("instructions", "")).strip(),
        secret_file=base / data["secret_file"] if data.get("secret_file") else None,
        roster=base / data["roster"] if data.get("roster") else None, path=path,
    )


def _positive_number(value) -> bool:
    """True for 3 or 2.5; False for 0, -1, .nan, .inf, true and text."""
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value > 0


def load_roster(path: Path) -> list[Student]:
    """Students from a CSV with an `id` column (and optional name, email, section)."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise AssignmentError(path, "no such roster file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise AssignmentError(path, f"cannot read roster: {exc}") from exc
    reader = csv.DictReader(io.StringIO(text))
    fields = [f.strip().lower() for f in reader.fieldnames or []]
    if "id" not in fields:
        raise AssignmentError(path, f"the roster needs an `id` column (found: {', '.join(fields) or 'nothing'})", 1)
    students, seen = [], set()
    for line, row in enumerate(reader, start=2):
        row = {(k or "").strip().lower(): (v or "").strip() for k, v in row.items()}
        if not any(row.values()):
            continue
        sid = row.get("id", "")
        if not _SAFE_ID.match(sid):
            raise AssignmentError(path, f"student id {sid!r} must be letters, digits, '.', '_' or '-' (it names files)", line)
        if sid in seen:
            raise AssignmentError(path, f"student id {sid!r} appears twice", line)
        seen.add(sid)
        students.append(Student(sid, row.get("name", ""), row.get("email", ""), row.get("section", "")))
    if not students:
        raise AssignmentError(path, "the roster lists no students")
    return students


def build_sheet(assignment: Assignment, student: Student, bank: Bank, secret: bytes) -> Sheet:
    """One student's sheet: every question drawn from its HMAC seed."""
    questions = []
    for number, spec in enumerate(assignment.questions, start=1):
        template = bank.get(spec.template)
        variant = make_variant(template, derive_seed(secret, assignment.id, student.id, spec.slot))
        questions.append(Question(number, spec.slot, variant, spec.points or template.points))
    code = sheet_code(secret, assignment.id, student.id, [f"{q.slot}={q.variant.template.id}" for q in questions])
    return Sheet(assignment, student, code, tuple(questions))
