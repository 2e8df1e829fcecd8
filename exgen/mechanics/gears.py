"""Spur gears and gear trains (course text §1.3): plain functions over SI floats, no I/O, no randomness.

Lengths in m, speeds in rad/s (signed: counter-clockwise positive), torques in N·m, inertias in kg·m².
The speed ratio is the text's n = ω_driven/ω_driver (eq. 1.24); a gear pair's ratio carries a sign,
negative for two external gears and positive for an external gear inside an internal (ring) gear
(eq. 1.25). A module is metres per tooth and a diametral pitch teeth per metre, so m = 1/P_d in SI
(m[mm] = 25.4/P_d[teeth per inch] in the usual units).
"""
from __future__ import annotations

import math

#: A gear pair's sign in a train value: external gears turn opposite ways, internal the same way.
EXTERNAL, INTERNAL = -1.0, 1.0


def pitch_diameter(teeth: float, module: float) -> float:
    """d = m t."""
    return module * teeth


def pitch_diameter_dp(teeth: float, diametral_pitch: float) -> float:
    """d = t / P_d."""
    return teeth / diametral_pitch


def circular_pitch(module: float) -> float:
    """p = π d / t = π m."""
    return math.pi * module


def diametral_pitch(module: float) -> float:
    """P_d = 1 / m (SI): teeth per metre of pitch diameter; 25.4 / m[mm] teeth per inch."""
    return 1.0 / module


def centre_distance(d1: float, d2: float, internal: bool = False) -> float:
    """C = (d2 + d1)/2 for external gears, (d2 - d1)/2 for a pinion inside a ring."""
    return (abs(d2 - d1) if internal else d1 + d2) / 2.0


def pair_ratio(t_driver: float, t_driven: float, sign: float = EXTERNAL) -> float:
    """ω_driven/ω_driver of one mesh: ±t_driver/t_driven (eq. 1.25)."""
    return sign * t_driver / t_driven


def train_value(meshes) -> float:
    """The product of the signed ratios of a train's meshes, [(t_driver, t_driven, sign), ...].

    Gears on one shaft turn together, so a compound train is the product over its meshes only.
    """
    value = 1.0
    for t_driver, t_driven, sign in meshes:
        value *= pair_ratio(t_driver, t_driven, sign)
    return value


def sense(omega: float) -> str:
    """'counter-clockwise' for a positive speed, 'clockwise' for a negative one."""
    return "counter-clockwise" if omega > 0 else "clockwise"


def signed(speed: float, sense_word: str) -> float:
    """A speed and its sense as one signed number (counter-clockwise positive)."""
    return -abs(speed) if sense_word == "clockwise" else abs(speed)


def reverted_teeth(m_first: float, t1: float, t2: float, m_second: float, t3: float) -> float:
    """Teeth on the last wheel of a reverted train: the two stages share one centre distance,
    m₁(t₁ + t₂) = m₂(t₃ + t₄)."""
    return m_first * (t1 + t2) / m_second - t3


# ---- epicyclic trains: sun S, planet P, ring R, arm A ----------------------------------------

def ring_teeth(t_sun: float, t_planet: float) -> float:
    """A coaxial simple planetary train with one module: t_R = t_S + 2 t_P."""
    return t_sun + 2.0 * t_planet


def epicyclic_value(t_sun: float, t_ring: float) -> float:
    """e = (ω_R - ω_A)/(ω_S - ω_A) = (-t_S/t_P)(+t_P/t_R) = -t_S/t_R (arm held, sun first)."""
    return -t_sun / t_ring


def arm_held_turns(fixed: str, t_sun: float, t_planet: float, t_ring: float,
                   ring_sign: float = INTERNAL) -> dict[str, float]:
    """Row (b) of the table: the arm held, the fixed member turned -1 so that row (a) + row (b)
    leaves it at rest; the others follow through their meshes (turns relative to the arm).
    `ring_sign` is the planet-ring mesh's sign (a known mistake gives it as external)."""
    if fixed == "sun":
        planet = -1.0 * pair_ratio(t_sun, t_planet, EXTERNAL)
        return {"sun": -1.0, "arm": 0.0, "planet": planet, "ring": planet * pair_ratio(t_planet, t_ring, ring_sign)}
    if fixed == "ring":
        planet = -1.0 * pair_ratio(t_ring, t_planet, ring_sign)
        return {"ring": -1.0, "arm": 0.0, "planet": planet, "sun": planet * pair_ratio(t_planet, t_sun, EXTERNAL)}
    raise ValueError(f"the fixed member must be the sun or the ring, not {fixed!r}")


def epicyclic_speeds(fixed: str, driver: str, omega_driver: float, t_sun: float, t_planet: float,
                     t_ring: float, ring_sign: float = INTERNAL) -> dict[str, float]:
    """Absolute speeds of every member (table method): row (c) = (a) + (b), scaled to the driver."""
    held = arm_held_turns(fixed, t_sun, t_planet, t_ring, ring_sign)
    total = {member: 1.0 + turns for member, turns in held.items()}
    scale = omega_driver / total[driver]
    return {member: scale * turns for member, turns in total.items()}


# ---- geared drives: hoists, lifts, vehicles ---------------------------------------------------

def referred_inertia(inertia: float, ratio: float, efficiency: float = 1.0) -> float:
    """A shaft's inertia seen at the motor: I n²/η, n = ω_shaft/ω_motor (Example 1.12)."""
    return inertia * ratio ** 2 / efficiency


def referred_torque(torque: float, ratio: float, efficiency: float = 1.0) -> float:
    """A load torque on a shaft seen at the motor: τ n/η (the motor also supplies the losses)."""
    return torque * ratio / efficiency


def available_torque(motor_torque: float, ratio: float, efficiency: float = 1.0) -> float:
    """What a motor torque delivers on a shaft of speed ratio n: τ η/n (the inverse of referred_torque)."""
    return motor_torque * efficiency / ratio


def hanging_pull(mass: float, accel: float, g: float) -> float:
    """Rope pull to raise a hanging mass with acceleration a: M (g + a)."""
    return mass * (g + accel)


def incline_pull(mass: float, accel: float, g: float, slope: float, friction: float = 0.0) -> float:
    """Rope pull to haul a mass up a slope of angle `slope` against a friction force: M a + f + M g sin θ."""
    return mass * accel + friction + mass * g * math.sin(slope)
