"""Geared hoists seen along the shafts: motor, gears, drum, rope and load (Figures 1.25, P1.2, P1.4).

Gears that mesh touch at their pitch circles, with pitch radii in proportion to their teeth; a
drum is drawn in front of the gear on its shaft. The text gives teeth but not the gears' size in
metres, so a drum is drawn to its own scale (larger for a larger diameter). Loads hang from the
drum's side or are hauled up a slope, drawn at its true angle and labelled with its data.
"""
from __future__ import annotations

import math

from .gears import fit_width, gear_face, teeth_label
from .pulleys import need
from .svg import FONT_SIZE, LINE, THIN, Drawing, on_circle
from .values import shown

GEAR_R = 95.0       # px: pitch radius of the largest gear
ROPE_W = 1.8
LABEL = FONT_SIZE
ROW = 17.0


def _scale(*teeth: float) -> float:
    return GEAR_R / max(teeth)


def _drum(drawing: Drawing, c, diameter_m: float, r: float | None = None) -> float:
    """The drum in front of its gear; returns its radius in px (by default 40 px for 0.6 m to 70 px for 1.6 m)."""
    if r is None:
        r = 40 + 30 * min(1.0, max(0.0, (diameter_m - 0.6) / 1.0))
    drawing.circle(c, r, LINE * 1.4, fill="#ececec", cls="drum")
    drawing.circle(c, 4, THIN, fill="white")
    drawing.centre_mark(c, 8)
    return r


def _load(drawing: Drawing, top, width: float, height: float, lines: list[str], up: bool, accel: str,
          side: int = 1) -> None:
    """A block hanging from `top` (the middle of its upper edge), its labels inside, an acceleration arrow
    beside it on the right (side 1) or the left (side -1)."""
    x0, y0 = top[0] - width / 2, top[1]
    drawing.polygon([(x0, y0), (x0 + width, y0), (x0 + width, y0 + height), (x0, y0 + height)], fill="white", width=LINE)
    for i, text in enumerate(lines):
        drawing.text((top[0], y0 + height / 2 + 5 + (i - (len(lines) - 1) / 2) * ROW), text,
                     weight="bold" if i == 0 else "")
    ax = x0 + width + 14 if side > 0 else x0 - 14
    tail, tip = ((ax, y0 + height), (ax, y0)) if up else ((ax, y0), (ax, y0 + height))
    drawing.line(tail, tip, THIN)
    drawing.arrowhead(tip, (0, -1) if up else (0, 1))
    drawing.text((ax + 6 * side, y0 + height / 2 + 5), accel, anchor="start" if side > 0 else "end",
                 cls="label-a")


def _leaders(drawing: Drawing, x: float, y0: float, entries) -> None:
    """Labels in a column at x from y0 down, each with a leader line to its point."""
    for i, (point, text) in enumerate(entries):
        y = y0 + i * (ROW + 6)
        drawing.line(point, (x - 5, y - 5), THIN, cls="leader")
        drawing.text((x, y), text, anchor="start")


def hoist(variant) -> str:
    """Example 1.12: a motor pinion drives the drum gear; the mass hangs from the drum. Inset: the slope of (d)."""
    t1, t2 = need(variant, "t1"), need(variant, "t2")
    k = _scale(t1.si, t2.si)
    r1, r2 = t1.si * k, t2.si * k
    motor, drum = (0.0, 0.0), (r1 + r2, 0.0)
    drawing = Drawing()
    drawing.polygon(_square(motor, 1.35 * r1 + 8), fill="white", width=THIN)
    gear_face(drawing, motor, r1, t1.si, "motor-gear")
    gear_face(drawing, drum, r2, t2.si, "drum-gear")
    r_d = _drum(drawing, drum, need(variant, "dD").si)
    bottom = r2 + 40
    rope = (drum[0] + r_d, 0.0)
    drawing.line(rope, (rope[0], bottom), ROPE_W, cls="rope")
    mass, accel = shown(variant, "M"), shown(variant, "a")
    _load(drawing, (rope[0], bottom), 96, 46, [mass.label() if mass else "M"], True, accel.label() if accel else "a")
    _motor_labels(drawing, motor, r1, teeth_label(variant, "t1"))
    _leaders(drawing, drum[0] + r2 + 30, -r2 + 10, [
        (on_circle(drum, r2, math.radians(-60)), f"drum gear: {teeth_label(variant, 't2')}"),
        (on_circle(drum, r_d, math.radians(-20)), f"drum: {need(variant, 'dD').value_text} diameter")])
    slope = shown(variant, "slope")
    if slope is not None:
        _slope_inset(drawing, drawing.box[2] - 150, bottom + 110, slope, shown(variant, "f"))
    fit_width(drawing)
    return drawing.svg("Geared hoist: motor, gears, drum and load")


