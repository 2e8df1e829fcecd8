"""Governor schematics drawn to each variant's geometry (course text chapter 4).

Watt, Porter and Proell governors are drawn in elevation about the spindle's axis, arms to scale
from their pivots, the balls at their radius, the sleeve and its load; where a problem asks about
two positions, both are drawn side by side at one scale. Hartnell governors are drawn as one bell
crank on its fulcrum with the spring on the sleeve; a spring-controlled governor's measurements
as a controlling-force graph. Values are printed as on the sheet; unknowns carry "?".
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..mechanics import governors as gv
from .flywheels import need
from .svg import LINE, THIN, Drawing, num
from .values import Shown, shown

BALL = 11.0         # px radius of a ball (its mass is not a size)
PIVOT = 3.0         # px radius of a pivot
VIEW_H = 230.0      # px from the upper pivots to the sleeve pivots in the lowest drawn position
VIEW_W = 300.0      # px across one view's balls
GAP = 60.0          # px between two views' labels
TWO_VIEW_W = 200.0  # px across one of two views' balls: both, with their labels, fit a sheet's width
ARM = 1.8           # arm stroke width


@dataclass(frozen=True)
class Position:
    """One drawn position of a Porter-type governor, in metres from the upper pivots (y down)."""

    pose: gv.Pose
    ball: tuple[float, float]       # ball centre: radius, depth below the upper pivots
    caption: str


def _porter_position(linkage: gv.Linkage, r: float, caption: str, extension: float = 0.0,
                     tilt: float = 0.0) -> Position:
    at = gv.pose(linkage, r)
    ball = (r + extension * math.sin(tilt), at.h_upper - extension * math.cos(tilt))
    return Position(at, ball, caption)


def _scale(positions: list[Position], view_w: float = VIEW_W) -> float:
    """One scale for every view: the deepest fits VIEW_H, the widest `view_w` across its balls."""
    deepest = max(p.pose.depth for p in positions)
    widest = max(max(p.ball[0], p.pose.r) for p in positions)
    return min(VIEW_H / deepest, (view_w / 2 - BALL) / widest)


def _draw_position(drawing: Drawing, linkage: gv.Linkage, at: Position, ox: float, scale: float,
                   load: str = "", labels: dict | None = None) -> dict:
    """One governor about the axis x = ox; returns where its parts are (px) for dimensions and labels."""
    labels = labels or {}
    s = scale
    pose = at.pose
    top, joint_y, sleeve_y = 0.0, pose.h_upper * s, pose.depth * s
    eu, el, rj = linkage.upper_offset * s, linkage.lower_offset * s, pose.r * s
    ball = (at.ball[0] * s, at.ball[1] * s)
    drawing.line((ox, top - 34), (ox, sleeve_y + (44 if load else 26)), THIN, dash="8 3 2 3", cls="axis")
    # the spindle's head carrying the upper pivots
    drawing.line((ox - eu - 8, top - 8), (ox + eu + 8, top - 8), LINE, cls="head")
    for side in (-1, 1):
        pivot = (ox + side * eu, top)
        joint = (ox + side * rj, joint_y)
        foot = (ox + side * el, sleeve_y)
        drawing.line((pivot[0], top - 8), pivot, THIN)
        drawing.line(pivot, joint, ARM, cls="arm upper")
        drawing.line(joint, foot, ARM, cls="arm lower")
        centre = (ox + side * ball[0], ball[1])
        if centre != joint:  # a Proell ball on its extension
            drawing.line(joint, centre, ARM, cls="arm extension")
        drawing.circle(pivot, PIVOT, THIN, fill="white")
        drawing.circle(foot, PIVOT, THIN, fill="white")
        drawing.circle(centre, BALL, LINE, fill="white", cls="ball")
    # the sleeve, and the central load on it
    half = max(el, 6.0) + 6
    drawing.path(f"M {num(ox - half)},{num(sleeve_y - 7)} L {num(ox + half)},{num(sleeve_y - 7)} "
                 f"L {num(ox + half)},{num(sleeve_y + 7)} L {num(ox - half)},{num(sleeve_y + 7)} Z", LINE, cls="sleeve")
    drawing.extend(ox - half, sleeve_y - 7, ox + half, sleeve_y + 7)
    if load:
        w = half + 10
        drawing.path(f"M {num(ox - w)},{num(sleeve_y + 7)} L {num(ox + w)},{num(sleeve_y + 7)} "
                     f"L {num(ox + w)},{num(sleeve_y + 30)} L {num(ox - w)},{num(sleeve_y + 30)} Z", LINE, cls="load")
        drawing.extend(ox - w, sleeve_y + 7, ox + w, sleeve_y + 30)
    return {"top": top, "joint_y": joint_y, "sleeve_y": sleeve_y, "eu": eu, "el": el, "rj": rj, "ball": ball,
            "half": half}


def _radius_dimension(drawing: Drawing, ox: float, where: dict, text: str, to_ball: bool = True, side: int = -1) -> None:
    """A horizontal dimension from the axis to a ball (or joint) on `side`, its label placed clear."""
    x = where["ball"][0] if to_ball else where["rj"]
    y = where["ball"][1] if to_ball else where["joint_y"]
    y_dim = y + BALL + 16
    end = ox + side * x
    drawing.line((end, y + BALL + 3), (end, y_dim + 5), THIN, cls="extension-line")
    drawing.dimension((ox, y_dim), (end, y_dim))
    anchor = "end" if side < 0 else "start"
    outside = end + side * (BALL + 6)
    drawing.place([((outside, y_dim + 5), anchor), ((outside, y_dim + 20), anchor), ((outside, y_dim + 35), anchor),
                   (((ox + end) / 2, y_dim - 5), "middle"), (((ox + end) / 2, y_dim + 16), "middle")], text,
                  cls="dim-label")


def _offset_dimension(drawing: Drawing, ox: float, y: float, offset: float, text: str, below: bool) -> None:
    """The distance of a pivot from the axis, on the right of the view."""
    if offset <= 0:
        return
    y_dim = y + (22 if below else -22)
    drawing.line((ox + offset, y + (4 if below else -4)), (ox + offset, y_dim + (4 if below else -4)), THIN,
                 cls="extension-line")
    drawing.dimension((ox, y_dim), (ox + offset, y_dim))
    base = y_dim + 5
    drawing.place([((ox + offset + 6, base), "start"), ((ox + offset + 6, base + (14 if below else -14)), "start")],
                  text, cls="dim-label")


def _outer(where: dict) -> float:
    """px from the axis to the outside of the widest part of a view."""
    return max(where["ball"][0], where["rj"]) + BALL


def _side_labels(drawing: Drawing, ox: float, where: dict, lines: list[str], side: int = 1) -> None:
    """Labels outside a view, level with its ball and then above and below it: the ball's mass and the like."""
    x = ox + side * (_outer(where) + 8)
    anchor = "start" if side > 0 else "end"
    by = where["ball"][1]
    for text in lines:
        drawing.place([((x, by + 5 + dy), anchor) for dy in (0, -18, 18, -36, 36, -54, 54, -72, 72)], text)


