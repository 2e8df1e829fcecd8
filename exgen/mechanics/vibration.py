"""Free vibration of one-degree-of-freedom systems (course text chapter 6): plain functions over SI floats.

Every undamped system here reduces to m' ẍ + K' x = 0 (or I θ̈ + q θ = 0), so ω_n = √(K'/m')
in rad/s and f_n = ω_n / 2π in Hz (eqs. 6.8-6.9, 6.21-6.22, 6.29-6.30). The equivalent method
(§6.5, §6.7) refers every mass, spring and damper on a lever to one reference point at radius
r_ref from the pivot: a mass at r counts m (r/r_ref)², an inertia I counts I / r_ref², a spring
K (r/r_ref)², a damper C (r/r_ref)², and a pendulum of weight m g at l from the pivot adds the
stiffness m g l / r_ref² (positive when it hangs below the pivot).

Damping (§6.6): ζ = C / C_c with C_c = 2 m ω_n; ω_d = ω_n √(1 − ζ²). The logarithmic decrement
over r − 1 cycles, between the first amplitude a₁ and the r-th a_r, is
ln(a₁/a_r) = (r − 1) · 2πζ / √(1 − ζ²)  (eq. 6.46): "after n complete cycles" means r − 1 = n.
"""
from __future__ import annotations

import math

G = 9.81  # m/s²
TWO_PI = 2 * math.pi


def natural_speed(stiffness: float, mass: float) -> float:
    """ω_n = √(K/m) in rad/s (or √(q/I) for a torsional system)."""
    return math.sqrt(stiffness / mass)


def frequency(omega: float) -> float:
    """f = ω / 2π in Hz."""
    return omega / TWO_PI


def period(omega: float) -> float:
    """T = 2π / ω in s."""
    return TWO_PI / omega


def pendulum_speed(length: float, g: float = G) -> float:
    """Simple pendulum: ω_n = √(g/l) (eq. 6.8)."""
    return math.sqrt(g / length)


def pendulum_length(period_s: float, g: float = G) -> float:
    """The simple pendulum that swings with period T: l = g (T/2π)²."""
    return g * (period_s / TWO_PI) ** 2


def compound_pendulum_speed(mass: float, pivot_to_cg: float, inertia_about_pivot: float, g: float = G) -> float:
    """A body swinging about a pivot h from its centre of gravity: ω_n = √(m g h / I_O) (eq. 6.3)."""
    return math.sqrt(mass * g * pivot_to_cg / inertia_about_pivot)


def parallel_axis(inertia_about_cg: float, mass: float, distance: float) -> float:
    """I_O = I_G + m h²."""
    return inertia_about_cg + mass * distance ** 2


def springs_parallel(*stiffnesses: float) -> float:
    """K' = K₁ + K₂ + ...: springs that share one displacement."""
    return sum(stiffnesses)


def springs_series(*stiffnesses: float) -> float:
    """1/K' = 1/K₁ + 1/K₂ + ...: springs that carry one force."""
    return 1.0 / sum(1.0 / k for k in stiffnesses)


# ---- shafts -----------------------------------------------------------------------------

def polar_second_moment(diameter: float) -> float:
    """J = π d⁴ / 32 of a solid round shaft (eq. 6.32)."""
    return math.pi * diameter ** 4 / 32


def torsional_stiffness(modulus_of_rigidity: float, diameter: float, length: float) -> float:
    """q = G J / l = G π d⁴ / (32 l) (eq. 6.33)."""
    return modulus_of_rigidity * polar_second_moment(diameter) / length


def equivalent_length(segments: list[tuple[float, float]], reference_diameter: float) -> float:
    """A stepped shaft as one shaft of the reference diameter: l' = Σ l_i (d'/d_i)⁴.

    Segments are (length, diameter); the torsional stiffness is unchanged (Example 6.3)."""
    return sum(length * (reference_diameter / d) ** 4 for length, d in segments)


def length_for_speed(modulus_of_rigidity: float, diameter: float, inertia: float, omega: float) -> float:
    """The length of shaft of diameter d that gives ω_n with a disc of inertia I: l = G J / (I ω²)."""
    return modulus_of_rigidity * polar_second_moment(diameter) / (inertia * omega ** 2)


