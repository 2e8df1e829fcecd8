"""Kinematic-diagram symbols (course text §7.4): links, pins, ground pivots, sliders, plates.

A `Frame` maps the mechanism's coordinates (m, y up) to the page (px, y down) at one scale, so a
figure is drawn to the variant's data. A `Sketch` draws the symbols first; labels written after
the geometry take the first of their candidate spots that is clear of every line and label
(the drawing remembers both), trying each spot both level and along its link.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .layout import text_box
from .svg import FONT_SIZE, LINE, NOTE_SIZE, THIN, Drawing, pts, unit

BAR = 3.2          # a link's stroke
PIN_R = 4.2        # a pin joint's circle
GROUND_W = 26.0    # a ground pivot's hatched base
HATCH = 6.0
SMALL = NOTE_SIZE
DASH = "7 4"


@dataclass(frozen=True)
class Frame:
    """World (m, y up) to page (px, y down)."""

    scale: float

    def __call__(self, p) -> tuple[float, float]:
        return p[0] * self.scale, -p[1] * self.scale


def fit(points, width_px: float = 400.0, height_px: float = 280.0) -> Frame:
    """The scale that fits every point in a box of the given size."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    span_x, span_y = max(xs) - min(xs), max(ys) - min(ys)
    return Frame(min(width_px / (span_x or 1e-9), height_px / (span_y or 1e-9)))


def centre_of(points) -> tuple[float, float]:
    return sum(p[0] for p in points) / len(points), sum(p[1] for p in points) / len(points)


