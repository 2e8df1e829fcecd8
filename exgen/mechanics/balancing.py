"""Balancing of rotating masses (course text chapter 2): plain functions over SI floats.

A mass m at radius r and angle θ (radians, measured from a reference radius in one sense)
is the vector m·r(cos θ, sin θ). Balance needs the sum of m·r vectors to vanish (one plane,
eq. 2.1) and, for several planes, also the sum of m·r·l moment vectors about a reference plane.
"""
from __future__ import annotations

import math
from typing import Iterable


def components(mr: float, angle: float) -> tuple[float, float]:
    """The horizontal and vertical components of m·r at `angle`."""
    return mr * math.cos(angle), mr * math.sin(angle)


def vector_sum(vectors: Iterable[tuple[float, float]]) -> tuple[float, float]:
    """Sum of (magnitude, angle) vectors as (x, y) components."""
    x = y = 0.0
    for magnitude, angle in vectors:
        dx, dy = components(magnitude, angle)
        x, y = x + dx, y + dy
    return x, y


def polar(x: float, y: float) -> tuple[float, float]:
    """(magnitude, angle in [0, 2π)) of the vector (x, y)."""
    return math.hypot(x, y), math.atan2(y, x) % (2 * math.pi)


def balancing_vector(vectors: Iterable[tuple[float, float]]) -> tuple[float, float]:
    """The (magnitude, angle) that closes the polygon: equal to the resultant, half a turn round."""
    x, y = vector_sum(vectors)
    return polar(-x, -y)
