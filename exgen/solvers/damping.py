"""Worked derivations for free damped vibration (course text §6.6).

The logarithmic decrement follows the text's eq. 6.46: between the first amplitude a₁ and the r-th
a_r lie r − 1 complete cycles, ln(a₁/a_r) = (r − 1)·2πζ/√(1 − ζ²). A sheet says "after n complete
cycles", so r − 1 = n; dividing by n + 1 (taking r for the number of cycles) or by n − 1 (taking n for
r) are the named slips. Those templates draw under-damped systems, which have a damped frequency to ask
for; `damped_shaft_disc` draws all of the text's cases (§6.6.3) and asks which it is.
"""
from __future__ import annotations

import math

from ..mechanics import vibration as vb

#: Damping ratios of real dampers on machines and mountings: well under critical.
ZETA_MAX = 0.6


def decrement_steps(p, d):
    """δ per cycle and ζ, from a₁/a_r after n cycles (params a1 and a_r, or their ratio `fall`)."""
    if "fall" in p:
        first, last, formula = p.fall, 1.0, r"\frac{\ln @fall}{@n}"
    else:
        first, last, formula = p.a1, p.a_r, r"\frac{1}{@n}\ln\frac{@a1}{@a_r}"
    n = p.n
    delta = d.step("delta", vb.decrement(first, last, n), "", symbol=r"\delta", formula=formula,
                   note=r"the logarithmic decrement per cycle: $n$ complete cycles lie between $a_1$ and $a_r$, so "
                        r"$r - 1 = n$ in $\ln(a_1/a_r) = (r - 1)\,\delta$ (eq. 6.46)")
    slips = {"cycles_plus_one": vb.decrement(first, last, n + 1),
             "log10_for_ln": math.log10(first / last) / n}
    if n > 1:
        slips["cycles_minus_one"] = vb.decrement(first, last, n - 1)
    for name, wrong in slips.items():
        d.mistake("delta", name, wrong)
    zeta = d.step("zeta", vb.ratio_from_decrement(delta), "", symbol=r"\zeta",
                  formula=r"\frac{@delta}{\sqrt{4\pi^2 + @delta^2}}", note="δ = 2πζ/√(1 − ζ²) solved for ζ")
    for name, wrong in slips.items():
        d.mistake("zeta", name, vb.ratio_from_decrement(wrong))
    d.require(zeta < ZETA_MAX, "damping too heavy for a machine that oscillates visibly")
    return zeta


def damped_spring_mass(p, d):
    """Problem 6.3: a mass, spring and damper: ω_n, C_c, ζ and the damped frequency and period."""
    omega = d.step("omega_n", vb.natural_speed(p.K, p.m), "rad/s", symbol=r"\omega_n",
                   formula=r"\sqrt{\frac{@K}{@m}}")
    cc = d.step("C_c", vb.critical_damping(p.m, omega), "N*s/m", symbol=r"C_c", formula=r"2\,@m\,@omega_n",
                note="critical damping")
    d.mistake("C_c", "factor_two_missing", p.m * omega)
    zeta = d.step("zeta", vb.damping_ratio(p.C, cc), "", symbol=r"\zeta", formula=r"\frac{@C}{@C_c}")
    d.mistake("zeta", "factor_two_missing", p.C / (p.m * omega))
    d.require(0.05 <= zeta <= ZETA_MAX, "a damping ratio outside 0.05-0.6: not a practical damper")
    wd = d.step("omega_d", vb.damped_speed(omega, zeta), "rad/s", symbol=r"\omega_d",
                formula=r"@omega_n\,\sqrt{1 - @zeta^2}", note="eq. 6.44")
    fd = d.step("f_d", vb.frequency(wd), "Hz", symbol=r"f_d", formula=r"\frac{@omega_d}{2\pi}")
    d.mistake("f_d", "omega_for_f", wd)
    d.mistake("f_d", "damping_ignored", vb.frequency(omega))
    d.step("T_d", 1 / fd, "s", symbol=r"T_d", formula=r"\frac{1}{@f_d}", note="the periodic time, eq. 6.45")
    d.mistake("T_d", "omega_for_f", 1 / wd)
    d.mistake("T_d", "damping_ignored", 1 / vb.frequency(omega))
    _equation_of_motion(p, d)


