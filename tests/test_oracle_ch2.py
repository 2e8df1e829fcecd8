"""Every chapter 2 answer and named mistake, recomputed over drawn variants by an oracle of its own from what
the sheet prints.

The oracle reads each given as printed, works the course text's method with no code from exgen's mechanics
or solvers, and compares each answer, and each mistake's value wherever the key records it, to 1e-9 (a
direction modulo a turn). It works with complex numbers where the solvers resolve components: a mass m at
radius r and angle θ is m r e^{iθ}, a plane's moment m r l e^{iθ}, a correction the number that makes the
sum vanish, and two unknown sizes on known directions come from the imaginary parts of the sum turned
onto each direction. An engine's cranks are e^{iθ} (primary) and e^{2iθ} (secondary).
"""
from __future__ import annotations

import cmath
import math

import pytest

import figure_readings
from sheet_values import check_answers, check_mistakes, printed

PI = math.pi
RPM = 2 * PI / 60
ZERO = 1e-9     # a sum below this fraction of its terms' sizes is float noise: exactly zero
TIED = 0.5      # N or N·m: an engine's force or couple this small is balanced


def e(angle: float) -> complex:
    return cmath.exp(1j * angle)


def polar(z: complex) -> tuple[float, float]:
    return abs(z), cmath.phase(z) % (2 * PI)


def closing(z: complex, divisor: float = 1.0) -> tuple[float, float]:
    """The vector that cancels z, its size divided by `divisor` (a radius, a distance)."""
    size, angle = polar(-z)
    return size / divisor, angle


def turned(value: tuple[float, float], turn: float = PI) -> tuple[float, float]:
    return value[0], value[1] + turn


def sized(value: tuple[float, float], factor: float) -> tuple[float, float]:
    return value[0] * factor, value[1]


def clean(z: complex, scale: float) -> complex:
    return complex(0.0 if abs(z.real) <= ZERO * scale else z.real, 0.0 if abs(z.imag) <= ZERO * scale else z.imag)


# ---- rotating masses (§2.1-2.2) ------------------------------------------------------------------------


def static_balance(v):
    g = printed(v, "m1", "r1", "m2", "r2", "theta2", "m3", "r3", "theta3", "b")
    masses = [(g.m1 * g.r1, 0.0), (g.m2 * g.r2, g.theta2), (g.m3 * g.r3, g.theta3)]
    balance = closing(sum(mr * e(a) for mr, a in masses))
    scalar = sum(mr for mr, _ in masses)
    answers = {"a": balance, "b": balance[0] / g.b}
    mistakes = {"a": {"scalar_sum": (scalar, balance[1]), "resultant_not_balance": turned(balance)},
                "b": {"scalar_sum": scalar / g.b,
                      "eccentricity_ignored": abs(g.m1 + g.m2 * e(g.theta2) + g.m3 * e(g.theta3))}}  # m, not m·r
    return answers, mistakes


def two_plane_balance(v):
    g = printed(v, *(f"{k}{i}" for i in (1, 2, 3) for k in ("m", "r", "theta", "z")), "zP", "zQ", "rP", "rQ")
    rows = [(getattr(g, f"m{i}") * getattr(g, f"r{i}"), getattr(g, f"z{i}") - g.zP, getattr(g, f"theta{i}"))
            for i in (1, 2, 3)]
    l_q = g.zQ - g.zP
    assert l_q > 0

    def corrections(distance):
        q = closing(sum(mr * distance(l) * e(a) for mr, l, a in rows), g.rQ * l_q)       # moments about P
        p = closing(sum(mr * e(a) for mr, _, a in rows) + q[0] * g.rQ * e(q[1]), g.rP)   # then forces
        return q, p

    q, p = corrections(lambda l: l)
    q_lost, p_lost = corrections(abs)
    answers = {"a": q, "b": p}
    mistakes = {"a": {"sign_lost": q_lost, "resultant_not_balance": turned(q)},
                "b": {"q_correction_left_out": closing(sum(mr * e(a) for mr, _, a in rows), g.rP),
                      "sign_lost": p_lost, "resultant_not_balance": turned(p)}}
    return answers, mistakes


