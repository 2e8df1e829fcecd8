"""Mark the parts of one question against its Variant: read, compare, carry errors forward, name mistakes.

The order of judgement for a part: no answer; a format problem (no marks, said apart from
wrong); an answer of the wrong kind; right within tolerance; right from the student's own
earlier answers (error carried forward: the solver re-run with them); otherwise wrong, with
the mistake named when its value is recognised. What reading, comparing and the messages mean
for each kind of answer is its answer type's (exgen.answertypes).
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Mapping

from exgen.answertypes import answer_type
from exgen.answertypes.base import Given
from exgen.errors import ExgenError, FormatProblem, SolverFailure, WrongKind
from exgen.issue.assignment import Question
from exgen.load.template import PartSpec
from exgen.solve.derivation import Derivation
from exgen.solve.variant import Answer, answer_for, mistakes_for, rerun

from .decisions import Alias, spelling_key
from .mistakes import generic_mistake, template_mistake
from .why_not import why_not
from .results import ALIAS, BLANK, CARRIED, CORRECT, UNREADABLE, WRONG, PartResult, QuestionResult, Review

NO_ANSWER = "no answer given"
RIGHT = "correct"
CARRIED_FORWARD = "correct from your {parts}"
#: Added to a wrong answer's feedback when the working could not be carried on from the student's own
#: earlier answers, so no credit could be carried forward (the reason is the instructor's, in report.md).
NOT_CARRIED = "No credit could be carried forward from your {parts}: the working cannot be carried on from {them}"
FORMAT_PROBLEM = "{reason}. This is a format problem, not a wrong answer: {how}."
WRONG_KIND = "wrong_kind"
ZERO_FRACTION = 1e-9  # below this fraction of the key, a value counts as zero
_WORDS_BLANK = ("", "~", "null", "none", "-")
#: Added to the feedback of an answer read by a spelling accepted in review.
READ_AS = "Your answer was read as '{means}', a spelling accepted in review"


class QuestionMarker:
    """Marks the parts of one question in order, remembering earlier answers for error carried forward.
    `aliases` are the spellings accepted in review, by part id and spelling_key (graders.review): such an
    answer is read as what it means, then marked as any other."""

    def __init__(self, question: Question, aliases: Mapping[str, Mapping[str, Alias]] | None = None):
        self.question = question
        self.aliases = aliases or {}
        self.variant = question.variant
        self.readings: dict[str, Given] = {}  # readable answers of the right kind, by part id
        self.right: set[str] = set()          # parts right against the key itself (within tolerance)
        self._reruns: dict[tuple, Derivation | str] = {}  # the derivation, or why there is none

    def mark(self, answers: Mapping[str, str], problems: Mapping[str, str] | None = None) -> QuestionResult:
        problems = problems or {}
        whole = problems.get("")
        results = tuple(
            self.part(part, answers.get(part.id, ""), whole or problems.get(part.id))
            for part in self.variant.template.parts
        )
        template = self.variant.template
        return QuestionResult(self.question.number, self.question.slot, template.title, template.id,
                              results, self.question.points)

    def part(self, part: PartSpec, text: str, problem: str | None = None) -> PartResult:
        """Grade one part; `problem` is a reason the answer file gave no readable text for it. An answer
        spelled as an alias is marked as what it means, and carries what it would have scored without."""
        alias = None if problem or is_blank(text) else self.aliases.get(part.id, {}).get(spelling_key(text))
        if alias is None:
            return self._part(part, text, problem)
        readings, right = dict(self.readings), set(self.right)
        before = self._part(part, text)
        self.readings, self.right = readings, right  # later parts are worked from the alias's reading
        after = self._part(part, alias.means)
        review = Review(ALIAS, before.status, before.points, alias.reviewer, alias.reason, spelling=alias.spelling,
                        means=alias.means, line=alias.line)
        message = f"{after.message.rstrip('.')}. {READ_AS.format(means=alias.means)}"
        return replace(after, given=before.given, message=message, review=review)

    def _part(self, part: PartSpec, text: str, problem: str | None = None) -> PartResult:
        kind = answer_type(part)
        answer = self.variant.answers[part.id]
        result = _Result(part, answer, self.variant.asks.get(part.id, part.ask), text, self.question.scale)
        if problem:
            return result.make(UNREADABLE, _format_problem(part, problem))
        if is_blank(text):
            return result.make(BLANK, NO_ANSWER)
        try:
            given = kind.read(text, part)
        except WrongKind as exc:
            return result.make(WRONG, str(exc), WRONG_KIND)
        except FormatProblem as exc:
            return result.make(UNREADABLE, _format_problem(part, str(exc)))
        self.readings[part.id] = given

        def matches(value, expected, widen: float = 1.0) -> bool:
            return kind.matches(value, expected, part, widen)

        if _safe(matches, given.value, answer.value):
            self.right.add(part.id)
            return result.make(CORRECT, RIGHT)
        carried = self._carried(part)
        if isinstance(carried, _NotCarried):
            result.not_carried = carried
            carried = None
        if carried and _safe(matches, given.value, carried[0].value):
            return result.make(CARRIED, CARRIED_FORWARD.format(parts=_names(carried[2])))
        recorded = [self.variant.mistakes.get(part.id, {})] + ([carried[1]] if carried else [])
        mistake = template_mistake(part, given.value, recorded, matches, self.variant.fill) or generic_mistake(part, given, answer.value)
        if mistake is not None:
            return result.make(WRONG, mistake.message, mistake.name)
        why = why_not(self.variant, part, given)
        return result.make(WRONG, kind.wrong_message(given, part) + (f". {why}" if why else ""))

    def _carried(self, part: PartSpec) -> tuple[Answer, dict[str, Any], list[str]] | _NotCarried | None:
        """The part's answer re-derived from the student's answers to the parts it uses, if any is not the
        key's own value: wrong, or right within its tolerance but not exact (a length read off a drawing, an
        answer rounded), since a later part worked from such an answer can fall outside its own tolerance.
        None where nothing is carried by rule (every earlier answer the key's, or a trivial zero), and the
        reason where the working could not be carried on from a wrong one."""
        differing = [u for u in part.uses if u in self.readings
                     and (u not in self.right or _differs(self.readings[u].value, self.variant.answers[u].value))]
        wrong = [u for u in differing if u not in self.right]
        if not differing or any(_degenerate(self.readings[u].value, self.variant.answers[u].value) for u in wrong):
            return None
        worked = self._worked_from(part)
        if isinstance(worked, str):   # why the working cannot go on: the student's to hear only if one was wrong
            return _NotCarried(wrong, worked) if wrong else None
        return worked and (*worked, wrong or differing)   # the message names the wrong ones, if any

    def _worked_from(self, part: PartSpec) -> tuple[Answer, dict[str, Any]] | str | None:
        """The part's answer and its slips' values worked from the student's answers to the parts it uses;
        why the working cannot go on from them; or None where it gives a trivial zero."""
        template = self.variant.template
        overrides = {}
        try:
            for used_id in part.uses:
                if used_id in self.readings:
                    used = template.part(used_id)
                    overrides.update(answer_type(used).overrides(used, self.readings[used_id].value, self.variant))
        except (ExgenError, ArithmeticError) as exc:  # a value its step cannot take (a unit, an overflow)
            return _reason(exc)
        derivation = self._rerun(overrides)
        if isinstance(derivation, str):
            return derivation
        try:
            carried = answer_for(part, derivation)
            found = mistakes_for(part, derivation)
        except ExgenError as exc:  # the working gives no answer of the asked kind from them
            return _reason(exc)
        if _degenerate(carried.value, self.variant.answers[part.id].value):
            return None
        return carried, found

    def _rerun(self, overrides: dict[str, Any]) -> Derivation | str:
        """The derivation worked from the student's values, or why it cannot be (the solver refuses
        them or fails on them): kept, since several parts may be worked from the same answers."""
        key = tuple(sorted((name, _key(value)) for name, value in overrides.items()))
        if key not in self._reruns:
            try:
                self._reruns[key] = rerun(self.variant, overrides)
            except ExgenError as exc:
                self._reruns[key] = _reason(exc)
        return self._reruns[key]


class _NotCarried:
    """Why the answer to a part could not be worked from the student's wrong earlier answers."""

    def __init__(self, parts: list[str], reason: str):
        self.parts, self.reason = parts, reason

    @property
    def sentence(self) -> str:
        return NOT_CARRIED.format(parts=_names(self.parts), them="them" if len(self.parts) > 1 else "it")


