"""Flywheel physics (exgen.mechanics.flywheels, .turning_moment) against chapter 3 and against
numerical integration.

Each textbook value is recomputed here from the data as printed; where the text's arithmetic
slips, the test holds the correct value and says what was printed.
"""
import math

import numpy as np
import pytest

from exgen.mechanics import flywheels as fw
from exgen.mechanics.turning_moment import (TrigTorque, crossings, energy_swing, single_harmonic_crossings,
                                            single_harmonic_swing)


def rpm(n: float) -> float:
    """rad/s from rpm, as the text converts: ω = 2πN/60 (Example 3.2 prints 1500 rpm as 157.08 rad/s)."""
    return 2 * math.pi * n / 60


def test_example_3_1_crossings_and_fluctuation():
    signed = fw.alternate([295, 685, 40, 340, 960, 270], first_above=True)
    assert signed == [295, -685, 40, -340, 960, -270]
    assert fw.crossing_energies(signed) == [0, 295, -390, -350, -690, 270, 0]   # A..G, as printed
    swing, high, low = fw.fluctuation_from_areas(signed)
    assert (swing, "ABCDEFG"[high], "ABCDEFG"[low]) == (985, "B", "E")
    per_mm2 = fw.energy_per_area(5.0, math.radians(1.0))
    assert per_mm2 == pytest.approx(math.pi / 36)
    delta_e = swing * per_mm2
    # printed 85.96 J, then carried into the last line as 85.97 J: the first is right
    assert delta_e == pytest.approx(85.96, abs=5e-3)
    inertia = 36 * 0.15 ** 2                       # printed "0.81 kg/m²": the unit is kg·m²
    assert inertia == pytest.approx(0.81)
    cs = fw.coefficient_of_fluctuation(delta_e, inertia, rpm(1800))
    assert cs == pytest.approx(0.002987, abs=5e-7)  # printed 0.003 or 0.3 %
    assert fw.inertia_for(delta_e, rpm(1800), cs) == pytest.approx(inertia)   # eq 3.5 read both ways


def test_problem_3_1_rim():
    signed = [-35, 410, -285, 325, -335, 260, -365, 285, -260]
    assert signed == fw.alternate([35, 410, 285, 325, 335, 260, 365, 285, 260], first_above=False)
    assert fw.crossing_energies(signed) == [0, -35, 375, 90, 415, 80, 340, -25, 260, 0]
    swing, high, low = fw.fluctuation_from_areas(signed)
    assert (swing, high, low) == (450, 4, 1)
    delta_e = swing * fw.energy_per_area(70, math.radians(4.5))
    assert delta_e == pytest.approx(2474.00, abs=0.005)
    inertia = fw.inertia_for(delta_e, rpm(900), 0.02)
    mass = fw.rim_mass(inertia, 0.325)
    assert mass == pytest.approx(131.84, abs=0.005)
    thickness = fw.rim_thickness(fw.rim_area(mass, 7200, 0.325), 2.0)
    width = 2.0 * thickness
    assert thickness == pytest.approx(0.06696, abs=5e-6)
    assert 7200 * 2 * math.pi * 0.325 * thickness * width == pytest.approx(mass)


def test_loops_that_do_not_close_are_refused():
    with pytest.raises(ValueError, match="do not close"):
        fw.crossing_energies([100, -50])


def test_example_3_2_torque_time():
    """5.5 N·m, rising from 0.5 s to 44 N·m at 0.7 s, held to 0.9 s, back at 1.1 s; a 2 s cycle at 1500 rpm."""
    w = rpm(1500)
    pulse = fw.trapezium_width(0.5, 0.7, 0.9, 1.1) * (44.0 - 5.5)
    assert pulse == pytest.approx(15.4)                           # ½[(1.1 − 0.5) + (0.9 − 0.7)] × 38.5
    work = (5.5 * 2.0 + pulse) * w
    assert work == pytest.approx(4146.912, abs=0.01)       # printed from ω = 157.08 rad/s
    mean = work / (w * 2.0)
    # Erratum: the text divides by 2 x 157.8 (a typo for 157.08 rad/s) and prints 13.14 N·m
    assert mean == pytest.approx(13.2)
    assert mean * w == pytest.approx(2073.5, abs=0.05)      # printed 2073 W (13.14 x 157.8 happens to agree)
    x, y = fw.trapezium_crossings(0.5, 0.7, 0.9, 1.1, 5.5, 44.0, mean)
    assert (x, y) == pytest.approx((0.54, 1.06))             # as printed
    delta_e = fw.trapezium_width(x, 0.7, 0.9, y) * w * (44.0 - mean)
    # Erratum: printed 1753.09 J from 157.8 rad/s and 13.14 N·m
    assert delta_e == pytest.approx(1741.70, abs=5e-3)
    cs = fw.coefficient_of_fluctuation(delta_e, 18 * 0.25 ** 2, w)
    # Erratum: printed 0.0626 (6.26 %) from 1753.09 J and 157.8 rad/s; the data give 6.27 %
    assert cs == pytest.approx(0.062745, abs=5e-7)