def complete_balance_position(v):
    g = printed(v, "mA", "rA", "thetaA", "rB", "mC", "rC", "mD", "rD", "lAB", "lBC")
    a, c = g.mA * g.rA * e(g.thetaA), g.mC * g.rC          # C's radius is the 0° line
    mr_d = g.mD * g.rD

    def plane_d(l_a: float):
        moment = -(a * l_a + c * g.lBC)                     # D's moment closes the polygon about B
        return abs(moment) / mr_d, cmath.phase(moment) % (2 * PI)

    l_d, theta_d = plane_d(-g.lAB)
    b = closing(a + c + mr_d * e(theta_d), g.rB)
    l_signless, theta_signless = plane_d(g.lAB)
    b_signless = closing(a + c + mr_d * e(theta_signless), g.rB)
    without_d = closing(a + c, g.rB)
    answers = {"a": l_d - g.lBC, "b": theta_d, "c": b[1], "d": b[0]}
    mistakes = {"a": {"sign_lost": l_signless - g.lBC, "distance_from_reference": l_d},
                "b": {"sign_lost": theta_signless, "resultant_not_balance": theta_d + PI},
                "c": {"d_left_out": without_d[1], "sign_lost": b_signless[1], "resultant_not_balance": b[1] + PI},
                "d": {"d_left_out": without_d[0], "sign_lost": b_signless[0]}}
    return answers, mistakes


def complete_balance_masses(v):
    g = printed(v, "mB", "mC", "rBC", "rAD", "thetaC", "thetaA", "lAB", "lBC")
    moment = -(g.mB * g.rBC * g.lAB + g.mC * g.rBC * (g.lAB + g.lBC) * e(g.thetaC))   # D's, about A
    mrl_d, theta_d = abs(moment), cmath.phase(moment) % (2 * PI)
    rest = -(g.mB * g.rBC + g.mC * g.rBC * e(g.thetaC))     # what A and D must supply together

    def along(total: complex, this: float, other: float) -> float:
        """The size along `this` of the split total = s ∠this + s' ∠other: turned onto `other`, s' drops out."""
        return (total * e(-other)).imag / math.sin(this - other)

    m_a = along(rest, g.thetaA, theta_d) / g.rAD
    m_d = along(rest, theta_d, g.thetaA) / g.rAD
    l_d = mrl_d / (m_d * g.rAD)
    same = g.rAD / g.rBC                                     # the masses, their eccentricities taken as one
    answers = {"a": theta_d, "b": m_d, "c": m_a, "d": l_d}
    mistakes = {"a": {"resultant_not_balance": theta_d + PI}, "b": {"eccentricity_ignored": m_d * same},
                "c": {"eccentricity_ignored": m_a * same},
                "d": {"eccentricity_ignored": mrl_d / (m_d * g.rBC)}}  # D's moment over B and C's eccentricity
    return answers, mistakes


def correction_plane_position(v):
    g = printed(v, *(f"{k}{i}" for i in (1, 2, 3) for k in ("m", "r", "theta", "z")), "B1", "b1", "bX")
    rows = [(getattr(g, f"m{i}") * getattr(g, f"r{i}"), getattr(g, f"z{i}"), getattr(g, f"theta{i}")) for i in (1, 2, 3)]
    moment = sum(mr * z * e(a) for mr, z, a in rows)         # about X
    x, theta_q = closing(moment, g.B1 * g.b1)
    forces = sum(mr * e(a) for mr, _, a in rows)
    in_x = closing(forces + g.B1 * g.b1 * e(theta_q), g.bX)
    answers = {"a": theta_q, "b": x, "c": in_x}
    mistakes = {"a": {"resultant_not_balance": theta_q + PI}, "b": {"radius_forgotten": abs(moment) / g.B1},
                "c": {"q_correction_left_out": closing(forces, g.bX), "resultant_not_balance": turned(in_x)}}
    return answers, mistakes