class Sketch:
    """A kinematic diagram being drawn: geometry first, then labels placed clear of it."""

    def __init__(self) -> None:
        self.d = Drawing()

    # ---- geometry -------------------------------------------------------------------------

    def bar(self, a, b, dash: str = "", cls: str = "link") -> None:
        self.d.line(a, b, BAR if not dash else LINE, dash=dash, cls=cls)

    def thin(self, a, b, dash: str = "", cls: str = "", width: float = THIN) -> None:
        self.d.line(a, b, width, dash=dash, cls=cls)

    def pin(self, c, dash: str = "") -> None:
        self.d.circle(c, PIN_R, LINE, fill="white", dash=dash, cls="pin")

    def dot(self, c) -> None:
        self.d.circle(c, 3.0, THIN, fill="black", cls="point")

    def hatch_line(self, a, b, towards) -> None:
        """A ground line from a to b, hatched on the side of the unit vector `towards`."""
        self.d.line(a, b, LINE, cls="ground")
        length = math.dist(a, b)
        ux, uy = unit((b[0] - a[0], b[1] - a[1]))
        count = max(2, int(length / HATCH))
        for k in range(count + 1):
            x, y = a[0] + ux * length * k / count, a[1] + uy * length * k / count
            self.d.line((x, y), (x + (towards[0] - ux) * HATCH * 0.9, y + (towards[1] - uy) * HATCH * 0.9), THIN)

    def ground_pivot(self, c, down=(0.0, 1.0)) -> None:
        """A pin on a triangular bracket standing on hatched ground; `down` points from the pin to the ground."""
        ux, uy = unit(down)
        nx, ny = -uy, ux
        base = (c[0] + ux * 16, c[1] + uy * 16)
        half = GROUND_W / 2
        left = (base[0] - nx * half * 0.6, base[1] - ny * half * 0.6)
        right = (base[0] + nx * half * 0.6, base[1] + ny * half * 0.6)
        self.d.path(f"M {pts(left)} L {pts(c)} L {pts(right)}", LINE, cls="bracket")
        self.hatch_line((base[0] - nx * half, base[1] - ny * half), (base[0] + nx * half, base[1] + ny * half), (ux, uy))
        self.pin(c)

    def plate(self, corners, dash: str = "") -> None:
        """A rigid body with three or more joints: a shaded polygon."""
        path = "M " + " L ".join(pts(p) for p in corners) + " Z"
        self.d.path(path, BAR if not dash else LINE, fill="#e6e6e6" if not dash else "none", dash=dash, cls="plate")
        for p in corners:
            self.d.extend(p[0], p[1], p[0], p[1])

    def slider_block(self, c, direction, dash: str = "") -> None:
        """A block centred on the pin c, lying along the line of slide `direction`."""
        ux, uy = unit(direction)
        nx, ny = -uy, ux
        hl, hw = 17.0, 10.0
        corners = [(c[0] + ux * sx * hl + nx * sy * hw, c[1] + uy * sx * hl + ny * sy * hw)
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        self.d.path("M " + " L ".join(pts(p) for p in corners) + " Z", LINE, fill="white", dash=dash, cls="slider")
        for p in corners:
            self.d.extend(p[0], p[1], p[0], p[1])
        self.pin(c, dash)

    def guide(self, a, b, side) -> None:
        """The line of slide from a to b, its ground hatched on `side` (a unit vector across it)."""
        off = 13.0
        self.hatch_line((a[0] + side[0] * off, a[1] + side[1] * off), (b[0] + side[0] * off, b[1] + side[1] * off), side)
        self.d.line(a, b, THIN, dash="10 3 2 3", cls="line-of-slide")

    def arc(self, c, r: float, start: float, end: float, cls: str = "angle") -> list:
        """An arc at c from world angle `start` counter-clockwise to `end`, arrowed at `end`; its points."""
        sweep = (end - start) % (2 * math.pi)
        steps = max(2, int(math.degrees(sweep) / 10))
        points = [(c[0] + r * math.cos(start + sweep * k / steps), c[1] - r * math.sin(start + sweep * k / steps))
                  for k in range(steps + 1)]
        self.d.path("M " + " L ".join(pts(p) for p in points), THIN, cls=cls)
        for p in points:
            self.d.extend(p[0], p[1], p[0], p[1])
        self.d.arrowhead(points[-1], (-math.sin(end), -math.cos(end)), 6.0)
        return points

    def reference_line(self, c, length: float = 60.0, angle: float = 0.0) -> None:
        """A thin dashed line from c at world angle `angle`: where an angle is measured from."""
        end = (c[0] + length * math.cos(angle), c[1] - length * math.sin(angle))
        self.d.line(c, end, THIN, dash="4 3", cls="reference")

    def axes(self, origin, size: float = 30.0) -> None:
        """x and y arrows at `origin` with a counter-clockwise arrow: the chapter's angle convention.
        Drawn last of the geometry, where nothing else is (see `corner_axes`)."""
        ox, oy = origin
        self.d.line((ox, oy), (ox + size, oy), THIN, cls="axis")
        self.d.arrowhead((ox + size, oy), (1, 0), 6.0)
        self.d.line((ox, oy), (ox, oy - size), THIN, cls="axis")
        self.d.arrowhead((ox, oy - size), (0, -1), 6.0)
        self.label([((ox + size + 4, oy + 5), "start", 0.0), ((ox + size - 2, oy + 16), "middle", 0.0)], "x",
                   size=SMALL, style="italic")
        self.label([((ox - 4, oy - size + 4), "end", 0.0), ((ox + 6, oy - size), "start", 0.0)], "y",
                   size=SMALL, style="italic")
        points = self.arc((ox, oy), size * 0.55, math.radians(12), math.radians(78), cls="convention")
        middle = points[len(points) // 2]
        self.label([((middle[0] + 5, middle[1] - 3), "start", 0.0), ((middle[0] + 9, middle[1] - 8), "start", 0.0)],
                   "+", size=SMALL)

    def corner_axes(self, size: float = 30.0) -> None:
        """The convention glyph to the left of everything drawn so far, at its foot."""
        x0, _, _, y1 = self.d.box
        self.axes((x0 - size - 30, y1 - 4), size)

    # ---- labels ---------------------------------------------------------------------------

    def label(self, candidates, content: str, size: float = FONT_SIZE, weight: str = "", style: str = "",
              cls: str = "") -> None:
        """`content` at the first candidate (at, anchor, angle) clear of every line and label so far,
        else at the one with fewest clashes (ties to the earliest)."""
        best, fewest = None, math.inf
        for at, anchor, angle in candidates:
            count = self.d.clashes(text_box(at, content, anchor, size, weight == "bold", style == "italic", angle),
                                   enough=fewest)
            if count < fewest:
                best, fewest = (at, anchor, angle), count
            if count == 0:
                break
        at, anchor, angle = best
        self.d.text(at, content, anchor, size, weight, style, cls, angle)

    def joint_label(self, at, text: str, centre, distance: float = 15.0) -> None:
        ux, uy = unit((at[0] - centre[0], at[1] - centre[1]))
        self.label(around(at, (ux, uy), distance, FONT_SIZE), text, weight="bold", cls="joint-label")

    def link_label(self, a, b, text: str, centre, size: float = SMALL) -> None:
        """Beside the link and along it; failing that (a short link), level and further out."""
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        ux, uy = unit((mid[0] - centre[0], mid[1] - centre[1]))
        level = [spot for reach in (26.0, 40.0, 56.0, 76.0) for spot in around(mid, (ux, uy), reach, size)]
        self.label(along(a, b, centre, size) + level, text, size=size, cls="link-label")

    def angle_label(self, c, r: float, start: float, end: float, text: str) -> None:
        sweep = (end - start) % (2 * math.pi)
        out = []
        for t in (start + sweep / 2, start + sweep * 0.3, start + sweep * 0.7, end + 0.35, start - 0.35,
                  end + 0.8, start - 0.8, end + 1.3, start - 1.3):
            for reach in (r + 10, r + 24, r + 40, r + 60):
                x, y = c[0] + reach * math.cos(t), c[1] - reach * math.sin(t)
                anchor = "start" if math.cos(t) > 0.3 else ("end" if math.cos(t) < -0.3 else "middle")
                out.append(((x, y + 5), anchor, 0.0))
        self.label(out, text, size=SMALL, cls="angle-label")

    def svg(self, title: str) -> str:
        return self.d.svg(title)


def around(point, first_direction, distance: float, size: float, widest: float = 4):
    """Candidate spots for a short level label round a point, starting in `first_direction` and
    turning both ways in 45° steps (then the 22.5° between) up to `widest` steps, at four distances."""
    base = math.atan2(first_direction[1], first_direction[0]) if any(first_direction) else -math.pi / 2
    turns = [k for k in (0, 1, -1, 2, -2, 3, -3, 4, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 3.5, -3.5) if abs(k) <= widest]
    out = []
    for reach in (distance, distance * 1.6, distance * 2.4, distance * 3.2):
        for k in turns:
            t = base + k * math.pi / 4
            x, y = point[0] + reach * math.cos(t), point[1] + reach * math.sin(t)
            anchor = "start" if math.cos(t) > 0.5 else ("end" if math.cos(t) < -0.5 else "middle")
            out.append(((x, y + size * 0.35), anchor, 0.0))
    return out


def along(a, b, centre, size: float, gaps=(6.0, 13.0), stations=(0.5, 0.38, 0.62, 0.28, 0.72)):
    """Candidate spots for a label beside the line a-b and written along it, the side away from
    `centre` first."""
    ux, uy = unit((b[0] - a[0], b[1] - a[1]))
    nx, ny = -uy, ux
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    if (mid[0] - centre[0]) * nx + (mid[1] - centre[1]) * ny < 0:
        nx, ny = -nx, -ny
    angle = math.degrees(math.atan2(uy, ux))
    if angle > 90:
        angle -= 180
    elif angle < -90:
        angle += 180
    up = (math.sin(math.radians(angle)), -math.cos(math.radians(angle)))   # the text's own "up" on the page
    out = []
    for side in (1, -1):
        sx, sy = nx * side, ny * side
        # beside the line on the text's underside, the baseline must clear the glyphs' height too
        lift_extra = size * 0.72 if sx * up[0] + sy * up[1] < 0 else size * 0.25
        for gap in gaps:
            for t in stations:
                px, py = a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t
                out.append(((px + sx * (gap + lift_extra), py + sy * (gap + lift_extra)), "middle", angle))
    return out
