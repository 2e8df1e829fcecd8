"""Planar four-bar linkages (course text §7.5-7.6, 7.9): plain functions over SI floats.

Angles are radians, measured from +x counter-clockwise (the chapter's convention, unlike
chapter 2's). Lengths are in any one unit. The four-bar is named as the text's figure for
circuit 1: ground pivots A (crank) and D (rocker), crank AB = L2, coupler BC = L3, rocker
CD = L4, ground AD = L1; BD is the diagonal and γ the transmission angle at C.

The circuit is the text's: in circuit 1 (eqs 7.5-7.6) θ4 = θ3 + γ, so C lies on the left of
the diagonal BD seen from B; in circuit 2 (eqs 7.7-7.8) θ4 = θ3 − γ and C lies on its right.
A linkage that cannot close at the asked crank angle raises NotAssemblable. The solvers work a
position step by step from these equations (so that a student's BD or γ carries forward); the figures
compose them into whole positions (exgen.figures.linkage_poses).
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

CIRCUITS = (1, 2)
GRASHOF_KINDS = ("crank-rocker", "double-crank", "double-rocker", "change-point", "triple-rocker")
#: Lengths equal to this relative precision are equal (S + L = P + Q is a change point).
EQUAL = 1e-9


class NotAssemblable(ValueError):
    """The links cannot be joined at this input position."""


def wrap(angle: float) -> float:
    """An angle in (-π, π]."""
    turned = math.remainder(angle, 2 * math.pi)
    return math.pi if turned == -math.pi else turned


def cosine_law_angle(adjacent1: float, adjacent2: float, opposite: float) -> float:
    """The angle between two sides of a triangle from the three sides (cosine law)."""
    cos = (adjacent1 ** 2 + adjacent2 ** 2 - opposite ** 2) / (2 * adjacent1 * adjacent2)
    if abs(cos) > 1 + EQUAL:
        raise NotAssemblable(f"no triangle has sides {adjacent1:g}, {adjacent2:g} and {opposite:g}")
    return math.acos(max(-1.0, min(1.0, cos)))


# ---- Grashof's criterion (§7.5, eq 7.2, Table 7.1) ---------------------------------------

@dataclass(frozen=True)
class Grashof:
    """The criterion's terms and the class of a four-bar with its ground link named."""

    s: float
    l: float
    p: float
    q: float
    kind: str
    shortest: str  # which link is shortest: 'ground', 'crank', 'coupler' or 'rocker'

    @property
    def s_plus_l(self) -> float:
        return self.s + self.l

    @property
    def p_plus_q(self) -> float:
        return self.p + self.q


def grashof(ground: float, crank: float, coupler: float, rocker: float) -> Grashof:
    """Classify by S + L against P + Q and by where the shortest link is (Table 7.1).

    S + L < P + Q: the shortest link turns fully; grounded beside it -> crank-rocker, the
    shortest grounded -> double-crank, the link opposite it grounded -> double-rocker.
    S + L = P + Q: change point. S + L > P + Q: no link turns fully, a triple rocker.
    """
    named = {"ground": ground, "crank": crank, "coupler": coupler, "rocker": rocker}
    s, p, q, l = sorted(named.values())
    shortest = min(named, key=named.get)
    return Grashof(s, l, p, q, grashof_kind(s + l, p + q, shortest), shortest)


def grashof_kind(s_plus_l: float, p_plus_q: float, shortest: str) -> str:
    """Table 7.1 from the two sums and the position of the shortest link."""
    if abs(s_plus_l - p_plus_q) <= EQUAL * max(s_plus_l, p_plus_q):
        return "change-point"
    if s_plus_l > p_plus_q:
        return "triple-rocker"
    return {"ground": "double-crank", "coupler": "double-rocker"}.get(shortest, "crank-rocker")


# ---- four-bar position (§7.6, eqs 7.3-7.8) ------------------------------------------------

def diagonal(ground: float, crank: float, theta2: float) -> float:
    """BD = sqrt(L1² + L2² - 2 L1 L2 cos θ2) (eq 7.3)."""
    return math.sqrt(max(0.0, ground ** 2 + crank ** 2 - 2 * ground * crank * math.cos(theta2)))


