"""Figures for a slider-crank's two assembly solutions (course text §7.10): the linkage as drawn, whose
root the sheet asks and the caption does not name, and for the key the other root dashed (C′)."""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from ..solvers.slider_crank_roots import LINES, along, offset_coordinate, roots
from .kinematic import DASH, Sketch, centre_of, fit


def as_drawn(variant) -> str:
    """The slider-crank as assembled, A at the origin."""
    return _figure(variant, key=False)


def both_roots(variant) -> str:
    """For the key: the linkage as drawn, and the other root's coupler and slider dashed (C′)."""
    return _figure(variant, key=True)


def _si(variant, name: str) -> float:
    return float(variant.param(name).si)


def _point(vertical: bool, across: float, at: float):
    return (across, at) if vertical else (at, across)


def _figure(variant, key: bool) -> str:
    line = str(variant.param("line").exact)
    slide, _ = LINES[line]
    vertical = slide == "vertical"
    crank, coupler, theta2 = _si(variant, "L2"), _si(variant, "L3"), _si(variant, "theta2")
    across = offset_coordinate(line, _si(variant, "L1"))
    first, second = roots(slide, crank, coupler, theta2, across)
    shown = str(variant.param("assembly").exact) == "1"
    drawn, other = (first, second) if shown else (second, first)
    world = {"A": (0.0, 0.0), "B": lk.polar((0.0, 0.0), crank, theta2),
             "C": _point(vertical, across, along(slide, crank, coupler, theta2, drawn))}
    other_c = _point(vertical, across, along(slide, crank, coupler, theta2, other))
    ends = [_point(vertical, across, t) for t in (min(0.0, -coupler - crank), max(0.0, coupler + crank))]
    frame = fit(list(world.values()) + [other_c] + ends, 420, 270)
    page = {k: frame(v) for k, v in world.items()}
    s = Sketch()
    start, end = frame(ends[0]), frame(ends[1])
    s.guide(start, end, (1.0, 0.0) if vertical else (0.0, 1.0))
    direction = (0.0, 1.0) if vertical else (1.0, 0.0)
    if key:
        s.bar(page["B"], frame(other_c), dash=DASH, cls="other-circuit")
        s.slider_block(frame(other_c), direction, dash="2 2")
    s.bar(page["A"], page["B"])
    s.bar(page["B"], page["C"])
    s.ground_pivot(page["A"], down=(-1.0, 0.0) if vertical else (0.0, -1.0))
    s.pin(page["B"])
    s.slider_block(page["C"], direction)
    radius = max(14.0, min(30.0, 0.45 * math.dist(page["A"], page["B"])))
    s.reference_line(page["A"], radius + 22)
    s.arc(page["A"], radius, 0.0, theta2)
    s.corner_axes()
    middle = centre_of([page[k] for k in "ABC"])
    s.joint_label(page["A"], "A (0, 0)", middle)
    s.joint_label(page["B"], "B", middle)
    s.joint_label(page["C"], "C", middle)
    if key:
        s.joint_label(frame(other_c), "C′", middle)
    s.link_label(page["A"], page["B"], f"L₂ = {variant.param('L2')}", middle)
    s.link_label(page["B"], page["C"], f"L₃ = {variant.param('L3')}", middle)
    s.angle_label(page["A"], radius, 0.0, theta2, f"θ₂ = {variant.param('theta2')}")
    return s.svg("Slider-crank as assembled; A at the origin" + (", the other root dashed (C′)" if key else ""))
