"""Flywheels (course text chapter 3): plain functions over SI floats, no I/O, no randomness.

A flywheel stores the energy a machine receives faster than it spends and gives it back
when it spends faster. Between the greatest and least speed of a cycle, ω₁ and ω₂, it
gives up the maximum fluctuation of energy

    ΔE = ½ I (ω₁² − ω₂²) = I ω² C_s          (eqs 3.1-3.5)

with ω = (ω₁ + ω₂)/2 the mean speed and C_s = (ω₁ − ω₂)/ω the coefficient of fluctuation
of speed: the *total* band, so "within ±0.5 % of the mean speed" is C_s = 0.01.

The fluctuation of energy comes from a turning-moment diagram: as loops of measured area
(Example 3.1), as a trapezoidal pulse of torque against time (Example 3.2), or as
an equation in the crank angle (Problems 3.2, 3.5, `turning_moment.py`'s closed-form integral).
"""
from __future__ import annotations

import math
from typing import Sequence

#: Standard gravity, m/s², as the text takes it.
G = 9.81

#: Below this fraction of the largest loop, a cumulative energy is taken as exactly zero.
ZERO = 1e-12


def energy_per_area(torque_scale: float, angle_scale: float) -> float:
    """Energy one unit of diagram area stands for: (torque per unit height) × (radians per unit length)."""
    return torque_scale * angle_scale


def crossing_energies(signed_areas: Sequence[float]) -> list[float]:
    """The energy at each crossing of the torque curve and the mean line, the first taken as zero:
    E_A = 0, E_B = a₁, E_C = a₁ + a₂, ... (areas above the line positive, below negative).

    Over a cycle the loops above and below balance, so the last crossing returns to zero.
    """
    levels = [0.0]
    for area in signed_areas:
        levels.append(levels[-1] + area)
    scale = max((abs(a) for a in signed_areas), default=0.0)
    if abs(levels[-1]) > ZERO * max(scale, 1.0) * len(signed_areas):
        raise ValueError(f"the loops do not close the cycle: they sum to {levels[-1]:g}, not zero")
    levels[-1] = 0.0
    return levels


def alternate(areas: Sequence[float], first_above: bool) -> list[float]:
    """Loop areas (all positive) as signed areas, alternately above (+) and below (−) the line."""
    sign = 1.0 if first_above else -1.0
    return [area * sign * (-1.0) ** i for i, area in enumerate(areas)]


def fluctuation_from_areas(signed_areas: Sequence[float]) -> tuple[float, int, int]:
    """(greatest − least crossing energy, index of the greatest, index of the least).

    The greatest energy is where the speed is greatest, the least where it is least; the
    first of equal crossings is named (the last crossing repeats the first and is never named).
    """
    levels = crossing_energies(signed_areas)[:-1]
    high = max(range(len(levels)), key=lambda i: (levels[i], -i))
    low = min(range(len(levels)), key=lambda i: (levels[i], i))
    return levels[high] - levels[low], high, low


def coefficient_of_fluctuation(delta_e: float, inertia: float, mean_omega: float) -> float:
    """C_s = ΔE / (I ω²) (eq 3.5 solved for C_s)."""
    return delta_e / (inertia * mean_omega ** 2)


def inertia_for(delta_e: float, mean_omega: float, cs: float) -> float:
    """The moment of inertia that holds the speed to the band C_s: I = ΔE / (ω² C_s)."""
    return delta_e / (mean_omega ** 2 * cs)


def rim_mass(inertia: float, mean_radius: float) -> float:
    """Mass of a rim whose inertia is I, all of it at the mean radius (arms neglected): m = I / R²."""
    return inertia / mean_radius ** 2


def rim_area(mass: float, density: float, mean_radius: float) -> float:
    """Cross-section of a rim of this mass: m = ρ · 2πR · A."""
    return mass / (density * 2.0 * math.pi * mean_radius)


def rim_thickness(area: float, width_per_thickness: float) -> float:
    """Thickness t of a rectangular section of this area whose width is b = k t: A = k t²."""
    return math.sqrt(area / width_per_thickness)


# ---- a torque that rises above a steady base in one trapezoidal pulse (Example 3.2) -------------------


def trapezium_width(start: float, top_start: float, top_end: float, end: float) -> float:
    """The mean width of a trapezium that rises from `start` to `top_start`, stays level to `top_end` and
    falls to `end`: ½[(end − start) + (top_end − top_start)], so that its area is this times its height."""
    return 0.5 * ((end - start) + (top_end - top_start))


def trapezium_crossings(start: float, top_start: float, top_end: float, end: float, base: float, peak: float,
                        level: float) -> tuple[float, float]:
    """Where a trapezoidal pulse from `base` up to `peak` crosses the height `level` on its way up and on its
    way down (the straight sides carried on for a level outside the pulse)."""
    rise = (level - base) / (peak - base)
    return start + (top_start - start) * rise, end - (end - top_end) * rise


# ---- presses and starting ------------------------------------------------------------------


def cycle_time(energy_per_cycle: float, power: float) -> float:
    """The shortest cycle a motor of constant power can feed: t = E / P (Example 3.3)."""
    return energy_per_cycle / power


def flywheel_share(energy: float, power: float, duration: float) -> float:
    """Energy the flywheel gives up during an operation the motor feeds at once: E − P t."""
    return energy - power * duration


def speed_after(omega1: float, energy_given: float, inertia: float) -> float:
    """ω₂ after the flywheel gives up ΔE: ½ I (ω₁² − ω₂²) = ΔE (eq 3.1)."""
    remaining = omega1 ** 2 - 2.0 * energy_given / inertia
    if remaining <= 0:
        raise ValueError("the flywheel would stop: it does not hold that much energy")
    return math.sqrt(remaining)


def kinetic_energy(inertia: float, omega_: float) -> float:
    """½ I ω²."""
    return 0.5 * inertia * omega_ ** 2


def weight(mass: float) -> float:
    """The weight m g of a flywheel, in N (Problem 3.4 asks the weight, not the mass)."""
    return mass * G


def work_per_cycle(power: float, mean_omega: float, cycle_angle: float = 2.0 * math.pi) -> float:
    """Work a steady engine does in one cycle of `cycle_angle` radians of the crank: P θ / ω."""
    return power * cycle_angle / mean_omega
