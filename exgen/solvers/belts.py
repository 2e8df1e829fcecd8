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
    d.step("alpha", mb.alpha_open(r1, r2, p.X), "rad", formula=rf"\sin^{{-1}}\frac{{@{large} - @{small}}}{{@X}}")
    theta = d.step("theta", mb.contact_angle_open(r1, r2, p.X), "rad", formula=r"180^\circ - 2\,@alpha",
                   note="on the smaller pulley, which governs an open drive")
    large = d.step("theta_large", mb.contact_angle_open_large(theta), "rad", symbol=r"\theta_{\mathrm{large}}",
                   formula=r"360^\circ - @theta", note="on the larger pulley, 180° + 2α: the two wraps make a full turn")
    d.mistake("theta", "crossed_formula", mb.contact_angle_crossed(r1, r2, p.X))
    d.mistake("theta", "larger_pulley", large)
    d.mistake("theta_large", "smaller_pulley", theta)
    d.mistake("theta_large", "crossed_formula", mb.contact_angle_crossed(r1, r2, p.X))
    if abs(p.d2 - p.d1) < p.X:
        d.mistake("theta", "diameters_for_radii", mb.contact_angle_open(p.d1, p.d2, p.X))
    return theta


def _belt_speed(p, d, r1):
    v = d.step("v", mb.belt_speed(p.N1, r1), "m/s", formula=r"@N1\,@r1",
               note="the driver's peripheral speed")
    d.mistake("v", "rpm_as_rad_s", p.N1 * 60 / (2 * math.pi) * r1)
    d.mistake("v", "diameter_for_radius", p.N1 * p.d1)
    return v


def _tension_ratio(p, d, theta, beta=None):
    if beta is None:
        ratio = d.step("ratio", mb.tension_ratio(p.mu, theta), "", symbol="R",
                       formula=r"e^{@mu\,@theta}", note="the tension ratio $T_1/T_2$")
    else:
        ratio = d.step("ratio", mb.tension_ratio(p.mu, theta, beta), "", symbol="R",
                       formula=r"e^{@mu\,@theta / \sin @beta}", note="the tension ratio $T_1/T_2$ of a V-belt")
    return ratio


