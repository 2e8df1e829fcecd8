"""Both assembly solutions of a slider-crank, then the one the figure shows (course text §7.10).

The text's vector loop R2 + R3 = R1 + R4 with A at the origin: R1 runs from A to its foot on the line of
slide (the offset), R4 along the line to the slider pin C. Across the line the loop fixes one
trigonometric function of θ3, which has two roots: for a vertical line cos θ3, so θ3 = ±cos⁻¹(…); for a
horizontal one sin θ3, so θ3 = sin⁻¹(…) or 180° − sin⁻¹(…) ("whichever makes sense"). The figure is
the given that picks one, so the sheet names neither; then the slider's place along the line follows.
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from .angles import wrapped

#: The line of slide from A: its direction ("vertical" or "horizontal") and the sign of its offset
#: coordinate (x of a vertical line, y of a horizontal one).
LINES = {"right": ("vertical", 1.0), "left": ("vertical", -1.0), "above": ("horizontal", 1.0),
         "below": ("horizontal", -1.0)}
ROOTS = ("first", "second")


def offset_coordinate(line: str, offset: float) -> float:
    """Where the line of slide crosses the axis through A: +L1 right of or above A, −L1 left or below."""
    return LINES[line][1] * offset


def roots(slide: str, crank: float, coupler: float, theta2: float, across: float) -> tuple[float, float]:
    """θ3 of both assemblies: the calculator's inverse, then the other angle with the same cos or sin."""
    if slide == "vertical":
        first = math.acos(_ratio((across - crank * math.cos(theta2)) / coupler))
        return first, -first
    first = math.asin(_ratio((across - crank * math.sin(theta2)) / coupler))
    return first, lk.wrap(math.pi - first)


def along(slide: str, crank: float, coupler: float, theta2: float, theta3: float) -> float:
    """The slider pin C's coordinate along its line, from A: y for a vertical line, x for a horizontal one."""
    if slide == "vertical":
        return crank * math.sin(theta2) + coupler * math.sin(theta3)
    return crank * math.cos(theta2) + coupler * math.cos(theta3)


def _ratio(value: float) -> float:
    if abs(value) > 1 + lk.EQUAL:
        raise lk.NotAssemblable(f"the coupler is too short to reach the line of slide (ratio {value:.4g})")
    return max(-1.0, min(1.0, value))


def slider_crank_both_roots(p, d):
    """θ3 of both roots, which one is drawn, and where the slider pin C is on the linkage as drawn."""
    line = str(p.line)
    slide, _ = LINES[line]
    across = offset_coordinate(line, p.L1)
    vertical = slide == "vertical"
    axis, cross = ("y", "x") if vertical else ("x", "y")
    fn = r"\cos" if vertical else r"\sin"
    d.step("across", across, "m", symbol=f"{cross}_1",
           note=f"R₁ from A to the line of slide: the line is {'right' if across > 0 else 'left'} of A"
           if vertical and across else (f"R₁ from A to the line of slide: the line is "
                                        f"{'above' if across > 0 else 'below'} A" if across else
                                        "R₁ = 0: the line of slide passes through A"))
    ratio = (across - p.L2 * (math.cos(p.theta2) if vertical else math.sin(p.theta2))) / p.L3
    d.require(abs(ratio) < 1, "the coupler cannot reach the line of slide")
    d.step("ratio", ratio, "", symbol=rf"{fn}\theta_3",
           formula=rf"\frac{{@across - @L2{fn} @theta2}}{{@L3}}",
           note=f"the loop R₂ + R₃ = R₁ + R₄ across the line of slide ({cross} components)")
    first, second = roots(slide, p.L2, p.L3, p.theta2, across)
    inverse = r"\cos^{-1}" if vertical else r"\sin^{-1}"
    d.step("theta3_first", first, "rad", symbol=r"\theta_3", formula=rf"{inverse} @ratio",
           note="the root the calculator gives")
    if vertical:
        wrapped(d, "theta3_second", r"\theta_3'", r"-@theta3_first", second,
                note="the other angle with the same cosine")
    else:
        wrapped(d, "theta3_second", r"\theta_3'", r"180^\circ - @theta3_first", math.pi - first,
                note="the other angle with the same sine")
    shown = "first" if str(p.assembly) == "1" else "second"
    other = ROOTS[1 - ROOTS.index(shown)]
    chosen = first if shown == "first" else second
    c_chosen = along(slide, p.L2, p.L3, p.theta2, chosen)
    drawn = d.step("root", shown, "", symbol=r"\text{as drawn}",
           note=f"the figure has C {_place(vertical, c_chosen, p.L2, p.theta2)} B: "
                + (r"$\theta_3$" if shown == "first" else r"$\theta_3'$"))
    d.mistake("root", "wrong_circuit", other)
    trig = r"\sin" if vertical else r"\cos"
    d.step("C_along", along(slide, p.L2, p.L3, p.theta2, d.value_of(f"theta3_{drawn}")), "m", symbol=f"{axis}_C",
           formula=rf"@L2{trig} @theta2 + @L3{trig} @theta3_{drawn}",
           note=f"the loop along the line of slide ({axis} components), the root as drawn")
    _slips(p, d, line, slide, across, (first, second), shown)
    d.require(abs(lk.wrap(first - second)) >= math.radians(20), "the two roots too close to tell apart on the figure")


def _place(vertical: bool, c_along: float, crank: float, theta2: float) -> str:
    b_along = crank * (math.sin(theta2) if vertical else math.cos(theta2))
    if vertical:
        return "below" if c_along < b_along else "above"
    return "to the left of" if c_along < b_along else "to the right of"


def _slips(p, d, line, slide, across, both, shown) -> None:
    """The offset on the wrong side of A; the other root by the other function's rule; the other root's C."""
    first, second = both
    try:
        flipped = roots(slide, p.L2, p.L3, p.theta2, -across) if across else None
    except lk.NotAssemblable:
        flipped = None      # with the offset on the other side the coupler would not reach: no such slip
    if flipped:
        d.mistake("theta3_first", "offset_sign", flipped[0], if_apart=True)
        d.mistake("theta3_second", "offset_sign", flipped[1], if_apart=True)
    # the rule of the other function: −θ3 where the sine asked 180° − θ3, 180° − θ3 where the cosine asked −θ3
    d.mistake("theta3_second", "other_function_rule",
              lk.wrap(math.pi - first) if slide == "vertical" else -first, if_apart=True)
    other = second if shown == "first" else first
    d.mistake("C_along", "wrong_circuit", along(slide, p.L2, p.L3, p.theta2, other))
    if flipped:
        d.mistake("C_along", "offset_sign",
                  along(slide, p.L2, p.L3, p.theta2, flipped[ROOTS.index(shown)]), if_apart=True)
