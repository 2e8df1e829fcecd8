"""Every chapter 3-4 answer, recomputed over drawn variants by an oracle of its own from what the sheet prints.

The oracle reads each given as the sheet prints it (and fails if a value it needs is not printed in the
statement or an ask), works the course text's method with no code from exgen's mechanics or solvers,
and compares each part with the key to 1e-9. Its methods differ from the solvers' where they can:
energies at crossings by a running sum, governor lever arms from the coordinates of the pivots, the
joint and the ball (the upper arm's line carried down to the sleeve pivots' level), fluctuations of
energy from the energy curve's own greatest and least values found on a fine grid and refined by golden
section, and the work of a torque curve from its integral in closed form.
"""
from __future__ import annotations

import math
import re
from decimal import Decimal

import pytest

from exgen.solve.variant import make_variant

import figure_readings
import sheet_values
from sheet_values import G

SEEDS = range(40)


def printed(v, *names, optional=()) -> dict:
    """The givens as the sheet prints them, in SI, by name (tests/sheet_values.py reads them)."""
    return vars(sheet_values.printed(v, *names, optional=optional))


def torque_terms(text: str) -> list[float]:
    """'12 500' -> 12500.0, for every number of a printed equation."""
    return [float(x.replace(" ", "")) for x in text]


def golden_extreme(f, lo: float, hi: float, sign: float) -> float:
    """sign·max of sign·f on [lo, hi] (a bracket holding one extreme), by golden section."""
    for _ in range(120):
        a, b = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        if sign * f(a) > sign * f(b):
            hi = b
        else:
            lo = a
    return f(0.5 * (lo + hi))


def swing(f, period: float, grid: int = 20000) -> float:
    """Greatest less least of f over one period."""
    step = period / grid
    values = [f(k * step) for k in range(grid)]
    top = max(range(grid), key=values.__getitem__)
    bottom = min(range(grid), key=values.__getitem__)
    return (golden_extreme(f, (top - 1) * step, (top + 1) * step, 1.0)
            - golden_extreme(f, (bottom - 1) * step, (bottom + 1) * step, -1.0))


# ---- chapter 3 --------------------------------------------------------------------------------------


def crossing_energies(areas: list[float], first: str) -> list[float]:
    energy, out = 0.0, [0.0]
    for k, area in enumerate(areas):
        energy += area if (k % 2 == 0) == (first == "above") else -area
        out.append(energy)
    assert abs(out[-1]) < 1e-6, "the loops do not close"
    return out[:-1]


def speed_fluctuation(v):
    p = printed(v, "a1", "a2", "a3", "a4", "a5", "a6", "first", "Ts", "As", "N", "m", "k")
    energies = crossing_energies([p[f"a{i}"] / 1e-6 for i in range(1, 7)], p["first"])
    fastest = max(range(6), key=energies.__getitem__)
    slowest = min(range(6), key=energies.__getitem__)
    energy = (energies[fastest] - energies[slowest]) * p["Ts"] * p["As"]
    return {"a": "ABCDEF"[fastest], "b": "ABCDEF"[slowest], "c": energy,
            "d": energy / (p["m"] * p["k"] ** 2 * p["N"] ** 2)}


def flywheel_rim(v):
    p = printed(v, *[f"a{i}" for i in range(1, 10)], "first", "Ts", "As", "N", "Cs", "D", "rho", "ratio")
    energies = crossing_energies([p[f"a{i}"] / 1e-6 for i in range(1, 10)], p["first"])
    energy = (max(energies) - min(energies)) * p["Ts"] * p["As"]
    radius = p["D"] / 2
    mass = energy / (p["N"] ** 2 * p["Cs"]) / radius ** 2
    thickness = math.sqrt(mass / (p["rho"] * 2 * math.pi * radius) / p["ratio"])
    return {"a": energy, "b": mass, "c": thickness, "d": p["ratio"] * thickness}


def loop_area_reading(v):
    """Problem 3.1 with the loops counted off the figure's grid and the square's scale read from its axes."""
    read = figure_readings.loop_area_reading(v)
    p = printed(v, "N", "Cs", "D", "rho", "ratio")
    energies = crossing_energies(read["areas"], read["first"])
    energy = (max(energies) - min(energies)) * read["Ts"] * read["As"]
    radius = p["D"] / 2
    mass = energy / (p["N"] ** 2 * p["Cs"]) / radius ** 2
    thickness = math.sqrt(mass / (p["rho"] * 2 * math.pi * radius) / p["ratio"])
    return {"a": energy, "b": mass, "c": thickness, "d": p["ratio"] * thickness}


