"""Every chapter 6 answer and named mistake, recomputed over drawn variants by an oracle of its own from what
the sheet prints.

The oracle reads each given as printed, works the course text's method with no code from exgen's mechanics
or solvers, and compares each answer, and each mistake's value wherever the key records it, to 1e-9. Its
methods differ from the solvers' where they can: every undamped system by its energies (ω² is the potential
energy's coefficient over the kinetic's for one coordinate), a stepped shaft by adding the steps' twist per
unit torque, a decrement's damping ratio by solving δ = 2πζ/√(1 − ζ²) for ζ by bisection.
"""
from __future__ import annotations

import math

import pytest

from sheet_values import G, check_answers, check_mistakes, printed

TWO_PI = 2 * math.pi


def omega(stiffness: float, mass: float) -> float:
    """From the energies ½ K' x² and ½ m' ẋ² (or ½ q θ² and ½ I θ̇²): ω² = K'/m'."""
    return math.sqrt(stiffness / mass)


def hz(w: float) -> float:
    return w / TWO_PI


def zeta_of(delta: float) -> float:
    """ζ with 2πζ/√(1 − ζ²) = δ, by bisection on [0, 1)."""
    low, high = 0.0, 1.0
    for _ in range(200):
        mid = (low + high) / 2
        if TWO_PI * mid / math.sqrt(1 - mid * mid) < delta:
            low = mid
        else:
            high = mid
    return (low + high) / 2


def decrements(first_over_last: float, n: int) -> dict[str, float]:
    """δ over n cycles, and what the slips divide by or take the logarithm with."""
    out = {"right": math.log(first_over_last) / n, "cycles_plus_one": math.log(first_over_last) / (n + 1),
           "log10_for_ln": math.log10(first_over_last) / n}
    if n > 1:
        out["cycles_minus_one"] = math.log(first_over_last) / (n - 1)
    return out


# ---- undamped (§6.2-6.5) -----------------------------------------------------------------------------


def simple_pendulum(v):
    g = printed(v, "l", "T")
    w = math.sqrt(G / g.l)
    answers = {"a": w, "b": hz(w), "c": TWO_PI / w, "d": G * (g.T / TWO_PI) ** 2,
               "e": lambda theta: -six(G / g.l) * theta}                       # m l^2 theta'' + m g l theta = 0
    mistakes = {"a": {"sqrt_missing": G / g.l}, "b": {"omega_for_f": w}, "c": {"omega_for_f": 1 / w},
                "d": {"missing_2pi": G * g.T ** 2, "period_as_frequency": G / (TWO_PI * g.T) ** 2},
                "e": {"sqrt_kept": lambda theta: -six(w) * theta}}
    return answers, mistakes


def compound_pendulum(v):
    g = printed(v, "m", "h", "k_G")
    i_g = g.m * g.k_G ** 2
    i_o = i_g + g.m * g.h ** 2                                # about the knife edge
    w = omega(g.m * G * g.h, i_o)                            # restoring moment m g h θ
    answers = {"a": i_o, "b": hz(w), "c": i_o / (g.m * g.h),
               "d": lambda theta: -six(g.m * G * g.h / i_o) * theta}       # I_O theta'' + m g h theta = 0
    mistakes = {"a": {"wrong_axis": i_g}, "b": {"omega_for_f": w, "wrong_axis": hz(omega(g.m * G * g.h, i_g))},
                "c": {"wrong_axis": i_g / (g.m * g.h)},
                "d": {"wrong_axis": lambda theta: -six(g.m * G * g.h / i_g) * theta,
                      "sqrt_kept": lambda theta: -six(w) * theta}}
    return answers, mistakes


