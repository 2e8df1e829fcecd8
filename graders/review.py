"""Review decisions applied to a grading run (the file: graders.decisions).

Before any sheet is graded, each alias is checked against the assignment (its question is still the
template it was made for, the part exists, what it means reads as an answer of that part): those that hold
are handed to the marker (graders.marking), which reads the spelling as what it means. After a question is
marked, a student's decision is applied to their part if it still matches: the same template, if it names
one, and the same answer text, cleaned. Every decision or alias that matches nothing graded is listed
(`not_applied`), on the terminal and in report.md, and changes no mark.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Mapping

from exgen.answertypes import answer_type
from exgen.errors import ExgenError, FormatProblem, WrongKind
from exgen.issue.assignment import Assignment
from exgen.load.bank import Bank

from .decisions import ACCEPT, Alias, Decision, Decisions, cleaned, spelling_key
from .echo import shown
from .results import (CORRECT, DECISION, GRADED, WRONG, BatchResult, NotApplied, PartResult, QuestionResult,
                      Review, ReviewSummary)

MARKED_BY_HAND = "marked by hand"
#: Points closer than this to the part's full marks are full marks.
EPSILON = 1e-9


@dataclass(frozen=True)
class ReviewPlan:
    """The decisions of a run, with the aliases that hold by question number, part id and spelling key."""

    decisions: Decisions
    aliases: Mapping[int, Mapping[str, Mapping[str, Alias]]] = field(default_factory=dict)
    alias_problems: tuple[NotApplied, ...] = ()

    def aliases_for(self, question: int) -> Mapping[str, Mapping[str, Alias]]:
        return self.aliases.get(question, {})

    def apply(self, student: str, result: QuestionResult) -> QuestionResult:
        """The question's result with this student's decisions that match applied."""
        parts, changed = [], False
        for part in result.parts:
            decision = self.decisions.decision_for(student, result.number, part.part_id)
            if decision is not None and decision_problem(decision, result.template, part) is None:
                part, changed = decided(part, decision), True
            parts.append(part)
        return replace(result, parts=tuple(parts)) if changed else result


def plan(decisions: Decisions | None, assignment: Assignment, bank: Bank) -> ReviewPlan | None:
    """The plan for grading `assignment` with `decisions`; None when there are none."""
    if not decisions:
        return None
    templates = {number: spec.template for number, spec in enumerate(assignment.questions, start=1)}
    usable: dict[int, dict[str, dict[str, Alias]]] = {}
    problems = []
    for alias in decisions.aliases:
        why = alias_problem(alias, templates, bank)
        if why:
            problems.append(NotApplied(alias.line, _alias_name(alias), why))
        else:
            usable.setdefault(alias.question, {}).setdefault(alias.part, {})[spelling_key(alias.spelling)] = alias
    return ReviewPlan(decisions, usable, tuple(problems))


def alias_problem(alias: Alias, templates: Mapping[int, str], bank: Bank) -> str | None:
    """Why an alias cannot be applied to this assignment, or None."""
    template_id = templates.get(alias.question)
    if template_id is None:
        return f"the assignment has no question {alias.question} (it has {len(templates)})"
    if template_id != alias.template:
        return f"question {alias.question} is now {template_id}, not {alias.template} the alias was made for"
    try:
        template = bank.get(template_id)
    except ExgenError as exc:
        return str(exc)
    part = next((p for p in template.parts if p.id == alias.part), None)
    if part is None:
        return f"question {alias.question} ({template_id}) has no part ({shown(alias.part, 20)})"
    problem = reading_problem(alias.means, part)
    return f"'{shown(alias.means, 60)}' {problem}" if problem else None


def reading_problem(means: str, part) -> str | None:
    """Why `means` is no answer the part reads (not one of its choices, not a value of its kind), or None."""
    kind = answer_type(part)
    try:
        kind.read(means, part)
    except (FormatProblem, WrongKind) as exc:
        choices = kind.form_choices(part) or ()
        if choices:
            return f"is not one of the part's choices ({', '.join(choices)})"
        return f"is not an answer the part reads: {shown(str(exc), 200)}"
    return None


def decision_problem(decision: Decision, template: str, part: PartResult) -> str | None:
    """Why a decision does not hold for this graded part, or None."""
    if decision.matches(template, part.given):
        if decision.decision == ACCEPT and decision.points is not None and \
                decision.points > part.max_points + EPSILON:
            return f"it gives {decision.points:g} points, more than the part's {part.max_points:g}"
        return None
    if decision.template and decision.template != template:
        return f"the question is now {template}, not {decision.template} the decision was made for"
    now = cleaned(part.given)
    if now != decision.answer:
        then = shown(decision.answer, 60) if decision.answer else "(blank)"
        return (f"the answer is now '{shown(now, 60)}'" if now else "the answer is now blank") + \
            f", not '{then}' the decision was made on"
    return None


def decided(part: PartResult, decision: Decision) -> PartResult:
    """The part as the decision marks it: its points, "marked by hand" and the comment, and what it had."""
    points = decision.points_for(part.max_points)
    full = decision.decision == ACCEPT and points >= part.max_points - EPSILON
    before = part.review  # an alias read it first: what the grader gave before any review
    review = Review(DECISION, before.status_before if before else part.status,
                    before.points_before if before else part.points, decision.reviewer, decision.reason,
                    decision=decision.decision, comment=decision.comment, line=decision.line)
    message = f"{MARKED_BY_HAND}: {decision.comment}" if decision.comment else MARKED_BY_HAND
    return replace(part, status=CORRECT if full else WRONG, points=part.max_points if full else points,
                   message=message, mistake=None, review=review, not_carried="")


def not_applied(review: ReviewPlan, batch: BatchResult) -> tuple[NotApplied, ...]:
    """Every decision and alias that changed nothing graded, and why, in the file's order."""
    sheets = {s.student.id: s for s in batch.sheets}
    found = list(review.alias_problems)
    for decision in review.decisions.decisions:
        why = _unmatched(decision, sheets, len(batch.columns))
        if why:
            found.append(NotApplied(decision.line, _decision_name(decision), why))
    return tuple(sorted(found, key=lambda n: (n.line or 0, n.what)))


def _unmatched(decision: Decision, sheets: Mapping, questions: int) -> str | None:
    sheet = sheets.get(decision.student)
    if sheet is None:
        return f"no student {shown(decision.student, 40)} in this class"
    if sheet.status != GRADED:
        return f"{shown(decision.student, 40)}'s answers were not graded ({sheet.status})"
    question = next((q for q in sheet.questions if q.number == decision.question), None)
    if question is None:
        return f"the assignment has no question {decision.question} (it has {questions})"
    part = next((p for p in question.parts if p.part_id == decision.part), None)
    if part is None:
        return f"question {decision.question} ({question.template}) has no part ({shown(decision.part, 20)})"
    if part.review is not None and part.review.by == DECISION:
        return None
    return decision_problem(decision, question.template, part) or "it matches, but was not applied"


def summary(review: ReviewPlan | None, batch: BatchResult) -> ReviewSummary | None:
    if review is None:
        return None
    decisions = review.decisions
    applied = sum(p.review is not None for s in batch.sheets for q in s.questions for p in q.parts)
    return ReviewSummary(decisions.path, len(decisions.decisions), len(decisions.aliases), not_applied(review, batch),
                         applied)


def _decision_name(d: Decision) -> str:
    return f"{d.decision} {shown(d.student, 40)}, question {d.question} ({shown(d.part, 20)})"


def _alias_name(a: Alias) -> str:
    return f"alias '{shown(a.spelling, 40)}' for question {a.question} ({shown(a.part, 20)})"
