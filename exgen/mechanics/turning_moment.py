"""A turning moment given as an equation in the crank angle (Problems 3.2 and 3.5).

T(θ) = T₀ + Σ (bₙ sin nθ + cₙ cos nθ) integrates in closed form,

    ∫ T dθ = T₀ θ + Σ (bₙ (1 − cos nθ) + cₙ sin nθ) / n      (from θ = 0),

so the energy above the resisting torque at any crank angle is exact. Its greatest and
least values over a cycle are at crossings, where engine and resisting torque are equal;
the crossings are found by bracketing sign changes on a fine grid and bisecting each to
the last bit. The fluctuation of energy is the greatest minus the least.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import reduce

#: Grid points per cycle and per harmonic when bracketing crossings: a trigonometric
#: polynomial of degree K has at most 2K zeros a cycle, so 512 K points leave every
#: bracket holding at most one crossing unless two lie within 1/100 of a degree.
GRID_PER_HARMONIC = 512
TAU = 2.0 * math.pi


@dataclass(frozen=True)
class TrigTorque:
    """T(θ) = mean + Σ (sin_n sin nθ + cos_n cos nθ); `terms` holds (n, sin_n, cos_n)."""

    mean: float
    terms: tuple[tuple[int, float, float], ...] = ()

    def __post_init__(self):
        for n, _, _ in self.terms:
            if not (isinstance(n, int) and n >= 1):
                raise ValueError(f"a harmonic is a whole number 1, 2, 3..., not {n!r}")

    def at(self, theta: float) -> float:
        return self.mean + sum(s * math.sin(n * theta) + c * math.cos(n * theta) for n, s, c in self.terms)

    def work(self, theta0: float, theta1: float) -> float:
        """∫ T dθ from θ₀ to θ₁, in closed form."""
        total = self.mean * (theta1 - theta0)
        for n, s, c in self.terms:
            total += (s * (math.cos(n * theta0) - math.cos(n * theta1)) + c * (math.sin(n * theta1) - math.sin(n * theta0))) / n
        return total

    def minus(self, other: "TrigTorque") -> "TrigTorque":
        """This torque less another, harmonic by harmonic."""
        merged: dict[int, list[float]] = {}
        for sign, torque in ((1.0, self), (-1.0, other)):
            for n, s, c in torque.terms:
                entry = merged.setdefault(n, [0.0, 0.0])
                entry[0] += sign * s
                entry[1] += sign * c
        terms = tuple((n, s, c) for n, (s, c) in sorted(merged.items()) if s or c)
        return TrigTorque(self.mean - other.mean, terms)

    @property
    def period(self) -> float:
        """The shortest angle after which T repeats: 2π / gcd of the harmonics."""
        if not self.terms:
            return TAU
        return TAU / reduce(math.gcd, (n for n, _, _ in self.terms))


@dataclass(frozen=True)
class Swing:
    """The energy above the resisting torque at each crossing in one cycle from θ = 0."""

    crossings: tuple[tuple[float, float], ...]   # (θ, E(θ)) in order
    delta: float                                  # greatest − least: the fluctuation of energy
    high: tuple[float, float]                     # (θ, E) where the speed is greatest
    low: tuple[float, float]                      # (θ, E) where the speed is least


def crossings(excess: TrigTorque, period: float | None = None) -> list[float]:
    """Angles in [0, period) where the excess torque changes sign (or is exactly zero on the grid)."""
    period = period or excess.period
    if not excess.terms:
        return []
    highest = max(n for n, _, _ in excess.terms)
    count = max(64, math.ceil(GRID_PER_HARMONIC * highest * period / TAU)) + 1
    grid = [period * j / (count - 1) for j in range(count)]
    found = []
    for j in _brackets(excess, grid):  # each decided on exact values, as if every point were evaluated so
        here, after = excess.at(grid[j]), excess.at(grid[j + 1])
        if here == 0.0:
            found.append(grid[j])
        elif here * after < 0.0:
            found.append(_bisect(excess.at, grid[j], grid[j + 1], here))
    return found


def _brackets(excess: TrigTorque, grid: list[float]) -> list[int]:
    """The grid intervals that may hold a crossing: the torque evaluated on the whole grid at once (numpy),
    keeping every interval whose ends differ in sign or lie near zero. Elsewhere both ends are far from
    zero on the same side, so the exact values (math.sin, math.cos) agree in sign with these."""
    import numpy as np

    theta = np.array(grid)
    values = np.full(len(grid), float(excess.mean))
    for n, s, c in excess.terms:
        values += s * np.sin(n * theta) + c * np.cos(n * theta)
    near = np.abs(values) <= 1e-9 * (abs(excess.mean) + sum(abs(s) + abs(c) for _, s, c in excess.terms))
    maybe = (values[:-1] * values[1:] < 0.0) | near[:-1] | near[1:]
    return np.flatnonzero(maybe).tolist()


def _bisect(f, a: float, b: float, fa: float) -> float:
    for _ in range(200):
        mid = 0.5 * (a + b)
        if mid in (a, b):
            break
        fm = f(mid)
        if fm == 0.0:
            return mid
        if (fm < 0.0) == (fa < 0.0):
            a, fa = mid, fm
        else:
            b = mid
    return 0.5 * (a + b)


def energy_swing(engine: TrigTorque, resisting: TrigTorque) -> Swing:
    """The fluctuation of energy over a cycle of engine torque against resisting torque.

    The two must do the same work per cycle (equal mean torques), or the speed would not
    be steady and there would be no cycle to speak of.
    """
    excess = engine.minus(resisting)
    scale = max([abs(engine.mean), abs(resisting.mean)] + [abs(v) for _, s, c in excess.terms for v in (s, c)])
    if abs(excess.mean) > 1e-12 * max(scale, 1.0):
        raise ValueError("engine and resisting torques differ in mean: the speed would not be steady")
    excess = TrigTorque(0.0, excess.terms)
    points = tuple((theta, excess.work(0.0, theta)) for theta in crossings(excess))
    if not points:
        return Swing((), 0.0, (0.0, 0.0), (0.0, 0.0))
    high = max(points, key=lambda p: p[1])
    low = min(points, key=lambda p: p[1])
    return Swing(points, high[1] - low[1], high, low)


def single_harmonic_swing(sin_n: float, cos_n: float, n: int) -> float:
    """Fluctuation of energy of b sin nθ + c cos nθ about its mean: one loop, 2√(b² + c²)/n."""
    return 2.0 * math.hypot(sin_n, cos_n) / n


def single_harmonic_crossings(sin_n: float, cos_n: float, n: int) -> tuple[float, float]:
    """The crossings that bound the loop above the mean line of b sin nθ + c cos nθ.

    With b sin nθ + c cos nθ = R sin(nθ + φ), φ = atan2(c, b), the loop above runs from
    nθ + φ = 0 to π (mod 2π): the first such start at or after θ = 0, and π/n later.
    """
    phi = math.atan2(cos_n, sin_n)
    first = ((-phi) % TAU) / n
    return first, first + math.pi / n
