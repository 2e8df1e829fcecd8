"""An angle: compared as a direction, modulo a full turn (-142° is 218°), within an absolute tolerance
in degrees (0.5° by default) whatever unit it is asked in. Generic slips named: half a turn out,
measured the other way round, from the other axis; then the number slips (units confused, rounding).
"""
from __future__ import annotations

import math

from .. import units
from ..load.template import PartSpec, Tolerance
from .base import Mistake, exact_quantity
from .lms import NumericGap, wrong_numbers
from .number import Number, readings
from .quantity import accepted_units

#: Angles: within half a degree, compared modulo a full turn.
ANGLE_ABS_TOL_DEG = 0.5
FULL_TURN_DEG = 360.0
#: The smallest tolerance (deg) at which a direction slip is recognised.
DIRECTION_TOL_DEG = 0.5

OPPOSITE_DIRECTION = "That direction is exactly opposite (180° from) the right one: check the sign of each component."
MIRRORED_ANGLE = ("Your angle is the mirror image of the right one: it is measured in the opposite sense. "
                  "Measure angles as the sheet says (from where, and which way round).")
WRONG_AXIS = ("Your angle is measured from the wrong reference line (a quarter turn out). "
              "The sheet says where 0° is and which way angles are measured.")


def angle(given_deg: float, expected_deg: float, rel: float = 0.0, abs_tol: float = ANGLE_ABS_TOL_DEG,
          period: float = FULL_TURN_DEG) -> bool:
    """Equal as directions: -142 deg is 218 deg. Tolerance is the larger of `abs_tol` and `rel` x |expected|."""
    if not (math.isfinite(given_deg) and math.isfinite(expected_deg)):
        return False
    gap = (given_deg - expected_deg) % period
    gap = min(gap, period - gap)
    return gap <= max(abs_tol, rel * abs(expected_deg))


def direction_slip(given_deg: float, expected_deg: float, tol_deg: float, opposite: str) -> Mistake | None:
    """An angle half a turn out, mirrored (measured the other way round), or a quarter turn out
    or measured from the other axis (90° - θ)."""
    tol = max(tol_deg, DIRECTION_TOL_DEG)

    def same(a, b):
        return angle(a, b, 0.0, tol)

    if same(given_deg, expected_deg + 180):
        return Mistake("opposite_side", opposite)
    if not same(expected_deg, -expected_deg) and same(given_deg, -expected_deg):
        return Mistake("mirrored_angle", MIRRORED_ANGLE)
    if any(same(given_deg, e) for e in (expected_deg + 90, expected_deg - 90, 90 - expected_deg)):
        return Mistake("wrong_axis", WRONG_AXIS)
    return None


class Angle(Number):
    name = "angle"
    tol_keys = ("rel", "abs")
    default_tol = Tolerance(rel=0.0, abs=ANGLE_ABS_TOL_DEG)

    def tolerance_text(self, part: PartSpec) -> str:
        pieces = [f"{100 * part.tol.rel:g} %"] if part.tol.rel else []
        if part.tol.abs or not pieces:
            pieces.append(exact_quantity(part.tol.abs, "deg"))
        return " or ".join(pieces)

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        to_deg = self._to_deg(part)
        return angle(given * to_deg, expected * to_deg, part.tol.rel * widen, part.tol.abs * widen)

    prefixed = False

    def gives_away(self, value, answer) -> bool:
        """A direction in degrees or radians (its mirror image, −θ, is another direction)."""
        return any(self.matches(v, answer.value, answer.part) for v in readings(value, answer.part.unit))

    def reach(self, value, part: PartSpec, widen: float = 1.0) -> float | None:
        """None: directions a turn apart match, so no distance bounds them."""
        return None

    def slip(self, given, expected, part: PartSpec) -> Mistake | None:
        if isinstance(expected, (int, float)):
            to_deg = self._to_deg(part)
            found = direction_slip(given.value * to_deg, expected * to_deg, part.tol.abs, OPPOSITE_DIRECTION)
            if found:
                return found
        return super().slip(given, expected, part)

    def detectors(self):
        return (self._unit_confused, self._percent_fraction)

    def lms_gaps(self, part: PartSpec, value, mistakes) -> tuple[NumericGap, ...]:
        """A direction within its tolerance; a learning system compares numbers, not directions, so the
        same direction a turn either way is listed as right too."""
        to_deg = self._to_deg(part)
        turn = FULL_TURN_DEG / to_deg

        def tolerance(v: float) -> float:
            return max(part.tol.abs, part.tol.rel * abs(v * to_deg)) / to_deg

        right = float(value)
        also = (right - turn, right + turn)
        return (NumericGap("", right, tolerance(right), units.pretty_unit(part.unit), also=also,
                           units=accepted_units(part.unit), wrong=wrong_numbers(mistakes, tolerance, (right, *also)),
                           otherwise=f"not within {self.tolerance_text(part)} of the expected direction"),)

    @staticmethod
    def _to_deg(part: PartSpec) -> float:
        return units.convert(1.0, part.unit, "deg") if part.unit else 1.0

    def sample_part(self) -> PartSpec:
        return PartSpec("a", "the angle of contact", "theta", "deg", type=self.name, tol=self.default_tol)


TYPE = Angle()
