"""Loops laid on squared paper (exgen/mechanics/grid_loops.py): for every area and width a drawn loop can
have, the loop fills its columns, stays off the mean line inside them, and counts back to its area."""
import pytest

from exgen.mechanics import grid_loops


@pytest.mark.parametrize("width", range(grid_loops.LEAST_WIDTH, 16))
def test_every_loop_counts_back_to_its_area(width):
    for area in range(width - 1, 200):
        profile = grid_loops.heights(area, width)
        assert len(profile) == width - 1 and min(profile) >= 1
        assert grid_loops.squares(profile) == area
        assert grid_loops.whole_squares(profile) < area < grid_loops.touched_squares(profile)
        rise = max(range(len(profile)), key=profile.__getitem__)           # one hump: up, then down
        assert list(profile[: rise + 1]) == sorted(profile[: rise + 1])
        assert list(profile[rise:]) == sorted(profile[rise:], reverse=True)


def test_the_columns_are_shared_out_whole_and_grow_with_the_area():
    for columns in (48, 60, 72, 80):
        areas = [8, 34, 12, 20, 28, 16, 9, 30, 21]
        widths = grid_loops.widths(areas, columns)
        assert sum(widths) == columns and min(widths) >= grid_loops.LEAST_WIDTH
        ranked = sorted(range(9), key=areas.__getitem__)
        assert [widths[i] for i in ranked] == sorted(widths)


def test_a_loop_smaller_than_its_columns_or_too_many_loops_is_refused():
    with pytest.raises(ValueError):
        grid_loops.heights(3, 6)
    with pytest.raises(ValueError):
        grid_loops.widths([10] * 9, 20)
