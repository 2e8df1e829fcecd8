"""Kinematic diagrams with numbered links, for counting mobility (course text §7.4, Figure 7.15).

Every hatched support is the ground, numbered 1; moving links are numbered 2, 3, ... in the
catalogue's order. A pin is a small circle, a ternary link a shaded plate, a slider a block on a
hatched guide, a pin in a slot a pin inside a slotted bracket, gears their pitch circles. Nothing
is dimensioned: the student counts from the picture alone.
"""
from __future__ import annotations

import math

from ..mechanics.mechanism_catalogue import parallel_cranks
from ..mechanics.mobility import GROUND, Mechanism
from ..solvers.mobility import mechanism_of
from .kinematic import Sketch, around, centre_of
from .svg import LINE, unit

SCALE = 44.0   # px per catalogue unit
SLOT_HALF = 5.5
SLOT_LENGTH = 2.2


def _page(p) -> tuple[float, float]:
    return p[0] * SCALE, -p[1] * SCALE


def _ordered(points) -> list:
    """A plate's corners in order round its centre."""
    c = centre_of(points)
    return sorted(points, key=lambda p: math.atan2(p[1] - c[1], p[0] - c[0]))


def _down(mech: Mechanism, page, point: str) -> tuple[float, float]:
    """Which way a support's bracket stands: the base's pivots on the floor below them, an addition's
    support beyond the link that reaches it."""
    if not point.startswith("G"):
        return 0.0, 1.0
    link = next(link for link in mech.links if point in link.points)
    other = page[next(p for p in link.points if p != point)]
    return unit((page[point][0] - other[0], page[point][1] - other[1]))


def _slot(s: Sketch, c, direction) -> None:
    """A straight slot (two lines with round ends) centred on c along `direction` (page units)."""
    ux, uy = unit(direction)
    nx, ny = -uy, ux
    half = SLOT_LENGTH * SCALE / 2
    ends = [(c[0] - ux * half, c[1] - uy * half), (c[0] + ux * half, c[1] + uy * half)]
    for side in (1, -1):
        s.thin((ends[0][0] + nx * side * SLOT_HALF, ends[0][1] + ny * side * SLOT_HALF),
               (ends[1][0] + nx * side * SLOT_HALF, ends[1][1] + ny * side * SLOT_HALF), width=LINE, cls="slot")
    for end, sign in zip(ends, (-1, 1)):
        a = (end[0] + nx * SLOT_HALF, end[1] + ny * SLOT_HALF)
        b = (end[0] - nx * SLOT_HALF, end[1] - ny * SLOT_HALF)
        sweep = 1 if sign > 0 else 0
        s.d.path(f"M {a[0]:.2f},{a[1]:.2f} A {SLOT_HALF} {SLOT_HALF} 0 0 {sweep} {b[0]:.2f},{b[1]:.2f}", LINE, cls="slot")


class _Words:
    """A variant's given words, read as a solver reads its parameters (p.base, p.add1, ...)."""

    def __init__(self, variant):
        self._variant = variant

    def __getattr__(self, name: str) -> str:
        return str(self._variant.param(name).exact)


def kinematic_diagram(variant) -> str:
    """The mechanism of a mobility problem, links numbered, ground hatched and numbered 1."""
    return draw(mechanism_of(_Words(variant)))


def parallel_linkage(variant) -> str:
    """§7.4's exceptions: a parallelogram linkage with its extra cranks, links numbered, ground hatched."""
    words = _Words(variant)
    return draw(parallel_cranks(words.case, variant.param("theta").si, words.mirror == "yes"))


def draw(mech: Mechanism) -> str:
    s = Sketch()
    page = {k: _page(p) for k, p in mech.points.items()}
    middle = centre_of(list(page.values()))
    grounds = []   # where a "1" goes: beside each support, guide and slotted bracket
    # the ground's guides and slotted brackets first, then the links over them
    for slider in mech.sliders:
        c = page[slider.point]
        along = (slider.direction[0], -slider.direction[1])
        across = (-along[1], along[0])
        if (c[0] - middle[0]) * across[0] + (c[1] - middle[1]) * across[1] < 0:
            across = (-across[0], -across[1])
        half = 1.3 * SCALE
        s.guide((c[0] - along[0] * half, c[1] - along[1] * half), (c[0] + along[0] * half, c[1] + along[1] * half),
                across)
        grounds.append(((c[0] + along[0] * half * 0.8 + across[0] * 22, c[1] + along[1] * half * 0.8 + across[1] * 22),
                        across))
    for slot in mech.slots:
        if slot.body == GROUND:
            c = page[slot.point]
            along = (slot.direction[0], -slot.direction[1])
            _slot(s, c, along)
            back = unit((c[0] - middle[0], c[1] - middle[1]))
            across = (-along[1], along[0])
            if back[0] * across[0] + back[1] * across[1] < 0:
                across = (-across[0], -across[1])
            half = SLOT_LENGTH * SCALE / 2 + 8
            base = (c[0] + across[0] * 14, c[1] + across[1] * 14)
            s.hatch_line((base[0] - along[0] * half, base[1] - along[1] * half),
                         (base[0] + along[0] * half, base[1] + along[1] * half), across)
            grounds.append(((base[0] + across[0] * 14, base[1] + across[1] * 14), across))
    _links(s, mech, page)
    for point in mech.ground:
        down = _down(mech, page, point)
        s.ground_pivot(page[point], down)
        grounds.append(((page[point][0] + down[0] * 30, page[point][1] + down[1] * 30), down))
    for point in mech.pins():
        if point not in mech.ground:
            s.pin(page[point])
    for slot in mech.slots:
        s.pin(page[slot.point])
    _numbers(s, mech, page, middle)
    for at, away in grounds:
        s.label(around(at, away, 12, 14, widest=2), "1", weight="bold", cls="ground-number")
    return s.svg(f"Kinematic diagram with {mech.link_count} numbered links; the ground is link 1")


