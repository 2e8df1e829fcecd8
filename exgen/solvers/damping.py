"""Worked derivations for free damped vibration (course text §6.6).

The logarithmic decrement follows the text's eq. 6.46: between the first amplitude a₁ and the r-th
a_r lie r − 1 complete cycles, ln(a₁/a_r) = (r − 1)·2πζ/√(1 − ζ²). A sheet says "after n complete
cycles", so r − 1 = n; dividing by n + 1 (taking r for the number of cycles) or by n − 1 (taking n for
r) are the named slips. Every drawn system is under-damped, so it has a damped frequency to ask for.
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