def spring_mass(v):
    g = printed(v, "m", "K1", "K2", "arrangement")
    series, parallel = 1 / (1 / g.K1 + 1 / g.K2), g.K1 + g.K2
    k, other = (series, parallel) if g.arrangement == "series" else (parallel, series)
    slip = "parallel_for_series" if g.arrangement == "series" else "series_for_parallel"
    w = omega(k, g.m)
    answers = {"a": k, "b": g.m * G / k, "c": hz(w), "d": 1 / hz(w)}
    mistakes = {"a": {slip: other}, "b": {slip: g.m * G / other},
                "c": {"omega_for_f": w, "sqrt_missing": k / g.m / TWO_PI, slip: hz(omega(other, g.m))},
                "d": {"omega_for_f": 1 / w}}
    return answers, mistakes


def torsional_shaft_disc(v):
    g = printed(v, "m", "D", "d", "l", "G")
    inertia = g.m * g.D ** 2 / 8                             # ½ m r² with r = D/2
    polar, bending = math.pi * g.d ** 4 / 32, math.pi * g.d ** 4 / 64
    q = g.G * polar / g.l
    w = omega(q, inertia)
    across = g.m * g.D ** 2 / 16                             # about a diameter: ¼ m r²
    answers = {"a": inertia, "b": q, "c": hz(w), "d": lambda theta: -six(q / inertia) * theta}   # I theta'' + q theta = 0
    mistakes = {"a": {"wrong_axis": across, "diameter_for_radius": g.m * g.D ** 2 / 2},
                "b": {"bending_for_polar": g.G * bending / g.l, "radius_for_diameter": g.G * math.pi * (g.d / 2) ** 4 / 32 / g.l},
                "c": {"omega_for_f": w, "sqrt_missing": q / inertia / TWO_PI, "wrong_axis": hz(omega(q, across)),
                      "bending_for_polar": hz(omega(g.G * bending / g.l, inertia))},
                "d": {"wrong_axis": lambda theta: -six(q / across) * theta, "sqrt_kept": lambda theta: -six(w) * theta}}
    return answers, mistakes


def stepped_shaft(v):
    g = printed(v, "m", "k", "l1", "d1", "l2", "d2", "l3", "G", "f")
    inertia = g.m * g.k ** 2

    def twist(length: float, diameter: float) -> float:
        """Radians per N·m of a round shaft: l / (G π d⁴/32)."""
        return length / (g.G * math.pi * diameter ** 4 / 32)

    def shaft_length(w: float) -> float:                    # of diameter d1, for ω with this flywheel
        return 1 / (inertia * w * w) / twist(1.0, g.d1)

    total = shaft_length(TWO_PI * g.f)
    rest = total - (twist(g.l1, g.d1) + twist(g.l2, g.d2)) / twist(1.0, g.d1)   # what CD must count as
    answers = {"a": inertia, "b": total, "c": g.d1 * (g.l3 / rest) ** 0.25}
    mistakes = {"a": {"k_not_squared": g.m * g.k},
                "b": {"omega_for_f": shaft_length(g.f), "bending_for_polar": total / 2,   # l'/(G I) for l'/(G J)
                      "radius_for_diameter": total / 16},                            # (d/2)⁴ for d⁴
                "c": {"square_for_fourth_power": g.d1 * math.sqrt(g.l3 / rest), "ratio_inverted": g.d1 * (rest / g.l3) ** 0.25}}
    return answers, mistakes


def cantilever_end_mass(v):
    g = printed(v, "d", "l", "m", "E")
    axial = g.E * math.pi * g.d ** 2 / 4 / g.l
    bending = math.pi * g.d ** 4 / 64
    end = 3 * g.E * bending / g.l ** 3
    w_l, w_t = omega(axial, g.m), omega(end, g.m)
    answers = {"a": hz(w_l), "b": hz(w_t), "c": g.m * G / end}
    mistakes = {"a": {"omega_for_f": w_l, "diameter_for_radius": hz(omega(g.E * math.pi * g.d ** 2 / g.l, g.m))},
                "b": {"omega_for_f": w_t, "polar_for_bending": hz(omega(3 * g.E * 2 * bending / g.l ** 3, g.m)),
                      "simply_supported": hz(omega(48 * g.E * bending / g.l ** 3, g.m))},
                "c": {"simply_supported": g.m * G * g.l ** 3 / (48 * g.E * bending),   # 48EI/l³ for 3EI/l³
                      "polar_for_bending": g.m * G * g.l ** 3 / (3 * g.E * 2 * bending)}}  # J = 2I for I
    return answers, mistakes


