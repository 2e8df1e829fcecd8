"""Every named mistake of chapters 3 and 4 has an expected value of its own: each is worked out here from what
the sheet prints and from the oracle's answers (tests/test_flywheels_governors_oracle.py, code of its own),
by the slip its name says, and compared with what the key records wherever it records it, over many draws."""
from __future__ import annotations

import math
import re
from decimal import Decimal
from types import SimpleNamespace

import pytest

import figure_readings
from sheet_values import G, check_mistakes, printed
from test_flywheels_governors_oracle import ORACLES, governor_speed, torque_terms

RPM = 2 * math.pi / 60   # a speed in rpm used as rad/s is this much too large, per rad/s


def answers(v) -> dict:
    return ORACLES[v.template.id](v)


# ---- chapter 3 ------------------------------------------------------------------------------------------


def loop_energies(v, loops: int) -> dict:
    """A turning-moment diagram's slips: one scale only, degrees for the angle scale, the largest loop."""
    g = printed(v, *(f"a{i}" for i in range(1, loops + 1)), "Ts", "As")
    delta_e = answers(v)["c" if loops == 6 else "a"]
    return {"one_scale_only": delta_e / g.As, "angle_scale_in_degrees": delta_e * 180 / math.pi,
            "largest_loop": max(getattr(g, f"a{i}") / 1e-6 for i in range(1, loops + 1)) * g.Ts * g.As}


def speed_fluctuation(v):
    g = printed(v, "N", "m", "k")
    a = answers(v)
    return {"a": {"least_for_greatest": a["b"]}, "b": {"least_for_greatest": a["a"]}, "c": loop_energies(v, 6),
            "d": {"rpm_as_rad_s": a["d"] * RPM ** 2, "half_band": a["d"] / 2, "k_not_squared": a["d"] * g.k}}


def flywheel_rim(v):
    return {"a": loop_energies(v, 9), **rim_slips(v)}


def rim_slips(v):
    """The rim's slips (b)-(d), from ΔE in (a)."""
    g = printed(v, "D", "ratio")
    a = answers(v)
    section = a["c"] ** 2 * float(g.ratio)                      # b t = k t²
    return {"b": {"rpm_as_rad_s": a["b"] * RPM ** 2, "diameter_for_radius": a["b"] / 4, "total_read_as_plus_minus": a["b"] / 2},
            "c": {"square_section": math.sqrt(section), "ratio_inverted": math.sqrt(section * float(g.ratio))},
            "d": {"square_section": math.sqrt(section), "ratio_inverted": a["c"] / float(g.ratio)}}


def loop_area_reading(v):
    """The slips of counting squares (whole squares only, every square touched as whole) and of the scales,
    from the loops read off the figure."""
    read = figure_readings.loop_area_reading(v)
    a = answers(v)
    per_square = read["Ts"] * read["As"]

    def swing(count) -> float:                # greatest less least energy at A to I, from loops so counted
        edges = [[0, *h, 0] for h in read["heights"]]
        counted = [sum(count(l, r) for l, r in zip(e, e[1:])) for e in edges]
        energy, levels = 0.0, [0.0]
        for k, area in enumerate(counted[:-1]):
            energy += area if (k % 2 == 0) == (read["first"] == "above") else -area
            levels.append(energy)
        return (max(levels) - min(levels)) * per_square

    return {"a": {"one_scale_only": a["a"] / read["As"], "angle_scale_in_degrees": a["a"] * 180 / math.pi,
                  "largest_loop": max(read["areas"]) * per_square,
                  "whole_squares_only": swing(min), "part_squares_as_whole": swing(max)},
            **rim_slips(v)}


def torque_time(v):
    dwell = v.param("dwell").text != "0"
    g = printed(v, "tau_0", "tau_p", "t1", "t2", "t4", "T", "N", *(("t3",) if dwell else ()))
    return _torque_time(v, g, g.t3 if dwell else g.t2)


def torque_time_reading(v):
    """The same slips, with the pulse read off the figure."""
    g = SimpleNamespace(**vars(printed(v, "N")), **figure_readings.torque_time_reading(v))
    return _torque_time(v, g, g.t3)


def _torque_time(v, g, t3):
    pulse = ((g.t4 - g.t1) + (t3 - g.t2)) / 2 * (g.tau_p - g.tau_0)     # the trapezium above the base
    a = answers(v)
    return {"a": {"peak_base_average": (g.tau_p + g.tau_0) / 2, "base_left_out": pulse / g.T},
            "b": {"rpm_as_rad_s": a["b"] / RPM},
            "c": {"area_above_base": pulse * g.N, "time_not_converted": a["c"] / g.N, "rpm_as_rad_s": a["c"] / RPM},
            "d": {"half_band": a["d"] / 2, "rpm_as_rad_s": a["d"] * RPM ** 2}}


