"""Angles as a reader of the key checks them: each line's arithmetic gives the value shown.

A direction from its components is tan⁻¹(y/x) plus the 180° or 360° that puts it in its quadrant
(the course text's "+180 because of the negative denominator"); a difference of two angles is
written larger minus smaller; an angle between two directions is reduced by whole turns in the open.
"""
from __future__ import annotations

import math


def direction_formula(y_latex: str, x_latex: str, y: float, x: float, angle: float) -> str:
    """The formula for `angle` (radians, the direction of (x, y) in the range the solver keeps):
    tan⁻¹(y/x) with the half or whole turns that reach it; empty when x = 0 (no ratio to show)."""
    if x == 0:
        return ""
    offset = round(math.degrees(angle - math.atan(y / x)) / 180) * 180
    turn = "" if offset == 0 else (rf" + {offset}^\circ" if offset > 0 else rf" - {-offset}^\circ")
    return rf"\tan^{{-1}}\frac{{{y_latex}}}{{{x_latex}}}" + turn


def direction(d, name: str, symbol: str, y: str, x: str, y_value: float, x_value: float, note: str) -> float:
    """The step `name`: the direction of (x, y) from +x, in (-180°, 180°]; `y` and `x` are the
    components' LaTeX (with @names), their values pick the quadrant."""
    angle = math.atan2(y_value, x_value)
    if x_value == 0:
        return d.step(name, angle, "rad", symbol=symbol, note=f"{note}: straight {'up' if y_value > 0 else 'down'}")
    if abs(math.atan(y_value / x_value) - angle) > 1e-12:   # not float noise: a half turn
        note += ", with the half turn that puts it in the quadrant of its components"
    return d.step(name, angle, "rad", symbol=symbol, formula=direction_formula(y, x, y_value, x_value, angle),
                  note=note)


def difference(d, name: str, symbol: str, first: str, second: str, note: str = "", unit: str = "rad") -> float:
    """The step `name`: the size of the difference of two earlier steps, larger minus smaller."""
    a, b = d.value_of(first), d.value_of(second)
    big, small = (first, second) if a >= b else (second, first)
    return d.step(name, abs(a - b), unit, symbol=symbol, formula=rf"@{big} - @{small}", note=note)


def between(d, name: str, symbol: str, expression: str, value: float, note: str) -> float:
    """The step `name`: the angle (0° to 180°) between two directions whose difference is
    `expression` (LaTeX with @names) worth `value` rad, reduced by whole turns in the formula."""
    turns = round(value / (2 * math.pi))
    reduced = value - 2 * math.pi * turns
    shift = f" - {360 * turns}^\\circ" if turns > 0 else (f" + {-360 * turns}^\\circ" if turns < 0 else "")
    formula = f"{expression}{shift}" if reduced >= 0 else f"-({expression}{shift})"
    return d.step(name, abs(reduced), "rad", symbol=symbol, formula=formula, note=note)


def wrapped(d, name: str, symbol: str, expression: str, value: float, note: str = "") -> float:
    """The step `name`: a direction worked as a sum of angles (`expression`, LaTeX with @names, worth
    `value` rad), kept in (-180°, 180°] with the whole turn that takes it there written in the formula,
    so the line's arithmetic gives the value shown."""
    kept = math.remainder(value, 2 * math.pi)
    kept = math.pi if kept == -math.pi else kept
    turns = round((value - kept) / (2 * math.pi))
    shift = f" - {360 * turns}^\\circ" if turns > 0 else (f" + {-360 * turns}^\\circ" if turns < 0 else "")
    return d.step(name, kept, "rad", symbol=symbol, formula=expression + shift, note=note)