def _links(s: Sketch, mech: Mechanism, page) -> None:
    for i, link in enumerate(mech.links):
        corners = [page[p] for p in link.points]
        if link.kind == "gear":
            centre = corners[0]
            mesh = next(m for m in mech.meshes if i in (m.a, m.b))
            radius = math.dist(centre, page[mesh.contact])   # the contact lies on the line of centres
            s.d.circle(centre, radius, 2.4, cls="gear")
            s.d.circle(centre, radius - 6, 0.6, dash="3 3", cls="gear-root")
            for corner in corners[1:]:
                s.bar(centre, corner)
        elif link.kind == "block":
            slider = next(sl for sl in mech.sliders if sl.block == i)
            c = page[slider.point]
            for corner in corners[1:]:
                s.bar(c, corner)
            s.slider_block(c, (slider.direction[0], -slider.direction[1]))
        elif link.kind == "slotted" or (link.kind == "plate" and any(sl.body == i for sl in mech.slots)):
            slot = next(sl for sl in mech.slots if sl.body == i)
            ends = [page[p] for p in link.points[:2]]
            if len(corners) > 2:
                s.plate(_ordered(corners))
            else:
                s.bar(ends[0], ends[1])
            mid = centre_of([ends[0], ends[1]])
            pin = page[slot.point]
            along = unit((ends[1][0] - ends[0][0], ends[1][1] - ends[0][1]))
            centre = (pin[0] + along[0] * 0.25 * SCALE, pin[1] + along[1] * 0.25 * SCALE)
            _slot(s, centre if math.dist(centre, mid) < math.dist(ends[0], ends[1]) else mid, along)
        elif len(corners) >= 3:
            s.plate(_ordered(corners))
        else:
            s.bar(corners[0], corners[1])
            if link.kind == "free":
                s.d.circle(corners[1], 2.2, LINE, fill="black", cls="loose-end")


def _numbers(s: Sketch, mech: Mechanism, page, middle) -> None:
    for i, link in enumerate(mech.links):
        corners = [page[p] for p in link.points]
        label = str(i + 2)
        if link.kind == "gear":
            mesh = next(m for m in mech.meshes if i in (m.a, m.b))
            c = corners[0]
            r = math.dist(c, page[mesh.contact])
            spots = [((c[0] + r * 0.55 * math.cos(t), c[1] + r * 0.55 * math.sin(t) + 5), "middle", 0.0)
                     for t in (math.radians(a) for a in (-60, -120, 60, 120, 0, 180))]
            s.label(spots + around(c, (0.0, -1.0), r + 14, 14), label, weight="bold", cls="link-number")
        elif link.kind == "block":
            slider = next(sl for sl in mech.sliders if sl.block == i)
            c = page[slider.point]
            s.label(around(c, unit((c[0] - middle[0], c[1] - middle[1])) if c != middle else (0, -1), 20, 14),
                    label, weight="bold", cls="link-number")
        elif len(corners) >= 3:
            c = centre_of(corners)
            s.label([((c[0], c[1] + 5), "middle", 0.0)] + around(c, (0.0, -1.0), 10, 14), label, weight="bold",
                    cls="link-number")
        else:
            a, b = corners[0], corners[1]
            mid = centre_of([a, b])
            normal = unit((-(b[1] - a[1]), b[0] - a[0]))
            spots = [((mid[0] + normal[0] * sgn * d + along * (b[0] - a[0]), mid[1] + normal[1] * sgn * d + 5
                       + along * (b[1] - a[1])), "middle", 0.0)
                     for d in (12, 18, 26) for sgn in (1, -1) for along in (0.0, 0.15, -0.15)]
            s.label(spots, label, weight="bold", cls="link-number")
