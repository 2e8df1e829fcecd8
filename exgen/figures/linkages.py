"""Linkage figures (course text §7.5-7.11), drawn to scale from each variant's data.

Joints are lettered as the sheets name them; each given length is written beside its link
and the crank angle is marked from its reference line. Angles on the page follow chapter 7's
convention, from +x counter-clockwise, which a small x-y glyph repeats. Nothing asked is
printed; the key's figures add what the working finds (the other circuit dashed, limit
positions, the synthesis construction).
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from ..mechanics.slider_cranks import slider_crank as solve_slider
from .kinematic import DASH, Sketch, centre_of, fit
from .linkage_poses import joints, pose
from .svg import NOTE_SIZE, unit

#: Where the slider is, as a caption says it: "to the right of" the pivot, but "below" it (never "below of").
SLIDER_PLACE = {"right": "to the right of", "left": "to the left of", "below": "below", "above": "above"}

SUBSCRIPT = dict(zip("1234", "₁₂₃₄"))


def _si(variant, name: str) -> float:
    return float(variant.param(name).si)


def _text(variant, name: str) -> str:
    return str(variant.param(name))


def _word(variant, name: str) -> str:
    return str(variant.param(name).exact)


def _step(variant, name: str) -> float:
    return float(variant.step(name).value)


def _crank_arc(s: Sketch, a, b, theta2: float, text: str) -> None:
    """θ2 from +x at the crank pivot: the reference line, the arc, and its label (after the geometry)."""
    radius = max(14.0, min(30.0, 0.45 * math.dist(a, b)))
    s.reference_line(a, radius + 22)
    s.arc(a, radius, 0.0, theta2)
    return lambda: s.angle_label(a, radius, 0.0, theta2, text)


def _fourbar_geometry(s: Sketch, page, other=None) -> None:
    a, b, c, d = (page[k] for k in "ABCD")
    s.thin(a, d, dash="12 3 2 3", cls="ground-line")
    if other is not None:
        s.bar(b, other, dash=DASH, cls="other-circuit")
        s.bar(d, other, dash=DASH, cls="other-circuit")
        s.pin(other, dash="2 2")
    s.bar(a, b)
    s.bar(b, c)
    s.bar(c, d)
    s.ground_pivot(a)
    s.ground_pivot(d)
    s.pin(b)
    s.pin(c)


def _fourbar_labels(s: Sketch, page, lengths, letters="ABCD", other=None) -> None:
    """Joint letters, then the four lengths (ground, crank, coupler, rocker)."""
    middle = centre_of([page[k] for k in "ABCD"])
    for key, letter in zip("ABCD", letters):
        s.joint_label(page[key], letter, middle)
    if other is not None:
        s.joint_label(other, "C′", middle)
    for (p, q), text in zip((("A", "D"), ("A", "B"), ("B", "C"), ("C", "D")), lengths):
        s.link_label(page[p], page[q], text, middle)


def _fourbar_figure(variant, key: bool) -> str:
    lengths = [_si(variant, f"L{i}") for i in range(1, 5)]
    theta2 = _si(variant, "theta2")
    circuit = int(_word(variant, "circuit"))
    points = joints(*lengths, theta2, circuit)
    other = joints(*lengths, theta2, 3 - circuit)["C"] if key else None
    frame = fit(list(points.values()) + ([other] if other else []), 380, 250)
    page = {k: frame(v) for k, v in points.items()}
    s = Sketch()
    _fourbar_geometry(s, page, frame(other) if other else None)
    angle_label = _crank_arc(s, page["A"], page["B"], theta2, f"θ₂ = {_text(variant, 'theta2')}")
    s.corner_axes()
    _fourbar_labels(s, page, [f"L{SUBSCRIPT[str(i)]} = {_text(variant, f'L{i}')}" for i in range(1, 5)],
                    other=frame(other) if other else None)
    angle_label()
    return s.svg(f"Four-bar linkage in circuit {circuit}" + (", the other circuit dashed (C′)" if key else ""))


def fourbar(variant) -> str:
    """The four-bar example's linkage at θ2 in the asked circuit, to scale."""
    return _fourbar_figure(variant, key=False)


def fourbar_circuits(variant) -> str:
    """For the key: the same linkage with the other circuit's coupler and rocker dashed (C′)."""
    return _fourbar_figure(variant, key=True)


