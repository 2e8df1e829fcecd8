"""What needs a human in a graded folder, read from its results.json: every format problem, every blank
on a sheet whose other parts were answered, every part a sign of copying rests on. Answers to the same
part that read the same (the same text, cleaned as results.json keeps it) stand together as one group,
with how many students typed it and who, so a spelling forty students used is decided once.

Each answer is shown with the decision already made on it, if one matches its text, or with the one that
no longer does (the student handed in something else since), from the decisions file; and with what the
last grading run applied (results.json records, per part, what review changed and what the grader gave
before). An answer is listed for what the grader gave before review, so a decided one stays listed.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import cached_property

from ..decisions import Alias, Decision, Decisions, cleaned
from ..results import BLANK, GRADED, UNREADABLE

FORMAT, BLANK_AMONG, COPYING = "format", "blank", "copying"
#: Why an answer needs a human, in the page's words, in the order the page lists them.
KINDS = {FORMAT: "Format problem", BLANK_AMONG: "Blank where other parts were answered",
         COPYING: "Flagged by signs of copying"}


@dataclass(frozen=True)
class Answer:
    """One student's answer to one part, as graded."""

    student: str
    name: str
    given: str
    expected: str
    points: float
    max_points: float
    mistake: str = ""
    message: str = ""                 # what the grader said of it
    evidence: tuple[str, ...] = ()
    decision: Decision | None = None  # the decision made on this very text
    stale: Decision | None = None     # a decision on this part made on another text: not applied
    applied: dict | None = None       # what review changed in the last grading run (results.json)

    @property
    def mistake_words(self) -> str:
        return self.mistake.replace("_", " ")


@dataclass(frozen=True)
class Group:
    """The answers to one part that read the same and need a human for the same reason."""

    kind: str
    question: int
    slot: str
    part: str
    template: str
    title: str
    given: str
    max_points: float
    answers: tuple[Answer, ...]
    alias: Alias | None = None  # a spelling accepted for everyone that this text is
    choices: tuple[str, ...] = ()  # what the part offers, when it is a choice

    @cached_property
    def id(self) -> str:
        """Stable across requests and runs while the group is the same: its reason, part and text."""
        return hashlib.sha256(f"{self.kind}\0{self.slot}\0{self.part}\0{self.given}".encode()).hexdigest()[:16]

    @property
    def students(self) -> tuple[str, ...]:
        return tuple(a.student for a in self.answers)

    @property
    def keys(self) -> tuple[str, ...]:
        """The distinct keys of its students (several when their numbers differ)."""
        return tuple(dict.fromkeys(a.expected for a in self.answers))

    @property
    def decided(self) -> bool:
        return self.alias is not None or all(a.decision is not None for a in self.answers)

    @property
    def message(self) -> str:
        """What the grader said, when it said the same to every student of the group (before any review: what
        a part marked by review says is review's)."""
        said = {a.message for a in self.answers if a.applied is None}
        return said.pop() if len(said) == 1 else ""

    @property
    def stale(self) -> tuple[Answer, ...]:
        return tuple(a for a in self.answers if a.stale is not None)

    @property
    def spelling_can_be_accepted(self) -> bool:
        """An alias reads a spelling as another: for text that could not be read, never for a blank."""
        return self.kind == FORMAT and bool(self.given.strip())


@dataclass(frozen=True)
class Question:
    number: int
    slot: str
    title: str
    parts: tuple[str, ...]


@dataclass(frozen=True)
class Queue:
    assignment: str
    title: str
    questions: tuple[Question, ...]
    groups: tuple[Group, ...]
    #: Signs of copying that rest on no part (a file carrying another student's sheet code): shown, not decided.
    notes: tuple[str, ...] = ()
    #: Decisions the last grading run did not apply, and why (results.json: line, what, why).
    not_applied: tuple[dict, ...] = ()

    def group(self, group_id: str) -> Group | None:
        return next((g for g in self.groups if g.id == group_id), None)

    def shown(self, question: int | None = None, part: str = "", everything: bool = False) -> tuple[Group, ...]:
        """The groups of a question (and part), those still open unless `everything`."""
        return tuple(g for g in self.groups if (question is None or g.question == question)
                     and (not part or g.part == part) and (everything or not g.decided))

    @property
    def answers(self) -> int:
        return sum(len(g.answers) for g in self.groups)

    @property
    def open_answers(self) -> int:
        return sum(len(g.answers) for g in self.groups if not g.decided)