def _motor_labels(drawing: Drawing, motor, r: float, teeth: str) -> None:
    """The word Motor over its box and the motor gear's teeth left of it, each moved clear of the drum gear's
    rim (which fills the space to the motor's right)."""
    half = 1.35 * r + 8
    x, y = motor
    drawing.place([((x, y - half - 6), "middle"), ((x - 4, y - half - 6), "end"), ((x - half - 8, y - half + 4), "end"),
                   ((x - half, y - half - 6), "end")], "Motor", weight="bold")
    drawing.place([((x - half - 8, y + 5), "end"), ((x - half - 8, y + 22), "end"), ((x - half - 8, y - 12), "end")],
                  f"gear: {teeth}", cls="label-t1")


def _square(c, half: float):
    return [(c[0] - half, c[1] - half), (c[0] + half, c[1] - half), (c[0] + half, c[1] + half), (c[0] - half, c[1] + half)]


def _slope_inset(drawing: Drawing, x0: float, y0: float, slope, friction) -> None:
    """Part (d): the same mass on a plane at the slope's angle, rope up the slope, friction down it."""
    angle = slope.si
    length = 170.0
    foot, top = (x0, y0), (x0 + length * math.cos(angle), y0 - length * math.sin(angle))
    drawing.line(foot, (top[0], y0), THIN)
    drawing.line(foot, top, LINE)
    drawing.line((top[0], y0), top, THIN)
    u = (math.cos(angle), -math.sin(angle))
    n = (-math.sin(angle), -math.cos(angle))  # the normal away from the slope
    mid = (foot[0] + u[0] * length * 0.45, foot[1] + u[1] * length * 0.45)
    w, h = 36.0, 22.0
    corners = [(mid[0] - u[0] * w / 2, mid[1] - u[1] * w / 2), (mid[0] + u[0] * w / 2, mid[1] + u[1] * w / 2)]
    corners += [(c[0] + n[0] * h, c[1] + n[1] * h) for c in corners[::-1]]
    drawing.polygon(corners, fill="white", width=LINE)
    front = (mid[0] + u[0] * w / 2 + n[0] * h / 2, mid[1] + u[1] * w / 2 + n[1] * h / 2)
    end = (front[0] + u[0] * 70, front[1] + u[1] * 70)
    drawing.line(front, end, ROPE_W, cls="rope")
    drawing.text((end[0] + 4, end[1] - 4), "to drum", anchor="start")
    back = (mid[0] - u[0] * w / 2, mid[1] - u[1] * w / 2)
    tail = (back[0] - u[0] * 34 + n[0] * 4, back[1] - u[1] * 34 + n[1] * 4)
    drawing.line((back[0] + n[0] * 4, back[1] + n[1] * 4), tail, THIN)
    drawing.arrowhead(tail, (-u[0], -u[1]))
    drawing.text((tail[0] + n[0] * 10, tail[1] + n[1] * 10), friction.label() if friction else "f", anchor="end")
    r = 46.0
    arc_end = on_circle(foot, r, -angle)
    drawing.path(f"M {foot[0] + r:.2f},{foot[1]:.2f} A {r} {r} 0 0 0 {arc_end[0]:.2f},{arc_end[1]:.2f}", THIN)
    drawing.text((foot[0] + r, foot[1] + LABEL + 4), slope.label("\u03b8"), anchor="middle")
    drawing.text((x0 - 10, y0 + 5), "(d)", anchor="end", weight="bold")


def lift(variant) -> str:
    """Problem 1.2: motor gear 1 drives 2; 3 on 2's shaft drives 4 on the drum; lift and counterweight hang
    on either side of the drum."""
    teeth = [need(variant, f"t{i}").si for i in range(1, 5)]
    d_drum = need(variant, "dD").si
    r_d = 40 + 20 * min(1.0, max(0.0, (d_drum - 0.6) / 0.6))  # wide enough to hang both loads apart
    # one module for both meshes, the drum's gear a ring wider than the drum (three shafts and two
    # loads: a smaller scale than the hoist's keeps the figure's height)
    k = max(0.8 * _scale(*teeth), r_d / (0.72 * teeth[3]))
    r = [t * k for t in teeth]
    drum = (0.0, 0.0)
    middle = on_circle(drum, r[2] + r[3], math.radians(-125))
    motor = on_circle(middle, r[0] + r[1], math.radians(-165))
    drawing = Drawing()
    # back to front: gear 2 behind the drum shaft's gear 4, the drum in front of gear 4 and smaller,
    # so every gear shows; the pitch circles that mesh touch
    gear_face(drawing, middle, r[1], teeth[1], "gear2")
    gear_face(drawing, drum, r[3], teeth[3], "gear4")
    gear_face(drawing, middle, r[2], teeth[2], "gear3")
    gear_face(drawing, motor, r[0], teeth[0], "gear1")
    _drum(drawing, drum, d_drum, r_d)
    drawing.place([((motor[0], motor[1] - r[0] - 8), "middle"), ((motor[0] - r[0] - 4, motor[1] - r[0]), "end"),
                   ((motor[0] - r[0] - 8, motor[1] + 5), "end")], "Motor", weight="bold")
    bottom = max(r[3], r_d) + 50
    drop = 40.0  # the counterweight hangs lower, so the two blocks never meet
    for side, end in ((-1, bottom), (1, bottom + drop)):
        drawing.line((side * r_d, 0.0), (side * r_d, end), ROPE_W, cls="rope")
    lift_mass, accel = shown(variant, "ml"), shown(variant, "a")
    accel_text = accel.label() if accel else "a"
    _load(drawing, (-r_d, bottom), 84, 70, ["Lift", lift_mass.value_text if lift_mass else ""], True, accel_text, -1)
    _load(drawing, (r_d, bottom + drop), 56, 46, ["M\u2082 = ?"], False, accel_text)
    right = max(c[0] + rr for c, rr in ((motor, r[0]), (middle, r[1]), (drum, r[3]))) + 110
    _leaders(drawing, right, middle[1] - r[1] + 10, [
        (on_circle(motor, r[0], math.radians(-60)), f"gear 1 (motor): {teeth_label(variant, 't1')}"),
        (on_circle(middle, r[1], math.radians(-40)), f"gear 2: {teeth_label(variant, 't2')}"),
        (on_circle(middle, r[2], math.radians(-10)), f"gear 3: {teeth_label(variant, 't3')}"),
        (on_circle(drum, r[3], math.radians(-20)), f"gear 4 (drum): {teeth_label(variant, 't4')}"),
        (on_circle(drum, r_d, math.radians(20)), f"drum: {need(variant, 'dD').value_text} diameter")])
    fit_width(drawing)
    return drawing.svg("Lift driven through two gear stages, with a counterweight")


