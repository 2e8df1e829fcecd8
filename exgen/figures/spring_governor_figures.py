"""Spring-loaded governors drawn to each variant's data (course text §4.5, 4.8).

A Hartnell governor is drawn in elevation: on each side a bell crank on its fulcrum, the ball arm
up, the sleeve arm bearing on the sleeve, the spring on the spindle; at two radii, side by side.
A spring-controlled governor's two measurements are drawn as points of its controlling-force
graph, joined by the straight line between them (extending it would show the answer).
"""
from __future__ import annotations

import math

from ..mechanics import governors as gv
from .flywheels import need
from .svg import LINE, THIN, Drawing, num
from .values import shown

BALL = 11.0
PIVOT = 3.0
ARM = 1.8
CRANK_PX = 150.0   # px for the longer of the two crank arms
TWO_VIEW_CRANK_PX = 105.0
GAP = 80.0


def _zigzag(drawing: Drawing, x: float, y0: float, y1: float, half: float = 8.0, turns: int = 6, cls: str = "spring") -> None:
    """A coil spring drawn as a zigzag along x from y0 to y1."""
    points = [(x, y0)]
    for k in range(1, 2 * turns):
        points.append((x + (half if k % 2 else -half), y0 + (y1 - y0) * k / (2 * turns)))
    points.append((x, y1))
    drawing.path("M " + " L ".join(f"{num(a)},{num(b)}" for a, b in points), THIN, cls=cls)
    drawing.extend(x - half, min(y0, y1), x + half, max(y0, y1))


def _hartnell(drawing: Drawing, ox: float, scale: float, a: float, b: float, c: float, theta: float) -> dict:
    """Both bell cranks about the axis x = ox, turned θ from the ball arms' vertical; fulcrums at y = 0."""
    fx = (b + c) * scale
    lift = b * math.sin(theta) * scale
    sleeve_y = -lift  # the rollers ride on the sleeve's lower flange
    top = -(a * scale + BALL + 40)
    drawing.line((ox, top - 10), (ox, 70), THIN, dash="8 3 2 3", cls="axis")
    drawing.line((ox - fx - 10, 34), (ox + fx + 10, 34), LINE, cls="frame")
    drawing.line((ox - 10, top), (ox + 10, top), LINE, cls="spring-cap")
    for side in (-1, 1):
        fulcrum = (ox + side * fx, 0.0)
        ball = (fulcrum[0] + side * a * scale * math.sin(theta), -a * scale * math.cos(theta))
        roller = (fulcrum[0] - side * b * scale * math.cos(theta), -b * scale * math.sin(theta))
        drawing.line((fulcrum[0], 34), fulcrum, THIN, cls="frame")
        drawing.line(fulcrum, ball, ARM, cls="arm ball-arm")
        drawing.line(fulcrum, roller, ARM, cls="arm sleeve-arm")
        drawing.circle(fulcrum, PIVOT, THIN, fill="white")
        drawing.circle(roller, 4.0, THIN, fill="white", cls="roller")
        drawing.circle(ball, BALL, LINE, fill="white", cls="ball")
    flange = c * scale + 4
    drawing.path(f"M {num(ox - flange)},{num(sleeve_y + 4)} L {num(ox + flange)},{num(sleeve_y + 4)} "
                 f"L {num(ox + flange)},{num(sleeve_y + 10)} L {num(ox - flange)},{num(sleeve_y + 10)} Z", LINE, cls="sleeve")
    drawing.path(f"M {num(ox - 9)},{num(sleeve_y - 24)} L {num(ox + 9)},{num(sleeve_y - 24)} "
                 f"L {num(ox + 9)},{num(sleeve_y + 4)} M {num(ox - 9)},{num(sleeve_y + 4)} L {num(ox - 9)},{num(sleeve_y - 24)}",
                 LINE, cls="sleeve")
    drawing.extend(ox - flange, sleeve_y - 24, ox + flange, sleeve_y + 10)
    _zigzag(drawing, ox, top, sleeve_y - 24)
    return {"fx": fx, "top": top, "sleeve_y": sleeve_y, "ball_y": -a * scale * math.cos(theta),
            "ball_x": fx + a * scale * math.sin(theta)}


