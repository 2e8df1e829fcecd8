"""Assignments, rosters and the per-student sheets they produce.

An assignment file names the problems (templates) in order; a roster lists students. Each
student's sheet draws every problem from a seed derived from the course secret, so the
same sheet can be rebuilt at grading time from the same three inputs.
"""
from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..draw.seeds import derive_seed, sheet_code
from ..errors import AssignmentError, ExgenError
from ..load.bank import Bank
from ..runtime.yamlfile import YamlFileError, place, read_yaml
from ..solve.variant import Variant, make_variant

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
    """Read an assignment file; with a bank, also check every template id exists. Every problem found is
    reported at once, each at its line and column, questions counted from 1 as on the sheet."""
    path = Path(path)
    try:
        root, data = read_yaml(path, "an assignment file")
    except YamlFileError as exc:
        raise AssignmentError(path, exc.detail, exc.line, exc.column) from None
    if not isinstance(data, dict):
        raise AssignmentError(path, "an assignment file is a list of `key: value` lines, with `assignment:` (its id) "
                                    "and `questions:` (the templates)", *place(root, ()) if root else (None, None))
    problems = _Problems(root)
    for key in data:
        if key not in ASSIGNMENT_KEYS:
            problems.add((key,), f"unknown key `{_shown(key)}`{_did_you_mean(key, ASSIGNMENT_KEYS)}; an assignment "
                                 f"file has {', '.join(sorted(ASSIGNMENT_KEYS))}")
    assignment_id = _assignment_id(data, problems)
    questions = _questions(data.get("questions"), bank, problems)
    for key in ("secret_file", "roster"):
        if data.get(key) is not None and not isinstance(data[key], str):
            problems.add((key,), f"`{key}:` must be a file name (a path beside the assignment file)")
    problems.raise_if_any(path)
    base = path.parent
    return Assignment(
        id=assignment_id, title=str(data.get("title") or assignment_id), questions=tuple(questions),
        course=str(data.get("course", "")), due=str(data.get("due", "")),
        instructions=str(data.get("instructions", "")).strip(),
        secret_file=base / data["secret_file"] if data.get("secret_file") else None,
        roster=base / data["roster"] if data.get("roster") else None, path=path,
    )


class _Problems:
    """Problems of one file, each at the place of a key path in its node tree."""

    def __init__(self, root):
        self.root, self.found = root, []

    def add(self, keypath: tuple, message: str) -> None:
        self.found.append((message, *place(self.root, keypath)))

    def raise_if_any(self, path: Path) -> None:
        if self.found:
            first, *more = self.found
            raise AssignmentError(path, *first, more=tuple(more))


def _assignment_id(data: dict, problems: _Problems) -> str:
    if "assignment" not in data or data["assignment"] in (None, ""):
        problems.add((), "no `assignment:` line: give the assignment an id, such as `assignment: tut1-belts` "
                         "(letters, digits, '.', '_' or '-'; it seeds every sheet, so it never changes once sheets are out)")
        return ""
    value = str(data["assignment"])
    if not _SAFE_ID.match(value):
        problems.add(("assignment",), f"`assignment: {_shown(value)}` is not an id: use letters, digits, '.', '_' "
                                      "or '-', with no spaces, such as `tut1-belts` (it seeds every sheet)")
    return value


def _questions(items, bank: Bank | None, problems: _Problems) -> list[QuestionSpec]:
    if items is None or items == []:
        problems.add(("questions",) if items == [] else (), "no questions: list the templates under `questions:`, "
                                                           "one `- template: ID` line each (`exgen list` names them)")
        return []
    if not isinstance(items, list):
        problems.add(("questions",), "`questions:` must be a list, one `- template: ID` line per question")
        return []
    questions, slots = [], {}
    for number, item in enumerate(items, start=1):
        where = ("questions", number - 1)
        line = place(problems.root, where)[0]
        name = f"question {number}" + (f" (line {line})" if line else "")
        item = {"template": item} if isinstance(item, str) else item
        if not isinstance(item, dict) or not isinstance(item.get("template"), str) or not item["template"]:
            problems.add(where, f"{name}: no `template:`; give the template's id, as `exgen list` prints it "
                                "(`- template: belts.flat_belt_power`)")
            continue
        for key in item:
            if key not in QUESTION_KEYS:
                problems.add(where + (key,), f"{name}: unknown key `{_shown(key)}`{_did_you_mean(key, QUESTION_KEYS)}; "
                                             f"a question has {', '.join(sorted(QUESTION_KEYS))}")
        slot = str(item.get("slot", f"q{number}"))
        if not _SAFE_ID.match(slot):
            problems.add(where + ("slot",), f"{name}: slot {_shown(slot)!r} must be letters, digits, '.', '_' or "
                                            "'-', starting with a letter or digit (it names the question's files)")
        if slot in slots:
            problems.add(where + ("slot",), f"{name}: slot {slot!r} is already question {slots[slot]}'s; "
                                            "give each question its own")
        slots.setdefault(slot, number)
        points = item.get("points")
        if points is not None and not _positive_number(points):
            problems.add(where + ("points",), f"{name}: points must be a positive, finite number (got "
                                              f"{_shown(points, 20)})")
            points = None
        if bank is not None:
            try:
                bank.get(item["template"])
            except ExgenError as exc:
                problems.add(where + ("template",), f"{name}: {exc}")
        questions.append(QuestionSpec(slot, item["template"], float(points) if points else None))
    return questions


def _did_you_mean(key, known) -> str:
    close = difflib.get_close_matches(str(key), sorted(known), n=1, cutoff=0.6)
    return f" (did you mean `{close[0]}`?)" if close else ""


def _shown(value, limit: int = 40) -> str:
    text = " ".join(str(value).split())
    return text if len(text) <= limit else text[: limit - 1] + "\u2026"


def _positive_number(value) -> bool:
    """True for 3 or 2.5; False for 0, -1, .nan, .inf, true and text."""
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value > 0


def build_sheet(assignment: Assignment, student: Student, bank: Bank, secret: bytes) -> Sheet:
    """One student's sheet: every question drawn from its HMAC seed."""
    questions = []
    for number, spec in enumerate(assignment.questions, start=1):
        template = bank.get(spec.template)
        variant = make_variant(template, derive_seed(secret, assignment.id, student.id, spec.slot))
        questions.append(Question(number, spec.slot, variant, spec.points or template.points))
    code = sheet_code(secret, assignment.id, student.id, [f"{q.slot}={q.variant.template.id}" for q in questions])
    return Sheet(assignment, student, code, tuple(questions))
