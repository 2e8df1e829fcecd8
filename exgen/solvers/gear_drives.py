"""Worked derivations for geared drives (course text §1.3.4): hoists, a lift, a haulage, a vehicle, a robot arm.

The text's method (Example 1.12): refer everything to the motor shaft. A shaft turning at n times
the motor's speed (n = ω_shaft/ω_motor, below 1 for a reducer) adds I n²/η to the motor's inertia
and a torque τ on it costs the motor τ n/η, η being the efficiency of the contacts between them
(η² through two contacts). The motor torque is the sum of what accelerates the inertias, what
drives the load and what overcomes the friction torques. g = 9.81 m/s².
"""
from __future__ import annotations

import math

from ..mechanics import gears as mg

G = 9.81


def _gravity(d) -> float:
    return d.constant("g", G, "m/s^2", note="standard gravity")


def _inertias(p, d):
    """Example 1.12: shaft inertias from mass and radius of gyration, referred to the motor."""
    i_m = d.step("I_M", p.mM * p.kM ** 2, "kg*m^2", formula=r"@mM\,@kM^2")
    i_d = d.step("I_D", p.mD * p.kD ** 2, "kg*m^2", formula=r"@mD\,@kD^2")
    n = d.step("n", p.t1 / p.t2, "", formula=r"\frac{@t1}{@t2}", note=r"$n = \omega_D/\omega_M$")
    i_eq = d.step("I_EQ", i_m + mg.referred_inertia(i_d, n, p.eta), "kg*m^2", symbol=r"I_{EQ}",
                  formula=r"@I_M + \frac{@I_D\,@n^2}{@eta}", note="the drum's inertia referred to the motor shaft")
    d.mistake("I_EQ", "ratio_not_squared", i_m + i_d * n / p.eta)
    d.mistake("I_EQ", "efficiency_multiplied", i_m + i_d * n ** 2 * p.eta)
    d.mistake("I_EQ", "inertia_not_referred", i_m + i_d)
    return i_eq, n


def _motor_acceleration(p, d, n):
    r_d = d.step("r_D", p.dD / 2, "m", formula=r"\frac{@dD}{2}")
    alpha_d = d.step("alpha_D", p.a / r_d, "rad/s^2", symbol=r"\alpha_D", formula=r"\frac{@a}{@r_D}")
    alpha_m = d.step("alpha_M", alpha_d / n, "rad/s^2", symbol=r"\alpha_M", formula=r"\frac{@alpha_D}{@n}")
    d.mistake("alpha_M", "diameter_for_radius", p.a / p.dD / n)
    d.mistake("alpha_M", "ratio_inverted", alpha_d * n)
    return r_d, alpha_m


def hoist_torque(p, d):
    """Example 1.12: motor torque to raise a hanging load (a), and to haul it up a slope with friction (b)."""
    i_eq, n = _inertias(p, d)
    r_d, alpha_m = _motor_acceleration(p, d, n)
    tau1 = d.step("tau_M1", i_eq * alpha_m, "N*m", symbol=r"\tau_{M1}", formula=r"@I_EQ\,@alpha_M",
                  note="accelerates the inertias")
    _gravity(d)
    pull = d.step("F", mg.hanging_pull(p.M, p.a, G), "N", formula=r"@M\,(@a + @g)", note="rope pull on the hanging mass")
    tau_d = d.step("tau_D2", pull * r_d, "N*m", symbol=r"\tau_{D2}", formula=r"@F\,@r_D")
    tau2 = d.step("tau_M2", mg.referred_torque(tau_d, n, p.eta), "N*m", symbol=r"\tau_{M2}",
                  formula=r"\frac{@tau_D2\,@n}{@eta}", note="the load torque referred to the motor")
    d.step("tau_M", tau1 + tau2, "N*m", symbol=r"\tau_M", formula=r"@tau_M1 + @tau_M2")
    d.mistake("tau_M", "efficiency_multiplied", tau1 + tau_d * n * p.eta)
    d.mistake("tau_M", "weight_forgotten", tau1 + p.M * p.a * r_d * n / p.eta)
    d.mistake("tau_M", "inertia_forgotten", tau2)
    d.mistake("tau_M", "diameter_for_radius", tau1 + pull * p.dD * n / p.eta)

    pull_b = d.step("F_b", mg.incline_pull(p.M, p.a, G, p.slope, p.f), "N", symbol=r"F'",
                    formula=r"@M\,@a + @f + @M\,@g \sin @slope", note="hauled up the slope against friction instead")
    tau_d_b = d.step("tau_D2b", pull_b * r_d, "N*m", symbol=r"\tau_{D2}'", formula=r"@F_b\,@r_D")
    tau2_b = d.step("tau_M2b", mg.referred_torque(tau_d_b, n, p.eta), "N*m", symbol=r"\tau_{M2}'",
                    formula=r"\frac{@tau_D2b\,@n}{@eta}")
    tau3 = d.step("tau_M3", p.tau_fM + mg.referred_torque(p.tau_fD, n, p.eta), "N*m", symbol=r"\tau_{M3}",
                  formula=r"@tau_fM + \frac{@tau_fD\,@n}{@eta}", note="friction torques, the drum's referred to the motor")
    total = d.step("tau_Mb", tau1 + tau2_b + tau3, "N*m", symbol=r"\tau_M'", formula=r"@tau_M1 + @tau_M2b + @tau_M3")
    d.mistake("tau_Mb", "drum_friction_not_referred", tau1 + tau2_b + p.tau_fM + p.tau_fD)
    d.mistake("tau_Mb", "efficiency_multiplied", tau1 + (tau_d_b + p.tau_fD) * n * p.eta + p.tau_fM)
    d.mistake("tau_Mb", "friction_torques_forgotten", tau1 + tau2_b)
    d.mistake("tau_Mb", "cos_for_sin", total - tau2_b + mg.referred_torque(
        (p.M * p.a + p.f + p.M * G * math.cos(p.slope)) * r_d, n, p.eta))


