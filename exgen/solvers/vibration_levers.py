"""Worked derivations for levers and beams on springs, with and without damping (course text §6.5-6.7).

The equivalent method refers each mass, spring and damper to one reference point on the lever: a
mass at r counts m (r/r_ref)², a spring K (r/r_ref)², a damper C (r/r_ref)², an inertia about the
pivot I/r_ref², and a pendulum weight m g l/r_ref² as a spring (Table 1 of §6.5, eq. 6.47). Newton's
law about the pivot gives the same ω_n; the keys show whichever way the text works the example.
"""
from __future__ import annotations

import math

from ..mechanics import vibration as vb
from .damping import decrement_steps
from .vibration import natural_frequency


def lever_equivalent(p, d):
    """Example 6.1: rod ABC pivoted at C with a mass and a spring at A, a spring at B and a hanging
    link BD carrying a mass at D; everything referred to B."""
    i_rod = d.step("I_rod", vb.rod_inertia_about_end(p.m_r, p.L), "kg*m^2", symbol=r"I_{ABC}",
                   formula=r"\frac{@m_r\,@L^2}{3}", note="the uniform rod about its end C")
    rod = d.step("m_rod", vb.inertia_referred(i_rod, p.b), "kg", symbol=r"m'_{ABC}", formula=r"\frac{@I_rod}{@b^2}")
    mass_a = d.step("m_Aeq", vb.referred(p.m_A, p.L, p.b), "kg", symbol=r"m'_A",
                    formula=r"@m_A\left(\frac{@L}{@b}\right)^2", note="A moves AC/BC times as far as B")
    total = d.step("m_T", rod + mass_a + p.m_D + p.m_BD, "kg", symbol=r"m_T", formula=r"@m_rod + @m_Aeq + @m_D + @m_BD",
                   note="the link and its mass move with B: they count in full")
    right_rod = rod
    wrong_rod = vb.inertia_referred(p.m_r * p.L ** 2 / 12, p.b)
    d.mistake("m_T", "wrong_axis", total - right_rod + wrong_rod)
    d.mistake("m_T", "ratio_not_squared", p.m_r * p.L ** 2 / 3 / p.b ** 2 + p.m_A * p.L / p.b + p.m_D + p.m_BD)
    spring_a = d.step("K_Aeq", vb.referred(p.K_A, p.L, p.b), "N/m", symbol=r"K'_A",
                      formula=r"@K_A\left(\frac{@L}{@b}\right)^2")
    k = d.step("K_T", spring_a + p.K_B, "N/m", symbol=r"K_T", formula=r"@K_Aeq + @K_B",
               note="springs at one reference point add, like springs in parallel")
    d.mistake("K_T", "ratio_not_squared", p.K_A * p.L / p.b + p.K_B)
    d.mistake("K_T", "ratio_inverted", p.K_A * (p.b / p.L) ** 2 + p.K_B)
    natural_frequency(d, "K_T", "m_T", note=r"$m_T\ddot{x} + K_T x = 0$ at B")
    d.mistake("f_n", "wrong_axis", vb.frequency(vb.natural_speed(k, total - right_rod + wrong_rod)))
    d.require(0.5 <= d.value_of("f_n") <= 30, "a natural frequency outside 0.5-30 Hz")


def beam_two_springs(p, d):
    """Problem 6.1: beam AOB pivoted at O with equal springs at A and B and a ball at B, by Newton's law."""
    beam = d.step("I_beam", p.m * p.k ** 2, "kg*m^2", symbol=r"I_{\mathrm{beam}}", formula=r"@m\,@k^2",
                  note="about O, with the radius of gyration about O")
    ball = d.step("I_ball", p.m_B * p.b ** 2, "kg*m^2", symbol=r"I_{\mathrm{ball}}", formula=r"@m_B\,@b^2")
    d.step("I_O", beam + ball, "kg*m^2", symbol="I_O", formula=r"@I_beam + @I_ball")
    d.mistake("I_O", "ball_ignored", beam)
    q = d.step("q", p.K * (p.a ** 2 + p.b ** 2), "N*m", symbol="q", formula=r"@K\,(@a^2 + @b^2)",
               note="a turn θ stretches each spring by its distance from O times θ, and each pushes back with "
                    r"a moment $K r^2\theta$: $I_O\ddot{\theta} + K(a^2 + b^2)\theta = 0$")
    d.mistake("q", "ratio_not_squared", p.K * (p.a + p.b))
    natural_frequency(d, "q", "I_O", torsional=True, note=r"from $I_O\ddot{\theta} + q\,\theta = 0$")
    d.mistake("f_n", "ball_ignored", vb.frequency(vb.natural_speed(q, beam)))
    d.require(1 <= d.value_of("f_n") <= 40, "a natural frequency outside 1-40 Hz")