def fourbar_as_drawn(variant) -> str:
    """§7.9 question 2: the linkage as assembled, D at the origin; which root it is the sheet asks, so the
    caption names no circuit."""
    return _roots_figure(variant, key=False)


def fourbar_both_roots(variant) -> str:
    """For the key: the linkage as drawn, and the other root's coupler and rocker dashed (C′)."""
    return _roots_figure(variant, key=True)


def _roots_figure(variant, key: bool) -> str:
    b = (_step(variant, "xB"), _step(variant, "yB"))
    points = {"A": (_si(variant, "xA"), _si(variant, "yA")), "B": b, "C": (_step(variant, "xC"), _step(variant, "yC")),
              "D": (0.0, 0.0)}
    shown = _word(variant, "circuit")
    other = lk.polar((0.0, 0.0), _si(variant, "L4"), _step(variant, "theta4_" + ("minus" if shown == "2" else "plus")))
    frame = fit(list(points.values()) + ([other] if key else []), 380, 250)
    page = {k: frame(v) for k, v in points.items()}
    s = Sketch()
    _fourbar_geometry(s, page, frame(other) if key else None)
    angle_label = _crank_arc(s, page["A"], page["B"], _si(variant, "theta2"), f"θ₂ = {_text(variant, 'theta2')}")
    s.corner_axes()
    middle = centre_of([page[k] for k in "ABCD"])
    for k in "ABC":
        s.joint_label(page[k], k, middle)
    s.joint_label(page["D"], "D (0, 0)", middle)
    if key:
        s.joint_label(frame(other), "C′", middle)
    for (p, q), text in zip((("A", "B"), ("B", "C"), ("C", "D")),
                            (f"L{SUBSCRIPT[str(i)]} = {_text(variant, f'L{i}')}" for i in (2, 3, 4))):
        s.link_label(page[p], page[q], text, middle)
    angle_label()
    return s.svg("Four-bar linkage as assembled; D at the origin" + (", the other root dashed (C′)" if key else ""))


def coupler_point(variant) -> str:
    """The four-bar example's suspension: D at the origin, A where given, the coupler plate BCP."""
    world = {"A": (_si(variant, "xA"), _si(variant, "yA")), "B": (_step(variant, "xB"), _step(variant, "yB")),
             "C": (_step(variant, "xC"), _step(variant, "yC")), "D": (0.0, 0.0),
             "P": (_step(variant, "xP"), _step(variant, "yP"))}
    frame = fit(list(world.values()), 380, 280)
    page = {k: frame(v) for k, v in world.items()}
    s = Sketch()
    s.plate([page["B"], page["C"], page["P"]])
    s.bar(page["A"], page["B"])
    s.bar(page["C"], page["D"])
    s.ground_pivot(page["A"])
    s.ground_pivot(page["D"])
    s.pin(page["B"])
    s.pin(page["C"])
    s.dot(page["P"])
    angle_label = _crank_arc(s, page["A"], page["B"], _si(variant, "theta2"), f"θ₂ = {_text(variant, 'theta2')}")
    s.corner_axes()
    linkage = centre_of([page[k] for k in "ABCD"])
    triangle = centre_of([page[k] for k in "BCP"])
    for key in "ABC":
        s.joint_label(page[key], key, linkage)
    s.joint_label(page["D"], "D (0, 0)", linkage)
    s.joint_label(page["P"], "P", triangle)
    s.link_label(page["A"], page["B"], f"L₂ = {_text(variant, 'L2')}", linkage)
    s.link_label(page["C"], page["D"], f"L₄ = {_text(variant, 'L4')}", linkage)
    for p, q, text in (("B", "C", f"L₃ = {_text(variant, 'L3')}"), ("C", "P", f"CP = {_text(variant, 'CP')}"),
                       ("B", "P", f"BP = {_text(variant, 'BP')}")):
        s.link_label(page[p], page[q], text, triangle)
    angle_label()
    return s.svg("Four-bar linkage with a triangular coupler plate BCP; D at the origin")


NAMES = ("AB", "BC", "CD", "DA")


def _loop_letters(ground: str) -> str:
    """The sheet's letters at the drawing's crank pivot, crank pin, rocker pin and rocker pivot
    when `ground` is the fixed link: its second letter is the pivot of the next link round."""
    ring = "ABCD"
    start = ring.index(ground[1])
    return "".join(ring[(start + k) % 4] for k in range(4))


