"""Every chapter 1 answer and named mistake, recomputed over drawn variants by an oracle of its own from what
the sheet prints.

The oracle reads each given as printed (and fails if one it needs is not on the sheet), works the course
text's method with no code from exgen's mechanics or solvers, and compares each part's answer, and each
mistake's value wherever the key records it, to 1e-9. Where it can it works another way than the solvers:
belt speeds as π d N/60 from the diameter in rpm, the tension ratio from the slack side, an epicyclic train
by its train value (ω_m − ω_A) = e_m (ω_fixed − ω_A) instead of the table, referred inertias and torques by
the energy and power a shaft takes through each contact.
"""
from __future__ import annotations

import math

import pytest

from sheet_values import G, check_answers, check_mistakes, printed

PI = math.pi
RPM = 2 * PI / 60


def _per_rpm(omega: float) -> float:
    """A speed in rad/s, as the number of rpm it is: a student using rpm where rad/s belong gets this."""
    return omega / RPM


# ---- belts (§1.2) ------------------------------------------------------------------------------------


def open_angles(d1: float, d2: float, x: float) -> tuple[float, float]:
    """Wrap on the smaller and larger pulley of an open drive, from the diameters: sin α = (d₂ − d₁)/2X."""
    alpha = math.asin(abs(d2 - d1) / (2 * x))
    return PI - 2 * alpha, PI + 2 * alpha


def crossed_angle(d1: float, d2: float, x: float) -> float:
    return PI + 2 * math.asin((d1 + d2) / (2 * x))


def belt_power(v):
    vee = "groove" in {p.name for p in v.params}
    g = printed(v, "d1", "d2", "X", "N1", "mu", "A", "rho", "E", "sigma", *(("groove",) if vee else ()))
    theta, large = open_angles(g.d1, g.d2, g.X)
    speed = PI * g.d1 * _per_rpm(g.N1) / 60                    # v = π d N / 60
    wedge = math.sin(g.groove / 2) if vee else 1.0

    def slack(ratio_exponent: float, tight: float, tc: float = 0.0) -> float:
        return tc + (tight - tc) * math.exp(-ratio_exponent)   # (T₂ − Tc) = (T₁ − Tc) e^(−μθ/sin β)

    t1, mass = g.sigma * g.A, g.rho * g.A
    t2_light = slack(g.mu * theta / wedge, t1)
    tc = mass * speed ** 2
    t2 = slack(g.mu * theta / wedge, t1, tc)
    p_light, p_heavy = (t1 - t2_light) * speed, (t1 - t2) * speed
    strain = (t1 - t2) / (g.A * g.E)                           # the driven side runs slower by the strain difference
    p_elastic = p_heavy * (1 - strain)
    torque = t1 - t2
    answers = {"a": theta, "b": speed, "c": p_light, "d": p_heavy, "e": p_elastic,
               "f": torque * g.d1 / 2, "g": torque * g.d2 / 2}
    degrees = min(g.mu * math.degrees(theta) / wedge, 700)
    light = {"theta_in_degrees": (t1 - slack(degrees, t1)) * speed,
             "larger_pulley": (t1 - slack(g.mu * large / wedge, t1)) * speed}   # the larger pulley's wrap
    if vee:
        light["flat_formula_on_v_belt"] = (t1 - slack(g.mu * theta, t1)) * speed
        light["full_groove_angle"] = (t1 - slack(g.mu * theta / math.sin(g.groove), t1)) * speed
    mistakes = {
        "a": {"crossed_formula": crossed_angle(g.d1, g.d2, g.X), "larger_pulley": large,
              "diameters_for_radii": PI - 2 * math.asin(abs(g.d2 - g.d1) / g.X)},
        "b": {"rpm_as_rad_s": _per_rpm(g.N1) * g.d1 / 2, "diameter_for_radius": g.N1 * g.d1},
        "c": light,
        "d": {"centrifugal_ignored": p_light, "tc_not_subtracted": (t1 + tc) * (1 - math.exp(-g.mu * theta / wedge)) * speed},
        "e": {"creep_ignored": p_heavy, "creep_added": p_heavy * (1 + strain)},
        "f": {"radii_swapped": answers["g"], "diameter_for_radius": torque * g.d1,
              "centrifugal_ignored": (t1 - t2_light) * g.d1 / 2},
        "g": {"radii_swapped": answers["f"], "diameter_for_radius": torque * g.d2,
              "centrifugal_ignored": (t1 - t2_light) * g.d2 / 2},
    }
    return answers, mistakes