def bearing_reactions(v):
    g = printed(v, "mA", "rA", "mB", "rB", "thetaB", "mC", "rC", "thetaC", "a", "b", "c", "e", "N")
    masses = [(g.mA * g.rA, 0.0), (g.mB * g.rB, g.thetaB), (g.mC * g.rC, g.thetaC)]
    l_y = g.b + g.c

    def reactions(l_a: float):
        """(Y's, X's) dynamic force on the bearing, opposite the m·r that would balance it there."""
        places = (l_a, g.b, g.b + g.c + g.e)
        in_y = closing(sum(mr * l * e(a) for (mr, a), l in zip(masses, places)), l_y)
        in_x = closing(sum(mr * e(a) for mr, a in masses) + in_y[0] * e(in_y[1]))
        return [turned(sized(r, g.N ** 2)) for r in (in_y, in_x)]

    y, x = reactions(-g.a)
    y_lost, x_lost = reactions(g.a)
    as_rpm = (g.N / RPM / g.N) ** 2
    answers = {"a": y, "b": x}
    mistakes = {}
    for part, right, other, lost in (("a", y, x, y_lost), ("b", x, y, x_lost)):
        mistakes[part] = {"balance_direction": turned(right), "sign_lost": lost, "bearings_swapped": other,
                          "rpm_as_rad_s": sized(right, as_rpm), "mm_for_m": sized(right, 1000)}
    mistakes["b"]["reaction_left_out"] = turned(sized(closing(sum(mr * e(a) for mr, a in masses)), g.N ** 2))
    return answers, mistakes


def balance_kind(v):
    """Σ m r and Σ m r l about plane A; both closed is dynamic balance, the first alone static."""
    g = printed(v, "m", "mD", "r", "a", "arrangement")
    angles = [math.radians(float(a)) for a in g.arrangement.split(",")]
    mr = [g.m * g.r] * 3 + [g.mD * g.r]
    force = clean(sum(s * e(t) for s, t in zip(mr, angles)), sum(mr))
    couple = clean(sum(s * k * g.a * e(t) for k, (s, t) in enumerate(zip(mr, angles))), 6 * g.a * max(mr))
    verdict = "neither" if force else "static only" if couple else "both"
    mistakes = {"a": {"scalar_sum": sum(mr)}, "b": {"scalar_sum": sum(s * k * g.a for k, s in enumerate(mr))}, "c": {}}
    if verdict == "static only":
        mistakes["c"]["static_is_enough"] = "both"
    return {"a": abs(force), "b": abs(couple), "c": verdict}, mistakes


# ---- reciprocating engines (§2.3) ----------------------------------------------------------------------


def engine_sums(angles, positions, harmonic: int):
    """(|Σ e^{ikθ}|, Σ x e^{ikθ}): the force in units of one crank's, and the couple's vector."""
    force = clean(sum(e(harmonic * a) for a in angles), len(angles))
    couple = clean(sum(x * e(harmonic * a) for x, a in zip(positions, angles)), sum(map(abs, positions)))
    return abs(force), couple


def centred(count: int, pitch: float) -> list[float]:
    return [(i - (count - 1) / 2) * pitch for i in range(count)]


def inline_forces(g, angles, positions, r: float):
    """Fp, Cp (with its vector), Fs, Cs of an in-line engine, and the primary and secondary crank forces."""
    primary = g.m * r * g.N ** 2
    secondary = primary / (g.l / r)
    fp, cp = engine_sums(angles, positions, 1)
    fs, cs = engine_sums(angles, positions, 2)
    return {"Fp": primary * fp, "Cp": primary * abs(cp), "Fs": secondary * fs, "Cs": secondary * abs(cs),
            "cp": primary * cp, "primary": primary, "secondary": secondary}


