"""Common slips a wrong method gives are named, not met with "Not within 1 %": each worked here by hand from
the sheet's printed givens, typed as a student would type it, and graded. One per slip, over many seeds of
the template it belongs to; the chapters' oracles work the same values again for every named mistake."""
import math

import pytest

from exgen.answertypes import answer_type
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from sheet_values import asked, printed

G = 9.81
SEEDS = range(40)


def rotor_static_reactions(v):
    """The bearing reactions with the gyroscopic couple left out: the weight's shares alone."""
    g = printed(v, "m", "l", "a")
    weight = g.m * G
    return {"c": weight * (g.l - g.a) / g.l, "d": weight * g.a / g.l}


def pendulum_without_root(v):
    g = printed(v, "l")
    return {"a": G / g.l}


def damping_ratio_without_two(v):
    g = printed(v, "m", "K", "C")
    return {"b": g.C / (g.m * math.sqrt(g.K / g.m))}


def cantilever_as_simply_supported(v):
    g = printed(v, "d", "l", "m", "E")
    return {"c": g.m * G * g.l ** 3 / (48 * g.E * math.pi * g.d ** 4 / 64)}


def porter_half_load_at_iz(v):
    g = printed(v, "l", "e_l", "m", "M", "r", optional=("e_u",))
    low = math.sqrt(g.l ** 2 - (g.r - g.e_l) ** 2)
    iz = (g.r - g.e_u) / math.sqrt(g.l ** 2 - (g.r - g.e_u) ** 2) * low
    return {"a": math.sqrt((g.m * G + g.M * G / 2) * iz / low / (g.m * g.r))}


def pitching_couple_in_rpm(v):
    g = printed(v, "m", "k", "N", "phi", "T")
    return {"d": g.m * g.k ** 2 * (g.N * 60 / (2 * math.pi)) * g.phi * 2 * math.pi / g.T}


def flywheel_k_not_squared(v):
    g = printed(v, "m", "k")
    return {"a": g.m * g.k}


def static_balance_of_masses(v):
    g = printed(v, "m1", "m2", "theta2", "m3", "theta3")
    return {"b": abs(g.m1 + g.m2 * complex(math.cos(g.theta2), math.sin(g.theta2))
                     + g.m3 * complex(math.cos(g.theta3), math.sin(g.theta3)))}


def lift_motor_acceleration_times_n(v):
    """The accelerating torque with the drum's angular acceleration multiplied by n = ω_D/ω_M, not divided."""
    g = printed(v, "eta", "a", "dD", "t1", "t2", "t3", "t4", "I_M", "I_T", "I_D")
    n1 = g.t1 / g.t2
    n = n1 * g.t3 / g.t4
    inertia = g.I_M + g.I_T * n1 ** 2 / g.eta + g.I_D * n ** 2 / g.eta ** 2
    return {"c": inertia * g.a / (g.dD / 2) * n}


def coupler_angle_at_b(v):
    g = printed(v, "L3", "CP", "BP")
    return {"c": math.acos((g.BP ** 2 + g.L3 ** 2 - g.CP ** 2) / (2 * g.BP * g.L3))}


def belt_power_with_larger_wrap(v):
    g = printed(v, "d1", "d2", "X", "N1", "mu", "A", "sigma")
    wrap = math.pi + 2 * math.asin(abs(g.d2 - g.d1) / (2 * g.X))   # the larger pulley's angle of contact
    tight = g.sigma * g.A
    return {"c": tight * (1 - math.exp(-g.mu * wrap)) * g.N1 * g.d1 / 2}


def rail_car_axles_alone(v):
    """The resultant gyroscopic couple at the limiting speed with the motors left out: 2 I_a v²/(r R)."""
    g = printed(v, "I_a", "r", "R")
    speed = v.answers["a"].value / 3.6                              # (b) is worked from (a)'s speed
    return {"b": 2 * g.I_a * speed ** 2 / (g.r * g.R)}


SLIPS = [
    ("gyroscopes.rotor_bearing_reactions", "gyro_ignored", rotor_static_reactions),
    ("vibration.simple_pendulum", "sqrt_missing", pendulum_without_root),
    ("vibration.damped_spring_mass", "factor_two_missing", damping_ratio_without_two),
    ("vibration.cantilever_end_mass", "simply_supported", cantilever_as_simply_supported),
    ("governors.porter_friction", "sleeve_moment_arm", porter_half_load_at_iz),
    ("gyroscopes.ship_turbine", "rpm_as_rad_s", pitching_couple_in_rpm),
    ("vibration.stepped_shaft", "k_not_squared", flywheel_k_not_squared),
    ("balancing.static_balance", "eccentricity_ignored", static_balance_of_masses),
    ("gears.lift_counterweight", "ratio_inverted", lift_motor_acceleration_times_n),
    ("linkages.coupler_point", "wrong_vertex", coupler_angle_at_b),
    ("belts.flat_belt_power", "larger_pulley", belt_power_with_larger_wrap),
    ("gyroscopes.rail_car_limiting_speed", "motors_ignored", rail_car_axles_alone),
]


@pytest.mark.parametrize("template_id, name, worked", SLIPS, ids=[f"{t}-{n}" for t, n, _ in SLIPS])
def test_the_slip_typed_as_a_student_works_it_is_named(bank, template_id, name, worked):
    template = bank.get(template_id)
    named = 0
    for seed in SEEDS:
        variant = make_variant(template, seed)
        for part_id, si in worked(variant).items():
            part, kind = template.part(part_id), answer_type(template.part(part_id))
            if not kind.apart(asked(si, part), variant.answers[part_id].value, part):
                continue  # a draw where the slip makes no difference, so it is not named
            typed = kind.text(asked(si, part), part)
            result = next(r for r in grade_variant(variant, {part_id: typed}).parts if r.part_id == part_id)
            assert (result.status, result.mistake) == ("wrong", name), (seed, part_id, typed, result.message)
            named += 1
    assert named >= len(SEEDS) // 2

