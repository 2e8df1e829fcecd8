"""Mark the parts of one question against its Variant: read, compare, carry errors forward, name mistakes.

The order of judgement for a part: no answer; a format problem (no marks, said apart from
wrong); a quantity of the wrong kind; right within tolerance; right from the student's own
earlier answers (error carried forward: the solver re-run with them); otherwise wrong, with
the mistake named when its value is recognised.
"""
from __future__ import annotations

from typing import Any, Mapping

from exgen import units
from exgen.assignment import Question
from exgen.derivation import Derivation
from exgen.errors import DimensionError, ExgenError, QuantityError
from exgen.template import PartSpec
from exgen.variant import Answer, Polar, answer_for, mistakes_for, rerun

from . import checks
from .mistakes import CLOSE_FACTOR, generic_mistake, template_mistake, tolerance_text
from .reading import NUMERIC_TYPES, Given, is_blank, read_answer, wrong_kind_message
from .results import BLANK, CARRIED, CORRECT, UNREADABLE, WRONG, PartResult, QuestionResult

NO_ANSWER = "no answer given"
RIGHT = "correct"
CARRIED_FORWARD = "correct from your {parts}"
FORMAT_PROBLEM = ("{reason}. This is a format problem, not a wrong answer: write a number with an "
                  "optional unit, such as \"{example}\".")
CHOICE_FORMAT = "{reason}. This is a format problem, not a wrong answer: write one of {choices}."
NOT_WITHIN = "not within {tol} of the expected value"
NOT_EXACT = "not the expected whole number"
NOT_A_WHOLE_NUMBER = "a whole number is asked"
WRONG_CHOICE = "not the right choice"
WRONG_KIND = "wrong_kind"
ZERO_FRACTION = 1e-9  # below this fraction of the key, a value counts as zero


class QuestionMarker:
    """Marks the parts of one question in order, remembering earlier answers for error carried forward."""

    def __init__(self, question: Question):
        self.question = question
        self.variant = question.variant
        self.readings: dict[str, Given] = {}  # readable answers of the right kind, by part id
        self.right: set[str] = set()          # parts right against the key itself
        self._reruns: dict[tuple, Derivation | None] = {}

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
        """Grade one part; `problem` is a reason the answer file gave no readable text for it."""
        answer = self.variant.answers[part.id]
        result = _Result(part, answer, self.variant.asks.get(part.id, part.ask), text, self.question.scale)
        if problem:
            return result.make(UNREADABLE, _format_problem(part, problem))
        if is_blank(text):
            return result.make(BLANK, NO_ANSWER)
        try:
            given = read_answer(text, part)
        except DimensionError as exc:
            return result.make(WRONG, wrong_kind_message(exc, part.unit), WRONG_KIND)
        except QuantityError as exc:
            return result.make(UNREADABLE, _format_problem(part, str(exc)))
        if part.type == "choice" and not any(checks.choice(given.value, c, checks.choice_aliases()) for c in part.choices):
            return result.make(UNREADABLE, _format_problem(part, f"'{_short(text)}' is not one of the choices"))
        self.readings[part.id] = given
        matches = checks.for_part(part)
        if _safe(matches, given.value, answer.value):
            self.right.add(part.id)
            return result.make(CORRECT, RIGHT)
        carried = self._carried(part)
        if carried and _safe(matches, given.value, carried[0].value):
            return result.make(CARRIED, CARRIED_FORWARD.format(parts=_names(carried[2])))
        recorded = [self.variant.mistakes.get(part.id, {})] + ([carried[1]] if carried else [])
        mistake = template_mistake(part, given.value, recorded, matches)
        if mistake is None:
            mistake = generic_mistake(part, given, answer.value, matches, checks.for_part(part, CLOSE_FACTOR))
        if mistake is not None:
            return result.make(WRONG, mistake.message, mistake.name)
        return result.make(WRONG, _plain_wrong(part, given))

    def _carried(self, part: PartSpec) -> tuple[Answer, dict[str, Any], list[str]] | None:
        """The part's answer re-derived from the student's answers to the parts it uses, if any is wrong."""
        wrong = [u for u in part.uses if u in self.readings and u not in self.right]
        if not wrong or any(_degenerate(self.readings[u].value, self.variant.answers[u].value) for u in wrong):
            return None
        template = self.variant.template
        overrides = {}
        try:
            for used_id in part.uses:
                used = template.part(used_id)
                if used_id not in self.readings:
                    continue
                value = self.readings[used_id].value
                if used.type in NUMERIC_TYPES:
                    step = self.variant.step(used.answer)
                    overrides[used.answer] = units.convert(float(value), used.unit, step.unit)
                elif used.type == "polar":  # both halves: the size in its step's unit, the angle in its own
                    overrides[used.answer] = units.convert(value.magnitude, used.unit, self.variant.step(used.answer).unit)
                    overrides[used.angle] = units.convert(value.angle_deg, "deg", self.variant.step(used.angle).unit)
        except (ExgenError, StopIteration, ValueError, ArithmeticError):
            return None
        derivation = self._rerun(overrides)
        if derivation is None:
            return None
        try:
            carried = answer_for(part, derivation)
            found = mistakes_for(part, derivation)
        except (ExgenError, ValueError, ArithmeticError, KeyError):
            return None
        if _degenerate(carried.value, self.variant.answers[part.id].value):
            return None
        return carried, found, wrong

    def _rerun(self, overrides: dict[str, float]) -> Derivation | None:
        key = tuple(sorted(overrides.items()))
        if key not in self._reruns:
            try:
                self._reruns[key] = rerun(self.variant, overrides)
            except (ExgenError, ValueError, ArithmeticError):
                self._reruns[key] = None  # the solver rejects the student's values: no error carried forward
        return self._reruns[key]