def _upper_arm_label(drawing: Drawing, ox: float, where: dict, text: str, side: int = 1) -> None:
    """The arms' length, outside the view, level with the upper arms' middle or near it."""
    x = ox + side * (_outer(where) + 8)
    anchor = "start" if side > 0 else "end"
    y = where["joint_y"] / 2
    drawing.place([((x, y + dy), anchor) for dy in (0, -18, 18, -36, 36, -54)], text)


def _caption(drawing: Drawing, ox: float, y: float, text: str) -> None:
    drawing.place([((ox, y), "middle"), ((ox, y + 16), "middle")], text, style="italic")


def _load_label(drawing: Drawing, ox: float, where: dict, text: str) -> None:
    y = where["sleeve_y"] + 24
    w = where["half"] + 10
    drawing.place([((ox + w + 8, y), "start"), ((ox + w + 8, y + 16), "start"), ((ox - w - 8, y), "end")], text)


def _label(q: Shown | None, symbol: str | None = None) -> str:
    return q.label(symbol) if q is not None else ""


def _porter_linkage(variant) -> gv.Linkage:
    """Equal arms l; pivots e_u and e_l off the axis, or all of them e where the template has one offset."""
    l = need(variant, "l").si
    e_u, e_l = shown(variant, "e_u"), shown(variant, "e_l")
    if e_u is None and e_l is None:
        e_u = e_l = shown(variant, "e")
    return gv.Linkage(l, l, e_u.si if e_u else 0.0, e_l.si if e_l else 0.0)


