"""A decision sent from the review page, checked and turned into entries of the decisions file: accept
(full marks, or the points given) or reject with a comment for each student of a group, or one of them;
or the group's spelling accepted for everyone (an alias of the part). Every one carries the reviewer's
name and a reason. The decisions on a group can be taken back. What a form says is only believed once checked against the group the server holds."""
from __future__ import annotations

import math

from exgen.echo import shown

from ..decisions import ACCEPT, ANSWER_LENGTH, COMMENT_LENGTH, REJECT, TEXT_LENGTH, Alias, Decision, Decisions
from ..review import reading_problem
from .queue import Group

ALIAS, WITHDRAW = "alias", "withdraw"
CHOICES = (ACCEPT, REJECT, ALIAS)
EVERYONE = "*"
NAME_LENGTH = 200


class Invalid(Exception):
    """A field of the form that cannot be used as it is, and why, said beside that field."""

    def __init__(self, name: str, message: str):
        super().__init__(message)
        self.name, self.message = name, message


def decide(decisions: Decisions, group: Group, form: dict[str, str], spec=None) -> tuple[Decisions, str]:
    """The decisions with this form's added (replacing any on the same answers), and a sentence saying what
    was decided for whom. `spec`: the part's PartSpec, if the bank has it, to check that what a spelling is
    accepted as is an answer the part reads (as `exgen grade` will read it)."""
    choice = form.get("decision", "")
    if choice == WITHDRAW:
        return withdraw(decisions, group)
    if choice not in CHOICES or (choice == ALIAS and not group.spelling_can_be_accepted):
        raise Invalid("decision", "choose accept, reject" + (" or accept this spelling for everyone"
                                                              if group.spelling_can_be_accepted else ""))
    reviewer = _text(form, "reviewer", NAME_LENGTH, "the reviewer's name")
    reason = _text(form, "reason", TEXT_LENGTH, "a reason (for the report and for anyone who reads the file)")
    if choice == ALIAS:
        means = _text(form, "means", ANSWER_LENGTH, "what the spelling means (as the key writes it)")
        if group.choices and means not in group.choices:
            raise Invalid("means", "choose what the spelling means from the part's choices")
        problem = reading_problem(means, spec) if spec is not None else None
        if problem:
            raise Invalid("means", f"“{means}” {problem}")
        if means.casefold() == group.given.casefold():
            raise Invalid("means", "give what the spelling means, not the spelling itself")
        alias = Alias(group.question, group.part, group.template, group.given, means, reviewer, reason)
        return decisions.with_alias(alias), (f"“{group.given}” is read as “{means}” in question {group.question} "
                                            f"({group.part}) for everyone")
    answers = group.answers
    who = form.get("student", EVERYONE)
    if who != EVERYONE:
        answers = tuple(a for a in answers if a.student == who)
        if not answers:
            raise Invalid("student", "choose the students this decision is for")
    comment = shown(form.get("comment", ""), COMMENT_LENGTH)
    points = None
    if choice == REJECT and not comment:
        raise Invalid("comment", "a rejected answer needs a comment: the student reads it in their feedback")
    if choice == ACCEPT:
        points = _points(form.get("points", ""), group.max_points)
    for answer in answers:
        decisions = decisions.with_decision(Decision(
            student=answer.student, question=group.question, part=group.part, answer=answer.given, decision=choice,
            reviewer=reviewer, reason=reason, points=points, comment=comment, template=group.template))
    whom = answers[0].student if len(answers) == 1 else f"{len(answers)} students"
    what = ("rejected" if choice == REJECT else
            "accepted" + (" for full marks" if points is None else f" for {points:g} of {group.max_points:g}"))
    return decisions, f"question {group.question} ({group.part}) {what} for {whom}"


def withdraw(decisions: Decisions, group: Group) -> tuple[Decisions, str]:
    """The decisions without any on this group's answers: its alias, and each student's decision, whether it
    still matches the answer or not."""
    left = decisions.without_alias(group.question, group.part, group.alias.spelling) if group.alias else decisions
    for answer in group.answers:
        if answer.decision is not None or answer.stale is not None:
            left = left.without_decision(answer.student, group.question, group.part)
    if left == decisions:
        raise Invalid("decision", "there is no decision on these answers to take back")
    return left, f"the decisions on question {group.question} ({group.part}) “{group.given}” taken back"


def _text(form: dict[str, str], name: str, limit: int, what: str) -> str:
    value = shown(form.get(name, ""), limit)
    if not value:
        raise Invalid(name, f"give {what}")
    return value


def _points(text: str, max_points: float) -> float | None:
    """Blank: the part's full marks; else a number above 0 and at most the part's points."""
    text = text.strip()
    if not text:
        return None
    try:
        value = float(text.replace(",", "."))
    except ValueError:
        raise Invalid("points", f"give the points as a number from 0 to {max_points:g}, or leave it blank "
                                "for full marks") from None
    if not math.isfinite(value) or value <= 0 or value > max_points:
        raise Invalid("points", f"give more than 0 and at most {max_points:g} points (reject the answer for 0)")
    return None if value == max_points else value
