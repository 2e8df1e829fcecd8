"""Every named mistake of chapters 5 and 7 has an expected value of its own: each is worked out here from what
the sheet prints, by the slip its name says, with the couples and positions worked as formulas of this file
(the directions of chapter 5 and the text's position equations of chapter 7 from exgen.mechanics, which
tests/test_gyroscopes_oracle.py and tests/test_linkages_oracle.py hold to oracles of their own), and
compared with what the key records wherever it records it, over many draws."""
from __future__ import annotations

import cmath
import math

import pytest

from exgen.mechanics import gyroscopes as gy
from exgen.mechanics import linkages as lk
from exgen.mechanics.mechanism_catalogue import build
from exgen.mechanics.slider_cranks import slider_crank
import figure_readings
from sheet_values import G, check_answers, check_mistakes, printed

RPM = 2 * math.pi / 60
KMH = 3.6                  # a speed in m/s left as the number of km/h is this much too large
OTHER = {"left": "right", "right": "left", "raises the bow": "lowers the bow", "lowers the bow": "raises the bow",
         "raises the nose": "lowers the nose", "lowers the nose": "raises the nose", "port": "starboard",
         "starboard": "port", "front": "rear", "rear": "front", "adds": "relieves", "relieves": "adds",
         "clockwise": "counter-clockwise", "counter-clockwise": "clockwise"}


def other(v, part: str) -> str:
    """The other choice than the key's (the direction oracle of chapter 5 checks the key's own)."""
    return OTHER[v.answers[part].value]


# ---- chapter 5 ------------------------------------------------------------------------------------------


def vehicle_rotor_springs(v):
    g = printed(v, "I", "N", "K", "l", "v", "R")
    couple = g.I * g.N * g.v / g.R
    return {"b": {"kmh_not_converted": KMH * g.v / g.R},
            "c": {"rpm_as_rad_s": g.I * (g.N / RPM) * g.v / g.R, "kmh_not_converted": couple * KMH},
            "d": {"half_spacing": 2 * couple / g.l, "couple_shared": couple / (2 * g.l)},
            "f": {"precession_reversed": other(v, "f")}}


def rotor_bearing_reactions(v):
    g = printed(v, "m", "k", "N", "l", "a", "v", "R", "sense", "turn")
    precession = g.v / g.R
    couple = g.m * g.k ** 2 * g.N * precession
    force = couple / g.l
    weight = g.m * G
    share = {"c": weight * (g.l - g.a) / g.l, "d": weight * g.a / g.l}
    bow_up = gy.pitch_effect(gy.reactive_couple(gy.axial_spin(g.sense, "rear"), gy.turning(g.turn))) == "nose up"
    lifted = "c" if bow_up else "d"                             # the rotor lifts on the bearing at the rising end
    reaction = {p: share[p] + (-force if p == lifted else force) for p in ("c", "d")}
    out = {"a": {"rpm_as_rad_s": couple / RPM, "radius_for_k": couple / 2}, "b": {"precession_reversed": other(v, "b")}}
    for part in ("c", "d"):
        wrong = {"gyro_added_where_it_relieves" if part == lifted else "gyro_subtracted_where_it_adds":
                 reaction[part] + (2 * force if part == lifted else -2 * force), "weight_ignored": force,
                 "gyro_ignored": share[part]}                    # the static reaction, the couple left out
        if abs(g.a - g.l / 2) > 0.05 * g.l:
            wrong["weight_halved"] = weight / 2 + reaction[part] - share[part]
        out[part] = wrong
    return out


def aircraft_turning(v):
    g = printed(v, "m", "k", "N", "v", "R")
    couple = g.m * g.k ** 2 * g.N * g.v / g.R
    return {"a": {"kmh_not_converted": KMH * g.v / g.R},
            "b": {"rpm_as_rad_s": couple / RPM, "radius_for_k": couple / 2}, "c": {"precession_reversed": other(v, "c")}}


