"""Worked derivations for the belt templates (course text §1.2).

Each solver records its steps in SI; formulas are LaTeX where @name stands for a given value
or an earlier step (its symbol in the formula line, its value in the substituted line).
Mistake values are what a known wrong method gives for the same step.
"""
from __future__ import annotations

import math

from ..mechanics import belts as mb


def _radii(p, d):
    r1 = d.step("r1", p.d1 / 2, "m", formula=r"\frac{@d1}{2}")
    r2 = d.step("r2", p.d2 / 2, "m", formula=r"\frac{@d2}{2}")
    return r1, r2


def _open_contact_angle(p, d, r1, r2):
    """Angle of contact on the smaller pulley of an open drive, with its known wrong versions."""
    small, large = ("r1", "r2") if r1 <= r2 else ("r2", "r1")
    alpha = d.step("alpha", mb.alpha_open(r1, r2, p.X), "rad",
                   formula=rf"\sin^{{-1}}\frac{{@{large} - @{small}}}{{@X}}")
    theta = d.step("theta", math.pi - 2 * alpha, "rad", formula=r"\pi - 2\,@alpha",
                   note="on the smaller pulley, which governs an open drive")
    d.mistake("theta", "crossed_formula", mb.contact_angle_crossed(r1, r2, p.X))
    d.mistake("theta", "larger_pulley", math.pi + 2 * alpha)
    if abs(p.d2 - p.d1) < p.X:
        d.mistake("theta", "diameters_for_radii", math.pi - 2 * math.asin(abs(p.d2 - p.d1) / p.X))
    return theta


def _belt_speed(p, d, r1):
    v = d.step("v", mb.belt_speed(p.N1, r1), "m/s", formula=r"@N1\,@r1",
               note="the driver's peripheral speed")
    d.mistake("v", "rpm_as_rad_s", p.N1 * 60 / (2 * math.pi) * r1)
    d.mistake("v", "diameter_for_radius", p.N1 * p.d1)
    return v


def _tension_ratio(p, d, theta, beta=None):
    if beta is None:
        ratio = d.step("ratio", mb.tension_ratio(p.mu, theta), "", symbol=r"\frac{T_1}{T_2}",
                       formula=r"e^{@mu\,@theta}")
    else:
        ratio = d.step("ratio", mb.tension_ratio(p.mu, theta, beta), "", symbol=r"\frac{T_1}{T_2}",
                       formula=r"e^{@mu\,@theta / \sin @beta}")
    return ratio


def belt_power(p, d):
    """Example 1.5 (flat) and 1.6 (V, when a groove angle is given): angle, speed, power, torque."""
    r1, r2 = _radii(p, d)
    theta = _open_contact_angle(p, d, r1, r2)
    v = _belt_speed(p, d, r1)
    beta = None
    if "groove" in p:
        beta = d.step("beta", p.groove / 2, "rad", formula=r"\frac{@groove}{2}", note="half the groove angle")
    ratio = _tension_ratio(p, d, theta, beta)
    flat_ratio = mb.tension_ratio(p.mu, theta)
    degree_ratio = math.exp(min(p.mu * math.degrees(theta) / (math.sin(beta) if beta else 1.0), 700))

    # (c) inelastic belt, mass neglected
    t1 = d.step("T1", p.T_max, "N", formula=r"@T_max", note="the tight side carries the maximum tension")
    t2_light = d.step("T2_light", mb.slack_tension(t1, ratio), "N", symbol=r"T_2",
                      formula=r"\frac{@T1}{@ratio}")
    p_light = d.step("P_light", mb.power(t1, t2_light, v), "W", symbol=r"P",
                     formula=r"(@T1 - @T2_light)\,@v")
    d.mistake("P_light", "theta_in_degrees", mb.power(t1, t1 / degree_ratio, v))
    if beta is not None:
        d.mistake("P_light", "flat_formula_on_v_belt", mb.power(t1, t1 / flat_ratio, v))
        d.mistake("P_light", "full_groove_angle", mb.power(t1, t1 / mb.tension_ratio(p.mu, theta, 2 * beta), v))

    # (d) inelastic belt, centrifugal tension considered
    tc = d.step("Tc", mb.centrifugal_tension(p.m, v), "N", symbol=r"T_c", formula=r"@m\,@v^2")
    d.require(tc < t1 / 3, "centrifugal tension above a third of the maximum: past the maximum-power speed")
    t2 = d.step("T2", mb.slack_tension(t1, ratio, tc), "N", symbol=r"T_2",
                formula=r"\frac{@T1 - @Tc}{@ratio} + @Tc")
    p_heavy = d.step("P_heavy", mb.power(t1, t2, v), "W", symbol=r"P",
                     formula=r"(@T1 - @T2)\,@v")
    d.mistake("P_heavy", "centrifugal_ignored", p_light)
    d.mistake("P_heavy", "tc_not_subtracted", (t1 + tc) * (1 - 1 / ratio) * v)

    # (e) elastic belt: creep slows the driven side
    creep = d.step("creep", mb.creep_speed_ratio(t1, t2, p.A, p.E), "", symbol=r"\frac{v_2}{v_1}",
                   formula=r"1 - \frac{@T1 - @T2}{@A\,@E}")
    v2 = d.step("v2", v * creep, "m/s", symbol=r"v_2", formula=r"@v\,@creep")
    p_elastic = d.step("P_elastic", mb.power(t1, t2, v2), "W", symbol=r"P",
                       formula=r"(@T1 - @T2)\,@v2")
    d.mistake("P_elastic", "creep_ignored", p_heavy)
    d.mistake("P_elastic", "creep_added", (t1 - t2) * v * (2 - creep))

    # (f) torque on each pulley
    tau1 = d.step("tau1", (t1 - t2) * r1, "N*m", symbol=r"\tau_1", formula=r"(@T1 - @T2)\,@r1")
    tau2 = d.step("tau2", (t1 - t2) * r2, "N*m", symbol=r"\tau_2", formula=r"(@T1 - @T2)\,@r2")
    for name, other, radius in (("tau1", tau2, r1), ("tau2", tau1, r2)):
        d.mistake(name, "radii_swapped", other)
        d.mistake(name, "diameter_for_radius", 2 * (t1 - t2) * radius)
        d.mistake(name, "centrifugal_ignored", (t1 - t2_light) * radius)