def inline_engine_unbalance(v):
    g = printed(v, "theta1", "theta2", "theta3", "theta4", "m", "r", "l", "a", "N")
    angles = [g.theta1, g.theta2, g.theta3, g.theta4]
    positions = centred(4, g.a)
    f = inline_forces(g, angles, positions, g.r)
    n = g.l / g.r
    couple = closing(f["cp"])
    lost = inline_forces(g, angles, [abs(x) for x in positions], g.r)
    as_rpm = (1 / RPM) ** 2
    answers = {"a": f["Fp"], "b": couple, "c": f["Fs"], "d": f["Cs"]}
    mistakes = {"a": {"scalar_sum": 4 * f["primary"]},
                "b": {"sign_lost": closing(lost["cp"]), "rpm_as_rad_s": sized(couple, as_rpm),
                      "resultant_not_balance": turned(couple)},
                "c": {"scalar_sum": 4 * f["secondary"]},
                "d": {"secondary_not_doubled": f["Cp"] / n, "sign_lost": lost["Cs"], "n_inverted": f["Cs"] * n * n,
                      "rpm_as_rad_s": f["Cs"] * as_rpm}}
    return answers, mistakes


def inline_engine_directions(v):
    """Every polygon open: each size with the direction that closes it, and the slips on both."""
    g = printed(v, "theta1", "theta2", "theta3", "theta4", "m", "r", "l", "a", "N")
    return _directions(g, [g.theta1, g.theta2, g.theta3, g.theta4])


def inline_engine_angles_read(v):
    """The same with the crank angles read off the end view's degree scale: each angle read is an answer
    (slips: read against the rotation, or from the crank before), then the polygons from those angles."""
    g = printed(v, "m", "r", "l", "a", "N")
    angles = figure_readings.crank_angles(v)
    answers, mistakes = _directions(g, angles)
    answers = {chr(ord(part) + 3): value for part, value in answers.items()}
    mistakes = {chr(ord(part) + 3): value for part, value in mistakes.items()}
    for part, i in zip("abc", (1, 2, 3)):
        answers[part] = angles[i]
        mistakes[part] = {"against_rotation": 2 * PI - angles[i], "angle_between_cranks": (angles[i] - angles[i - 1]) % (2 * PI)}
    return answers, mistakes


def _directions(g, angles):
    x = centred(4, g.a)
    n = g.l / g.r
    primary = g.m * g.r * g.N ** 2
    as_rpm = (1 / RPM) ** 2

    def vectors(positions, harmonic: int):
        """(force vector, couple vector) of the cranks at harmonic × θ, with distances `positions`."""
        size = primary / (n if harmonic == 2 else 1)
        return (clean(size * sum(e(harmonic * a) for a in angles), 4 * size),
                clean(size * sum(p * e(harmonic * a) for p, a in zip(positions, angles)),
                      size * sum(map(abs, positions))))

    right = {1: vectors(x, 1), 2: vectors(x, 2)}
    end = {h: vectors([p - x[0] for p in x], h)[1] for h in (1, 2)}
    lost = {h: vectors([abs(p) for p in x], h)[1] for h in (1, 2)}
    undoubled = vectors(x, 1)
    answers, mistakes = {}, {}
    for part, harmonic, which in (("a", 1, 0), ("b", 1, 1), ("c", 2, 0), ("d", 2, 1)):
        balance = closing(right[harmonic][which])
        answers[part] = balance
        wrong = {"resultant_not_balance": turned(balance), "rpm_as_rad_s": sized(balance, as_rpm)}
        if which == 0:
            wrong["scalar_sum"] = (4 * primary / (n if harmonic == 2 else 1), balance[1])
        else:
            wrong["couple_about_end_plane"] = closing(end[harmonic])
            wrong["sign_lost"] = closing(lost[harmonic])
        if harmonic == 2:
            wrong["n_inverted"] = sized(balance, n * n)
            wrong["secondary_not_doubled"] = closing(undoubled[which] / n)
        mistakes[part] = wrong
    return answers, mistakes


