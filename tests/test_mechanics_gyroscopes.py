"""Gyroscope physics (exgen.mechanics.gyroscopes) against chapter 5's examples and problems.

Values are recomputed here from the data as printed, in double precision with g = 9.81 m/s².
The problems print no answers; where a direction is asked, the expected effect is the one the
right-hand rule gives (and which Khurmi & Gupta, the text's reference 1, state for these cases).
"""
import math

import pytest

from exgen.mechanics import gyroscopes as gy


def rpm(n):
    return 2 * math.pi * n / 60


def kmh(v):
    return v / 3.6


def test_example_5_1_couple_and_springs():
    omega, big_omega = rpm(1500), gy.precession_rate(kmh(60), 30)
    c = gy.couple(4, omega, big_omega)
    force = gy.couple_force(c, 0.3)
    assert omega == pytest.approx(157.08, abs=0.005)
    # Erratum (Example 5.1): the text rounds Ω = 0.5556 rad/s to 0.56 before using it, and prints
    # M' = 351.86 N m, F = 1172.9 N, x = 0.06 m. Unrounded: 349.07 N m, 1163.6 N, 0.0582 m.
    assert big_omega == pytest.approx(0.5556, abs=5e-5)
    assert c == pytest.approx(349.066, abs=5e-4)
    assert force == pytest.approx(1163.55, abs=5e-3)
    assert force / 20e3 == pytest.approx(0.05818, abs=5e-6)
    assert gy.couple(4, omega, 0.56) == pytest.approx(351.8592, abs=0.01)  # the text's rounded working


def test_example_5_1_right_spring_in_tension():
    # A flywheel turning like the road wheels (its spin vector points to the left) on a right turn:
    # the reactive couple H x Ω points rearwards, which lifts the right side and presses the left down.
    c = gy.reactive_couple(gy.wheel_spin(True), gy.turning("right"))
    assert c == pytest.approx((-1, 0, 0))
    assert gy.roll_effect(c) == "left"  # left spring compressed, right spring stretched: as printed


def test_example_5_2_banking_angle():
    iw, ie = 2 * gy.moment_of_inertia(9, 0.225), gy.moment_of_inertia(12, 0.075)
    v = kmh(160)
    omega_w = v / 0.3
    omega_e = 3.5 * omega_w
    momentum = iw * omega_w + ie * omega_e
    assert iw == pytest.approx(0.91125) and ie == pytest.approx(0.0675)  # printed 0.912 and 0.0675
    assert omega_w == pytest.approx(148.15, abs=0.005)                   # printed 148 (and 518 for the engine)
    assert momentum * v / 60 == pytest.approx(125.93, abs=0.005)         # printed 125.88 cos α, from 148 and 518
    assert gy.centrifugal_force(320, v, 60) == pytest.approx(10534.98, abs=0.005)  # printed 10532.87 (v = 44.44)
    couples = (momentum * gy.precession_rate(v, 60), gy.centrifugal_force(320, v, 60) * 0.525)
    angle = math.degrees(gy.heel_angle(*couples, 320, 0.525))
    assert angle == pytest.approx(73.757, abs=5e-4)  # printed 73.75°: the text's rounded ω and v, not a slip


def test_problem_5_1_ship_engine_bearings():
    inertia = gy.moment_of_inertia(100, 0.2)
    c = gy.couple(inertia, rpm(5000), gy.precession_rate(30, 500))
    assert c == pytest.approx(125.664, abs=5e-4)
    # Clockwise seen from behind spins forward; a left turn precesses upwards: H x Ω points to
    # starboard (-y), which raises the bow. The couple lifts the forward bearing's load.
    couple_vector = gy.reactive_couple(gy.axial_spin("clockwise", "rear"), gy.turning("left"))
    assert gy.pitch_effect(couple_vector) == "nose up"
    weight_a, weight_b = gy.weight_shares(100 * gy.G, 0.6, 1.2)
    assert weight_a == weight_b == pytest.approx(490.5)
    force = gy.couple_force(c, 1.2)
    assert force == pytest.approx(104.72, abs=0.005)
    assert (weight_a - force, weight_b + force) == pytest.approx((385.78, 595.22), abs=0.005)  # forward, aft


def test_problem_5_2_aircraft():
    c = gy.couple(gy.moment_of_inertia(400, 0.3), rpm(2400), gy.precession_rate(kmh(200), 50))
    assert c == pytest.approx(10053.1, abs=0.05)
    couple_vector = gy.reactive_couple(gy.axial_spin("clockwise", "rear"), gy.turning("left"))
    assert gy.pitch_effect(couple_vector) == "nose up"  # raises the nose, dips the tail


def test_problem_5_4_ship_turbine():
    c = gy.couple(gy.moment_of_inertia(9000, 0.75), rpm(1500), gy.precession_rate(kmh(100), 90))
    assert c == pytest.approx(245436.9, abs=0.05)
    couple_vector = gy.reactive_couple(gy.axial_spin("counter-clockwise", "rear"), gy.turning("right"))
    assert gy.pitch_effect(couple_vector) == "nose up"  # raises the bow, lowers the stern