def _equivalent_check(p, d):
    """The same system by the equivalent method at A (the text's second working of Example 6.4)."""
    d.step("m_ADEeq", vb.inertia_referred(p.m_b * p.k_D ** 2, p.a), "kg", symbol=r"m'_{ADE}",
           formula=r"\frac{@I_ADE}{@a^2}", note="check by the equivalent method at A")
    d.step("m_Meq", vb.referred(p.M, p.l, p.a), "kg", symbol=r"m'_M", formula=r"@M\left(\frac{@l}{@a}\right)^2")
    spring = d.step("K_eq", vb.referred(p.K, p.b, p.a), "N/m", symbol=r"K'", formula=r"@K\left(\frac{@b}{@a}\right)^2")
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    pendulum = d.step("K_pend", vb.pendulum_stiffness(p.M, p.l, p.a), "N/m", symbol=r"K''",
                      formula=r"\frac{@M\,@g\,@l}{@a^2}", note="the pendulum's weight acts as a spring")
    d.step("K_T", spring + pendulum, "N/m", symbol=r"K_T", formula=r"@K_eq + @K_pend",
           note=r"$\omega_n = \sqrt{K_T/m_T}$ is the same as from Newton's law")


def damped_pendulum_lever(p, d):
    """Example 6.4: a bell crank pivoted at D with a pendulum mass at E, a spring at B and a dashpot at A,
    its amplitude falling to 1/q of itself after n cycles: ζ, ω_n, C, C_c, ω_d."""
    zeta = decrement_steps(p, d)
    i_body = d.step("I_ADE", p.m_b * p.k_D ** 2, "kg*m^2", symbol=r"I_{ADE}", formula=r"@m_b\,@k_D^2")
    i_m = d.step("I_M", p.M * p.l ** 2, "kg*m^2", symbol=r"I_M", formula=r"@M\,@l^2")
    i_p = d.step("I_p", p.m_p * p.a ** 2, "kg*m^2", symbol=r"I_{m_p}", formula=r"@m_p\,@a^2")
    inertia = d.step("I_D", i_body + i_m + i_p, "kg*m^2", symbol=r"I_D", formula=r"@I_ADE + @I_M + @I_p",
                     note="everything turns about D")
    d.constant("g", vb.G, "m/s^2", note="standard gravity")
    q = d.step("q", p.K * p.b ** 2 + p.M * vb.G * p.l, "N*m", symbol="q", formula=r"@K\,@b^2 + @M\,@g\,@l",
               note="moments about D for a small turn θ: the spring K (bθ) b and the weight M g l θ both restore")
    d.mistake("q", "pendulum_ignored", p.K * p.b ** 2)
    omega = d.step("omega_n", vb.natural_speed(q, inertia), "rad/s", symbol=r"\omega_n", formula=r"\sqrt{\frac{@q}{@I_D}}",
                   note=r"from $I_D\ddot{\theta} + C a^2\dot{\theta} + q\,\theta = 0$")
    d.mistake("omega_n", "pendulum_ignored", vb.natural_speed(p.K * p.b ** 2, inertia))
    d.mistake("omega_n", "omega_for_f", vb.frequency(omega))
    mass = d.step("m_T", inertia / p.a ** 2, "kg", symbol=r"m_T", formula=r"\frac{@I_D}{@a^2}",
                  note=r"the equivalent mass at A, the dashpot: $I_{ADE}/DA^2 + M(DE/DA)^2 + m_p$")
    _equivalent_check(p, d)
    c = d.step("C", zeta * vb.critical_damping(mass, omega), "N*s/m", formula=r"2\,@zeta\,@omega_n\,@m_T",
               note=r"$\zeta = C a^2/(2 I_D\omega_n)$, the dashpot referred to itself")
    d.mistake("C", "lever_ignored", 2 * zeta * omega * inertia)
    cc = d.step("C_c", vb.critical_damping(mass, omega), "N*s/m", symbol=r"C_c", formula=r"\frac{@C}{@zeta}",
                note="the dashpot that would make the system critically damped")
    d.mistake("C_c", "lever_ignored", 2 * omega * inertia)
    d.step("omega_d", vb.damped_speed(omega, zeta), "rad/s", symbol=r"\omega_d",
           formula=r"@omega_n\,\sqrt{1 - @zeta^2}", note="eq. 6.44")
    d.mistake("omega_d", "omega_for_f", vb.frequency(vb.damped_speed(omega, zeta)))
    d.require(cc > c, "over-damped")
