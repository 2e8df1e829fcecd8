"""Worked derivations for undamped free vibration (course text §6.2-6.5).

Each system is brought to m' ẍ + K' x = 0 (or I θ̈ + q θ = 0), then ω_n = √(K'/m') and f_n = ω_n/2π.
The step for f_n records ω_n itself as the mistake `omega_for_f` (the 2π left out), the slip the
text's Hz-unit questions most often meet.
"""
from __future__ import annotations

import math

from ..mechanics import vibration as vb
from .slips import record


def natural_frequency(d, stiffness: str, mass: str, *, torsional: bool = False, note: str = ""):
    """ω_n = √(K/m) and f_n = ω_n / 2π from two earlier steps or givens; returns (ω_n, f_n)."""
    omega = d.step("omega_n", vb.natural_speed(d.value_of(stiffness), d.value_of(mass)), "rad/s",
                   symbol=r"\omega_n", formula=rf"\sqrt{{\frac{{@{stiffness}}}{{@{mass}}}}}",
                   note=note or ("from I θ̈ + q θ = 0" if torsional else "from m ẍ + K x = 0"))
    f = d.step("f_n", vb.frequency(omega), "Hz", symbol="f_n", formula=r"\frac{@omega_n}{2\pi}")
    d.mistake("f_n", "omega_for_f", omega)
    d.mistake("f_n", "sqrt_missing", d.value_of(stiffness) / d.value_of(mass) / (2 * math.pi))
    return omega, f


def periodic_time(d):
    """T = 1 / f_n, with the slip of 1/ω_n."""
    t = d.step("T_n", 1 / d.value_of("f_n"), "s", symbol=r"T_n", formula=r"\frac{1}{@f_n}")
    d.mistake("T_n", "omega_for_f", 1 / d.value_of("omega_n"))
    return t


# ---- §6.2: pendulums ---------------------------------------------------------------------

def simple_pendulum(p, d):
    """A simple pendulum: ω_n = √(g/l), f_n, T_n, and the length that gives another period."""
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    d.step("omega_n", vb.pendulum_speed(p.l), "rad/s", symbol=r"\omega_n", formula=r"\sqrt{\frac{@g}{@l}}",
           note="from m l² θ̈ + m g l θ = 0 (eq. 6.8)")
    d.mistake("omega_n", "sqrt_missing", vb.G / p.l)
    d.step("f_n", vb.frequency(d.value_of("omega_n")), "Hz", symbol="f_n", formula=r"\frac{@omega_n}{2\pi}")
    d.mistake("f_n", "omega_for_f", d.value_of("omega_n"))
    periodic_time(d)
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    length = d.step("l_T", vb.pendulum_length(p.T), "m", symbol=r"l'", formula=r"@g\left(\frac{@T}{2\pi}\right)^2",
                    note="T = 2π √(l/g) solved for l")
    d.mistake("l_T", "missing_2pi", vb.G * p.T ** 2)
    record(d, "l_T", "period_as_frequency", vb.G / (2 * math.pi * p.T) ** 2)
    d.require(abs(length - p.l) >= 0.03 * length, "the second pendulum would be nearly as long as the first")
    _pendulum_equation(p, d)


def _pendulum_equation(p, d) -> None:
    """Eq. 6.8, m l² θ̈ + m g l θ = 0 for small angles, asked as θ̈ in θ."""
    d.step("alpha_expr", acceleration(vb.G / p.l), symbol=r"\ddot{\theta}(\theta)",
           note=r"eq. 6.8: $m l^2\ddot\theta + m g l\,\theta = 0$ ($\sin\theta \approx \theta$), so $\ddot\theta = -(g/l)\,\theta$")
    d.mistake("alpha_expr", "sqrt_kept", acceleration(math.sqrt(vb.G / p.l)))


def acceleration(coefficient: float):
    """θ̈ = −c θ, an equation of motion solved for the angular acceleration, as a symbolic answer (c to six
    figures, as the key prints it)."""
    from ..answertypes.symbolic import Expression

    return Expression.parse(f"-({coefficient:.6g})*theta", ("theta",))


