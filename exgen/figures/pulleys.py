"""Parts of belt figures: pulleys, diameter marks, labels kept clear of the belt, motion arrows."""
from __future__ import annotations

import math

from ..errors import ExgenError
from .svg import FONT_SIZE, LINE, THIN, Drawing, lerp, num, on_circle, pts, text_width
from .tangents import BeltLoop
from .values import Shown, shown

BELT_GAP = 2.2       # belt centre line outside the pulley rim
BELT_W = 2.6
ROW = 19.0           # text line spacing
GAP = 8.0            # clearance between a label and what it names
ARC_GAP = 10.0       # rotation arrows run this far outside the belt
CENTRE_DASH = "10 3 2 3"
HIDDEN_DASH = "5 3"


def need(variant, name: str) -> Shown:
    """A size the figure cannot be drawn without."""
    found = shown(variant, name)
    if found is None or not math.isfinite(found.si) or found.si <= 0:
        raise ExgenError(f"{variant.template.id}: the belt figure needs a positive {name!r} "
                         "(a parameter, or a step when it is the unknown)")
    return found


def pulley(drawing: Drawing, c, r: float, cls: str) -> None:
    """A pulley seen along its shaft: rim (filled white, so it hides what is behind), hub, centre mark."""
    drawing.circle(c, r, LINE, fill="white", cls=f"pulley {cls}")
    hub = max(3.5, 0.14 * r)
    drawing.circle(c, hub, THIN)
    drawing.centre_mark(c, hub + 4)


def diameter_mark(drawing: Drawing, c, r: float, angle_deg: float = 45.0, tag: str = "",
                  tag_end: str = "left", inside: bool = False) -> None:
    """A diameter dimension across the pulley at `angle_deg` above the horizontal, arrowheads on the
    rim; `tag` names it beside its left or right end (outside the rim, or just inside it)."""
    a = math.radians(angle_deg)
    right, left = on_circle(c, r, -a), on_circle(c, r, math.pi - a)
    drawing.dimension(left, right)
    if not tag:
        return
    end, outward = (left, -1) if tag_end == "left" else (right, 1)
    if inside:
        anchor, dx, dy = ("start" if outward < 0 else "end"), -outward * 10, -9
    else:
        anchor, dx, dy = ("end" if outward < 0 else "start"), outward * 4, 5
    at = (end[0] + dx, end[1] + dy)
    candidates = [((at[0] + ox, at[1] + oy), anchor) for ox, oy in ((0, 0), (0, -8), (0, 8), (-outward * 8, -10),
                                                                   (outward * 8, 10), (0, -16), (0, 16))]
    # failing those, along the dimension line inside the rim, just above or below it
    for share in (0.7, 0.5, 0.85, 0.35):
        x, y = c[0] + (end[0] - c[0]) * share, c[1] + (end[1] - c[1]) * share
        candidates += [((x, y - 5), "middle"), ((x, y + 16), "middle")]
    drawing.place(candidates, tag)


def _run_y(run, x0: float, x1: float, pick) -> float | None:
    """The extreme (by `pick`) y of a straight run over [x0, x1], or None where it is not there."""
    (ax, ay), (bx, by) = run
    lo, hi = max(min(ax, bx), x0), min(max(ax, bx), x1)
    if lo > hi or ax == bx:
        return None
    return pick(ay + (by - ay) * (x - ax) / (bx - ax) for x in (lo, hi))


def label_stack(drawing: Drawing, c, radius: float, lines: list[str], runs, above: bool = True) -> None:
    """Labels centred above (or below) a pulley, moved clear of the belt's straight runs.

    Above, the first line is the bold title and sits on top; below, lines read downwards.
    """
    if above:
        y = c[1] - radius - 12
        for i, text in enumerate(reversed(lines)):
            half = text_width(text) / 2
            tops = [t for t in (_run_y(r, c[0] - half, c[0] + half, min) for r in runs) if t is not None]
            y = min([y] + [t - 0.24 * FONT_SIZE - 5 for t in tops])
            drawing.text((c[0], y), text, weight="bold" if i == len(lines) - 1 else "")
            y -= ROW
    else:
        y = c[1] + radius + 0.78 * FONT_SIZE + 8
        for text in lines:
            half = text_width(text) / 2
            lows = [t for t in (_run_y(r, c[0] - half, c[0] + half, max) for r in runs) if t is not None]
            y = max([y] + [t + 0.78 * FONT_SIZE + 5 for t in lows])
            drawing.text((c[0], y), text)
            y += ROW


def belt_motion(drawing: Drawing, loop: BeltLoop, at: tuple[float, float]) -> None:
    """Arrowheads on both runs in the direction the belt moves (tight run, slack run)."""
    for run, t in ((loop.tight, at[0]), (loop.slack, at[1])):
        direction = (run[1][0] - run[0][0], run[1][1] - run[0][1])
        drawing.arrowhead(lerp(*run, t + 0.03), direction, 10)


def run_label(drawing: Drawing, run, t: float, text: str, below: bool) -> None:
    """A label parallel to a straight run of belt, just below or above it."""
    (ax, ay), (bx, by) = run
    dx, dy = (bx - ax, by - ay) if bx >= ax else (ax - bx, ay - by)  # read left to right
    length = math.hypot(dx, dy) or 1.0
    nx, ny = -dy / length, dx / length  # the normal on the lower side
    offset = 6 + 0.78 * FONT_SIZE if below else -(5 + 0.24 * FONT_SIZE)
    p = lerp(*run, t)
    drawing.text((p[0] + nx * offset, p[1] + ny * offset), text, style="italic", cls="tight",
                 angle=math.degrees(math.atan2(dy, dx)))


def centre_distance(drawing: Drawing, c1, r1: float, c2, r2: float, y_dim: float, label: str) -> None:
    """Centre lines down to a dimension line between the shafts, the label below it."""
    for c, r in ((c1, r1), (c2, r2)):
        drawing.line((c[0], c[1] + r + 4), (c[0], y_dim + 6), THIN, dash=CENTRE_DASH)
    drawing.dimension((c1[0], y_dim), (c2[0], y_dim))
    drawing.text(((c1[0] + c2[0]) / 2, y_dim + FONT_SIZE + 3), label, cls="label-X")


def hidden(drawing: Drawing, clip_id: str, c, r: float, paths: list[tuple[str, float]]) -> None:
    """Outlines hidden behind a front pulley of radius r at c, drawn dashed inside its disc."""
    drawing.clip_circle(clip_id, c, r)
    for d, width in paths:
        drawing.path(d, width, dash=HIDDEN_DASH, clip=clip_id, cls="hidden")


def circle_path(c, r: float) -> str:
    """A full circle as a path (so it can be clipped and dashed like any outline)."""
    left, right = (c[0] - r, c[1]), (c[0] + r, c[1])
    return f"M {pts(left)} A {num(r)} {num(r)} 0 1 1 {pts(right)} A {num(r)} {num(r)} 0 1 1 {pts(left)} Z"