def lift_counterweight(p, d):
    """Problem 1.2: the counterweight that lets a motor's maximum torque accelerate a lift, two gear stages."""
    n1 = d.step("n1", p.t1 / p.t2, "", symbol=r"n_{1/2}", formula=r"\frac{@t1}{@t2}",
                note="gear 1 on the motor drives gear 2 on the middle shaft")
    n = d.step("n", n1 * p.t3 / p.t4, "", formula=r"@n1\,\frac{@t3}{@t4}",
               note="gear 3 on the middle shaft drives gear 4 on the drum: $n = \\omega_D/\\omega_M$")
    d.mistake("n", "ratio_inverted", 1 / (n1 * p.t3 / p.t4))
    i_eq = d.step("I_EQ", p.I_M + p.I_T * n1 ** 2 / p.eta + p.I_D * n ** 2 / p.eta ** 2, "kg*m^2",
                  symbol=r"I_{EQ}", formula=r"@I_M + \frac{@I_T\,@n1^2}{@eta} + \frac{@I_D\,@n^2}{@eta^2}",
                  note="the drum is two contacts from the motor, the middle shaft one")
    one_contact = p.I_M + (p.I_T * n1 ** 2 + p.I_D * n ** 2) / p.eta  # a small effect: named where it shows
    d.mistake("I_EQ", "one_contact_efficiency", one_contact, if_apart=True)
    d.mistake("I_EQ", "ratio_not_squared", p.I_M + p.I_T * n1 / p.eta + p.I_D * n / p.eta ** 2)
    d.mistake("I_EQ", "efficiency_multiplied", p.I_M + p.I_T * n1 ** 2 * p.eta + p.I_D * n ** 2 * p.eta ** 2)
    r_d, alpha_m = _motor_acceleration(p, d, n)
    tau1 = d.step("tau_M1", i_eq * alpha_m, "N*m", symbol=r"\tau_{M1}", formula=r"@I_EQ\,@alpha_M",
                  note="the part of the motor torque that accelerates the shafts")
    d.mistake("tau_M1", "ratio_inverted", i_eq * d.value_of("alpha_D") * n)
    d.mistake("tau_M1", "diameter_for_radius", i_eq * p.a / p.dD / n)
    left = d.step("tau_D2", mg.available_torque(p.tau_M - tau1, n, p.eta ** 2), "N*m", symbol=r"\tau_{D2}",
                  formula=r"\frac{(@tau_M - @tau_M1)\,@eta^2}{@n}", note="what reaches the drum for the ropes")
    net = d.step("F_net", left / r_d, "N", symbol=r"\Delta T", formula=r"\frac{@tau_D2}{@r_D}",
                 note="the lift's rope tension less the counterweight's, $T_L - T_C$")
    _gravity(d)
    mass = d.step("M2", (p.ml * (G + p.a) + p.R - net) / (G - p.a), "kg", symbol=r"M_2",
                  formula=r"\frac{@ml\,(@g + @a) + @R - @F_net}{@g - @a}",
                  note=r"lift: $T_L = m_l(g + a) + R$; counterweight, accelerating down: $T_C = M_2(g - a)$")
    d.require(0.3 * p.ml <= mass <= p.ml, "a counterweight outside 30-100 % of the lift's mass")

    def counterweight(tau_drum, accel_sign=-1.0, resist=p.R):
        return (p.ml * (G + p.a) + resist - tau_drum / r_d) / (G + accel_sign * p.a)

    for name, drum in (("one_contact_efficiency", (p.tau_M - tau1) * p.eta / n),
                       ("efficiency_wrong_way", (p.tau_M - tau1) / (p.eta ** 2 * n))):
        d.mistake("M2", name, counterweight(drum), if_apart=True)  # small effects: named where they show
    d.mistake("M2", "counterweight_accel_sign", counterweight(left, +1.0))
    d.mistake("M2", "resistance_forgotten", counterweight(left, resist=0.0))
    d.mistake("M2", "inertia_forgotten", counterweight(mg.available_torque(p.tau_M, n, p.eta ** 2)))