@pytest.mark.parametrize("sense, rising, turns", [
    ("clockwise", True, "right"), ("clockwise", False, "left"),
    ("counter-clockwise", True, "left"), ("counter-clockwise", False, "right"),
])
def test_pitching_turns_the_ship(sense, rising, turns):
    couple_vector = gy.reactive_couple(gy.axial_spin(sense, "rear"), gy.pitching(rising))
    assert gy.yaw_effect(couple_vector) == turns and gy.pitch_effect(couple_vector) == ""


def test_rolling_about_the_spin_axis_has_no_gyroscopic_effect():
    for to_right in (True, False):
        couple_vector = gy.reactive_couple(gy.axial_spin("clockwise", "rear"), gy.rolling(to_right))
        assert couple_vector == (0.0, 0.0, 0.0)
        assert gy.pitch_effect(couple_vector) == gy.yaw_effect(couple_vector) == gy.roll_effect(couple_vector) == ""


def test_viewed_from_the_front_reverses_the_sense():
    assert gy.axial_spin("clockwise", "front") == gy.axial_spin("counter-clockwise", "rear")


def test_road_wheels_overturn_outwards_on_either_turn():
    for turn in ("left", "right"):
        couple_vector = gy.reactive_couple(gy.wheel_spin(True), gy.turning(turn))
        assert gy.roll_effect(couple_vector) == gy.outer_side(turn)


def test_problem_5_3_car_reactions():
    # 2000 kg car, wheelbase 2.5 m, track 1.5 m, G 0.5 m up and 1 m behind the front axle; wheels 0.8 m
    # in diameter with I = 0.8 kg m² each; engine parts 75 kg, k = 100 mm, at 4x the wheels, clockwise
    # seen from the front; right turn of 60 m at 60 km/h. Overturning couples shared equally by the axles.
    v, radius = kmh(60), 60
    omega_w, big_omega = v / 0.4, gy.precession_rate(v, radius)
    front_each, rear_each = (2000 * gy.G * (2.5 - 1) / 2.5 / 2, 2000 * gy.G * 1 / 2.5 / 2)
    wheels = gy.couple(4 * 0.8, omega_w, big_omega) / (2 * 1.5)
    engine_c = gy.couple(gy.moment_of_inertia(75, 0.1), 4 * omega_w, big_omega)
    engine = engine_c / (2 * 2.5)
    centrifugal = gy.centrifugal_force(2000, v, radius) * 0.5 / (2 * 1.5)
    assert (wheels, engine, centrifugal) == pytest.approx((12.346, 6.944, 1543.21), abs=5e-3)
    engine_vector = gy.reactive_couple(gy.axial_spin("clockwise", "front"), gy.turning("right"))
    assert gy.pitch_effect(engine_vector) == "nose up"  # the front wheels are relieved, the rear loaded
    assert gy.outer_side("right") == "left"
    front_left = front_each + wheels + centrifugal - engine
    front_right = front_each - wheels - centrifugal - engine
    rear_left = rear_each + wheels + centrifugal + engine
    rear_right = rear_each - wheels - centrifugal + engine
    assert (front_left, front_right, rear_left, rear_right) == pytest.approx(
        (7434.61, 4323.50, 5486.50, 2375.39), abs=0.01)


def test_problem_5_5_rail_car_limiting_speed():
    # Axles (30 kg m² each) turn like the wheels; the motors (15 kg m², 3x) turn against their axles,
    # so Σ I·G = 2(30) - 2(15)(3) = -30 kg m²: the motors' couple outweighs the axles' and eases the inner wheels.
    per_v2 = gy.centrifugal_couple_per_v2(4000, 1.0, 250) + gy.gyroscopic_couple_per_v2(2 * 30 - 2 * 15 * 3, 0.39, 250)
    v = gy.rail_limiting_speed(4000, 1.75, per_v2)
    assert v == pytest.approx(46.776, abs=5e-4) and v * 3.6 == pytest.approx(168.39, abs=0.005)
    with pytest.raises(ValueError, match="no wheel"):
        gy.rail_limiting_speed(4000, 1.75, gy.centrifugal_couple_per_v2(4000, 0.01, 250)
                               + gy.gyroscopic_couple_per_v2(-500, 0.39, 250))


def test_problem_5_6_motorcycle_heel():
    v = kmh(50)
    omega_w = v / 0.25
    momentum = 2 * 1.75 * omega_w + 0.25 * 4 * omega_w  # engine in the same sense as the wheels
    assert momentum * v / 30 == pytest.approx(115.74, abs=0.005)
    couples = (momentum * gy.precession_rate(v, 30), gy.centrifugal_force(275, v, 30) * 0.5)
    assert math.degrees(gy.heel_angle(*couples, 275, 0.5)) == pytest.approx(36.548, abs=5e-4)


def test_pitching_rate_is_the_amplitude_times_the_circular_frequency():
    assert gy.pitching_rate(math.radians(6), 20) == pytest.approx(math.radians(6) * 2 * math.pi / 20)