def compound_pendulum(p, d):
    """A body swinging about a knife edge h from its centre of gravity: I_O, ω_n, f_n and the length of
    the simple pendulum that keeps time with it."""
    i_g = d.step("I_G", p.m * p.k_G ** 2, "kg*m^2", symbol="I_G", formula=r"@m\,@k_G^2")
    i_o = d.step("I_O", vb.parallel_axis(i_g, p.m, p.h), "kg*m^2", symbol="I_O", formula=r"@I_G + @m\,@h^2",
                 note="about the knife edge: the parallel-axis theorem")
    d.mistake("I_O", "wrong_axis", i_g)
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    omega = d.step("omega_n", vb.compound_pendulum_speed(p.m, p.h, i_o), "rad/s", symbol=r"\omega_n",
                   formula=r"\sqrt{\frac{@m\,@g\,@h}{@I_O}}", note=r"from $I_O\ddot{\theta} + m g h\,\theta = 0$")
    d.mistake("omega_n", "wrong_axis", vb.compound_pendulum_speed(p.m, p.h, i_g))
    d.step("f_n", vb.frequency(omega), "Hz", symbol="f_n", formula=r"\frac{@omega_n}{2\pi}")
    d.mistake("f_n", "omega_for_f", omega)
    d.mistake("f_n", "wrong_axis", vb.frequency(vb.compound_pendulum_speed(p.m, p.h, i_g)))
    d.step("L", i_o / (p.m * p.h), "m", symbol="L", formula=r"\frac{@I_O}{@m\,@h}",
           note=r"the simple pendulum with the same $\omega_n$: $g/L = m g h/I_O$")
    d.mistake("L", "wrong_axis", i_g / (p.m * p.h))
    restoring = p.m * vb.G * p.h
    d.step("alpha_expr", acceleration(restoring / i_o), symbol=r"\ddot{\theta}(\theta)",
           note=r"$I_O\ddot\theta + m g h\,\theta = 0$ (eqs. 6.2-6.3, $\sin\theta \approx \theta$), "
                r"so $\ddot\theta = -(m g h/I_O)\,\theta$")
    d.mistake("alpha_expr", "wrong_axis", acceleration(restoring / i_g))
    d.mistake("alpha_expr", "sqrt_kept", acceleration(math.sqrt(restoring / i_o)))


# ---- §6.3 and §6.5: springs and a mass -------------------------------------------------------

def spring_mass(p, d):
    """A mass on two springs in series or in parallel: K', the static deflection, ω_n, f_n, T_n."""
    series = p.arrangement == "series"
    k_series, k_parallel = vb.springs_series(p.K1, p.K2), vb.springs_parallel(p.K1, p.K2)
    if series:
        k = d.step("K_eq", k_series, "N/m", symbol=r"K'", formula=r"\frac{@K1\,@K2}{@K1 + @K2}",
                   note=r"in series the springs carry one force: $1/K' = 1/K_1 + 1/K_2$")
        d.mistake("K_eq", "parallel_for_series", k_parallel)
    else:
        k = d.step("K_eq", k_parallel, "N/m", symbol=r"K'", formula=r"@K1 + @K2",
                   note=r"in parallel the springs share one displacement: $K' = K_1 + K_2$")
        d.mistake("K_eq", "series_for_parallel", k_series)
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    delta = d.step("delta", p.m * vb.G / k, "m", symbol=r"\delta", formula=r"\frac{@m\,@g}{@K_eq}",
                   note=r"the static deflection under the weight, $m g = K'\delta$")
    d.mistake("delta", "parallel_for_series" if series else "series_for_parallel",
              p.m * vb.G / (k_parallel if series else k_series))
    omega, _ = natural_frequency(d, "K_eq", "m", note=r"from $m\ddot{x} + K'x = 0$; the same as $\sqrt{g/\delta}$")
    d.mistake("f_n", "parallel_for_series" if series else "series_for_parallel",
              vb.frequency(vb.natural_speed(k_parallel if series else k_series, p.m)))
    periodic_time(d)
    d.require(0.5 <= vb.frequency(omega) <= 60, "a natural frequency outside 0.5-60 Hz: no machine mounting")
    d.require(delta <= 0.1, "a static deflection over 100 mm")