def lever_equivalent(v):
    g = printed(v, "m_r", "L", "b", "m_A", "m_BD", "m_D", "K_A", "K_B")
    ratio = g.L / g.b                                         # A moves L/b times as far as B

    def mass(rod_inertia: float, a_factor: float) -> float:
        return rod_inertia / g.b ** 2 + g.m_A * a_factor + g.m_D + g.m_BD

    rod_end, rod_middle = g.m_r * g.L ** 2 / 3, g.m_r * g.L ** 2 / 12
    m_t, k_t = mass(rod_end, ratio ** 2), g.K_A * ratio ** 2 + g.K_B
    answers = {"a": m_t, "b": k_t, "c": hz(omega(k_t, m_t))}
    mistakes = {"a": {"wrong_axis": mass(rod_middle, ratio ** 2), "ratio_not_squared": mass(rod_end, ratio)},
                "b": {"ratio_not_squared": g.K_A * ratio + g.K_B, "ratio_inverted": g.K_A / ratio ** 2 + g.K_B},
                "c": {"omega_for_f": omega(k_t, m_t), "wrong_axis": hz(omega(k_t, mass(rod_middle, ratio ** 2)))}}
    return answers, mistakes


def beam_two_springs(v):
    g = printed(v, "m", "k", "m_B", "K", "a", "b")
    beam = g.m * g.k ** 2
    i_o = beam + g.m_B * g.b ** 2
    q = g.K * g.a ** 2 + g.K * g.b ** 2                        # each spring's energy ½ K (r θ)²
    answers = {"a": i_o, "b": q, "c": hz(omega(q, i_o))}
    mistakes = {"a": {"ball_ignored": beam}, "b": {"ratio_not_squared": g.K * (g.a + g.b)},
                "c": {"omega_for_f": omega(q, i_o), "ball_ignored": hz(omega(q, beam))}}
    return answers, mistakes


#: Each system's equivalent stiffness and mass at its reference point, from its energies, and the slips'.
SYSTEMS = {
    "floating pulley": ((lambda K, M, m: K, lambda K, M, m: 1.5 * M + 4 * m),   # turns about its rim: I_O = 3Mr²/2
                        {"wrong_axis": (lambda K, M, m: K, lambda K, M, m: M / 2 + 4 * m),
                         "ratio_not_squared": (lambda K, M, m: K, lambda K, M, m: 1.5 * M + 2 * m)}),
    "fixed pulley": ((lambda K, M, m: K, lambda K, M, m: M / 2 + m),
                     {"pulley_as_ring": (lambda K, M, m: K, lambda K, M, m: M + m),
                      "pulley_ignored": (lambda K, M, m: K, lambda K, M, m: m)}),
    "stepped pulley": ((lambda K, M, m: K / 4, lambda K, M, m: M / 2 + m),       # the spring at r, the mass at 2r
                       {"ratio_not_squared": (lambda K, M, m: K / 2, lambda K, M, m: M / 2 + m),
                        "ratio_inverted": (lambda K, M, m: 4 * K, lambda K, M, m: M / 2 + m)}),
    "lever": ((lambda K, M, m: K, lambda K, M, m: M / 3 + m / 4),
              {"wrong_axis": (lambda K, M, m: K, lambda K, M, m: M / 12 + m / 4),
               "ratio_not_squared": (lambda K, M, m: K, lambda K, M, m: M / 3 + m / 2)}),
    "two springs": ((lambda K, M, m: 2 * K, lambda K, M, m: M / 3 + m),
                    {"one_spring": (lambda K, M, m: K, lambda K, M, m: M / 3 + m),
                     "wrong_axis": (lambda K, M, m: 2 * K, lambda K, M, m: 4 * M / 3 + m)}),
}