def grashof_links(variant) -> str:
    """The four links joined in their loop, the fixed one on the ground, each with its length."""
    ground = _word(variant, "ground")
    at = NAMES.index(ground)
    order = [NAMES[(at + k) % 4] for k in range(4)]          # ground, then round the loop
    lengths = [_si(variant, n) for n in order]
    theta2 = _clearest_pose(*lengths)
    points = joints(*lengths, theta2, 1)
    frame = fit(list(points.values()), 360, 230)
    page = {k: frame(v) for k, v in points.items()}
    s = Sketch()
    _fourbar_geometry(s, page)
    s.corner_axes()
    _fourbar_labels(s, page, [f"{name} = {_text(variant, name)}" for name in order], _loop_letters(ground))
    return s.svg(f"Four-bar linkage ABCD with link {ground} fixed")


def _clearest_pose(ground: float, crank: float, coupler: float, rocker: float) -> float:
    """The crank angle at which the linkage is drawn most clearly: the transmission angle nearest 90°."""
    best, best_gap = math.radians(60), math.inf
    for degrees in range(5, 360, 5):
        theta2 = math.radians(degrees)
        if lk.can_assemble(ground, crank, coupler, rocker, theta2):
            gap = abs(pose(ground, crank, coupler, rocker, theta2).gamma - math.pi / 2) + 0.2 * abs(theta2 - 1.2)
            if gap < best_gap:
                best, best_gap = theta2, gap
    return best


TOWARDS = {"right": (1.0, 0.0), "left": (-1.0, 0.0), "below": (0.0, -1.0), "above": (0.0, 1.0)}


def slider_crank(variant) -> str:
    """The slider-crank example: crank pivot A placed from O, the slider on its line of slide, the piston tip P."""
    where = _word(variant, "slider")
    vertical = where in ("below", "above")
    offset, crank, coupler = _si(variant, "L1"), _si(variant, "L2"), _si(variant, "L3")
    theta2, tip = _si(variant, "theta2"), _si(variant, "tip")
    xa, ya = _si(variant, "xA"), _si(variant, "yA")
    pos = solve_slider(crank, coupler, offset, theta2, "vertical" if vertical else "horizontal", where)
    ux, uy = TOWARDS[where]
    world = {"O": (0.0, 0.0), "A": (xa, ya), "B": (xa + pos.b[0], ya + pos.b[1]), "C": (xa + pos.c[0], ya + pos.c[1])}
    world["P"] = (world["C"][0] + ux * tip, world["C"][1] + uy * tip)
    foot = (xa + offset, ya) if vertical else (xa, ya - offset)    # A's foot on the line of slide
    frame = fit(list(world.values()) + [foot], 520, 270)
    page = {k: frame(v) for k, v in world.items()}
    s = Sketch()
    start, end = frame(foot), page["P"]
    direction = unit((end[0] - start[0], end[1] - start[1])) if math.dist(start, end) > 1 else (1.0, 0.0)
    # the guide's ground on the side of the line away from the crank pivot
    across = (1.0, 0.0) if vertical else (0.0, 1.0)
    s.guide((start[0] - direction[0] * 30, start[1] - direction[1] * 30),
            (end[0] + direction[0] * 30, end[1] + direction[1] * 30), across)
    s.thin(page["C"], page["P"], width=6.0, cls="piston")
    s.dot(page["P"])
    s.bar(page["A"], page["B"])
    s.bar(page["B"], page["C"])
    s.ground_pivot(page["A"], down=(-1.0, 0.0) if vertical else (0.0, -1.0))
    s.pin(page["B"])
    s.slider_block(page["C"], direction)
    if offset > 0:
        s.thin(page["A"], frame(foot), cls="offset")
        s.d.arrowhead(frame(foot), unit((frame(foot)[0] - page["A"][0], frame(foot)[1] - page["A"][1])), 6.0)
    angle_label = _crank_arc(s, page["A"], page["B"], theta2, f"θ₂ = {_text(variant, 'theta2')}")
    s.dot(page["O"])
    s.corner_axes()
    middle = centre_of([page[k] for k in "ABC"])
    for key in "ABC":
        s.joint_label(page[key], key, middle)
    s.joint_label(page["P"], "P", page["C"], 13)
    s.joint_label(page["O"], "O (0, 0)", middle)
    s.link_label(page["A"], page["B"], f"L₂ = {_text(variant, 'L2')}", middle)
    s.link_label(page["B"], page["C"], f"L₃ = {_text(variant, 'L3')}", middle)
    if offset > 0:
        s.link_label(page["A"], frame(foot), f"L₁ = {_text(variant, 'L1')}", page["C"])
    s.link_label(page["C"], page["P"], f"{_text(variant, 'tip')}", middle)
    angle_label()
    kind = "In-line" if offset == 0 else "Offset"
    return s.svg(f"{kind} slider-crank, the slider {SLIDER_PLACE.get(where, where)} the crank pivot")