def belt_power(p, d):
    """Example 1.5 (flat) and 1.6 (V, when a groove angle is given): angle, speed, power, torque."""
    r1, r2 = _radii(p, d)
    theta = _open_contact_angle(p, d, r1, r2)
    v = _belt_speed(p, d, r1)
    beta = None
    if "groove" in p:
        beta = d.step("beta", p.groove / 2, "rad", formula=r"\frac{@groove}{2}", note="half the groove angle",
                      symbolic=False)
    ratio = _tension_ratio(p, d, theta, beta)
    flat_ratio = mb.tension_ratio(p.mu, theta)
    degree_ratio = math.exp(min(p.mu * math.degrees(theta) / (math.sin(beta) if beta else 1.0), 700))

    # (c) inelastic belt, mass neglected
    t1 = d.step("T1", p.sigma * p.A, "N", formula=r"@sigma\,@A",
                note="the tight side carries the largest tension the allowable stress permits")
    t2_light = d.step("T2_light", mb.slack_tension(t1, ratio), "N", symbol=r"T_2",
                      formula=r"\frac{@T1}{@ratio}", note="the belt's mass neglected")
    p_light = d.step("P_light", mb.power(t1, t2_light, v), "W", symbol=r"P",
                     formula=r"(@T1 - @T2_light)\,@v")
    d.mistake("P_light", "theta_in_degrees", mb.power(t1, t1 / degree_ratio, v))
    # the larger pulley's wrap in the friction ratio: the smaller pulley slips first and governs (in a
    # V-groove the ratio is so large that the wrap hardly shows: named only where it does)
    d.mistake("P_light", "larger_pulley", mb.power(t1, t1 / mb.tension_ratio(p.mu, d.value_of("theta_large"), beta), v),
              if_apart=beta is not None)
    if beta is not None:
        d.mistake("P_light", "flat_formula_on_v_belt", mb.power(t1, t1 / flat_ratio, v))
        d.mistake("P_light", "full_groove_angle", mb.power(t1, t1 / mb.tension_ratio(p.mu, theta, 2 * beta), v))

    # (d) inelastic belt, centrifugal tension considered
    m = d.step("m", p.rho * p.A, "kg/m", formula=r"@rho\,@A", note="the belt's mass per metre")
    tc = d.step("Tc", mb.centrifugal_tension(m, v), "N", symbol=r"T_c", formula=r"@m\,@v^2")
    d.require(tc < t1 / 3, "centrifugal tension above a third of the maximum: past the maximum-power speed")
    t2 = d.step("T2", mb.slack_tension(t1, ratio, tc), "N", symbol=r"T_2'",
                formula=r"\frac{@T1 - @Tc}{@ratio} + @Tc", note="with centrifugal tension: primed values")
    p_heavy = d.step("P_heavy", mb.power(t1, t2, v), "W", symbol=r"P'",
                     formula=r"(@T1 - @T2)\,@v")
    d.mistake("P_heavy", "centrifugal_ignored", p_light)
    d.mistake("P_heavy", "tc_not_subtracted", (t1 + tc) * (1 - 1 / ratio) * v)

    # (e) elastic belt: creep slows the driven side
    creep = d.step("creep", mb.creep_speed_ratio(t1, t2, p.A, p.E), "", symbol=r"\frac{v_2}{v_1}",
                   formula=r"1 - \frac{@T1 - @T2}{@A\,@E}")
    v2 = d.step("v2", v * creep, "m/s", symbol=r"v_2", formula=r"@v\,@creep")
    d.step("P_elastic", mb.power(t1, t2, v2), "W", symbol=r"P''", formula=r"(@T1 - @T2)\,@v2",
           note="the elastic belt delivers at the driven pulley's slower speed")
    d.mistake("P_elastic", "creep_ignored", p_heavy)
    d.mistake("P_elastic", "creep_added", (t1 - t2) * v * (2 - creep))

    # (f) torque on each pulley
    tau1 = d.step("tau1", (t1 - t2) * r1, "N*m", symbol=r"\tau_1", formula=r"(@T1 - @T2)\,@r1")
    tau2 = d.step("tau2", (t1 - t2) * r2, "N*m", symbol=r"\tau_2", formula=r"(@T1 - @T2)\,@r2")
    for name, other, radius in (("tau1", tau2, r1), ("tau2", tau1, r2)):
        d.mistake(name, "radii_swapped", other)
        d.mistake(name, "diameter_for_radius", 2 * (t1 - t2) * radius)
        d.mistake(name, "centrifugal_ignored", (t1 - t2_light) * radius)


def driven_diameter(p, d):
    """Example 1.1: the driven pulley diameter for a wanted speed, with thickness and slip."""
    n = d.step("n", p.N2 / p.N1, "", symbol=r"\frac{N_2}{N_1}", formula=r"\frac{@N2}{@N1}")
    d.step("d2_plain", p.d1 / n, "m", symbol=r"d_2", formula=r"\frac{@d1}{@n}")
    d.step("d2_thick", mb.driven_diameter(p.d1, n, p.t), "m", symbol=r"d_{2,t}",
           formula=r"\frac{@d1 + @t}{@n} - @t", note="with the belt's thickness")
    d.step("d2_slip", mb.driven_diameter(p.d1, n, 0.0, p.G), "m", symbol=r"d_{2,s}",
           formula=r"\frac{@d1\,(1 - @G)}{@n}", note="with slip")
    both = d.step("d2_both", mb.driven_diameter(p.d1, n, p.t, p.G), "m", symbol=r"d_{2,ts}",
                  formula=r"\frac{(@d1 + @t)(1 - @G)}{@n} - @t", note="with thickness and slip")
    d.require(both > 0, "driven pulley would have no size")
    for name, thickness, slip_fraction in (("d2_plain", 0, 0), ("d2_thick", p.t, 0),
                                           ("d2_slip", 0, p.G), ("d2_both", p.t, p.G)):
        d.mistake(name, "ratio_inverted", (p.d1 + thickness) * n * (1 - slip_fraction) - thickness)
        if thickness:
            d.mistake(name, "thickness_forgotten", p.d1 * (1 - slip_fraction) / n)
            d.mistake(name, "thickness_not_subtracted", (p.d1 + thickness) * (1 - slip_fraction) / n)
        if slip_fraction:
            d.mistake(name, "slip_not_applied", (p.d1 + thickness) / n - thickness)
            d.mistake(name, "slip_wrong_way", (p.d1 + thickness) / (n * (1 - slip_fraction)) - thickness)