def inline_engine_firing(v):
    g = printed(v, "firing", "strokes", "m", "r", "l", "a", "N")
    order = [int(c) for c in g.firing.split("-")]
    strokes = int(g.strokes)

    def cranks(stroke: int) -> list[float]:
        """Cylinder i's crank angle: cranks follow the firing order at 180° × strokes / N intervals."""
        return [order.index(i + 1) * stroke * PI / len(order) for i in range(len(order))]

    positions = centred(len(order), g.a)
    f = inline_forces(g, cranks(strokes), positions, g.r)
    other = inline_forces(g, cranks(6 - strokes), positions, g.r)
    n = g.l / g.r
    balanced = all(f[k] <= TIED for k in ("Fp", "Cp", "Fs", "Cs"))
    as_rpm = (1 / RPM) ** 2
    answers = {"a": f["Cp"], "b": f["Fs"], "c": f["Cs"], "d": "balanced" if balanced else "not balanced"}
    mistakes = {"a": {"interval_wrong": other["Cp"], "rpm_as_rad_s": f["Cp"] * as_rpm},
                "b": {"secondary_not_doubled": f["Fp"] / n, "interval_wrong": other["Fs"], "n_inverted": f["Fs"] * n * n,
                      "rpm_as_rad_s": f["Fs"] * as_rpm},
                "c": {"secondary_not_doubled": f["Cp"] / n, "n_inverted": f["Cs"] * n * n, "rpm_as_rad_s": f["Cs"] * as_rpm},
                "d": {"secondary_ignored": "balanced"}}
    return answers, mistakes


def inline_primary_balance(v):
    g = printed(v, "m_out", "phi", "lAB", "lBC", "lCD", "r", "l", "N")
    a, d = g.m_out, g.m_out * e(g.phi)                       # A's crank is the 0° line

    def balance(l_a: float):
        c = closing(a * l_a + d * (g.lBC + g.lCD), g.lBC)   # C's mass closes the moments about B
        b = closing(a + d + c[0] * e(c[1]))
        return c, b

    c, b = balance(-g.lAB)
    c_lost, b_lost = balance(g.lAB)
    per_mass = g.r * g.N ** 2 / (g.l / g.r)                  # r ω²/n
    masses = [(g.m_out, 0.0), (b[0], b[1]), (c[0], c[1]), (g.m_out, g.phi)]
    secondary = closing(sum(m * per_mass * e(2 * t) for m, t in masses))
    n = g.l / g.r
    resultant = sum(m * per_mass * e(2 * t) for m, t in masses)
    # the force along the stroke at crank angle x is Re(resultant e^(2jx)): largest first where 2x + arg = k pi
    peak = ((-cmath.phase(resultant)) % PI) / 2
    answers = {"a": c, "b": b, "c": secondary, "d": peak}
    mistakes = {"a": {"sign_lost": c_lost, "resultant_not_balance": turned(c)},
                "b": {"sign_lost": b_lost, "resultant_not_balance": turned(b)},
                "c": {"secondary_not_doubled": closing(clean(sum(m * per_mass * e(t) for m, t in masses),
                                                             sum(m * per_mass for m, _ in masses))),
                      "n_inverted": sized(secondary, n * n), "rpm_as_rad_s": sized(secondary, (1 / RPM) ** 2),
                      "resultant_direction": turned(secondary)},
                "d": {"secondary_not_halved": 2 * peak}}
    return answers, mistakes


def direct_reverse(g, lines, radius: float) -> dict:
    """The four resultants of direct and reverse cranks, cylinders on `lines`, the crank at θ = 0: each
    primary crank carries m/2 at r and ω, each secondary m/2 at r/4n and 2ω."""
    n = g.l / radius
    primary = g.m / 2 * radius * g.N ** 2
    secondary = g.m / 2 * (radius / (4 * n)) * (2 * g.N) ** 2
    count = len(lines)

    def resultant(turns):
        return abs(clean(sum(e(t) for t in turns), count))

    return {"P_dir": primary * resultant([0.0] * count), "P_rev": primary * resultant([2 * a for a in lines]),
            "S_dir": secondary * resultant([-a for a in lines]), "S_rev": secondary * resultant([3 * a for a in lines]),
            "primary": primary, "n": n}