def max_power(v):
    g = printed(v, "d1", "d2", "X", "mu", "A", "rho", "sigma")
    theta, _ = open_angles(g.d1, g.d2, g.X)
    t_max, mass = g.sigma * g.A, g.rho * g.A
    speed = math.sqrt(t_max / (3 * mass))                      # dP/dv = 0 at Tc = T_max / 3
    grip = 1 - math.exp(-g.mu * theta)
    p_max = (t_max - mass * speed ** 2) * grip * speed
    answers = {"a": speed, "b": p_max, "c": 2 * speed / g.d1}
    mistakes = {"a": {"tc_equals_tmax": math.sqrt(t_max / mass), "tc_half": math.sqrt(t_max / (2 * mass))},
                "b": {"centrifugal_ignored": t_max * grip * speed, "theta_in_degrees": (t_max - mass * speed ** 2) * speed},
                "c": {"diameter_for_radius": speed / g.d1}}
    return answers, mistakes


def v_belt_count(v):
    g = printed(v, "P", "N2", "N1", "d2_max", "X", "A", "rho", "sigma", "groove", "mu", "idler")
    d1 = g.d2_max * g.N2 / g.N1                                 # the motor pulley for the compressor's speed
    theta, _ = open_angles(d1, g.d2_max, g.X)
    speed = g.N1 * d1 / 2
    t1, tc = g.sigma * g.A, g.rho * g.A * speed ** 2
    wedge = math.sin(g.groove / 2)

    def per_belt(wrap: float, sine: float = wedge, tension: float = t1 - tc) -> float:
        return tension * (1 - math.exp(-g.mu * wrap / sine)) * speed

    def count(power: float) -> int:
        return math.ceil(g.P / power - 1e-9)

    each, wrapped = per_belt(theta), per_belt(theta * (1 + g.idler))
    change = wrapped / each - 1
    trend = "increase" if change > 0 else "decrease"
    slack = tc + (t1 - tc) * math.exp(-g.mu * theta / wedge)     # (T1 - Tc)/(T2 - Tc) = e^(mu theta / sin beta)
    answers = {"a": count(each), "b": trend, "c": change, "d": slack}
    flat = (1 - math.exp(-g.mu * theta * (1 + g.idler))) / (1 - math.exp(-g.mu * theta)) - 1
    mistakes = {"a": {"rounded_down": math.floor(g.P / each), "centrifugal_ignored": count(per_belt(theta, tension=t1)),
                      "flat_formula_on_v_belt": count(per_belt(theta, sine=1.0))},
                "b": {"opposite": "decrease" if trend == "increase" else "increase"},
                "c": {"ratio_inverted": each / wrapped - 1, "flat_formula_on_v_belt": flat},
                "d": {"centrifugal_ignored": t1 * math.exp(-g.mu * theta / wedge),
                      "flat_formula_on_v_belt": tc + (t1 - tc) * math.exp(-g.mu * theta)}}
    return answers, mistakes