def transmission_angle(coupler: float, rocker: float, bd: float) -> float:
    """γ = cos⁻¹((L3² + L4² - BD²) / (2 L3 L4)) (eq 7.4): the angle between coupler and rocker."""
    try:
        return cosine_law_angle(coupler, rocker, bd)
    except NotAssemblable:
        raise NotAssemblable(f"coupler {coupler:g} and rocker {rocker:g} cannot span BD = {bd:g}") from None


def _half_angle(numerator: float, denominator: float, fallback: complex) -> float:
    """2 tan⁻¹(numerator / denominator), the text's form, as a direction in (-π, π].

    When both vanish the half-angle form is indeterminate; `fallback` is the direction itself.
    """
    if math.hypot(numerator, denominator) < 1e-12 * (abs(fallback) or 1.0):
        return wrap(cmath.phase(fallback))
    return wrap(2 * math.atan2(numerator, denominator))


def _sign(circuit: int) -> float:
    if circuit not in CIRCUITS:
        raise ValueError(f"circuit must be 1 or 2, not {circuit!r}")
    return 1.0 if circuit == 1 else -1.0


def coupler_angle(ground: float, crank: float, coupler: float, rocker: float, theta2: float, gamma: float,
                  circuit: int = 1) -> float:
    """θ3 = 2 tan⁻¹[(-L2 sin θ2 ± L4 sin γ) / (L1 + L3 - L2 cos θ2 - L4 cos γ)] (eq 7.5, 7.7 with -)."""
    sign = _sign(circuit)
    l1, l2, l3, l4 = ground, crank, coupler, rocker
    # e^{iθ3} (L3 - L4 e^{±iγ}) = L1 - L2 e^{iθ2}, the vector B -> D
    fallback = complex(l1 - l2 * math.cos(theta2), -l2 * math.sin(theta2)) / \
        complex(l3 - l4 * math.cos(gamma), -sign * l4 * math.sin(gamma))
    return _half_angle(*_coupler_terms(l1, l2, l3, l4, theta2, gamma, sign), fallback)


def rocker_angle(ground: float, crank: float, coupler: float, rocker: float, theta2: float, gamma: float,
                 circuit: int = 1) -> float:
    """θ4 = 2 tan⁻¹[(L2 sin θ2 ∓ L3 sin γ) / (L4 - L1 + L2 cos θ2 - L3 cos γ)] (eq 7.6, 7.8 with +)."""
    sign = _sign(circuit)
    l1, l2, l3, l4 = ground, crank, coupler, rocker
    # e^{iθ4} (L4 - L3 e^{∓iγ}) = L2 e^{iθ2} - L1, the vector D -> B
    fallback = complex(l2 * math.cos(theta2) - l1, l2 * math.sin(theta2)) / \
        complex(l4 - l3 * math.cos(gamma), sign * l3 * math.sin(gamma))
    return _half_angle(*_rocker_terms(l1, l2, l3, l4, theta2, gamma, sign), fallback)


def _coupler_terms(l1, l2, l3, l4, theta2, gamma, sign) -> tuple[float, float]:
    """Numerator and denominator of eq 7.5 (7.7)."""
    return (-l2 * math.sin(theta2) + sign * l4 * math.sin(gamma),
            l1 + l3 - l2 * math.cos(theta2) - l4 * math.cos(gamma))


def _rocker_terms(l1, l2, l3, l4, theta2, gamma, sign) -> tuple[float, float]:
    """Numerator and denominator of eq 7.6 (7.8)."""
    return (l2 * math.sin(theta2) - sign * l3 * math.sin(gamma),
            l4 - l1 + l2 * math.cos(theta2) - l3 * math.cos(gamma))