def radial_engine(v):
    g = printed(v, "ncyl", "S", "l", "m", "N")
    count = int(g.ncyl)
    lines = [2 * PI * i / count for i in range(count)]
    f = direct_reverse(g, lines, g.S / 2)
    stroke = direct_reverse(g, lines, g.S)                   # the stroke taken for the crank radius
    s_max = f["S_dir"] + f["S_rev"]
    as_rpm = (1 / RPM) ** 2
    answers = {"a": f["P_dir"], "b": count * g.m * g.S / 4, "c": s_max,
               "d": "balanced" if s_max <= TIED else "not balanced",
               # the direct cranks, m/2 each at r, all at the crank: (N/2) m r w^2 as a formula
               "e": lambda m, r, omega: count * m / 2 * r * omega ** 2}
    mistakes = {"a": {"stroke_for_radius": stroke["P_dir"], "rpm_as_rad_s": f["P_dir"] * as_rpm},
                "b": {"stroke_for_radius": count * g.m * g.S / 2},
                "c": {"secondary_speed_not_doubled": s_max / 4, "n_inverted": s_max * f["n"] ** 2,
                      "stroke_for_radius": stroke["S_dir"] + stroke["S_rev"], "rpm_as_rad_s": s_max * as_rpm},
                "e": {"full_mass_on_direct_crank": lambda m, r, omega: count * m * r * omega ** 2}}
    return answers, mistakes


def v_engine(v):
    g = printed(v, "V", "S", "l", "m", "N")
    lines = [g.V / 2, -g.V / 2]
    f = direct_reverse(g, lines, g.S / 2)
    stroke = direct_reverse(g, lines, g.S)
    as_rpm = (1 / RPM) ** 2
    keys = ("P_dir", "P_rev", "S_dir", "S_rev")
    answers = dict(zip("abcd", (f[k] for k in keys)))
    swapped = {"P_dir": "P_rev", "P_rev": "P_dir", "S_dir": "S_rev", "S_rev": "S_dir"}
    mistakes = {}
    for part, key in zip("abcd", keys):
        wrong = {"stroke_for_radius": stroke[key], "rpm_as_rad_s": f[key] * as_rpm, "direct_reverse_swapped": f[swapped[key]]}
        if key.startswith("S"):
            wrong.update(n_inverted=f[key] * f["n"] ** 2, secondary_speed_not_doubled=f[key] / 4)
        mistakes[part] = wrong
    mistakes["b"]["angle_not_doubled"] = abs(e(g.V / 2) + e(-g.V / 2)) * f["primary"]   # reverse cranks at ±α, not ±2α
    return answers, mistakes


ORACLES = {
    "balancing.static_balance": static_balance, "balancing.balance_kind": balance_kind, "balancing.two_plane_balance": two_plane_balance,
    "balancing.complete_balance_position": complete_balance_position,
    "balancing.complete_balance_masses": complete_balance_masses,
    "balancing.correction_plane_position": correction_plane_position,
    "balancing.bearing_reactions": bearing_reactions, "balancing.inline_engine_unbalance": inline_engine_unbalance,
    "balancing.inline_engine_firing": inline_engine_firing,
    "balancing.inline_engine_directions": inline_engine_directions,
    "balancing.inline_engine_angles_read": inline_engine_angles_read, "balancing.inline_primary_balance": inline_primary_balance,
    "balancing.radial_engine": radial_engine, "balancing.v_engine": v_engine,
}


def test_every_chapter_2_template_has_an_oracle(bank):
    assert sorted(t.id for t in bank if t.chapter == 2) == sorted(ORACLES)


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_the_key_agrees_with_the_oracle_from_the_printed_data(bank, template_id):
    check_answers(bank, template_id, ORACLES[template_id])


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_every_named_mistake_has_the_value_the_oracle_works_out(bank, template_id):
    check_mistakes(bank, template_id, lambda variant: ORACLES[template_id](variant)[1])
