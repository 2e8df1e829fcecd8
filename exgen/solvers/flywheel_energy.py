"""Worked derivations for flywheel energy (course text chapter 3: Example 3.3, Problems 3.2-3.5).

A press's flywheel gives up what its motor cannot supply during a stroke; an engine's flywheel
takes up the swing of its turning moment, ΔE = I ω² C_s (eq 3.5). A speed band written "±x %"
is a total fluctuation C_s = 2x; the commonest slip reads it as x.
"""
from __future__ import annotations

import math

from ..mechanics import flywheels as fw
from ..mechanics.turning_moment import TrigTorque, energy_swing, single_harmonic_crossings, single_harmonic_swing

RPM = 2 * math.pi / 60  # rad/s in one rpm


def _band(p, d) -> float:
    """C_s from a band written ± either side of the mean."""
    cs = d.step("Cs", 2 * p.band, "", symbol=r"C_s", formula=r"2 \times @band",
                note="±x % of the mean speed is a total fluctuation of 2x %")
    return cs


def punching_press(p, d):
    """Example 3.3: pressings an hour a motor can feed, the flywheel's share, the speed it loses."""
    w1 = p.N
    cycle = d.step("t_c", fw.cycle_time(p.E, p.P), "s", formula=r"\frac{@E}{@P}",
                   note="the motor must supply each pressing's energy over a cycle")
    count = d.step("n", math.floor(3600 / cycle + 1e-9), "", symbol=r"n",
                   formula=r"\left\lfloor \frac{3600}{@t_c} \right\rfloor", note="whole pressings in an hour")
    d.mistake("n", "rounded_up", math.ceil(3600 / cycle - 1e-9))
    motor = d.step("E_M", p.P * p.t, "J", symbol=r"E_M", formula=r"@P\,@t", note="supplied by the motor during the pressing")
    given = d.step("dE", fw.flywheel_share(p.E, p.P, p.t), "J", symbol=r"\Delta E", formula=r"@E - @E_M",
                   note="the rest comes from the flywheel")
    d.mistake("dE", "motor_ignored", p.E)
    held = fw.kinetic_energy(p.I, w1)
    d.require(p.E < held, "the flywheel holds less energy than one pressing needs")  # then it cannot stop either
    w2 = d.step("omega_2", fw.speed_after(w1, given, p.I), "rad/s", symbol=r"\omega_2",
                formula=r"\sqrt{@N^2 - \frac{2\,@dE}{@I}}", note=r"from $\Delta E = \tfrac{1}{2} I(\omega_1^2 - \omega_2^2)$")
    drop = d.step("drop", w1 - w2, "rad/s", symbol=r"\omega_1 - \omega_2", formula=r"@N - @omega_2")
    d.mistake("drop", "motor_ignored", w1 - fw.speed_after(w1, p.E, p.I))
    d.mistake("drop", "linearised", given / (p.I * w1), if_apart=True)  # nearly right for a small drop
    d.mistake("drop", "final_speed", w2)
    as_rad_s = w1 / RPM  # the rpm figure taken for rad/s
    d.mistake("drop", "rpm_as_rad_s", as_rad_s - math.sqrt(as_rad_s ** 2 - 2 * given / p.I))


def _engine_torque(p) -> TrigTorque:
    return TrigTorque(p.T0, ((int(p.n), p.b, p.c),))