def natural_frequency_formula(v):
    g = printed(v, "K", "M", "m")
    (stiffness, mass), slips = SYSTEMS[v.param("system").text]    # the statement describes the system

    def frequency(k, m_eq, per=TWO_PI):
        return lambda K, M, m: math.sqrt(k(K, M, m) / m_eq(K, M, m)) / per

    formulas = {"omega_for_f": frequency(stiffness, mass, 1.0)}
    formulas.update({name: frequency(*pair) for name, pair in slips.items()})
    right = frequency(stiffness, mass)
    answers = {"a": right, "b": right(g.K, g.M, g.m)}
    mistakes = {"a": formulas, "b": {name: f(g.K, g.M, g.m) for name, f in formulas.items()}}
    return answers, mistakes


# ---- damped (§6.6-6.7) ---------------------------------------------------------------------------------


def six(coefficient: float) -> float:
    """A formula's coefficient as the key prints it, to six significant figures."""
    return float(f"{coefficient:.6g}")


def damped_spring_mass(v):
    g = printed(v, "m", "K", "C")
    w = omega(g.K, g.m)
    critical = 2 * g.m * w
    zeta = g.C / critical
    wd = w * math.sqrt(1 - zeta ** 2)
    answers = {"a": critical, "b": zeta, "c": hz(wd), "d": TWO_PI / wd,
               "e": lambda x, v: -six(g.C / g.m) * v - six(g.K / g.m) * x}   # m x'' + C x' + K x = 0
    mistakes = {"a": {"factor_two_missing": g.m * w}, "b": {"factor_two_missing": g.C / (g.m * w)},
                "c": {"omega_for_f": wd, "damping_ignored": hz(w)},
                "d": {"omega_for_f": 1 / wd, "damping_ignored": TWO_PI / w},
                "e": {"damping_ignored": lambda x, v: -six(g.K / g.m) * x}}
    return answers, mistakes


def log_decrement(v):
    g = printed(v, "m", "n_s", "K", "a1", "a_r", "n")
    springs, n = int(g.n_s), int(g.n)
    w = omega(springs * g.K, g.m)
    deltas = decrements(g.a1 / g.a_r, n)
    zetas = {k: zeta_of(d) for k, d in deltas.items()}
    zeta = zetas["right"]
    ratio = math.sqrt(1 - zeta ** 2)
    answers = {"a": deltas["right"], "b": zeta, "c": 2 * zeta * g.m * w, "d": ratio, "e": TWO_PI / (w * ratio)}
    slips = [k for k in deltas if k != "right"]
    mistakes = {"a": {k: deltas[k] for k in slips}, "b": {k: zetas[k] for k in slips},
                "c": {k: 2 * zetas[k] * g.m * w for k in slips if k.startswith("cycles")},
                "d": {"ratio_inverted": 1 / ratio, "damping_ignored": 1.0}, "e": {"omega_for_f": 1 / (w * ratio)}}
    mistakes["c"]["omega_for_f"] = 2 * zeta * g.m * hz(w)
    if springs > 1:
        mistakes["c"]["one_spring"] = 2 * zeta * g.m * omega(g.K, g.m)
    return answers, mistakes


def damped_pendulum_lever(v):
    g = printed(v, "M", "l", "m_b", "k_D", "K", "b", "m_p", "a", "fall", "n")
    zetas = {k: zeta_of(d) for k, d in decrements(float(g.fall), int(g.n)).items()}
    zeta = zetas.pop("right")
    inertia = g.m_b * g.k_D ** 2 + g.M * g.l ** 2 + g.m_p * g.a ** 2      # about D
    restoring = g.K * g.b ** 2 + g.M * G * g.l                             # spring and pendulum, per radian
    w = omega(restoring, inertia)
    at_a = inertia / g.a ** 2                                              # the dashpot's own point
    answers = {"a": zeta, "b": w, "c": 2 * zeta * w * at_a, "d": 2 * w * at_a, "e": w * math.sqrt(1 - zeta ** 2)}
    mistakes = {"a": zetas, "b": {"pendulum_ignored": omega(g.K * g.b ** 2, inertia), "omega_for_f": hz(w)},
                "c": {"lever_ignored": 2 * zeta * w * inertia}, "d": {"lever_ignored": 2 * w * inertia},
                "e": {"omega_for_f": hz(answers["e"])}}
    return answers, mistakes


