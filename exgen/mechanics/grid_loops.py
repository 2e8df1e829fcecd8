"""A turning-moment diagram's loops as drawn on squared paper, for a question whose loop areas are read off
the figure by counting squares (course text Problem 3.1 measures them in mm² off its drawing).

Each loop runs from one crossing of the mean line to the next along whole columns of the grid, and the
torque curve goes straight from one grid crossing to the next: at each vertical grid line inside the loop it
stands a whole number of squares from the mean line. Each column is then a trapezium of (h₁ + h₂)/2
squares, and the loop's area, counted, is the sum of its heights at the lines inside it (the trapezoidal
rule, exact for straight sides): whole squares plus the halves cut by the sloping sides.
"""
from __future__ import annotations

import math
from typing import Sequence

#: Columns a loop spans at least: two grid lines inside it, so that it rises and falls.
LEAST_WIDTH = 3


def widths(areas: Sequence[float], columns: int) -> list[int]:
    """Whole columns for each loop, summing to `columns`, growing with the square root of its area (a larger
    loop is both wider and taller, as on an engine's diagram)."""
    if columns < LEAST_WIDTH * len(areas):
        raise ValueError(f"{columns} columns cannot hold {len(areas)} loops of {LEAST_WIDTH} columns")
    roots = [math.sqrt(max(a, 0.0)) for a in areas]
    spare = columns - LEAST_WIDTH * len(areas)
    share = [spare * r / sum(roots) for r in roots]
    out = [LEAST_WIDTH + math.floor(s) for s in share]
    for i in sorted(range(len(areas)), key=lambda i: (math.floor(share[i]) - share[i], i))[: columns - sum(out)]:
        out[i] += 1
    return out


def heights(area: int, width: int) -> tuple[int, ...]:
    """Whole-square heights at the `width - 1` grid lines inside a loop, at least 1 each (the curve leaves the
    mean line only at the loop's ends), shaped as a half sine, summing to `area` squares."""
    inside = width - 1
    if area < inside:
        raise ValueError(f"a loop of {area} squares cannot span {width} columns")
    shape = [math.sin(math.pi * (i + 1) / width) for i in range(inside)]
    raw = [area * s / sum(shape) for s in shape]
    out = [max(1, math.floor(r)) for r in raw]
    while sum(out) < area:
        i = max(range(inside), key=lambda i: (raw[i] - out[i], -abs(2 * i + 1 - inside)))
        out[i] += 1
    while sum(out) > area:
        i = min((i for i in range(inside) if out[i] > 1), key=lambda i: (raw[i] - out[i], i))
        out[i] -= 1
    return tuple(out)


def _columns(profile: Sequence[int]):
    """(left, right) heights of each column of a loop, its ends on the mean line."""
    edge = (0, *profile, 0)
    return zip(edge, edge[1:])


def squares(profile: Sequence[int]) -> float:
    """A loop's area in squares: each column a trapezium of (h₁ + h₂)/2."""
    return sum((a + b) / 2 for a, b in _columns(profile))


def whole_squares(profile: Sequence[int]) -> int:
    """Only the squares wholly inside the loop: the part-squares along the sloping sides left out."""
    return sum(min(a, b) for a, b in _columns(profile))


def touched_squares(profile: Sequence[int]) -> int:
    """Every square the loop reaches into, a part-square counted as whole."""
    return sum(max(a, b) for a, b in _columns(profile))
