"""Force and moment polygons as worked steps: component sums and the vector that closes them.

Angles follow whatever convention a sheet states; every vector is (size, angle) with components
size·cos θ along the 0° line and size·sin θ along the 90° line, so the working reads the same
for angles measured from +y clockwise (§2.2) or from a mass's radius.
"""
from __future__ import annotations

import math

#: How far a known wrong method must land from the right answer for a sheet to test it: sizes
#: are graded at 1 % and angles at 1°, so 3 % and 3° leave a clear gap.
APART = 0.03
APART_DEG = 3.0
#: Below this fraction of the terms' sizes, a sum is float noise: exactly zero.
ZERO = 1e-9


def components(d, name: str, symbol: str, terms, unit: str, what: str, harmonic: int = 1):
    """Steps `name_0` and `name_90`: Σ size·cos kθ and Σ size·sin kθ over terms (size name, angle name or
    None for a term on the 0° line), k the harmonic (2 for secondary cranks). Returns the two values;
    float noise below 1e-9 of the terms' sizes is taken as zero."""
    value = d.value_of
    angle = (lambda a: harmonic * value(a) if a else 0.0)
    along = sum(value(s) * math.cos(angle(a)) for s, a in terms)
    across = sum(value(s) * math.sin(angle(a)) for s, a in terms if a)
    scale = sum(abs(value(s)) for s, _ in terms)
    along, across = (0.0 if abs(v) <= ZERO * scale else v for v in (along, across))
    arg = (lambda a: rf"(2\,@{a})") if harmonic == 2 else (lambda a: f"@{a}")
    x = d.step(f"{name}_0", along, unit, symbol=_subscript(symbol, "0"),
               formula=" + ".join(rf"@{s} \cos {arg(a)}" if a else f"@{s}" for s, a in terms),
               note=f"{what}: components along the 0° line")
    y = d.step(f"{name}_90", across, unit, symbol=_subscript(symbol, "90"),
               formula=" + ".join(rf"@{s} \sin {arg(a)}" for s, a in terms if a) or "0",
               note=f"{what}: components along the 90° line")
    return x, y


def _subscript(symbol: str, index: str) -> str:
    """'M' -> 'M_{0}'; a symbol that has a subscript already gets the index added: 'F_{p}' -> 'F_{p,0}'."""
    if "_{" in symbol and symbol.endswith("}"):
        return f"{symbol[:-1]},{index}}}"
    return f"{symbol}_{{{index}}}"


def closing_angle(d, name: str, symbol: str, x_name: str, y_name: str, opposite: bool = True) -> float:
    """The angle of the vector that closes the polygon (opposite the resultant), or of the resultant."""
    x, y = d.value_of(x_name), d.value_of(y_name)
    if opposite:
        angle = math.atan2(-y, -x) % (2 * math.pi)
        return d.step(name, angle, "rad", symbol=symbol, formula=rf"\tan^{{-1}}\frac{{-@{y_name}}}{{-@{x_name}}}",
                      note=r"opposite the resultant: in the quadrant of its negative components")
    angle = math.atan2(y, x) % (2 * math.pi)
    return d.step(name, angle, "rad", symbol=symbol, formula=rf"\tan^{{-1}}\frac{{@{y_name}}}{{@{x_name}}}",
                  note="the resultant's direction: in the quadrant of its components")


def magnitude_formula(x_name: str, y_name: str) -> str:
    return rf"\sqrt{{@{x_name}^2 + @{y_name}^2}}"


def angle_gap_deg(a: float, b: float) -> float:
    """The gap between two directions (radians) in degrees, 0-180."""
    gap = math.degrees(a - b) % 360.0
    return min(gap, 360.0 - gap)


def polar_apart(right: tuple[float, float], wrong: tuple[float, float]) -> bool:
    """A wrong (size, angle) a student's answer can tell from the right one."""
    size, angle = right
    return abs(wrong[0] - size) >= APART * abs(size) or angle_gap_deg(wrong[1], angle) >= APART_DEG


def require_polar_apart(d, right, wrong, what: str) -> None:
    d.require(polar_apart(right, wrong), f"{what} changes the answer by less than {APART:.0%} or {APART_DEG:g}°")


def require_angle_apart(d, right: float, wrong: float, what: str) -> None:
    d.require(angle_gap_deg(right, wrong) >= APART_DEG, f"{what} moves the angle by less than {APART_DEG:g}°")