def ship_turbine(v):
    g = printed(v, "m", "k", "N", "v", "R", "phi", "T")
    couple = g.m * g.k ** 2 * g.N * g.v / g.R
    return {"a": {"rpm_as_rad_s": couple / RPM, "kmh_not_converted": couple * KMH},
            "b": {"precession_reversed": other(v, "b")},
            "c": {"degrees_not_converted": math.degrees(g.phi) * 2 * math.pi / g.T, "missing_2pi": g.phi / g.T},
            "d": {"rpm_as_rad_s": g.m * g.k ** 2 * g.N * (g.phi * 2 * math.pi / g.T) / RPM},
            "e": {"precession_reversed": other(v, "e")},
            "f": {"rolling_like_steering": v.answers["b"].value, "rolling_like_pitching": v.answers["e"].value}}


def car_wheel_reactions(v):
    g = printed(v, "m", "b", "x", "h", "a", "d_w", "I_w", "m_e", "k_e", "G", "v", "R", "turn")
    weight = g.m * G
    share = {"f": weight * (g.b - g.a) / (2 * g.b), "r": weight * g.a / (2 * g.b)}
    wheel = 2 * g.v / g.d_w
    precession = g.v / g.R
    wheels_couple = 4 * g.I_w * wheel * precession
    engine_couple = g.m_e * g.k_e ** 2 * float(g.G) * wheel * precession
    p_w, p_e = wheels_couple / (2 * g.x), engine_couple / (2 * g.b)
    centrifugal = g.m * g.v ** 2 / g.R
    p_c = centrifugal * g.h / (2 * g.x)
    loaded = v.answers["c"].value                               # checked by the direction oracle
    outer = "left" if g.turn == "right" else "right"
    out = {"a": {"diameter_for_radius": p_w / 2, "wheelbase_for_track": wheels_couple / (2 * g.b)},
           "b": {"track_for_wheelbase": engine_couple / (2 * g.x), "not_shared": engine_couple / g.b},
           "c": {"precession_reversed": OTHER[loaded]}, "d": {"not_shared": centrifugal * g.h / g.x}}
    for part, axle, side in (("e", "f", "left"), ("f", "f", "right"), ("g", "r", "left"), ("h", "r", "right")):
        out_side = 1.0 if side == outer else -1.0
        engine = p_e * (1.0 if (axle == "r") == (loaded == "rear") else -1.0)
        other_share = share["r" if axle == "f" else "f"]
        out[part] = {"sides_swapped": share[axle] - out_side * (p_w + p_c) + engine,
                     "weight_split_reversed": other_share + out_side * (p_w + p_c) + engine,
                     "centrifugal_ignored": share[axle] + out_side * p_w + engine}
    return out


def heel(couple: float, centrifugal: float, mass: float, height: float) -> float:
    """Leaning θ: (C_g + C_c) cos θ = m g h sin θ."""
    return math.atan2(couple + centrifugal, mass * G * height)


def motorcycle_banking(v):
    g = printed(v, "m", "h", "m_w", "k_w", "r_w", "m_e", "k_e", "G", "v", "R")
    s = 1.0 if v.param("engine").text == "same" else -1.0      # said in words on the sheet
    precession, wheel = g.v / g.R, g.v / g.r_w
    wheels, engine = 2 * g.m_w * g.k_w ** 2, g.m_e * g.k_e ** 2
    ratio = float(g.G)

    def gyro(wheel_inertia, engine_inertia, engine_speed, sign=s):
        return (wheel_inertia * wheel + sign * engine_inertia * engine_speed) * precession

    couple = gyro(wheels, engine, ratio * wheel)
    centrifugal = g.m * g.v ** 2 / g.R * g.h
    theta = heel(couple, centrifugal, g.m, g.h)
    return {"a": {"diameter_for_radius": g.v / (2 * g.r_w)},
            "b": {"engine_sense_reversed": gyro(wheels, engine, ratio * wheel, -s),
                  "radius_for_k": gyro(2 * g.m_w * g.r_w ** 2, engine, ratio * wheel),
                  "one_wheel": gyro(wheels / 2, engine, ratio * wheel), "ratio_inverted": gyro(wheels, engine, wheel / ratio)},
            "c": {"kmh_not_converted": g.m * (KMH * g.v) ** 2 / g.R},
            "d": {"gyro_ignored": heel(0.0, centrifugal, g.m, g.h), "complement": math.pi / 2 - theta}}


