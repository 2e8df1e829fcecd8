"""A catalogue of planar mechanisms to count (course text §7.3-7.4, Figures 7.5-7.15).

A mechanism is a base (four-bar, slider-crank, crank and slotted lever, gear pair, five-bar,
two-bar truss) with up to three additions at the base's sites: a dyad to the ground (which makes
a Watt or Stephenson six-bar of a four-bar), a rod and slider, a dyad on an existing pin (a joint
shared by three links), a link whose pin runs in a slot of the frame, a brace to the ground, or a
loose link. Each addition is drawn in the free space its site points to, so every combination can
be drawn without one part crossing another; coordinates are the diagram's (about 10 units wide,
y up) and a kinematic diagram need not be to scale (§7.4).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .mobility import GROUND, Link, Mechanism, Mesh, Slider, Slot

BASES = ("four-bar", "slider-crank", "slotted-lever", "gear-pair", "five-bar", "truss")
ADDITIONS = ("none", "dyad", "slider", "shared", "slot", "brace", "loose")
WIDTH = 10.0


@dataclass(frozen=True)
class Site:
    """Where an addition may go: a point `anchor` on link `host` (off its line, so the host becomes a
    plate), the direction `out` of free space from there, and for a dyad on a shared pin, the pin and
    its own direction."""

    host: int
    anchor: tuple[float, float]
    out: tuple[float, float]
    pin: str
    pin_out: tuple[float, float]


def _base(name: str) -> tuple[Mechanism, tuple[Site, Site, Site]]:
    if name == "four-bar":
        points = {"O2": (1.0, 1.0), "A": (1.8, 3.4), "B": (6.4, 4.4), "O4": (7.8, 1.0)}
        mech = Mechanism(points, ("O2", "O4"), (Link(("O2", "A")), Link(("A", "B")), Link(("B", "O4"))))
        sites = (Site(1, (4.2, 5.0), (0.0, 1.0), "A", (-0.35, 1.0)),
                 Site(2, (7.85, 3.0), (1.0, 0.1), "B", (1.0, 0.55)),
                 Site(0, (0.65, 2.5), (-1.0, 0.0), "O2", (-1.0, -0.15)))
    elif name == "slider-crank":
        points = {"O2": (1.2, 2.0), "A": (2.2, 3.8), "B": (7.0, 2.0)}
        mech = Mechanism(points, ("O2",), (Link(("O2", "A")), Link(("A", "B")), Link(("B",), "block")),
                         sliders=(Slider(2, "B", GROUND, (1.0, 0.0)),))
        sites = (Site(1, (4.9, 3.75), (0.0, 1.0), "A", (-0.35, 1.0)),
                 Site(2, (7.7, 2.9), (1.0, 0.35), "B", (0.55, 1.0)),
                 Site(0, (0.9, 3.35), (-1.0, 0.1), "O2", (-1.0, -0.2)))
    elif name == "slotted-lever":
        o4, a = (3.4, 0.3), (4.4, 4.2)
        s = (o4[0] + 1.45 * (a[0] - o4[0]), o4[1] + 1.45 * (a[1] - o4[1]))
        points = {"O2": (2.9, 3.2), "A": a, "O4": o4, "S": s}
        direction = (a[0] - o4[0], a[1] - o4[1])
        mech = Mechanism(points, ("O2", "O4"), (Link(("O2", "A")), Link(("O4", "S"), "slotted")),
                         slots=(Slot("A", 0, 1, direction),))
        sites = (Site(1, (5.45, 6.0), (1.0, 0.3), "O2", (-1.0, 0.2)),
                 Site(0, (3.3, 4.3), (-0.6, 1.0), "O4", (-1.0, -0.3)),
                 Site(1, (4.45, 1.5), (1.0, -0.2), "O4", (1.0, -0.1)))
    elif name == "gear-pair":
        c2, c3, r2 = (2.6, 3.0), (6.2, 3.0), 1.4
        points = {"C2": c2, "C3": c3, "K": (c2[0] + r2, c2[1])}
        mech = Mechanism(points, ("C2", "C3"), (Link(("C2",), "gear"), Link(("C3",), "gear")),
                         meshes=(Mesh(0, 1, "K"),))
        sites = (Site(0, _on(c2, 0.9, 125), (-0.6, 1.0), "C2", (-1.0, -0.3)),
                 Site(1, _on(c3, 1.5, 55), (0.6, 1.0), "C3", (1.0, 0.2)),
                 Site(1, _on(c3, 1.5, -60), (0.45, -1.0), "C3", (0.35, -1.0)))
    elif name == "five-bar":
        points = {"O2": (1.0, 1.0), "A": (1.5, 3.3), "B": (4.6, 5.0), "C": (7.7, 3.4), "O5": (8.0, 1.0)}
        mech = Mechanism(points, ("O2", "O5"), (Link(("O2", "A")), Link(("A", "B")), Link(("B", "C")),
                                                Link(("C", "O5"))))
        sites = (Site(1, (2.55, 4.75), (-0.35, 1.0), "B", (0.0, 1.0)),
                 Site(3, (8.55, 2.3), (1.0, 0.0), "C", (1.0, 0.45)),
                 Site(0, (0.55, 2.25), (-1.0, 0.0), "O2", (-1.0, -0.15)))
    elif name == "truss":
        points = {"P": (1.5, 1.0), "R": (4.5, 4.5), "Q": (7.5, 1.0)}
        mech = Mechanism(points, ("P", "Q"), (Link(("P", "R")), Link(("R", "Q"))))
        sites = (Site(0, (2.45, 3.3), (-0.6, 0.8), "R", (0.0, 1.0)),
                 Site(1, (6.55, 3.3), (0.6, 0.8), "Q", (1.0, 0.2)),
                 Site(0, (1.75, 2.2), (-1.0, 0.1), "P", (-1.0, -0.2)))
    else:
        raise ValueError(f"no base mechanism {name!r}; the catalogue has {', '.join(BASES)}")
    return mech, sites


def _on(centre, radius: float, degrees: float) -> tuple[float, float]:
    t = math.radians(degrees)
    return centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t)


def _unit(v) -> tuple[float, float]:
    length = math.hypot(*v)
    return v[0] / length, v[1] / length


def _at(origin, u, v, along: float, across: float) -> tuple[float, float]:
    return origin[0] + along * u[0] + across * v[0], origin[1] + along * u[1] + across * v[1]


def build(base: str, additions: tuple[str, ...] = (), mirror: bool = False) -> Mechanism:
    """The base with an addition at each of its sites in turn ('none' leaves a site empty)."""
    mech, sites = _base(base)
    points, ground = dict(mech.points), list(mech.ground)
    links = [Link(link.points, link.kind) for link in mech.links]
    sliders, slots, meshes, loose = list(mech.sliders), list(mech.slots), list(mech.meshes), []
    for k, (site, kind) in enumerate(zip(sites, additions), start=1):
        if kind not in ADDITIONS:
            raise ValueError(f"no addition {kind!r}; the catalogue has {', '.join(ADDITIONS)}")
        if kind == "none":
            continue
        if kind == "shared":
            start, u = site.pin, _unit(site.pin_out)
        else:
            start, u = f"H{k}", _unit(site.out)
            points[start] = site.anchor
            host = links[site.host]
            kind_of_host = "plate" if host.kind in ("bar", "plate") else host.kind
            links[site.host] = Link(host.points + (start,), kind_of_host)
        v = (-u[1], u[0])
        origin = points[start]
        x, g = f"X{k}", f"G{k}"
        if kind in ("dyad", "shared"):
            points[x], points[g] = _at(origin, u, v, 1.7, 0.9), _at(origin, u, v, 2.5, -0.6)
            links += [Link((start, x)), Link((x, g))]
            ground.append(g)
        elif kind == "slider":
            points[x] = _at(origin, u, v, 2.4, 0.4)
            links += [Link((start, x)), Link((x,), "block")]
            sliders.append(Slider(len(links) - 1, x, GROUND, v))
        elif kind == "slot":
            points[x] = _at(origin, u, v, 2.0, 0.0)
            links.append(Link((start, x)))
            slots.append(Slot(x, len(links) - 1, GROUND, _unit((u[0] + v[0], u[1] + v[1]))))  # not square to the link
        elif kind == "brace":
            points[g] = _at(origin, u, v, 2.2, -0.3)
            links.append(Link((start, g)))
            ground.append(g)
        else:  # loose
            points[x] = _at(origin, u, v, 1.8, 0.6)
            links.append(Link((start, x), "free"))
            loose.append(x)
    built = Mechanism(points, tuple(ground), tuple(links), tuple(sliders), tuple(slots), tuple(meshes), tuple(loose))
    return mirrored(built) if mirror else built


def mirrored(mech: Mechanism) -> Mechanism:
    """The same mechanism drawn the other way round (x -> WIDTH - x)."""
    flip = (lambda p: (WIDTH - p[0], p[1]))
    turn = (lambda d: (-d[0], d[1]))
    return Mechanism({k: flip(p) for k, p in mech.points.items()}, mech.ground, mech.links,
                     tuple(Slider(s.block, s.point, s.guide, turn(s.direction)) for s in mech.sliders),
                     tuple(Slot(s.point, s.pin_link, s.body, turn(s.direction)) for s in mech.slots),
                     mech.meshes, mech.free_ends)


def misleading(mech: Mechanism) -> bool:
    """Whether Gruebler's count misleads for this mechanism (the exceptions §7.4 warns of): loose links
    hanging on a part that has members to spare add freedoms that the spare members seem to cancel,
    so M looks like 0 or 1 while the loose links swing and the rest is locked."""
    loose = len(mech.free_ends)
    return loose > 0 and mech.mobility - loose < 0


#: Linkages whose geometry Gruebler's count cannot see (§7.4, Figure 7.13): a parallelogram four-bar, and
#: the same with one or two more cranks joining ground and coupler. Parallel and equal, an extra crank moves
#: as the coupler already makes it (a redundant constraint); set askew, it locks the linkage.
PARALLEL_CASES = ("four-bar", "three cranks", "three cranks, one askew", "four cranks")
CRANK = 2.6        # the cranks' length, in diagram units
#: The ground pivots' heights, so the coupler is a plate of the pivots' own shape.
PIVOT_RISE = (0.0, 0.7, 0.0, 0.7)


def parallel_cranks(case: str, theta: float, mirror: bool = False) -> Mechanism:
    """The linkage of `case` with its cranks at `theta` (radians from +x): ground pivots O2, O6, O8, O4 along
    the frame, each crank joining one to the coupler at A, C, D, B; an askew crank leans 35° off the others."""
    if case not in PARALLEL_CASES:
        raise ValueError(f"no case {case!r}; the catalogue has {', '.join(PARALLEL_CASES)}")
    count = {"four-bar": 2, "four cranks": 4}.get(case, 3)
    names = (("O2", "A"), ("O6", "C"), ("O8", "D"), ("O4", "B"))
    chosen = [names[0]] + list(names[1:count - 1]) + [names[3]]
    spacing = 7.0 / (count - 1)
    points = {}
    for k, (pivot, pin) in enumerate(chosen):
        o = (1.0 + k * spacing, 1.0 + PIVOT_RISE[k])
        points[pin] = (o[0] + CRANK * math.cos(theta), o[1] + CRANK * math.sin(theta))
        points[pivot] = o
    if case.endswith("askew"):
        pivot, pin = chosen[1]
        lean = theta + math.radians(35)
        points[pivot] = (points[pin][0] - CRANK * math.cos(lean), points[pin][1] - CRANK * math.sin(lean))
    coupler = Link(tuple(pin for _, pin in chosen), "plate" if count > 2 else "bar")
    cranks = tuple(Link((pivot, pin)) for pivot, pin in chosen)
    mech = Mechanism(points, tuple(pivot for pivot, _ in chosen), (cranks[0], coupler) + cranks[1:])
    return mirrored(mech) if mirror else mech
