"""Worked derivations for gear geometry and gear trains (course text §1.3.1-1.3.3, Examples 1.7-1.9).

Speeds are rad/s in the steps (the sheet asks in rpm); a train value is signed, counter-clockwise
positive, and the sense of an output is the word the sheet's choice part expects. Mistake values
are what a known wrong method gives for the same step.
"""
from __future__ import annotations

import math

from ..mechanics import gears as mg

#: How far apart a right answer and a known mistake must be (parts are graded at 1 %).
OTHER_SENSE = {"clockwise": "counter-clockwise", "counter-clockwise": "clockwise"}


def _whole(value: float) -> bool:
    return abs(value - round(value)) < 1e-6


def _sense_step(d, name: str, omega: float, note: str, driver_sense: str) -> str:
    """The output's sense as a choice step, with the other sense recorded as the mesh-count mistake."""
    word = d.step(name, mg.sense(omega), "", symbol=r"\text{sense}", note=note)
    d.mistake(name, "mesh_count", OTHER_SENSE[word])
    d.mistake(name, "sense_ignored", driver_sense)
    return word


def pitch_geometry(p, d):
    """§1.3.1: circular pitch, pitch diameters, centre distance, speed, pitch-line velocity, P_d."""
    d.step("p", mg.circular_pitch(p.m), "m", formula=r"\pi\,@m", shown="mm", note=r"circular pitch $p = \pi d/t = \pi m$")
    d.mistake("p", "pitch_over_pi", p.m / math.pi)
    d1 = d.step("d1", mg.pitch_diameter(p.t1, p.m), "m", formula=r"@m\,@t1", shown="mm")
    d2 = d.step("d2", mg.pitch_diameter(p.t2, p.m), "m", formula=r"@m\,@t2", shown="mm",
                note="mating gears share one module")
    mm = p.m * 1000  # the module as printed, for the confusion of m with a diametral pitch
    d.mistake("d1", "module_as_diametral_pitch", p.t1 / mm / 1000)
    d.mistake("d2", "module_as_diametral_pitch", p.t2 / mm / 1000)
    d.step("C", mg.centre_distance(d1, d2), "m", formula=r"\frac{@d1 + @d2}{2}", shown="mm")
    d.mistake("C", "diameters_not_halved", d1 + d2)
    d.mistake("C", "internal_formula", mg.centre_distance(d1, d2, internal=True))
    n2 = d.step("N2", p.N1 * p.t1 / p.t2, "rad/s", symbol=r"\omega_2", formula=r"@N1\,\frac{@t1}{@t2}", shown="rpm",
                note=r"$\omega_2/\omega_1 = t_1/t_2$")
    d.mistake("N2", "ratio_inverted", p.N1 * p.t2 / p.t1)
    d.step("v", p.N1 * d1 / 2, "m/s", formula=r"\frac{@N1\,@d1}{2}", note="pitch-line velocity, the same on both gears")
    d.mistake("v", "diameter_for_radius", p.N1 * d1)
    d.mistake("v", "rpm_as_rad_s", p.N1 * 60 / (2 * math.pi) * d1 / 2)
    d.mistake("v", "other_gear_speed", n2 * d1 / 2)
    d.step("Pd", mg.diametral_pitch(p.m), "1/m", symbol=r"P_d", formula=r"\frac{25.4}{@m}", shown="1/in",
           note="teeth per inch of pitch diameter, with the module in mm (25.4 mm to the inch)")
    d.mistake("Pd", "inch_factor_missing", 1 / mm / 0.0254)


def teeth_for_centre_distance(p, d):
    """Teeth for a centre distance and a speed reduction k = N1/N2: t1 + t2 = 2C/m, t2 = k t1."""
    total = d.step("t_sum", 2 * p.C / p.m, "", symbol=r"t_1 + t_2", formula=r"\frac{2\,@C}{@m}",
                   note="C is half the sum of the pitch diameters, m(t₁ + t₂)/2")
    d.require(_whole(total), "the centre distance does not hold a whole number of teeth")
    raw = total / (1 + p.k)
    d.require(_whole(raw) and _whole(p.k * raw), "the ratio does not split the teeth into whole gears")
    d.require(14 <= raw and p.k * raw <= 200, "a pinion below 14 teeth undercuts; a gear over 200 is unusual")
    t1 = d.step("t1", int(round(raw)), "", formula=r"\frac{@t_sum}{1 + @k}", note=r"$t_2 = k t_1$ with $k = N_1/N_2$")
    t2 = d.step("t2", int(round(p.k * t1)), "", formula=r"@k\,@t1")
    d.mistake("t1", "ratio_inverted", t2)
    d.mistake("t2", "ratio_inverted", t1)
    d.mistake("t1", "diameters_not_halved", round(total / 2 / (1 + p.k)))
    d.mistake("t2", "diameters_not_halved", round(p.k * total / 2 / (1 + p.k)))
    d1 = d.step("d1", mg.pitch_diameter(t1, p.m), "m", formula=r"@m\,@t1", shown="mm")
    d.step("v", p.N1 * d1 / 2, "m/s", formula=r"\frac{@N1\,@d1}{2}", note="pitch-line velocity")
    d.mistake("v", "diameter_for_radius", p.N1 * d1)
    d.mistake("v", "rpm_as_rad_s", p.N1 * 60 / (2 * math.pi) * d1 / 2)


