"""Worked derivations for moving a link where it is wanted (course text Problem 7.2 and §7.11).

- A support link swung by a linear actuator (Problem 7.2): the actuator, pinned to the ground
  and to the link, closes a triangle with the two ground pivots, so the cosine law gives the
  link's angle for any actuator length.
- Two-position synthesis (§7.11): a ground pivot that moves a point of the coupler from one
  position to the other lies on the perpendicular bisector of the two positions; the sheet fixes
  the design choice that picks one point of each bisector (both pivots on the floor, y = 0).
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from .fourbars import GRASHOF_REASON
from .angles import difference, direction, wrapped
from .polygons import angle_gap_deg

SENSES = ("clockwise", "counter-clockwise")
PIVOT = {"M": "E", "N": "F"}   # the ground pivots of the links to M and to N


def actuator_swing(p, d):
    """Problem 7.2: the support link's angle as drawn and after its actuator is retracted to s2.

    The triangle A (link pivot), O (actuator pivot), B (actuator pin) has AO fixed, AB = r and
    OB the actuator's length, so the cosine law gives the angle OAB for each length; B stays on
    the side of AO where it is drawn.
    """
    ao = d.step("AO", math.hypot(p.xO, p.yO), "m", symbol="AO", formula=r"\sqrt{@xO^2 + @yO^2}",
                note="between the link's pivot A and the actuator's pivot O")
    beta = direction(d, "beta", r"\beta", "@yO", "@xO", p.yO, p.xO, "the direction A → O")
    turn = 1.0 if str(p.side) == "left" else -1.0
    sign = "+" if turn > 0 else "-"
    angles = {}
    for k, length in ((1, "s1"), (2, "s2")):
        angle = d.step(f"angle{k}", lk.actuator_link_angle(ao, p.r, getattr(p, length)), "rad",
                       symbol=rf"\angle OAB_{k}", formula=rf"\cos^{{-1}}\frac{{@AO^2 + @r^2 - @{length}^2}}{{2\,@AO\,@r}}",
                       note=f"in triangle OAB with the actuator {'as drawn' if k == 1 else 'retracted'} (cosine law)")
        angles[k] = wrapped(d, f"theta{k}", rf"\theta_{k}", rf"@beta {sign} @angle{k}", beta + turn * angle,
                            note=f"B on the {p.side} of the line from A to O")
        d.mistake(f"theta{k}", "other_side", lk.wrap(beta - turn * angle))
        d.mistake(f"theta{k}", "interior_angle", angle)
        d.require(math.radians(25) <= angle <= math.radians(155), "the actuator nearly in line with the link")
    rotation = lk.wrap(angles[2] - angles[1])
    size = difference(d, "rotation", r"\Delta\theta", "angle1", "angle2",
                      note="the support link turns as much as the angle OAB changes")
    d.step("sense", SENSES[rotation > 0], "", symbol=r"\text{sense}",
           note="retracting pulls B towards O, " + ("counter-clockwise" if rotation > 0 else "clockwise") + " here")
    d.mistake("rotation", "radians_for_degrees", math.radians(size))
    d.mistake("sense", "opposite", SENSES[rotation <= 0])
    d.require(math.radians(8) <= size <= math.radians(90), "a rotation the sheet's drawing could not show")


def two_position_synthesis(p, d):
    """§7.11 with two positions: ground pivots E (for M) and F (for N) on the floor."""
    points = {}
    for k in (1, 2):
        xm, ym, phi = (getattr(p, f"{n}{k}") for n in ("xM", "yM", "phi"))
        points[f"M{k}"] = (xm, ym)
        xn = d.step(f"xN{k}", xm + p.b * math.cos(phi), "m", symbol=f"x_{{N{k}}}", formula=rf"@xM{k} + @b\cos @phi{k}")
        yn = d.step(f"yN{k}", ym + p.b * math.sin(phi), "m", symbol=f"y_{{N{k}}}", formula=rf"@yM{k} + @b\sin @phi{k}")
        points[f"N{k}"] = (xn, yn)
    pivots, lengths = {}, {}
    for name in ("M", "N"):
        (x1, y1), (x2, y2) = points[f"{name}1"], points[f"{name}2"]
        d.require(abs(x2 - x1) > 0.15 * p.b, f"the bisector of {name}1 {name}2 nearly parallel to the floor")
        pivot = PIVOT[name]
        x = d.step(f"xO{name}", lk.bisector_on_line((x1, y1), (x2, y2), 0.0)[0], "m", symbol=f"x_{pivot}",
                   formula=rf"\frac{{@x{name}1 + @x{name}2}}{{2}} + \frac{{@y{name}1 + @y{name}2}}{{2}}"
                           rf"\,\frac{{@y{name}2 - @y{name}1}}{{@x{name}2 - @x{name}1}}",
                   note=f"the perpendicular bisector of {name}1 {name}2 meets the floor y = 0")
        pivots[name] = (x, 0.0)
        lengths[name] = d.step(f"R{name}", math.hypot(x1 - x, y1), "m", symbol=f"{pivot}{name}",
                               formula=rf"\sqrt{{(@x{name}1 - @xO{name})^2 + @y{name}1^2}}",
                               note=f"the link from {pivot} to {name}: it reaches {name}2 as well")
        mid = (x1 + x2) / 2
        d.mistake(f"xO{name}", "midpoint", mid)
        below_mid = math.hypot(x1 - mid, y1)
        d.mistake(f"R{name}", "midpoint", below_mid, if_apart=True)
    ground = difference(d, "ground", "EF", "xON", "xOM", note="the ground link", unit="m")
    g = lk.grashof(ground, lengths["M"], p.b, lengths["N"])
    d.step("kind", g.kind, "", symbol=r"\text{class}",
           note=f"S + L = {_mm(g.s_plus_l)} against P + Q = {_mm(g.p_plus_q)}, with EM the input: "
                f"{GRASHOF_REASON[g.kind]}")
    wrong = lk.grashof_kind(g.s + g.p, g.l + g.q, g.shortest)
    if wrong != g.kind:
        d.mistake("kind", "wrong_pair", wrong)
    _require_buildable(p, d, points, pivots, ground)


def _mm(metres: float) -> str:
    return f"{metres * 1000:.4g} mm"


def _require_buildable(p, d, points, pivots, ground) -> None:
    """The linkage must carry the coupler from one position to the other, with pivots a real machine has."""
    if not d.strict:
        return
    d.require(lk.moves_between(pivots["M"], pivots["N"], points["M1"], points["N1"], points["M2"], points["N2"]),
              "the linkage cannot move from one position to the other without changing circuit")
    span = max(abs(v) for pt in points.values() for v in pt)
    for name in ("M", "N"):
        d.require(abs(pivots[name][0]) <= 1.5 * span, "a ground pivot far outside the work area")
        length = d.value_of(f"R{name}")
        d.require(0.25 * p.b <= length <= 4 * p.b, "a link out of proportion to the coupler")
        mid = (points[f"{name}1"][0] + points[f"{name}2"][0]) / 2
        d.require(abs(pivots[name][0] - mid) >= 0.03 * length, "the pivot is nearly below the midpoint")
    d.require(ground >= 0.25 * p.b, "the ground pivots too close together")
    for name in ("M", "N"):
        (x1, y1), (x2, y2), o = points[f"{name}1"], points[f"{name}2"], pivots[name]
        swing = angle_gap_deg(math.atan2(y1 - o[1], x1 - o[0]), math.atan2(y2 - o[1], x2 - o[0]))
        d.require(swing >= 10, "a link that barely turns")


VERDICTS = {(True, True): "both", (True, False): "M only", (False, True): "N only", (False, False): "neither"}


def three_position_synthesis(p, d):
    """§7.11 as the text works it, three positions: each ground pivot is where the perpendicular bisectors
    of its pin's three positions cross (the circumcentre), and the text's test calls a pin a good choice when
    that pivot falls above the floor."""
    points = {}
    for k in (1, 2, 3):
        xm, ym, phi = (getattr(p, f"{n}{k}") for n in ("xM", "yM", "phi"))
        points[f"M{k}"] = (xm, ym)
        xn = d.step(f"xN{k}", xm + p.b * math.cos(phi), "m", symbol=f"x_{{N{k}}}", formula=rf"@xM{k} + @b\cos @phi{k}")
        yn = d.step(f"yN{k}", ym + p.b * math.sin(phi), "m", symbol=f"y_{{N{k}}}", formula=rf"@yM{k} + @b\sin @phi{k}")
        points[f"N{k}"] = (xn, yn)
    pivots, above = {}, {}
    for name in ("M", "N"):
        pivot = PIVOT[name]
        trio = [points[f"{name}{k}"] for k in (1, 2, 3)]
        chord = min(math.dist(trio[0], trio[1]), math.dist(trio[1], trio[2]))
        turn = abs(wrap_angle(math.atan2(trio[2][1] - trio[1][1], trio[2][0] - trio[1][0])
                              - math.atan2(trio[1][1] - trio[0][1], trio[1][0] - trio[0][0])))
        d.require(chord >= 0.5 * p.b and turn >= math.radians(20), f"{name}'s three positions nearly in a line")
        x, y = _circumcentre_steps(d, name, pivot, trio)
        pivots[name] = (x, y)
        d.step(f"R{name}", math.hypot(trio[0][0] - x, trio[0][1] - y), "m", symbol=f"{pivot}{name}",
               formula=rf"\sqrt{{(@x{name}1 - @xO{name})^2 + (@y{name}1 - @yO{name})^2}}",
               note=f"the link from {pivot} to {name}: it reaches {name}2 and {name}3 as well")
        above[name] = y > 0
        cx, cy = (sum(pt[0] for pt in trio) / 3, sum(pt[1] for pt in trio) / 3)
        d.mistake(f"xO{name}", "centroid", cx)
        d.mistake(f"yO{name}", "centroid", cy)
        d.mistake(f"R{name}", "centroid", math.dist(trio[0], (cx, cy)), if_apart=True)
    verdict = VERDICTS[(above["M"], above["N"])]
    d.step("verdict", verdict, "", symbol=r"\text{good choices}",
           note=f"E is {_floor_side(pivots['M'][1])} and F {_floor_side(pivots['N'][1])}: by the text's test a pin "
                "is a good choice when its ground pivot stands above the floor")
    d.mistake("verdict", "floor_test_reversed", VERDICTS[(not above["M"], not above["N"])])
    _require_three_positions(p, d, points, pivots)


def wrap_angle(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi


def _floor_side(y: float) -> str:
    return "above the floor" if y > 0 else "below the floor"


def _circumcentre_steps(d, name: str, pivot: str, trio) -> tuple[float, float]:
    """The two perpendicular bisectors as linear equations, (x₂ − x₁) x + (y₂ − y₁) y = c, solved by
    Cramer's rule: the working the text's construction stands for."""
    q = [(f"@x{name}{k}", f"@y{name}{k}") for k in (1, 2, 3)]
    for i, (a, b) in enumerate(((0, 1), (1, 2)), start=1):
        (xa, ya), (xb, yb) = trio[a], trio[b]
        d.step(f"c{i}_{name}", (xb * xb + yb * yb - xa * xa - ya * ya) / 2, "m^2", symbol=f"c_{{{i}{name}}}",
               formula=rf"\frac{{{q[b][0]}^2 + {q[b][1]}^2 - {q[a][0]}^2 - {q[a][1]}^2}}{{2}}",
               note=f"the perpendicular bisector of {name}{a + 1} {name}{b + 1}: "
                    f"$(x_{{{name}{b + 1}}} - x_{{{name}{a + 1}}})\\,x + (y_{{{name}{b + 1}}} - y_{{{name}{a + 1}}})\\,y = c_{{{i}{name}}}$")
    (x1, y1), (x2, y2), (x3, y3) = trio
    d.step(f"D_{name}", (x2 - x1) * (y3 - y2) - (y2 - y1) * (x3 - x2), "m^2", symbol=f"\\Delta_{name}",
           formula=rf"({q[1][0]} - {q[0][0]})({q[2][1]} - {q[1][1]}) - ({q[1][1]} - {q[0][1]})({q[2][0]} - {q[1][0]})",
           note="the determinant of the two bisectors' equations")
    centre = lk.circumcentre(*trio)
    x = d.step(f"xO{name}", centre[0], "m", symbol=f"x_{pivot}",
               formula=rf"\frac{{@c1_{name}\,({q[2][1]} - {q[1][1]}) - @c2_{name}\,({q[1][1]} - {q[0][1]})}}{{@D_{name}}}",
               note=f"where the bisectors cross: {pivot} is as far from {name}1, {name}2 and {name}3")
    y = d.step(f"yO{name}", centre[1], "m", symbol=f"y_{pivot}",
               formula=rf"\frac{{@c2_{name}\,({q[1][0]} - {q[0][0]}) - @c1_{name}\,({q[2][0]} - {q[1][0]})}}{{@D_{name}}}")
    return x, y


def _require_three_positions(p, d, points, pivots) -> None:
    """The linkage carries the plate 1 → 2 → 3 on one circuit, with pivots and links a machine could have."""
    if not d.strict:
        return
    for a, b in ((1, 2), (2, 3)):
        d.require(lk.moves_between(pivots["M"], pivots["N"], points[f"M{a}"], points[f"N{a}"], points[f"M{b}"],
                                   points[f"N{b}"]), "the linkage cannot pass through the positions on one circuit")
    span = max(abs(v) for pt in points.values() for v in pt)
    for name in ("M", "N"):
        o = pivots[name]
        d.require(math.hypot(*o) <= 1.5 * span and o[1] >= -0.8 * span, "a ground pivot far outside the work area")
        d.require(0.25 * p.b <= d.value_of(f"R{name}") <= 5 * p.b, "a link out of proportion to the coupler")
        angles = [math.atan2(points[f"{name}{k}"][1] - o[1], points[f"{name}{k}"][0] - o[0]) for k in (1, 2, 3)]
        steps = [wrap_angle(angles[1] - angles[0]), wrap_angle(angles[2] - angles[1])]
        d.require(min(map(abs, steps)) >= math.radians(10) and steps[0] * steps[1] > 0,
                  "a link that barely turns, or turns back, between positions")
        d.require(abs(o[1]) >= 0.05 * d.value_of(f"R{name}"), "a ground pivot almost on the floor: the test undecided")
    d.require(math.dist(pivots["M"], pivots["N"]) >= 0.25 * p.b, "the ground pivots too close together")
