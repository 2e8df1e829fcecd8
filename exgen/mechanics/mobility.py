"""Mobility of planar mechanisms (course text §7.2-7.4): Gruebler's equation as Kutzbach modified it.

M = 3(L - 1) - 2 J1 - J2 (eq 7.1), L counting the ground as a link, J1 the lower pairs (pins and
sliders, one freedom each) and J2 the higher pairs (a pin in a slot, a gear mesh: two freedoms).
A pin where k links meet is k - 1 joints (Figure 7.11): the commonest slip counts it once.

A `Mechanism` is the diagram the student counts from: named points (with the drawing's
coordinates), the ground's points, the moving links by the points they carry, slider blocks on
their guides, pins in slots and gear meshes.
"""
from __future__ import annotations

from dataclasses import dataclass, field

GROUND = -1   # the index that stands for the frame where a body is named


def mobility(links: int, lower_pairs: int, higher_pairs: int = 0) -> int:
    """M = 3(L - 1) - 2 J1 - J2 (eq 7.1), with L counting the ground."""
    return 3 * (links - 1) - 2 * lower_pairs - higher_pairs


@dataclass(frozen=True)
class Link:
    """A moving link: the points it carries. `kind` is how it is drawn: bar, plate, block (a slider),
    slotted (a bar with a slot along it), gear or free (a bar with one loose end)."""

    points: tuple[str, ...]
    kind: str = "bar"


@dataclass(frozen=True)
class Slider:
    """Link `block` slides on `guide` (GROUND or a link index) along `direction` through its point."""

    block: int
    point: str
    guide: int = GROUND
    direction: tuple[float, float] = (1.0, 0.0)


@dataclass(frozen=True)
class Slot:
    """The pin `point` of link `pin_link` runs in a straight slot of `body` (GROUND or a link) along `direction`."""

    point: str
    pin_link: int
    body: int
    direction: tuple[float, float]


@dataclass(frozen=True)
class Mesh:
    """Gear links `a` and `b` (each pinned to the ground at its centre) mesh at the point `contact`."""

    a: int
    b: int
    contact: str


@dataclass(frozen=True)
class Mechanism:
    points: dict[str, tuple[float, float]]
    ground: tuple[str, ...]
    links: tuple[Link, ...]
    sliders: tuple[Slider, ...] = ()
    slots: tuple[Slot, ...] = ()
    meshes: tuple[Mesh, ...] = ()
    free_ends: tuple[str, ...] = field(default=())   # points that join nothing (a loose link's end)

    def bodies_at(self, point: str) -> list[int]:
        """The bodies (GROUND and link indices) that carry `point`."""
        out = [GROUND] if point in self.ground else []
        return out + [i for i, link in enumerate(self.links) if point in link.points]

    @property
    def link_count(self) -> int:
        """L: the moving links and the ground."""
        return len(self.links) + 1

    def pins(self) -> dict[str, int]:
        """Pin joints at each point: k - 1 where k bodies meet."""
        return {p: len(self.bodies_at(p)) - 1 for p in self.points if len(self.bodies_at(p)) >= 2}

    @property
    def lower_pairs(self) -> int:
        """J1: the pins, counted k - 1 where k links meet, and one sliding pair per slider."""
        return sum(self.pins().values()) + len(self.sliders)

    @property
    def higher_pairs(self) -> int:
        """J2: pins in slots and gear meshes."""
        return len(self.slots) + len(self.meshes)

    @property
    def mobility(self) -> int:
        return mobility(self.link_count, self.lower_pairs, self.higher_pairs)

    @property
    def shared_extra(self) -> int:
        """Joints lost by counting each pin once however many links meet there."""
        return sum(k - 1 for k in self.pins().values() if k >= 2)


def instantaneous_mobility(mech: Mechanism, tolerance: float = 1e-9) -> int:
    """The mobility the drawn geometry really has (what seize-and-fix finds, §7.4): the freedoms 3 per
    moving link less the rank of the joints' constraints on small motions at the drawn position. Gruebler's
    count assumes every constraint independent; a redundant one (a crank parallel and equal to another, in a
    parallelogram) takes nothing away, so the rank, not the count, says how many inputs the linkage needs."""
    index = {i: i for i in range(len(mech.links))}
    rows: list[list[float]] = []

    def motion(body: int, point: tuple[float, float]) -> list[tuple[list[float], list[float]]]:
        """The point's small displacement (x and y rows) as a combination of the body's δx, δy, δφ."""
        x_row, y_row = [0.0] * (3 * len(index)), [0.0] * (3 * len(index))
        if body != GROUND:
            origin = mech.points[mech.links[body].points[0]]
            k = 3 * body
            x_row[k], x_row[k + 2] = 1.0, -(point[1] - origin[1])
            y_row[k + 1], y_row[k + 2] = 1.0, point[0] - origin[0]
        return [(x_row, y_row)]

    def difference(a: int, b: int, point, along=None) -> None:
        """Rows saying points of bodies a and b at `point` move alike (along `along` only, when given)."""
        (ax, ay), = motion(a, point)
        (bx, by), = motion(b, point)
        dx = [p - q for p, q in zip(ax, bx)]
        dy = [p - q for p, q in zip(ay, by)]
        if along is None:
            rows.extend([dx, dy])
        else:
            rows.append([along[0] * u + along[1] * v for u, v in zip(dx, dy)])

    def rotation(a: int, b: int) -> None:
        row = [0.0] * (3 * len(index))
        if a != GROUND:
            row[3 * a + 2] += 1.0
        if b != GROUND:
            row[3 * b + 2] -= 1.0
        rows.append(row)

    for name in mech.points:
        bodies = mech.bodies_at(name)
        for other in bodies[1:]:
            difference(bodies[0], other, mech.points[name])
    for s in mech.sliders:
        normal = (-s.direction[1], s.direction[0])
        difference(s.block, s.guide, mech.points[s.point], normal)
        rotation(s.block, s.guide)
    for s in mech.slots:
        normal = (-s.direction[1], s.direction[0])
        difference(s.pin_link, s.body, mech.points[s.point], normal)
    for m in mech.meshes:
        ca, cb = (mech.points[mech.links[g].points[0]] for g in (m.a, m.b))
        tangent = (-(cb[1] - ca[1]), cb[0] - ca[0])
        difference(m.a, m.b, mech.points[m.contact], tangent)
    return 3 * len(mech.links) - _rank(rows, tolerance)


def _rank(rows: list[list[float]], tolerance: float) -> int:
    """The rank of a small matrix, by Gaussian elimination with partial pivoting."""
    matrix = [list(r) for r in rows]
    rank, columns = 0, len(matrix[0]) if matrix else 0
    scale = max((abs(v) for r in matrix for v in r), default=1.0) or 1.0
    for col in range(columns):
        pivot = max(range(rank, len(matrix)), key=lambda i: abs(matrix[i][col]), default=None)
        if pivot is None or abs(matrix[pivot][col]) <= tolerance * scale:
            continue
        matrix[rank], matrix[pivot] = matrix[pivot], matrix[rank]
        for i in range(len(matrix)):
            if i != rank and matrix[i][col]:
                factor = matrix[i][col] / matrix[rank][col]
                matrix[i] = [a - factor * b for a, b in zip(matrix[i], matrix[rank])]
        rank += 1
    return rank
