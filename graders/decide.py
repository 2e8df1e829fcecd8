"""`exgen decide GRADED`: a review decision written without the review page, for scripts and for a lecturer
on a terminal. Every decision is checked against the graded run (its results.json) before the file is
touched: the question and part exist, the student is in the class and was graded, the points fit the part,
what a spelling is accepted as is one of the part's choices (or an answer the part reads). A decision on a
student's answer records the text as graded, so it holds for that text only.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from exgen.errors import ExgenError
from exgen.load.bank import Bank

from .decisions import (ACCEPT, COMMENT_LENGTH, REJECT, TEXT_LENGTH, Alias, Decision, Decisions, cleaned,
                        default_path, load_decisions, save_decisions, spelling_key)
from .echo import shown
from .record import RESULTS, read_record
from .review import reading_problem

GRADE_AGAIN = "grade again to apply it (exgen grade ISSUED SUBMISSIONS --out {graded})"


class DecideError(ExgenError):
    """A decision that cannot be written: one line saying why; the decisions file is left as it was."""


@dataclass(frozen=True)
class Target:
    """The part of the graded run a decision is about."""

    record: dict
    column: dict
    part: dict

    @property
    def question(self) -> int:
        return self.column["number"]

    @property
    def name(self) -> str:
        return f"question {self.question} ({self.part['id']})"


def target(graded: Path, question: int, part: str) -> Target:
    """The column and part of question `question` in the run in `graded`, or DecideError."""
    record = _checked(read_record(Path(graded)), graded)
    columns = record["columns"]
    column = next((c for c in columns if c.get("number") == question), None)
    if column is None:
        raise DecideError(f"{graded}: there is no question {question}: the assignment has questions 1 to "
                          f"{len(columns)}")
    wanted = part.strip().strip("().").strip().lower()
    found = next((p for p in column["parts"] if p["id"].lower() == wanted), None)
    if found is None:
        ids = ", ".join(p["id"] for p in column["parts"])
        raise DecideError(f"{graded}: question {question} ({column['template']}) has no part "
                          f"({shown(part, 20)}): its parts are {ids or 'none'}")
    return Target(record, column, found)


def _checked(record: dict, graded: Path) -> dict:
    """results.json as exgen grade writes it, in what a decision reads (it may have been edited by hand)."""
    def fields(item, **kinds) -> bool:
        return isinstance(item, dict) and all(isinstance(item.get(k), t) and not isinstance(item.get(k), bool)
                                              for k, t in kinds.items())

    ok = fields(record, assignment=dict, columns=list, sheets=list) and fields(record["assignment"], id=str) \
        and all(fields(c, number=int, slot=str, template=str, parts=list)
                and all(fields(p, id=str, max_points=(int, float)) for p in c["parts"]) for c in record["columns"]) \
        and all(fields(s, student=dict, status=str, parts=list) and fields(s["student"], id=str)
                and all(fields(p, slot=str, part=str, max_points=(int, float)) for p in s["parts"])
                for s in record["sheets"])
    if not ok:
        raise DecideError(f"{Path(graded) / RESULTS}: not grading results as exgen grade writes them; grade again")
    return record


def _file(graded: Path, path: Path | None, record: dict) -> tuple[Path, Decisions]:
    path = Path(path) if path else default_path(Path(graded))
    return path, load_decisions(path, record["assignment"]["id"])


def accept_spelling(graded: Path, question: int, part: str, spelling: str, means: str, reviewer: str, reason: str,
                    bank: Bank, path: Path | None = None) -> tuple[Path, str]:
    """Write an alias: `spelling` read as `means` for everyone on this part. (the file, what was done)"""
    where = target(graded, question, part)
    template = where.column["template"]
    if not spelling_key(spelling):
        raise DecideError("--accept-spelling is blank: give the spelling students wrote")
    choices = where.part.get("choices")
    means = _listed(means, [c for c in choices if isinstance(c, str)] if isinstance(choices, list) else [])
    spec = next((p for p in bank.get(template).parts if p.id == where.part["id"]), None)
    if spec is None:
        raise DecideError(f"{template} has no part ({where.part['id']}) any more: grade again first")
    problem = reading_problem(means, spec)
    if problem:
        raise DecideError(f"--means '{shown(means, 60)}' {problem}, for {where.name} ({template})")
    if spelling_key(spelling) == spelling_key(means):
        raise DecideError(f"--accept-spelling and --means are the same: '{shown(spelling, 60)}'")
    file, decisions = _file(graded, path, where.record)
    alias = Alias(where.question, where.part["id"], template, cleaned(spelling), means,
                  _text(reviewer, "reviewer", 200), _text(reason, "reason"))
    replaced = any(a.key == alias.key for a in decisions.aliases)
    save_decisions(decisions.with_alias(alias), file)
    return file, (f"accepted the spelling '{shown(alias.spelling, 60)}' as '{shown(means, 60)}' for everyone on "
                  f"{where.name}{' (replacing the earlier one)' if replaced else ''}, in {file}; "
                  + GRADE_AGAIN.format(graded=graded))


def decide_answer(graded: Path, verdict: str, student: str, question: int, part: str, reviewer: str, reason: str,
                  points: float | None = None, comment: str = "", path: Path | None = None) -> tuple[Path, str]:
    """Write a decision on one student's answer as graded in `graded`. (the file, what was done)"""
    where = target(graded, question, part)
    sheets = where.record["sheets"]
    sheet = next((s for s in sheets if s["student"]["id"] == student), None)
    if sheet is None:  # a21001 for A21001, if it names one student only
        alike = [s for s in sheets if s["student"]["id"].casefold() == student.casefold()]
        sheet = alike[0] if len(alike) == 1 else None
        student = sheet["student"]["id"] if sheet else student
    if sheet is None:
        raise DecideError(f"{graded}: no student {shown(student, 40)} in this class")
    if sheet.get("status") != "graded":
        raise DecideError(f"{graded}: {shown(student, 40)}'s answers were not graded ({sheet.get('status')}): there "
                          "is no answer to decide on")
    graded_part = next((p for p in sheet.get("parts", []) if p.get("slot") == where.column["slot"]
                        and p.get("part") == where.part["id"]), None)
    if graded_part is None:
        raise DecideError(f"{graded}: {shown(student, 40)} has no {where.name} in results.json")
    if verdict == REJECT and points is not None:
        raise DecideError("--points is for --accept: a rejected answer scores 0")
    top = graded_part["max_points"]
    if points is not None and not 0 <= points <= top:
        raise DecideError(f"--points {points:g} is outside 0 to {top:g}, the marks of {where.name}")
    file, decisions = _file(graded, path, where.record)
    decision = Decision(student, where.question, where.part["id"], cleaned(graded_part.get("given", "")), verdict,
                        _text(reviewer, "reviewer", 200), _text(reason, "reason"), points=points,
                        comment=_capped(" ".join((comment or "").split()), "comment", COMMENT_LENGTH), template=where.column["template"])
    replaced = decisions.decision_for(*decision.key) is not None
    save_decisions(decisions.with_decision(decision), file)
    given = f"'{shown(decision.answer, 60)}'" if decision.answer else "(blank)"
    done = "accepted" if verdict == ACCEPT else "rejected"
    worth = f" for {points:g} of {top:g} points" if verdict == ACCEPT and points is not None else ""
    return file, (f"{done} {student}'s answer {given} to {where.name}{worth}"
                  f"{' (replacing the earlier decision)' if replaced else ''}, in {file}; "
                  + GRADE_AGAIN.format(graded=graded))


