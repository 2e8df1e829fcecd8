"""The symbols of vibration and gyroscope sketches: springs, dashpots, fixed ground, pivots, blocks,
dimension lines with their labels and labelled arrows. Each draws into a Drawing at given points.
"""
from __future__ import annotations

import math

from .svg import LINE, THIN, Drawing, lerp, pts, unit

HATCH = 7.0     # px between hatch strokes on fixed ground
LABEL_GAP = 5.0  # px between a mark and its label


def _along(a, b):
    """Unit vector from a to b, the normal to its left (screen), and the length."""
    ux, uy = unit((b[0] - a[0], b[1] - a[1]))
    return (ux, uy), (uy, -ux), math.hypot(b[0] - a[0], b[1] - a[1])


def spring(d: Drawing, a, b, coils: int = 6, width: float = 9.0, cls: str = "spring") -> None:
    """A zigzag spring from a to b, straight leads of a fifth of its length at each end."""
    (ux, uy), (nx, ny), length = _along(a, b)
    lead = length * 0.18
    points = [a, (a[0] + ux * lead, a[1] + uy * lead)]
    zig = length - 2 * lead
    for i in range(1, 2 * coils):
        t = lead + zig * i / (2 * coils)
        side = width if i % 2 else -width
        points.append((a[0] + ux * t + nx * side, a[1] + uy * t + ny * side))
    points += [(b[0] - ux * lead, b[1] - uy * lead), b]
    d.path("M " + " L ".join(pts(p) for p in points), LINE, cls=cls)
    d.extend(min(p[0] for p in points), min(p[1] for p in points), max(p[0] for p in points),
             max(p[1] for p in points))


def dashpot(d: Drawing, a, b, width: float = 12.0) -> None:
    """A dashpot from a (the cylinder's end) to b (the piston rod's end): an open cylinder, a piston inside."""
    (ux, uy), (nx, ny), length = _along(a, b)
    base = lerp(a, b, 0.15)
    mouth = lerp(a, b, 0.7)
    piston = lerp(a, b, 0.5)
    d.line(a, base, LINE)
    for s in (-1, 1):
        d.line((base[0] + nx * width * s, base[1] + ny * width * s), (mouth[0] + nx * width * s, mouth[1] + ny * width * s),
               LINE, cls="dashpot")
    d.line((base[0] - nx * width, base[1] - ny * width), (base[0] + nx * width, base[1] + ny * width), LINE)
    inner = width - 3
    d.line((piston[0] - nx * inner, piston[1] - ny * inner), (piston[0] + nx * inner, piston[1] + ny * inner), LINE * 1.6)
    d.line(piston, b, LINE)


def ground(d: Drawing, p, along, length: float = 50.0, side: int = 1) -> None:
    """Fixed ground: a line through p along `along`, hatched on one side (side +1: the left normal)."""
    (ux, uy) = unit(along)
    nx, ny = uy * side, -ux * side
    a = (p[0] - ux * length / 2, p[1] - uy * length / 2)
    b = (p[0] + ux * length / 2, p[1] + uy * length / 2)
    d.line(a, b, LINE * 1.3, cls="ground")
    count = max(2, int(length // HATCH))
    for i in range(count + 1):
        s = lerp(a, b, i / count)
        d.line(s, (s[0] + (nx - ux) * 6, s[1] + (ny - uy) * 6), THIN, cls="ground")


def pivot(d: Drawing, p, size: float = 10.0, below: bool = True) -> None:
    """A pinned support: a small ring at p on a triangle, hatched ground under it."""
    s = 1 if below else -1
    d.polygon([(p[0], p[1]), (p[0] - size * 0.8, p[1] + size * 1.3 * s), (p[0] + size * 0.8, p[1] + size * 1.3 * s)],
              fill="white", width=LINE)
    d.circle(p, 3.2, LINE, fill="white", cls="pivot")
    ground(d, (p[0], p[1] + size * 1.3 * s), (1, 0), size * 2.6, side=-s)


def block(d: Drawing, centre, w: float, h: float, label: str = "", cls: str = "mass") -> None:
    """A rectangular mass with its label inside."""
    x0, y0 = centre[0] - w / 2, centre[1] - h / 2
    d.polygon([(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)], fill="white", width=LINE)
    if label:
        d.text((centre[0], centre[1] + 5), label, cls=cls)


def ball(d: Drawing, c, r: float = 9.0) -> None:
    d.circle(c, r, LINE, fill="#d8d8d8", cls="ball")


def dimension(d: Drawing, a, b, text: str, side: int = 1, offset: float = 16.0, cls: str = "dim") -> None:
    """A dimension between points a and b, drawn `offset` px to one side with extension lines and its
    label beside the middle (placed clear of what is drawn)."""
    (ux, uy), (nx, ny), _ = _along(a, b)
    nx, ny = nx * side, ny * side
    pa = (a[0] + nx * offset, a[1] + ny * offset)
    pb = (b[0] + nx * offset, b[1] + ny * offset)
    for p, q in ((a, pa), (b, pb)):
        d.line((p[0] + nx * 3, p[1] + ny * 3), (q[0] + nx * 4, q[1] + ny * 4), THIN, cls="extension")
    d.dimension(pa, pb)
    mid = lerp(pa, pb, 0.5)
    candidates = []
    for k, (mx, my) in ((1, (nx, ny)), (2.5, (nx, ny)), (1, (-nx, -ny)), (2.5, (-nx, -ny)), (5, (nx, ny)),
                        (8, (nx, ny))):
        at = (mid[0] + mx * LABEL_GAP * k, mid[1] + my * LABEL_GAP * k)
        anchor = "start" if mx > 0.3 else "end" if mx < -0.3 else "middle"
        baseline = at[1] + (14 if my > 0.3 else 5 if abs(my) <= 0.3 else -1)
        candidates.append(((at[0], baseline), anchor))
    for t in (0.25, 0.75):
        at = lerp(pa, pb, t)
        candidates.append(((at[0] + nx * LABEL_GAP, at[1] + ny * LABEL_GAP + (14 if ny > 0.3 else 5)),
                           "start" if nx > 0.3 else "end" if nx < -0.3 else "middle"))
    d.place(candidates, text, cls=cls)


def arrow(d: Drawing, tail, tip, text: str = "", width: float = LINE, cls: str = "arrow", double: bool = False) -> None:
    """A straight arrow (a double head for a couple or an angular velocity vector), labelled past its tip."""
    d.line(tail, tip, width, cls=cls)
    d.arrowhead(tip, (tip[0] - tail[0], tip[1] - tail[1]), 9.0)
    (ux, uy), _, _ = _along(tail, tip)
    if double:
        back = (tip[0] - ux * 8, tip[1] - uy * 8)
        d.arrowhead(back, (ux, uy), 9.0)
    if text:
        at = (tip[0] + ux * 10, tip[1] + uy * 10 + 5)
        anchor = "start" if ux > 0.3 else "end" if ux < -0.3 else "middle"
        if abs(ux) <= 0.3:
            at = (tip[0], tip[1] - 8) if uy < 0 else (tip[0], tip[1] + 18)
        d.place([(at, anchor), ((at[0] + 4, at[1] - 14), anchor), ((at[0] + 4, at[1] + 14), anchor),
                 ((tip[0] + 10, tip[1] + 5), "start"), ((tip[0] - 10, tip[1] + 5), "end")], text, cls=cls)