def punching_press(v):
    g = printed(v, "P", "I", "N", "E", "t")
    a = answers(v)
    per_hour = Decimal(3600) * Decimal(v.param("P").text) / Decimal(v.param("E").text)
    as_rpm = g.N / RPM
    drop = {"linearised": a["b"] / (g.I * g.N), "final_speed": g.N - a["c"],
            "rpm_as_rad_s": as_rpm - math.sqrt(as_rpm ** 2 - 2 * a["b"] / g.I)}
    if g.E < g.I * g.N ** 2 / 2:                               # the flywheel holds the whole pressing
        drop["motor_ignored"] = g.N - math.sqrt(g.N ** 2 - 2 * g.E / g.I)
    return {"a": {"rounded_up": math.ceil(per_hour)}, "b": {"motor_ignored": g.E}, "c": drop}


def turning_moment_equation(v):
    g = printed(v, "N", "band", "theta")
    a = answers(v)
    found = re.search(r"T = ([\d ]+) ([+−]) ([\d ]+) sin (\d*)θ\s+([+−]) ([\d ]+) cos (\d*)θ N·m", v.statement)
    mean, b, c = torque_terms(found.group(1, 3, 6))
    b, c = (b if found.group(2) == "+" else -b), (c if found.group(5) == "+" else -c)
    n = int(found.group(4) or 1)
    degrees = math.degrees(g.theta)                              # θ in degrees put into sin nθ
    return {"a": {"rpm_as_rad_s": a["a"] / RPM},
            "b": {"plus_minus_read_as_total": 2 * a["b"], "rpm_as_rad_s": a["b"] * RPM ** 2},
            "c": {"degrees_as_radians": (b * math.sin(n * degrees) + c * math.cos(n * degrees)) / a["b"],
                  "total_torque": a["c"] + mean / a["b"],
                  "harmonic_order_ignored": (b * math.sin(g.theta) + c * math.cos(g.theta)) / a["b"]}}


def fluctuating_resistance(v):
    a = answers(v)
    return {"a": {"rpm_as_rad_s": a["a"] / RPM}, "b": {"half_band": a["b"] / 2, "rpm_as_rad_s": a["b"] * RPM ** 2},
            "c": {"constant_resistance": a["b"], "half_band": a["c"] / 2, "rpm_as_rad_s": a["c"] * RPM ** 2}}


def starting_torque(v):
    g = printed(v, "m", "k", "tau", "t")
    a = answers(v)
    inertia = g.m * g.k ** 2
    return {"a": {"k_not_squared": g.tau / (g.m * g.k)},
            "b": {"half_forgotten": 2 * a["b"], "speed_not_squared": inertia * a["a"] * g.t / 2}}


def energy_coefficient(v):
    g = printed(v, "cycle", "k")
    a = answers(v)
    work = {"rpm_as_rad_s": a["a"] * RPM}
    if g.cycle.startswith("two"):
        work["one_revolution"] = a["a"] / 2
    return {"a": work, "c": {"plus_minus_read_as_total": 2 * a["c"], "rpm_as_rad_s": a["c"] * RPM ** 2,
                             "k_not_squared": a["c"] * g.k},
            "d": {"mass_for_weight": a["c"]}}     # the kilograms given as newtons


# ---- chapter 4 ------------------------------------------------------------------------------------------


def watt_height(v):
    g = printed(v, "N2", "l")
    a = answers(v)
    return {"a": {"rpm_as_rad_s": a["a"] * RPM ** 2}, "b": {"rpm_as_rad_s": a["b"] * RPM ** 2, "height_not_change": G / g.N2 ** 2},
            "c": {"sine_for_cosine": math.asin(a["a"] / g.l)}}


def porter_dead_load(v):
    g = printed(v, "l", "m", "N", "alpha", "x", optional=("e",))
    a = answers(v)
    iz, h = g.l * math.sin(g.alpha), g.l * math.cos(g.alpha)
    r = g.e + iz

    def load(force: float) -> float:
        """M from F·h = m g·IZ + ½ M g·2 IZ (equal arms and offsets: IY = 2 IZ)."""
        return (force * h - g.m * G * iz) / (G * iz)

    mistakes = {"a": {"rpm_as_rad_s": load(g.m * (g.N / RPM) ** 2 * r), "sleeve_moment_arm": 2 * a["a"],
                      "offset_ignored": load(g.m * g.N ** 2 * iz)},
                "b": {}, "c": {}, "d": {"sensitivity_inverted": 1 / a["d"], "rpm_as_rad_s": a["d"] / RPM}}
    for part, sign in (("b", -1), ("c", 1)):                     # the sleeve's whole travel taken for each arm's
        wrong_h = h + sign * g.x
        if 0 < wrong_h < g.l:
            mistakes[part]["full_sleeve_travel"] = governor_speed(g.m, a["a"] * G, g.l, g.e, g.e,
                                                                 g.e + math.sqrt(g.l ** 2 - wrong_h ** 2))[0]
    return mistakes