def driven_speed(p, d):
    """Example 1.2: the driven speed with slip on each pulley (G = G1 + G2) and belt thickness."""
    g = d.step("G", p.G1 + p.G2, "", symbol="G", formula=r"@G1 + @G2", note="slip on each pulley adds")
    ideal = d.step("N2_ideal", p.N1 * p.d1 / p.d2, "rad/s", symbol=r"\omega_2", shown="rpm",
                   formula=r"@N1\,\frac{@d1}{@d2}")
    slipping = d.step("N2_slip", p.N1 * mb.speed_ratio(p.d1, p.d2, 0.0, g), "rad/s", symbol=r"\omega_{2,s}",
                      shown="rpm", formula=r"@N1\,\frac{@d1}{@d2}\,(1 - @G)", note="with slip")
    d.step("N2_thick", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t, g), "rad/s", symbol=r"\omega_{2,ts}",
           shown="rpm", formula=r"@N1\,\frac{@d1 + @t}{@d2 + @t}\,(1 - @G)", note="with slip and thickness")
    d.mistake("N2_ideal", "ratio_inverted", p.N1 * p.d2 / p.d1)
    d.mistake("N2_slip", "ratio_inverted", p.N1 * p.d2 / p.d1 * (1 - g))
    d.mistake("N2_slip", "slip_not_applied", ideal)
    d.mistake("N2_slip", "slip_one_pulley", p.N1 * mb.speed_ratio(p.d1, p.d2, 0.0, p.G1))
    d.mistake("N2_slip", "slip_wrong_way", ideal * (1 + g))
    d.mistake("N2_thick", "thickness_forgotten", slipping)
    d.mistake("N2_thick", "slip_not_applied", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t))
    d.mistake("N2_thick", "slip_one_pulley", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t, p.G1))


def compound_drive(p, d):
    """Problem 1.4: motor -> main shaft -> countershaft, slip on each drive and belt thickness."""
    main = d.step("N2", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t, p.G), "rad/s", symbol=r"\omega_2", shown="rpm",
                  formula=r"@N1\,\frac{@d1 + @t}{@d2 + @t}\,(1 - @G)", note="main shaft")
    d.step("N4", main * mb.speed_ratio(p.d3, p.d4, p.t, p.G), "rad/s", symbol=r"\omega_4", shown="rpm",
           formula=r"@N2\,\frac{@d3 + @t}{@d4 + @t}\,(1 - @G)",
           note="the pulley $d_3$ turns with the main shaft")
    d.mistake("N2", "slip_not_applied", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t))
    d.mistake("N2", "thickness_forgotten", p.N1 * mb.speed_ratio(p.d1, p.d2, 0.0, p.G))
    d.mistake("N2", "ratio_inverted", p.N1 * (p.d2 + p.t) / (p.d1 + p.t) * (1 - p.G))
    d.mistake("N4", "slip_not_applied", p.N1 * mb.speed_ratio(p.d1, p.d2, p.t) * mb.speed_ratio(p.d3, p.d4, p.t))
    d.mistake("N4", "slip_once", main * mb.speed_ratio(p.d3, p.d4, p.t))
    d.mistake("N4", "thickness_forgotten",
              p.N1 * mb.speed_ratio(p.d1, p.d2, 0.0, p.G) * mb.speed_ratio(p.d3, p.d4, 0.0, p.G))
    d.mistake("N4", "ratio_inverted", main * (p.d4 + p.t) / (p.d3 + p.t) * (1 - p.G))


