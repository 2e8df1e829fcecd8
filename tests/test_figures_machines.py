"""The vehicle on a hill and the robot arm: drawn to the data, the asked angle never drawn to its answer."""
import math

import pytest

from exgen.figures.machines import CAR_M, CAR_PX, HILL, robot_arm, vehicle_on_hill
from svg_helpers import circles, elements, root, texts, variant_of

SVG = "{http://www.w3.org/2000/svg}"


def _slope(line):
    return math.atan2(float(line.get("y1")) - float(line.get("y2")), float(line.get("x2")) - float(line.get("x1")))


@pytest.mark.parametrize("radius", [0.28, 0.33, 0.38])
def test_wheels_follow_the_wheel_radius_at_the_car_scale(bank, radius):
    svg = vehicle_on_hill(variant_of(bank, "gears.vehicle_gradient", r=radius))
    wheels = circles(svg, "wheel")
    assert len(wheels) == 2
    for wheel in wheels:
        assert float(wheel.get("r")) == pytest.approx(radius * CAR_PX / CAR_M, abs=0.01)
    assert f"r = {radius:g} m" in texts(svg)


def test_the_hill_is_drawn_at_a_nominal_angle_and_asked(bank):
    slopes = set()
    for seed in (1, 2, 3):
        svg = vehicle_on_hill(variant_of(bank, "gears.vehicle_gradient", seed=seed))
        (road,) = elements(svg, "road")
        slopes.add(round(_slope(road), 3))
        labels = texts(svg)
        assert "θ = ?" in labels and any(t.startswith("v = ") for t in labels)
    assert slopes == {round(HILL, 3)}


@pytest.mark.parametrize("theta", [10, 35, 70])
def test_the_arm_is_at_its_angle_above_the_horizontal(bank, theta):
    svg = robot_arm(variant_of(bank, "gears.robot_arm", theta=theta))
    (mass,) = circles(svg, "centre-of-mass")
    x, y = float(mass.get("cx")), float(mass.get("cy"))
    assert math.degrees(math.atan2(-y, x)) == pytest.approx(theta, abs=0.05)
    assert f"θ = {theta}°" in texts(svg)


@pytest.mark.parametrize("k12, k34", [(1.5, 2), (3, 4), (2.5, 1.5)])
def test_gear_pairs_are_drawn_to_their_ratios(bank, k12, k34):
    svg = robot_arm(variant_of(bank, "gears.robot_arm", k12=k12, k34=k34))
    radius = {}
    for name in ("gear1", "gear2", "gear3", "gear4"):
        pitch = [c for c in root(svg).iter(f"{SVG}circle") if c.get("class") == f"pitch {name}"]
        radius[name] = float(pitch[0].get("r"))
    assert radius["gear2"] / radius["gear1"] == pytest.approx(k12, rel=1e-3)
    assert radius["gear4"] / radius["gear3"] == pytest.approx(k34, rel=1e-3)
    assert radius["gear2"] > radius["gear3"]  # gear 2 shows as a ring round gear 3 on their shaft
