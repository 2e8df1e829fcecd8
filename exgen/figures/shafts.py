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

from .svg import FONT_SIZE, LINE, NOTE_SIZE, THIN, Drawing, on_circle, text_width

ROW = 16.0            # label line spacing
DISC_H = 26.0         # half height of a disc seen edge-on
SHAFT_H = 5.0         # half thickness of the shaft
SPOKE_MAX = 50.0      # the longest arm in an end view: its dot stays inside the sense arrow
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
    """A mass or crank in the end view: `size` (its radius) sets its length relative to the others; angle None
    = unknown."""

    name: str
    label: str
    size: float
    angle: float | None
    mass: float = 0.0  # sets the dot's size; 0 for a crank


@dataclass(frozen=True)
class Plane:
    """A plane along the shaft: kind is mass, correction, bearing or crank; `lines` label it (first bold)."""

    name: str
    z: float
    kind: str
    lines: tuple[str, ...]
    unknown_position: bool = False


def end_view(d: Drawing, c, spokes: Sequence[Spoke], conv: Convention, note: str = "") -> None:
    """The end view: outline, 0° line, the sense of measurement, spokes with their labels, unknowns listed.
    Spokes are drawn to their radii (the largest reaches SPOKE_MAX) and a mass's dot to its mass."""
    d.circle(c, OUTLINE, THIN, cls="outline")
    d.centre_mark(c, 6)
    on_zero = any(s.angle is not None and abs(math.sin(s.angle / 2)) < 1e-9 for s in spokes)
    d.line(c, on_circle(c, OUTLINE + (4 if on_zero else 18), conv.zero), THIN, dash=CENTRE_DASH, cls="zero-line")
    sense = math.radians(38) * (1 if conv.clockwise else -1)
    start, end = conv.zero + 0.12 * (1 if conv.clockwise else -1), conv.zero + sense
    r = OUTLINE - 12
    a0, a1 = (start, end) if conv.clockwise else (end, start)
    p0, p1 = on_circle(c, r, a0), on_circle(c, r, a1)
    d.path(f"M {p0[0]:.2f},{p0[1]:.2f} A {r:.2f} {r:.2f} 0 0 1 {p1[0]:.2f},{p1[1]:.2f}", THIN, cls="sense")
    tip = on_circle(c, r, end)
    tangent = (-math.sin(end), math.cos(end)) if conv.clockwise else (math.sin(end), -math.cos(end))
    d.arrowhead(tip, tangent, 7)
    first = len(d.labels)
    known = [s for s in spokes if s.angle is not None]
    longest = max((s.size for s in known), default=1.0) or 1.0
    heaviest = max((s.mass for s in known if s.mass), default=0.0)
    ordered = sorted(known, key=lambda s: conv.screen(s.angle) % (2 * math.pi))
    for spoke in ordered:
        a = conv.screen(spoke.angle)
        tip = on_circle(c, SPOKE_MAX * spoke.size / longest, a)
        d.line(c, tip, 2.2, cls=f"spoke spoke-{spoke.name}")
        dot = 5.0 if not (spoke.mass and heaviest) else 3.5 + 3.0 * math.sqrt(spoke.mass / heaviest)
        d.circle(tip, dot, fill="black", cls=f"mass mass-{spoke.name}")
    candidates = [(on_circle(c, radius, conv.zero + sense * share), (dx, dy)) for radius in (r - 14, r - 24, r - 34)
                  for share in (0.55, 0.3, 0.8) for dx, dy in _NUDGES[:5]]
    candidates += [(on_circle(c, radius, conv.zero + sense * share), (0, 0)) for radius in (r - 10, r - 20, r - 30, r - 40)
                   for share in (0.13, 0.26, 0.42, 0.68, 0.79, 0.92, 1.1)]
    candidates += [(on_circle(c, OUTLINE + 9, conv.zero + sense * share), (0, 0)) for share in (0.5, 0.75, 1.0, 1.25)]
    d.place([((x + dx, y + 5 + dy), "middle") for (x, y), (dx, dy) in candidates], "\u03b8",
            style="italic", cls="sense-label")
    if not on_zero:  # a spoke on the 0° line names it; otherwise the line is labelled
        _outside_label(d, c, OUTLINE + 22, conv.zero, conv.zero_label, "zero-label")
    for spoke in ordered:
        _outside_label(d, c, OUTLINE + 8, conv.screen(spoke.angle), spoke.label, f"spoke-label label-{spoke.name}")
    y = max([c[1] + OUTLINE + 34] + [b.extent()[3] + ROW + 4 for b in d.labels[first:] if b.extent()[1] > c[1]])
    for spoke in spokes:
        if spoke.angle is None:
            d.text((c[0], y), spoke.label, cls=f"unknown label-{spoke.name}")
            y += ROW
    if note:
        d.text((c[0], y), note, size=NOTE_SIZE, style="italic")