@pytest.mark.parametrize("level", [5.5, 10.0, 30.0, 43.0])
def test_the_pulse_above_a_level_is_its_trapezium_from_the_crossings(level):
    """∫ (τ − level) dt where the pulse lies above the level, by numerical integration, against the
    trapezium between the crossings: the energy the flywheel gives up above a motor torque `level`."""
    times, torques = (0.0, 0.5, 0.7, 0.9, 1.1, 2.0), (5.5, 5.5, 44.0, 44.0, 5.5, 5.5)
    xs = np.linspace(0, 2, 800001)
    above = np.clip(np.interp(xs, times, torques) - level, 0.0, None)
    x, y = fw.trapezium_crossings(0.5, 0.7, 0.9, 1.1, 5.5, 44.0, level)
    assert fw.trapezium_width(x, 0.7, 0.9, y) * (44.0 - level) == pytest.approx(np.trapezoid(above, xs), rel=1e-6)


def test_example_3_3_press():
    t = fw.cycle_time(4750, 2250)
    assert t == pytest.approx(2.111, abs=5e-4)
    assert math.floor(3600 / t) == 1705
    given = fw.flywheel_share(4750, 2250, 0.75)
    assert given == 3062.5
    w1 = rpm(250)
    w2 = fw.speed_after(w1, given, 50)
    assert w1 == pytest.approx(26.18, abs=5e-3) and w2 == pytest.approx(23.73, abs=5e-3)
    assert w1 - w2 == pytest.approx(2.45, abs=5e-3)
    with pytest.raises(ValueError, match="stop"):
        fw.speed_after(w1, 1e6, 50)


def test_problem_3_3_starting():
    inertia = 2450 * 1.0 ** 2
    alpha = 1250 / inertia
    assert alpha == pytest.approx(0.5102, abs=5e-5)
    assert fw.kinetic_energy(inertia, alpha * 10) == pytest.approx(1250 * 0.5 * alpha * 10 ** 2)  # = work done
    assert fw.kinetic_energy(inertia, alpha * 10) == pytest.approx(31888, abs=1)


def test_problem_3_4_energy_coefficient():
    w = rpm(100)
    work = fw.work_per_cycle(305e3, w)
    assert work == pytest.approx(183_000)
    inertia = fw.inertia_for(0.1 * work, w, 0.01)      # ±0.5 % is a total band of 1 %
    assert fw.rim_mass(inertia, 2.0) == pytest.approx(4171.90, abs=0.005)


# ---- the analytic turning moment ------------------------------------------------------------------


def _numeric_swing(engine: TrigTorque, resisting: TrigTorque, period: float, n: int = 400_001) -> float:
    """Fluctuation of energy by brute force: the trapezium rule on a fine grid, no closed form."""
    theta = np.linspace(0.0, period, n)
    excess = np.array([engine.at(t) - resisting.at(t) for t in theta])
    running = np.concatenate([[0.0], np.cumsum((excess[1:] + excess[:-1]) / 2 * np.diff(theta))])
    return float(running.max() - running.min())


def test_problem_3_2_single_harmonic():
    engine, resisting = TrigTorque(14500, ((2, 2300, -1900),)), TrigTorque(14500)
    w = rpm(150)
    assert engine.mean * w == pytest.approx(227_765, abs=1)       # 227.77 kW
    swing = energy_swing(engine, resisting)
    assert swing.delta == pytest.approx(math.hypot(2300, 1900)) == single_harmonic_swing(2300, -1900, 2)
    first, second = single_harmonic_crossings(2300, -1900, 2)
    assert math.degrees(first) == pytest.approx(19.78, abs=5e-3) and math.degrees(second) == pytest.approx(109.78, abs=5e-3)
    assert engine.minus(resisting).work(first, second) == pytest.approx(swing.delta)
    inertia = fw.inertia_for(swing.delta, w, 0.01)                 # ±0.5 %: a 1 % band
    assert inertia == pytest.approx(1209.1, abs=0.05)
    alpha = (engine.at(math.radians(30)) - resisting.at(math.radians(30))) / inertia
    assert alpha == pytest.approx(0.8617, abs=5e-5)