def _offset_labels(variant) -> tuple[str, str]:
    """The upper and lower pivots' offsets as printed ("" where a pivot is on the axis): the dimension
    line itself says what the distance is. `e` is the offset of every pivot where there is no e_u, e_l."""
    e_u, e_l = shown(variant, "e_u"), shown(variant, "e_l")
    if e_u is None and e_l is None:
        e_u = e_l = shown(variant, "e")
        e_u = None
    return (e_u.value_text if e_u and e_u.si > 0 else ""), (e_l.value_text if e_l and e_l.si > 0 else "")


def _point_letters(drawing: Drawing, ox: float, where: dict, side: int = -1) -> None:
    """The points the statement names on one side of a Proell governor: the ball A on the extension AB of
    the lower arm BC, the upper arm BD from its pivot D (Example 4.2's figure)."""
    bx, by = where["ball"]
    points = (("A", (ox + side * bx, by), BALL), ("B", (ox + side * where["rj"], where["joint_y"]), PIVOT),
              ("C", (ox + side * where["el"], where["sleeve_y"]), PIVOT), ("D", (ox + side * where["eu"], where["top"]), PIVOT))
    out, back = ("end", "start") if side < 0 else ("start", "end")
    for letter, (x, y), radius in points:
        d = radius + 5
        near = [((x + side * d, y - d + 2), out), ((x + side * d, y + d + 9), out), ((x, y - d - 3), "middle"),
                ((x - side * d, y - d + 2), back), ((x, y + d + 13), "middle"), ((x - side * d, y + d + 9), back)]
        if letter == "C":  # beside the sleeve, level with its pivot, rather than on the sleeve or its load
            near.insert(0, ((ox + side * (where["half"] + 5), y + 4), out))
        drawing.place(near, letter, cls="point")


def _two_positions(variant, positions: list[Position], radius_labels: list[str], title: str,
                   load: str = "", extension_label: str = "", letters: bool = False) -> str:
    linkage = _porter_linkage(variant)
    scale = _scale(positions, VIEW_W if len(positions) == 1 else TWO_VIEW_W)
    drawing = Drawing()
    upper_offset, lower_offset = _offset_labels(variant)
    arm = need(variant, "l").value_text
    mass = _label(shown(variant, "m"))
    width = max(max(p.ball[0], p.pose.r) for p in positions) * scale * 2 + 2 * BALL + GAP
    origins = []
    for k, (at, radius) in enumerate(zip(positions, radius_labels)):
        ox = k * width
        where = _draw_position(drawing, linkage, at, ox, scale, load)
        side = -1 if k == 0 and len(positions) > 1 else 1   # labels face outward, away from the other view
        if k == 0:
            _upper_arm_label(drawing, ox, where, f"all arms {arm}", side)
            if upper_offset:
                _offset_dimension(drawing, ox, where["top"] - 8, where["eu"], upper_offset, below=False)
            if lower_offset:
                _offset_dimension(drawing, ox, where["sleeve_y"] + (30 if load else 7), where["el"], lower_offset, below=True)
            extra = [mass] + ([extension_label] if extension_label else [])
            _side_labels(drawing, ox, where, [t for t in extra if t], side)
            if load:
                _load_label(drawing, ox, where, load)
        _radius_dimension(drawing, ox, where, radius, to_ball=not extension_label, side=-1 if k == 0 else 1)
        if letters:
            _point_letters(drawing, ox, where, side=-1 if k == 0 else 1)
        origins.append(ox)
    bottom = drawing.box[3] + 20
    for ox, at in zip(origins, positions):
        if at.caption:
            _caption(drawing, ox, bottom, at.caption)
    return drawing.svg(title)