_NUDGES = [(0, 0), (0, -6), (0, 6), (-6, 0), (6, 0), (-8, -8), (8, 8), (8, -8), (-8, 8)]


def _outside_label(d: Drawing, c, radius: float, angle: float, text: str, cls: str) -> None:
    """A label just outside the outline in direction `angle`: pushed outwards, then turned a little either
    way, until it is clear of the labels and lines already drawn."""
    candidates = []
    for step in range(7):
        for turn in (0.0, 0.12, -0.12, 0.25, -0.25):
            a = angle + turn * (1 + step / 3)
            cos, sin = math.cos(a), math.sin(a)
            anchor = "start" if cos > 0.35 else "end" if cos < -0.35 else "middle"
            x, y = on_circle(c, radius + 12 * step, a)
            candidates.append(((x, y + 0.3 * FONT_SIZE + 0.5 * FONT_SIZE * sin), anchor))
    d.place(candidates, text, cls=cls)


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
    """Each plane's label block above it, in one row kept in the planes' order; blocks that would run
    into each other are spread apart and joined to their planes by leader lines. Bearings are named
    beside their pedestals."""
    above = [(x, p) for x, p in placed if p.kind != "bearing"]
    widths = [max(text_width(t, FONT_SIZE, bold=i == 0) for i, t in enumerate(p.lines)) for _, p in above]
    centres = spread([x for x, _ in above], widths, 12.0)
    moved = any(abs(c - x) > 1 for c, (x, _) in zip(centres, above))
    base = -DISC_H - 12 - (26 if moved else 0)
    for c, (x, plane) in zip(centres, above):
        if abs(c - x) > 1:
            d.line((x, -DISC_H - 7), (c, base + 4), THIN, cls="leader")
        for i, text in enumerate(reversed(plane.lines)):
            bold = i == len(plane.lines) - 1
            d.text((c, base - i * ROW), text, weight="bold" if bold else "", cls=f"name-{plane.name}" if bold else "")
    for x, plane in placed:  # beside the pedestal, clear of the dimensions below
        if plane.kind == "bearing":
            d.place([((x + 17, SHAFT_H + 17), "start"), ((x - 17, SHAFT_H + 17), "end"),
                     ((x + 17, SHAFT_H + 32), "start"), ((x - 17, SHAFT_H + 32), "end")],
                    plane.lines[0], weight="bold", cls=f"name-{plane.name}")


def spread(ideal: Sequence[float], widths: Sequence[float], gap: float) -> list[float]:
    """Centres for blocks of these widths in this order, at least `gap` apart, each as near its ideal
    centre as the others allow (clusters of touching blocks sit centred on their ideals' mean)."""
    clusters: list[list[int]] = []  # runs of block indices laid edge to edge

    def layout(cluster):
        offsets, at = [], 0.0
        for k, i in enumerate(cluster):
            if k:
                at += widths[cluster[k - 1]] / 2 + gap + widths[i] / 2
            offsets.append(at)
        shift = sum(ideal[i] - o for i, o in zip(cluster, offsets)) / len(cluster)
        return [shift + o for o in offsets]

    for i in range(len(ideal)):
        clusters.append([i])
        while len(clusters) > 1:
            left, right = layout(clusters[-2]), layout(clusters[-1])
            if left[-1] + widths[clusters[-2][-1]] / 2 + gap <= right[0] - widths[clusters[-1][0]] / 2:
                break
            clusters[-2:] = [clusters[-2] + clusters[-1]]
    return [c for cluster in clusters for c in layout(cluster)]


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
        if text_width(text, FONT_SIZE) + 6 <= abs(xb - xa):
            d.text(((xa + xb) / 2, y - 4), text, cls="dim-label")
        else:
            below += 1
            d.text(((xa + xb) / 2, y + ROW * below), text, cls="dim-label")


def ordinates(d: Drawing, x_of, items: Sequence[tuple[float, str]], top: float = DISC_H + 4) -> None:
    """Positions from a datum: an extension line at each, its value written downwards beneath it."""
    for z, text in items:
        x = x_of(z)
        d.line((x, top), (x, top + 12), THIN, cls="extension")
        d.text((x + 4.5, top + 17), text, anchor="end", angle=-90, cls="ordinate")


def rotation_note(d: Drawing, at, text: str) -> None:
    """A short italic note (a speed, a firing order) at `at`."""
    d.text(at, text, anchor="start" - 1, style="italic")


def fit_width(d: Drawing, width: float) -> None:
    """Widen a narrow drawing (centred) so that, scaled to the page like the others, it prints at their scale."""
    middle, half = (d.box[0] + d.box[2]) / 2, max(width / 2, (d.box[2] - d.box[0]) / 2)
    d.extend(middle - half, d.box[1], middle + half, d.box[3])