def drive_geometry(p, d):
    """Example 1.3: angle of contact and belt length, open and crossed."""
    r1, r2 = _radii(p, d)
    theta_open = _open_contact_angle(p, d, r1, r2)
    d.step("alpha_crossed", mb.alpha_crossed(r1, r2, p.X), "rad", symbol=r"\alpha_{\times}",
           formula=r"\sin^{-1}\frac{@r1 + @r2}{@X}")
    d.step("theta_crossed", mb.contact_angle_crossed(r1, r2, p.X), "rad", symbol=r"\theta_{\times}",
           formula=r"180^\circ + 2\,@alpha_crossed", note="the same on both pulleys of a crossed drive")
    d.mistake("theta_crossed", "open_formula", theta_open)
    if p.d1 + p.d2 <= p.X:  # else the diameters give no angle at all
        d.mistake("theta_crossed", "diameters_for_radii", mb.contact_angle_crossed(p.d1, p.d2, p.X))
    d.step("L_open", mb.length_open(r1, r2, p.X), "m", symbol=r"L_{\mathrm{open}}",
           formula=r"\pi(@r1 + @r2) + 2\,@X + \frac{(@r2 - @r1)^2}{@X}")
    d.step("L_crossed", mb.length_crossed(r1, r2, p.X), "m", symbol=r"L_{\times}",
           formula=r"\pi(@r1 + @r2) + 2\,@X + \frac{(@r1 + @r2)^2}{@X}")
    d.mistake("L_open", "crossed_length", mb.length_crossed(r1, r2, p.X))
    d.mistake("L_crossed", "open_length", mb.length_open(r1, r2, p.X))
    for name, fn in (("L_open", mb.length_open), ("L_crossed", mb.length_crossed)):
        d.mistake(name, "diameters_for_radii", fn(p.d1, p.d2, p.X))


def max_power(p, d):
    """§1.2.7: the belt speed that gives the greatest power (Tc = T_max / 3) and that power."""
    r1, r2 = _radii(p, d)
    theta = _open_contact_angle(p, d, r1, r2)
    ratio = _tension_ratio(p, d, theta)
    t_max = d.step("T_max", p.sigma * p.A, "N", symbol=r"T_{\max}", formula=r"@sigma\,@A",
                   note="the largest tension the allowable stress permits")
    m = d.step("m", p.rho * p.A, "kg/m", formula=r"@rho\,@A", note="the belt's mass per metre")
    v = d.step("v_opt", mb.speed_for_max_power(t_max, m), "m/s", symbol=r"v_{\mathrm{opt}}",
               formula=r"\sqrt{\frac{@T_max}{3\,@m}}", note=r"maximum power when $T_c = T_{\max}/3$")
    d.mistake("v_opt", "tc_equals_tmax", math.sqrt(t_max / m))
    d.mistake("v_opt", "tc_half", math.sqrt(t_max / (2 * m)))
    tc = d.step("Tc", m * v ** 2, "N", symbol=r"T_c", formula=r"@m\,@v_opt^2")
    d.step("P_max", (t_max - tc) * (1 - 1 / ratio) * v, "W", symbol=r"P_{\max}",
                   formula=r"(@T_max - @Tc)\left(1 - \frac{1}{@ratio}\right)\,@v_opt")
    d.mistake("P_max", "centrifugal_ignored", t_max * (1 - 1 / ratio) * v)
    d.mistake("P_max", "theta_in_degrees", (t_max - tc) * v)
    d.step("N_opt", v / r1, "rad/s", symbol=r"\omega_1", formula=r"\frac{@v_opt}{@r1}",
           note="driver speed that gives this belt speed")
    d.mistake("N_opt", "diameter_for_radius", v / p.d1)