def _hartnell_labels(drawing: Drawing, ox: float, where: dict, a_text: str, b_text: str, m_text: str, spring: str,
                     sleeve: str) -> None:
    fx = where["fx"]
    drawing.place([((ox + fx + 10, where["ball_y"] / 2 + 5), "start"), ((ox + fx - 10, where["ball_y"] / 2 + 5), "end")],
                  a_text)
    drawing.place([((ox + fx / 2 + 8, 24), "middle"), ((ox + fx / 2 + 8, 54), "middle")], b_text)
    drawing.place([((ox + where["ball_x"] + BALL + 8, where["ball_y"] + 5), "start"),
                   ((ox + where["ball_x"] + BALL + 8, where["ball_y"] - 13), "start")], m_text)
    if spring:
        mid = (where["top"] + where["sleeve_y"] - 24) / 2
        drawing.place([((ox - 14, mid + 5), "end"), ((ox - 14, mid - 13), "end")], spring)
    if sleeve:
        drawing.place([((ox - 16, where["sleeve_y"] + 26), "end"), ((ox - 16, where["sleeve_y"] + 44), "end")], sleeve)


def _radius(drawing: Drawing, ox: float, where: dict, text: str) -> None:
    y = where["ball_y"] - BALL - 14
    x = ox + where["ball_x"]
    drawing.line((x, where["ball_y"] - BALL - 3), (x, y - 5), THIN, cls="extension-line")
    drawing.dimension((ox, y), (x, y))
    drawing.place([((ox + where["ball_x"] / 2, y - 5), "middle"), ((x + 8, y + 5), "start"),
                   ((ox + where["ball_x"] / 2, y - 20), "middle"), ((x + 8, y - 12), "start")], text)


def hartnell_radii(variant) -> str:
    """The Hartnell governor at its least and greatest radii (the sleeve raised by the crank's turn)."""
    a, b = need(variant, "a"), need(variant, "b")
    r1, r2 = need(variant, "r1"), need(variant, "r2")
    # the rollers' radius is not data: the drawing puts the ball arm vertical midway between r1 and r2
    mid = (r1.si + r2.si) / 2
    c = max(mid - b.si, 0.015)
    scale = TWO_VIEW_CRANK_PX / max(a.si, b.si, mid)
    drawing = Drawing()
    width = 2 * (r2.si * scale + BALL) + GAP + 120
    for k, (r, caption) in enumerate(((r1, "least radius"), (r2, "greatest radius"))):
        ox = k * width
        theta = math.asin(max(-0.95, min(0.95, (r.si - (b.si + c)) / a.si)))
        where = _hartnell(drawing, ox, scale, a.si, b.si, c, theta)
        if k == 0:
            _hartnell_labels(drawing, ox, where, a.label("a"), b.label("b"), _text(variant, "m"), "spring",
                             _sleeve(variant, "M"))
        _radius(drawing, ox, where, r.label("r₁" if k == 0 else "r₂"))
        speed = shown(variant, "N1" if k == 0 else "N2")
        drawing.place([((ox, 92), "middle"), ((ox, 108), "middle")], caption + (f", {speed.value_text}" if speed else ""),
                      style="italic")
    return drawing.svg("Hartnell governor at its least and greatest radii")


