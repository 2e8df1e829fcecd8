"""Gyroscopic couples (course text chapter 5): plain functions over SI floats, no I/O.

A rotor of moment of inertia I spinning at ω whose axis turns (precesses) at Ω needs an active
couple I·ω·Ω (eq. 5.2); it pushes back on its mounting with the equal and opposite reactive
(gyroscopic) couple. Directions are worked with vectors in the vehicle's own axes, so every
case (left or right turn, either spin, pitching, rolling) follows from one cross product:

    x forward (bow, nose), y to the left (port), z up.

A rotation vector points the way the right-hand rule gives: fingers curled with the rotation,
the thumb along the vector. The active couple is the rate of change of angular momentum,
dH/dt = Ω × H; the reactive couple on the vehicle is H × Ω.
"""
from __future__ import annotations

import math

G = 9.81  # m/s², the course text's value

Vector = tuple[float, float, float]
FORWARD: Vector = (1.0, 0.0, 0.0)
LEFT: Vector = (0.0, 1.0, 0.0)
UP: Vector = (0.0, 0.0, 1.0)


def moment_of_inertia(mass: float, radius_of_gyration: float) -> float:
    """I = m k²."""
    return mass * radius_of_gyration ** 2


def precession_rate(speed: float, radius: float) -> float:
    """Ω = v / R for a vehicle on a curve of radius R (eq. 5.3)."""
    return speed / radius


def couple(inertia: float, spin: float, precession: float) -> float:
    """The gyroscopic couple I ω Ω (eq. 5.2)."""
    return inertia * spin * precession


def pitching_rate(amplitude: float, period: float) -> float:
    """Greatest angular speed of a simple harmonic pitch (or roll) φ = φ₀ sin(2πt/T): φ₀ 2π/T."""
    return amplitude * 2 * math.pi / period


# ---- directions --------------------------------------------------------------------------

def scale(v: Vector, k: float) -> Vector:
    return (v[0] * k, v[1] * k, v[2] * k)


def cross(a: Vector, b: Vector) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def axial_spin(sense: str, viewed_from: str) -> Vector:
    """Unit spin vector of a rotor on the fore-and-aft axis, from how it looks.

    Seen by an observer looking along a vector, a rotation that appears clockwise has its vector
    pointing away from the observer. Looking from the rear (stern, tail, behind) one looks forward.
    """
    looking = {"rear": FORWARD, "front": scale(FORWARD, -1.0)}[viewed_from]
    return looking if sense == "clockwise" else scale(looking, -1.0)


def wheel_spin(same_as_wheels: bool = True) -> Vector:
    """Unit spin vector of a rotor on a transverse axis. A road wheel rolling forward spins about
    the axis pointing to the vehicle's left: its top moves forward."""
    return LEFT if same_as_wheels else scale(LEFT, -1.0)


def turning(turn: str) -> Vector:
    """Unit precession vector of a vehicle turning 'left' (anticlockwise seen from above: up) or 'right'."""
    return UP if turn == "left" else scale(UP, -1.0)


def pitching(bow_rising: bool) -> Vector:
    """Unit precession vector while pitching: about +y the bow dips, so a rising bow is about -y."""
    return scale(LEFT, -1.0 if bow_rising else 1.0)


def rolling(to_right: bool) -> Vector:
    """Unit precession vector while rolling: rolling to the right (starboard down) is about +x."""
    return FORWARD if to_right else scale(FORWARD, -1.0)


def reactive_couple(spin: Vector, precession: Vector, magnitude: float = 1.0) -> Vector:
    """The gyroscopic couple the rotor exerts on the vehicle, H × Ω, for unit spin and precession
    vectors, scaled to `magnitude` (I ω Ω)."""
    return scale(cross(spin, precession), magnitude)


TOLERANCE = 1e-12


def pitch_effect(c: Vector) -> str:
    """'nose up' or 'nose down' for a couple on the vehicle (about +y the nose dips), '' if none."""
    if abs(c[1]) < TOLERANCE:
        return ""
    return "nose down" if c[1] > 0 else "nose up"


def yaw_effect(c: Vector) -> str:
    """'left' or 'right': the way a couple about the vertical axis turns the nose, '' if none."""
    if abs(c[2]) < TOLERANCE:
        return ""
    return "left" if c[2] > 0 else "right"


def roll_effect(c: Vector) -> str:
    """The side a couple about the fore-and-aft axis presses down, 'left' or 'right' ('' if none).
    About +x the left side rises, so the right side goes down."""
    if abs(c[0]) < TOLERANCE:
        return ""
    return "right" if c[0] > 0 else "left"


def outer_side(turn: str) -> str:
    """The side of a vehicle on the outside of its turn."""
    return "left" if turn == "right" else "right"


# ---- supports ----------------------------------------------------------------------------

def weight_shares(weight: float, from_a: float, span: float) -> tuple[float, float]:
    """The weight carried by bearings A and B of a rotor `from_a` from A on a span (eqs. 5.4-5.5)."""
    return weight * (span - from_a) / span, weight * from_a / span


def couple_force(c: float, arm: float) -> float:
    """The pair of equal and opposite forces, `arm` apart, that make a couple: F = C / l."""
    return c / arm


# ---- vehicles on a curve -------------------------------------------------------------------

def centrifugal_force(mass: float, speed: float, radius: float) -> float:
    """F_c = m v² / R."""
    return mass * speed ** 2 / radius


def heel_angle(gyroscopic: float, centrifugal: float, mass: float, height: float, g: float = G) -> float:
    """Angle of heel (from the vertical) of a two-wheeler on a curve, radians, from the couples it makes
    upright: the gyroscopic Σ(I ω)·v/R of wheels and engine and the centrifugal m v²/R · h, both
    overturning outwards (a gyroscopic couple against them is negative).

    Leaning by θ, both couples scale with cos θ and the weight rights the machine with m g h sin θ:
    tan θ = (C_g + C_c) / (m g h)  (Example 5.2).
    """
    return math.atan2(gyroscopic + centrifugal, mass * g * height)


def centrifugal_couple_per_v2(mass: float, height: float, radius: float) -> float:
    """The centrifugal couple m v² h / R on a vehicle on a curve, per v²."""
    return mass * height / radius


def gyroscopic_couple_per_v2(spin_inertia: float, wheel_radius: float, radius: float) -> float:
    """The gyroscopic couple Σ(I G)·(v/r)·(v/R) of rotors turning G times as fast as wheels of radius r,
    per v²; `spin_inertia` is Σ I·G, signed, positive when it overturns outwards like the wheels."""
    return spin_inertia / (wheel_radius * radius)


def rail_limiting_speed(mass: float, gauge: float, couple_per_v2: float, g: float = G) -> float:
    """Speed at which the inner wheels of a four-wheeled rail car (two axles) just leave the rail: the
    overturning couples are `couple_per_v2` · v², and each inner wheel, carrying m g / 4, loses
    (couple)/(2 × gauge)."""
    if couple_per_v2 <= 0:
        raise ValueError("the couples do not overturn the car outwards: no wheel ever leaves the rail")
    return math.sqrt(mass * g * gauge / 2 / couple_per_v2)