def torque_time(v):
    return _torque_time(printed(v, "tau_0", "tau_p", "t1", "t2", "t4", "T", "N", "m", "k",
                                *(() if v.param("dwell").text == "0" else ("t3",))))


def torque_time_reading(v):
    """The same, with the pulse read off the figure (its grid and the scales its axes print)."""
    return _torque_time({**printed(v, "N", "m", "k"), **figure_readings.torque_time_reading(v)})


def _torque_time(p):
    t3 = p.get("t3", p["t2"])
    corners = [(0.0, p["tau_0"]), (p["t1"], p["tau_0"]), (p["t2"], p["tau_p"]), (t3, p["tau_p"]),
               (p["t4"], p["tau_0"]), (p["T"], p["tau_0"])]

    def work_to(t):  # ∫ τ dt from 0 to t along the straight pieces
        total = 0.0
        for (x0, y0), (x1, y1) in zip(corners, corners[1:]):
            if t <= x0:
                break
            x = min(t, x1)
            y = y0 + (y1 - y0) * (x - x0) / (x1 - x0) if x1 > x0 else y0
            total += (x - x0) * (y0 + y) / 2
        return total

    mean = work_to(p["T"]) / p["T"]
    w = p["N"]
    energy = swing(lambda t: mean * t - work_to(t), p["T"]) * w   # the motor's work less the machine's
    return {"a": mean, "b": mean * w, "c": energy, "d": energy / (p["m"] * p["k"] ** 2 * w ** 2)}