def porter_friction(v):
    g = printed(v, "l", "e_l", "m", "M", "r", "f", optional=("e_u",))
    a = answers(v)

    def speed(sleeve_force: float) -> float:
        return governor_speed(g.m, sleeve_force, g.l, g.e_u, g.e_l, g.r)[0]

    low = math.sqrt(g.l ** 2 - (g.r - g.e_l) ** 2)               # XZ: the lower arm's height
    iz = (g.r - g.e_u) / math.sqrt(g.l ** 2 - (g.r - g.e_u) ** 2) * low  # I on the upper arm's line
    at_iz = math.sqrt((g.m * G * iz + g.M * G / 2 * iz) / low / (g.m * g.r))  # half the sleeve load at IZ
    return {"a": {"offset_ignored": governor_speed(g.m, g.M * G, g.l, g.e_u, g.e_u, g.r)[0], "sleeve_moment_arm": at_iz},
            "b": {"friction_wrong_side": a["c"], "friction_doubled": speed(g.M * G + 2 * g.f)},
            "c": {"friction_wrong_side": a["b"], "friction_doubled": speed(g.M * G - 2 * g.f)}}


def porter_sleeve_friction(v):
    g = printed(v, "l", "e", "m", "M", "N0", "alpha0", "alpha1")
    a = answers(v)
    iz, h = g.l * math.sin(g.alpha0), g.l * math.cos(g.alpha0)
    slow = g.N0 / RPM
    friction = (g.m * slow ** 2 * (g.e + iz) * h - g.m * G * iz) / iz - g.M * G
    ignored = governor_speed(g.m, g.M * G, g.l, g.e, g.e, g.e + g.l * math.sin(g.alpha1))[0]
    return {"a": {"friction_wrong_side": -a["a"], "rpm_as_rad_s": friction},
            "b": {"friction_wrong_side": a["c"], "friction_ignored": ignored},
            "c": {"friction_wrong_side": a["b"], "friction_ignored": ignored}}


def porter_speed_range(v):
    g = printed(v, "l", "e_l", "m", "M", "r1", "r2", optional=("e_u",))
    a = answers(v)

    def at_iz(r: float) -> float:
        """The speed with half the sleeve load taken at IZ, not IY (moments about I)."""
        low = math.sqrt(g.l ** 2 - (r - g.e_l) ** 2)
        up = math.sqrt(g.l ** 2 - (r - g.e_u) ** 2)
        iz = (r - g.e_u) / up * low                              # I lies on the upper arm's line, low below the joint
        return math.sqrt((g.m * G * iz + g.M * G / 2 * iz) / low / (g.m * r))

    def upper_height(r: float) -> float:
        return math.sqrt(g.l ** 2 - (r - g.e_u) ** 2)

    return {part: {"offset_ignored": governor_speed(g.m, g.M * G, g.l, g.e_u, g.e_u, r)[0], "sleeve_moment_arm": at_iz(r)}
            for part, r in (("a", g.r1), ("b", g.r2))} | {"d": {"one_arm_only": upper_height(g.r1) - upper_height(g.r2)}} | {
        part: {"rpm_as_rad_s": g.m * (a[w] * 60 / (2 * math.pi)) ** 2 * r, "speed_not_squared": g.m * a[w] * r}
        for part, w, r in (("e", "a", g.r1), ("f", "b", g.r2))} | {
        "g": {"stability_inverted": {"stable": "unstable", "unstable": "stable"}.get(a["g"], "stable")}}


def proell_extension(v):
    g = printed(v, "l", "m", "M", "r", "N", optional=("e",))
    a = answers(v)
    iz = g.r - g.e
    height = math.sqrt(g.l ** 2 - iz ** 2)
    alpha = math.asin(iz / g.l)
    return {"a": {"rpm_as_rad_s": (g.m + g.M) * G * iz / (g.m * (g.N / RPM) ** 2 * g.r) - height,
                  "sleeve_moment_arm": (g.m + g.M / 2) * G * iz / (g.m * g.N ** 2 * g.r) - height},
            "b": {"whole_sleeve_load": (g.m + g.M) * G / math.cos(alpha), "sine_for_cosine": (g.m + g.M / 2) * G / math.sin(alpha)}}