def half_angle_conditioning(ground: float, crank: float, coupler: float, rocker: float, theta2: float,
                            gamma: float, circuit: int = 1) -> float:
    """How far the half-angle fractions of eqs 7.5-7.8 are from 0/0, as a fraction of the longest link:
    the smaller of |(numerator, denominator)| for θ3 and for θ4. Near 0 (a kite or parallelogram
    linkage with B on the diagonal's far side: L1 = L4, L2 = L3 and γ = θ2) the fraction reads 0/0
    in the working, and the rounding of four printed figures decides the angle. A denominator that
    cancels exactly (x/0, a calculator's error) counts as 0 too."""
    sign = _sign(circuit)
    lengths = (ground, crank, coupler, rocker, theta2, gamma, sign)
    longest = max(ground, crank, coupler, rocker)
    fractions = (_coupler_terms(*lengths), _rocker_terms(*lengths))
    if any(abs(denominator) < 1e-9 * longest for _, denominator in fractions):
        return 0.0
    return min(math.hypot(*terms) for terms in fractions) / longest


def can_assemble(ground: float, crank: float, coupler: float, rocker: float, theta2: float) -> bool:
    """Whether coupler and rocker reach across BD at this crank angle (either circuit)."""
    bd = diagonal(ground, crank, theta2)
    return abs(coupler - rocker) <= bd <= coupler + rocker


def polar(origin: tuple[float, float], length: float, angle: float) -> tuple[float, float]:
    """The point `length` from `origin` in the direction `angle` (eq 7.9)."""
    return origin[0] + length * math.cos(angle), origin[1] + length * math.sin(angle)


def side(a, b, point) -> float:
    """> 0 when `point` lies on the left of the line a -> b, < 0 on its right."""
    return (b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0])


def rocker_pin(a: tuple[float, float], crank: float, coupler: float, rocker: float, theta2: float,
               turn: float) -> tuple[tuple[float, float], tuple[float, float]]:
    """The crank pin B and rocker pin C of a four-bar whose rocker pivots at the origin and whose crank pivots
    at `a`, by the four-bar example's vector method (§7.9): R_H = R_1 + R_2 from the origin to B, and C at
    the angle φ (cosine law in the triangle of R_H, coupler and rocker) from it, counter-clockwise for
    `turn` = +1 and clockwise for -1."""
    b = polar(a, crank, theta2)
    phi = cosine_law_angle(math.hypot(*b), rocker, coupler)
    return b, polar((0.0, 0.0), rocker, math.atan2(b[1], b[0]) + turn * phi)


# ---- coupler point (§7.6, Figure 7.21; the four-bar example's point C) --------------------

def coupler_point(c: tuple[float, float], theta3: float, distance: float, alpha: float,
                  left_of_bc: bool) -> tuple[float, float]:
    """The point `distance` from C, at the angle α from CB, on the given side of the line B -> C.

    Seen from C the coupler points back along θ3 + π; a point on the right of B -> C is turned
    counter-clockwise from there (the example's θ6 = θ3 + α), a point on the left clockwise.
    """
    turn = -alpha if left_of_bc else alpha
    return polar(c, distance, theta3 + math.pi + turn)


def plate_pose(a: tuple[float, float], crank: float, coupler: float, rocker: float, theta2: float, turn: float,
               cp: float, bp: float, left: bool) -> dict[str, tuple[float, float]]:
    """B, C and the plate's point P of the four-bar of `rocker_pin` at the crank angle theta2, its coupler a
    triangular plate BCP with sides CP and BP, P on the left (or right) of B -> C."""
    b, c = rocker_pin(a, crank, coupler, rocker, theta2, turn)
    alpha = cosine_law_angle(cp, coupler, bp)
    return {"B": b, "C": c, "P": coupler_point(c, math.atan2(c[1] - b[1], c[0] - b[0]), cp, alpha, left)}


def inside_triangle(point, corners) -> bool:
    """Whether `point` lies inside the triangle `corners` (on the same side of its three edges)."""
    sides = [side(corners[k], corners[(k + 1) % 3], point) for k in range(3)]
    return all(x > 0 for x in sides) or all(x < 0 for x in sides)


# ---- limit positions of a crank-rocker (Problems 7.2-7.3) ---------------------------------