def motorcycle_heel(v):
    g = printed(v, "I_w", "I_e", "G", "d_w", "m", "h", "v", "R")
    s = 1.0 if v.param("engine").text == "same" else -1.0
    precession, wheel = g.v / g.R, 2 * g.v / g.d_w
    ratio = float(g.G)

    def gyro(wheels=2 * g.I_w, sign=s, speed=wheel):
        return (wheels + sign * ratio * g.I_e) * speed * precession

    centrifugal = g.m * g.v ** 2 / g.R * g.h
    theta = heel(gyro(), centrifugal, g.m, g.h)
    return {"a": {"diameter_for_radius": g.v / g.d_w},
            "b": {"engine_sense_reversed": gyro(sign=-s), "diameter_for_radius": gyro(speed=g.v / g.d_w),
                  "one_wheel": gyro(wheels=g.I_w)},
            "c": {"kmh_not_converted": g.m * (KMH * g.v) ** 2 / g.R * g.h},
            "d": {"gyro_ignored": heel(0.0, centrifugal, g.m, g.h), "complement": math.pi / 2 - theta,
                  "engine_sense_reversed": heel(gyro(sign=-s), centrifugal, g.m, g.h)}}


def rail_car_limiting_speed(v):
    g = printed(v, "m", "I_a", "I_m", "G", "x", "r", "h", "R")
    s = 1.0 if v.param("motor").text == "same" else -1.0

    def limit(spin_inertia: float) -> float | None:
        """Each inner wheel (m g/4) loses (m v² h/R + Σ(IG) v²/(r R))/(2x): the speed where nothing is left."""
        per_v2 = g.m * g.h / g.R + spin_inertia / (g.r * g.R)
        return math.sqrt(g.m * G / 4 * 2 * g.x / per_v2) if per_v2 > 0 else None

    ratio = float(g.G)
    wrong = {"gyro_ignored": limit(0.0), "motors_ignored": limit(2 * g.I_a),
             ("gyro_added_where_it_relieves" if s < 0 else "gyro_subtracted_where_it_adds"):
                 limit(2 * g.I_a - s * 2 * ratio * g.I_m)}
    speed = limit(2 * g.I_a + s * 2 * ratio * g.I_m)             # the limiting speed itself

    def couple(spin_inertia: float) -> float:                   # |Σ(IG)| v²/(r R) at that speed
        return abs(spin_inertia) / (g.r * g.R) * speed ** 2

    return {"a": {k: value for k, value in wrong.items() if value is not None},
            "b": {"motors_ignored": couple(2 * g.I_a),
                  ("gyro_added_where_it_relieves" if s < 0 else "gyro_subtracted_where_it_adds"):
                      couple(2 * g.I_a - s * 2 * ratio * g.I_m)},
            "c": {"precession_reversed": other(v, "c")}}


# ---- chapter 7 ------------------------------------------------------------------------------------------


def fourbar_position(v):
    g = printed(v, "L1", "L2", "L3", "L4", "theta2", "circuit")
    circuit = int(g.circuit)
    bd = math.sqrt(g.L1 ** 2 + g.L2 ** 2 - 2 * g.L1 * g.L2 * math.cos(g.theta2))
    gamma = math.acos((g.L3 ** 2 + g.L4 ** 2 - bd ** 2) / (2 * g.L3 * g.L4))
    lengths = (g.L1, g.L2, g.L3, g.L4, g.theta2, gamma)
    theta3 = lk.coupler_angle(*lengths, circuit)
    theta4 = lk.rocker_angle(*lengths, circuit)
    return {"a": {"degrees_as_radians": math.sqrt(g.L1 ** 2 + g.L2 ** 2 - 2 * g.L1 * g.L2 * math.cos(math.degrees(g.theta2)))},
            "b": {"theta4_for_gamma": theta4, "supplement": math.pi - gamma},
            "c": {"wrong_circuit": lk.coupler_angle(*lengths, 3 - circuit), "radians_for_degrees": math.radians(theta3)},
            "d": {"wrong_circuit": lk.rocker_angle(*lengths, 3 - circuit), "gamma_for_theta4": gamma,
                  "radians_for_degrees": math.radians(theta4)}}


