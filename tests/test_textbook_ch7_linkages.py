"""Chapter 7 templates against the course text's worked examples, through exgen.check.given.

Printed values: the four-bar example (§7.9: the vector method in its own frame, then the
analytical method in the frame turned to the ground line) and the slider-crank example (§7.10).
Errata and slips, each recomputed independently below:
- four-bar example, analytical method: θ3 is printed 6.14°; eq 7.5 with the example's own
  numbers gives 2 tan⁻¹(1.0390 / 23.1177) = 5.146°, and the vector method agrees (84.87° for the
  text's R3 from its D to B is 264.85° for B to C, turned back by the frame's 90° and mirrored:
  5.15°). θ4 = 66.38° is right.
- the same: γ is printed 61.2377°; cos⁻¹((16² + 10² − 14.21353²)/320) = 61.23794°.
- the vector method rounds θ_H to 123° and so prints φ = 80.65° and θ4 = 203.65°; unrounded they
  are 80.68° and 203.62° (Figure 7.32 has 203.62°).
Problems 7.1-7.4 give their data in figures the text does not carry; the templates that follow
them are checked here on data of our own, against the same equations worked by hand.
"""
import math

import pytest

from exgen.check.given import solve
from textbook_helpers import answers_and_steps


deg, rad = math.degrees, math.radians


def test_four_bar_example_analytical_method(bank):
    got, steps, warnings = answers_and_steps(bank, "linkages.fourbar_position", L1="14 inch", L2="8 inch", L3="16 inch",
                                   L4="10 inch", theta2="75 deg", circuit="1")
    assert got["a"] == pytest.approx(14.2135 * 25.4, abs=5e-5 * 25.4)      # BE = 14.2135
    assert got["b"] == pytest.approx(61.2377, abs=5e-4)                    # γ (exactly 61.23794°)
    # Erratum: the text prints θ3 = 6.14°; eq 7.5 gives 5.146°.
    assert got["c"] == pytest.approx(5.146, abs=5e-4)
    assert got["c"] != pytest.approx(6.14, abs=0.5)
    assert got["d"] == pytest.approx(66.38, abs=5e-3)
    assert warnings == []


def test_four_bar_example_vector_method_and_point_c(bank):
    got, steps, warnings = answers_and_steps(bank, "linkages.coupler_point", xA="0 inch", yA="14 inch", L2="8 inch",
                                   L3="16 inch", L4="10 inch", theta2="195 deg", circuit="2", CP="14 inch",
                                   BP="28 inch", side="right")
    inch = 0.0254
    assert (steps["xB"] / inch, steps["yB"] / inch) == pytest.approx((-7.73, 11.93), abs=5e-3)   # R_H
    assert deg(steps["theta_H"]) == pytest.approx(123, abs=0.1)            # printed 123° (rounded)
    # printed r_H = 14.22 from the rounded components (7.73, 11.93); it is the analytical method's BE
    assert steps["r_H"] / inch == pytest.approx(14.2135, abs=5e-5)
    assert deg(steps["phi"]) == pytest.approx(80.65, abs=0.05)             # printed from θ_H = 123°
    assert got["a"] % 360 == pytest.approx(203.62, abs=5e-3)               # θ4 (Figure 7.32)
    # the text's R3 runs from its D (our C) to B: 84.87°; B to C is 180° round
    assert (got["b"] + 180) % 360 == pytest.approx(84.87, abs=0.02)
    assert got["c"] == pytest.approx(137.82, abs=5e-3)                     # α
    assert deg(steps["theta6"]) % 360 == pytest.approx(222.68, abs=0.02)   # θ6 = θ3 + α (text's θ3)
    # printed C = (-19.45, -13.50) from angles rounded to 0.01°; unrounded (-19.4552, -13.4961)
    assert got["d"] / 25.4 == pytest.approx(-19.4552, abs=5e-5)
    assert got["e"] / 25.4 == pytest.approx(-13.4961, abs=5e-5)
    assert (got["d"] / 25.4, got["e"] / 25.4) == pytest.approx((-19.45, -13.50), abs=0.006)
    assert warnings == []


