"""Belt drive figures, drawn to the variant's proportions (course text §1.2, Problem 1.4).

Pulleys are circles of the drawn diameters at the drawn centre distance, one scale for the
whole figure; the belt follows the exact common tangents. Values come from the variant as
printed on the sheet; an unknown is drawn to its solved size and labelled "?".
"""
from __future__ import annotations

import math

from ..errors import ExgenError
from .groove import INSET_H, INSET_W, groove_inset
from .svg import FONT_SIZE, LINE, THIN, Drawing, lerp, on_circle, text_width
from .tangents import belt_loop
from .values import Shown, choice, shown

GEOM_W = 420.0       # px from the driver's far rim to the driven pulley's far rim
MAX_D_PX = 250.0     # cap on a pulley's drawn diameter
BELT_GAP = 2.2       # belt centre line outside the pulley rim
BELT_W = 2.6
ROW = 19.0           # text line spacing
GAP = 10.0           # clearance between a label and what it names
CENTRE_DASH = "10 3 2 3"


def _need(variant, name: str) -> Shown:
    found = shown(variant, name)
    if found is None or not math.isfinite(found.si) or found.si <= 0:
        raise ExgenError(f"{variant.template.id}: the belt figure needs a positive {name!r} "
                         "(a parameter, or a step when it is the unknown)")
    return found


def pulley(drawing: Drawing, c, r: float, cls: str, front: bool = True) -> None:
    """A pulley seen along its shaft: rim, hub and centre mark."""
    drawing.circle(c, r, LINE, fill="white", cls=f"pulley {cls}")
    hub = max(3.5, 0.14 * r)
    drawing.circle(c, hub, THIN)
    drawing.centre_mark(c, hub + 4)


def diameter_mark(drawing: Drawing, c, r: float, angle_deg: float = 45.0) -> None:
    """A diameter dimension across the pulley, arrowheads on the rim."""
    a = math.radians(angle_deg)
    drawing.dimension(on_circle(c, r, math.pi - a), on_circle(c, r, -a))


def _label_stack(drawing: Drawing, c, radius: float, lines: list[str], clockwise: bool) -> float:
    """Rotation arrow round the top of a pulley and the labels above it; returns the top y used."""
    arc = radius + 10
    drawing.rotation_arrow(c, arc, clockwise)
    y = c[1] - arc - 9
    for i, text in enumerate(reversed(lines)):
        weight = "bold" if i == len(lines) - 1 else ""
        drawing.text((c[0], y), text, weight=weight)
        y -= ROW
    return y + ROW - FONT_SIZE


def stack_height(radius: float, lines: int) -> float:
    return radius + 10 + 9 + (lines - 1) * ROW + FONT_SIZE + 6


def belt_drive(variant) -> str:
    """An open or crossed belt drive with d₁, d₂, X, the driver speed and the tight side."""
    d1, d2, x = _need(variant, "d1"), _need(variant, "d2"), _need(variant, "X")
    n1, n2, groove = shown(variant, "N1"), shown(variant, "N2"), shown(variant, "groove")
    crossed = choice(variant, "drive", "open") == "crossed"
    scale = min(GEOM_W / (d1.si / 2 + x.si + d2.si / 2), MAX_D_PX / max(d1.si, d2.si))
    r1, r2 = d1.si / 2 * scale, d2.si / 2 * scale
    rb1, rb2 = r1 + BELT_GAP, r2 + BELT_GAP
    top1 = ["Driver"] + ([n1.label()] if n1 else [])
    top2 = ["Driven"] + ([n2.label()] if n2 else [])
    label1, label2 = d1.label(), d2.label()
    left = max(text_width(label1) + GAP + 4, max(map(text_width, top1)) / 2 - rb1, 0) + 8
    cx1 = left + rb1
    cx2 = cx1 + x.si * scale
    cy = max(stack_height(rb1, len(top1)), stack_height(rb2, len(top2)))
    c1, c2 = (cx1, cy), (cx2, cy)

    drawing = Drawing()
    loop = belt_loop(c1, rb1, c2, rb2, crossed)
    pulley(drawing, c1, r1, "driver")
    pulley(drawing, c2, r2, "driven")
    drawing.path(loop.path, BELT_W, cls="belt")
    diameter_mark(drawing, c1, r1)
    diameter_mark(drawing, c2, r2)
    drawing.text((cx1 - rb1 - GAP, cy + 5), label1, anchor="end", cls="label-d1")
    drawing.text((cx2 + rb2 + GAP, cy + 5), label2, anchor="start", cls="label-d2")
    _label_stack(drawing, c1, rb1, top1, clockwise=True)
    _label_stack(drawing, c2, rb2, top2, clockwise=not crossed)

    # Belt motion: the driver winds in the tight run.
    t_at, s_at = (0.5, 0.5) if not crossed else (0.72, 0.28)
    tight_mid = lerp(*loop.tight, t_at)
    slack_mid = lerp(*loop.slack, s_at)
    tight_dir = (loop.tight[1][0] - loop.tight[0][0], loop.tight[1][1] - loop.tight[0][1])
    slack_dir = (loop.slack[1][0] - loop.slack[0][0], loop.slack[1][1] - loop.slack[0][1])
    drawing.arrowhead(lerp(tight_mid, loop.tight[1], 0.04), tight_dir, 10)
    drawing.arrowhead(lerp(slack_mid, loop.slack[1], 0.04), slack_dir, 10)
    bottom = cy + max(rb1, rb2)
    if crossed:
        near = lerp(*loop.tight, 0.12)
        drawing.text((near[0] - 8, near[1] - 6), "tight side", anchor="end", style="italic", cls="tight")
    else:
        slope = abs(tight_dir[1] / tight_dir[0]) if tight_dir[0] else 0.0
        y = tight_mid[1] + slope * text_width("tight side") / 2 + 6 + FONT_SIZE * 0.8
        drawing.text((tight_mid[0], y), "tight side", style="italic", cls="tight")
        bottom = max(bottom, y)

    # Centre distance: centre lines down to a dimension line below the drive.
    y_dim = bottom + 16
    for c, r in ((c1, rb1), (c2, rb2)):
        drawing.line((c[0], c[1] + r + 4), (c[0], y_dim + 6), THIN, dash=CENTRE_DASH)
    drawing.dimension((cx1, y_dim), (cx2, y_dim))
    drawing.text(((cx1 + cx2) / 2, y_dim + FONT_SIZE + 3), x.label("X"), cls="label-X")

    width = cx2 + max(rb2 + GAP + text_width(label2), max(map(text_width, top2)) / 2) + 8
    height = y_dim + FONT_SIZE + 10
    if groove is not None:
        groove_inset(drawing, width, 6, groove.si, groove.label("2\u03b2"))
        width += INSET_W
        height = max(height, INSET_H + 6)
    kind = "Crossed" if crossed else "Open"
    belt = "V-belt" if groove is not None else "belt"
    return drawing.svg(width, height, f"{kind} {belt} drive")


def compound_drive(variant) -> str:
    """Two belt stages (Problem 1.4): motor d₁ -> main shaft d₂; d₃ on the main shaft -> countershaft d₄."""
    raise ExgenError(f"{variant.template.id}: the compound drive figure is not drawn yet")