def coupler_point(v):
    g = printed(v, "xA", "yA", "L2", "L3", "L4", "theta2", "circuit", "CP", "BP", "side")
    b = complex(g.xA, g.yA) + g.L2 * cmath.exp(1j * g.theta2)       # D at the origin
    phi = math.acos((abs(b) ** 2 + g.L4 ** 2 - g.L3 ** 2) / (2 * g.L4 * abs(b)))
    turn = 1.0 if int(g.circuit) == 2 else -1.0
    alpha = math.acos((g.CP ** 2 + g.L3 ** 2 - g.BP ** 2) / (2 * g.CP * g.L3))
    right = g.side == "right"
    ground = math.atan2(-g.yA, -g.xA)                                  # the line A -> D

    def pose(rocker: float, p_right: bool):
        c = g.L4 * cmath.exp(1j * rocker)
        coupler = cmath.phase(c - b)
        return coupler, c + g.CP * cmath.exp(1j * (coupler + math.pi + (alpha if p_right else -alpha)))

    theta4 = cmath.phase(b) + turn * phi
    theta3, _ = pose(theta4, right)
    other4 = cmath.phase(b) - turn * phi
    other3, other_p = pose(other4, right)
    _, side_p = pose(theta4, not right)
    return {"a": {"wrong_circuit": other4, "relative_to_ground_line": theta4 - ground},
            "b": {"coupler_reversed": theta3 + math.pi, "relative_to_ground_line": theta3 - ground, "wrong_circuit": other3},
            "c": {"wrong_vertex": math.acos((g.BP ** 2 + g.L3 ** 2 - g.CP ** 2) / (2 * g.BP * g.L3))},  # the angle at B
            "d": {"wrong_circuit": other_p.real, "other_side": side_p.real},
            "e": {"wrong_circuit": other_p.imag, "other_side": side_p.imag}}


def fourbar_both_roots(v):
    g = printed(v, "xA", "yA", "L2", "L3", "L4", "theta2")
    drawn = 1.0 if str(v.param("circuit").exact) == "2" else -1.0    # the figure: +phi for circuit 2
    b = complex(g.xA, g.yA) + g.L2 * cmath.exp(1j * g.theta2)       # D at the origin
    bare = math.atan(b.imag / b.real)                                # tan^-1 without the half turn
    at_b = math.acos((abs(b) ** 2 + g.L3 ** 2 - g.L4 ** 2) / (2 * g.L3 * abs(b)))
    phi = math.acos((abs(b) ** 2 + g.L4 ** 2 - g.L3 ** 2) / (2 * g.L4 * abs(b)))
    out = {part: {"quadrant_lost": bare + sign * phi, "angle_at_b": cmath.phase(b) + sign * at_b}
           for part, sign in (("a", 1.0), ("b", -1.0))}
    out["c"] = {"wrong_circuit": "minus" if drawn > 0 else "plus"}
    theta3 = cmath.phase(g.L4 * cmath.exp(1j * (cmath.phase(b) + drawn * phi)) - b)
    other3 = cmath.phase(g.L4 * cmath.exp(1j * (cmath.phase(b) - drawn * phi)) - b)
    out["d"] = {"wrong_circuit": other3, "coupler_reversed": theta3 + math.pi}
    return out


def slider_crank_both_roots(v):
    """Worked from the loop R2 + R3 = R1 + R4 with A at the origin, by the slip each name says."""
    g = printed(v, "L1", "L2", "L3", "theta2")
    line = str(v.param("line").exact)
    vertical = line in ("right", "left")
    across = g.L1 * (1.0 if line in ("right", "above") else -1.0)
    drawn_first = str(v.param("assembly").exact) == "1"

    def both(offset):
        if vertical:
            r = (offset - g.L2 * math.cos(g.theta2)) / g.L3
            return (math.acos(r), -math.acos(r)) if abs(r) <= 1 else None
        r = (offset - g.L2 * math.sin(g.theta2)) / g.L3
        return (math.asin(r), math.pi - math.asin(r)) if abs(r) <= 1 else None

    def c_at(theta3):
        if vertical:
            return g.L2 * math.sin(g.theta2) + g.L3 * math.sin(theta3)
        return g.L2 * math.cos(g.theta2) + g.L3 * math.cos(theta3)

    first, second = both(across)
    out = {"a": {}, "b": {"other_function_rule": math.pi - first if vertical else -first},
           "c": {"wrong_circuit": "second" if drawn_first else "first"},
           "d": {"wrong_circuit": c_at(second if drawn_first else first)}}
    flipped = both(-across) if across else None
    if flipped:
        out["a"]["offset_sign"], out["b"]["offset_sign"] = flipped
        out["d"]["offset_sign"] = c_at(flipped[0] if drawn_first else flipped[1])
    return out


