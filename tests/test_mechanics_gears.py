"""Gear physics (exgen.mechanics.gears): train values, the epicyclic table against the formula, referral to a motor."""
import itertools
import math

import pytest

from exgen.mechanics import gears as mg


@pytest.mark.parametrize("meshes, expected", [
    ([(20, 40, mg.EXTERNAL)], -0.5),
    ([(20, 40, mg.EXTERNAL), (40, 60, mg.EXTERNAL)], 20 / 60),            # an idler's teeth cancel
    ([(12, 30, mg.EXTERNAL), (15, 30, mg.EXTERNAL), (12, 32, mg.EXTERNAL)], -0.075),  # Example 1.7 by teeth
    ([(15, 22.5, mg.EXTERNAL), (22.5, 60, mg.INTERNAL)], -0.25),          # sun to ring, arm held
])
def test_train_value(meshes, expected):
    assert mg.train_value(meshes) == pytest.approx(expected)


CONFIGURATIONS = [(f, d) for f, d in itertools.product(["sun", "ring"], ["arm", "sun", "ring"]) if f != d]


@pytest.mark.parametrize("fixed, driver", CONFIGURATIONS)
@pytest.mark.parametrize("ts, tp", [(30, 35), (15, 22.5), (40, 16)])
def test_table_method_agrees_with_the_train_value_formula(fixed, driver, ts, tp):
    tr = mg.ring_teeth(ts, tp)
    w = mg.epicyclic_speeds(fixed, driver, -125.0, ts, tp, tr)
    assert w[fixed] == 0 and w[driver] == pytest.approx(-125.0)
    assert (w["ring"] - w["arm"]) / (w["sun"] - w["arm"]) == pytest.approx(mg.epicyclic_value(ts, tr))
    # the planet turns about the arm as a simple gear meshing with the sun
    assert (w["planet"] - w["arm"]) / (w["sun"] - w["arm"]) == pytest.approx(-ts / tp)


def test_the_fixed_member_must_be_a_gear():
    with pytest.raises(ValueError, match="sun or the ring"):
        mg.arm_held_turns("arm", 20, 20, 60)


@pytest.mark.parametrize("module, teeth, pd", [(0.002, 30, 1 / 0.002), (0.0254 / 12, 12, 12 / 0.0254)])
def test_module_and_diametral_pitch_are_reciprocal(module, teeth, pd):
    assert mg.diametral_pitch(module) == pytest.approx(pd)
    assert mg.pitch_diameter(teeth, module) == pytest.approx(mg.pitch_diameter_dp(teeth, pd))
    assert mg.circular_pitch(module) == pytest.approx(math.pi * mg.pitch_diameter(teeth, module) / teeth)


def test_referring_to_the_motor_and_back():
    # Example 1.12: 275 kg m² at n = 0.1 through 90 % is 3.056 kg m² at the motor; 1651.5 N m is 183.5 N m
    assert mg.referred_inertia(275, 0.1, 0.9) == pytest.approx(275 * 0.01 / 0.9)
    assert mg.referred_torque(1651.5, 0.1, 0.9) == pytest.approx(183.5)
    assert mg.available_torque(mg.referred_torque(1000, 0.1, 0.9), 0.1, 0.9) == pytest.approx(1000)


@pytest.mark.parametrize("omega, word", [(3.0, "counter-clockwise"), (-3.0, "clockwise")])
def test_sense_and_sign(omega, word):
    assert mg.sense(omega) == word
    assert mg.signed(abs(omega), word) == omega


def test_reverted_teeth_of_example_1_8():
    assert mg.reverted_teeth(2, 24, 120, 3, 24) == 72
    assert mg.centre_distance(0.048, 0.240) == pytest.approx(0.144)
    assert mg.centre_distance(0.03, 0.12, internal=True) == pytest.approx(0.045)