def _rocker_figure(variant, key: bool) -> str:
    lengths = [_si(variant, f"L{i}") for i in range(1, 5)]
    limits = lk.rocker_limits(*lengths)
    drawn_at = _clearest_pose(*lengths)
    points = joints(*lengths, drawn_at, 1)
    extremes = [joints(*lengths, t, 1) for t in (limits.theta2_extended, limits.theta2_folded)]
    frame = fit(list(points.values()) + [e[k] for e in extremes for k in "BC"], 380, 250)
    page = {k: frame(v) for k, v in points.items()}
    s = Sketch()
    ends = []
    if key:
        for extreme in extremes:
            a, b, c, d = (frame(extreme[k]) for k in "ABCD")
            s.bar(a, b, dash=DASH, cls="limit")
            s.bar(b, c, dash=DASH, cls="limit")
            s.bar(c, d, dash=DASH, cls="limit")
            s.pin(c, dash="2 2")
            ends.append(c)
        low, high = sorted((limits.theta4_extended, limits.theta4_folded))
        radius = 0.5 * lengths[3] * frame.scale
        s.arc(page["D"], radius, low, high)
    _fourbar_geometry(s, page)
    s.corner_axes()
    _fourbar_labels(s, page, [f"L{SUBSCRIPT[str(i)]} = {_text(variant, f'L{i}')}" for i in range(1, 5)])
    if key:
        middle = centre_of([page[k] for k in "ABCD"])
        for c, name in zip(ends, ("C′", "C″")):
            s.joint_label(c, name, middle)
        s.angle_label(page["D"], radius, low, high, "ψ")
    return s.svg("Crank-rocker" + (" with its limit positions dashed: C′ stretched out, C″ folded" if key else ""))


def rocker_limits(variant) -> str:
    """The crank-rocker of Problems 7.2-7.3 at a position between its limits, to scale."""
    return _rocker_figure(variant, key=False)


def rocker_limit_positions(variant) -> str:
    """For the key: the limit positions C′ (stretched out) and C″ (folded) dashed, and the swing ψ."""
    return _rocker_figure(variant, key=True)


def actuator(variant) -> str:
    """Problem 7.2: the support link about A, the actuator from O to B, as drawn."""
    o, r = (_si(variant, "xO"), _si(variant, "yO")), _si(variant, "r")
    theta1 = _step(variant, "theta1")
    world = {"A": (0.0, 0.0), "O": o, "B": lk.polar((0.0, 0.0), r, theta1), "E": lk.polar((0.0, 0.0), 1.3 * r, theta1)}
    frame = fit(list(world.values()), 380, 270)
    page = {k: frame(v) for k, v in world.items()}
    s = Sketch()
    s.bar(page["A"], page["E"], cls="support-link")
    ux, uy = unit((page["B"][0] - page["O"][0], page["B"][1] - page["O"][1]))
    body = 0.55 * math.dist(page["O"], page["B"])
    s.thin(page["O"], (page["O"][0] + ux * body, page["O"][1] + uy * body), width=9.0, cls="cylinder")
    s.thin(page["O"], page["B"], width=2.2, cls="rod")
    s.ground_pivot(page["A"])
    s.ground_pivot(page["O"])
    s.pin(page["B"])
    s.corner_axes()
    middle = centre_of([page[k] for k in "AOB"])
    for key in "AOB":
        s.joint_label(page[key], key, middle)
    s.link_label(page["A"], page["B"], f"AB = {_text(variant, 'r')}", middle)
    s.link_label(page["O"], page["B"], f"OB = {_text(variant, 's1')}", middle)
    return s.svg("Support link about A turned by a linear actuator OB; A at the origin")