def driven_pulley_diameter(v):
    g = printed(v, "N1", "N2", "d1", "t", "G")
    n = g.N2 / g.N1

    def diameter(thickness: float, slip: float) -> float:
        """N₂/N₁ = (d₁ + t)(1 − s)/(d₂ + t) solved for d₂."""
        return (g.d1 + thickness) * (1 - slip) / n - thickness

    cases = {"a": (0.0, 0.0), "b": (g.t, 0.0), "c": (0.0, g.G), "d": (g.t, g.G)}
    answers = {part: diameter(*case) for part, case in cases.items()}
    mistakes = {}
    for part, (thickness, slip) in cases.items():
        wrong = {"ratio_inverted": (g.d1 + thickness) * n * (1 - slip) - thickness}
        if thickness:
            wrong["thickness_forgotten"] = diameter(0.0, slip)
            wrong["thickness_not_subtracted"] = diameter(thickness, slip) + thickness
        if slip:
            wrong["slip_not_applied"] = diameter(thickness, 0.0)
            wrong["slip_wrong_way"] = (g.d1 + thickness) / ((1 - slip) * n) - thickness
        mistakes[part] = wrong
    return answers, mistakes


def driven_speed_slip(v):
    g = printed(v, "N1", "d1", "d2", "G1", "G2", "t")

    def speed(thickness: float = 0.0, slip: float = 0.0) -> float:
        return g.N1 * (g.d1 + thickness) / (g.d2 + thickness) * (1 - slip)

    total = g.G1 + g.G2
    answers = {"a": speed(), "b": speed(slip=total), "c": speed(g.t, total)}
    upside_down = g.N1 * g.d2 / g.d1
    mistakes = {"a": {"ratio_inverted": upside_down},
                "b": {"ratio_inverted": upside_down * (1 - total), "slip_not_applied": speed(),
                      "slip_one_pulley": speed(slip=g.G1), "slip_wrong_way": speed() * (1 + total)},
                "c": {"thickness_forgotten": speed(slip=total), "slip_not_applied": speed(g.t),
                      "slip_one_pulley": speed(g.t, g.G1)}}
    return answers, mistakes


def compound_drive(v):
    g = printed(v, "N1", "d1", "d2", "d3", "d4", "G", "t")

    def stage(a: float, b: float, thickness: float = g.t, slip: float = g.G) -> float:
        return (a + thickness) / (b + thickness) * (1 - slip)

    main = g.N1 * stage(g.d1, g.d2)
    answers = {"a": main, "b": main * stage(g.d3, g.d4)}
    mistakes = {"a": {"slip_not_applied": g.N1 * stage(g.d1, g.d2, slip=0.0),
                      "thickness_forgotten": g.N1 * stage(g.d1, g.d2, thickness=0.0),
                      "ratio_inverted": g.N1 * stage(g.d2, g.d1)},
                "b": {"slip_not_applied": g.N1 * stage(g.d1, g.d2, slip=0.0) * stage(g.d3, g.d4, slip=0.0),
                      "slip_once": main * stage(g.d3, g.d4, slip=0.0),
                      "thickness_forgotten": g.N1 * stage(g.d1, g.d2, thickness=0.0) * stage(g.d3, g.d4, thickness=0.0),
                      "ratio_inverted": main * stage(g.d4, g.d3)}}
    return answers, mistakes


def drive_geometry(v):
    g = printed(v, "d1", "d2", "X")
    small, large = open_angles(g.d1, g.d2, g.X)
    crossed = crossed_angle(g.d1, g.d2, g.X)

    def length(a: float, b: float, crossed_belt: bool) -> float:
        """Belt length from diameters: π(d₁ + d₂)/2 + 2X + (d₂ ∓ d₁)²/4X."""
        return PI * (a + b) / 2 + 2 * g.X + ((b + a) if crossed_belt else (b - a)) ** 2 / (4 * g.X)

    answers = {"a": small, "b": large, "c": crossed, "d": length(g.d1, g.d2, False), "e": length(g.d1, g.d2, True)}
    mistakes = {"a": {"crossed_formula": crossed, "larger_pulley": large,
                      "diameters_for_radii": PI - 2 * math.asin(abs(g.d2 - g.d1) / g.X)},
                "b": {"smaller_pulley": small, "crossed_formula": crossed},
                "c": {"open_formula": small},
                "d": {"crossed_length": answers["e"], "diameters_for_radii": length(2 * g.d1, 2 * g.d2, False)},
                "e": {"open_length": answers["d"], "diameters_for_radii": length(2 * g.d1, 2 * g.d2, True)}}
    if g.d1 + g.d2 <= g.X:
        mistakes["c"]["diameters_for_radii"] = PI + 2 * math.asin((g.d1 + g.d2) / g.X)
    return answers, mistakes


