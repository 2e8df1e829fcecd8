"""Linkage physics (exgen.mechanics.linkages, slider_cranks; whole positions as the figures compose them) against the course text's chapter 7.

Printed values come from the four-bar example (§7.9) and the slider-crank example (§7.10).
Erratum: the four-bar example's analytical method prints θ3 = 6.14°; eq 7.5 with its own
numbers gives 5.146° (the loop-closure test below confirms it; θ4 = 66.38° is right).
"""
import math

import pytest

from exgen.figures.linkage_poses import joints, pose
from exgen.mechanics import linkages as lk
from exgen.mechanics.slider_cranks import slider_crank

deg, rad = math.degrees, math.radians


def is_crossed(points) -> bool:
    """Whether the loop A-B-C-D crosses itself (the crossed configuration), else it is open."""
    def cross(p1, p2, q1, q2):
        return lk.side(p1, p2, q1) * lk.side(p1, p2, q2) < 0 and lk.side(q1, q2, p1) * lk.side(q1, q2, p2) < 0

    a, b, c, d = (points[k] for k in "ABCD")
    return cross(a, b, c, d) or cross(b, c, d, a)


def close_loop(ground, crank, coupler, rocker, theta2, pos):
    """A -> B -> C must end at D: the vector loop R2 + R3 = R1 + R4."""
    x = crank * math.cos(theta2) + coupler * math.cos(pos.theta3) - rocker * math.cos(pos.theta4) - ground
    y = crank * math.sin(theta2) + coupler * math.sin(pos.theta3) - rocker * math.sin(pos.theta4)
    return math.hypot(x, y)


def test_four_bar_example_analytical_method():
    pos = pose(14, 8, 16, 10, rad(75), circuit=1)
    assert pos.bd == pytest.approx(14.2135, abs=5e-5)            # printed BE = 14.2135
    # printed γ = 61.2377°: the exact 61.23794° rounds to 61.2379 (a slip in the fourth decimal)
    assert deg(pos.gamma) == pytest.approx(61.2377, abs=5e-4)
    # Erratum: printed θ3 = 6.14°; eq 7.5 gives 2 tan⁻¹(1.0390 / 23.1177) = 5.146°.
    assert deg(pos.theta3) == pytest.approx(5.146, abs=5e-4)
    assert deg(pos.theta4) == pytest.approx(66.38, abs=5e-3)     # printed θ4 = 66.38°
    assert close_loop(14, 8, 16, 10, rad(75), pos) < 1e-12
    assert deg(pos.theta4 - pos.theta3) == pytest.approx(deg(pos.gamma))  # circuit 1: θ4 = θ3 + γ


def test_four_bar_example_vector_method_in_its_own_frame():
    """The suspension of Figure 7.28: E (rocker pivot) at the origin, A 14 above it, θ2 = 195°."""
    points = joints(14, 8, 16, 10, rad(195), circuit=2, origin=(0, 14), theta1=rad(-90))
    b, c, d = points["B"], points["C"], points["D"]
    assert d == pytest.approx((0, 0), abs=1e-12)
    # the text's R3 runs from its D (our C) to B: θ3 = 84.87°; its θ4 = 203.65° (203.62° in Fig 7.32)
    assert deg(math.atan2(b[1] - c[1], b[0] - c[0])) == pytest.approx(84.854, abs=5e-3)
    assert deg(math.atan2(c[1], c[0])) % 360 == pytest.approx(203.616, abs=5e-3)
    alpha = lk.cosine_law_angle(16, 14, 28)
    assert deg(alpha) == pytest.approx(137.82, abs=5e-3)          # printed α = 137.82°
    theta3 = math.atan2(c[1] - b[1], c[0] - b[0])
    point = lk.coupler_point(c, theta3, 14, alpha, left_of_bc=False)
    assert point == pytest.approx((-19.45, -13.50), abs=0.006)    # printed R_C = (-19.45, -13.50)


def test_four_bar_example_by_the_vector_method_as_one_pose():
    """The same suspension by rocker_pin (R_H, φ by the cosine law, θ4 = θ_H + φ) and plate_pose (the plate's
    point C, our P): the text's θ4 and R_C, and the joints the text's loop places, A -> B -> C ending at D."""
    b, c = lk.rocker_pin((0, 14), 8, 16, 10, rad(195), turn=1.0)
    assert b == pytest.approx((-7.73, 11.93), abs=5e-3)                  # R_H
    assert deg(math.atan2(c[1], c[0])) % 360 == pytest.approx(203.616, abs=5e-3)
    assert (math.dist(b, c), math.hypot(*c)) == pytest.approx((16, 10))
    pose = lk.plate_pose((0, 14), 8, 16, 10, rad(195), 1.0, 14, 28, left=False)
    assert pose["P"] == pytest.approx((-19.45, -13.50), abs=0.006)       # printed R_C
    assert (math.dist(pose["C"], pose["P"]), math.dist(pose["B"], pose["P"])) == pytest.approx((14, 28))
    other = lk.plate_pose((0, 14), 8, 16, 10, rad(195), -1.0, 14, 28, left=False)["C"]
    assert lk.side(b, (0, 0), c) < 0 < lk.side(b, (0, 0), other)        # turn +1: C on the right of B -> D