def _reason(exc: ExgenError) -> str:
    """What stopped the working, for the instructor: the exception and where, for a solver's failure."""
    if isinstance(exc, SolverFailure):
        return f"{exc.reason}" + (f" at {exc.where}" if exc.where else "")
    return str(exc)


class _Result:
    """The fields every outcome of one part shares."""

    def __init__(self, part: PartSpec, answer: Answer, ask: str, text: str, scale: float):
        self.part, self.answer, self.ask, self.text = part, answer, ask, text or ""
        self.max_points = part.points * scale
        self.not_carried: _NotCarried | None = None

    def make(self, status: str, message: str, mistake: str | None = None) -> PartResult:
        points = self.max_points if status in (CORRECT, CARRIED) else 0.0
        why = ""
        if self.not_carried is not None and status == WRONG:
            message = f"{message.rstrip('.')}. {self.not_carried.sentence}"
            why = self.not_carried.reason
        return PartResult(self.part.id, self.ask, self.part.unit, self.text, self.answer.text, status,
                          points, self.max_points, message, mistake, self.answer.value, why)


def is_blank(text: str | None) -> bool:
    return text is None or text.strip().lower() in _WORDS_BLANK


def _key(value) -> Any:
    """A hashable stand-in for an override value (numbers are; an answer object may not be)."""
    try:
        hash(value)
        return value
    except TypeError:
        return repr(value)


def _differs(value, key) -> bool:
    """Whether an answer read as right is other than the key's own value (beyond float noise)."""
    if isinstance(value, (int, float)) and isinstance(key, (int, float)):
        return not math.isclose(value, key, rel_tol=1e-9, abs_tol=1e-300)
    return _key(value) != _key(key)


def _degenerate(value, key) -> bool:
    """A zero where the key is not: an answer of 0 for a speed makes every later power 0, and a
    trivial 0 carried forward earns nothing."""
    if not isinstance(value, (int, float)) or not isinstance(key, (int, float)):
        return False
    return key != 0 and abs(value) <= ZERO_FRACTION * abs(key)


def _safe(matches, given, expected) -> bool:
    """A comparison that overflows or leaves a number's domain is no match; any other error is a defect
    of the answer type and is raised."""
    try:
        return bool(matches(given, expected))
    except (ValueError, ArithmeticError):
        return False


def _names(part_ids: list[str]) -> str:
    shown = [f"({p})" for p in part_ids]
    return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1]


def _format_problem(part: PartSpec, reason: str) -> str:
    return FORMAT_PROBLEM.format(reason=reason.rstrip("."), how=answer_type(part).format_hint(part))