def simple_train(p, d):
    """§1.3.3, Figure 1.16: driver, one or two idlers, driven; speed, sense and span of the train."""
    idlers = int(p.idlers)
    teeth = [("t1", p.t1), ("ta", p.ta)] + ([("tb", p.tb)] if idlers == 2 else []) + [("t2", p.t2)]
    meshes = len(teeth) - 1
    omega1 = mg.signed(p.N1, p.sense1)
    value = d.step("e", mg.train_value((a, b, mg.EXTERNAL) for (_, a), (_, b) in zip(teeth, teeth[1:])), "",
                   symbol="e", formula=rf"(-1)^{{{meshes}}}\,\frac{{@t1}}{{@t2}}",
                   note=f"{meshes} external meshes; each idler's teeth cancel")
    d.step("N2", abs(value) * p.N1, "rad/s", symbol=r"\omega_2", formula=r"\left|@e\right|\,@N1", shown="rpm")
    d.mistake("N2", "ratio_inverted", p.N1 * p.t2 / p.t1)
    d.mistake("N2", "first_mesh_only", p.N1 * p.t1 / p.ta)
    parity = "an even number keeps" if meshes % 2 == 0 else "an odd number reverses"
    _sense_step(d, "sense2", value * omega1, f"the sign of e: {meshes} meshes, and {parity} the driver's sense",
                p.sense1)
    spans = " + ".join(f"@{name}" for name, _ in teeth[1:-1])
    d.step("C", p.m * (p.t1 / 2 + sum(t for _, t in teeth[1:-1]) + p.t2 / 2), "m", symbol=r"C",
           formula=rf"@m\left(\frac{{@t1}}{{2}} + {spans} + \frac{{@t2}}{{2}}\right)", shown="mm",
           note="gears in a line: the driver's radius, each idler's diameter, the driven radius")
    full = p.m * (p.t1 / 2 + sum(t for _, t in teeth[1:-1]) + p.t2 / 2)
    d.mistake("C", "diameters_not_halved", 2 * full)
    d.mistake("C", "idlers_left_out", p.m * (p.t1 + p.t2) / 2)


def compound_train(p, d):
    """Example 1.7: gears 2-3, 4-5, 6-7 with 3-4 and 5-6 keyed together; diametral pitches in inches."""
    d2 = d.step("d2", mg.pitch_diameter_dp(p.t2, p.P23), "m", formula=r"\frac{@t2}{@P23}", shown="in",
                note="a diametral pitch is teeth per inch of pitch diameter, so the working is in inches")
    d4 = d.step("d4", mg.pitch_diameter_dp(p.t4, p.P45), "m", formula=r"\frac{@t4}{@P45}", shown="in")
    d7 = d.step("d7", mg.pitch_diameter_dp(p.t7, p.P67), "m", formula=r"\frac{@t7}{@P67}", shown="in")
    for diameter, pitch, what in ((p.d3, p.P23, "gear 3"), (p.d5, p.P45, "gear 5"), (p.d6, p.P67, "gear 6")):
        d.require(_whole(diameter * pitch), f"{what} would not have a whole number of teeth")
    d.require(d2 < p.d3 and d4 < p.d5 and p.d6 < d7, "each mesh should reduce the speed")
    value = d.step("e", (-d2 / p.d3) * (-d4 / p.d5) * (-p.d6 / d7), "", symbol="e",
                   formula=r"\left(-\frac{@d2}{@d3}\right)\left(-\frac{@d4}{@d5}\right)\left(-\frac{@d6}{@d7}\right)",
                   note="gears 3 and 4, and 5 and 6, share shafts: only the meshes count")
    d.step("N7", abs(value) * p.N2, "rad/s", symbol=r"\omega_7", formula=r"\left|@e\right|\,@N2", shown="rpm")
    d.mistake("N7", "ratio_inverted", p.N2 / abs(value))
    swapped = [t * pitch * 0.0254 ** 2 for t, pitch in ((p.t2, p.P23), (p.t4, p.P45), (p.t7, p.P67))]
    d.mistake("N7", "pd_as_module", p.N2 * swapped[0] / p.d3 * swapped[1] / p.d5 * p.d6 / swapped[2])
    _sense_step(d, "sense7", value * mg.signed(p.N2, p.sense2), "three external meshes reverse the sense",
                p.sense2)
    radii = d.step("C", (d2 + p.d3 + d4 + p.d5 + p.d6 + d7) / 2, "m",
                   formula=r"\frac{@d2 + @d3 + @d4 + @d5 + @d6 + @d7}{2}", shown="in",
                   note="the shafts lie in one plane: the sum of the six pitch radii")
    d.mistake("C", "diameters_not_halved", 2 * radii)
    d.mistake("C", "pd_as_module", (sum(swapped) + p.d3 + p.d5 + p.d6) / 2)