# ---- gear geometry and trains (§1.3.1-1.3.3) ---------------------------------------------------------

OTHER = {"clockwise": "counter-clockwise", "counter-clockwise": "clockwise"}


def sense_after(sense: str, meshes: int) -> str:
    """Each external mesh reverses the sense."""
    return sense if meshes % 2 == 0 else OTHER[sense]


def pitch_geometry(v):
    g = printed(v, "m", "t1", "t2", "N1")
    d1, d2 = g.m * g.t1, g.m * g.t2
    module_mm = g.m / 1e-3
    answers = {"a": PI * g.m, "b": d1, "c": d2, "d": (d1 + d2) / 2, "e": g.N1 * g.t1 / g.t2,
               "f": PI * d1 * _per_rpm(g.N1) / 60, "g": 1 / g.m}
    mistakes = {"a": {"pitch_over_pi": g.m / PI},
                "b": {"module_as_diametral_pitch": g.t1 / module_mm * 0.0254 / 25.4},   # t/P_d, read as inches
                "c": {"module_as_diametral_pitch": g.t2 / module_mm * 0.0254 / 25.4},
                "d": {"diameters_not_halved": d1 + d2, "internal_formula": (d2 - d1) / 2},
                "e": {"ratio_inverted": g.N1 * g.t2 / g.t1},
                "f": {"diameter_for_radius": g.N1 * d1, "rpm_as_rad_s": _per_rpm(g.N1) * d1 / 2,
                      "other_gear_speed": answers["e"] * d1 / 2},
                "g": {"inch_factor_missing": 1 / module_mm / 0.0254}}
    return answers, mistakes


def teeth_for_centre_distance(v):
    g = printed(v, "C", "m", "k", "N1")
    total = round(2 * g.C / g.m)
    t1 = round(total / (1 + g.k))
    t2 = round(g.k * t1)
    answers = {"a": t1, "b": t2, "c": g.N1 * g.m * t1 / 2}
    mistakes = {"a": {"ratio_inverted": t2, "diameters_not_halved": round(total / 2 / (1 + g.k))},
                "b": {"ratio_inverted": t1, "diameters_not_halved": round(g.k * total / 2 / (1 + g.k))},
                "c": {"diameter_for_radius": g.N1 * g.m * t1, "rpm_as_rad_s": _per_rpm(g.N1) * g.m * t1 / 2}}
    return answers, mistakes


def simple_train(v):
    two = v.param("idlers").text == "2"
    g = printed(v, "m", "t1", "ta", "t2", "N1", "sense1", *(("tb",) if two else ()))   # one idler or two, as the text says
    idler_teeth = [g.ta] + ([g.tb] if two else [])
    meshes = len(idler_teeth) + 1
    span = g.m * (g.t1 / 2 + sum(idler_teeth) + g.t2 / 2)       # the driver's and driven radii, each idler whole
    answers = {"a": g.N1 * g.t1 / g.t2, "b": sense_after(g.sense1, meshes), "c": span}
    mistakes = {"a": {"ratio_inverted": g.N1 * g.t2 / g.t1, "first_mesh_only": g.N1 * g.t1 / g.ta},
                "b": {"mesh_count": sense_after(g.sense1, meshes + 1)},
                "c": {"diameters_not_halved": 2 * span, "idlers_left_out": g.m * (g.t1 + g.t2) / 2}}
    return answers, mistakes


