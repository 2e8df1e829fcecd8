"""What grading produces: per part, per question, per sheet and per batch. Read by the report writers."""
from __future__ import annotations

import statistics
from typing import Any, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from exgen.issue.assignment import Assignment, Student

# Part statuses. A format problem ("unreadable") is kept apart from a wrong answer.
CORRECT = "correct"
CARRIED = "carried"      # right from the student's own earlier answers (error carried forward)
WRONG = "wrong"
BLANK = "blank"
UNREADABLE = "unreadable"
PART_STATUSES = (CORRECT, CARRIED, WRONG, BLANK, UNREADABLE)

# Sheet statuses.
GRADED = "graded"
NO_SUBMISSION = "no submission"
UNREADABLE_FILE = "unreadable file"
NOT_GRADED = "not graded"  # the sheet itself could not be rebuilt (a bank or secret problem)
PROBLEM_FILE = "problem file"  # a file in the student's place names another student, sheet or assignment


@dataclass(frozen=True)
class Review:
    """How a review decision changed a part (graders.review): `by` a decision on this student's answer or an
    alias (a spelling accepted for everyone), and the status and points the grader gave before it."""

    by: str  # DECISION | ALIAS
    status_before: str
    points_before: float
    reviewer: str
    reason: str
    decision: str = ""   # accept | reject (a decision)
    comment: str = ""    # what the student reads (a decision)
    spelling: str = ""   # the spelling read as `means` (an alias)
    means: str = ""
    line: int | None = None  # where it is in the decisions file



DECISION, ALIAS = "decision", "alias"


@dataclass(frozen=True)
class PartResult:
    part_id: str
    ask: str
    unit: str
    given: str
    expected: str
    status: str
    points: float
    max_points: float
    message: str
    mistake: str | None = None
    #: the expected answer as a value (what `expected` writes), for comparing answers across sheets
    value: Any = field(default=None, compare=False, repr=False)
    #: why no credit could be carried forward from the student's wrong earlier answers (the working failed
    #: on them: the exception and where), for the instructor's report; "" when nothing stood in the way
    not_carried: str = ""
    #: what review changed (graders.review), None if nothing
    review: Review | None = None

    @property
    def correct(self) -> bool:
        return self.status in (CORRECT, CARRIED)

    @property
    def changed_by_review(self) -> bool:
        """Whether review changed the part's marks."""
        return self.review is not None and abs(self.points - self.review.points_before) > 1e-12


@dataclass(frozen=True)
class QuestionResult:
    number: int
    slot: str
    title: str
    template: str
    parts: tuple[PartResult, ...]
    max_points: float

    @cached_property
    def points(self) -> float:  # read for every gradebook, page and report: summed once
        return sum(p.points for p in self.parts)


@dataclass(frozen=True)
class SheetResult:
    student: Student
    status: str
    max_points: float
    code: str = ""
    questions: tuple[QuestionResult, ...] = ()
    warnings: tuple[str, ...] = ()
    path: Path | None = None
    code_mismatch: bool = False  # the answer file's sheet code is not this sheet's

    @cached_property
    def points(self) -> float:
        return sum(q.points for q in self.questions)

    @property
    def percent(self) -> float:
        return 100.0 * self.points / self.max_points if self.max_points else 0.0

    def question(self, slot: str) -> QuestionResult | None:
        return next((q for q in self.questions if q.slot == slot), None)


@dataclass(frozen=True)
class FileProblem:
    """An answer file the batch could not use, and why (unreadable, unknown student, a duplicate)."""

    path: Path
    reason: str
    student: str = ""


@dataclass(frozen=True)
class Column:
    """One question of the assignment, as a gradebook column."""

    number: int
    slot: str
    template: str
    max_points: float
    #: each part's (id, answer type, choices offered): what a reviewer may accept a spelling as
    kinds: tuple[tuple[str, str, tuple[str, ...]], ...] = ()


@dataclass(frozen=True)
class NotApplied:
    """A review decision or alias that does not match what was graded, and why: listed, never applied."""

    line: int | None
    what: str
    why: str


@dataclass(frozen=True)
class ReviewSummary:
    """The decisions file a batch was graded with: how many it holds, how many answers they marked, and
    those not applied."""

    path: Path
    decisions: int
    aliases: int
    not_applied: tuple[NotApplied, ...] = ()
    applied: int = 0  # graded answers a decision or an alias marked


@dataclass(frozen=True)
class BatchResult:
    assignment: Assignment
    columns: tuple[Column, ...]
    sheets: tuple[SheetResult, ...]
    problems: tuple[FileProblem, ...] = field(default=())
    submissions: Path | None = None  # the directory the answer files came from
    warnings: tuple[str, ...] = ()   # about the whole batch (graded with --force although ...)
    #: Limits the walk of the submissions folder reached, graded anyway (--accept-limits): graders.walk.
    limits: tuple[str, ...] = ()
    #: The review decisions applied (graders.review), None when there were none to apply.
    review: ReviewSummary | None = None
    #: Feedback pages written where the sheets were graded, in parallel: student id -> (the sheet, its page).
    #: graders.report writes the page of a sheet not here, or replaced since, itself.
    pages: Mapping[str, tuple[SheetResult, str]] = field(default_factory=dict, compare=False, repr=False)

    @property
    def max_points(self) -> float:
        return sum(c.max_points for c in self.columns)

    def summary(self) -> str:
        """One line for the terminal: how many sheets, by status, and the mean mark."""
        counts = ", ".join(f"{n} {status}" for status, n in sorted(self.by_status().items())) or "no students"
        marks = self.percent_summary()
        mean = f"; mean {marks[0]:.1f} %, median {marks[1]:.1f} %" if marks else ""
        problems = f"; {len(self.problems)} file(s) not graded" if self.problems else ""
        forced = f" (graded with --force: {len(self.warnings)} warning(s) in the report)" if self.warnings else ""
        limits = f" (limits reached: {len(self.limits)}, in the report)" if self.limits else ""
        return f"{len(self.sheets)} student(s): {counts}{mean}{problems}{forced}{limits}"

    def by_status(self) -> dict[str, int]:
        counts: dict[str, int] = {}
        for sheet in self.sheets:
            counts[sheet.status] = counts.get(sheet.status, 0) + 1
        return counts

    def percent_summary(self) -> tuple[float, float] | None:
        """Mean and median percentage over the sheets that were graded."""
        marks = [s.percent for s in self.sheets if s.status == GRADED]
        if not marks:
            return None
        return statistics.fmean(marks), statistics.median(marks)
