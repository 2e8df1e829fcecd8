"""Parts of balancing figures: a shaft seen from the side with its planes, and an end view with
the masses (or cranks) at their angles and the sheet's angle convention.

Positions are drawn to scale where they are data; a plane whose position is asked is drawn
dashed at a nominal place and its distance labelled "?". A mass whose angle is asked is not
drawn in the end view (its direction would give the answer away); it is listed as "?" instead.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

from .svg import FONT_SIZE, LINE, THIN, Drawing, on_circle, text_box, text_width

SMALL = 14.0          # label font size
ROW = 16.0            # label line spacing
DISC_H = 26.0         # half height of a disc seen edge-on
SHAFT_H = 5.0         # half thickness of the shaft
SPOKE_MIN, SPOKE_MAX = 26.0, 60.0
OUTLINE = 70.0        # end view outline radius
CENTRE_DASH = "10 3 2 3"
HIDDEN_DASH = "5 3"
MIN_WIDTH = 640.0     # a figure is at least this wide, so figures print at one scale


@dataclass(frozen=True)
class Convention:
    """How a sheet measures angles, as drawn: the screen angle (radians, y down) of its 0° line and
    whether angles grow clockwise on the page."""

    zero: float
    clockwise: bool
    zero_label: str = "0°"

    def screen(self, angle: float) -> float:
        return self.zero + (angle if self.clockwise else -angle)


UP_CLOCKWISE = -math.pi / 2, True
RIGHT_COUNTER_CLOCKWISE = 0.0, False


@dataclass(frozen=True)
class Spoke:
    """A mass or crank in the end view: `size` sets its length relative to the others; angle None = unknown."""

    name: str
    label: str
    size: float
    angle: float | None


@dataclass(frozen=True)
class Plane:
    """A plane along the shaft: kind is mass, correction, bearing or crank; `lines` label it (first bold)."""

    name: str
    z: float
    kind: str
    lines: tuple[str, ...]
    unknown_position: bool = False


def end_view(d: Drawing, c, spokes: Sequence[Spoke], conv: Convention, note: str = "") -> None:
    """The end view: outline, 0° line, the sense of measurement, spokes with their labels, unknowns listed."""
    d.circle(c, OUTLINE, THIN, cls="outline")
    d.centre_mark(c, 6)
    placed: list[tuple[float, float, float, float]] = []
    on_zero = any(s.angle is not None and abs(math.sin(s.angle / 2)) < 1e-9 for s in spokes)
    d.line(c, on_circle(c, OUTLINE + (4 if on_zero else 18), conv.zero), THIN, dash=CENTRE_DASH, cls="zero-line")
    if not on_zero:  # a spoke on the 0° line names it; otherwise the line is labelled
        _outside_label(d, c, OUTLINE + 22, conv.zero, conv.zero_label, placed, "zero-label")
    sense = math.radians(38) * (1 if conv.clockwise else -1)
    start, end = conv.zero + 0.12 * (1 if conv.clockwise else -1), conv.zero + sense
    r = OUTLINE - 12
    a0, a1 = (start, end) if conv.clockwise else (end, start)
    p0, p1 = on_circle(c, r, a0), on_circle(c, r, a1)
    d.path(f"M {p0[0]:.2f},{p0[1]:.2f} A {r:.2f} {r:.2f} 0 0 1 {p1[0]:.2f},{p1[1]:.2f}", THIN, cls="sense")
    tip = on_circle(c, r, end)
    tangent = (-math.sin(end), math.cos(end)) if conv.clockwise else (math.sin(end), -math.cos(end))
    d.arrowhead(tip, tangent, 7)
    label_at = on_circle(c, r - 14, conv.zero + sense * 0.55)
    d.text((label_at[0], label_at[1] + 5), "\u03b8", size=SMALL, style="italic", cls="sense-label")
    known = [s for s in spokes if s.angle is not None]
    largest = max((s.size for s in known), default=1.0) or 1.0
    for spoke in sorted(known, key=lambda s: conv.screen(s.angle) % (2 * math.pi)):
        a = conv.screen(spoke.angle)
        length = SPOKE_MIN + (SPOKE_MAX - SPOKE_MIN) * spoke.size / largest
        tip = on_circle(c, length, a)
        d.line(c, tip, 2.2, cls=f"spoke spoke-{spoke.name}")
        d.circle(tip, 5.0, fill="black", cls=f"mass mass-{spoke.name}")
        _outside_label(d, c, OUTLINE + 10, a, spoke.label, placed, f"spoke-label label-{spoke.name}")
    y = max(c[1] + OUTLINE + 34, max((b[3] for b in placed), default=0.0) + ROW + 4)
    for spoke in spokes:
        if spoke.angle is None:
            d.text((c[0], y), spoke.label, size=SMALL, cls=f"unknown label-{spoke.name}")
            y += ROW
    if note:
        d.text((c[0], y), note, size=SMALL, style="italic")


def _outside_label(d: Drawing, c, radius: float, angle: float, text: str, placed: list, cls: str) -> None:
    """A label just outside the outline in direction `angle`, pushed outwards clear of earlier ones."""
    cos, sin = math.cos(angle), math.sin(angle)
    anchor = "start" if cos > 0.35 else "end" if cos < -0.35 else "middle"
    for step in range(8):
        x, y = on_circle(c, radius + 14 * step, angle)
        at = (x, y + 0.3 * SMALL + 0.5 * SMALL * sin)
        box = text_box(at, text, anchor, SMALL)
        if not any(_overlap(box, other) for other in placed):
            break
    placed.append(box)
    d.text(at, text, anchor=anchor, size=SMALL, cls=cls)


def _overlap(a, b, gap: float = 2.0) -> bool:
    return a[0] < b[2] + gap and b[0] < a[2] + gap and a[1] < b[3] + gap and b[1] < a[3] + gap


def side_view(d: Drawing, planes: Sequence[Plane], length_px: float = 340.0,
              ends: tuple[float, float] | None = None) -> Callable[[float], float]:
    """The shaft from the side, its axis at y = 0; returns the function placing a position z at x."""
    zs = [p.z for p in planes] + list(ends or ())
    z0, z1 = min(zs), max(zs)
    scale = length_px / ((z1 - z0) or 1.0)

    def x_of(z: float) -> float:
        return (z - z0) * scale

    left, right = (x_of(ends[0]), x_of(ends[1])) if ends else (x_of(z0) - 26, x_of(z1) + 26)
    d.line((left - 14, 0), (right + 14, 0), THIN, dash=CENTRE_DASH, cls="axis")
    for y in (-SHAFT_H, SHAFT_H):
        d.line((left, y), (right, y), LINE, cls="shaft")
    for x in (left, right):
        d.line((x, -SHAFT_H), (x, SHAFT_H), LINE)
    for plane in planes:
        _plane(d, x_of(plane.z), plane)
    _labels(d, [(x_of(p.z), p) for p in sorted(planes, key=lambda p: p.z)])
    return x_of


def _labels(d: Drawing, placed: list[tuple[float, Plane]]) -> None:
    """Each plane's label block above it (bearings: beside the pedestal), raised a tier with a leader
    line where it would run into its left neighbour's."""
    tiers: list[float] = []  # right edge of the last block in each tier
    height = max((len(p.lines) for _, p in placed if p.kind != "bearing"), default=1) * ROW + 6
    for x, plane in placed:
        if plane.kind == "bearing":
            d.text((x + 17, SHAFT_H + 17), plane.lines[0], anchor="start", size=SMALL, weight="bold",
                   cls=f"name-{plane.name}")
            continue
        width = max(text_width(t, SMALL) for t in plane.lines)
        tier = next((i for i, edge in enumerate(tiers) if edge + 8 <= x - width / 2), len(tiers))
        if tier == len(tiers):
            tiers.append(0.0)
        tiers[tier] = x + width / 2
        base = -DISC_H - 12 - tier * height
        if tier:
            d.line((x, -DISC_H - 7), (x, base + 4), THIN, cls="leader")
        for i, text in enumerate(reversed(plane.lines)):
            bold = i == len(plane.lines) - 1
            d.text((x, base - i * ROW), text, size=SMALL, weight="bold" if bold else "",
                   cls=f"name-{plane.name}" if bold else "")


