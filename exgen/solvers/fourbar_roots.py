"""Both assembly solutions of a four-bar, then the one the figure shows (course text §7.9, question 2).

The text's vector method: R_H = R_1 + R_2 runs from the rocker pivot D to the crank pin B; the cosine
law in triangle DBC gives the angle φ at D, and θ4 = θ_H ± φ are the two ways the linkage closes.
The text then asks which one "corresponds to the figure/reality": the figure is the given that
picks it, so the sheet names no circuit.
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from .angles import direction, wrapped
from .fourbars import require_well_conditioned

ROOTS = ("plus", "minus")


def fourbar_both_roots(p, d):
    """θ4 = θ_H + φ and θ_H − φ, which one is drawn, and θ3 of the linkage as drawn."""
    pin = lk.polar((p.xA, p.yA), p.L2, p.theta2)
    xb = d.step("xB", pin[0], "m", symbol="x_B", formula=r"@xA + @L2\cos @theta2",
                note="$R_H = R_1 + R_2$, from D to the crank pin B")
    yb = d.step("yB", pin[1], "m", symbol="y_B", formula=r"@yA + @L2\sin @theta2")
    theta_h = direction(d, "theta_H", r"\theta_H", "@yB", "@xB", yb, xb, "the direction D → B")
    r_h = d.step("r_H", math.hypot(xb, yb), "m", symbol="r_H", formula=r"\sqrt{@xB^2 + @yB^2}")
    phi = d.step("phi", lk.cosine_law_angle(r_h, p.L4, p.L3), "rad", symbol=r"\varphi",
                 formula=r"\cos^{-1}\frac{@r_H^2 + @L4^2 - @L3^2}{2\,@L4\,@r_H}",
                 note="the angle BDC in triangle DBC (cosine law): C lies φ to either side of D → B")
    roots = {}
    for root, sign, prime in (("plus", 1.0, ""), ("minus", -1.0, "'")):
        roots[root] = wrapped(d, f"theta4_{root}", rf"\theta_4{prime}", rf"@theta_H {'+' if sign > 0 else '-'} @phi",
                              theta_h + sign * phi, note="C " + ("counter-clockwise" if sign > 0 else "clockwise")
                              + " from D → B")
    shown = _drawn_root(p)
    drawn = d.step("root", shown, "", symbol=r"\text{as drawn}",
           note=f"the figure has C on the {'right' if shown == 'plus' else 'left'} of B → D, "
                f"{'counter-' if shown == 'plus' else ''}clockwise from D → B: "
                + (r"$\theta_4 = \theta_H + \varphi$" if shown == "plus" else r"$\theta_4' = \theta_H - \varphi$"))
    other = ROOTS[1 - ROOTS.index(shown)]
    d.mistake("root", "wrong_circuit", other)
    chosen = d.value_of(f"theta4_{drawn}")
    c = lk.polar((0.0, 0.0), p.L4, chosen)
    xc = d.step("xC", c[0], "m", symbol="x_C", formula=rf"@L4\cos @theta4_{drawn}")
    yc = d.step("yC", c[1], "m", symbol="y_C", formula=rf"@L4\sin @theta4_{drawn}")
    theta3 = direction(d, "theta3", r"\theta_3", "@yC - @yB", "@xC - @xB", yc - yb, xc - xb,
                       "the coupler B → C of the linkage as drawn")
    _slips(p, d, (xb, yb), theta_h, r_h, phi, roots, other, theta3)
    gamma = lk.cosine_law_angle(p.L3, p.L4, r_h)
    require_well_conditioned(d, gamma, 2 * phi)
    d.require(2 * phi >= math.radians(20), "the two roots too close to tell apart on the figure")


def _drawn_root(p) -> str:
    """The root the figure draws: the circuit parameter, as coupler_point's convention has it (circuit 2
    puts C counter-clockwise from D → B)."""
    return "plus" if str(p.circuit) == "2" else "minus"


def _slips(p, d, b, theta_h, r_h, phi, roots, other, theta3) -> None:
    """θ_H without its half turn; the triangle's angle at B taken for the one at D; the other root's θ3;
    the coupler from C to B."""
    xb, yb = b
    bare = math.atan(yb / xb) if xb else theta_h
    at_b = lk.cosine_law_angle(r_h, p.L3, p.L4)
    for root, sign in (("plus", 1.0), ("minus", -1.0)):
        d.mistake(f"theta4_{root}", "quadrant_lost", lk.wrap(bare + sign * phi), if_apart=True)
        d.mistake(f"theta4_{root}", "angle_at_b", lk.wrap(theta_h + sign * at_b))
    c = lk.polar((0.0, 0.0), p.L4, roots[other])
    d.mistake("theta3", "wrong_circuit", math.atan2(c[1] - yb, c[0] - xb))
    d.mistake("theta3", "coupler_reversed", lk.wrap(theta3 + math.pi))