def _equation_of_motion(p, d) -> None:
    """Eq. 6.42, m ẍ + C ẋ + K x = 0, asked as the acceleration in the displacement x and velocity v = ẋ."""
    from ..answertypes.symbolic import Expression

    def acceleration(damping: float, stiffness: float) -> Expression:
        text = f"-({damping / p.m:.6g})*v" if damping else ""
        return Expression.parse(f"{text} - ({stiffness / p.m:.6g})*x", ("x", "v"))

    d.step("a_expr", acceleration(p.C, p.K), symbol=r"\ddot{x}(x, v)",
           note=r"eq. 6.42: $m\ddot x + C\dot x + Kx = 0$, so $\ddot x = -(C/m)\,v - (K/m)\,x$ with $v = \dot x$")
    d.mistake("a_expr", "damping_ignored", acceleration(0.0, p.K))


def log_decrement(p, d):
    """Problems 6.4 and 6.5: a machine on n_s springs whose amplitude falls from a₁ to a_r in n cycles:
    δ, ζ, the damping coefficient, f_d/f_n and the damped period."""
    k = d.step("K_T", p.n_s * p.K, "N/m", symbol=r"K_T", formula=r"@n_s\,@K",
               note="the springs share the machine's displacement: in parallel they add")
    omega = d.step("omega_n", vb.natural_speed(k, p.m), "rad/s", symbol=r"\omega_n", formula=r"\sqrt{\frac{@K_T}{@m}}")
    zeta = decrement_steps(p, d)
    d.require(zeta >= 0.08, "damping too light to show in f_d/f_n at four figures")
    c = d.step("C", zeta * vb.critical_damping(p.m, omega), "N*s/m", formula=r"2\,@zeta\,@m\,@omega_n",
               note=r"$C = \zeta C_c$ with $C_c = 2 m\omega_n$: the resistance at unit velocity")
    if p.n_s > 1:
        d.mistake("C", "one_spring", zeta * vb.critical_damping(p.m, vb.natural_speed(p.K, p.m)))
    d.mistake("C", "cycles_plus_one", d.mistakes["zeta"]["cycles_plus_one"] * vb.critical_damping(p.m, omega))
    if p.n > 1:
        d.mistake("C", "cycles_minus_one", d.mistakes["zeta"]["cycles_minus_one"] * vb.critical_damping(p.m, omega))
    d.mistake("C", "omega_for_f", zeta * vb.critical_damping(p.m, vb.frequency(omega)))
    ratio = d.step("ratio", math.sqrt(1 - zeta ** 2), "", symbol=r"\frac{f_d}{f_n}", formula=r"\sqrt{1 - @zeta^2}",
                   note=r"$\omega_d = \omega_n\sqrt{1 - \zeta^2}$")
    d.mistake("ratio", "ratio_inverted", 1 / ratio)
    d.mistake("ratio", "damping_ignored", 1.0)
    wd = d.step("omega_d", omega * ratio, "rad/s", symbol=r"\omega_d", formula=r"@omega_n\,@ratio")
    d.step("T_d", vb.period(wd), "s", symbol=r"T_d", formula=r"\frac{2\pi}{@omega_d}", note="eq. 6.45")
    d.mistake("T_d", "omega_for_f", 1 / wd)
    d.require(c > 0, "no damping")


