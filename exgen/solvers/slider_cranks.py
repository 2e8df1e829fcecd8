"""Worked derivation for slider-crank position (course text §7.7 and the slider-crank example, §7.10).

The slider lies right or left of the crank pivot A on a horizontal line of slide that passes L1
below A (eqs 7.10-7.12), or below or above A on a vertical line L1 to the right of A (eqs
7.13-7.14). θ3 is the text's angle of the coupler from the line of its equation; the answer
asked is the coupler's direction from +x counter-clockwise, the chapter's convention.
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from ..mechanics.slider_cranks import slider_crank as solve_slider
from .angles import between, wrapped

SLIDE_OF = {"right": "horizontal", "left": "horizontal", "below": "vertical", "above": "vertical"}
OTHER = {"right": "left", "left": "right", "below": "above", "above": "below"}
THETA3 = {
    "horizontal": (r"\sin^{-1}\frac{@L1 + @L2\sin @theta2}{@L3}", "eq 7.10: the coupler's angle below the horizontal"),
    "vertical": (r"\cos^{-1}\frac{@L1 - @L2\cos @theta2}{@L3}", "eq 7.13: the coupler's angle from the horizontal"),
}
DIRECTION = {"right": (r"-@theta3", "pointing down to the right"),
             "left": (r"180^\circ + @theta3", "pointing down to the left"),
             "below": (r"-@theta3", "pointing down"),
             "above": (r"@theta3", "pointing up")}
L4 = {"right": (r"@L2\cos @theta2 + @L3\cos @theta3", "eq 7.11: C to the right of A"),
      "left": (r"@L3\cos @theta3 - @L2\cos @theta2", "C to the left of A"),
      "below": (r"@L3\sin @theta3 - @L2\sin @theta2", "eq 7.14: C below A"),
      "above": (r"@L3\sin @theta3 + @L2\sin @theta2", "C above A")}
#: Unit vector along the line of slide towards the slider's side of A.
TOWARDS = {"right": (1.0, 0.0), "left": (-1.0, 0.0), "below": (0.0, -1.0), "above": (0.0, 1.0)}


#: The piston tip P from the origin O: O -> A, A -> C (L1 across the line, L4 along it), C -> P.
TIP = {"right": (r"@xA + @L4 + @tip", r"@yA - @L1"), "left": (r"@xA - @L4 - @tip", r"@yA - @L1"),
       "below": (r"@xA + @L1", r"@yA - @L4 - @tip"), "above": (r"@xA + @L1", r"@yA + @L4 + @tip")}


def distance_along(position, where: str) -> float:
    """How far C is from A's foot on the line of slide, towards the slider's side."""
    ux, uy = TOWARDS[where]
    return position.c[0] * ux + position.c[1] * uy


def slider_crank(p, d):
    """θ3, the slider's distance from A, γ and the piston tip P, by the text's equations."""
    where = str(p.slider)
    slide = SLIDE_OF[where]
    position = solve_slider(p.L2, p.L3, p.L1, p.theta2, slide, where)   # raises if it cannot reach
    formula, note = THETA3[slide]
    theta3 = d.step("theta3", position.theta3, "rad", symbol=r"\theta_3", formula=formula, note=note)
    formula, note = DIRECTION[where]
    phi3 = wrapped(d, "phi3", r"\varphi_3", formula, _direction(where, theta3), note=f"the coupler B → C from +x, {note}")
    formula, note = L4[where]
    l4 = d.step("L4", _distance(where, p.L2, p.L3, p.theta2, _from_direction(where, phi3)), "m", symbol="L_4",
                formula=formula, note=f"{note}, along the line of slide")
    text_gamma = math.pi - (p.theta2 + theta3)
    if where in ("right", "below") and 0 <= text_gamma <= math.pi:
        d.step("gamma", text_gamma, "rad", symbol=r"\gamma", formula=r"180^\circ - (@theta2 + @theta3)",
               note="eq 7.12: the angle ABC between crank and coupler")
    else:
        between(d, "gamma", r"\gamma", r"@theta2 + 180^\circ - @phi3", p.theta2 + math.pi - phi3,
                "the angle ABC between crank (B → A at θ2 + 180°) and coupler (B → C at φ3), "
                "taken by whole turns to between 0° and 180°")
    ux, uy = TOWARDS[where]
    cx = p.L1 if slide == "vertical" else ux * l4
    cy = -p.L1 if slide == "horizontal" else uy * l4
    d.step("xP", p.xA + cx + ux * p.tip, "m", symbol="x_P", formula=TIP[where][0],
           note="O → A, then A → C, then C → P along the line of slide")
    d.step("yP", p.yA + cy + uy * p.tip, "m", symbol="y_P", formula=TIP[where][1])
    _mistakes(p, d, where, position)


def _direction(where: str, theta3: float) -> float:
    return {"right": -theta3, "left": math.pi + theta3, "below": -theta3, "above": theta3}[where]


def _from_direction(where: str, phi3: float) -> float:
    """θ3 back from the coupler's direction: L4 is worked from (a)'s answer, so an error there carries."""
    return {"right": -phi3, "left": phi3 - math.pi, "below": -phi3, "above": phi3}[where]


def _distance(where: str, crank: float, coupler: float, theta2: float, theta3: float) -> float:
    s, c = math.sin, math.cos
    return {"right": crank * c(theta2) + coupler * c(theta3), "left": coupler * c(theta3) - crank * c(theta2),
            "below": coupler * s(theta3) - crank * s(theta2), "above": coupler * s(theta3) + crank * s(theta2)}[where]


def _mistakes(p, d, where: str, position) -> None:
    """The other branch, the size of θ3 without its sense, γ's supplement and the offset left out:
    each named only where the data let it show (by the answer's tolerance: exgen.solve.variant.mistakes_apart)."""
    slide = SLIDE_OF[where]
    other = solve_slider(p.L2, p.L3, p.L1, p.theta2, slide, OTHER[where])
    theta3, l4, gamma = position.theta3, d.value_of("L4"), d.value_of("gamma")
    _angle_mistake(d, "phi3", "magnitude_only", theta3)
    _angle_mistake(d, "phi3", "wrong_branch", other.direction)
    _angle_mistake(d, "gamma", "supplement", math.pi - gamma)
    d.mistake("L4", "wrong_branch", distance_along(other, where))
    ux, uy = TOWARDS[where]
    along = "xP" if slide == "horizontal" else "yP"
    d.mistake(along, "wrong_branch", (p.xA + other.c[0] + ux * p.tip) if slide == "horizontal"
              else (p.yA + other.c[1] + uy * p.tip))
    if p.L1 > 0:
        inline = solve_slider(p.L2, p.L3, 0.0, p.theta2, slide, where)
        _angle_mistake(d, "phi3", "offset_ignored", inline.direction)
        d.mistake("L4", "offset_ignored", distance_along(inline, where), if_apart=True)
    d.require(not d.strict or l4 > 0.2 * p.L3, "the slider would sit behind the crank pivot")


def _angle_mistake(d, step: str, name: str, wrong: float) -> None:
    d.mistake(step, name, wrong, if_apart=True)
