"""Exact belt geometry: common tangents of two pulleys and the closed belt path around them.

Screen coordinates (y down). `u` runs from pulley 1 to pulley 2 and `w` is `u` turned a
quarter clockwise on screen, so for a horizontal drive `w` points down. A tangent line
touches circle i at c_i + r_i n (open drive) or at c_1 + r_1 n and c_2 - r_2 n (crossed),
where n = a u + b w with a = (r1 - r2)/D (open) or (r1 + r2)/D (crossed) and b = ±sqrt(1 - a²).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .svg import num, pts

Point = tuple[float, float]


@dataclass(frozen=True)
class BeltLoop:
    """The two straight runs of a belt and its closed outline (an SVG path)."""

    tight: tuple[Point, Point]   # from the driven pulley to the driver (the driver pulls it in)
    slack: tuple[Point, Point]   # from the driver to the driven pulley
    wrap1: float                 # angle of contact on pulley 1, radians
    wrap2: float                 # angle of contact on pulley 2, radians
    path: str


def _frame(c1: Point, c2: Point):
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    distance = math.hypot(dx, dy)
    u = (dx / distance, dy / distance)
    w = (-u[1], u[0])
    return distance, u, w


def _at(c: Point, r: float, n: Point) -> Point:
    return c[0] + r * n[0], c[1] + r * n[1]


def tangent_normals(c1: Point, r1: float, c2: Point, r2: float, crossed: bool) -> tuple[Point, Point]:
    """The unit normals of the two common tangents, on the -w side first (the upper run)."""
    distance, u, w = _frame(c1, c2)
    a = ((r1 + r2) if crossed else (r1 - r2)) / distance
    if abs(a) >= 1:
        raise ValueError(f"pulleys overlap: no {'internal' if crossed else 'external'} tangents "
                         f"(r1={r1}, r2={r2}, centre distance {distance})")
    b = math.sqrt(1 - a * a)
    upper = (a * u[0] - b * w[0], a * u[1] - b * w[1])
    lower = (a * u[0] + b * w[0], a * u[1] + b * w[1])
    return upper, lower


def belt_loop(c1: Point, r1: float, c2: Point, r2: float, crossed: bool = False) -> BeltLoop:
    """The belt around pulley 1 (the driver, turning clockwise on screen) and pulley 2."""
    upper, lower = tangent_normals(c1, r1, c2, r2, crossed)
    u = _frame(c1, c2)[1]
    a = upper[0] * u[0] + upper[1] * u[1]  # cosine of the normal's angle from the line of centres
    far_side = 2 * (math.pi - math.acos(max(-1.0, min(1.0, a))))  # wrap on the side away from the other pulley
    sign = -1 if crossed else 1
    t1_up, t1_low = _at(c1, r1, upper), _at(c1, r1, lower)
    t2_up, t2_low = _at(c2, sign * r2, upper), _at(c2, sign * r2, lower)
    wrap1 = far_side
    wrap2 = far_side if crossed else 2 * math.pi - far_side
    large1, large2 = int(wrap1 > math.pi), int(wrap2 > math.pi)
    if crossed:
        # upper-right of 1 -> lower-left of 2, round 2 anticlockwise, upper-left of 2 -> lower-right of 1
        d = (f"M {pts(t1_up)} L {pts(t2_up)} A {num(r2)} {num(r2)} 0 {large2} 0 {pts(t2_low)} "
             f"L {pts(t1_low)} A {num(r1)} {num(r1)} 0 {large1} 1 {pts(t1_up)} Z")
    else:
        d = (f"M {pts(t1_up)} L {pts(t2_up)} A {num(r2)} {num(r2)} 0 {large2} 1 {pts(t2_low)} "
             f"L {pts(t1_low)} A {num(r1)} {num(r1)} 0 {large1} 1 {pts(t1_up)} Z")
    # A clockwise driver winds in the run that touches it on the +w side (lower for an open drive).
    return BeltLoop(tight=(t2_low, t1_low), slack=(t1_up, t2_up), wrap1=wrap1, wrap2=wrap2, path=d)