class _Result:
    """The fields every outcome of one part shares."""

    def __init__(self, part: PartSpec, answer: Answer, ask: str, text: str, scale: float):
        self.part, self.answer, self.ask, self.text = part, answer, ask, text or ""
        self.max_points = part.points * scale

    def make(self, status: str, message: str, mistake: str | None = None) -> PartResult:
        points = self.max_points if status in (CORRECT, CARRIED) else 0.0
        return PartResult(self.part.id, self.ask, self.part.unit, self.text, self.answer.text, status,
                          points, self.max_points, message, mistake)


def _degenerate(value, key) -> bool:
    """A zero where the key is not: an answer of 0 for a speed makes every later power 0, and a
    trivial 0 carried forward earns nothing."""
    if not isinstance(value, (int, float)) or not isinstance(key, (int, float)):
        return False
    return key != 0 and abs(value) <= ZERO_FRACTION * abs(key)


def _safe(matches, given, expected) -> bool:
    try:
        return bool(matches(given, expected))
    except (TypeError, ValueError, ArithmeticError):
        return False


def _names(part_ids: list[str]) -> str:
    shown = [f"({p})" for p in part_ids]
    return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1]


def _short(text: str, limit: int = 40) -> str:
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "\u2026"


def _format_problem(part: PartSpec, reason: str) -> str:
    reason = reason.rstrip(".")
    if part.type == "choice":
        return CHOICE_FORMAT.format(reason=reason, choices=", ".join(part.choices))
    if part.type == "polar":
        return FORMAT_PROBLEM.format(reason=reason, example=Polar(12.5, 30.0).text(part.unit))
    example = units.format_quantity(12.5, part.unit, 3) if part.type != "integer" else "4"
    return FORMAT_PROBLEM.format(reason=reason, example=example)


def _plain_wrong(part: PartSpec, given: Given) -> str:
    if part.type == "choice":
        return WRONG_CHOICE
    if part.type == "integer":
        value = float(given.value)
        return NOT_EXACT if value.is_integer() else NOT_A_WHOLE_NUMBER
    return NOT_WITHIN.format(tol=tolerance_text(part))