def compound_train(v):
    g = printed(v, "N2", "sense2", "t2", "P23", "d3", "t4", "P45", "d5", "d6", "t7", "P67")
    d2, d4, d7 = g.t2 / g.P23, g.t4 / g.P45, g.t7 / g.P67
    value = (d2 / g.d3) * (d4 / g.d5) * (g.d6 / d7)
    inch2 = 0.0254 ** 2
    as_module = [g.t2 * g.P23 * inch2, g.t4 * g.P45 * inch2, g.t7 * g.P67 * inch2]   # t × P_d taken for t m
    answers = {"a": value * g.N2, "b": sense_after(g.sense2, 3), "c": (d2 + g.d3 + d4 + g.d5 + g.d6 + d7) / 2}
    mistakes = {"a": {"ratio_inverted": g.N2 / value,
                      "pd_as_module": g.N2 * (as_module[0] / g.d3) * (as_module[1] / g.d5) * (g.d6 / as_module[2])},
                "b": {"mesh_count": g.sense2},
                "c": {"diameters_not_halved": 2 * answers["c"], "pd_as_module": (sum(as_module) + g.d3 + g.d5 + g.d6) / 2}}
    return answers, mistakes


def reverted_train(v):
    g = printed(v, "m1", "m2", "t1", "t2", "t3", "NA")
    centre = g.m1 * (g.t1 + g.t2) / 2                           # both stages span the same distance
    t4 = round(2 * centre / g.m2 - g.t3)
    answers = {"a": t4, "b": centre, "c": g.NA * g.t1 * g.t3 / (g.t2 * t4), "d": "same direction"}
    mistakes = {"a": {"same_module": round(g.t1 + g.t2 - g.t3), "modules_swapped": round(g.m2 * (g.t1 + g.t2) / g.m1 - g.t3)},
                "b": {"diameters_not_halved": 2 * centre, "modules_swapped": g.m2 * (g.t1 + g.t2) / 2},
                "c": {"ratio_inverted": g.NA * g.t2 * t4 / (g.t1 * g.t3), "first_stage_only": g.NA * g.t1 / g.t2},
                "d": {"mesh_count": "opposite direction"}}
    return answers, mistakes


def gear_pair_power(v):
    g = printed(v, "m", "t1", "t2", "tau1", "N1", "eta")
    n = g.t1 / g.t2
    power_in = g.tau1 * g.N1
    out_speed = g.N1 * n
    ideal = power_in / out_speed                                # power through unchanged: τ₂ ω₂ = τ₁ ω₁
    answers = {"a": n, "b": g.m * g.t2, "c": ideal, "d": out_speed, "e": power_in, "f": g.eta * power_in,
               "g": g.eta * power_in / out_speed}
    mistakes = {"a": {"ratio_inverted": 1 / n},
                "b": {"module_as_diametral_pitch": g.t2 / (g.m / 1e-3) * 1e-3, "wrong_gear": g.m * g.t1},
                "c": {"ratio_inverted": g.tau1 * n},
                "d": {"ratio_inverted": g.N1 / n},
                "e": {"rpm_as_rad_s": g.tau1 * _per_rpm(g.N1)},
                "f": {"efficiency_wrong_way": power_in / g.eta, "efficiency_ignored": power_in},
                "g": {"efficiency_ignored": ideal, "efficiency_wrong_way": ideal / g.eta, "ratio_inverted": g.eta * g.tau1 * n}}
    return answers, mistakes


def epicyclic(v):
    g = printed(v, "ts", "tp", "planets", "fixed", "driver", "N_in", "sense_in")
    ring = g.ts + 2 * g.tp
    free = "ring" if g.fixed == "sun" else "sun"
    driver = "arm" if g.driver == "arm" else free
    output = free if driver == "arm" else "arm"
    w_in = g.N_in * (-1 if g.sense_in == "clockwise" else 1)

    def speeds(ring_mesh: float) -> dict:
        """ω_m − ω_A = e_m (ω_fixed − ω_A), e_m the train value from the fixed member to m with the arm held:
        sun-planet external (−), planet-ring internal (+, or `ring_mesh`)."""
        to_planet = -g.ts / g.tp if g.fixed == "sun" else ring_mesh * ring / g.tp
        to_free = to_planet * (ring_mesh * g.tp / ring if free == "ring" else -g.tp / g.ts)
        e = {"arm": 0.0, g.fixed: 1.0, "planet": to_planet, free: to_free}
        arm = w_in if driver == "arm" else w_in / (1 - e[driver])
        return {member: arm * (1 - value) for member, value in e.items()}, e

    right, e = speeds(1.0)
    wrong, _ = speeds(-1.0)
    answers = {"a": ring, "b": -g.ts / ring, "c": right[output], "d": right["planet"]}
    relative = right[output] - right["arm"] if driver == "arm" else w_in / -e[driver]   # ω_A left out
    mistakes = {"a": {"planet_counted_once": g.ts + g.tp},
                "b": {"ratio_inverted": -ring / g.ts, "sign_ignored": g.ts / ring},
                "c": {"arm_not_subtracted": relative, "internal_mesh_sign": wrong[output]},
                "d": {"planet_relative": right["planet"] - right["arm"], "internal_mesh_sign": wrong["planet"]}}
    return answers, mistakes