# ---- the templates' figures ----------------------------------------------------------------------


def watt(variant) -> str:
    """A Watt governor, arms on the axis, drawn to its arms and (solved) height; the height marked unknown."""
    h, arm = need(variant, "h_1"), need(variant, "l")
    linkage = gv.Linkage(arm.si, arm.si, 0.0, 0.0)
    at = _porter_position(linkage, math.sqrt(max(arm.si ** 2 - h.si ** 2, 1e-6 * arm.si ** 2)), "")
    scale = _scale([at])
    drawing = Drawing()
    where = _draw_position(drawing, linkage, at, 0.0, scale)
    x = where["rj"] + BALL + 26
    drawing.line((where["rj"] + BALL + 4, where["joint_y"]), (x + 5, where["joint_y"]), THIN, cls="extension-line")
    drawing.line((where["eu"] + PIVOT + 4, 0.0), (x + 5, 0.0), THIN, cls="extension-line")
    drawing.dimension((x, 0.0), (x, where["joint_y"]))
    drawing.place([((x + 8, where["joint_y"] / 2 + 5), "start"), ((x + 8, where["joint_y"] / 2 + 22), "start")],
                  h.label("h"))
    _upper_arm_label(drawing, 0.0, where, f"arms {arm.value_text}", side=-1)
    speed = shown(variant, "N1")
    if speed is not None:
        drawing.place([((0.0, -48), "middle"), ((0.0, -64), "middle")], speed.label("N₁"))
    return drawing.svg("Watt governor: the height h from the arms' pivot to the balls' plane")


def porter_travel(variant) -> str:
    """Example 4.1: the governor in its mean position, arms at α, with the sleeve's travel ±x marked."""
    linkage = _porter_linkage(variant)
    alpha = need(variant, "alpha")
    mean = _porter_position(linkage, linkage.upper_offset + linkage.upper * math.sin(alpha.si), "mean position")
    scale = _scale([mean])
    drawing = Drawing()
    load = _label(shown(variant, "M"))
    where = _draw_position(drawing, linkage, mean, 0.0, scale, load)
    _upper_arm_label(drawing, 0.0, where, f"all arms {need(variant, 'l').value_text}")
    _side_labels(drawing, 0.0, where, [t for t in (_label(shown(variant, "m")),) if t])
    upper_offset, lower_offset = _offset_labels(variant)
    if lower_offset:
        _offset_dimension(drawing, 0.0, where["sleeve_y"] + 30, where["el"], lower_offset, below=True)
    _load_label(drawing, 0.0, where, load)
    # the angle α at the left upper pivot, between the axis direction and the arm
    pivot = (-where["eu"], 0.0)
    radius = 46.0
    end = (pivot[0] - radius * math.sin(alpha.si), radius * math.cos(alpha.si))
    drawing.line(pivot, (pivot[0], radius + 12), THIN, dash="3 3", cls="vertical")
    drawing.path(f"M {num(pivot[0])},{num(radius)} A {num(radius)} {num(radius)} 0 0 1 {num(end[0])},{num(end[1])}",
                 THIN, cls="angle-arc")
    mid = alpha.si / 2
    # inside the angle, down its bisector to where the wedge is wide enough for the label
    drawing.place([((pivot[0] - d * math.sin(mid), d * math.cos(mid) + 5), "middle") for d in range(70, 200, 10)]
                  + [((end[0] - 8, end[1] + dy), "end") for dy in (5, 20, -10, 35)], alpha.label("α"))
    # the sleeve's travel, either way from the mean position
    travel = need(variant, "x")
    x0 = -where["half"] - 22
    for sign in (-1, 1):
        drawing.line((x0 - 6, where["sleeve_y"] + sign * travel.si * scale), (x0 + 6, where["sleeve_y"] + sign * travel.si * scale), THIN)
    drawing.dimension((x0, where["sleeve_y"] - travel.si * scale), (x0, where["sleeve_y"] + travel.si * scale))
    drawing.place([((x0 - 8, where["sleeve_y"] + 5), "end"), ((x0 - 8, where["sleeve_y"] + 22), "end")], f"±{travel.value_text}")
    return drawing.svg("Porter governor in its mean position; the sleeve moves ±x from it")