def v_belt_count(p, d):
    """Problem 1.3: how many V-belts carry a duty, and the effect of an idler on the wrap."""
    d2 = d.step("d2", p.d2_max, "m", symbol=r"d_2", formula=r"@d2_max",
                note="the largest allowed pulley keeps the belt speed up and the belt count down")
    d1 = d.step("d1", d2 * p.N2 / p.N1, "m", symbol=r"d_1", formula=r"@d2\,\frac{@N2}{@N1}", shown="m")
    r1 = d.step("r1", d1 / 2, "m", formula=r"\frac{@d1}{2}")
    r2 = d.step("r2", d2 / 2, "m", formula=r"\frac{@d2}{2}")
    v = d.step("v", p.N1 * r1, "m/s", formula=r"@N1\,@r1")
    d.require(v <= p.v_max, "belt speed above the limit")
    d.step("alpha", mb.alpha_open(r1, r2, p.X), "rad", formula=r"\sin^{-1}\frac{@r2 - @r1}{@X}")
    theta = d.step("theta", mb.contact_angle_open(r1, r2, p.X), "rad", formula=r"180^\circ - 2\,@alpha",
                   note="on the smaller (motor) pulley")
    beta = d.step("beta", p.groove / 2, "rad", formula=r"\frac{@groove}{2}", note="half the groove angle",
                      symbolic=False)
    t_max = d.step("T1", p.sigma * p.A, "N", symbol=r"T_1", formula=r"@sigma\,@A",
                   note="the allowable stress sets the tight-side tension")
    m = d.step("m", p.rho * p.A, "kg/m", formula=r"@rho\,@A")
    tc = d.step("Tc", m * v ** 2, "N", symbol=r"T_c", formula=r"@m\,@v^2")
    d.require(tc < t_max / 3, "belt above its maximum-power speed")
    ratio = d.step("ratio", mb.tension_ratio(p.mu, theta, beta), "", symbol="R",
                   formula=r"e^{@mu\,@theta / \sin @beta}", note="the tension ratio $(T_1 - T_c)/(T_2 - T_c)$")
    slack = d.step("T2", mb.slack_tension(t_max, ratio, tc), "N", symbol=r"T_2",
                   formula=r"@Tc + \frac{@T1 - @Tc}{@ratio}", note="the slack side of each belt")
    d.mistake("T2", "centrifugal_ignored", t_max / ratio)
    d.mistake("T2", "flat_formula_on_v_belt", mb.slack_tension(t_max, mb.tension_ratio(p.mu, theta), tc))
    per_belt = d.step("P_belt", (t_max - slack) * v, "W", symbol=r"P_{\mathrm{belt}}",
                      formula=r"(@T1 - @T2)\,@v")
    exact = d.step("n_exact", p.P / per_belt, "", symbol=r"\frac{P}{P_{\mathrm{belt}}}",
                   formula=r"\frac{@P}{@P_belt}", note="belts needed, before rounding")
    count = d.step("n_belts", mb.belts_needed(p.P, per_belt), "", symbol="n",
                   formula=r"\left\lceil @n_exact \right\rceil", note="rounded up to whole belts")
    d.require(0.05 < exact - math.floor(exact) < 0.95, "the duty needs nearly a whole number of belts: rounding "
              "earlier steps could change the count")
    d.require(2 <= count <= 12, "an unrealistic number of belts")
    d.mistake("n_belts", "rounded_down", math.floor(p.P / per_belt))
    d.mistake("n_belts", "centrifugal_ignored", mb.belts_needed(p.P, t_max * (1 - 1 / ratio) * v))
    d.mistake("n_belts", "flat_formula_on_v_belt",
              mb.belts_needed(p.P, (t_max - tc) * (1 - 1 / mb.tension_ratio(p.mu, theta)) * v))
    theta_idler = d.step("theta_idler", theta * (1 + p.idler), "rad", symbol=r"\theta'",
                         formula=r"@theta\,(1 + @idler)")
    ratio_idler = d.step("ratio_idler", mb.tension_ratio(p.mu, theta_idler, beta), "",
                         symbol="R'",
                         formula=r"e^{@mu\,@theta_idler / \sin @beta}")
    per_belt_idler = d.step("P_belt_idler", (t_max - tc) * (1 - 1 / ratio_idler) * v, "W",
                            symbol=r"P_{\mathrm{belt}}'",
                            formula=r"(@T1 - @Tc)\left(1 - \frac{1}{@ratio_idler}\right)\,@v")
    change = d.step("change", per_belt_idler / per_belt - 1, "", symbol=r"\Delta P / P",
                    formula=r"\frac{@P_belt_idler}{@P_belt} - 1")
    d.step("trend", "increase" if change > 0 else "decrease", "", symbol=r"\text{power}",
           note="more wrap, more friction: each belt carries more")
    d.mistake("change", "ratio_inverted", per_belt / per_belt_idler - 1)
    d.mistake("change", "flat_formula_on_v_belt",
              (1 - 1 / mb.tension_ratio(p.mu, theta_idler)) / (1 - 1 / mb.tension_ratio(p.mu, theta)) - 1)
    d.mistake("trend", "opposite", "decrease" if change > 0 else "increase")