# ---- geared drives (§1.3.4): everything referred to the motor -----------------------------------------


def referred(inertia: float, n: float, eta: float = 1.0) -> float:
    """Kinetic energy ½ I (nω)² through contacts of efficiency η: I n²/η at the motor."""
    return inertia * n * n / eta


def hoist_torque(v):
    g = printed(v, "M", "a", "dD", "t1", "t2", "eta", "mM", "kM", "mD", "kD", "slope", "f", "tau_fM", "tau_fD")
    n = g.t1 / g.t2
    i_m, i_d = g.mM * g.kM ** 2, g.mD * g.kD ** 2
    i_eq = i_m + referred(i_d, n, g.eta)
    r = g.dD / 2
    alpha = g.a / r / n
    tau_acc = i_eq * alpha
    lift = g.M * (G + g.a) * r
    haul = (g.M * g.a + g.f + g.M * G * math.sin(g.slope)) * r
    answers = {"a": i_eq, "b": alpha, "c": tau_acc + lift * n / g.eta,
               "d": tau_acc + (haul + g.tau_fD) * n / g.eta + g.tau_fM}
    mistakes = {"a": {"ratio_not_squared": i_m + i_d * n / g.eta, "efficiency_multiplied": i_m + i_d * n * n * g.eta,
                      "inertia_not_referred": i_m + i_d},
                "b": {"diameter_for_radius": g.a / g.dD / n, "ratio_inverted": g.a / r * n},
                "c": {"efficiency_multiplied": tau_acc + lift * n * g.eta,
                      "weight_forgotten": tau_acc + g.M * g.a * r * n / g.eta,
                      "inertia_forgotten": lift * n / g.eta, "diameter_for_radius": tau_acc + 2 * lift * n / g.eta},
                "d": {"drum_friction_not_referred": tau_acc + haul * n / g.eta + g.tau_fM + g.tau_fD,
                      "efficiency_multiplied": tau_acc + (haul + g.tau_fD) * n * g.eta + g.tau_fM,
                      "friction_torques_forgotten": tau_acc + haul * n / g.eta,
                      "cos_for_sin": tau_acc + ((g.M * g.a + g.f + g.M * G * math.cos(g.slope)) * r + g.tau_fD) * n / g.eta
                      + g.tau_fM}}
    return answers, mistakes