NAMES = ("AB", "BC", "CD", "DA")


def table_7_1(s_l: float, p_q: float, shortest: str) -> str:
    """Grashof's class from S + L against P + Q and the role of the shortest link."""
    if abs(s_l - p_q) <= 1e-9 * max(s_l, p_q):
        return "change-point"
    if s_l > p_q:
        return "triple-rocker"
    return {"ground": "double-crank", "coupler": "double-rocker"}.get(shortest, "crank-rocker")


def grashof(v):
    g = printed(v, *NAMES, "ground")
    lengths = {n: getattr(g, n) for n in NAMES}
    s, p, q, l = sorted(NAMES, key=lambda n: (lengths[n], NAMES.index(n)))
    at = NAMES.index(g.ground)
    in_order = [NAMES[(at + k) % 4] for k in range(4)]            # ground, crank, coupler, rocker
    ground, crank, coupler, rocker = (lengths[n] for n in in_order)
    shortest = ("ground", "crank", "coupler", "rocker")[in_order.index(s)]
    right = table_7_1(lengths[s] + lengths[l], lengths[p] + lengths[q], shortest)
    pairs = [(ground + crank, coupler + rocker), (coupler + rocker, ground + crank),
             (ground + coupler, crank + rocker), (crank + rocker, ground + coupler),
             (lengths[s] + lengths[p], lengths[l] + lengths[q])]     # links summed by position, or S with P
    wrong = next((k for k in (table_7_1(*pair, shortest) for pair in pairs) if k != right), None)
    out = {"a": {"wrong_pair": lengths[s] + lengths[p]}, "b": {"wrong_pair": lengths[l] + lengths[q]}, "c": {}}
    if wrong:
        out["c"]["wrong_pair"] = wrong
    if right in ("double-crank", "double-rocker", "crank-rocker"):
        out["c"]["ground_ignored"] = "double-crank" if right == "crank-rocker" else "crank-rocker"
    # a double-rocker is Grashof, but the link that turns fully is the coupler: a motor on the frame cannot drive it
    out["d"] = {"grashof_only": "motor"} if right == "double-rocker" else {}
    return out


def rocker_swing(v):
    g = printed(v, "L1", "L2", "L3", "L4")

    def at_d(reach: float) -> float:                             # the angle ADC in triangle ACD
        return math.acos((g.L1 ** 2 + g.L4 ** 2 - reach ** 2) / (2 * g.L1 * g.L4))

    extended, folded = at_d(g.L3 + g.L2), at_d(g.L3 - g.L2)
    swing = abs(extended - folded)
    return {"a": {"interior_angle": extended, "sum_and_difference_swapped": math.pi - folded},
            "b": {"interior_angle": folded, "sum_and_difference_swapped": math.pi - extended},
            "c": {"radians_for_degrees": math.radians(swing)}}


TOWARDS = {"right": (1.0, 0.0), "left": (-1.0, 0.0), "below": (0.0, -1.0), "above": (0.0, 1.0)}
BRANCH = {"right": "left", "left": "right", "below": "above", "above": "below"}


def slider_crank_mistakes(v):
    g = printed(v, "slider", "L2", "L3", "theta2", "xA", "yA", "tip", optional=("L1",))
    slide = "horizontal" if g.slider in ("right", "left") else "vertical"
    ux, uy = TOWARDS[g.slider]
    right = slider_crank(g.L2, g.L3, g.L1, g.theta2, slide, g.slider)
    wrong = slider_crank(g.L2, g.L3, g.L1, g.theta2, slide, BRANCH[g.slider])
    gamma = right.gamma                                           # the angle ABC

    def along(position) -> float:
        return position.c[0] * ux + position.c[1] * uy

    tip = (g.xA + wrong.c[0] + ux * g.tip) if slide == "horizontal" else (g.yA + wrong.c[1] + uy * g.tip)
    out = {"a": {"magnitude_only": right.theta3, "wrong_branch": wrong.direction},
           "b": {"wrong_branch": along(wrong)}, "c": {"supplement": math.pi - gamma},
           "d" if slide == "horizontal" else "e": {"wrong_branch": tip}}
    if g.L1 > 0:
        inline = slider_crank(g.L2, g.L3, 0.0, g.theta2, slide, g.slider)
        out["a"]["offset_ignored"] = inline.direction
        out["b"]["offset_ignored"] = along(inline)
    return out


