"""A direction from its components, as a worked line: tan⁻¹(y/x) lies between −90° and 90°, so the
line adds the 180° or 360° that puts the direction in the quadrant of its components."""
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