def test_problem_3_5_constant_and_fluctuating_resistance():
    engine = TrigTorque(5000, ((3, 1500, 0),))
    w = rpm(300)
    assert engine.mean * w == pytest.approx(157_080, abs=1)
    constant = energy_swing(engine, TrigTorque(5000))
    assert constant.delta == pytest.approx(1000)                   # 2 x 1500 / 3
    assert 100 * fw.coefficient_of_fluctuation(constant.delta, 1000, w) == pytest.approx(0.1013, abs=5e-5)
    varying = energy_swing(engine, TrigTorque(5000, ((1, 600, 0),)))
    # crossings where 1500 sin 3θ = 600 sin θ: sin²θ = 0.65; E = 600 cos θ − 500 cos 3θ − 100
    # there cos θ = ±√0.35 and cos 3θ = cos θ (4 cos² θ − 3) = −1.6 cos θ, so E = ±1400 √0.35 − 100
    assert varying.high[1] == pytest.approx(1400 * math.sqrt(0.35) - 100) == pytest.approx(728.25, abs=0.005)
    assert varying.low[1] == pytest.approx(-1400 * math.sqrt(0.35) - 100) == pytest.approx(-928.25, abs=0.005)
    assert varying.delta == pytest.approx(1656.50, abs=0.01)
    assert 100 * fw.coefficient_of_fluctuation(varying.delta, 1000, w) == pytest.approx(0.16784, abs=5e-5)


@pytest.mark.parametrize("engine, resisting", [
    (TrigTorque(14500, ((2, 2300, -1900),)), TrigTorque(14500)),
    (TrigTorque(5000, ((3, 1500, 0),)), TrigTorque(5000, ((1, 600, 0),))),
    (TrigTorque(800, ((1, 300, 120), (2, -250, 60), (4, 90, -40))), TrigTorque(800, ((1, 50, 0),))),
    (TrigTorque(2000, ((6, 0, 900),)), TrigTorque(2000, ((2, 400, 300),))),
])
def test_closed_form_swing_agrees_with_numerical_integration(engine, resisting):
    swing = energy_swing(engine, resisting)
    period = engine.minus(resisting).period
    assert swing.delta == pytest.approx(_numeric_swing(engine, resisting, period), rel=1e-6)


@pytest.mark.parametrize("theta0, theta1", [(0.0, 1.0), (0.3, 2.9), (-1.0, 4.0)])
def test_closed_form_work_agrees_with_numerical_integration(theta0, theta1):
    torque = TrigTorque(700, ((1, 120, -40), (3, 55, 80)))
    grid = np.linspace(theta0, theta1, 200_001)
    values = np.array([torque.at(t) for t in grid])
    numeric = float(np.sum((values[1:] + values[:-1]) / 2 * np.diff(grid)))
    assert torque.work(theta0, theta1) == pytest.approx(numeric, rel=1e-9)


def test_crossings_are_where_the_torques_meet():
    excess = TrigTorque(5000, ((3, 1500, 0),)).minus(TrigTorque(5000, ((1, 600, 0),)))
    found = crossings(excess)
    assert len(found) == 6
    assert all(abs(excess.at(t)) < 1e-9 for t in found)


def test_unequal_mean_torques_have_no_cycle():
    with pytest.raises(ValueError, match="mean"):
        energy_swing(TrigTorque(5000, ((3, 1500, 0),)), TrigTorque(4000))


def test_harmonics_are_whole_numbers():
    with pytest.raises(ValueError, match="whole number"):
        TrigTorque(1.0, ((1.5, 1.0, 0.0),))


def test_period_is_set_by_the_common_harmonic():
    assert TrigTorque(0, ((2, 1, 0), (4, 0, 1))).period == pytest.approx(math.pi)
    assert TrigTorque(0, ((3, 1, 0), (1, 1, 0))).period == pytest.approx(2 * math.pi)