def damped_shaft_disc(p, d):
    """§6.6.2-6.7: a disc on a shaft with a dashpot on an arm: q, f_n, the torsional coefficient C a²,
    ζ, the case of §6.6.3, the damped frequency where there is one, and the dashpot that damps critically."""
    r = p.D / 2
    inertia = d.step("I", p.m * r ** 2 / 2, "kg*m^2", formula=r"\frac{@m\,(@D/2)^2}{2}",
                     note="a solid disc about its own axis, ½ m r²")
    d.step("J", vb.polar_second_moment(p.d), "m^4", formula=r"\frac{\pi\,@d^4}{32}",
           note="the shaft's polar second moment of area")
    q = d.step("q", vb.torsional_stiffness(p.G, p.d, p.l), "N*m", symbol="q", formula=r"\frac{@G\,@J}{@l}",
               note="torsional stiffness, torque per radian of twist")
    d.mistake("q", "bending_for_polar", p.G * vb.second_moment(p.d) / p.l)
    omega = d.step("omega_n", vb.natural_speed(q, inertia), "rad/s", symbol=r"\omega_n",
                   formula=r"\sqrt{\frac{@q}{@I}}", note=r"from $I\ddot\theta + C_t\dot\theta + q\theta = 0$ (eq. 6.43) without the damper")
    f_n = d.step("f_n", vb.frequency(omega), "Hz", symbol="f_n", formula=r"\frac{@omega_n}{2\pi}")
    d.mistake("f_n", "omega_for_f", omega)
    d.mistake("f_n", "sqrt_missing", q / inertia / (2 * math.pi))
    d.require(2 <= f_n <= 100, "a torsional frequency outside 2-100 Hz")
    c_t = d.step("C_t", vb.torsional_damping(p.C, p.a), "N*m*s", symbol="C_t", formula=r"@C\,@a^2",
                 note=r"the dashpot's force $C a\dot\theta$ acts at arm $a$: a torque $C a^2\dot\theta$ (eq. 6.47, $C' = C(a/b)^2$, per unit $b^2$)")
    d.mistake("C_t", "arm_not_squared", p.C * p.a)
    # worked from f_n and C_t, the steps (b) and (c) answer, so a student's own values carry forward
    cc = d.step("C_c", vb.critical_damping(inertia, 2 * math.pi * f_n), "N*m*s", symbol="C_c",
                formula=r"2\,@I \times 2\pi\,@f_n", note=r"critical damping: $C_t/I = 2\zeta\omega_n$ with $\zeta = 1$")
    zeta = d.step("zeta", vb.damping_ratio(c_t, cc), "", symbol=r"\zeta", formula=r"\frac{@C_t}{@C_c}")
    d.mistake("zeta", "factor_two_missing", c_t / (inertia * 2 * math.pi * f_n))
    d.mistake("zeta", "arm_not_squared", vb.damping_ratio(p.C * p.a, cc))
    d.require(0.15 <= zeta <= 3 and abs(zeta - 1) >= 0.1,
              "a damping ratio outside 0.15-3, or within 10 % of critical, where a printed value's rounding could decide the case")
    case = d.step("case", vb.damping_case(zeta), "", symbol=r"\text{damping}",
                  note={"light": r"$\zeta < 1$: light damping (under-damped), the disc oscillates as it dies away",
                        "heavy": r"$\zeta > 1$: heavy damping (over-damped), the disc creeps back without oscillating",
                        "critical": r"$\zeta = 1$: critical damping, back in the shortest time without oscillating"}[vb.damping_case(zeta)])
    d.mistake("case", "case_inverted", {"light": "heavy", "heavy": "light", "critical": "light"}[case])
    if case == "light":
        w_d = d.step("omega_d", vb.damped_speed(2 * math.pi * f_n, zeta), "rad/s", symbol=r"\omega_d",
                     formula=r"2\pi\,@f_n\,\sqrt{1 - @zeta^2}", note="eq. 6.44")
        d.step("f_d", vb.frequency(w_d), "Hz", symbol="f_d", formula=r"\frac{@omega_d}{2\pi}")
        d.mistake("f_d", "omega_for_f", w_d)
        d.mistake("f_d", "damping_ignored", f_n)
    else:
        d.step("f_d", 0.0, "Hz", symbol="f_d",
               note=r"$\zeta \ge 1$: the motion is not a vibration, so there is no damped frequency; $\sqrt{1 - \zeta^2}$ has no real value")
        d.mistake("f_d", "root_of_negative", f_n * math.sqrt(zeta ** 2 - 1))
        d.mistake("f_d", "damping_ignored", f_n)
    d.step("C_crit", cc / p.a ** 2, "N*s/m", symbol=r"C_{\mathrm{crit}}", formula=r"\frac{@C_c}{@a^2}",
           note=r"the dashpot at the same arm whose $C a^2$ is $C_c$")
    d.mistake("C_crit", "arm_not_squared", cc / p.a)
    _disc_equation(p, d, inertia, q)


def _disc_equation(p, d, inertia: float, q: float) -> None:
    """Eq. 6.43, I θ̈ + C a² θ̇ + q θ = 0, asked as θ̈ in the twist θ and the angular velocity w = θ̇."""
    from ..answertypes.symbolic import Expression

    def acceleration(damping: float) -> Expression:
        text = f"-({damping / inertia:.6g})*w" if damping else ""
        return Expression.parse(f"{text} - ({q / inertia:.6g})*theta", ("theta", "w"))

    d.step("alpha_expr", acceleration(p.C * p.a ** 2), symbol=r"\ddot{\theta}(\theta, w)",
           note=r"eq. 6.43: $I\ddot\theta + C a^2\dot\theta + q\theta = 0$, so "
                r"$\ddot\theta = -(C a^2/I)\,w - (q/I)\,\theta$ with $w = \dot\theta$")
    d.mistake("alpha_expr", "damping_ignored", acceleration(0.0), if_apart=True)
    d.mistake("alpha_expr", "arm_not_squared", acceleration(p.C * p.a), if_apart=True)
