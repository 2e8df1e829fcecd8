"""Belt drives (course text §1.2): plain functions over SI floats, no I/O, no randomness.

Angles in radians, lengths in m, speeds in rad/s or m/s, forces in N, power in W.
Slip is a fraction (0.03 for 3 %); on a drive with slip on each pulley the fractions add
(text eq. 1.6, Example 1.2).
"""
from __future__ import annotations

import math


def speed_ratio(d1: float, d2: float, thickness: float = 0.0, slip: float = 0.0) -> float:
    """N2/N1 for a driver of diameter d1 and a follower of diameter d2 (eqs. 1.4-1.7)."""
    return (d1 + thickness) / (d2 + thickness) * (1.0 - slip)


def driven_diameter(d1: float, speed_ratio_wanted: float, thickness: float = 0.0, slip: float = 0.0) -> float:
    """The follower diameter that gives N2/N1 = speed_ratio_wanted (eq. 1.7 solved for d2)."""
    return (d1 + thickness) * (1.0 - slip) / speed_ratio_wanted - thickness


def alpha_open(r1: float, r2: float, centre_distance: float) -> float:
    """Half the wrap lost (or gained) on an open drive: asin(|r1 - r2| / X) (eq. 1.9)."""
    if abs(r1 - r2) > centre_distance:
        raise ValueError("the belt cannot run between the pulleys: the difference of their radii is more "
                         "than the centre distance")
    return math.asin(abs(r1 - r2) / centre_distance)


def alpha_crossed(r1: float, r2: float, centre_distance: float) -> float:
    """asin((r1 + r2) / X) for a crossed drive (eq. 1.11)."""
    if r1 + r2 > centre_distance:
        raise ValueError("the pulleys overlap: the sum of their radii is more than the centre distance")
    return math.asin((r1 + r2) / centre_distance)


def contact_angle_open(r1: float, r2: float, centre_distance: float) -> float:
    """Angle of contact on the smaller pulley of an open drive, pi - 2 alpha (eq. 1.8)."""
    return math.pi - 2.0 * alpha_open(r1, r2, centre_distance)


def contact_angle_open_large(theta_small: float) -> float:
    """Angle of contact on the larger pulley of an open drive from the smaller's: the two wraps make a
    full turn, 2 pi - theta (= pi + 2 alpha)."""
    return 2.0 * math.pi - theta_small


def contact_angle_crossed(r1: float, r2: float, centre_distance: float) -> float:
    """Angle of contact on either pulley of a crossed drive, pi + 2 alpha (eq. 1.10)."""
    return math.pi + 2.0 * alpha_crossed(r1, r2, centre_distance)


def length_open(r1: float, r2: float, centre_distance: float) -> float:
    """Belt length of an open drive, pi (r1 + r2) + 2X + (r1 - r2)^2 / X (eq. 1.12)."""
    return math.pi * (r1 + r2) + 2.0 * centre_distance + (r1 - r2) ** 2 / centre_distance


def length_crossed(r1: float, r2: float, centre_distance: float) -> float:
    """Belt length of a crossed drive, pi (r1 + r2) + 2X + (r1 + r2)^2 / X (eq. 1.13)."""
    return math.pi * (r1 + r2) + 2.0 * centre_distance + (r1 + r2) ** 2 / centre_distance


def belt_speed(omega: float, radius: float) -> float:
    """Belt speed v = omega r (v = pi d N / 60 with N in rpm)."""
    return omega * radius


def tension_ratio(mu: float, theta: float, groove_half_angle: float | None = None) -> float:
    """T1/T2: e^(mu theta) for a flat belt (1.14), e^(mu theta / sin beta) for a V-belt (1.15)."""
    if groove_half_angle is None:
        return math.exp(mu * theta)
    return math.exp(mu * theta / math.sin(groove_half_angle))


def centrifugal_tension(mass_per_length: float, speed: float) -> float:
    """Tc = m v^2 (eq. 1.21)."""
    return mass_per_length * speed ** 2


def slack_tension(t1: float, ratio: float, tc: float = 0.0) -> float:
    """T2 from (T1 - Tc)/(T2 - Tc) = ratio (eqs. 1.19-1.20; Tc = 0 neglects belt mass)."""
    return (t1 - tc) / ratio + tc


def power(t1: float, t2: float, speed: float) -> float:
    """P = (T1 - T2) v (eq. 1.17)."""
    return (t1 - t2) * speed


def creep_speed_ratio(t1: float, t2: float, area: float, modulus: float) -> float:
    """v2/v1 = 1 - (T1 - T2)/(A E) for an elastic belt (eq. 1.23)."""
    return 1.0 - (t1 - t2) / (area * modulus)


def speed_for_max_power(t_max: float, mass_per_length: float) -> float:
    """The belt speed at which power is greatest: Tc = T_max / 3, so v = sqrt(T_max / 3m)."""
    return math.sqrt(t_max / (3.0 * mass_per_length))


def belts_needed(power_required: float, power_per_belt: float) -> int:
    """Whole belts to carry a duty: the next integer up (a tolerance absorbs float noise)."""
    return math.ceil(power_required / power_per_belt - 1e-9)
