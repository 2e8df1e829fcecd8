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