def haulage_power(p, d):
    """Problem 1.6: the mass a given drum torque hauls up a slope of 1 in s, then motor torque and power."""
    r_d = d.step("r_D", p.dD / 2, "m", formula=r"\frac{@dD}{2}")
    pull = d.step("F", p.tau_D / r_d, "N", formula=r"\frac{@tau_D}{@r_D}", note="rope pull from the drum torque")
    sine = d.step("sin_theta", 1 / p.s, "", symbol=r"\sin\theta", formula=r"\frac{1}{@s}",
                  note="a slope of 1 in s rises 1 for s along the slope")
    _gravity(d)
    d.step("M", (pull - p.f) / (p.a + G * sine), "kg", formula=r"\frac{@F - @f}{@a + @g\,@sin_theta}",
           note=r"$F = M a + f + M g \sin\theta$")
    d.mistake("M", "diameter_for_radius", (p.tau_D / p.dD - p.f) / (p.a + G * sine))
    d.mistake("M", "weight_component_forgotten", (pull - p.f) / p.a)
    d.mistake("M", "friction_forgotten", pull / (p.a + G * sine))
    d.mistake("M", "cos_for_sin", (pull - p.f) / (p.a + G * math.cos(math.asin(sine))))
    n = d.step("n", p.t1 / p.t2, "", formula=r"\frac{@t1}{@t2}", note=r"$n = \omega_D/\omega_M$")
    i_eq = d.step("I_EQ", p.I_M + mg.referred_inertia(p.I_D, n, p.eta), "kg*m^2", symbol=r"I_{EQ}",
                  formula=r"@I_M + \frac{@I_D\,@n^2}{@eta}")
    alpha_m = d.step("alpha_M", p.a / r_d / n, "rad/s^2", symbol=r"\alpha_M", formula=r"\frac{@a}{@r_D\,@n}")
    tau1 = d.step("tau_M1", i_eq * alpha_m, "N*m", symbol=r"\tau_{M1}", formula=r"@I_EQ\,@alpha_M")
    tau2 = d.step("tau_M2", mg.referred_torque(p.tau_D, n, p.eta), "N*m", symbol=r"\tau_{M2}",
                  formula=r"\frac{@tau_D\,@n}{@eta}")
    tau3 = d.step("tau_M3", p.tau_fM + mg.referred_torque(p.tau_fD, n, p.eta), "N*m", symbol=r"\tau_{M3}",
                  formula=r"@tau_fM + \frac{@tau_fD\,@n}{@eta}")
    torque = d.step("tau_M", tau1 + tau2 + tau3, "N*m", symbol=r"\tau_M", formula=r"@tau_M1 + @tau_M2 + @tau_M3")
    d.mistake("tau_M", "efficiency_multiplied",
              p.I_M * alpha_m + p.I_D * n ** 2 * p.eta * alpha_m + (p.tau_D + p.tau_fD) * n * p.eta + p.tau_fM)
    d.mistake("tau_M", "ratio_not_squared", (p.I_M + p.I_D * n / p.eta) * alpha_m + tau2 + tau3)
    d.mistake("tau_M", "inertia_forgotten", tau2 + tau3)
    d.mistake("tau_M", "drum_friction_not_referred", tau1 + tau2 + p.tau_fM + p.tau_fD)
    d.step("P", torque * p.N_M, "W", formula=r"@tau_M\,@N_M")
    d.mistake("P", "rpm_as_rad_s", torque * p.N_M * 60 / (2 * math.pi))