def test_slider_crank_example(bank):
    """§7.10: A at (2, 1) from O, crank 0.5 at 75°, coupler 1.75, slide vertical 1 right of A, P 2 below C."""
    got, steps, warnings = answers_and_steps(bank, "linkages.slider_crank", slider="below", L1="1 inch", L2="0.5 inch",
                                   L3="1.75 inch", theta2="75 deg", xA="2 inch", yA="1 inch", tip="2 inch")
    assert deg(steps["theta3"]) == pytest.approx(60.17, abs=5e-3)          # eq 7.13
    assert got["a"] == pytest.approx(-60.17, abs=5e-3)                     # the vector method's -60.16°
    assert got["b"] == pytest.approx(1.035 * 25.4, abs=5e-4 * 25.4)        # L4 = r4 = 1.035 in
    assert got["c"] == pytest.approx(44.83, abs=5e-3)                      # γ, eq 7.12
    assert got["d"] == pytest.approx(3 * 25.4, abs=1e-9)                   # x_P = 3 in
    assert got["e"] == pytest.approx(-2.035 * 25.4, abs=5e-4 * 25.4)       # y_P = -2.035 in
    assert warnings == []


def test_horizontal_offset_slider_crank_turned_35_degrees_clockwise(bank):
    """Problem 7.1's form: an offset crank turned 35° clockwise (θ2 = 325°), eqs 7.10-7.12 by hand."""
    got, steps, _ = answers_and_steps(bank, "linkages.slider_crank", slider="right", L1="20 mm", L2="50 mm", L3="180 mm",
                            theta2="325 deg", xA="0 mm", yA="0 mm", tip="60 mm")
    theta2 = rad(-35)
    theta3 = math.asin((20 + 50 * math.sin(theta2)) / 180)
    l4 = 50 * math.cos(theta2) + 180 * math.cos(theta3)
    assert got["a"] == pytest.approx(-deg(theta3))
    assert got["b"] == pytest.approx(l4)
    # eq 7.12 gives 180° - (θ2 + θ3) = 217.8° here: past 180°, the angle ABC is its explement
    assert 180 - deg(theta2 + theta3) > 180
    assert got["c"] == pytest.approx(360 - (180 - deg(theta2 + theta3)))
    assert (got["d"], got["e"]) == pytest.approx((l4 + 60, -20))


def test_slider_on_the_other_branch(bank):
    got, _, _ = answers_and_steps(bank, "linkages.slider_crank", slider="left", L1="0 mm", L2="50 mm", L3="180 mm",
                        theta2="60 deg", xA="100 mm", yA="50 mm", tip="40 mm")
    theta3 = math.asin(50 * math.sin(rad(60)) / 180)
    assert got["a"] % 360 == pytest.approx(180 + deg(theta3))    # down to the left
    l4 = 180 * math.cos(theta3) - 50 * math.cos(rad(60))
    assert got["b"] == pytest.approx(l4)
    assert (got["d"], got["e"]) == pytest.approx((100 - l4 - 40, 50))


# §7.5: "Knowing which category can help choose the right input. This may form electric motors for continuous
# revolutions or hydraulic cylinders for rocking motions": a motor where a link pivoted on the frame turns fully.
@pytest.mark.parametrize("lengths, ground, kind, actuator", [
    ((14, 8, 16, 10), "DA", "change-point", "motor"),       # the four-bar example: 8 + 16 = 14 + 10; AB turns
    ((70, 20, 80, 50), "DA", "crank-rocker", "motor"),      # the shortest, AB, beside the ground
    ((70, 20, 80, 50), "AB", "double-crank", "motor"),      # the shortest grounded
    ((70, 20, 80, 50), "CD", "double-rocker", "cylinder"),  # the link opposite the shortest grounded
    ((80, 40, 60, 50), "DA", "triple-rocker", "cylinder"),  # 40 + 80 > 60 + 50
])
def test_grashof_table_7_1(bank, lengths, ground, kind, actuator):
    da, ab, bc, cd = lengths
    got, steps, _ = answers_and_steps(bank, "linkages.grashof", AB=f"{ab} mm", BC=f"{bc} mm", CD=f"{cd} mm",
                            DA=f"{da} mm", ground=ground)
    assert got["a"] == min(lengths) + max(lengths)
    assert got["b"] == sum(lengths) - min(lengths) - max(lengths)
    assert got["c"] == kind
    assert got["d"] == actuator


def test_crank_rocker_limit_positions(bank):
    got, _, _ = answers_and_steps(bank, "linkages.rocker_swing", L1="70 mm", L2="20 mm", L3="80 mm", L4="50 mm")
    ext = 180 - deg(math.acos((70 ** 2 + 50 ** 2 - 100 ** 2) / (2 * 70 * 50)))
    fold = 180 - deg(math.acos((70 ** 2 + 50 ** 2 - 60 ** 2) / (2 * 70 * 50)))
    assert (got["a"], got["b"], got["c"]) == pytest.approx((ext, fold, abs(ext - fold)))


