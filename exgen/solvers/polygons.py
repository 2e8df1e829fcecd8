"""Force and moment polygons as worked steps: component sums and the vector that closes them.

Angles follow whatever convention a sheet states; every vector is (size, angle) with components
size·cos θ along the 0° line and size·sin θ along the 90° line, so the working reads the same
for angles measured from +y clockwise (§2.2) or from a mass's radius.
"""
from __future__ import annotations

import math

from .angles import direction_formula

#: Below this fraction of the terms' sizes, a sum is float noise: exactly zero.
ZERO = 1e-9


def components(d, name: str, symbol: str, terms, unit: str, what: str, harmonic: int = 1, table=None, shown=()):
    """Steps `name_0` and `name_90`: Σ size·cos kθ and Σ size·sin kθ over terms (size name, angle name or
    None for a term on the 0° line), k the harmonic (2 for secondary cranks). Returns the two values;
    float noise below 1e-9 of the terms' sizes is taken as zero.

    With `table` = (title, columns, rows, size), the sums are shown as the course text works them: a
    table with a row per term (its given cells, then its two components) and the sums as its Σ row.
    `size` is the LaTeX of the sized quantity (m r l), heading the component columns; `shown` names steps
    the table lists that keep their own line too (a row worked out just before, whose working the table lacks)."""
    value = d.value_of
    angle = (lambda a: harmonic * value(a) if a else 0.0)
    parts = [(value(s) * math.cos(angle(a)), value(s) * math.sin(angle(a)) if a else 0.0) for s, a in terms]
    along, across = sum(p[0] for p in parts), sum(p[1] for p in parts)
    scale = sum(abs(value(s)) for s, _ in terms)
    along, across = (0.0 if abs(v) <= ZERO * scale else v for v in (along, across))
    parts = [tuple(0.0 if abs(v) <= ZERO * scale else v for v in p) for p in parts]
    arg = (lambda a: rf"(2\,@{a})") if harmonic == 2 else (lambda a: f"@{a}")
    x = d.step(f"{name}_0", along, unit, symbol=_subscript(symbol, "0"),
               formula=" + ".join(rf"@{s} \cos {arg(a)}" if a else f"@{s}" for s, a in terms),
               note=f"{what}: components along the 0° line")
    y = d.step(f"{name}_90", across, unit, symbol=_subscript(symbol, "90"),
               formula=" + ".join(rf"@{s} \sin {arg(a)}" for s, a in terms if a) or "0",
               note=f"{what}: components along the 90° line")
    if table:
        title, columns, rows, size = table
        k = "2" if harmonic == 2 else ""
        heads = [(rf"${size}\cos {k}\theta$", unit), (rf"${size}\sin {k}\theta$", unit)]
        d.table(title, list(columns) + heads, [list(r) + list(p) for r, p in zip(rows, parts)],
                total=["Σ"] + [None] * (len(columns) - 1) + [f"@{name}_0", f"@{name}_90"], shown=tuple(shown))
    return x, y


def _subscript(symbol: str, index: str) -> str:
    """'M' -> 'M_{0}'; a symbol that has a subscript already gets the index added: 'F_{p}' -> 'F_{p,0}'."""
    if "_{" in symbol and symbol.endswith("}"):
        return f"{symbol[:-1]},{index}}}"
    return f"{symbol}_{{{index}}}"


def closing_angle(d, name: str, symbol: str, x_name: str, y_name: str, opposite: bool = True) -> float:
    """The angle of the vector that closes the polygon (opposite the resultant), or of the resultant:
    tan⁻¹(y/x) of the resultant's components, plus the 180° or 360° that puts it in its quadrant."""
    x, y = d.value_of(x_name), d.value_of(y_name)
    angle = math.atan2(-y, -x) if opposite else math.atan2(y, x)
    angle %= 2 * math.pi
    note = "opposite the resultant" if opposite else "the resultant's direction"
    if x == 0:
        return d.step(name, angle, "rad", symbol=symbol, note=f"{note}: its components lie on the 90° line")
    formula = direction_formula(f"@{y_name}", f"@{x_name}", y, x, angle)
    if y == 0:   # on the 0° line: no quadrant to name ("in the quadrant +x, −y" for 0°)
        return d.step(name, angle, "rad", symbol=symbol, formula=formula, note=f"{note}: it lies on the 0° line")
    quadrant = f"{'−' if (x < 0) != opposite else '+'}x, {'−' if (y < 0) != opposite else '+'}y"
    return d.step(name, angle, "rad", symbol=symbol, formula=formula, note=f"{note}, in the quadrant {quadrant}")


def magnitude_formula(x_name: str, y_name: str) -> str:
    return rf"\sqrt{{@{x_name}^2 + @{y_name}^2}}"


def angle_gap_deg(a: float, b: float) -> float:
    """The gap between two directions (radians) in degrees, 0-180."""
    gap = math.degrees(a - b) % 360.0
    return min(gap, 360.0 - gap)
