"""Where text sits on a figure: a label's box from the font's metrics, and tests of that box against
other labels and against the lines drawn, so labels can be placed clear of both.

Coordinates are the SVG's (px, y down). A label may be turned about its anchor point; its box is
kept in its own unturned frame, and points are carried into that frame for every test.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

from .metrics import FROM_MATH, measure

SUBSCRIPTS = "₀₁₂₃₄₅₆₇₈₉"
SUPERSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻"
#: Scripts become plain digits; a middle dot (a unit's, kg·m²) becomes the math face's dot operator: the
#: text face's stands spaced ("kg · m²") beside the sheet's tight "kg·m²".
_PLAIN = str.maketrans(SUBSCRIPTS + SUPERSCRIPTS + "·", "0123456789" * 2 + "−" + "⋅")
SCRIPT = 0.72        # size of a sub- or superscript, as a fraction of the text's
SUB_SHIFT = 0.2      # baseline shift of a subscript (down) and superscript (up), in ems of the text
SUP_SHIFT = -0.36


@dataclass(frozen=True)
class Run:
    """A piece of a label set at one size and baseline: shift is 0, +1 (subscript) or -1 (superscript)."""

    text: str
    shift: int = 0
    math: bool = False  # set in the math companion face (signs the text face lacks, such as primes)

    @property
    def scale(self) -> float:
        return SCRIPT if self.shift else 1.0

    @property
    def dy(self) -> float:
        """Baseline offset in ems of the label's size (y down)."""
        return {0: 0.0, 1: SUB_SHIFT, -1: SUP_SHIFT}[self.shift]


def runs(content: str) -> list[Run]:
    """'ω₁ = 2 m/s²' -> [ω][1 sub][ = 2 m/s][2 sup]: scripts are set as smaller digits, never as the
    font's own script glyphs (most text fonts lack them and would fall back to another font)."""
    return list(_runs(content))


@lru_cache(maxsize=4096)
def _runs(content: str) -> tuple[Run, ...]:
    out: list[Run] = []
    for char in content:
        shift = 1 if char in SUBSCRIPTS else -1 if char in SUPERSCRIPTS else 0
        plain = char.translate(_PLAIN)
        math = plain in FROM_MATH
        if out and out[-1].shift == shift and out[-1].math == math:
            out[-1] = Run(out[-1].text + plain, shift, math)
        else:
            out.append(Run(plain, shift, math))
    return tuple(out)


@dataclass(frozen=True)
class TextBox:
    """The ink box of a label: (x0, y0)-(x1, y1) in its own frame, turned by `angle` degrees about `pivot`."""

    x0: float
    y0: float
    x1: float
    y1: float
    angle: float = 0.0
    pivot: tuple[float, float] = (0.0, 0.0)
    text: str = ""

    def to_page(self, p) -> tuple[float, float]:
        if not self.angle:
            return p
        t = math.radians(self.angle)
        dx, dy = p[0] - self.pivot[0], p[1] - self.pivot[1]
        return (self.pivot[0] + dx * math.cos(t) - dy * math.sin(t),
                self.pivot[1] + dx * math.sin(t) + dy * math.cos(t))

    def to_local(self, p) -> tuple[float, float]:
        if not self.angle:
            return p
        t = math.radians(-self.angle)
        dx, dy = p[0] - self.pivot[0], p[1] - self.pivot[1]
        return (self.pivot[0] + dx * math.cos(t) - dy * math.sin(t),
                self.pivot[1] + dx * math.sin(t) + dy * math.cos(t))

    def corners(self) -> list[tuple[float, float]]:
        return [self.to_page(p) for p in ((self.x0, self.y0), (self.x1, self.y0), (self.x1, self.y1), (self.x0, self.y1))]

    def extent(self) -> tuple[float, float, float, float]:
        if not self.angle:
            return self.x0, self.y0, self.x1, self.y1
        xs, ys = zip(*self.corners())
        return min(xs), min(ys), max(xs), max(ys)

    def grown(self, margin: float) -> "TextBox":
        return TextBox(self.x0 - margin, self.y0 - margin, self.x1 + margin, self.y1 + margin, self.angle,
                       self.pivot, self.text)


def text_width(content: str, size: float = 14.0, bold: bool = False, italic: bool = False) -> float:
    return sum(measure(r.text, bold, italic).width * size * r.scale for r in _runs(content))


@lru_cache(maxsize=4096)
def _extent(content: str, size: float, bold: bool, italic: bool) -> tuple[float, float, float]:
    """(width, ink above, ink below the baseline) of a label: a label is tried at many spots, measured once."""
    width, above, below = 0.0, 0.0, 0.0
    for run in _runs(content):
        ink = measure(run.text, bold, italic)
        s = size * run.scale
        width += ink.width * s
        above = max(above, ink.above * s - run.dy * size)
        below = max(below, ink.below * s + run.dy * size)
    return width, above, below


def text_box(at, content: str, anchor: str = "middle", size: float = 14.0, bold: bool = False,
             italic: bool = False, angle: float = 0.0) -> TextBox:
    """The ink box of `content` with its baseline starting, centred or ending (anchor) at `at`."""
    width, above, below = _extent(content, size, bold, italic)
    x0 = at[0] - {"start": 0.0, "middle": width / 2, "end": width}[anchor]
    return TextBox(x0, at[1] - above, x0 + width, at[1] + below, angle, (at[0], at[1]), content)


# ---- tests between boxes and drawn lines -------------------------------------------------------