def test_support_link_retracted_by_its_actuator(bank):
    """Problem 7.2's form: A at the origin, O at (400, -100) mm, B 300 mm up the link, 600 -> 400 mm."""
    got, _, _ = answers_and_steps(bank, "linkages.actuator_swing", xO="400 mm", yO="-100 mm", r="300 mm", s1="600 mm",
                        s2="400 mm", side="left")
    ao = math.hypot(400, -100)
    beta = math.atan2(-100, 400)
    before = beta + math.acos((ao ** 2 + 300 ** 2 - 600 ** 2) / (2 * ao * 300))
    after = beta + math.acos((ao ** 2 + 300 ** 2 - 400 ** 2) / (2 * ao * 300))
    assert got["a"] == pytest.approx(deg(before))
    assert got["b"] == pytest.approx(deg(after))
    assert got["c"] == pytest.approx(deg(before - after))
    assert got["d"] == "clockwise"


def test_two_position_synthesis_pivots_on_the_floor(bank):
    got, steps, _ = answers_and_steps(bank, "linkages.two_position_synthesis", b="200 mm", xM1="-300 mm", yM1="300 mm",
                            phi1="30 deg", xM2="100 mm", yM2="450 mm", phi2="-20 deg")
    m1, m2 = (-300, 300), (100, 450)
    n1 = (m1[0] + 200 * math.cos(rad(30)), m1[1] + 200 * math.sin(rad(30)))
    n2 = (m2[0] + 200 * math.cos(rad(-20)), m2[1] + 200 * math.sin(rad(-20)))
    for (p1, p2), x_part, r_part in (((m1, m2), "a", "b"), ((n1, n2), "c", "d")):
        x = got[x_part]
        assert math.hypot(p1[0] - x, p1[1]) == pytest.approx(math.hypot(p2[0] - x, p2[1]))  # on the bisector
        assert got[r_part] == pytest.approx(math.hypot(p1[0] - x, p1[1]))
    assert got["e"] in ("crank-rocker", "double-crank", "double-rocker", "change-point", "triple-rocker")


@pytest.mark.parametrize("case, counts", [
    ("four-bar", (4, 4, 1, 1, "mechanism")),                 # the parallelogram itself: the count holds
    ("three cranks", (5, 6, 0, 1, "mechanism")),             # Figure 7.13's exception: M = 0, yet it moves
    ("three cranks, one askew", (5, 6, 0, 0, "structure")),  # the same count, and truly locked
    ("four cranks", (6, 8, -1, 1, "mechanism")),
])
def test_section_7_4_where_grueblers_equation_misleads(bank, case, counts):
    # §7.4: "The KMoGE does not account for link sizes and shapes. It can give misleading results in the case of
    # unique geometric configurations. Hence, logic or intuition must be used determining the mobility value"
    # (seize-and-fix). M = 3(5 - 1) - 2(6) = 0 for three parallel cranks on one coupler, which still moves.
    got, _, warnings = answers_and_steps(bank, "linkages.mobility_exceptions", case=case, theta="75 deg", mirror="no",
                                         r="100 mm", a="200 mm")
    assert tuple(got[k] for k in "abcde") == counts
    assert warnings == []


def test_four_bar_example_question_2_both_roots_then_the_one_drawn(bank):
    # §7.9, question 2: r1 = 14 (A straight above D), r2 = 8 at 195 deg, r3 = 16, r4 = 10 (inches).
    # R_H = (-7.73, 11.93), theta_H = 123 deg, phi = 80.65 deg: theta4 = theta_H + phi = 203.65 deg, "the one
    # that corresponds to the figure"; the other root is theta_H - phi = 42.35 deg (from the rounded 123 deg;
    # exactly 42.25). The text's theta3 = 84.87 deg is the loop's R3 from C to B; the sheet asks B -> C.
    given = dict(xA="0 inch", yA="14 inch", L2="8 inch", L3="16 inch", L4="10 inch", theta2="195 deg")
    got, steps, _ = answers_and_steps(bank, "linkages.fourbar_both_roots", circuit="2", **given)
    assert got["a"] % 360 == pytest.approx(203.65, abs=0.05)
    assert got["b"] % 360 == pytest.approx(123 - 80.65, abs=0.15)
    # phi is 80.68 deg from the exact r_H = 14.2135 (the text's BE); the text's 80.65 is from r_H rounded to 14.22
    assert deg(steps["phi"]) == pytest.approx(80.68, abs=0.005) and steps["r_H"] == pytest.approx(14.2135 * 0.0254, rel=1e-5)
    assert got["c"] == "plus"
    assert (got["d"] + 180) % 360 == pytest.approx(84.87, abs=0.05)
    # drawn the other way, the same two roots, and the other is picked
    mirrored, _, _ = answers_and_steps(bank, "linkages.fourbar_both_roots", circuit="1", **given)
    assert (mirrored["a"], mirrored["b"]) == (pytest.approx(got["a"]), pytest.approx(got["b"]))
    assert mirrored["c"] == "minus"


