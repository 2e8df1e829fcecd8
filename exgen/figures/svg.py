"""A tiny SVG writer: black line art as text, deterministic to the byte.

Figures are written directly (no plotting library) so a sheet costs milliseconds. Numbers
are printed with two decimals at most, so the same geometry always gives the same bytes.
Arrowheads are small polygons rather than markers: every SVG renderer (browsers, Typst's
usvg) draws polygons the same way.
"""
from __future__ import annotations

import math
from xml.sax.saxutils import escape

FONT_FAMILY = "DejaVu Sans, Helvetica, Arial, sans-serif"
FONT_SIZE = 15
LINE = 1.3       # outline stroke width
THIN = 0.8       # dimension and centre lines
ARROW = 7.0      # arrowhead length
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


def text_width(text: str, size: float = FONT_SIZE) -> float:
    """A generous estimate of a label's width (layout only; fonts differ between renderers)."""
    return 0.6 * size * len(text)


def text_box(at, text: str, anchor: str = "middle", size: float = FONT_SIZE) -> tuple[float, float, float, float]:
    """The estimated extent (x0, y0, x1, y1) of a label drawn at baseline point `at`."""
    w = text_width(text, size)
    x0 = at[0] - {"start": 0.0, "middle": w / 2, "end": w}[anchor]
    return x0, at[1] - 0.78 * size, x0 + w, at[1] + 0.24 * size


class Drawing:
    """Collects SVG elements; `svg()` wraps them with a viewBox."""

    def __init__(self) -> None:
        self.items: list[str] = []
        self.defs: list[str] = []
        self.box = [math.inf, math.inf, -math.inf, -math.inf]  # x0, y0, x1, y1 of what is drawn

    def add(self, element: str) -> None:
        self.items.append(element)

    def extend(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Grow the drawn extent (the viewBox is fitted to it)."""
        b = self.box
        self.box = [min(b[0], x0), min(b[1], y0), max(b[2], x1), max(b[3], y1)]

    def line(self, a, b, width: float = LINE, dash: str = "", cls: str = "") -> None:
        self.extend(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<line x1="{num(a[0])}" y1="{num(a[1])}" x2="{num(b[0])}" y2="{num(b[1])}" '
                 f'stroke-width="{num(width)}"{extra}/>')

    def circle(self, c, r: float, width: float = LINE, fill: str = "none", dash: str = "",
               cls: str = "") -> None:
        self.extend(c[0] - r, c[1] - r, c[0] + r, c[1] + r)
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<circle cx="{num(c[0])}" cy="{num(c[1])}" r="{num(r)}" fill="{fill}" '
                 f'stroke-width="{num(width)}"{extra}/>')

    def path(self, d: str, width: float = LINE, fill: str = "none", dash: str = "", cls: str = "",
             clip: str = "") -> None:
        """A path; its extent is not tracked (callers draw paths inside tracked shapes or call extend)."""
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' class="{cls}"' if cls else ""
        extra += f' clip-path="url(#{clip})"' if clip else ""
        self.add(f'<path d="{d}" fill="{fill}" stroke-width="{num(width)}"{extra}/>')

    def polygon(self, points, fill: str = "black", width: float = 0) -> None:
        self.extend(min(p[0] for p in points), min(p[1] for p in points),
                    max(p[0] for p in points), max(p[1] for p in points))
        self.add(f'<polygon points="{pts(*points)}" fill="{fill}" stroke-width="{num(width)}"/>')

    def text(self, at, content: str, anchor: str = "middle", size: float = FONT_SIZE,
             weight: str = "", style: str = "", cls: str = "", angle: float = 0.0) -> None:
        """A label with its baseline at `at`, optionally turned by `angle` degrees about that point."""
        x0, y0, x1, y1 = text_box(at, content, anchor, size)
        t = math.radians(angle)
        corners = [(at[0] + (x - at[0]) * math.cos(t) - (y - at[1]) * math.sin(t),
                    at[1] + (x - at[0]) * math.sin(t) + (y - at[1]) * math.cos(t))
                   for x, y in ((x0, y0), (x1, y0), (x0, y1), (x1, y1))]
        self.extend(min(c[0] for c in corners), min(c[1] for c in corners),
                    max(c[0] for c in corners), max(c[1] for c in corners))
        extra = f' font-size="{num(size)}"' if size != FONT_SIZE else ""
        extra += f' transform="rotate({num(angle)} {num(at[0])} {num(at[1])})"' if angle else ""
        extra += f' font-weight="{weight}"' if weight else ""
        extra += f' font-style="{style}"' if style else ""
        extra += f' class="{cls}"' if cls else ""
        self.add(f'<text x="{num(at[0])}" y="{num(at[1])}" text-anchor="{anchor}" stroke="none" '
                 f'fill="black"{extra}>{escape(content)}</text>')

    def clip_circle(self, ident: str, c, r: float) -> None:
        self.defs.append(f'<clipPath id="{ident}"><circle cx="{num(c[0])}" cy="{num(c[1])}" r="{num(r)}"/></clipPath>')

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
        """The document, its viewBox fitted to everything drawn plus `pad`."""
        x0, y0 = self.box[0] - pad, self.box[1] - pad
        width, height = self.box[2] + pad - x0, self.box[3] + pad - y0
        head = (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{num(x0)} {num(y0)} {num(width)} {num(height)}" '
                f'width="{num(width)}" height="{num(height)}" font-family="{FONT_FAMILY}" '
                f'font-size="{FONT_SIZE}" stroke="black" stroke-linecap="round" stroke-linejoin="round">')
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