def actuator_swing(v):
    g = printed(v, "xO", "yO", "r", "s1", "s2", "side")
    to_o = math.atan2(g.yO, g.xO)
    ao = math.hypot(g.xO, g.yO)
    turn = 1.0 if g.side == "left" else -1.0
    out = {}
    angles = []
    for part, length in (("a", g.s1), ("b", g.s2)):
        angle = math.acos((ao ** 2 + g.r ** 2 - length ** 2) / (2 * ao * g.r))    # OAB, by the cosine law
        angles.append(angle)
        out[part] = {"other_side": to_o - turn * angle, "interior_angle": angle}
    out["c"] = {"radians_for_degrees": math.radians(abs(angles[0] - angles[1]))}
    out["d"] = {"opposite": other(v, "d")}
    return out


def two_position_synthesis(v):
    g = printed(v, "b", "xM1", "yM1", "phi1", "xM2", "yM2", "phi2")
    points = {"M": [(g.xM1, g.yM1), (g.xM2, g.yM2)]}
    points["N"] = [(x + g.b * math.cos(phi), y + g.b * math.sin(phi)) for (x, y), phi in zip(points["M"], (g.phi1, g.phi2))]
    out, lengths, pivots = {}, {}, {}
    for (xo, r), name in ((("a", "b"), "M"), (("c", "d"), "N")):
        (x1, y1), (x2, y2) = points[name]
        pivot = (x2 ** 2 + y2 ** 2 - x1 ** 2 - y1 ** 2) / (2 * (x2 - x1))    # on y = 0, as far from both
        pivots[name], lengths[name] = pivot, math.hypot(x1 - pivot, y1)
        mid = (x1 + x2) / 2
        out[xo], out[r] = {"midpoint": mid}, {"midpoint": math.hypot(x1 - mid, y1)}
    roles = {"ground": abs(pivots["N"] - pivots["M"]), "crank": lengths["M"], "coupler": g.b, "rocker": lengths["N"]}
    s, p, q, l = sorted(roles.values())
    shortest = min(roles, key=roles.get)
    wrong = table_7_1(s + p, l + q, shortest)                      # S with P against L with Q
    out["e"] = {"wrong_pair": wrong} if wrong != v.answers["e"].value else {}
    return out


def three_position_synthesis(v):
    g = printed(v, "b", "xM1", "yM1", "phi1", "xM2", "yM2", "phi2", "xM3", "yM3", "phi3")
    m = [(g.xM1, g.yM1), (g.xM2, g.yM2), (g.xM3, g.yM3)]
    n = [(x + g.b * math.cos(phi), y + g.b * math.sin(phi)) for (x, y), phi in zip(m, (g.phi1, g.phi2, g.phi3))]
    out, good = {}, {}
    for (xo, yo, r), name, trio in ((("a", "b", "c"), "M", m), (("d", "e", None), "N", n)):
        centroid = (sum(p[0] for p in trio) / 3, sum(p[1] for p in trio) / 3)
        out[xo], out[yo] = {"centroid": centroid[0]}, {"centroid": centroid[1]}
        if r:
            out[r] = {"centroid": math.dist(trio[0], centroid)}
        # the circumcentre from |q - p1|² = |q - p2|² = |q - p3|²: two linear equations, by elimination
        (x1, y1), (x2, y2), (x3, y3) = trio
        a1, b1, c1 = x2 - x1, y2 - y1, (x2 ** 2 + y2 ** 2 - x1 ** 2 - y1 ** 2) / 2
        a2, b2, c2 = x3 - x1, y3 - y1, (x3 ** 2 + y3 ** 2 - x1 ** 2 - y1 ** 2) / 2
        good[name] = (a1 * c2 - a2 * c1) / (a1 * b2 - a2 * b1) > 0      # y of the pivot above the floor
    reversed_test = {(True, True): "neither", (False, False): "both", (True, False): "N only", (False, True): "M only"}
    out["f"] = {"floor_test_reversed": reversed_test[(good["M"], good["N"])]}
    return out