def proell_speeds(v):
    g = printed(v, "l", "e_l", "e", "m", "M", "r1", "r2", optional=("e_u",))

    def porter(r: float) -> float:                               # the ball at the joint
        return governor_speed(g.m, g.M * G, g.l, g.e_u, g.e_l, r)[0]

    upright = governor_speed(g.m, g.M * G, g.l, g.e_u, g.e_l, g.r2, g.e, 0.0)[0]
    return {"a": {"porter_formula": porter(g.r1)}, "b": {"extension_kept_vertical": upright, "porter_formula": porter(g.r2)},
            "c": {"extension_kept_vertical": g.r2}, "d": {"extension_kept_vertical": g.r2}}


def hartnell_spring(v):
    g = printed(v, "m", "a", "b", "M", "f", "N1", "r1", "N2", "r2")
    a = answers(v)
    out = {}
    for part, n, r in (("a", g.N1, g.r1), ("b", g.N2, g.r2)):
        force = g.m * n ** 2 * r
        right = a[part]
        out[part] = {"friction_wrong_side": right + 2 * g.f, "arms_inverted": 2 * force * g.b / g.a - g.M * G - g.f,
                     "sleeve_weight_forgotten": right + g.M * G, "one_ball": force * g.a / g.b - g.M * G - g.f,
                     "rpm_as_rad_s": 2 * g.m * (n / RPM) ** 2 * r * g.a / g.b - g.M * G - g.f}
    rise = a["b"] - a["a"]
    out["c"] = {"lift_not_scaled": rise / (g.r2 - g.r1), "arms_inverted": rise / ((g.r2 - g.r1) * g.a / g.b)}
    return out


def hartnell_two_springs(v):
    g = printed(v, "m", "a", "b", "c", "Ms", "K1", "L1", "L2", "f", "N", "r1")
    a = answers(v)
    rise = g.b * math.sin(math.asin((g.r1 - g.b - g.c) / g.a))   # the sleeve's rise: spring 1's compression

    def sleeve(speed: float, ball_arm: float, sleeve_arm: float) -> float:
        return 2 * g.m * speed ** 2 * g.r1 * ball_arm / sleeve_arm - g.Ms * G - g.K1 * rise - g.f

    right = sleeve(g.N, g.a, g.b)
    return {"a": {"friction_wrong_side": (right + 2 * g.f) * g.L1 / g.L2, "lever_inverted": right * g.L2 / g.L1,
                  "arms_inverted": sleeve(g.N, g.b, g.a) * g.L1 / g.L2, "rpm_as_rad_s": sleeve(g.N / RPM, g.a, g.b) * g.L1 / g.L2},
            "b": {"lever_inverted": a["a"] / (rise * g.L1 / g.L2), "sleeve_travel_for_spring": a["a"] / rise}}


def spring_controlled(v):
    g = printed(v, "m", "r1", "F1", "r2", "F2", "N")
    a = answers(v)
    slope = (g.F2 - g.F1) / (g.r2 - g.r1)
    intercept = g.F1 - slope * g.r1
    return {"a": {"stability_inverted": {"stable": "unstable", "unstable": "stable"}.get(a["a"], "stable")},
            "b": {"rpm_as_rad_s": intercept / (g.m * (g.N / RPM) ** 2 - slope)},
            "d": {"opposite": "decrease" if a["d"] == "increase" else "increase"},
            "e": {"mass_not_divided": math.sqrt(slope)}}


MISTAKES = {
    "flywheels.speed_fluctuation": speed_fluctuation, "flywheels.flywheel_rim": flywheel_rim,
    "flywheels.torque_time": torque_time, "flywheels.punching_press": punching_press,
    "flywheels.torque_time_reading": torque_time_reading, "flywheels.loop_area_reading": loop_area_reading,
    "flywheels.turning_moment_equation": turning_moment_equation,
    "flywheels.fluctuating_resistance": fluctuating_resistance, "flywheels.starting_torque": starting_torque,
    "flywheels.energy_coefficient": energy_coefficient, "governors.watt_height": watt_height,
    "governors.porter_dead_load": porter_dead_load, "governors.porter_friction": porter_friction,
    "governors.porter_sleeve_friction": porter_sleeve_friction, "governors.porter_speed_range": porter_speed_range,
    "governors.proell_extension": proell_extension, "governors.proell_speeds": proell_speeds,
    "governors.hartnell_spring": hartnell_spring, "governors.hartnell_two_springs": hartnell_two_springs,
    "governors.spring_controlled": spring_controlled,
}


def test_every_chapter_3_and_4_template_has_its_mistakes_worked(bank):
    assert sorted(t.id for t in bank if t.chapter in (3, 4)) == sorted(MISTAKES)


@pytest.mark.parametrize("template_id", sorted(MISTAKES))
def test_every_named_mistake_has_the_value_its_slip_gives(bank, template_id):
    check_mistakes(bank, template_id, MISTAKES[template_id])
