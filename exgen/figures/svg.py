"""A tiny SVG writer: black line art as text, deterministic to the byte.

Figures are written directly (no plotting library) so a sheet costs milliseconds. Numbers
are printed with two decimals at most, so the same geometry always gives the same bytes.
Arrowheads are small polygons rather than markers: every SVG renderer (browsers, Typst's
usvg) draws polygons the same way.

Text is set in the sheets' own family (metrics.py) at one size for every label, and a figure
states its printed size: one px prints as PT_PER_PX pt on every sheet, so labels print at
one size in every figure. A drawing remembers each label's box and each line it draws, so a
label can be placed where it is clear of both (`place`), and tests can check the result.
"""
from __future__ import annotations

import math
from xml.sax.saxutils import escape

from .layout import (TextBox, boxes_overlap, circle_hits, path_points, ring_crosses, runs, segment_hits, segments_cross,
                     text_box, text_width)
from .metrics import MATH_FAMILY, SVG_FAMILY

FONT_SIZE = 14.0  # every label
NOTE_SIZE = 13.0  # italic remarks ("positions from the left end")
PT_PER_PX = 0.62  # printed size: 14 px labels print at 8.7 pt, a 758 px figure fills a 16.6 cm text width
MAX_WIDTH = 758.0  # widest figure that prints at that scale on an A4 sheet's text width
LINE = 1.3       # outline stroke width
THIN = 0.8       # dimension and centre lines
ARROW = 7.0      # arrowhead length
CLEAR = 2.0      # the least gap between a label and another label or a line
SUBSCRIPTS = str.maketrans("0123456789", "\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089")


def num(x: float) -> str:
    """A coordinate as short, stable text: 12.5, 3, -0.25 (never '-0')."""
    text = f"{x:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def pts(*points) -> str:
    return " ".join(f"{num(x)},{num(y)}" for x, y in points)


def subscripted(name: str) -> str:
    """'d1' -> 'd₁', 'N1' -> 'N₁': a parameter name as a label symbol."""
    head = name.rstrip("0123456789")
    return head + name[len(head):].translate(SUBSCRIPTS)