def turning_moment_equation(p, d):
    """Problem 3.2: T = T₀ + b sin nθ + c cos nθ against a constant resisting torque: power,
    flywheel inertia for a speed band, angular acceleration at a crank angle."""
    n, w = int(p.n), p.N
    d.step("P", p.T0 * w, "W", symbol=r"P", formula=r"@T0\,@N",
           note="the resisting torque is constant, so it equals the mean torque T₀")
    d.mistake("P", "rpm_as_rad_s", p.T0 * w / RPM)
    first, second = single_harmonic_crossings(p.b, p.c, n)
    d.step("theta_1", first, "rad", symbol=r"\theta_1", formula="",
           note=rf"$T = T_0$ where $\tan {n}\theta = -c/b$: the loop above the mean line starts")
    d.step("theta_2", second, "rad", symbol=r"\theta_2", formula=rf"@theta_1 + \frac{{180^\circ}}{{{n}}}", note="and ends")
    delta_e = d.step("dE", single_harmonic_swing(p.b, p.c, n), "J", symbol=r"\Delta E",
                     formula=rf"\frac{{2\sqrt{{@b^2 + @c^2}}}}{{{n}}}",
                     note=rf"the work of the loop above the mean line: $b \sin {n}\theta + c \cos {n}\theta$ integrated from θ₁ to θ₂")
    cs = _band(p, d)
    inertia = d.step("I", fw.inertia_for(delta_e, w, cs), "kg*m^2", formula=r"\frac{@dE}{@N^2\,@Cs}")
    d.mistake("I", "plus_minus_read_as_total", delta_e / (w ** 2 * p.band))
    d.mistake("I", "rpm_as_rad_s", delta_e / ((w / RPM) ** 2 * cs))
    excess = d.step("T_ex", _engine_torque(p).at(p.theta) - p.T0, "N*m", symbol=r"T - T_0",
                    formula=rf"@b \sin({n}\,@theta) + @c \cos({n}\,@theta)",
                    note="the torque left over to accelerate the flywheel")
    d.require(abs(excess) >= 0.05 * math.hypot(p.b, p.c), "the crank angle is too near a crossing")
    d.step("alpha", excess / inertia, "rad/s^2", symbol=r"\alpha", formula=r"\frac{@T_ex}{@I}",
           note="positive: the flywheel is speeding up" if excess > 0 else "negative: the flywheel is slowing down")
    degrees = math.degrees(p.theta)
    d.mistake("alpha", "degrees_as_radians", (p.b * math.sin(n * degrees) + p.c * math.cos(n * degrees)) / inertia)
    d.mistake("alpha", "total_torque", (excess + p.T0) / inertia)
    # sin θ and cos θ for sin nθ and cos nθ: no slip at all when n = 1
    d.mistake("alpha", "harmonic_order_ignored", (p.b * math.sin(p.theta) + p.c * math.cos(p.theta)) / inertia,
              if_apart=True)


def fluctuating_resistance(p, d):
    """Problem 3.5: T = T₀ + b sin nθ; the fluctuation of speed against a constant resisting torque
    and against T₀ + r sin θ, whose crossings are found numerically and energies in closed form."""
    n, w = int(p.n), p.N
    d.step("P", p.T0 * w, "W", symbol=r"P", formula=r"@T0\,@N", note="the mean torque times the speed")
    d.mistake("P", "rpm_as_rad_s", p.T0 * w / RPM)
    delta_1 = d.step("dE_1", single_harmonic_swing(p.b, 0.0, n), "J", symbol=r"\Delta E_1",
                     formula=rf"\frac{{2\,@b}}{{{n}}}",
                     note=rf"(i) constant resisting torque: one loop of the sine, $b \sin {n}\theta$ integrated over 180°/{n}")
    cs1 = d.step("Cs_1", fw.coefficient_of_fluctuation(delta_1, p.I, w), "", symbol=r"C_{s1}",
                 formula=r"\frac{@dE_1}{@I\,@N^2}")
    d.mistake("Cs_1", "half_band", cs1 / 2)
    d.mistake("Cs_1", "rpm_as_rad_s", delta_1 / (p.I * (w / RPM) ** 2))
    engine = TrigTorque(p.T0, ((n, p.b, 0.0),))
    swing = energy_swing(engine, TrigTorque(p.T0, ((1, p.r, 0.0),)))
    for k, (theta, e) in enumerate(swing.crossings, start=1):
        d.step(f"theta_{k}", theta, "rad", symbol=rf"\theta_{k}")
        d.step(f"E_{k}", e, "J", symbol=rf"E_{k}")
    d.table(rf"(ii) Crossings, where the engine and resisting torques are equal, and the energy above the resisting "
            rf"torque since $\theta = 0$: $E = \frac{{b}}{{{n}}}(1 - \cos {n}\theta) - r\,(1 - \cos\theta)$",
            [("Crossing",), (r"$\theta$", "rad"), ("$E$", "J")],
            [[str(k), f"@theta_{k}", f"@E_{k}"] for k in range(1, len(swing.crossings) + 1)])
    high = next(k for k, c in enumerate(swing.crossings, start=1) if c == swing.high)
    low = next(k for k, c in enumerate(swing.crossings, start=1) if c == swing.low)
    delta_2 = d.step("dE_2", swing.delta, "J", symbol=r"\Delta E_2", formula=rf"@E_{high} - @E_{low}",
                     note="greatest less least energy above the resisting torque, from θ = 0")
    cs2 = d.step("Cs_2", fw.coefficient_of_fluctuation(delta_2, p.I, w), "", symbol=r"C_{s2}",
                 formula=r"\frac{@dE_2}{@I\,@N^2}")
    d.mistake("Cs_2", "constant_resistance", cs1)
    d.mistake("Cs_2", "half_band", cs2 / 2)
    d.mistake("Cs_2", "rpm_as_rad_s", delta_2 / (p.I * (w / RPM) ** 2))


