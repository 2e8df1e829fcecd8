"""Balancing of reciprocating engines (course text §2.3): plain functions over SI floats.

In-line engines: each crank's reciprocating mass m gives a primary force m r ω² cos θ and a
secondary force (m r ω² / n) cos 2θ along the line of stroke, n = l/r. Summed as vectors at
θᵢ (primary) and 2θᵢ (secondary), the polygons give the largest unbalanced forces and, with
each crank's signed distance x from a reference plane, the couples.

Radial and V engines share one crank: a cylinder whose line is at αᵢ has its primary force
split into a direct crank at θ and a reverse crank at 2αᵢ − θ, each carrying m/2; the
secondary into a direct crank at 2θ − αᵢ and a reverse crank at 3αᵢ − 2θ, each of length
r/4n turning at 2ω. Sums here are taken with the crank along the reference line (θ = 0):
the resultants' sizes do not depend on θ.
"""
from __future__ import annotations

import math
from typing import Sequence

from .balancing import polar, vector_sum

#: Below this fraction of the largest term, a resultant is taken as exactly zero (float noise).
ZERO = 1e-9


def crank_angles(firing_order: Sequence[int], strokes: int) -> dict[int, float]:
    """Crank angle of each cylinder (radians, from crank 1) for a firing order: cranks are spaced
    720°/N on a four-stroke engine and 360°/N on a two-stroke, in the order they fire."""
    if strokes not in (2, 4):
        raise ValueError(f"an engine is two- or four-stroke, not {strokes}-stroke")
    count = len(firing_order)
    if sorted(firing_order) != list(range(1, count + 1)):
        raise ValueError(f"firing order {firing_order} must name cylinders 1..{count} once each")
    interval = (strokes * math.pi) / count
    return {cylinder: (k * interval) % (2 * math.pi) for k, cylinder in enumerate(firing_order)}


def parse_firing_order(text: str) -> tuple[int, ...]:
    """'1-3-4-2' -> (1, 3, 4, 2)."""
    return tuple(int(part) for part in str(text).replace(",", "-").split("-"))


def _clean(x: float, y: float, scale: float) -> tuple[float, float]:
    """(magnitude, angle) with float noise below ZERO * scale taken as zero."""
    size, angle = polar(x, y)
    return (0.0, 0.0) if size <= ZERO * max(scale, 1e-300) else (size, angle)


def polygon(sizes: Sequence[float], angles: Sequence[float], harmonic: int = 1) -> tuple[float, float]:
    """Resultant (magnitude, angle) of sizes at harmonic × angles: Σ sᵢ ∠(k θᵢ)."""
    x, y = vector_sum((s, harmonic * a) for s, a in zip(sizes, angles))
    return _clean(x, y, sum(abs(s) for s in sizes))


def centred_positions(count: int, pitch: float) -> list[float]:
    """Signed distances of equally spaced cylinders from the engine's centre plane, cylinder 1 negative."""
    return [(i - (count - 1) / 2) * pitch for i in range(count)]


def inline_unbalance(mass: float, radius: float, n: float, omega: float, angles: Sequence[float],
                     positions: Sequence[float], harmonic: int = 1) -> tuple[tuple[float, float], tuple[float, float]]:
    """((force, angle), (couple, angle)) of the primary (harmonic 1) or secondary (harmonic 2)
    unbalance of an in-line engine; the secondary carries the factor 1/n."""
    scale = mass * radius * omega ** 2 / (n if harmonic == 2 else 1.0)
    force = polygon([scale] * len(angles), angles, harmonic)
    couple = polygon([scale * x for x in positions], angles, harmonic)
    return force, couple


def peak_crank_angle(resultant_angle: float, harmonic: int = 2) -> float:
    """The first crank angle after the reference crank's inner dead centre at which a harmonic's
    unbalanced force along the line of stroke is largest in size.

    With the resultant of the k-th harmonic at ψ in its polygon (cranks drawn at kθ), the force along
    the line of stroke is F cos(kθ + ψ): largest, one way or the other, when kθ + ψ is a whole number
    of half turns, so θ = ((−ψ) mod 180°)/k, in [0, 180°/k).
    """
    return ((-resultant_angle) % math.pi) / harmonic


def radial_cranks(cylinder_angles: Sequence[float]) -> dict[str, tuple[float, float]]:
    """Resultants of the unit direct and reverse cranks, primary and secondary, as
    (size in cranks, angle) with the crank on the reference line: |Σ ∠φᵢ| for each set."""
    count = len(cylinder_angles)
    ones = [1.0] * count
    return {
        "primary_direct": polygon(ones, [0.0] * count),
        "primary_reverse": polygon(ones, [2 * a for a in cylinder_angles]),
        "secondary_direct": polygon(ones, [-a for a in cylinder_angles]),
        "secondary_reverse": polygon(ones, [3 * a for a in cylinder_angles]),
    }


def crank_force(mass: float, radius: float, omega: float, n: float | None = None) -> float:
    """The force on one direct or reverse crank: (m/2) r ω² (primary), or with n, (m/2)(2ω)² r/(4n)
    = (m/2) r ω² / n (secondary)."""
    primary = mass / 2 * radius * omega ** 2
    return primary if n is None else mass / 2 * (2 * omega) ** 2 * radius / (4 * n)


def radial_cylinder_angles(count: int) -> list[float]:
    """Lines of stroke of a radial engine with `count` cylinders equally spaced."""
    return [2 * math.pi * i / count for i in range(count)]


def v_cylinder_angles(included: float) -> list[float]:
    """Lines of stroke of a two-cylinder V engine, at ±half the included angle from its centre line."""
    return [included / 2, -included / 2]