PIVOT = {"M": "E", "N": "F"}   # the ground pivots of the links to M and to N


#: How positions 1, 2, 3 of the gripper are drawn: solid, dashed, dotted.
POSITION_DASH = ("", DASH, "2 3")


def _synthesis_figure(variant, key: bool, count: int = 2) -> str:
    world = {}
    positions = range(1, count + 1)
    for k in positions:
        world[f"M{k}"] = (_si(variant, f"xM{k}"), _si(variant, f"yM{k}"))
        world[f"N{k}"] = (_step(variant, f"xN{k}"), _step(variant, f"yN{k}"))
    height = {name: (_step(variant, f"yO{name}") if count == 3 else 0.0) for name in ("M", "N")}
    pivots = {name: (_step(variant, f"xO{name}"), height[name]) for name in ("M", "N")}
    extent = list(world.values()) + [(0.0, 0.0)] + (list(pivots.values()) if key else [])
    frame = fit(extent, 400, 260)
    page = {k: frame(v) for k, v in world.items()}
    s = Sketch()
    xs = [p[0] for p in page.values()] + [0.0] + ([frame(p)[0] for p in pivots.values()] if key else [])
    floor = frame((0.0, 0.0))[1]
    s.hatch_line((min(xs) - 40, floor), (max(xs) + 40, floor), (0.0, 1.0))
    for k in positions:
        dash = POSITION_DASH[k - 1]
        s.thin(page[f"M{k}"], page[f"N{k}"], dash=dash, width=7.0 if not dash else 2.0, cls=f"gripper-{k}")
        s.pin(page[f"M{k}"], dash="2 2" if dash else "")
        s.pin(page[f"N{k}"], dash="2 2" if dash else "")
    if key:
        for name in ("M", "N"):
            o = frame(pivots[name])
            for k in positions:
                s.bar(o, page[f"{name}{k}"], dash=POSITION_DASH[k - 1] and DASH, cls="synthesised")
            for k in positions[:-1]:
                s.thin(page[f"{name}{k}"], page[f"{name}{k + 1}"], dash="2 3", cls="chord")
            s.ground_pivot(o)
    origin = frame((0.0, 0.0))
    s.thin((origin[0], origin[1] - 7), (origin[0], origin[1] + 7), cls="origin")
    s.corner_axes()
    for k in positions:
        centre = centre_of([page[f"M{k}"], page[f"N{k}"]])
        centre = (centre[0], centre[1] + 30)
        s.joint_label(page[f"M{k}"], f"M{SUBSCRIPT[str(k)]}", centre)
        s.joint_label(page[f"N{k}"], f"N{SUBSCRIPT[str(k)]}", centre)
    if key:
        for name in ("M", "N"):
            o = frame(pivots[name])
            s.joint_label(o, PIVOT[name], (o[0], o[1] - 40))
    s.label([((max(xs) + 44, floor + 5), "start", 0.0), ((min(xs) - 44, floor + 5), "end", 0.0)],
            "floor, y = 0", size=NOTE_SIZE, style="italic")
    s.label([((origin[0] + dx, origin[1] - rise), anchor, 0.0) for rise in (12, 26, -26, 42, -40)
             for dx, anchor in ((0, "middle"), (8, "start"), (-8, "end"), (24, "start"), (-24, "end"))],
            "x = 0", size=NOTE_SIZE, style="italic")
    shown = ("in position 1 (solid) and position 2 (dashed)" if count == 2 else
             "in positions 1 (solid), 2 (dashed) and 3 (dotted)")
    return s.svg(f"Gripper plate MN {shown}" + (", with the ground pivots found" if key else ""))


def synthesis(variant) -> str:
    """§7.11: the gripper's two positions above the floor on which both pivots must stand."""
    return _synthesis_figure(variant, key=False)


def synthesis_construction(variant) -> str:
    """For the key: the ground pivots E and F on the floor and the links to both positions."""
    return _synthesis_figure(variant, key=True)


def synthesis_three(variant) -> str:
    """§7.11 as the text draws it: the gripper's three positions, above the floor."""
    return _synthesis_figure(variant, key=False, count=3)


def synthesis_three_construction(variant) -> str:
    """For the key: each ground pivot where its pin's chords' bisectors cross, with the links to all three
    positions; a pivot below the floor is drawn where it falls."""
    return _synthesis_figure(variant, key=True, count=3)