def diameter_for_length(segment_length: float, equivalent: float, reference_diameter: float) -> float:
    """The diameter a segment of `segment_length` needs to count as `equivalent` metres of the
    reference shaft: l (d'/d)⁴ = l_eq, so d = d' (l / l_eq)^¼."""
    if equivalent <= 0:
        raise ValueError("the other segments already exceed the equivalent length")
    return reference_diameter * (segment_length / equivalent) ** 0.25


# ---- bars and beams -------------------------------------------------------------------------

def area(diameter: float) -> float:
    return math.pi * diameter ** 2 / 4


def second_moment(diameter: float) -> float:
    """I = π d⁴ / 64 of a round section about a diameter (bending)."""
    return math.pi * diameter ** 4 / 64


def axial_stiffness(modulus: float, diameter: float, length: float) -> float:
    """s = E A / l of a round bar pulled along its axis (longitudinal vibration)."""
    return modulus * area(diameter) / length


def cantilever_stiffness(modulus: float, diameter: float, length: float) -> float:
    """s = 3 E I / l³ at the free end of a round cantilever (transverse vibration)."""
    return 3 * modulus * second_moment(diameter) / length ** 3


# ---- the equivalent method ----------------------------------------------------------------

def referred(value: float, radius: float, reference: float) -> float:
    """A mass, spring or damper at `radius` from the pivot, referred to the reference radius:
    value (r / r_ref)² (the same kinetic or potential energy, or the same power lost)."""
    return value * (radius / reference) ** 2


def inertia_referred(inertia: float, reference: float) -> float:
    """An inertia about the pivot as a mass at the reference radius: I / r_ref²."""
    return inertia / reference ** 2


def pendulum_stiffness(mass: float, arm: float, reference: float, g: float = G) -> float:
    """A weight m g hanging `arm` below the pivot acts as a spring m g l / r_ref² at the reference."""
    return mass * g * arm / reference ** 2


def rod_inertia_about_end(mass: float, length: float) -> float:
    """A uniform rod about one end: m l² / 3."""
    return mass * length ** 2 / 3


# ---- damping -------------------------------------------------------------------------------

def critical_damping(mass: float, omega_n: float) -> float:
    """C_c = 2 m ω_n (for a torsional system 2 I ω_n)."""
    return 2 * mass * omega_n


def damping_ratio(damping: float, critical: float) -> float:
    """ζ = C / C_c."""
    return damping / critical


def damped_speed(omega_n: float, zeta: float) -> float:
    """ω_d = ω_n √(1 − ζ²) (eq. 6.44); only an under-damped system (ζ < 1) oscillates."""
    if not 0 <= zeta < 1:
        raise ValueError(f"damping ratio {zeta:g} is not under-damped: the system does not oscillate")
    return omega_n * math.sqrt(1 - zeta ** 2)


def damping_case(zeta: float) -> str:
    """The text's three cases (§6.6.3): light (ζ < 1, it oscillates), critical (ζ = 1), heavy (ζ > 1)."""
    if zeta < 0:
        raise ValueError(f"a damping ratio of {zeta:g} is no damper")
    return "light" if zeta < 1 else ("critical" if zeta == 1 else "heavy")


def torsional_damping(damping: float, arm: float) -> float:
    """A dashpot of coefficient C acting tangentially at radius a resists a rotation θ̇ with a force
    C a θ̇ at arm a: a torque C a² θ̇, so the torsional coefficient is C a² (eq. 6.47's C(a/b)² times b²)."""
    return damping * arm ** 2


def decrement(first: float, last: float, cycles: float) -> float:
    """The logarithmic decrement per cycle, δ = ln(a₁/a_r) / (r − 1), with r − 1 = `cycles`."""
    return math.log(first / last) / cycles


def ratio_from_decrement(delta: float) -> float:
    """ζ from δ = 2πζ / √(1 − ζ²): ζ = δ / √(4π² + δ²) (eq. 6.46 solved)."""
    return delta / math.sqrt(TWO_PI ** 2 + delta ** 2)