def vehicle_gradient(p, d):
    """Problem 1.5: wheel speed, gear ratio and the hill a car climbs while accelerating in a gear."""
    omega_w = d.step("N_W", p.v / p.r, "rad/s", symbol=r"\omega_W", formula=r"\frac{@v}{@r}", note=r"$v = \omega d/2$")
    d.mistake("N_W", "diameter_for_radius", p.v / (2 * p.r))
    d.mistake("N_W", "kmh_as_ms", p.v * 3.6 / p.r)
    n = d.step("n", omega_w / p.N_E, "", formula=r"\frac{@N_W}{@N_E}", note=r"$n = \omega_W/\omega_E$, the text's definition")
    d.mistake("n", "ratio_inverted", p.N_E / omega_w)
    d.step("ratio_EW", 1 / n, "", symbol=r"\frac{\omega_E}{\omega_W}", formula=r"\frac{1}{@n}",
           note="the same gear quoted engine to wheel, as gearboxes usually are")
    alpha_e = d.step("alpha_E", p.a / p.r / n, "rad/s^2", symbol=r"\alpha_E", formula=r"\frac{@a}{@r\,@n}")
    i_eq = d.step("I_EQ", p.I_E + mg.referred_inertia(p.I_W, n, p.eta), "kg*m^2", symbol=r"I_{EQ}",
                  formula=r"@I_E + \frac{@I_W\,@n^2}{@eta}")
    tau1 = d.step("tau_1", i_eq * alpha_e, "N*m", symbol=r"\tau_{E1}", formula=r"@I_EQ\,@alpha_E",
                  note="accelerates the engine and the wheels")
    tau_f = d.step("tau_f", p.tau_fE + mg.referred_torque(p.tau_fW, n, p.eta), "N*m", symbol=r"\tau_{E3}",
                   formula=r"@tau_fE + \frac{@tau_fW\,@n}{@eta}", note="bearing friction, the wheels' referred to the engine")
    wheel = d.step("tau_W", mg.available_torque(p.tau_E - tau1 - tau_f, n, p.eta), "N*m", symbol=r"\tau_W",
                   formula=r"\frac{(@tau_E - @tau_1 - @tau_f)\,@eta}{@n}", note="what reaches the wheels to drive the car")
    traction = d.step("F_T", wheel / p.r, "N", symbol=r"F_T", formula=r"\frac{@tau_W}{@r}")
    _gravity(d)
    sine = d.step("sin_theta", (traction - p.m * p.a - p.R) / (p.m * G), "", symbol=r"\sin\theta",
                  formula=r"\frac{@F_T - @m\,@a - @R}{@m\,@g}", note=r"$F_T = m a + R + m g \sin\theta$")
    d.require(-1 < sine < 1, "no such hill")
    theta = d.step("theta", math.asin(sine), "rad", symbol=r"\theta", formula=r"\sin^{-1} @sin_theta",
                   symbolic=False)
    d.require(math.radians(1) <= theta <= math.radians(12), "not a road gradient (1-12 degrees)")

    def hill(tau_wheel):
        s = (tau_wheel / p.r - p.m * p.a - p.R) / (p.m * G)
        return math.asin(s) if -1 < s < 1 else None

    for name, tau_wheel in (("efficiency_wrong_way", (p.tau_E - tau1 - tau_f) / (p.eta * n)),
                            ("inertia_forgotten", (p.tau_E - tau_f) * p.eta / n),
                            ("friction_forgotten", (p.tau_E - tau1) * p.eta / n)):
        wrong = hill(tau_wheel)
        if wrong is not None:
            d.mistake("theta", name, wrong)