def lift_counterweight(v):
    g = printed(v, "tau_M", "eta", "ml", "a", "R", "dD", "t1", "t2", "t3", "t4", "I_M", "I_T", "I_D")
    n1 = g.t1 / g.t2
    n = n1 * g.t3 / g.t4
    i_eq = g.I_M + referred(g.I_T, n1, g.eta) + referred(g.I_D, n, g.eta ** 2)
    r = g.dD / 2
    alpha = g.a / r / n
    accelerating = i_eq * alpha

    def counterweight(drum_torque: float, down: float = -1.0, resist: float = g.R) -> float:
        """The counterweight, accelerating downwards: T_L − T_C = (drum torque)/r with T_L = m_l(g + a) + R
        and T_C = M₂(g − a)."""
        return (g.ml * (G + g.a) + resist - drum_torque / r) / (G + down * g.a)

    spare = g.tau_M - accelerating
    drum = spare * g.eta ** 2 / n                               # power through two contacts
    answers = {"a": n, "b": i_eq, "c": accelerating, "d": counterweight(drum)}
    mistakes = {"a": {"ratio_inverted": 1 / n},
                "c": {"ratio_inverted": i_eq * g.a / r * n,           # the drum's α multiplied by n
                      "diameter_for_radius": i_eq * g.a / g.dD / n},    # α = a/d
                "b": {"one_contact_efficiency": g.I_M + (g.I_T * n1 ** 2 + g.I_D * n ** 2) / g.eta,
                      "ratio_not_squared": g.I_M + g.I_T * n1 / g.eta + g.I_D * n / g.eta ** 2,
                      "efficiency_multiplied": g.I_M + g.I_T * n1 ** 2 * g.eta + g.I_D * n ** 2 * g.eta ** 2},
                "d": {"one_contact_efficiency": counterweight(spare * g.eta / n),
                      "efficiency_wrong_way": counterweight(spare / (g.eta ** 2 * n)),
                      "counterweight_accel_sign": counterweight(drum, down=+1.0),
                      "resistance_forgotten": counterweight(drum, resist=0.0),
                      "inertia_forgotten": counterweight(g.tau_M * g.eta ** 2 / n)}}
    return answers, mistakes


def haulage_power(v):
    g = printed(v, "dD", "s", "f", "tau_D", "a", "eta", "tau_fM", "tau_fD", "N_M", "I_M", "I_D", "t1", "t2")
    r = g.dD / 2
    pull = g.tau_D / r
    sine = 1 / g.s
    mass = (pull - g.f) / (g.a + G * sine)
    n = g.t1 / g.t2
    alpha = g.a / (r * n)
    i_eq = g.I_M + referred(g.I_D, n, g.eta)
    load = (g.tau_D + g.tau_fD) * n / g.eta + g.tau_fM
    torque = i_eq * alpha + load
    answers = {"a": mass, "b": torque, "c": torque * g.N_M}
    mistakes = {"a": {"diameter_for_radius": (g.tau_D / g.dD - g.f) / (g.a + G * sine),
                      "weight_component_forgotten": (pull - g.f) / g.a, "friction_forgotten": pull / (g.a + G * sine),
                      "cos_for_sin": (pull - g.f) / (g.a + G * math.sqrt(1 - sine ** 2))},
                "b": {"efficiency_multiplied": (g.I_M + g.I_D * n * n * g.eta) * alpha + (g.tau_D + g.tau_fD) * n * g.eta + g.tau_fM,
                      "ratio_not_squared": (g.I_M + g.I_D * n / g.eta) * alpha + load,
                      "inertia_forgotten": load,
                      "drum_friction_not_referred": i_eq * alpha + g.tau_D * n / g.eta + g.tau_fM + g.tau_fD},
                "c": {"rpm_as_rad_s": torque * _per_rpm(g.N_M)}}
    return answers, mistakes


def vehicle_gradient(v):
    g = printed(v, "m", "v", "I_E", "I_W", "eta", "r", "R", "tau_E", "N_E", "a", "tau_fE", "tau_fW")
    wheel = g.v / g.r
    n = wheel / g.N_E
    alpha = g.a / g.r / n
    accelerating = (g.I_E + referred(g.I_W, n, g.eta)) * alpha
    friction = g.tau_fE + g.tau_fW * n / g.eta

    def hill(wheel_torque: float) -> float | None:
        sine = (wheel_torque / g.r - g.m * g.a - g.R) / (g.m * G)
        return math.asin(sine) if -1 < sine < 1 else None

    answers = {"a": wheel, "b": n, "c": hill((g.tau_E - accelerating - friction) * g.eta / n)}
    wrongs = {"efficiency_wrong_way": hill((g.tau_E - accelerating - friction) / (g.eta * n)),
              "inertia_forgotten": hill((g.tau_E - friction) * g.eta / n),
              "friction_forgotten": hill((g.tau_E - accelerating) * g.eta / n)}
    mistakes = {"a": {"diameter_for_radius": g.v / (2 * g.r), "kmh_as_ms": g.v * 3.6 / g.r},
                "b": {"ratio_inverted": 1 / n},
                "c": {name: value for name, value in wrongs.items() if value is not None}}
    return answers, mistakes