# ---- §6.4: shaft and disc ----------------------------------------------------------------

def torsional_shaft_disc(p, d):
    """A disc on a shaft fixed at its far end: I, J, q = G J / l, ω_n and f_n (eqs. 6.29-6.35)."""
    r = p.D / 2
    inertia = d.step("I", p.m * r ** 2 / 2, "kg*m^2", formula=r"\frac{@m\,(@D/2)^2}{2}",
                     note="a solid disc about its own axis, ½ m r²")
    d.mistake("I", "wrong_axis", p.m * r ** 2 / 4)
    d.mistake("I", "diameter_for_radius", p.m * p.D ** 2 / 2)
    j = d.step("J", vb.polar_second_moment(p.d), "m^4", formula=r"\frac{\pi\,@d^4}{32}",
               note="the shaft's polar second moment of area (eq. 6.32)")
    d.mistake("J", "bending_for_polar", vb.second_moment(p.d))
    q = d.step("q", vb.torsional_stiffness(p.G, p.d, p.l), "N*m", symbol="q", formula=r"\frac{@G\,@J}{@l}",
               note="torsional stiffness, torque per radian of twist (eq. 6.33)")
    d.mistake("q", "bending_for_polar", p.G * vb.second_moment(p.d) / p.l)
    d.mistake("q", "radius_for_diameter", vb.torsional_stiffness(p.G, p.d / 2, p.l))
    natural_frequency(d, "q", "I", torsional=True)
    d.mistake("f_n", "wrong_axis", vb.frequency(vb.natural_speed(q, p.m * r ** 2 / 4)))
    d.mistake("f_n", "bending_for_polar", vb.frequency(vb.natural_speed(p.G * vb.second_moment(p.d) / p.l, inertia)))
    d.require(2 <= d.value_of("f_n") <= 200, "a torsional frequency outside 2-200 Hz")
    d.step("alpha_expr", acceleration(q / inertia), symbol=r"\ddot{\theta}(\theta)",
           note=r"$I\ddot\theta + q\,\theta = 0$ (eq. 6.27), so $\ddot\theta = -(q/I)\,\theta$")
    d.mistake("alpha_expr", "wrong_axis", acceleration(q / (p.m * r ** 2 / 4)))
    d.mistake("alpha_expr", "sqrt_kept", acceleration(math.sqrt(q / inertia)))


def stepped_shaft(p, d):
    """Example 6.3: the diameter of the last step of a shaft that gives a flywheel a wanted frequency."""
    inertia = d.step("I", p.m * p.k ** 2, "kg*m^2", formula=r"@m\,@k^2", note="the flywheel")
    d.mistake("I", "k_not_squared", p.m * p.k, if_apart=True)  # k = 1 m: k and k² agree
    omega = d.step("omega_n", 2 * math.pi * p.f, "rad/s", symbol=r"\omega_n", formula=r"2\pi\,@f")
    length = d.step("l_eq", vb.length_for_speed(p.G, p.d1, inertia, omega), "m", symbol=r"l'",
                    formula=r"\frac{@G\,\pi\,@d1^4}{32\,@I\,@omega_n^2}",
                    note=r"the length of a shaft of diameter $d_1$ that gives $f_n$: $\omega_n^2 = G\pi d_1^4/(32\,l'I)$")
    d.mistake("l_eq", "omega_for_f", vb.length_for_speed(p.G, p.d1, inertia, p.f))
    d.mistake("l_eq", "bending_for_polar", length / 2)  # I = πd⁴/64 for J = πd⁴/32
    d.mistake("l_eq", "radius_for_diameter", vb.length_for_speed(p.G, p.d1 / 2, inertia, omega))
    known = d.step("l_12", vb.equivalent_length([(p.l1, p.d1), (p.l2, p.d2)], p.d1), "m", symbol=r"l_{12}'",
                   formula=r"@l1 + @l2\left(\frac{@d1}{@d2}\right)^4",
                   note="the first two steps as lengths of diameter d₁: l (d₁/d)⁴ twists alike")
    rest = d.step("l_3eq", length - known, "m", symbol=r"l_3'", formula=r"@l_eq - @l_12",
                  note="what the last step must count as")
    d.require(rest >= 0.05 * length, "the last step would be nearly rigid: the answer hangs on rounding")
    d3 = d.step("d3", vb.diameter_for_length(p.l3, rest, p.d1), "m", symbol="d_3",
                formula=r"@d1\left(\frac{@l3}{@l_3eq}\right)^{1/4}", note="from l₃ (d₁/d₃)⁴ = l₃'")
    d.require(p.d1 * 0.5 <= d3 <= 0.25, "an impractical last step")
    d.mistake("d3", "square_for_fourth_power", p.d1 * math.sqrt(p.l3 / rest))
    d.mistake("d3", "ratio_inverted", p.d1 * (rest / p.l3) ** 0.25)