def robot_arm(p, d):
    """Problem 1.1: a robot arm through two gear pairs; motor torque to hold it and to accelerate it."""
    n12 = d.step("n12", 1 / p.k12, "", symbol=r"n_{1/2}", formula=r"\frac{1}{@k12}")
    n34 = d.step("n34", 1 / p.k34, "", symbol=r"n_{3/4}", formula=r"\frac{1}{@k34}")
    n = d.step("n", n12 * n34, "", formula=r"@n12\,@n34", note=r"$n = \omega_A/\omega_m$")
    i_arm = d.step("I_A", p.I_G4 + p.m * p.L ** 2, "kg*m^2", symbol=r"I_A", formula=r"@I_G4 + @m\,@L^2",
                   note="gear 4 and the arm, its mass taken at its centre of mass, L from the joint")
    first = p.I_m + p.I_G1
    i_eq = d.step("I_EQ", first + (p.I_G2 + p.I_G3) * n12 ** 2 / p.eta + i_arm * n ** 2 / p.eta ** 2,
                  "kg*m^2", symbol=r"I_{EQ}",
                  formula=r"@I_m + @I_G1 + \frac{(@I_G2 + @I_G3)\,@n12^2}{@eta} + \frac{@I_A\,@n^2}{@eta^2}",
                  note="gears 2 and 3 are one contact from the motor, the arm two")
    d.mistake("I_EQ", "ratio_not_squared", first + (p.I_G2 + p.I_G3) * n12 / p.eta + i_arm * n / p.eta ** 2)
    one_contact = first + ((p.I_G2 + p.I_G3) * n12 ** 2 + i_arm * n ** 2) / p.eta
    d.mistake("I_EQ", "one_contact_efficiency", one_contact, if_apart=True)
    d.mistake("I_EQ", "arm_mass_forgotten", first + (p.I_G2 + p.I_G3) * n12 ** 2 / p.eta + p.I_G4 * n ** 2 / p.eta ** 2)
    weight = p.m * G * p.L
    _gravity(d)
    hold = d.step("tau_g", weight * math.cos(p.theta) * n / p.eta ** 2, "N*m", symbol=r"\tau_{mg}",
                  formula=r"\frac{@m\,@g\,@L\,@n \cos @theta}{@eta^2}",
                  note="the arm's weight, referred to the motor through both pairs")
    d.mistake("tau_g", "efficiency_multiplied", weight * math.cos(p.theta) * n * p.eta ** 2)
    d.mistake("tau_g", "sin_for_cos", weight * math.sin(p.theta) * n / p.eta ** 2)
    d.mistake("tau_g", "ratio_inverted", weight * math.cos(p.theta) / n / p.eta ** 2)
    d.step("k_alpha", i_eq / n, "kg*m^2", symbol=r"\frac{I_{EQ}}{n}", formula=r"\frac{@I_EQ}{@n}",
           note=r"Problem 1.1's equation: $\tau_m = (I_{EQ}/n)\,\alpha_A + (n/\eta^2)\,m g L \cos\theta$")
    d.step("k_weight", weight * n / p.eta ** 2, "N*m", symbol=r"\frac{n\,m g L}{\eta^2}",
           formula=r"\frac{@n\,@m\,@g\,@L}{@eta^2}", note=r"the coefficient of $\cos\theta$")
    alpha_m = d.step("alpha_m", p.alpha_A / n, "rad/s^2", symbol=r"\alpha_m", formula=r"\frac{@alpha_A}{@n}")
    d.step("tau_m", i_eq * alpha_m + hold, "N*m", symbol=r"\tau_m", formula=r"@I_EQ\,@alpha_m + @tau_g")
    d.mistake("tau_m", "ratio_inverted", i_eq * p.alpha_A * n + hold)
    d.mistake("tau_m", "weight_forgotten", i_eq * alpha_m)
    _torque_equation(d, i_eq, n, weight * n / p.eta ** 2)


def _torque_equation(d, i_eq: float, n: float, weight_term: float) -> None:
    """Problem 1.1's own question: τ_m as an equation in θ and α_A, from the coefficients worked above."""
    from ..answertypes.symbolic import Expression

    def equation(accelerating: float, holding: float, trig: str = "cos") -> Expression:
        text = f"{accelerating:.6g}*alpha_A" + (f" + {holding:.6g}*{trig}(theta)" if holding else "")
        return Expression.parse(text, ("theta", "alpha_A"))

    d.step("tau_expr", equation(i_eq / n, weight_term), symbol=r"\tau_m(\theta, \alpha_A)",
           note=r"$\tau_m = (I_{EQ}/n)\,\alpha_A + (n\,m g L/\eta^2)\cos\theta$, θ above the horizontal")
    d.mistake("tau_expr", "ratio_inverted", equation(i_eq * n, weight_term))
    d.mistake("tau_expr", "weight_forgotten", equation(i_eq / n, 0.0))
    d.mistake("tau_expr", "sin_for_cos", equation(i_eq / n, weight_term, "sin"))
