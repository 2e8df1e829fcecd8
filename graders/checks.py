"""Small pure comparators, one per method; defaults are the grading rules of DESIGN.md.

Each takes the student's value and the expected one in the same unit and answers True/False.
None of them reads text or knows about parts: `graders.grade` picks one by the part's type.
"""
from __future__ import annotations

import math
from functools import lru_cache
from importlib import resources
from typing import Any, Callable, Mapping

from exgen import units

#: A number is right within 1 % (textbook working rounds to 3-4 figures) ...
REL_TOL = 0.01
#: ... or within this absolute floor, for answers that can be zero.
ABS_TOL = 0.0
#: Angles: within half a degree, compared modulo a full turn.
ANGLE_ABS_TOL_DEG = 0.5
FULL_TURN_DEG = 360.0
#: With significant figures, the given value may differ by this many units in the last figure.
SIG_FIG_SLACK = 0.51


def numeric(given: float, expected: float, rel: float = REL_TOL, abs_tol: float = ABS_TOL,
            sig: int | None = None) -> bool:
    """Within `rel` of the expected value or within `abs_tol` of it; with `sig`, within half a unit
    in the sig-th significant figure instead of `rel`."""
    if not (math.isfinite(given) and math.isfinite(expected)):
        return False
    error = abs(given - expected)
    if error <= abs_tol:
        return True
    if sig:
        return error <= sig_fig_tolerance(expected, sig)
    return error <= rel * abs(expected)


def sig_fig_tolerance(expected: float, sig: int) -> float:
    """Half a unit (a little more, for float noise) in the sig-th significant figure of `expected`."""
    if expected == 0:
        return 0.0
    power = math.floor(math.log10(abs(expected)))
    return SIG_FIG_SLACK * 10.0 ** (power - sig + 1)


def angle(given_deg: float, expected_deg: float, rel: float = 0.0, abs_tol: float = ANGLE_ABS_TOL_DEG,
          period: float = FULL_TURN_DEG) -> bool:
    """Equal as directions: -142 deg is 218 deg. Tolerance is the larger of `abs_tol` and `rel` x |expected|."""
    if not (math.isfinite(given_deg) and math.isfinite(expected_deg)):
        return False
    gap = (given_deg - expected_deg) % period
    gap = min(gap, period - gap)
    return gap <= max(abs_tol, rel * abs(expected_deg))


def polar(given, expected, rel: float = REL_TOL, abs_deg: float = ANGLE_ABS_TOL_DEG) -> bool:
    """A magnitude at an angle: the magnitude within `rel`, the direction within `abs_deg` modulo a turn.
    Both are normalised (exgen.variant.Polar), so "remove m at θ" equals "add m at θ + 180°"."""
    return numeric(given.magnitude, expected.magnitude, rel) and angle(given.angle_deg, expected.angle_deg, 0.0, abs_deg)


def integer(given: float, expected: float) -> bool:
    """Exactly the expected whole number ("4" and "4.0" are 4; "3.99" is not)."""
    return math.isfinite(given) and float(given) == float(expected) and float(given).is_integer()


def canonical(name: str) -> str:
    """'Crossed belt', 'crossed-belt' and ' CROSSED_belt ' all read as 'crossed belt'."""
    return " ".join(str(name).replace("-", " ").replace("_", " ").lower().split())


@lru_cache(maxsize=1)
def choice_aliases() -> dict[str, str]:
    """Other words for the choices templates use ("ccw" for counter-clockwise), from exgen's data."""
    text = resources.files("exgen").joinpath("data/choice_aliases.txt").read_text("utf-8")
    pairs = (line.split("=", 1) for line in text.splitlines() if line.strip() and not line.startswith("#"))
    return {a.strip(): b.strip() for a, b in pairs}


def choice(given: str, expected: str, aliases: Mapping[str, str] | None = None) -> bool:
    """The canonical name of the given choice, after aliases ({'ccw': 'anticlockwise'}), is the expected one."""
    table = {canonical(k): canonical(v) for k, v in (aliases or {}).items()}
    key = canonical(given)
    return table.get(key, key) == canonical(expected)


def for_part(part, widen: float = 1.0) -> Callable[[Any, Any], bool]:
    """The comparator a part's type and tolerance call for, as `matches(given, expected)` in the
    asked unit. `widen` scales the tolerance (to tell "close" from "wrong"). An angle part's
    absolute tolerance is in degrees whatever unit it is asked in."""
    tol = part.tol
    if part.type == "integer":
        return integer
    if part.type == "choice":
        return lambda given, expected: choice(str(given), str(expected), choice_aliases())
    if part.type == "polar":
        return lambda given, expected: polar(given, expected, tol.rel * widen, tol.abs * widen)
    if part.type == "angle":
        to_deg = units.convert(1.0, part.unit, "deg") if part.unit else 1.0
        return lambda given, expected: angle(given * to_deg, expected * to_deg, tol.rel * widen, tol.abs * widen)

    def matches(given, expected) -> bool:
        if tol.sig:
            return numeric(given, expected, 0.0, max(tol.abs, sig_fig_tolerance(expected, tol.sig)) * widen)
        return numeric(given, expected, tol.rel * widen, tol.abs * widen)

    return matches