def mobility_exceptions(v):
    """From the drawing's cranks: L = cranks + coupler + ground, two pins a crank; parallel cranks move."""
    case = str(v.param("case").exact)
    cranks = {"four-bar": 2, "four cranks": 4}.get(case, 3)
    links, pins = cranks + 2, 2 * cranks
    gruebler = 3 * (links - 1) - 2 * pins
    moves = not case.endswith("askew")
    out = {"a": {"ground_not_counted": links - 1}, "b": {},
           "c": {"ground_not_counted": 3 * (links - 2) - 2 * pins, "without_minus_one": 3 * links - 2 * pins},
           "d": {}, "e": {}}
    if moves and gruebler != 1:
        out["d"]["gruebler_trusted"] = gruebler
        out["e"]["gruebler_trusted"] = "structure"
    return out


def mobility(v):
    """The counts from the drawn mechanism (its figure is the sheet's data), by Gruebler's equation."""
    mech = build(*(v.param(n).text for n in ("base",)), tuple(v.param(n).text for n in ("add1", "add2", "add3")),
                 v.param("mirror").text == "yes")
    links, j1, j2 = mech.link_count, mech.lower_pairs, mech.higher_pairs

    def gruebler(l, lower, higher):
        return 3 * (l - 1) - 2 * lower - higher

    out = {"a": {"ground_not_counted": links - 1}, "b": {}, "c": {},
           "d": {"ground_not_counted": gruebler(links - 1, j1, j2), "without_minus_one": 3 * links - 2 * j1 - j2}}
    if mech.shared_extra:
        out["b"]["shared_joint_counted_once"] = j1 - mech.shared_extra
        out["d"]["shared_joint_counted_once"] = gruebler(links, j1 - mech.shared_extra, j2)
    if j2:
        out["b"]["higher_pair_as_lower"], out["c"]["higher_pair_as_lower"] = j1 + j2, 0
        out["d"]["higher_pair_as_lower"] = gruebler(links, j1 + j2, 0)
    if mech.sliders:
        out["b"]["slider_not_counted"] = j1 - len(mech.sliders)
        out["d"]["slider_not_counted"] = gruebler(links, j1 - len(mech.sliders), j2)
    return out


# ---- linkages measured off their drawings: the lengths read back off the SVG (tests/figure_readings.py), then
# the positions by intersecting circles, a method of this file's own


def _circles_meet(p: complex, r: float, q: complex, s: float) -> tuple[complex, complex]:
    """The two points r from p and s from q: the one on the left of p -> q first."""
    gap = abs(q - p)
    along = (r * r - s * s + gap * gap) / (2 * gap)
    across = math.sqrt(max(r * r - along * along, 0.0))
    u = (q - p) / gap
    return p + along * u + 1j * u * across, p + along * u - 1j * u * across


def suspension_read_worked(v):
    """§7.9's suspension from its lengths as read, at the crank angle asked: C where the coupler's and the
    rocker's circles meet on the side of B -> D the figure draws it, P where BP's and CP's circles meet on its
    side of B -> C. Answers and slips."""
    r = figure_readings.suspension_reading(v)
    g = printed(v, "yA", "theta2")
    b = complex(0.0, g.yA) + r["AB"] * cmath.exp(1j * g.theta2)
    left, right = _circles_meet(b, r["BC"], 0j, r["DC"])
    c, c_other = (left, right) if r["C_left_of_BD"] else (right, left)

    def plate(pin: complex, same_side: bool = True) -> complex:
        on_left, on_right = _circles_meet(b, r["BP"], pin, r["CP"])
        return on_left if r["P_left_of_BC"] == same_side else on_right

    p, theta4, theta3 = plate(c), cmath.phase(c), cmath.phase(c - b)
    down = -math.pi / 2                                              # the ground line A -> D
    answers = {"a": r["AB"], "b": r["BC"], "c": r["DC"], "d": r["CP"], "e": r["BP"], "f": theta4, "g": theta3,
               "h": abs(cmath.phase((p - c) / (b - c))), "i": p.real, "j": p.imag}
    other_p, side_p = plate(c_other), plate(c, same_side=False)
    mistakes = {"f": {"wrong_circuit": cmath.phase(c_other), "relative_to_ground_line": theta4 - down},
                "g": {"coupler_reversed": theta3 + math.pi, "relative_to_ground_line": theta3 - down,
                      "wrong_circuit": cmath.phase(c_other - b)},
                "h": {"wrong_vertex": abs(cmath.phase((p - b) / (c - b)))},           # the plate's angle at B
                "i": {"wrong_circuit": other_p.real, "other_side": side_p.real},
                "j": {"wrong_circuit": other_p.imag, "other_side": side_p.imag}}
    return answers, mistakes


