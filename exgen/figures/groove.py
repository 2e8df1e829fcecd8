"""A small cross-section of a V-groove with the belt in it, showing the groove angle 2β."""
from __future__ import annotations

import math

from .svg import THIN, Drawing, num, on_circle, pts

INSET_W = 150.0
INSET_H = 168.0
_DEPTH = 46.0     # groove depth
_BOTTOM = 12.0    # width of the groove floor
_RIM = 26.0       # rim thickness below the groove floor


def groove_inset(drawing: Drawing, x0: float, y0: float, groove_rad: float, label: str) -> None:
    """Draw the inset in the box (x0, y0, INSET_W, INSET_H); `label` is e.g. '2β = 40°'."""
    beta = max(math.radians(10), min(math.radians(50), groove_rad / 2))  # keep the sketch readable
    cx = x0 + INSET_W / 2
    top = y0 + 26
    floor = top + _DEPTH
    half_top = _BOTTOM / 2 + _DEPTH * math.tan(beta)
    half_rim = half_top + 14
    drawing.text((cx, y0 + 14), "groove section", size=12, style="italic")
    rim = [(cx - half_rim, top), (cx - half_top, top), (cx - _BOTTOM / 2, floor), (cx + _BOTTOM / 2, floor),
           (cx + half_top, top), (cx + half_rim, top), (cx + half_rim, floor + _RIM), (cx - half_rim, floor + _RIM)]
    drawing.path("M " + " L ".join(pts(p) for p in rim) + " Z", cls="groove")
    # The belt: a trapezoid wedged against both walls, standing proud of the rim and clear of the floor.
    belt_top, belt_bottom = top - 7, floor - 12
    def wall_half(y: float) -> float:
        return _BOTTOM / 2 + (floor - y) * math.tan(beta)
    belt = [(cx - wall_half(belt_top), belt_top), (cx + wall_half(belt_top), belt_top),
            (cx + wall_half(belt_bottom), belt_bottom), (cx - wall_half(belt_bottom), belt_bottom)]
    drawing.path("M " + " L ".join(pts(p) for p in belt) + " Z", fill="#d9d9d9", cls="belt-section")
    # The walls produced meet at the virtual apex; the arc there marks the groove angle.
    apex = (cx, floor + (_BOTTOM / 2) / math.tan(beta))
    for side in (-1, 1):
        drawing.line((cx + side * _BOTTOM / 2, floor), apex, THIN, dash="3 2")
    r = 16.0
    start, end = on_circle(apex, r, -math.pi / 2 - beta), on_circle(apex, r, -math.pi / 2 + beta)
    drawing.path(f"M {pts(start)} A {num(r)} {num(r)} 0 0 1 {pts(end)}", THIN)
    drawing.text((cx, apex[1] + 18), label, size=13)
