"""A whole number, graded exactly: a count of belts, of teeth. "4", "4.0", "4 belts" and "four" are 4 (a
count may carry the noun for what it counts); "3.99" is not a whole number. A unit, when the part asks one,
converts as for numbers, and a unit of another kind ("4 kg") is an answer of the wrong kind.
"""
from __future__ import annotations

import math
import re

from .. import units
from ..errors import FormatProblem
from ..load.template import PartSpec, Tolerance
from .base import AnswerType, Given, asked_unit, refuse_long
from .lms import NumericGap, wrong_numbers
from .number import readings
from .quantity import accepted_units, in_unit

NOT_EXACT = "not the expected whole number"
NOT_A_WHOLE_NUMBER = "a whole number is asked"
#: "5 belts", "24 teeth", "3 V-belts": a count followed by up to three words for what is counted.
_COUNT_WITH_NOUN = re.compile(r"\s*([+-]?\d{1,9}(?:\.\d{0,9})?)\s+([A-Za-z][A-Za-z-]{0,29}(?: [A-Za-z][A-Za-z-]{0,29}){0,2})\s*")


#: "five", "Five belts.": a count in words, as far as a count in this course goes.
_WORDS = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen "
          "sixteen seventeen eighteen nineteen twenty").split()
_COUNT_IN_WORDS = re.compile(rf"\s*({'|'.join(_WORDS)})(?:\s+[A-Za-z][A-Za-z-]{{0,29}}){{0,3}}\s*\.?\s*", re.IGNORECASE)


def integer(given: float, expected: float) -> bool:
    """Exactly the expected whole number ("4" and "4.0" are 4; "3.99" is not)."""
    return math.isfinite(given) and float(given) == float(expected) and float(given).is_integer()


class Integer(AnswerType):
    name = "integer"
    default_tol = Tolerance(rel=0.0, abs=0.0)

    def problem(self, value, part: PartSpec) -> str | None:
        return None if isinstance(value, int) and not isinstance(value, bool) else f"answer {value!r} is not a whole number"

    def hint(self, part: PartSpec) -> str:
        return "a whole number" + (f", in {asked_unit(part)}" if part.unit else "")

    def form_hint(self, part: PartSpec) -> str:
        return f"whole number{' of ' + asked_unit(part) if part.unit else ''}"

    def read(self, text: str, part: PartSpec) -> Given:
        refuse_long(text)
        try:
            reading, value = in_unit(text, part.unit)
        except FormatProblem:
            counted = _COUNT_WITH_NOUN.fullmatch(text)
            in_words = _COUNT_IN_WORDS.fullmatch(text)
            if in_words is not None and sum(w.lower().strip(".") in _WORDS for w in text.split()) > 1:
                in_words = None  # "one two": which?
            if counted is None and in_words is None:
                raise
            # the words name what is counted: not a unit
            number = float(counted.group(1)) if counted else float(_WORDS.index(in_words.group(1).lower()))
            return Given(text, number, number, None)
        return Given(text, value, reading.value, reading.unit)

    def example(self, part: PartSpec) -> int:
        return 4

    def format_hint(self, part: PartSpec) -> str:
        return "write a number with an optional unit, such as \"4\""

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        return integer(given, expected)

    def reach(self, value, part: PartSpec, widen: float = 1.0) -> float | None:
        """Exact: only the value itself matches."""
        return 0.0 if isinstance(value, (int, float)) and math.isfinite(value) else None

    def gives_away(self, value, answer) -> bool:
        """A count is its own number; one with a unit is read in any unit of its kind."""
        unit = answer.part.unit
        shown = readings(value, unit) if unit else list(readings(value, ""))[:1]  # a count is no percentage
        return any(integer(abs(value), abs(answer.value)) for value in shown)

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        return NOT_EXACT if float(given.value).is_integer() else NOT_A_WHOLE_NUMBER

    def nudges(self, value, part: PartSpec) -> tuple[int, ...]:
        return (value + 1, value + 2, 2 * value + 1)

    def overrides(self, part: PartSpec, value, variant) -> dict[str, float]:
        return {part.answer: units.convert(float(value), part.unit, variant.step(part.answer).unit)}

    def lms_gaps(self, part: PartSpec, value, mistakes) -> tuple[NumericGap, ...]:
        """Exactly the whole number: a tolerance of 0."""
        right = float(value)
        return (NumericGap("", right, 0.0, units.pretty_unit(part.unit), units=accepted_units(part.unit),
                           wrong=wrong_numbers(mistakes, lambda v: 0.0, (right,)), whole=True, otherwise=NOT_EXACT),)

    def sample_part(self) -> PartSpec:
        return PartSpec("a", "the number of belts", "n", type=self.name, tol=self.default_tol)


TYPE = Integer()