def boxes_overlap(a: TextBox, b: TextBox, gap: float = 0.0) -> bool:
    """Whether two boxes come closer than `gap` (separating-axis test on their corners)."""
    pa, pb = a.corners(), b.corners()
    for poly in (pa, pb):
        for i in range(4):
            (x1, y1), (x2, y2) = poly[i], poly[(i + 1) % 4]
            ax, ay = y1 - y2, x2 - x1
            norm = math.hypot(ax, ay) or 1.0
            ax, ay = ax / norm, ay / norm
            proj_a = [x * ax + y * ay for x, y in pa]
            proj_b = [x * ax + y * ay for x, y in pb]
            if max(proj_a) + gap <= min(proj_b) or max(proj_b) + gap <= min(proj_a):
                return False
    return True


def segment_hits(box: TextBox, p, q, margin: float = 0.0) -> bool:
    """Whether the segment p-q passes through the box grown by `margin` (Liang-Barsky in its frame)."""
    (x0, y0), (x1, y1) = box.to_local(p), box.to_local(q)
    lo, hi = 0.0, 1.0
    dx, dy = x1 - x0, y1 - y0
    for d, start, low, high in ((dx, x0, box.x0 - margin, box.x1 + margin), (dy, y0, box.y0 - margin, box.y1 + margin)):
        if abs(d) < 1e-12:
            if start < low or start > high:
                return False
            continue
        t1, t2 = (low - start) / d, (high - start) / d
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
        if lo > hi:
            return False
    return True


def circle_hits(box: TextBox, c, r: float, margin: float = 0.0) -> bool:
    """Whether the circle's outline passes through the box grown by `margin`."""
    x, y = box.to_local(c)
    x0, y0, x1, y1 = box.x0 - margin, box.y0 - margin, box.x1 + margin, box.y1 + margin
    nearest = math.hypot(max(x0 - x, 0, x - x1), max(y0 - y, 0, y - y1))
    farthest = max(math.hypot(cx - x, cy - y) for cx in (x0, x1) for cy in (y0, y1))
    return nearest <= r <= farthest


def segments_cross(p, q, a, b) -> bool:
    """Whether segments p-q and a-b meet (touching counts)."""
    def side(o, s, t):
        return (s[0] - o[0]) * (t[1] - o[1]) - (s[1] - o[1]) * (t[0] - o[0])

    d1, d2, d3, d4 = side(a, b, p), side(a, b, q), side(p, q, a), side(p, q, b)
    if ((d1 > 0) != (d2 > 0)) and ((d3 > 0) != (d4 > 0)) and d1 and d2 and d3 and d4:
        return True
    box = TextBox(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))
    return any(abs(v) < 1e-9 for v in (d1, d2)) and segment_hits(box, p, q)


def ring_crosses(p, q, c, r: float) -> bool:
    """Whether segment p-q crosses the circle's outline (one end inside, the other outside, or through it)."""
    inside = [math.hypot(x - c[0], y - c[1]) < r for x, y in (p, q)]
    if inside[0] != inside[1]:
        return True
    if inside[0]:
        return False
    dx, dy = q[0] - p[0], q[1] - p[1]
    t = max(0.0, min(1.0, ((c[0] - p[0]) * dx + (c[1] - p[1]) * dy) / ((dx * dx + dy * dy) or 1.0)))
    return math.hypot(p[0] + t * dx - c[0], p[1] + t * dy - c[1]) <= r


# ---- path outlines as points (for the tests above) ----------------------------------------------

_TOKEN = re.compile(r"[MLAZmlaz]|-?\d*\.?\d+(?:e-?\d+)?")


def path_points(d: str, per_arc: int = 16) -> list[list[tuple[float, float]]]:
    """The polylines of an SVG path made of M, L, A and Z (absolute), arcs sampled."""
    tokens = _TOKEN.findall(d)
    lines: list[list[tuple[float, float]]] = []
    i, command, here = 0, "M", (0.0, 0.0)
    while i < len(tokens):
        if tokens[i].isalpha():
            command = tokens[i].upper()
            i += 1
            if command == "Z":
                if lines and lines[-1]:
                    lines[-1].append(lines[-1][0])
                continue
        if command == "M":
            here = (float(tokens[i]), float(tokens[i + 1]))
            lines.append([here])
            i += 2
            command = "L"
        elif command == "L":
            here = (float(tokens[i]), float(tokens[i + 1]))
            lines[-1].append(here)
            i += 2
        elif command == "A":
            rx, ry, _, large, sweep, x, y = (float(t) for t in tokens[i:i + 7])
            lines[-1].extend(_arc(here, (x, y), rx, ry, bool(large), bool(sweep), per_arc))
            here = (x, y)
            i += 7
        else:  # a command this figure code never writes
            raise ValueError(f"unsupported path command {command!r}")
    return lines


def _arc(p0, p1, rx: float, ry: float, large: bool, sweep: bool, steps: int):
    """Points along a circular arc from p0 to p1 (SVG endpoint form, rx == ry, no rotation)."""
    r = max(rx, ry)
    mx, my = (p1[0] - p0[0]) / 2, (p1[1] - p0[1]) / 2
    half = math.hypot(mx, my)
    if half < 1e-9:
        return [p1]
    r = max(r, half)
    h = math.sqrt(max(r * r - half * half, 0.0))
    # the centre lies on the perpendicular bisector, on the side that gives the sweep asked for
    ux, uy = -my / half, mx / half
    sign = 1 if large != sweep else -1
    cx, cy = p0[0] + mx + sign * h * ux, p0[1] + my + sign * h * uy
    a0 = math.atan2(p0[1] - cy, p0[0] - cx)
    a1 = math.atan2(p1[1] - cy, p1[0] - cx)
    delta = a1 - a0
    if sweep and delta < 0:
        delta += 2 * math.pi
    elif not sweep and delta > 0:
        delta -= 2 * math.pi
    return [(cx + r * math.cos(a0 + delta * k / steps), cy + r * math.sin(a0 + delta * k / steps))
            for k in range(1, steps + 1)]