@pytest.mark.parametrize("centre, verdict", [((0, -100), "neither"), ((0, 100), "both")])
def test_three_position_synthesis_pivot_is_the_circumcentre_and_the_floor_test(bank, centre, verdict):
    # §7.11 (Problem 7.4 asks the same of a bottle): the fixed pivot of a moving pivot is where the perpendicular
    # bisectors of its three positions cross. The text gives no numbers: M's positions are put on a circle
    # (about (0, -100) of radius 500, or about (0, 100) of radius 250), so E must come back at its centre, and
    # "below the floor - usually a bad selection", "higher than the floor indicating good selection".
    radius = 500 if centre[1] < 0 else 250
    ms = [(-400, 200), (0, 400), (300, 300)] if centre[1] < 0 else [(-240, 170), (0, 350), (200, 250)]
    assert all(math.dist(m, centre) == pytest.approx(radius) for m in ms)
    phis = (60, 0, -30)
    given = {"b": "200 mm"}
    for k, ((x, y), phi) in enumerate(zip(ms, phis), start=1):
        given.update({f"xM{k}": f"{x} mm", f"yM{k}": f"{y} mm", f"phi{k}": f"{phi} deg"})
    got, _, warnings = answers_and_steps(bank, "linkages.three_position_synthesis", **given)
    assert (got["a"], got["b"], got["c"]) == (pytest.approx(centre[0], abs=1e-9), pytest.approx(centre[1]),
                                              pytest.approx(radius))
    ns = [(x + 200 * math.cos(rad(phi)), y + 200 * math.sin(rad(phi))) for (x, y), phi in zip(ms, phis)]
    f = (got["d"], got["e"])
    distances = [math.dist(n, f) for n in ns]
    assert distances == pytest.approx([distances[0]] * 3)                # F as far from N1, N2 and N3
    assert (f[1] > 0) == (centre[1] > 0) and got["f"] == verdict
    assert warnings == []


@pytest.mark.parametrize("slider, line, where", [
    ("right", "horizontal line of slide 20 mm below A", "with the slider to the right of A."),
    ("left", "horizontal line of slide 20 mm below A", "with the slider to the left of A."),
    ("below", "vertical line of slide 20 mm to the right of A", "with the slider below A."),
    ("above", "vertical line of slide 20 mm to the right of A", "with the slider above A."),
])
def test_slider_crank_statement_says_where_the_slider_runs_in_plain_words(bank, slider, line, where):
    variant, _ = solve(bank.get("linkages.slider_crank"), {
        "slider": slider, "L1": "20 mm", "L2": "50 mm", "L3": "180 mm", "theta2": "60 deg", "xA": "0 mm",
        "yA": "0 mm", "tip": "40 mm"})
    statement = " ".join(variant.statement.split())
    assert line in statement and where in statement


def test_slider_crank_example_both_roots_then_the_one_drawn(bank):
    # §7.10: crank 0.5 in at 75 deg, coupler 1.75 in, a vertical line of slide 1 in right of A. The loop
    # across the line gives cos theta3 = 0.4975, "theta3 = 60.16 deg or -60.16 deg"; "based on the problem"
    # the slider is below, theta3 = -60.16 deg, and r4 = 1.035 in down the line: y_C = -1.035 in from A.
    given = dict(line="right", L1="1 inch", L2="0.5 inch", L3="1.75 inch", theta2="75 deg")
    got, steps, _ = answers_and_steps(bank, "linkages.slider_crank_both_roots", assembly="2", **given)
    assert steps["ratio"] == pytest.approx(0.4975, abs=5e-5)
    assert got["a"] == pytest.approx(60.16, abs=0.01)
    assert got["b"] == pytest.approx(-60.16, abs=0.01)
    assert got["c"] == "second"
    assert got["d"] / 25.4 == pytest.approx(-1.035, abs=5e-4)
    # drawn the other way: the same two roots, the first picked, the slider above B
    other, _, _ = answers_and_steps(bank, "linkages.slider_crank_both_roots", assembly="1", **given)
    assert (other["a"], other["b"]) == (pytest.approx(got["a"]), pytest.approx(got["b"]))
    assert other["c"] == "first"
    assert other["d"] / 25.4 == pytest.approx(0.5 * math.sin(rad(75)) + 1.75 * math.sin(rad(60.165)), abs=1e-3)


