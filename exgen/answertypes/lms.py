"""What a learning system can be told about an answer: the gaps a part becomes in an export.

A learning system knows a few response kinds: a number within an absolute tolerance, one of a list
of choices. Each answer type says which gaps its part becomes (`AnswerType.lms_gaps`): a number is one
numeric gap, a polar answer two (its size and its angle), a formula none (NoLmsForm says why). The
exporters (exgen.export) write each kind of gap in their own format and never ask which type made it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

from ..errors import ExgenError


class NoLmsForm(ExgenError, ValueError):
    """A part no learning-system response can grade (a formula, compared at points): says why."""


@dataclass(frozen=True)
class Wrong:
    """A known wrong answer, marked 0 where the format allows it, with the feedback it earns."""

    value: float | str
    message: str
    name: str
    tolerance: float = 0.0


@dataclass(frozen=True)
class NumericGap:
    """A number in the asked unit, right within ±`tolerance`; `also` are values as right (an angle a
    turn on). `units` are (name, multiplier) pairs a format with units accepts: the answer in that unit
    is the value × multiplier, the asked unit first with 1."""

    key: str
    value: float
    tolerance: float
    unit: str = ""
    label: str = ""
    also: tuple[float, ...] = ()
    units: tuple[tuple[str, float], ...] = ()
    wrong: tuple[Wrong, ...] = ()
    share: Fraction = Fraction(1)
    whole: bool = False
    otherwise: str = ""  # the feedback for any other answer
    kind: str = field(default="numeric", init=False)

    @property
    def values(self) -> tuple[float, ...]:
        """Every value marked right, the key's first."""
        return (self.value, *self.also)


@dataclass(frozen=True)
class ChoiceGap:
    """One of `choices`, `correct` right; `wrong` holds the feedback for the choices a known mistake gives."""

    key: str
    choices: tuple[str, ...]
    correct: str
    label: str = ""
    wrong: tuple[Wrong, ...] = ()
    share: Fraction = Fraction(1)
    unit: str = ""
    kind: str = field(default="choice", init=False)


Gap = NumericGap | ChoiceGap


def wrong_numbers(mistakes: dict, tolerance_of, right: tuple[float, ...]) -> tuple[Wrong, ...]:
    """The named mistakes (name -> (value, message), in the order the grader tries them) as 0 % answers,
    each within the tolerance the part would give it. A value that is not a finite number, that lands
    among the right answers or on an earlier mistake (the grader would name that one) is left out."""
    out: list[Wrong] = []
    for name, (value, message) in mistakes.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            continue
        tolerance = tolerance_of(float(value))
        taken = (*right, *(w.value for w in out))
        if any(abs(float(value) - r) <= tolerance for r in taken):
            continue
        out.append(Wrong(float(value), message, name, tolerance))
    return tuple(out)
