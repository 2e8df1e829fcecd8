"""A small cross-section of a V-groove with the belt in it, dimensioned with the groove angle 2β."""
from __future__ import annotations

import math

from .svg import NOTE_SIZE, THIN, Drawing, num, on_circle, pts

_DEPTH = 48.0     # groove depth
_FLOOR = 8.0      # width of the groove floor
_RIM = 22.0       # rim thickness below the groove floor
_SHOULDER = 16.0  # rim beyond the groove on each side


def groove_inset(drawing: Drawing, x0: float, y0: float, groove_rad: float, label: str) -> None:
    """Draw the inset with its top-left corner near (x0, y0); `label` is e.g. '2β = 40°'."""
    beta = max(math.radians(12), min(math.radians(45), groove_rad / 2))  # keep the sketch readable
    tan = math.tan(beta)
    half_top = _FLOOR / 2 + _DEPTH * tan
    cx = x0 + half_top + _SHOULDER + 12
    apex_y_from_top = _DEPTH + (_FLOOR / 2) / tan       # the walls produced meet below the floor
    radius = apex_y_from_top + 30                       # the angle is dimensioned above the belt
    top = y0 + 50  # room above for the arc dimension (30 above the rim) and its label
    floor = top + _DEPTH
    apex = (cx, top + apex_y_from_top)
    half_rim = half_top + _SHOULDER
    rim = [(cx - half_rim, top), (cx - half_top, top), (cx - _FLOOR / 2, floor), (cx + _FLOOR / 2, floor),
           (cx + half_top, top), (cx + half_rim, top), (cx + half_rim, floor + _RIM), (cx - half_rim, floor + _RIM)]
    drawing.path("M " + " L ".join(pts(p) for p in rim) + " Z", cls="groove")
    drawing.extend(cx - half_rim, top, cx + half_rim, floor + _RIM)

    def wall_half(y: float) -> float:
        return _FLOOR / 2 + (floor - y) * tan

    belt_top, belt_bottom = top - 8, floor - 14  # wedged on the walls, proud of the rim, clear of the floor
    belt = [(cx - wall_half(belt_top), belt_top), (cx + wall_half(belt_top), belt_top),
            (cx + wall_half(belt_bottom), belt_bottom), (cx - wall_half(belt_bottom), belt_bottom)]
    drawing.path("M " + " L ".join(pts(p) for p in belt) + " Z", fill="#d9d9d9", cls="belt-section")

    # Extension lines along the walls, and an arc dimension between them centred on the apex.
    ends = [on_circle(apex, radius, -math.pi / 2 + side * beta) for side in (-1, 1)]
    for side, end in zip((-1, 1), ends):
        start = (cx + side * half_top, top)
        beyond = on_circle(apex, radius + 6, -math.pi / 2 + side * beta)
        drawing.line(start, beyond, THIN, dash="3 2")
    drawing.path(f"M {pts(ends[0])} A {num(radius)} {num(radius)} 0 0 1 {pts(ends[1])}", THIN)
    for side, end in zip((-1, 1), ends):
        t = -math.pi / 2 + side * beta
        drawing.arrowhead(end, (side * -math.sin(t), side * math.cos(t)), 6)
    drawing.text((cx, apex[1] - radius - 7), label, cls="label-groove")
    drawing.text((cx, floor + _RIM + 16), "V-groove section", size=NOTE_SIZE, style="italic")
