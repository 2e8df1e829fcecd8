"""Slider-crank position (course text §7.7 and the slider-crank example, eqs 7.10-7.14).

The crank AB = L2 turns about A at θ2 (from +x counter-clockwise); the coupler BC = L3 joins
it to the slider pin C, which runs on a straight line of slide offset L1 from A (L1 = 0: the
in-line slider-crank).

- Horizontal slide (eqs 7.10-7.12): the line passes L1 below A (a negative L1 is above it).
  θ3 = sin⁻¹((L1 + L2 sin θ2) / L3) is the coupler's angle below the horizontal and
  L4 = L2 cos θ2 + L3 cos θ3 the slider's distance from A along the line.
- Vertical slide (eqs 7.13-7.14): the line passes L1 to the right of A (negative: left).
  θ3 = cos⁻¹((L1 - L2 cos θ2) / L3) and L4 = L3 sin θ3 - L2 sin θ2 the slider's distance below A.

Those are the branches the text draws (the slider ahead of the crank: to the right, or
below). The other branch, "whichever makes sense" in the text, puts the slider behind (left,
or above): θ3 is then read as 180° - θ3 (horizontal) or -θ3 (vertical).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .linkages import EQUAL, NotAssemblable, polar, wrap

SLIDES = ("horizontal", "vertical")
#: The branch the text's equations give, and the other one, for each line of slide.
BRANCHES = {"horizontal": ("right", "left"), "vertical": ("below", "above")}


@dataclass(frozen=True)
class SliderCrank:
    theta3: float      # the text's θ3 (eq 7.10 or 7.13), on the text's branch
    direction: float   # the coupler B -> C, from +x counter-clockwise
    l4: float          # the slider's position along its line, measured as the text does
    gamma: float       # the angle ABC between crank and coupler (eq 7.12)
    b: tuple[float, float]
    c: tuple[float, float]


def _ratio(value: float, what: str) -> float:
    if abs(value) > 1 + EQUAL:
        raise NotAssemblable(f"the coupler is too short to reach the line of slide ({what} = {value:.4g})")
    return max(-1.0, min(1.0, value))


def slider_crank(crank: float, coupler: float, offset: float, theta2: float,
                 slide: str = "horizontal", branch: str | None = None) -> SliderCrank:
    """Position of the slider-crank with A at the origin; `branch` defaults to the text's."""
    if slide not in SLIDES:
        raise ValueError(f"slide must be one of {SLIDES}, not {slide!r}")
    ahead, behind = BRANCHES[slide]
    branch = branch or ahead
    if branch not in (ahead, behind):
        raise ValueError(f"a {slide} slide has branches {ahead!r} and {behind!r}, not {branch!r}")
    b = polar((0.0, 0.0), crank, theta2)
    if slide == "horizontal":
        theta3 = math.asin(_ratio((offset + crank * math.sin(theta2)) / coupler, "sin θ3"))
        direction = -theta3 if branch == ahead else math.pi + theta3
        c = polar(b, coupler, direction)
        l4 = c[0]
    else:
        theta3 = math.acos(_ratio((offset - crank * math.cos(theta2)) / coupler, "cos θ3"))
        direction = -theta3 if branch == ahead else theta3
        c = polar(b, coupler, direction)
        l4 = -c[1]
    gamma = abs(wrap(math.pi + theta2 - direction))  # between B -> A and B -> C
    return SliderCrank(theta3, wrap(direction), l4, gamma, b, c)