def porter_radii(variant) -> str:
    """Problem 4.2: the governor at its least and greatest radii, side by side."""
    linkage = _porter_linkage(variant)
    r1, r2 = need(variant, "r1"), need(variant, "r2")
    positions = [_porter_position(linkage, r1.si, "least radius"), _porter_position(linkage, r2.si, "greatest radius")]
    return _two_positions(variant, positions, [r1.label("r₁"), r2.label("r₂")],
                          "Porter governor at its least and greatest radii", load=_label(shown(variant, "M")))


def porter_radius(variant) -> str:
    """Problem 4.5: the governor at the radius asked about."""
    linkage = _porter_linkage(variant)
    r = need(variant, "r")
    return _two_positions(variant, [_porter_position(linkage, r.si, "")], [r.label("r")],
                          "Porter governor", load=_label(shown(variant, "M")))


def porter_angles(variant) -> str:
    """Problem 4.4: the governor where the sleeve starts to rise and at the second angle."""
    linkage = _porter_linkage(variant)
    a0, a1 = need(variant, "alpha0"), need(variant, "alpha1")
    positions = [_porter_position(linkage, linkage.upper_offset + linkage.upper * math.sin(a.si), caption)
                 for a, caption in ((a0, f"α₀ = {a0.value_text}"), (a1, f"α₁ = {a1.value_text}"))]
    return _two_positions(variant, positions, ["r₀ = ?", "r₁ = ?"], "Porter governor at the two arm angles",
                          load=_label(shown(variant, "M")))


def proell_mid(variant) -> str:
    """Example 4.2: the Proell governor in mid position, the extension AB vertical (its length unknown)."""
    linkage = _porter_linkage(variant)
    r, ext = need(variant, "r"), need(variant, "AB")
    at = _porter_position(linkage, r.si, "mid position", extension=ext.si)
    return _two_positions(variant, [at], [r.label("r")], "Proell governor in mid position",
                          load=_label(shown(variant, "M")), extension_label=ext.label("AB"), letters=True)


def proell_radii(variant) -> str:
    """Problem 4.3: the Proell governor at its least and greatest joint radii, extensions fixed to the lower arms."""
    linkage = _porter_linkage(variant)
    r1, r2, ext = need(variant, "r1"), need(variant, "r2"), need(variant, "e")
    low = gv.pose(linkage, r1.si)
    high = gv.pose(linkage, r2.si)
    positions = [_porter_position(linkage, r1.si, "lowest position", ext.si),
                 _porter_position(linkage, r2.si, "highest position", ext.si, high.beta - low.beta)]
    return _two_positions(variant, positions, [r1.label("r₁"), r2.label("r₂")],
                          "Proell governor at its lowest and highest positions", load=_label(shown(variant, "M")),
                          extension_label=f"extension {ext.value_text}")