def damped_shaft_disc(v):
    g = printed(v, "m", "D", "d", "l", "G", "a", "C")
    inertia = g.m * g.D ** 2 / 8
    q = g.G * math.pi * g.d ** 4 / 32 / g.l
    w = omega(q, inertia)
    torque_per_rad_s = g.C * g.a * g.a                       # force C a θ̇ at arm a
    critical = 2 * inertia * w
    zeta = torque_per_rad_s / critical
    case = "light" if zeta < 1 else "heavy"                  # never drawn at exactly 1
    answers = {"a": q, "b": hz(w), "c": torque_per_rad_s, "d": zeta, "e": case,
               "f": hz(w * math.sqrt(1 - zeta ** 2)) if zeta < 1 else 0.0, "g": critical / g.a ** 2,
               # I theta'' + C a^2 theta' + q theta = 0
               "h": lambda theta, w: -six(torque_per_rad_s / inertia) * w - six(q / inertia) * theta}
    mistakes = {"a": {"bending_for_polar": g.G * math.pi * g.d ** 4 / 64 / g.l},
                "b": {"omega_for_f": w, "sqrt_missing": q / inertia / TWO_PI},
                "c": {"arm_not_squared": g.C * g.a},
                "d": {"factor_two_missing": 2 * zeta, "arm_not_squared": zeta / g.a},
                "e": {"case_inverted": "heavy" if case == "light" else "light"},
                "f": {"damping_ignored": hz(w)}, "g": {"arm_not_squared": critical / g.a},
                "h": {"damping_ignored": lambda theta, w: -six(q / inertia) * theta,
                      "arm_not_squared": lambda theta, w: -six(g.C * g.a / inertia) * w - six(q / inertia) * theta}}
    if zeta < 1:
        mistakes["f"]["omega_for_f"] = w * math.sqrt(1 - zeta ** 2)
    else:
        mistakes["f"]["root_of_negative"] = hz(w * math.sqrt(zeta ** 2 - 1))
    return answers, mistakes


ORACLES = {
    "vibration.simple_pendulum": simple_pendulum, "vibration.compound_pendulum": compound_pendulum,
    "vibration.spring_mass": spring_mass, "vibration.torsional_shaft_disc": torsional_shaft_disc,
    "vibration.stepped_shaft": stepped_shaft, "vibration.cantilever_end_mass": cantilever_end_mass,
    "vibration.lever_equivalent": lever_equivalent, "vibration.beam_two_springs": beam_two_springs,
    "vibration.natural_frequency_formula": natural_frequency_formula,
    "vibration.damped_spring_mass": damped_spring_mass, "vibration.log_decrement": log_decrement,
    "vibration.damped_pendulum_lever": damped_pendulum_lever, "vibration.damped_shaft_disc": damped_shaft_disc,
}


def test_every_chapter_6_template_has_an_oracle(bank):
    assert sorted(t.id for t in bank if t.chapter == 6) == sorted(ORACLES)


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_the_key_agrees_with_the_oracle_from_the_printed_data(bank, template_id):
    check_answers(bank, template_id, ORACLES[template_id])


@pytest.mark.parametrize("template_id", sorted(ORACLES))
def test_every_named_mistake_has_the_value_the_oracle_works_out(bank, template_id):
    check_mistakes(bank, template_id, lambda variant: ORACLES[template_id](variant)[1])