def _plane(d: Drawing, x: float, plane: Plane) -> None:
    cls = f"plane plane-{plane.name}"
    dash = HIDDEN_DASH if plane.unknown_position else ""
    if plane.kind == "bearing":
        d.polygon([(x, SHAFT_H + 1), (x - 10, SHAFT_H + 18), (x + 10, SHAFT_H + 18)], fill="white", width=LINE)
        d.line((x - 15, SHAFT_H + 18), (x + 15, SHAFT_H + 18), LINE, cls=cls)
        d.line((x, -DISC_H + 6), (x, SHAFT_H + 1), THIN, dash=CENTRE_DASH)
    elif plane.kind == "correction":
        d.line((x, -DISC_H), (x, DISC_H), LINE, dash=HIDDEN_DASH, cls=cls)
        d.circle((x, -DISC_H), 4.5, LINE, fill="white")
    elif plane.kind == "crank":
        d.line((x - 6, -SHAFT_H), (x - 6, -DISC_H), LINE, dash=dash, cls=cls)
        d.line((x + 6, -SHAFT_H), (x + 6, -DISC_H), LINE, dash=dash)
        d.line((x - 6, -DISC_H), (x + 6, -DISC_H), LINE, dash=dash)
        d.circle((x, -DISC_H + 5), 3.0, THIN)
    else:
        d.line((x, -DISC_H), (x, DISC_H), 2.6, dash=dash, cls=cls)
        d.circle((x, -DISC_H), 5.0, fill="white" if plane.unknown_position else "black")