def hartnell_levers(variant) -> str:
    """Example 4.3: the Hartnell governor as the sleeve starts to rise, with spring 2's lever below it."""
    a, b, c = need(variant, "a"), need(variant, "b"), need(variant, "c")
    r1, L1, L2 = need(variant, "r1"), need(variant, "L1"), need(variant, "L2")
    scale = CRANK_PX / max(a.si, b.si + c.si)
    drawing = Drawing()
    theta = gv.bell_crank_angle(r1.si, b.si + c.si, a.si)
    where = _hartnell(drawing, 0.0, scale, a.si, b.si, c.si, theta)
    k1 = shown(variant, "K1")
    _hartnell_labels(drawing, 0.0, where, a.label("a"), b.label("b"), _text(variant, "m"),
                     "spring 1" + (f", {k1.value_text}" if k1 else ""), _sleeve(variant, "Ms"))
    _radius(drawing, 0.0, where, r1.label("r₁"))
    # spring 2's lever: pushed by the sleeve's rod at the axis, its fulcrum L1 to the right, spring 2 at L2 from it
    lever_y, lx = 96.0, L1.si * scale
    drawing.line((0.0, 70), (0.0, lever_y), LINE, cls="sleeve-rod")
    drawing.line((-14, lever_y), (lx + 14, lever_y), ARM, cls="lever")
    drawing.polygon([(lx, lever_y + 3), (lx - 8, lever_y + 17), (lx + 8, lever_y + 17)], fill="white", width=THIN)
    spring_x = lx - L2.si * scale
    _zigzag(drawing, spring_x, lever_y + 3, lever_y + 50, cls="spring spring-2")
    drawing.line((spring_x - 12, lever_y + 50), (spring_x + 12, lever_y + 50), LINE, cls="ground")
    drawing.place([((spring_x + 14, lever_y + 34), "start"), ((spring_x - 14, lever_y + 34), "end")], "spring 2")
    for start, text, y in ((spring_x, L2.label("L₂"), lever_y + 72), (0.0, L1.label("L₁"), lever_y + 100)):
        drawing.line((start, lever_y + (52 if start else 4)), (start, y + 4), THIN, cls="extension-line")
        drawing.line((lx, lever_y + 20), (lx, y + 4), THIN, cls="extension-line")
        drawing.dimension((start, y), (lx, y))
        drawing.place([(((start + lx) / 2, y - 5), "middle"), (((start + lx) / 2, y + 16), "middle")], text)
    return drawing.svg("Hartnell governor as the sleeve begins to rise, spring 2 acting through a lever")


def _sleeve(variant, name: str) -> str:
    q = shown(variant, name)
    return f"sleeve {q.value_text}" if q is not None else ""


def _text(variant, name: str, symbol: str | None = None) -> str:
    q = shown(variant, name)
    return q.label(symbol) if q is not None else ""


PLOT_W = 380.0
PLOT_H = 220.0


def controlling_force(variant) -> str:
    """The controlling force measured at two radii, on axes from the origin; the line between them only."""
    r1, r2, f1, f2 = need(variant, "r1"), need(variant, "r2"), need(variant, "F1"), need(variant, "F2")
    sx, sy = PLOT_W / (r2.si * 1.15), PLOT_H / (f2.si * 1.15)
    drawing = Drawing()
    drawing.line((0, 0), (PLOT_W + 20, 0), THIN, cls="axis")
    drawing.arrowhead((PLOT_W + 20, 0), (1, 0))
    drawing.line((0, 0), (0, -PLOT_H - 20), THIN, cls="axis")
    drawing.arrowhead((0, -PLOT_H - 20), (0, -1))
    drawing.text((PLOT_W + 28, 5), "r", anchor="start", style="italic")
    drawing.text((8, -PLOT_H - 14), "F", anchor="start", style="italic")
    points = [(r1.si * sx, -f1.si * sy), (r2.si * sx, -f2.si * sy)]
    drawing.line(points[0], points[1], LINE, cls="force-line")
    for (x, y), r, f in zip(points, (r1, r2), (f1, f2)):
        drawing.line((x, y), (x, 0), THIN, dash="3 3", cls="guide")
        drawing.line((x, y), (0, y), THIN, dash="3 3", cls="guide")
        drawing.circle((x, y), 3.0, THIN, fill="black", cls="measured")
        drawing.place([((x, 18), "middle"), ((x, 34), "middle")], r.value_text)
        drawing.place([((-6, y + 5), "end"), ((-6, y + 20), "end")], f.value_text)
    drawing.text((0, 18), "0", anchor="middle")
    return drawing.svg("Controlling force on each ball against its radius, as measured")
