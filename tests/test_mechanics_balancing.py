"""Balancing physics (exgen.mechanics.balancing, .engines): vectors, crank layouts and their error paths."""
import math

import pytest

from exgen.mechanics import balancing as mb
from exgen.mechanics import engines as me

DEG = math.pi / 180


@pytest.mark.parametrize("x, y, size, angle_deg", [
    (3, 4, 5, 53.1301), (-3, -4, 5, 233.1301), (1, -1e-17, 1, 0.0), (0, -2, 2, 270), (-1, 0, 1, 180),
])
def test_polar_gives_an_angle_in_a_full_turn(x, y, size, angle_deg):
    got = mb.polar(x, y)
    assert got[0] == pytest.approx(size) and math.degrees(got[1]) == pytest.approx(angle_deg, abs=1e-4)
    assert 0 <= got[1] < 2 * math.pi


def test_balancing_vector_closes_the_polygon():
    vectors = [(3, 0), (4, 90 * DEG), (2.5, 200 * DEG)]
    size, angle = mb.balancing_vector(vectors)
    x, y = mb.vector_sum(vectors + [(size, angle)])
    assert abs(x) < 1e-12 and abs(y) < 1e-12


@pytest.mark.parametrize("target, a1, a2", [((1, 2), 0, 90 * DEG), ((-3, 0.5), 30 * DEG, 200 * DEG), ((0, 0), 10 * DEG, 80 * DEG)])
def test_two_directions_solves_for_the_sizes(target, a1, a2):
    s1, s2 = mb.two_directions(target, a1, a2)
    assert mb.vector_sum([(s1, a1), (s2, a2)]) == pytest.approx(target, abs=1e-12)


def test_two_parallel_directions_have_no_unique_sizes():
    with pytest.raises(ValueError, match="parallel"):
        mb.two_directions((1, 1), 30 * DEG, 210 * DEG)


def test_two_plane_correction_balances_forces_and_moments():
    rows = [(0.08, 1.2, 90 * DEG), (0.05, 2.4, 0.0), (0.03, -0.3, 200 * DEG)]
    (q, qa), (p, pa) = mb.two_plane_correction(rows, 3.6)
    all_rows = rows + [(q, 3.6, qa), (p, 0.0, pa)]
    assert mb.vector_sum((mr, a) for mr, _, a in all_rows) == pytest.approx((0, 0), abs=1e-12)
    assert mb.vector_sum((mr * l, a) for mr, l, a in all_rows) == pytest.approx((0, 0), abs=1e-12)


@pytest.mark.parametrize("order, strokes, expected_deg", [
    ((1, 3, 4, 2), 4, {1: 0, 3: 180, 4: 0, 2: 180}),
    ((1, 3, 4, 2), 2, {1: 0, 3: 90, 4: 180, 2: 270}),
    ((1, 3, 5, 6, 4, 2), 4, {1: 0, 3: 120, 5: 240, 6: 0, 4: 120, 2: 240}),  # Example 2.7
])
def test_crank_angles_follow_the_firing_order(order, strokes, expected_deg):
    got = me.crank_angles(order, strokes)
    assert {k: round(math.degrees(v)) % 360 for k, v in got.items()} == expected_deg


@pytest.mark.parametrize("order, strokes, words", [((1, 2, 2), 4, "once each"), ((1, 3), 4, "once each"),
                                                   ((1, 2, 3), 3, "two- or four-stroke")])
def test_crank_angles_reject_impossible_engines(order, strokes, words):
    with pytest.raises(ValueError, match=words):
        me.crank_angles(order, strokes)


def test_firing_orders_are_read_with_dashes_or_commas():
    assert me.parse_firing_order("1-5-3-6-2-4") == (1, 5, 3, 6, 2, 4) == me.parse_firing_order("1,5,3,6,2,4")


def test_centred_positions_are_symmetric_with_cylinder_1_negative():
    assert me.centred_positions(4, 1.0) == [-1.5, -0.5, 0.5, 1.5]
    assert me.centred_positions(3, 0.2) == pytest.approx([-0.2, 0.0, 0.2])


@pytest.mark.parametrize("count, reverse, sec_direct, sec_reverse", [
    (3, 0, 0, 3), (4, 0, 0, 0), (5, 0, 0, 0), (6, 0, 0, 0), (9, 0, 0, 0),
])
def test_radial_cranks(count, reverse, sec_direct, sec_reverse):
    got = me.radial_cranks(me.radial_cylinder_angles(count))
    assert got["primary_direct"][0] == pytest.approx(count)
    assert [got[k][0] for k in ("primary_reverse", "secondary_direct", "secondary_reverse")] == \
        pytest.approx([reverse, sec_direct, sec_reverse], abs=1e-12)


@pytest.mark.parametrize("v_deg", [40, 60, 90, 120])
def test_v_twin_cranks_are_the_cosines_of_the_half_angle(v_deg):
    half = v_deg / 2 * DEG
    got = me.radial_cranks(me.v_cylinder_angles(v_deg * DEG))
    assert got["primary_direct"][0] == pytest.approx(2)
    assert got["primary_reverse"][0] == pytest.approx(abs(2 * math.cos(2 * half)), abs=1e-12)
    assert got["secondary_direct"][0] == pytest.approx(abs(2 * math.cos(half)), abs=1e-12)
    assert got["secondary_reverse"][0] == pytest.approx(abs(2 * math.cos(3 * half)), abs=1e-12)


def test_crank_forces_primary_and_secondary():
    omega = 2 * math.pi * 2000 / 60
    assert me.crank_force(2, 0.06, omega) == pytest.approx(0.06 * omega ** 2)          # (m/2) r w^2
    assert me.crank_force(2, 0.06, omega, 3) == pytest.approx(0.06 * omega ** 2 / 3)   # (m/2)(2w)^2 r/4n
