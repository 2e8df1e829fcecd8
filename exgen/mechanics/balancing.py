"""Balancing of rotating masses (course text §2.1-2.2): plain functions over SI floats.

A mass m at radius r and angle θ (radians, measured from a reference radius in one sense)
is the vector m·r(cos θ, sin θ). Balance needs the sum of m·r vectors to vanish (one plane,
eq. 2.1) and, for several planes, also the sum of m·r·l moment vectors about a reference
plane, l being signed: planes on the other side of the reference have l < 0.
"""
from __future__ import annotations

import math
from typing import Iterable

Vector = tuple[float, float]
TWO_PI = 2 * math.pi


def components(mr: float, angle: float) -> Vector:
    """The horizontal and vertical components of m·r at `angle`."""
    return mr * math.cos(angle), mr * math.sin(angle)


def vector_sum(vectors: Iterable[tuple[float, float]]) -> Vector:
    """Sum of (magnitude, angle) vectors as (x, y) components."""
    x = y = 0.0
    for magnitude, angle in vectors:
        dx, dy = components(magnitude, angle)
        x, y = x + dx, y + dy
    return x, y


def polar(x: float, y: float) -> tuple[float, float]:
    """(magnitude, angle in [0, 2π)) of the vector (x, y)."""
    angle = math.atan2(y, x) % TWO_PI
    return math.hypot(x, y), 0.0 if angle >= TWO_PI else angle  # -1e-17 % 2π rounds to 2π


def balancing_vector(vectors: Iterable[tuple[float, float]]) -> tuple[float, float]:
    """The (magnitude, angle) that closes the polygon: equal to the resultant, half a turn round."""
    x, y = vector_sum(vectors)
    return polar(-x, -y)


def two_directions(target: Vector, a1: float, a2: float) -> tuple[float, float]:
    """The signed sizes (s1, s2) with s1 ∠a1 + s2 ∠a2 = target (Cramer's rule).

    Raises ValueError when the two directions are parallel (no unique answer)."""
    c1, s1, c2, s2 = math.cos(a1), math.sin(a1), math.cos(a2), math.sin(a2)
    det = c1 * s2 - c2 * s1
    if abs(det) < 1e-9:
        raise ValueError("the two directions are parallel")
    return (target[0] * s2 - target[1] * c2) / det, (c1 * target[1] - s1 * target[0]) / det


def rotating_force(mr: float, omega: float) -> float:
    """Centrifugal force of an m·r product at angular speed ω: F = m r ω² (eq. 2.2)."""
    return mr * omega ** 2


def two_plane_correction(rows: Iterable[tuple[float, float, float]], l_q: float
                         ) -> tuple[tuple[float, float], tuple[float, float]]:
    """Balance rows of (m·r, l, θ), l measured from correction plane P, by corrections in P and in Q
    at l_q: moments about P give Q's m·r, then forces give P's. Returns ((mr_Q, θ_Q), (mr_P, θ_P))."""
    rows = list(rows)
    mx, my = vector_sum((mr * l, angle) for mr, l, angle in rows)
    q_size, q_angle = polar(-mx / l_q, -my / l_q)
    fx, fy = vector_sum([(mr, angle) for mr, _, angle in rows] + [(q_size, q_angle)])
    return (q_size, q_angle), polar(-fx, -fy)
