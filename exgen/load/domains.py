"""The physical domain of a template's parameter: the values that make sense at all (a diameter is
positive, an efficiency is at most 100 %), as against the narrower range the template draws from.

`exgen solve` refuses a value outside the domain. A parameter declares its domain with `domain:` as
an interval, "(0, 100]", "[0, inf)", "(-inf, inf)" or "any"; without one it is derived from the unit:
an angle may be anything, a percentage lies in (0, 100], and any other quantity must not be negative
(zero stays allowed: a belt thickness neglected, a plane at the reference), unless the template itself
draws negative values for it (then anything goes).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .template import ParamSpec

_NUMBER = r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?|[-+]?inf"
_INTERVAL = re.compile(rf"\s*([(\[])\s*({_NUMBER})\s*,\s*({_NUMBER})\s*([)\]])\s*")
PERCENT_UNITS = ("percent", "%")
ANGLE_UNITS = ("deg", "degree", "degrees", "rad", "radian", "radians", "rev", "turn")


@dataclass(frozen=True)
class Domain:
    low: float = -math.inf
    high: float = math.inf
    low_closed: bool = False
    high_closed: bool = False

    def __contains__(self, value: float) -> bool:
        above = value >= self.low if self.low_closed else value > self.low
        below = value <= self.high if self.high_closed else value < self.high
        return above and below

    @property
    def unbounded(self) -> bool:
        return self.low == -math.inf and self.high == math.inf

    def requirement(self, unit: str = "") -> str:
        """In words, for a message: "must be positive", "must lie in (0, 100] %"."""
        if self == POSITIVE:
            return "must be positive"
        if self == NOT_NEGATIVE:
            return "must not be negative"
        return f"must lie in {self.text()}{' ' + unit if unit else ''}"

    def text(self) -> str:
        def end(x: float) -> str:
            return "inf" if x == math.inf else "-inf" if x == -math.inf else f"{x:g}"

        return f"{'[' if self.low_closed else '('}{end(self.low)}, {end(self.high)}{']' if self.high_closed else ')'}"


ANY = Domain()
POSITIVE = Domain(0.0)
NOT_NEGATIVE = Domain(0.0, low_closed=True)
PERCENTAGE = Domain(0.0, 100.0, high_closed=True)


def parse_domain(text: str) -> Domain:
    """'(0, 100]' -> Domain(0, 100, high_closed); 'any' -> everything. ValueError says what is wrong."""
    if str(text).strip().lower() in ("any", "(-inf, inf)"):
        return ANY
    match = _INTERVAL.fullmatch(str(text))
    if not match:
        raise ValueError(f"{text!r} is not an interval such as \"(0, 100]\", \"[0, inf)\" or \"any\"")
    opening, low, high, closing = match.groups()
    low_value, high_value = float(low), float(high)
    if not low_value < high_value:
        raise ValueError(f"{text!r}: the lower end must be below the upper end")
    return Domain(low_value, high_value, opening == "[" and math.isfinite(low_value),
                  closing == "]" and math.isfinite(high_value))


def domain_of(spec: ParamSpec) -> Domain:
    """The declared domain, else the one the unit implies (see the module's docstring)."""
    if spec.domain:
        return parse_domain(spec.domain)
    if spec.unit.strip() in ANGLE_UNITS:
        return ANY
    drawn = drawn_values(spec)
    if drawn and min(drawn) < 0:
        return ANY
    return PERCENTAGE if spec.unit.strip() in PERCENT_UNITS else NOT_NEGATIVE


def drawn_values(spec: ParamSpec) -> list[float]:
    """The ends of what the template draws (numbers only): [min, max], or the numeric choices."""
    if spec.is_range:
        return [float(spec.min), float(spec.max)]
    return [float(c) for c in spec.choices if not isinstance(c, str)]