def test_horizontal_slider_crank_roots_are_the_sine_and_its_supplement(bank):
    # eq 7.10's line L1 below A: sin theta3 = (-L1 - L2 sin theta2) / L3, and "theta3 or (180 deg - theta3)".
    got, _, _ = answers_and_steps(bank, "linkages.slider_crank_both_roots", line="below", L1="20 mm", L2="50 mm",
                                  L3="180 mm", theta2="60 deg", assembly="1")
    first = math.asin((-20 - 50 * math.sin(rad(60))) / 180)
    assert got["a"] == pytest.approx(deg(first))
    assert got["b"] % 360 == pytest.approx(180 - deg(first))
    assert got["c"] == "first" and got["d"] == pytest.approx(50 * math.cos(rad(60)) + 180 * math.cos(first))


def test_four_bar_example_question_1_lengths_measured_then_point_c(bank):
    # §7.9 question 1 measures the triangular body off the figure: 16, 14 and 28 in (and the links 8 and 10 in,
    # with the ground's 14 in the one dimension); α = 137.82°; then, with the crank turned to 195°, the same
    # θ4, θ3 and C as the printed vector method (see test_four_bar_example_vector_method_and_point_c). The
    # figure's pose is data of our own (the text's figure does not survive): drawn at 120°, the same assembly.
    got, steps, warnings = answers_and_steps(bank, "linkages.coupler_point_reading", yA="14 inch", AB="8 inch",
                                             BC="16 inch", DC="10 inch", PC="14 inch", PB="28 inch", theta2="195 deg",
                                             circuit="2", side="right", drawn="120 deg")
    inch = 25.4
    assert [got[k] / inch for k in "abcde"] == pytest.approx([8, 16, 10, 14, 28])     # the lengths measured
    assert got["h"] == pytest.approx(137.82, abs=5e-3)                               # α
    assert got["f"] % 360 == pytest.approx(203.62, abs=5e-3)                         # θ4 (Figure 7.32)
    assert (got["g"] + 180) % 360 == pytest.approx(84.87, abs=0.02)                  # the text's θ3, D to B
    assert (got["i"] / inch, got["j"] / inch) == pytest.approx((-19.45, -13.50), abs=0.006)
    assert warnings == []


def test_problem_7_1_lengths_measured_then_the_crank_turned_35_degrees_clockwise(bank):
    # Problem 7.1 (data of our own): the offset slider-crank drawn with its crank at 60°, turned 35° clockwise
    # to 25°; the lengths read are the printed ones of linkages.slider_crank, which works the same position.
    got, steps, warnings = answers_and_steps(bank, "linkages.slider_crank_reading", slider="right", L3="180 mm",
                                             AB="50 mm", offset="20 mm", piston="60 mm", drawn="60 deg",
                                             turn="35 deg", sense="clockwise")
    printed, _, _ = answers_and_steps(bank, "linkages.slider_crank", slider="right", L1="20 mm", L2="50 mm",
                                      L3="180 mm", theta2="25 deg", xA="0 mm", yA="0 mm", tip="60 mm")
    assert [got[k] for k in "abc"] == pytest.approx([50, 20, 60])
    assert got["d"] == pytest.approx(25)
    assert (got["e"], got["f"], got["g"]) == pytest.approx((printed["a"], printed["b"], printed["d"]))
    theta3 = math.asin((20 + 50 * math.sin(rad(25))) / 180)                          # eq 7.10, below the horizontal
    assert got["e"] == pytest.approx(-deg(theta3))
    assert got["g"] == pytest.approx(50 * math.cos(rad(25)) + 180 * math.cos(theta3) + 60)   # eq 7.11, then the piston
    assert warnings == []