def test_a_point_is_inside_a_triangle_only_within_its_three_edges():
    corners = [(0, 0), (4, 0), (0, 3)]
    assert lk.inside_triangle((1, 1), corners) and lk.inside_triangle((1, 1), corners[::-1])
    assert not any(lk.inside_triangle(q, corners) for q in ((3, 2), (-1, 1), (2, -0.1), (5, 0)))


def test_the_example_is_circuit_2_in_its_own_frame_and_circuit_1_mirrored():
    points = joints(14, 8, 16, 10, rad(195), circuit=2, origin=(0, 14), theta1=rad(-90))
    assert lk.side(points["B"], points["D"], points["C"]) < 0    # C on the right of B -> D
    standard = joints(14, 8, 16, 10, rad(75), circuit=1)
    assert lk.side(standard["B"], standard["D"], standard["C"]) > 0
    assert not is_crossed(points) and not is_crossed(standard)


@pytest.mark.parametrize("theta2", range(-175, 180, 10))
@pytest.mark.parametrize("circuit", lk.CIRCUITS)
def test_circuits_close_the_loop_on_their_own_side_of_bd(theta2, circuit):
    ground, crank, coupler, rocker = 7.0, 2.0, 8.0, 5.0   # a crank-rocker: assembles at every θ2
    pos = pose(ground, crank, coupler, rocker, rad(theta2), circuit)
    assert close_loop(ground, crank, coupler, rocker, rad(theta2), pos) < 1e-9
    points = joints(ground, crank, coupler, rocker, rad(theta2), circuit)
    assert (lk.side(points["B"], points["D"], points["C"]) > 0) == (circuit == 1)
    turn = lk.wrap(pos.theta4 - pos.theta3)
    assert turn == pytest.approx(pos.gamma if circuit == 1 else -pos.gamma)


@pytest.mark.parametrize("theta2", range(5, 360, 10))
def test_the_two_circuits_are_mirror_images_across_bd(theta2):
    one, two = (joints(7, 2, 8, 5, rad(theta2), circuit) for circuit in lk.CIRCUITS)
    b, d, c1, c2 = one["B"], one["D"], one["C"], two["C"]
    assert math.dist(b, c1) == pytest.approx(math.dist(b, c2)) and math.dist(d, c1) == pytest.approx(math.dist(d, c2))
    assert lk.side(b, d, c1) == pytest.approx(-lk.side(b, d, c2))


def test_circuit_1_is_the_open_configuration_while_the_crank_is_above_the_ground_line():
    for theta2 in range(5, 180, 10):
        assert not is_crossed(joints(7, 2, 8, 5, rad(theta2), 1))
    assert is_crossed(joints(7, 2, 8, 5, rad(45), 2))


def test_a_linkage_that_cannot_reach_does_not_assemble():
    # a triple rocker: at θ2 = 180° BD = L1 + L2 = 12 > L3 + L4 = 11
    assert not lk.can_assemble(8, 4, 6, 5, math.pi)
    with pytest.raises(lk.NotAssemblable, match="cannot span"):
        pose(8, 4, 6, 5, math.pi)
    with pytest.raises(ValueError, match="circuit"):
        pose(7, 2, 8, 5, 0.3, circuit=3)


def test_half_angle_form_survives_its_indeterminate_case():
    # a parallelogram at θ2 = 90°, circuit 2: numerator and denominator of eq 7.7 both vanish
    pos = pose(4, 3, 4, 3, rad(90), circuit=2)
    assert close_loop(4, 3, 4, 3, rad(90), pos) < 1e-9


@pytest.mark.parametrize("lengths, kind, shortest", [
    ((7, 2, 8, 5), "crank-rocker", "crank"),
    ((7, 5, 8, 2), "crank-rocker", "rocker"),      # the shortest beside the ground, either side
    ((2, 7, 8, 5), "double-crank", "ground"),
    ((7, 5, 2, 8), "double-rocker", "coupler"),
    ((14, 8, 16, 10), "change-point", "crank"),    # the four-bar example: 8 + 16 = 14 + 10
    ((8, 4, 6, 5), "triple-rocker", "crank"),
])
def test_grashof_table(lengths, kind, shortest):
    result = lk.grashof(*lengths)
    assert (result.kind, result.shortest) == (kind, shortest)
    assert result.s_plus_l == min(lengths) + max(lengths)
    assert result.p_plus_q == sum(lengths) - result.s_plus_l