def slider_crank_read_worked(v):
    """Problem 7.1's slider-crank from its lengths as read, the crank turned: C where the coupler's circle
    about B meets the line of slide, on the slider's side. Answers and slips."""
    r = figure_readings.slider_crank_reading(v)
    g = printed(v, "L3", "drawn", "turn", "sense", "slider")
    sign = 1.0 if g.sense == "counter-clockwise" else -1.0
    theta2 = g.drawn + sign * g.turn
    b = r["AB"] * cmath.exp(1j * theta2)
    way = 1.0 if g.slider == "right" else -1.0

    def slider(offset: float, toward: float) -> complex:
        return complex(b.real + toward * math.sqrt(g.L3 ** 2 - (offset + b.imag) ** 2), -offset)

    c, behind, inline = slider(r["offset"], way), slider(r["offset"], -way), slider(0.0, way)
    answers = {"a": r["AB"], "b": r["offset"], "c": r["CP"], "d": theta2, "e": cmath.phase(c - b),
               "f": way * c.real, "g": c.real + way * r["CP"]}
    mistakes = {"d": {"turned_other_way": g.drawn - sign * g.turn},
                "e": {"magnitude_only": math.asin((r["offset"] + b.imag) / g.L3), "wrong_branch": cmath.phase(behind - b),
                      "offset_ignored": cmath.phase(inline - b)},
                "f": {"wrong_branch": way * behind.real, "offset_ignored": way * inline.real},
                "g": {"wrong_branch": behind.real + way * r["CP"]}}
    return answers, mistakes


@pytest.mark.parametrize("template_id, worked", [("linkages.coupler_point_reading", suspension_read_worked),
                                                 ("linkages.slider_crank_reading", slider_crank_read_worked)])
def test_a_linkage_measured_off_its_drawing_gives_the_key_s_answers(bank, template_id, worked):
    check_answers(bank, template_id, worked)


MISTAKES = {
    "gyroscopes.vehicle_rotor_springs": vehicle_rotor_springs, "gyroscopes.rotor_bearing_reactions": rotor_bearing_reactions,
    "gyroscopes.aircraft_turning": aircraft_turning, "gyroscopes.ship_turbine": ship_turbine,
    "gyroscopes.car_wheel_reactions": car_wheel_reactions, "gyroscopes.motorcycle_banking": motorcycle_banking,
    "gyroscopes.motorcycle_heel": motorcycle_heel, "gyroscopes.rail_car_limiting_speed": rail_car_limiting_speed,
    "linkages.fourbar_position": fourbar_position, "linkages.coupler_point": coupler_point, "linkages.grashof": grashof,
    "linkages.rocker_swing": rocker_swing, "linkages.slider_crank": slider_crank_mistakes,
    "linkages.actuator_swing": actuator_swing, "linkages.two_position_synthesis": two_position_synthesis,
    "linkages.three_position_synthesis": three_position_synthesis,
    "linkages.fourbar_both_roots": fourbar_both_roots, "linkages.slider_crank_both_roots": slider_crank_both_roots,
    "linkages.mobility_exceptions": mobility_exceptions,
    "linkages.mobility": mobility,
    "linkages.coupler_point_reading": lambda v: suspension_read_worked(v)[1],
    "linkages.slider_crank_reading": lambda v: slider_crank_read_worked(v)[1],
}


def test_every_chapter_5_and_7_template_has_its_mistakes_worked(bank):
    assert sorted(t.id for t in bank if t.chapter in (5, 7)) == sorted(MISTAKES)


@pytest.mark.parametrize("template_id", sorted(MISTAKES))
def test_every_named_mistake_has_the_value_its_slip_gives(bank, template_id):
    check_mistakes(bank, template_id, MISTAKES[template_id])