def chain(d: Drawing, x_of, items: Sequence[tuple[float, float, str]], y: float, top: float = SHAFT_H + 4) -> None:
    """Dimension lines between pairs of positions on one row at height y; a label that does not fit
    between its arrows goes below the row."""
    for z in sorted({z for a, b, _ in items for z in (a, b)}):
        d.line((x_of(z), top), (x_of(z), y + 5), THIN, cls="extension")
    below = 0
    for a, b, text in items:
        xa, xb = x_of(a), x_of(b)
        d.dimension((xa, y), (xb, y))
        if text_width(text, SMALL) + 6 <= abs(xb - xa):
            d.text(((xa + xb) / 2, y - 4), text, size=SMALL, cls="dim-label")
        else:
            below += 1
            d.text(((xa + xb) / 2, y + ROW * below), text, size=SMALL, cls="dim-label")


def ordinates(d: Drawing, x_of, items: Sequence[tuple[float, str]], top: float = DISC_H + 4) -> None:
    """Positions from a datum: an extension line at each, its value written downwards beneath it."""
    for z, text in items:
        x = x_of(z)
        d.line((x, top), (x, top + 12), THIN, cls="extension")
        d.text((x + 4.5, top + 17), text, anchor="end", size=SMALL, angle=-90, cls="ordinate")


def rotation_note(d: Drawing, at, text: str) -> None:
    """A short italic note (a speed, a firing order) at `at`."""
    d.text(at, text, anchor="start", size=FONT_SIZE - 1, style="italic")


def fit_width(d: Drawing, width: float) -> None:
    """Widen a narrow drawing (centred) so that, scaled to the page like the others, it prints at their scale."""
    middle, half = (d.box[0] + d.box[2]) / 2, max(width / 2, (d.box[2] - d.box[0]) / 2)
    d.extend(middle - half, d.box[1], middle + half, d.box[3])