def reverted_train(p, d):
    """Example 1.8: shafts A and B in line through a parallel shaft; the stages share a centre distance."""
    d.require(p.m1 != p.m2, "one module for both stages makes the count trivial")
    raw = mg.reverted_teeth(p.m1, p.t1, p.t2, p.m2, p.t3)
    d.require(_whole(raw), "the last wheel would not have a whole number of teeth")
    d.require(1.5 * p.t3 <= raw <= 200, "the second stage should reduce the speed, with a wheel of usual size")
    t4 = d.step("t4", int(round(raw)), "", formula=r"\frac{@m1\,(@t1 + @t2)}{@m2} - @t3",
                note=r"coaxial: $r_1 + r_2 = r_3 + r_4$, so $m_1(t_1 + t_2) = m_2(t_3 + t_4)$")
    d.mistake("t4", "same_module", int(round(p.t1 + p.t2 - p.t3)))
    d.mistake("t4", "modules_swapped", int(round(p.m2 * (p.t1 + p.t2) / p.m1 - p.t3)))
    centre = d.step("C", p.m1 * (p.t1 + p.t2) / 2, "m", formula=r"\frac{@m1\,(@t1 + @t2)}{2}", shown="mm")
    d.mistake("C", "diameters_not_halved", 2 * centre)
    d.mistake("C", "modules_swapped", p.m2 * (p.t1 + p.t2) / 2)
    value = d.step("e", (p.t1 / p.t2) * (p.t3 / t4), "", symbol="e",
                   formula=r"\left(-\frac{@t1}{@t2}\right)\left(-\frac{@t3}{@t4}\right)",
                   note="two external meshes: B turns the same way as A")
    d.step("NB", value * p.NA, "rad/s", symbol=r"\omega_B", formula=r"@e\,@NA", shown="rpm")
    d.mistake("NB", "ratio_inverted", p.NA / value)
    d.mistake("NB", "first_stage_only", p.NA * p.t1 / p.t2)
    d.step("senseB", "same direction", "", symbol=r"\text{sense}", note="an even number of external meshes")
    d.mistake("senseB", "mesh_count", "opposite direction")


def gear_pair_power(p, d):
    """Example 1.9: ratio, output torque and speed, input power, and output power and torque with losses."""
    n = d.step("n", p.t1 / p.t2, "", symbol="n", formula=r"\frac{@t1}{@t2}",
               note=r"$n = \omega_2/\omega_1 = d_1/d_2 = t_1/t_2$; the gears turn opposite ways")
    d.mistake("n", "ratio_inverted", p.t2 / p.t1)
    d.step("d2", mg.pitch_diameter(p.t2, p.m), "m", formula=r"@m\,@t2", shown="mm")
    d.mistake("d2", "module_as_diametral_pitch", p.t2 / (p.m * 1000) / 1000)
    d.mistake("d2", "wrong_gear", mg.pitch_diameter(p.t1, p.m))
    torque_ideal = d.step("tau2_ideal", p.tau1 / n, "N*m", symbol=r"\tau_{2,\mathrm{ideal}}", formula=r"\frac{@tau1}{@n}",
                          note=r"no losses: $\tau_1 \omega_1 = \tau_2 \omega_2$")
    d.mistake("tau2_ideal", "ratio_inverted", p.tau1 * n)
    d.step("N2", n * p.N1, "rad/s", symbol=r"\omega_2", formula=r"@n\,@N1", shown="rpm")
    d.mistake("N2", "ratio_inverted", p.N1 / n)
    p1 = d.step("P1", p.tau1 * p.N1, "W", formula=r"@tau1\,@N1")
    d.mistake("P1", "rpm_as_rad_s", p.tau1 * p.N1 * 60 / (2 * math.pi))
    d.step("P2", p.eta * p1, "W", formula=r"@eta\,@P1", note=r"efficiency $\eta = P_2/P_1$")
    d.mistake("P2", "efficiency_wrong_way", p1 / p.eta)
    d.mistake("P2", "efficiency_ignored", p1)
    d.step("tau2", p.eta * torque_ideal, "N*m", formula=r"@eta\,@tau2_ideal", note=r"$\tau_2 = P_2/\omega_2$")
    d.mistake("tau2", "efficiency_ignored", torque_ideal)
    d.mistake("tau2", "efficiency_wrong_way", torque_ideal / p.eta)
    d.mistake("tau2", "ratio_inverted", p.eta * p.tau1 * n)