def build_queue(record: dict, decisions: Decisions) -> Queue:
    """Everything in a graded folder's record that needs a human, grouped, with the decisions made so far."""
    columns = {c["slot"]: c for c in record.get("columns", ())}
    choices = {(c["slot"], p["id"]): tuple(p.get("choices") or ()) for c in columns.values() for p in c.get("parts", ())}
    flagged = _flagged(record.get("signs", ()))
    groups: dict[tuple, list] = {}
    for sheet in record.get("sheets", ()):
        if sheet.get("status") != GRADED:
            continue
        student = sheet["student"]
        answered = sum(1 for p in sheet["parts"] if str(p.get("given", "")).strip())
        for part in sheet["parts"]:
            column = columns.get(part["slot"])
            evidence = tuple(flagged.get((student["id"], part["slot"], part["part"]), ()))
            applied = part.get("review") or None
            kind = _kind(applied.get("status_before") if applied else part.get("status"), answered, evidence)
            if kind is None or column is None:
                continue
            answer = _answer(student, part, column, evidence, applied, decisions)
            key = (column["number"], part["part"], list(KINDS).index(kind), answer.given, kind, column["slot"])
            groups.setdefault(key, []).append(answer)
    made = []
    for (number, part_id, _, given, kind, slot), answers in sorted(groups.items(), key=lambda kv: (
            kv[0][0], kv[0][1], kv[0][2], -len(kv[1]), kv[0][3])):
        column = columns[slot]
        alias = next((a for a in decisions.aliases_for(number, part_id)
                      if a.template == column["template"] and a.matches(given)), None) if kind == FORMAT else None
        made.append(Group(kind, number, slot, part_id, column["template"], column.get("title", column["template"]),
                          given, max(a.max_points for a in answers), tuple(answers), alias,
                          choices.get((slot, part_id), ())))
    questions = tuple(Question(c["number"], c["slot"], c.get("title", c["template"]),
                               tuple(p["id"] for p in c.get("parts", ())))
                      for c in sorted(columns.values(), key=lambda c: c["number"]))
    notes = tuple(s.get("summary", "") for s in record.get("signs", ()) if not s.get("parts"))
    assignment = record.get("assignment", {})
    review = record.get("review") or {}
    return Queue(assignment.get("id", ""), assignment.get("title", ""), questions, tuple(made), notes,
                 tuple(review.get("not_applied", ())))


def _answer(student: dict, part: dict, column: dict, evidence: tuple[str, ...], applied: dict | None,
            decisions: Decisions) -> Answer:
    """One student's graded part, with the decision on it that matches its text, or the one that no longer does."""
    given = cleaned(part.get("given", ""))
    decision = decisions.decision_for(student["id"], column["number"], part["part"])
    matching = decision if decision is not None and decision.matches(column["template"], given) else None
    return Answer(student["id"], student.get("name", ""), given, str(part.get("expected", "")),
                  float(part.get("points", 0.0)), float(part.get("max_points", 0.0)), part.get("mistake") or "",
                  str(part.get("message", "")), evidence, matching, decision if matching is None else None, applied)


def _kind(status: str | None, answered: int, evidence) -> str | None:
    """Why a part needs a human, if it does: a blank counts where any other part of the sheet was answered."""
    if status == UNREADABLE:
        return FORMAT
    if status == BLANK and answered > 0:
        return BLANK_AMONG
    if evidence:
        return COPYING
    return None


def _flagged(signs) -> dict[tuple[str, str, str], list[str]]:
    """(student, slot, part) -> the evidence of every sign resting on that answer: each line of a sign's
    evidence starts with the part it is about, "q1 (a): ..." (graders.copying writes it so)."""
    found: dict[tuple[str, str, str], list[str]] = {}
    for sign in signs:
        lines = {line.split(":", 1)[0]: line for line in sign.get("evidence", ())}
        for where in sign.get("parts", ()):
            key = (where["student"], where["slot"], where["part"])
            line = lines.get(f"{where['slot']} ({where['part']})", sign.get("summary", ""))
            found.setdefault(key, []).append(line)
    return found