def robot_arm(v):
    g = printed(v, "k12", "k34", "I_m", "I_G1", "I_G2", "I_G3", "I_G4", "m", "L", "eta", "theta", "alpha_A")
    n12, n = 1 / float(g.k12), 1 / (float(g.k12) * float(g.k34))
    arm = g.I_G4 + g.m * g.L ** 2
    first = g.I_m + g.I_G1
    i_eq = first + referred(g.I_G2 + g.I_G3, n12, g.eta) + referred(arm, n, g.eta ** 2)
    weight = g.m * G * g.L
    hold = weight * math.cos(g.theta) * n / g.eta ** 2
    lift = weight * n / g.eta ** 2                              # the coefficient of cos(theta)

    def equation(accelerating: float, holding: float, trig=math.cos):
        accelerating, holding = (float(f"{c:.6g}") for c in (accelerating, holding))   # the key prints six figures
        return lambda theta, alpha_A: accelerating * alpha_A + holding * trig(theta)

    answers = {"a": i_eq, "b": hold, "c": i_eq * g.alpha_A / n + hold, "d": equation(i_eq / n, lift)}
    mistakes = {"a": {"ratio_not_squared": first + (g.I_G2 + g.I_G3) * n12 / g.eta + arm * n / g.eta ** 2,
                      "one_contact_efficiency": first + ((g.I_G2 + g.I_G3) * n12 ** 2 + arm * n ** 2) / g.eta,
                      "arm_mass_forgotten": first + referred(g.I_G2 + g.I_G3, n12, g.eta) + referred(g.I_G4, n, g.eta ** 2)},
                "b": {"efficiency_multiplied": weight * math.cos(g.theta) * n * g.eta ** 2,
                      "sin_for_cos": weight * math.sin(g.theta) * n / g.eta ** 2,
                      "ratio_inverted": weight * math.cos(g.theta) / n / g.eta ** 2},
                "c": {"ratio_inverted": i_eq * g.alpha_A * n + hold, "weight_forgotten": i_eq * g.alpha_A / n},
                "d": {"ratio_inverted": equation(i_eq * n, lift), "weight_forgotten": equation(i_eq / n, 0.0),
                      "sin_for_cos": equation(i_eq / n, lift, math.sin)}}
    return answers, mistakes


ORACLES = {
    "belts.flat_belt_power": belt_power, "belts.v_belt_power": belt_power, "belts.max_power": max_power,
    "belts.v_belt_count": v_belt_count, "belts.driven_pulley_diameter": driven_pulley_diameter,
    "belts.driven_speed_slip": driven_speed_slip, "belts.compound_drive": compound_drive,
    "belts.drive_geometry": drive_geometry, "gears.pitch_geometry": pitch_geometry,
    "gears.teeth_for_centre_distance": teeth_for_centre_distance, "gears.simple_train": simple_train,
    "gears.compound_train": compound_train, "gears.reverted_train": reverted_train,
    "gears.gear_pair_power": gear_pair_power, "gears.epicyclic": epicyclic, "gears.hoist_torque": hoist_torque,
    "gears.lift_counterweight": lift_counterweight, "gears.haulage_power": haulage_power,
    "gears.vehicle_gradient": vehicle_gradient, "gears.robot_arm": robot_arm,
}


def test_every_chapter_1_template_has_an_oracle(bank):
    assert sorted(t.id for t in bank if t.chapter == 1) == sorted(ORACLES)


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_the_key_agrees_with_the_oracle_from_the_printed_data(bank, template_id):
    check_answers(bank, template_id, ORACLES[template_id])


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_every_named_mistake_has_the_value_the_oracle_works_out(bank, template_id):
    check_mistakes(bank, template_id, lambda variant: ORACLES[template_id](variant)[1])