def test_limit_positions_of_a_crank_rocker():
    limits = lk.rocker_limits(7, 2, 8, 5)
    for theta2, theta4, reach in ((limits.theta2_extended, limits.theta4_extended, 10),
                                  (limits.theta2_folded, limits.theta4_folded, 6)):
        b = lk.polar((0, 0), 2, theta2)
        c = lk.polar((7, 0), 5, theta4)
        assert math.dist(b, c) == pytest.approx(8)                       # the coupler fits
        assert math.dist((0, 0), c) == pytest.approx(reach)              # A, B, C in line
        pos = pose(7, 2, 8, 5, theta2, 1)
        assert lk.wrap(pos.theta4 - theta4) == pytest.approx(0, abs=1e-6)
    # the rocker never passes its limits: sample the whole turn of the crank
    theta4s = [pose(7, 2, 8, 5, rad(t / 4), 1).theta4 for t in range(1440)]
    low, high = sorted((limits.theta4_extended, limits.theta4_folded))
    assert min(theta4s) == pytest.approx(low, abs=1e-5) and max(theta4s) == pytest.approx(high, abs=1e-5)
    assert limits.swing == pytest.approx(high - low)


def test_limits_need_a_crank_shorter_than_the_coupler():
    with pytest.raises(lk.NotAssemblable):
        lk.rocker_limits(7, 8, 2, 5)


def test_slider_crank_example_vertical_slide():
    """§7.10: A at (2, 1), crank 0.5 at 75°, coupler 1.75, vertical slide 1 to the right of A."""
    s = slider_crank(0.5, 1.75, 1.0, rad(75), "vertical")
    assert deg(s.theta3) == pytest.approx(60.17, abs=5e-3)    # printed 60.17° (60.16° by vectors)
    assert s.l4 == pytest.approx(1.035, abs=5e-4)              # printed L4 = r4 = 1.035 in
    assert deg(s.gamma) == pytest.approx(44.83, abs=5e-3)     # printed γ = 44.83°
    tip = (2 + s.c[0], 1 + s.c[1] - 2.0)                       # the piston tip is 2 below C
    assert tip == pytest.approx((3.0, -2.035), abs=5e-4)       # printed P = (3, -2.035)


@pytest.mark.parametrize("slide", ["horizontal", "vertical"])
@pytest.mark.parametrize("theta2", range(0, 360, 15))
def test_slider_crank_both_branches_keep_the_coupler_length(slide, theta2):
    for branch in ("right", "left") if slide == "horizontal" else ("below", "above"):
        s = slider_crank(0.6, 2.0, 0.3, rad(theta2), slide, branch)
        assert math.dist(s.b, s.c) == pytest.approx(2.0)
        on_line = s.c[1] + 0.3 if slide == "horizontal" else s.c[0] - 0.3
        assert on_line == pytest.approx(0, abs=1e-12)
        assert (s.c[0] > s.b[0]) == (branch == "right") if slide == "horizontal" else \
            (s.c[1] < s.b[1]) == (branch == "below")


def test_horizontal_slider_crank_follows_eqs_7_10_to_7_12():
    s = slider_crank(0.5, 1.75, 0.2, rad(40), "horizontal")
    theta3 = math.asin((0.2 + 0.5 * math.sin(rad(40))) / 1.75)
    assert s.theta3 == pytest.approx(theta3)
    assert s.l4 == pytest.approx(0.5 * math.cos(rad(40)) + 1.75 * math.cos(theta3))
    assert s.gamma == pytest.approx(math.pi - (rad(40) + theta3))
    assert s.c == pytest.approx((s.l4, -0.2))


def test_slider_crank_that_cannot_reach_its_line():
    with pytest.raises(lk.NotAssemblable, match="too short"):
        slider_crank(1.0, 1.5, 1.0, rad(90), "horizontal")
    with pytest.raises(ValueError, match="branches"):
        slider_crank(1.0, 3.0, 0.0, 0.0, "vertical", "right")


def test_synthesis_pivots_are_equidistant():
    p1, p2 = (1.0, 3.0), (4.0, 5.0)
    pivot = lk.bisector_on_line(p1, p2, 0.0)
    assert pivot[1] == 0 and math.dist(pivot, p1) == pytest.approx(math.dist(pivot, p2))
    with pytest.raises(lk.NotAssemblable):
        lk.bisector_on_line((1, 3), (1, 5), 0.0)


def test_circumcentre_is_as_far_from_three_positions():
    # three positions of a pin on a circle about (100, -50) of radius 300: the pivot is its centre
    centre, radius = (100.0, -50.0), 300.0
    trio = [(centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a)) for a in (0.3, 1.2, 2.5)]
    assert lk.circumcentre(*trio) == pytest.approx(centre)
    with pytest.raises(lk.NotAssemblable):
        lk.circumcentre((0, 0), (1, 1), (2, 2))