def haulage(variant) -> str:
    """Problem 1.6: motor pinion, drum gear and drum; the rope hauls M up a slope of 1 in s."""
    t1, t2 = need(variant, "t1"), need(variant, "t2")
    k = _scale(t1.si, t2.si)
    r1, r2 = t1.si * k, t2.si * k
    drum = (0.0, 0.0)
    motor = on_circle(drum, r1 + r2, math.radians(-150))
    drawing = Drawing()
    drawing.polygon(_square(motor, 1.35 * r1 + 8), fill="white", width=THIN)
    gear_face(drawing, motor, r1, t1.si, "motor-gear")
    gear_face(drawing, drum, r2, t2.si, "drum-gear")
    r_d = _drum(drawing, drum, need(variant, "dD").si)
    s = need(variant, "s")
    angle = math.asin(1 / s.si)                           # 1 in s, measured along the slope
    u = (math.cos(angle), math.sin(angle))                # down the slope, away from the drum
    n = (-math.sin(angle), math.cos(angle))               # towards the slope, below the rope
    start = (drum[0] + r_d * n[0], drum[1] + r_d * n[1])
    run = r2 + 180
    block = (start[0] + u[0] * run, start[1] + u[1] * run)
    w, h = 70.0, 40.0
    near = (block[0] - u[0] * w / 2, block[1] - u[1] * w / 2)
    drawing.line(start, near, ROPE_W, cls="rope")
    base = [(near[0] + n[0] * h / 2, near[1] + n[1] * h / 2), (near[0] + u[0] * w + n[0] * h / 2, near[1] + u[1] * w + n[1] * h / 2)]
    top = [(p[0] - n[0] * h, p[1] - n[1] * h) for p in base[::-1]]
    drawing.polygon(base + top, fill="white", width=LINE)
    drawing.text((block[0], block[1] + 5), "M = ?", weight="bold")
    ground0 = (base[0][0] - u[0] * 120, base[0][1] - u[1] * 120)
    ground1 = (base[1][0] + u[0] * 60, base[1][1] + u[1] * 60)
    drawing.line(ground0, ground1, LINE, cls="slope")
    drawing.line(ground1, (ground0[0], ground1[1]), THIN)
    drawing.line((ground0[0], ground1[1]), ground0, THIN)
    drawing.text(((ground0[0] + ground1[0]) / 2, ground1[1] + FONT_SIZE + 4), f"slope 1 in {s.value_text}")
    accel, friction = shown(variant, "a"), shown(variant, "f")
    above = (top[0][0] - n[0] * 14, top[0][1] - n[1] * 14)   # over the block's far upper corner
    tip = (above[0] - u[0] * 50, above[1] - u[1] * 50)
    drawing.line(above, tip, THIN)
    drawing.arrowhead(tip, (-u[0], -u[1]))
    drawing.text((above[0] + 4, above[1] - 4), accel.label() if accel else "a", anchor="start")
    tail = (base[1][0] + u[0] * 40 - n[0] * h * 0.4, base[1][1] + u[1] * 40 - n[1] * h * 0.4)
    drawing.line((base[1][0] - n[0] * h * 0.4, base[1][1] - n[1] * h * 0.4), tail, THIN)
    drawing.arrowhead(tail, u)
    drawing.text((tail[0] + 6, tail[1] - 4), friction.label() if friction else "f", anchor="start")
    _motor_labels(drawing, motor, r1, teeth_label(variant, "t1"))
    _leaders(drawing, drum[0] + r2 + 40, -r2 - 10, [
        (on_circle(drum, r2, math.radians(-50)), f"drum gear: {teeth_label(variant, 't2')}"),
        (on_circle(drum, r_d, math.radians(-15)), f"drum: {need(variant, 'dD').value_text} diameter")])
    fit_width(drawing)
    return drawing.svg("Geared haulage: motor, gears, drum and a mass hauled up a slope")