def punching_press(v):
    p = printed(v, "P", "I", "N", "E", "t")
    per_hour = Decimal(3600) * Decimal(v.param("P").text) / Decimal(v.param("E").text)   # kW and kJ: exact
    flywheel = p["E"] - p["P"] * p["t"]
    return {"a": int(per_hour // 1), "b": flywheel,
            "c": p["N"] - math.sqrt(p["N"] ** 2 - 2 * flywheel / p["I"])}


def turning_moment_equation(v):
    p = printed(v, "N", "band", "theta")
    found = re.search(r"T = ([\d ]+) ([+−]) ([\d ]+) sin (\d*)θ\s+([+−]) ([\d ]+) cos (\d*)θ N·m", v.statement)
    mean, b, c = torque_terms(found.group(1, 3, 6))
    b, c = (b if found.group(2) == "+" else -b), (c if found.group(5) == "+" else -c)
    n = int(found.group(4) or 1)
    assert n == int(found.group(7) or 1)
    energy = swing(lambda th: (b * (1 - math.cos(n * th)) + c * math.sin(n * th)) / n, 2 * math.pi)
    inertia = energy / (p["N"] ** 2 * 2 * p["band"])    # ±x % is a band of 2x %
    excess = b * math.sin(n * p["theta"]) + c * math.cos(n * p["theta"])
    return {"a": mean * p["N"], "b": inertia, "c": excess / inertia}


def fluctuating_resistance(v):
    p = printed(v, "N", "I")
    engine = re.search(r"T = \(([\d ]+) \+ ([\d ]+) sin (\d)θ\) N·m", v.statement)
    resisting = re.search(r"\(([\d ]+) \+ ([\d ]+) sin θ\) N·m", v.asks["c"])
    mean, b = torque_terms(engine.group(1, 2))
    n = int(engine.group(3))
    resisting_mean, r = torque_terms(resisting.group(1, 2))
    assert resisting_mean == mean
    constant = swing(lambda th: b / n * (1 - math.cos(n * th)), 2 * math.pi)
    fluctuating = swing(lambda th: b / n * (1 - math.cos(n * th)) - r * (1 - math.cos(th)), 2 * math.pi)
    scale = p["I"] * p["N"] ** 2
    return {"a": mean * p["N"], "b": constant / scale, "c": fluctuating / scale}


def starting_torque(v):
    p = printed(v, "m", "k", "tau", "t")
    alpha = p["tau"] / (p["m"] * p["k"] ** 2)
    return {"a": alpha, "b": p["tau"] * alpha * p["t"] ** 2 / 2}   # the torque's work over θ = ½ α t²


def energy_coefficient(v):
    p = printed(v, "P", "N", "cycle", "Ce", "band", "k")
    revolutions = {"one revolution": 1, "two revolutions": 2}[p["cycle"]]
    work = p["P"] * revolutions * 2 * math.pi / p["N"]
    energy = p["Ce"] * work
    mass = energy / (p["N"] ** 2 * 2 * p["band"]) / p["k"] ** 2
    return {"a": work, "b": energy, "c": mass, "d": mass * G}


# ---- chapter 4 --------------------------------------------------------------------------------------


def governor_speed(m, sleeve_force, l, upper, lower, joint, extension=0.0, turned=0.0):
    """ω and the ball's radius, by moments about I from coordinates (x out from the axis, y up from the
    sleeve pivots): the upper pivot, the joint, the ball on an extension turned `turned` from upright."""
    low_h = math.sqrt(l * l - (joint - lower) ** 2)           # joint above the sleeve pivot
    up_h = math.sqrt(l * l - (joint - upper) ** 2)            # upper pivot above the joint
    i_x = joint + (joint - upper) / up_h * low_h              # upper arm's line carried down to y = 0
    ball_x, ball_y = joint + extension * math.sin(turned), low_h + extension * math.cos(turned)
    force = (m * G * (i_x - ball_x) + sleeve_force / 2 * (i_x - lower)) / ball_y
    return math.sqrt(force / (m * ball_x)), ball_x


def watt_height(v):
    p = printed(v, "l", "N1", "N2")
    h1, h2 = G / p["N1"] ** 2, G / p["N2"] ** 2
    return {"a": h1, "b": h1 - h2, "c": math.acos(h1 / p["l"])}


def porter_dead_load(v):
    p = printed(v, "l", "m", "N", "alpha", "x", optional=("e",))
    l, e, m = p["l"], p["e"], p["m"]
    height = l * math.cos(p["alpha"])
    joint = e + l * math.sin(p["alpha"])
    i_x = e + 2 * l * math.sin(p["alpha"])
    load = (m * p["N"] ** 2 * joint * height - m * G * (i_x - joint)) / (G / 2 * (i_x - e))
    speeds = [governor_speed(m, load * G, l, e, e, e + math.sqrt(l * l - (height + dh) ** 2))[0]
              for dh in (-p["x"] / 2, p["x"] / 2)]   # risen: each arm's height less by half the travel
    return {"a": load, "b": speeds[0], "c": speeds[1], "d": p["N"] / (speeds[0] - speeds[1])}


def porter_friction(v):
    p = printed(v, "l", "e_l", "m", "M", "r", "f", optional=("e_u",))
    speed = [governor_speed(p["m"], p["M"] * G + f, p["l"], p["e_u"], p["e_l"], p["r"])[0]
             for f in (0.0, p["f"], -p["f"])]
    return {"a": speed[0], "b": speed[1], "c": speed[2], "d": speed[1] - speed[2]}


def porter_sleeve_friction(v):
    p = printed(v, "l", "e", "m", "M", "N0", "alpha0", "alpha1")
    l, e, m = p["l"], p["e"], p["m"]
    joint = e + l * math.sin(p["alpha0"])
    iz, height = l * math.sin(p["alpha0"]), l * math.cos(p["alpha0"])
    friction = 2 * (m * p["N0"] ** 2 * joint * height - m * G * iz) / (2 * iz) - p["M"] * G
    joint1 = e + l * math.sin(p["alpha1"])
    falling, rising = (governor_speed(m, p["M"] * G + f, l, e, e, joint1)[0] for f in (-friction, friction))
    return {"a": friction, "b": falling, "c": rising}


def porter_speed_range(v):
    p = printed(v, "l", "e_l", "m", "M", "r1", "r2", optional=("e_u",))
    l, eu, el = p["l"], p["e_u"], p["e_l"]
    w1, w2 = (governor_speed(p["m"], p["M"] * G, l, eu, el, p[r])[0] for r in ("r1", "r2"))

    def depth(r):
        return math.sqrt(l * l - (r - eu) ** 2) + math.sqrt(l * l - (r - el) ** 2)

    f1, f2 = p["m"] * w1 ** 2 * p["r1"], p["m"] * w2 ** 2 * p["r2"]
    axis = f1 - (f2 - f1) / (p["r2"] - p["r1"]) * p["r1"]         # the chord through both points at r = 0
    kind = "stable" if axis < 0 else "unstable" if axis > 0 else "isochronous"
    return {"a": w1, "b": w2, "c": w2 - w1, "d": depth(p["r1"]) - depth(p["r2"]), "e": f1, "f": f2, "g": kind}


def proell_extension(v):
    p = printed(v, "l", "m", "M", "r", "N", optional=("e",))
    l, e, r = p["l"], p["e"], p["r"]
    height = math.sqrt(l * l - (r - e) ** 2)
    i_x = e + 2 * (r - e)
    force = p["m"] * p["N"] ** 2 * r          # the extension upright: the ball turns at the joint's radius
    extension = (p["m"] * G * (i_x - r) + p["M"] * G / 2 * (i_x - e)) / force - height
    return {"a": extension, "b": (p["m"] * G + p["M"] * G / 2) / (height / l)}


def proell_speeds(v):
    p = printed(v, "l", "e_l", "e", "m", "M", "r1", "r2", optional=("e_u",))
    l, eu, el = p["l"], p["e_u"], p["e_l"]
    turned = math.asin((p["r2"] - el) / l) - math.asin((p["r1"] - el) / l)   # the lower arm's turn
    w1, _ = governor_speed(p["m"], p["M"] * G, l, eu, el, p["r1"], p["e"], 0.0)
    w2, ball = governor_speed(p["m"], p["M"] * G, l, eu, el, p["r2"], p["e"], turned)
    joint = p["r2"]                     # the ball at r2 instead: the joint by fixed-point iteration
    for _ in range(200):
        joint = p["r2"] - p["e"] * math.sin(math.asin((joint - el) / l) - math.asin((p["r1"] - el) / l))
    return {"a": w1, "b": w2, "c": ball, "d": joint}


def hartnell_spring(v):
    p = printed(v, "m", "a", "b", "M", "f", "N1", "r1", "N2", "r2")
    spring = [2 * p["m"] * p[n] ** 2 * p[r] * p["a"] / p["b"] - p["M"] * G - p["f"]
              for n, r in (("N1", "r1"), ("N2", "r2"))]   # rising: friction adds to the sleeve load
    lift = (p["r2"] - p["r1"]) * p["b"] / p["a"]
    return {"a": spring[0], "b": spring[1], "c": (spring[1] - spring[0]) / lift}


def hartnell_two_springs(v):
    p = printed(v, "m", "a", "b", "c", "Ms", "K1", "L1", "L2", "f", "N", "r1")
    turn = math.asin((p["r1"] - p["b"] - p["c"]) / p["a"])
    rise = p["b"] * math.sin(turn)
    lever_load = (2 * p["m"] * p["N"] ** 2 * p["r1"] * p["a"] / p["b"] - p["Ms"] * G - p["K1"] * rise - p["f"])
    tension = lever_load * p["L1"] / p["L2"]
    return {"a": tension, "b": tension / (rise * p["L2"] / p["L1"])}


def spring_controlled(v):
    p = printed(v, "m", "r1", "F1", "r2", "F2", "N")
    slope = (p["F2"] - p["F1"]) / (p["r2"] - p["r1"])
    intercept = p["F1"] - slope * p["r1"]
    return {"a": "stable" if intercept < 0 else "unstable", "b": intercept / (p["m"] * p["N"] ** 2 - slope),
            "c": abs(intercept), "d": "increase" if intercept < 0 else "decrease", "e": math.sqrt(slope / p["m"])}


ORACLES = {
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


def test_every_chapter_3_and_4_template_has_an_oracle(bank):
    assert sorted(t.id for t in bank if t.chapter in (3, 4)) == sorted(ORACLES)


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_the_key_agrees_with_the_oracle_from_the_printed_data(bank, template_id):
    template, oracle = bank.get(template_id), ORACLES[template_id]
    for seed in SEEDS:
        variant = make_variant(template, seed)
        expected = oracle(variant)
        assert sorted(expected) == sorted(variant.answers), seed
        for part, answer in variant.answers.items():
            if isinstance(expected[part], str):
                assert answer.value == expected[part], (seed, part)
            else:
                assert answer.si == pytest.approx(expected[part], rel=1e-9, abs=1e-12), (seed, part, answer.text)