@dataclass(frozen=True)
class Limits:
    """The rocker's two extreme positions, where crank and coupler line up."""

    theta4_extended: float   # crank and coupler in line, AC = L3 + L2
    theta4_folded: float     # crank folded back on the coupler, AC = L3 - L2
    theta2_extended: float
    theta2_folded: float

    @property
    def swing(self) -> float:
        return abs(self.theta4_extended - self.theta4_folded)


def rocker_limits(ground: float, crank: float, coupler: float, rocker: float) -> Limits:
    """Limit positions of a crank-rocker in circuit 1 (C above the ground line AD)."""
    if crank >= coupler:
        raise NotAssemblable("the crank must be shorter than the coupler to fold back on it")
    angles = []
    for reach in (coupler + crank, coupler - crank):
        at_d = cosine_law_angle(ground, rocker, reach)
        at_a = cosine_law_angle(ground, reach, rocker)
        angles.append((math.pi - at_d, at_a))
    (t4_ext, t2_ext), (t4_fold, a_fold) = angles
    return Limits(t4_ext, t4_fold, t2_ext, wrap(a_fold + math.pi))


# ---- a link swung by a linear actuator (Problem 7.2) --------------------------------------

def actuator_link_angle(pivots: float, arm: float, actuator: float) -> float:
    """The angle at the link's pivot between the line to the actuator's pivot and the link."""
    return cosine_law_angle(pivots, arm, actuator)


# ---- two-position synthesis (§7.11) -------------------------------------------------------

def bisector_on_line(p1: tuple[float, float], p2: tuple[float, float], y_line: float) -> tuple[float, float]:
    """Where the perpendicular bisector of p1 p2 meets the line y = y_line: a ground pivot
    from which a link moves the point p1 to p2."""
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    if abs(dx) < EQUAL * (abs(dy) + 1.0):
        raise NotAssemblable("the bisector is parallel to the pivot line")
    mx, my = (p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2
    # points q on the bisector satisfy (q - m)·(p2 - p1) = 0
    return mx - (y_line - my) * dy / dx, y_line


def circumcentre(p1: tuple[float, float], p2: tuple[float, float], p3: tuple[float, float]) -> tuple[float, float]:
    """The point equally far from three positions of a moving pivot (§7.11, three positions): where the
    perpendicular bisectors of p1 p2 and p2 p3 cross, the only ground pivot from which one link reaches all
    three."""
    (ax, ay), (bx, by), (cx, cy) = p1, p2, p3
    det = 2 * ((bx - ax) * (cy - by) - (by - ay) * (cx - bx))
    scale = max(abs(v) for v in (ax, ay, bx, by, cx, cy)) + 1.0
    if abs(det) < EQUAL * scale * scale:
        raise NotAssemblable("three positions in a line: their bisectors are parallel")
    # each bisector: (q - m)·(b - a) = 0, i.e. q·(b - a) = (|b|² - |a|²)/2
    k1 = (bx * bx + by * by - ax * ax - ay * ay)
    k2 = (cx * cx + cy * cy - bx * bx - by * by)
    x = (k1 * (cy - by) - k2 * (by - ay)) / det
    y = (k2 * (bx - ax) - k1 * (cx - bx)) / det
    return tuple(0.0 if abs(v) < EQUAL * scale else v for v in (x, y))


def moves_between(a, d, b1, c1, b2, c2, samples: int = 90) -> bool:
    """Whether the four-bar A-B-C-D (ground pivots a, d) carries B and C from (b1, c1) to (b2, c2)
    without leaving its circuit: the crank turns the short way round and the linkage assembles
    all along, with C on the same side of BD at both ends."""
    ground, crank = math.dist(a, d), math.dist(a, b1)
    coupler, rocker = math.dist(b1, c1), math.dist(d, c1)
    theta1 = math.atan2(d[1] - a[1], d[0] - a[0])
    start = math.atan2(b1[1] - a[1], b1[0] - a[0]) - theta1
    turn = wrap(math.atan2(b2[1] - a[1], b2[0] - a[0]) - theta1 - start)
    if (side(b1, d, c1) > 0) != (side(b2, d, c2) > 0):
        return False
    return all(can_assemble(ground, crank, coupler, rocker, start + turn * k / samples) for k in range(samples + 1))
