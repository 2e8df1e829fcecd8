"""A magnitude at an angle (a balancing mass-radius, a force with its direction): "0.85 kg m at 218 deg",
"remove 0.85 @ 38°", "0.85∠218". The size within a relative tolerance, the direction within an
absolute one in degrees, modulo a turn; "remove m at θ" is "add m at θ + 180°". Two solver steps
hold it: `answer:` the size and `angle:` the direction.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction
from typing import Mapping

from .. import units
from ..errors import ExgenError, NoAnswer, QuantityError
from ..load.template import PartSpec, Tolerance
from .angle import ANGLE_ABS_TOL_DEG, angle, direction_slip
from .base import AnswerType, Given, Mistake, Report, asked_unit, exact_quantity, refuse_long
from .lms import NumericGap, wrong_numbers
from .number import PREFIXES, REL_TOL, numeric, readings
from .quantity import accepted_units
from .quantity import in_unit

_POLAR = re.compile(r"(?:(add|remove|subtract|take away)\s+)?(.+?)\s*(?:\bat\b|@|\u2220|<)\s*(.+)", re.IGNORECASE)
_REMOVE = ("remove", "subtract", "take away")
# Also a pair, as written in working: "(0.57 kg, 48°)", "m = 0.57 kg; θ = 48°", "0.57 kg 48°". The angle
# must carry its unit, so that a decimal comma ("0,57 kg at 48°") is never taken for the separator.
_ANGLE_LAST = r"(?:[^\W\d_]{1,3}\s*=\s*)?[+\-\u2212]?(?:\d+\.?\d*|\.\d+)\s*(?:\u00b0|\u00ba|deg(?:rees?)?|rad(?:ians?)?)\.?"
_PAIR = re.compile(rf"(?:(add|remove|subtract|take away)\s+)?\(?\s*(.+?)\s*(?:[,;]|\s)\s*({_ANGLE_LAST})\s*\)?",
                   re.IGNORECASE)

OPPOSITE_SIDE = ("That direction is exactly opposite the right one. To add balancing mass, put it at the "
                 "angle found; half a turn away is where mass would be removed (write \"remove ... at ...\" "
                 "if that is what you mean).")
MAGNITUDE_ONLY = "The magnitude is right; the angle is not."
ANGLE_ONLY = "The angle is right; the magnitude is not."


@dataclass(frozen=True)
class Polar:
    """A magnitude at an angle, normalised so the magnitude is not negative and the angle (degrees)
    is in [0, 360): "remove m at θ" is the same answer as "add m at θ + 180°"."""

    magnitude: float
    angle_deg: float

    @classmethod
    def of(cls, magnitude: float, angle_deg: float) -> "Polar":
        if magnitude < 0:
            magnitude, angle_deg = -magnitude, angle_deg + 180.0
        return cls(magnitude, angle_deg % 360.0)

    def text(self, unit: str) -> str:
        return f"{units.format_quantity(self.magnitude, unit)} at {units.format_quantity(self.angle_deg, 'deg')}"


def polar(given: Polar, expected: Polar, rel: float = REL_TOL, abs_deg: float = ANGLE_ABS_TOL_DEG) -> bool:
    """The magnitude within `rel`, the direction within `abs_deg` modulo a turn; a zero has no direction
    (a polygon that closes: any angle written with 0 is that zero)."""
    if given.magnitude == expected.magnitude == 0:
        return True
    return numeric(given.magnitude, expected.magnitude, rel) and angle(given.angle_deg, expected.angle_deg, 0.0, abs_deg)


class PolarType(AnswerType):
    name = "polar"
    part_keys = ("angle",)
    tol_keys = ("rel", "abs")
    default_tol = Tolerance(rel=REL_TOL, abs=ANGLE_ABS_TOL_DEG)

    def load_options(self, spec: Mapping, report: Report) -> dict:
        if not spec.get("angle"):
            report(("angle",), "a polar answer needs `angle:`, the step holding its angle")
        return {"angle": str(spec.get("angle") or "")}

    # ---- variants ----------------------------------------------------------------------------

    def steps(self, part: PartSpec) -> tuple[str, ...]:
        return (part.answer, part.options["angle"])

    def expected(self, part: PartSpec, derivation) -> Polar:
        size = self.step_value(part, derivation, part.answer)
        direction = part.options["angle"]
        if direction not in derivation:
            raise ExgenError(f"{direction!r} (angle of part {part.id}) is not a step the solver records")
        return self._polar(part, derivation, size, derivation[direction].value)

    def mistake_values(self, part: PartSpec, derivation) -> dict[str, Polar]:
        """A mistake recorded on one of the two steps keeps the right value of the other."""
        direction = part.options["angle"]
        sizes = derivation.mistakes.get(part.answer, {})
        angles = derivation.mistakes.get(direction, {})
        right_size, right_angle = derivation[part.answer].value, derivation[direction].value
        out = {}
        for name in {**sizes, **angles}:
            try:
                out[name] = self._polar(part, derivation, sizes.get(name, right_size), angles.get(name, right_angle))
            except NoAnswer:
                continue
        return out

    @staticmethod
    def _polar(part: PartSpec, derivation, magnitude, direction) -> Polar:
        """A polar answer in the asked unit, from SI magnitude and angle (rad)."""
        if not all(isinstance(v, (int, float)) and math.isfinite(v) for v in (magnitude, direction)):
            raise NoAnswer(f"part {part.id}: answer {magnitude!r} at {direction!r} is not finite")
        size = units.convert(float(magnitude), derivation[part.answer].unit, part.unit)
        return Polar.of(size, units.convert(float(direction), derivation[part.options["angle"]].unit, "deg"))

    def problem(self, value, part: PartSpec) -> str | None:
        if not (math.isfinite(value.magnitude) and math.isfinite(value.angle_deg)):
            return f"answer {value!r} is not finite"
        return None

    def text(self, value: Polar, part: PartSpec) -> str:
        return value.text(part.unit)

    def worked_values(self, answer, step_name: str):
        if step_name == answer.part.options["angle"]:
            return ((answer.value.angle_deg, "deg"),)
        return ((answer.value.magnitude, answer.part.unit),)

    # ---- display -----------------------------------------------------------------------------

    def hint(self, part: PartSpec) -> str:
        return f"{asked_unit(part) or 'magnitude'} at an angle in degrees"

    def form_hint(self, part: PartSpec) -> str:
        return f"{asked_unit(part) or 'size'} at deg, e.g. 1.5 {asked_unit(part)} at 218 deg"

    def tolerance_text(self, part: PartSpec) -> str:
        return f"{100 * part.tol.rel:g} % in size and {exact_quantity(part.tol.abs, 'deg')} in angle"

    # ---- grading -----------------------------------------------------------------------------

    def read(self, text: str, part: PartSpec) -> Given:
        refuse_long(text)
        match = _POLAR.fullmatch(text.strip()) or _PAIR.fullmatch(text.strip())
        if not match:
            raise QuantityError(f"cannot read {text.strip()!r} as a magnitude at an angle, such as "
                                f"\"{self.example(part).text(part.unit)}\"")
        action, size_text, angle_text = match.groups()
        size_reading, size = in_unit(size_text, part.unit)
        _, angle_deg = in_unit(angle_text, "deg")
        if action and action.lower() in _REMOVE:
            size = -size
        return Given(text, Polar.of(size, angle_deg), size_reading.value, size_reading.unit)

    def example(self, part: PartSpec) -> Polar:
        return Polar(12.5, 30.0)

    def format_hint(self, part: PartSpec) -> str:
        return f"write a number with an optional unit, such as \"{self.example(part).text(part.unit)}\""

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        return polar(given, expected, part.tol.rel * widen, part.tol.abs * widen)

    def gives_away(self, value, answer) -> bool:
        """Either half: the size in any unit of its kind, or the direction in degrees or radians."""
        part, key = answer.part, answer.value
        return any(numeric(abs(v), key.magnitude, part.tol.rel) for v in readings(value, part.unit, PREFIXES)) or \
            any(angle(v, key.angle_deg, 0.0, part.tol.abs) for v in readings(value, "deg"))

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        return f"not within {self.tolerance_text(part)} of the expected value"

    def slip(self, given: Given, expected, part: PartSpec) -> Mistake | None:
        """Which half of the answer is wrong, and why the angle might be."""
        value = given.value
        size_right = numeric(value.magnitude, expected.magnitude, part.tol.rel)
        angle_right = angle(value.angle_deg, expected.angle_deg, 0.0, part.tol.abs)
        if size_right and not angle_right:
            return direction_slip(value.angle_deg, expected.angle_deg, part.tol.abs, OPPOSITE_SIDE) or \
                Mistake("angle_wrong", MAGNITUDE_ONLY)
        if angle_right and not size_right:
            return Mistake("magnitude_wrong", ANGLE_ONLY)
        return None

    def nudges(self, value: Polar, part: PartSpec) -> tuple[Polar, ...]:
        size = value.magnitude or 1.0
        return tuple(Polar.of(size * k, value.angle_deg + turn) for k, turn in ((1.02, 2.0), (0.5, 90.0), (2.0, 180.0)))

    def overrides(self, part: PartSpec, value: Polar, variant) -> dict[str, float]:
        """Both halves: the size in its step's unit, the angle in its own."""
        direction = part.options["angle"]
        return {part.answer: units.convert(value.magnitude, part.unit, variant.step(part.answer).unit),
                direction: units.convert(value.angle_deg, "deg", variant.step(direction).unit)}

    # ---- learning systems ----------------------------------------------------------------------

    def lms_gaps(self, part: PartSpec, value: Polar, mistakes) -> tuple[NumericGap, NumericGap]:
        """Two numbers, each for half the part's marks: the size within its relative tolerance and the
        angle within its tolerance in degrees (a turn either way right too). A learning system cannot
        read "remove m at θ" as "add m at θ + 180°": the form asks for the mass to add."""
        def size_tol(v: float) -> float:
            return part.tol.rel * abs(v)

        def angle_tol(v: float) -> float:
            return part.tol.abs

        # A gap sees one half only: it names a slip only where that half's window and the right one's do not
        # meet, so a size just outside the tolerance, typed with the right angle, is not told of a slip that
        # differs in its angle alone (exgen's grader, reading both halves, names none there either).
        def sizes_meet(size: float) -> bool:
            return abs(size - value.magnitude) <= size_tol(size) + size_tol(value.magnitude)

        sizes = {n: (m.magnitude, say) for n, (m, say) in mistakes.items() if not sizes_meet(m.magnitude)}
        angles = {n: (m.angle_deg, say) for n, (m, say) in mistakes.items()
                  if not angle(m.angle_deg, value.angle_deg, 0.0, 2 * part.tol.abs)}
        turns = (value.angle_deg - 360.0, value.angle_deg + 360.0)
        half = Fraction(1, 2)
        return (
            NumericGap("size", value.magnitude, size_tol(value.magnitude), units.pretty_unit(part.unit), "size",
                       units=accepted_units(part.unit), wrong=wrong_numbers(sizes, size_tol, (value.magnitude,)), share=half,
                       otherwise=f"the size is not within {100 * part.tol.rel:g} % of the expected one"),
            NumericGap("angle", value.angle_deg, part.tol.abs, "\u00b0", "angle", also=turns,
                       units=accepted_units("deg"), wrong=wrong_numbers(angles, angle_tol, (value.angle_deg, *turns)),
                       share=half, otherwise=f"the angle is not within {exact_quantity(part.tol.abs, 'deg')} of the expected one"),
        )

    def sample_part(self) -> PartSpec:
        return PartSpec("a", "the balancing mass-radius", "mr", "kg*mm", type=self.name, tol=self.default_tol,
                        options={"angle": "theta"})


TYPE = PolarType()