def starting_torque(p, d):
    """Problem 3.3: a constant starting torque accelerates a flywheel from rest."""
    inertia = d.step("I", p.m * p.k ** 2, "kg*m^2", formula=r"@m\,@k^2")
    alpha = d.step("alpha", p.tau / inertia, "rad/s^2", symbol=r"\alpha", formula=r"\frac{@tau}{@I}")
    d.mistake("alpha", "k_not_squared", p.tau / (p.m * p.k), if_apart=True)  # k = 1 m: k and k² agree
    w = d.step("omega", alpha * p.t, "rad/s", symbol=r"\omega", formula=r"@alpha\,@t", note="from rest")
    d.step("KE", fw.kinetic_energy(inertia, w), "J", symbol=r"E_k", formula=r"\tfrac{1}{2}\,@I\,@omega^2",
           note="equal to the work of the torque, τ θ with θ = ½ α t²")
    d.mistake("KE", "half_forgotten", inertia * w ** 2)
    d.mistake("KE", "speed_not_squared", 0.5 * inertia * w)


def energy_coefficient(p, d):
    """Problem 3.4: the flywheel mass from the engine's power, the coefficient of fluctuation of
    energy and a speed band."""
    w = p.N
    revolutions = 2 if p.cycle.startswith("two") else 1
    work = d.step("W", fw.work_per_cycle(p.P, w, revolutions * 2 * math.pi), "J", symbol=r"W",
                  formula=rf"\frac{{@P \times {2 * revolutions}\pi}}{{@N}}",
                  note="work done in one cycle of the turning moment")
    d.mistake("W", "rpm_as_rad_s", p.P * revolutions * 2 * math.pi / (w / RPM))
    if revolutions > 1:
        d.mistake("W", "one_revolution", p.P * 2 * math.pi / w)
    delta_e = d.step("dE", p.Ce * work, "J", symbol=r"\Delta E", formula=r"@Ce\,@W",
                     note="the coefficient of fluctuation of energy is ΔE over the work per cycle")
    cs = _band(p, d)
    inertia = d.step("I", fw.inertia_for(delta_e, w, cs), "kg*m^2", formula=r"\frac{@dE}{@N^2\,@Cs}")
    mass = d.step("m", fw.rim_mass(inertia, p.k), "kg", formula=r"\frac{@I}{@k^2}")
    d.mistake("m", "plus_minus_read_as_total", delta_e / (w ** 2 * p.band) / p.k ** 2)
    d.mistake("m", "rpm_as_rad_s", delta_e / ((w / RPM) ** 2 * cs) / p.k ** 2)
    d.mistake("m", "k_not_squared", inertia / p.k, if_apart=True)  # k = 1 m: k and k² agree
    d.constant("g", fw.G, "m/s^2", note="standard gravity")
    d.step("weight", fw.weight(mass), "N", symbol=r"W_{\mathrm{f}}", formula=r"@m\,@g",
           note="the problem asks the weight: the mass times g")
    d.mistake("weight", "mass_for_weight", mass)