def cantilever_end_mass(p, d):
    """Problem 6.2: longitudinal and transverse natural frequencies of a cantilever shaft carrying a disc."""
    area = d.step("A", vb.area(p.d), "m^2", formula=r"\frac{\pi\,@d^2}{4}")
    s_long = d.step("s_l", vb.axial_stiffness(p.E, p.d, p.l), "N/m", symbol=r"s_l", formula=r"\frac{@E\,@A}{@l}",
                    note="axial stiffness: the disc pulls the shaft along its length")
    w_long = d.step("omega_l", vb.natural_speed(s_long, p.m), "rad/s", symbol=r"\omega_l",
                    formula=r"\sqrt{\frac{@s_l}{@m}}")
    d.step("f_l", vb.frequency(w_long), "Hz", symbol=r"f_l", formula=r"\frac{@omega_l}{2\pi}")
    d.mistake("f_l", "omega_for_f", w_long)
    d.mistake("f_l", "diameter_for_radius", vb.frequency(vb.natural_speed(vb.axial_stiffness(p.E, 2 * p.d, p.l), p.m)))
    i = d.step("I_a", vb.second_moment(p.d), "m^4", symbol="I", formula=r"\frac{\pi\,@d^4}{64}",
               note="second moment of area about a diameter (bending)")
    s_trans = d.step("s_t", vb.cantilever_stiffness(p.E, p.d, p.l), "N/m", symbol=r"s_t",
                     formula=r"\frac{3\,@E\,@I_a}{@l^3}", note="the end stiffness of a cantilever, W / δ = 3 E I / l³")
    w_trans = d.step("omega_t", vb.natural_speed(s_trans, p.m), "rad/s", symbol=r"\omega_t",
                     formula=r"\sqrt{\frac{@s_t}{@m}}")
    d.step("f_t", vb.frequency(w_trans), "Hz", symbol=r"f_t", formula=r"\frac{@omega_t}{2\pi}")
    d.mistake("f_t", "omega_for_f", w_trans)
    d.mistake("f_t", "polar_for_bending", vb.frequency(vb.natural_speed(3 * p.E * vb.polar_second_moment(p.d) / p.l ** 3, p.m)))
    d.mistake("f_t", "simply_supported", vb.frequency(vb.natural_speed(48 * p.E * vb.second_moment(p.d) / p.l ** 3, p.m)))
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    d.step("delta_t", p.m * vb.G / s_trans, "m", symbol=r"\delta_t", formula=r"\frac{@m\,@g}{@s_t}",
           note=r"the static deflection under the disc's weight; $f_t = \sqrt{g/\delta}/2\pi$ again")
    d.mistake("delta_t", "simply_supported", p.m * vb.G * p.l ** 3 / (48 * p.E * vb.second_moment(p.d)))
    d.mistake("delta_t", "polar_for_bending", p.m * vb.G * p.l ** 3 / (3 * p.E * vb.polar_second_moment(p.d)))
    d.require(5 <= vb.frequency(w_trans) <= 200, "a transverse frequency outside 5-200 Hz")