class Drawing:
    """Collects SVG elements; `svg()` wraps them with a viewBox. Remembers label boxes and drawn lines."""

    def __init__(self) -> None:
        self.items: list[str] = []
        self.defs: list[str] = []
        self.box = [math.inf, math.inf, -math.inf, -math.inf]  # x0, y0, x1, y1 of what is drawn
        self.labels: list[TextBox] = []
        self.segments: list[tuple[tuple[float, float], tuple[float, float]]] = []
        self._extents: list[tuple] = []  # each segment's extent, with it (segments are only ever appended)
        self.rings: list[tuple[tuple[float, float], float]] = []  # circle outlines

    def add(self, element: str) -> None:
        self.items.append(element)

    def extend(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Grow the drawn extent (the viewBox is fitted to it)."""
        b = self.box
        self.box = [min(b[0], x0), min(b[1], y0), max(b[2], x1), max(b[3], y1)]

    def line(self, a, b, width: float = LINE, dash: str = "", cls: str = "") -> None:
        self.extend(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))
        self.segments.append((tuple(a), tuple(b)))
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<line x1="{num(a[0])}" y1="{num(a[1])}" x2="{num(b[0])}" y2="{num(b[1])}" '
                 f'stroke-width="{num(width)}"{extra}/>')

    def circle(self, c, r: float, width: float = LINE, fill: str = "none", dash: str = "",
               cls: str = "") -> None:
        self.extend(c[0] - r, c[1] - r, c[0] + r, c[1] + r)
        self.rings.append((tuple(c), r))
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<circle cx="{num(c[0])}" cy="{num(c[1])}" r="{num(r)}" fill="{fill}" '
                 f'stroke-width="{num(width)}"{extra}/>')

    def path(self, d: str, width: float = LINE, fill: str = "none", dash: str = "", cls: str = "",
             clip: str = "") -> None:
        """A path; its extent is not tracked (callers draw paths inside tracked shapes or call extend).
        Its outline is remembered unless it is clipped (hidden lines inside a part in front)."""
        if not clip:
            for points in path_points(d):
                self.segments.extend(zip(points, points[1:]))
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        extra += f' clip-path="url(#{clip})"' if clip else ""
        self.add(f'<path d="{d}" fill="{fill}" stroke-width="{num(width)}"{extra}/>')

    def polygon(self, points, fill: str = "black", width: float = 0) -> None:
        self.extend(min(p[0] for p in points), min(p[1] for p in points),
                    max(p[0] for p in points), max(p[1] for p in points))
        if fill != "black":  # an outlined shape; a solid arrowhead is part of its line
            self.segments.extend(zip(points, list(points[1:]) + [points[0]]))
        self.add(f'<polygon points="{pts(*points)}" fill="{fill}" stroke-width="{num(width)}"/>')

    def text(self, at, content: str, anchor: str = "middle", size: float = FONT_SIZE,
             weight: str = "", style: str = "", cls: str = "", angle: float = 0.0) -> TextBox:
        """A label with its baseline at `at`, optionally turned by `angle` degrees about that point.
        Digits written as Unicode sub- or superscripts are set as smaller digits in the same font."""
        box = text_box(at, content, anchor, size, weight == "bold", style == "italic", angle)
        self.extend(*box.extent())
        self.labels.append(box)
        extra = f' font-size="{num(size)}"' if size != FONT_SIZE else ""
        extra += f' transform="rotate({num(angle)} {num(at[0])} {num(at[1])})"' if angle else ""
        extra += f' font-weight="{weight}"' if weight else ""
        extra += f' font-style="{style}"' if style else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<text x="{num(at[0])}" y="{num(at[1])}" text-anchor="{anchor}" stroke="none" '
                 f'fill="black"{extra}>{_tspans(content, size)}</text>')
        return box

    def clip_circle(self, ident: str, c, r: float) -> None:
        self.defs.append(f'<clipPath id="{ident}"><circle cx="{num(c[0])}" cy="{num(c[1])}" r="{num(r)}"/></clipPath>')

    # ---- keeping labels clear --------------------------------------------------------------

    def clashes(self, box: TextBox, gap: float = CLEAR, enough: float = math.inf) -> int:
        """How many labels and drawn lines `box` would touch (0: it is clear), counted up to `enough` (a
        spot that touches as many as the best so far is out of the running). What lies outside the box's
        extent is passed over before the exact tests, which keeps placing labels cheap."""
        x0, y0, x1, y1 = box.extent()
        x0, y0, x1, y1 = x0 - gap, y0 - gap, x1 + gap, y1 + gap
        count = 0
        for other in self.labels:
            ox0, oy0, ox1, oy1 = other.extent()
            if ox0 <= x1 and ox1 >= x0 and oy0 <= y1 and oy1 >= y0 and boxes_overlap(box, other, gap):
                count += 1
                if count >= enough:
                    return count
        for sx0, sy0, sx1, sy1, p, q in self._segment_extents():
            if sx0 <= x1 and sx1 >= x0 and sy0 <= y1 and sy1 >= y0 and segment_hits(box, p, q, gap):
                count += 1
                if count >= enough:
                    return count
        for c, r in self.rings:
            if c[0] - r <= x1 and c[0] + r >= x0 and c[1] - r <= y1 and c[1] + r >= y0 and circle_hits(box, c, r, gap):
                count += 1
                if count >= enough:
                    return count
        return count

    def _segment_extents(self) -> list[tuple]:
        """(x0, y0, x1, y1, p, q) of every segment drawn so far: worked out once each, not at every clash test."""
        extents = self._extents
        for p, q in self.segments[len(extents):]:
            extents.append((min(p[0], q[0]), min(p[1], q[1]), max(p[0], q[0]), max(p[1], q[1]), p, q))
        return extents

    def crosses(self, points, gap: float = CLEAR) -> int:
        """How many drawn lines and labels the polyline `points` would cross or touch."""
        count = 0
        for p, q in zip(points, points[1:]):
            count += sum(segments_cross(p, q, a, b) for a, b in self.segments)
            count += sum(ring_crosses(p, q, c, r) for c, r in self.rings)
            count += sum(segment_hits(box, p, q, gap) for box in self.labels)
        return count

    def place(self, candidates, content: str, size: float = FONT_SIZE, weight: str = "", style: str = "",
              cls: str = "", angle: float = 0.0) -> TextBox:
        """The label at the first of `candidates` ((at, anchor) pairs) where it is clear of every label and
        line so far; where none is clear, at the one it clashes least with (ties to the earliest)."""
        best, fewest = None, math.inf
        for at, anchor in candidates:
            box = text_box(at, content, anchor, size, weight == "bold", style == "italic", angle)
            count = self.clashes(box, enough=fewest)
            if count < fewest:
                best, fewest = (at, anchor), count
            if count == 0:
                break
        return self.text(best[0], content, best[1], size, weight, style, cls, angle)

    # ---- composite marks -----------------------------------------------------------------

    def arrowhead(self, tip, direction, length: float = ARROW) -> None:
        """A filled arrowhead with its tip at `tip`, pointing along `direction`."""
        ux, uy = unit(direction)
        base = (tip[0] - ux * length, tip[1] - uy * length)
        half = length * 0.38
        self.polygon([tip, (base[0] - uy * half, base[1] + ux * half), (base[0] + uy * half, base[1] - ux * half)])

    def dimension(self, a, b, width: float = THIN) -> None:
        """A dimension line with arrowheads at both ends."""
        self.line(a, b, width)
        self.arrowhead(b, (b[0] - a[0], b[1] - a[1]))
        self.arrowhead(a, (a[0] - b[0], a[1] - b[1]))

    def centre_mark(self, c, size: float = 5.0) -> None:
        self.line((c[0] - size, c[1]), (c[0] + size, c[1]), THIN)
        self.line((c[0], c[1] - size), (c[0], c[1] + size), THIN)

    def rotation_arrow(self, c, r: float, clockwise: bool, start_deg: float = -140, end_deg: float = -40) -> None:
        """An arc around `c` (screen angles, y down) with an arrowhead showing the sense of rotation."""
        a0, a1 = (start_deg, end_deg) if clockwise else (end_deg, start_deg)
        p0, p1 = on_circle(c, r, math.radians(a0)), on_circle(c, r, math.radians(a1))
        sweep = 1 if clockwise else 0
        large = 1 if abs(end_deg - start_deg) > 180 else 0
        self.path(f"M {pts(p0)} A {num(r)} {num(r)} 0 {large} {sweep} {pts(p1)}", THIN, cls="rotation")
        for k in range(9):
            x, y = on_circle(c, r, math.radians(start_deg + (end_deg - start_deg) * k / 8))
            self.extend(x, y, x, y)
        t = math.radians(a1)
        tangent = (-math.sin(t), math.cos(t)) if clockwise else (math.sin(t), -math.cos(t))
        self.arrowhead(p1, tangent, ARROW * 1.1)

    def svg(self, title: str = "", pad: float = 6.0) -> str:
        """The document, its viewBox fitted to everything drawn plus `pad`, its size in pt at the common scale."""
        x0, y0 = self.box[0] - pad, self.box[1] - pad
        width, height = self.box[2] + pad - x0, self.box[3] + pad - y0
        head = (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{num(x0)} {num(y0)} {num(width)} {num(height)}" '
                f'width="{num(width * PT_PER_PX)}pt" height="{num(height * PT_PER_PX)}pt" font-family="{SVG_FAMILY}" '
                f'font-size="{num(FONT_SIZE)}" stroke="black" stroke-linecap="round" stroke-linejoin="round">')
        parts = [head]
        if title:
            parts.append(f"<title>{escape(title)}</title>")
        if self.defs:
            parts.append("<defs>" + "".join(self.defs) + "</defs>")
        parts.append(f'<rect x="{num(x0)}" y="{num(y0)}" width="{num(width)}" height="{num(height)}" fill="white" stroke="none"/>')
        parts.extend(self.items)
        parts.append("</svg>")
        return "\n".join(parts) + "\n"


def unit(v) -> tuple[float, float]:
    length = math.hypot(v[0], v[1]) or 1.0
    return v[0] / length, v[1] / length


def on_circle(c, r: float, angle: float) -> tuple[float, float]:
    """The point at screen angle `angle` (radians, y down, so positive turns clockwise)."""
    return c[0] + r * math.cos(angle), c[1] + r * math.sin(angle)


def lerp(a, b, t: float) -> tuple[float, float]:
    return a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t


def _tspans(content: str, size: float) -> str:
    """The label's text, its sub- and superscripts as smaller digits shifted off the baseline (dy: every
    SVG renderer supports it, unlike baseline-shift)."""
    out, offset = [], 0.0
    for run in runs(content):
        dy = run.dy * size - offset
        offset += dy
        attributes = f' dy="{num(dy)}"' if dy or run.shift else ""
        attributes += f' font-size="{num(size * run.scale)}"' if run.shift else ""
        attributes += f' font-family="{MATH_FAMILY}"' if run.math else ""
        text = escape(run.text)
        out.append(f"<tspan{attributes}>{text}</tspan>" if attributes else text)
    return "".join(out)