def withdraw(graded: Path, question: int, part: str, student: str | None = None, spelling: str | None = None,
             path: Path | None = None) -> tuple[Path, str]:
    """Take back the decision on a student's part, or the alias for a spelling of a part. (the file, what was
    done)"""
    record = _checked(read_record(Path(graded)), graded)
    file, decisions = _file(graded, path, record)
    part_id = part.strip().strip("().").strip().lower()
    if student is not None:
        if decisions.decision_for(student, question, part_id) is None:
            raise DecideError(f"{file}: there is no decision on {shown(student, 40)}'s question {question} "
                              f"({shown(part_id, 20)})")
        left, what = decisions.without_decision(student, question, part_id), \
            f"the decision on {student}'s question {question} ({part_id})"
    else:
        left = decisions.without_alias(question, part_id, spelling or "")
        if left == decisions:
            raise DecideError(f"{file}: there is no alias for '{shown(spelling, 60)}' on question {question} "
                              f"({shown(part_id, 20)})")
        what = f"the spelling '{shown(spelling, 60)}' on question {question} ({part_id})"
    save_decisions(left, file)
    return file, f"withdrew {what}, in {file}; " + GRADE_AGAIN.format(graded=graded)


def _listed(means: str, choices: list) -> str:
    """A choice written as listed ('Raises the bow' -> 'raises the bow'); other text as typed, on one line."""
    means = " ".join(str(means).split())
    return next((c for c in choices if spelling_key(c) == spelling_key(means)), means)


def _text(value: str, name: str, limit: int = TEXT_LENGTH) -> str:
    value = " ".join(str(value or "").split())
    if not value:
        raise DecideError(f"--{name} is blank: every decision says who made it and why")
    return _capped(value, name, limit)


def _capped(value: str, name: str, limit: int) -> str:
    if len(value) > limit:
        raise DecideError(f"--{name} is {len(value):,} characters long; at most {limit:,}")
    return value
