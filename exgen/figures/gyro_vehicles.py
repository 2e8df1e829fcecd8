"""Road and rail vehicles on a curve (course text §5.1, Example 5.2, Problems 5.3, 5.5, 5.6), and the
key's vector sketch of spin, precession and gyroscopic couple.

A two-wheeler is drawn from behind leaning at its solved angle (labelled "?", never with the value),
a car from above with its wheelbase, track and centre of gravity, a rail car from behind on its rails.
"""
from __future__ import annotations

import math

from .flywheels import need
from .gyroscopes import SHADE, car_body, curve, spin_disc
from .svg import LINE, THIN, Drawing
from .symbols import arrow, dimension, ground
from .values import choice, shown


def _angle_text(variant, name: str, symbol: str) -> str:
    return shown(variant, name).label(symbol)


def motorcycle(variant) -> str:
    """A two-wheeler from behind, leaning at θ (normal to a banked track when the template banks it), its
    centre of gravity h up; and from above on its curve."""
    theta = shown(variant, "theta")
    banked = variant.template.id.endswith("banking")
    lean = theta.si
    h = need(variant, "h")
    d = Drawing()
    contact = (0.0, 0.0)
    axis = (math.sin(lean), -math.cos(lean))          # up the motorcycle, leaning into the turn (to the right)
    height = 150.0
    top = (contact[0] + axis[0] * height * 1.25, contact[1] + axis[1] * height * 1.25)
    if banked:
        surface = (math.cos(lean), math.sin(lean))
        ground(d, contact, surface, 260, side=-1)
        d.line(contact, (contact[0] + 160, contact[1]), THIN, dash="6 4", cls="horizontal")
        d.path(f"M {contact[0] + 110} {contact[1]} A 110 110 0 0 1 {contact[0] + 110 * surface[0]:.2f} "
               f"{contact[1] + 110 * surface[1]:.2f}", THIN, cls="angle")
        half = (math.cos(lean / 2), math.sin(lean / 2))
        d.place([((contact[0] + 124 * half[0], contact[1] + 124 * half[1] + 6), "start"),
                 ((contact[0] + 150 * half[0], contact[1] + 150 * half[1] + 10), "start"),
                 ((contact[0] + 118, contact[1] - 8), "start")], _angle_text(variant, "theta", "θ"))
    else:
        ground(d, contact, (1, 0), 260, side=-1)
        arc = 0.8 * height
        d.line(contact, (0, -height * 1.2), THIN, dash="6 4", cls="vertical")
        d.path(f"M 0 {-arc} A {arc} {arc} 0 0 1 {arc * axis[0]:.2f} {arc * axis[1]:.2f}", THIN, cls="angle")
        d.place([((-10, -arc - 2), "end"), ((-10, -arc + 16), "end")], _angle_text(variant, "theta", "θ"))
    # the wheel seen from behind (a tyre section) and the rider's bulk, along the leaning axis
    n = (-axis[1], axis[0])
    wheel_top = (axis[0] * 70, axis[1] * 70)
    d.polygon([(contact[0] + n[0] * 7, contact[1] + n[1] * 7), (wheel_top[0] + n[0] * 7, wheel_top[1] + n[1] * 7),
               (wheel_top[0] - n[0] * 7, wheel_top[1] - n[1] * 7), (contact[0] - n[0] * 7, contact[1] - n[1] * 7)],
              fill="black", width=0)
    d.line(wheel_top, top, LINE * 3, cls="rider")
    cg = (axis[0] * height * 0.72, axis[1] * height * 0.72)
    d.circle(cg, 5, THIN, fill="white", cls="cg")
    # h along the machine, on the side away from the track's rise, its label past the dimension's top end
    side = 1 if banked else -1
    off = (-n[0] * 40 * side, -n[1] * 40 * side)
    pa, pb = (contact[0] + off[0], contact[1] + off[1]), (cg[0] + off[0], cg[1] + off[1])
    for p, q in ((contact, pa), (cg, pb)):
        d.line(p, (q[0] - n[0] * 4 * side, q[1] - n[1] * 4 * side), THIN, cls="extension")
    d.dimension(pa, pb)
    tip = (pb[0] + axis[0] * 12 - n[0] * 6 * side, pb[1] + axis[1] * 12 - n[1] * 6 * side)
    d.place([((tip[0], tip[1]), "end" if side > 0 else "start"), ((tip[0], tip[1] - 16), "end" if side > 0 else "start"),
             ((tip[0], tip[1] + 16), "end" if side > 0 else "start")], h.label("h"))
    g_side = side  # away from the dimension
    d.place([((cg[0] + g_side * n[0] * 16, cg[1] + g_side * n[1] * 16 + 5), "start" if g_side * n[0] > 0 else "end"),
             ((cg[0] + g_side * n[0] * 30, cg[1] + g_side * n[1] * 30 + 5), "start" if g_side * n[0] > 0 else "end"),
             ((cg[0] - 14, cg[1] - 8), "end"), ((cg[0] + 14, cg[1] - 10), "start")], "G", style="italic")
    d.place([((top[0], top[1] - 14), "middle"), ((top[0] - 60, top[1]), "end")], "seen from behind", size=13,
            style="italic")
    ox = -400.0
    d.polygon([(ox - 6, -40), (ox + 6, -40), (ox + 6, 40), (ox - 6, 40)], fill="white", width=LINE)
    curve(d, (ox, 0), "right", need(variant, "R").label("R"), need(variant, "v").label("v"), clear=14)
    return d.svg("Motorcycle on a " + ("banked " if banked else "") + "curve to the right: from above and from behind")


def car(variant) -> str:
    """Problem 5.3: the car from above with wheelbase, track and centre of gravity, on its curve; the
    engine's rotor seen from the front with its sense."""
    b, x, a = need(variant, "b"), need(variant, "x"), need(variant, "a")
    turn = choice(variant, "turn", "right")
    scale = 140 / b.si
    width, length = x.si * scale, b.si * scale / 0.64   # the wheels sit at 18 % and 82 % of the body's length
    d = Drawing()
    wheels = car_body(d, (0, 0), width, length)
    front_y, rear_y = wheels[0][1], wheels[2][1]
    g = (0.0, front_y + a.si * scale)
    d.circle(g, 4, THIN, fill="white", cls="cg")
    d.polygon([(-8, front_y - 4), (8, front_y - 4), (8, front_y + 26), (-8, front_y + 26)], fill=SHADE, width=LINE)
    # dimensions on the outside of the turn, away from its centre
    side = -1 if turn == "right" else 1
    front, rear = (wheels[0], wheels[2]) if side < 0 else (wheels[1], wheels[3])
    dimension(d, front, rear, b.label("b"), side=side, offset=124)
    dimension(d, front, (front[0], g[1]), a.label("a"), side=side, offset=30)
    dimension(d, (wheels[2][0], rear_y + 12), (wheels[3][0], rear_y + 12), x.label("x"), side=-1, offset=40)
    d.place([((0, -length / 2 - 12), "middle")], "front", size=13, style="italic")
    curve(d, (0, 0), turn, need(variant, "R").label("R"), need(variant, "v").label("v"), clear=width / 2 + 12)
    ox = 330.0 if turn == "left" else -330.0
    spin_disc(d, (ox, 120), choice(variant, "sense", "clockwise") == "clockwise", "engine seen from the front")
    d.place([((g[0] + gx, g[1] + gy), anchor) for gx, gy, anchor in
             ((-10, 5, "end"), (10, 5, "start"), (0, 20, "middle"), (0, -9, "middle"), (-10, 20, "end"), (10, 20, "start"))],
            "G", style="italic")
    return d.svg(f"Car turning {turn}, from above; its engine seen from the front")


def rail_car(variant) -> str:
    """Problem 5.5: the car from behind on its rails, the gauge, wheel radius and centre of gravity; and
    from above on its curve."""
    x, r, h = need(variant, "x"), need(variant, "r"), need(variant, "h")
    scale = 200 / x.si
    half = x.si * scale / 2
    wheel = r.si * scale
    d = Drawing()
    ground(d, (0, 0), (1, 0), 2 * half + 120, side=-1)
    for s in (-1, 1):
        d.polygon([(s * half - 9, 0), (s * half + 9, 0), (s * half + 9, -8), (s * half - 9, -8)], fill="black", width=0)
        d.polygon([(s * half - 8, -8), (s * half + 8, -8), (s * half + 8, -8 - 2 * wheel), (s * half - 8, -8 - 2 * wheel)],
                  fill=SHADE, width=LINE)
    axle = -8 - wheel
    d.line((-half, axle), (half, axle), LINE * 1.6, cls="axle")
    cg_y = -8 - h.si * scale
    body_bottom = -8 - 2 * wheel - 10
    d.polygon([(-half - 30, body_bottom), (half + 30, body_bottom), (half + 30, cg_y - 60), (-half - 30, cg_y - 60)],
              fill="white", width=LINE)
    d.circle((0, cg_y), 4, THIN, fill="white", cls="cg")
    d.place([((-10, cg_y + 5), "end"), ((0, cg_y + 22), "middle")], "G", style="italic")
    dimension(d, (-half, 0), (half, 0), x.label("x"), side=-1, offset=24)
    dimension(d, (0, -8), (0, cg_y), h.label("h"), side=-1, offset=half + 70)
    dimension(d, (-half - 8, -8), (-half - 8, axle), r.label("r"), side=1, offset=22)   # rail head to axle
    d.place([((0, cg_y - 74), "middle")], "seen from behind", size=13, style="italic")
    ox, oy = -half - 330, 40
    d.polygon([(ox - 14, oy - 40), (ox + 14, oy - 40), (ox + 14, oy + 40), (ox - 14, oy + 40)], fill="white", width=LINE)
    curve(d, (ox, oy), "right", need(variant, "R").label("R"), clear=20)
    return d.svg("Rail car on its rails, from behind; and from above on its curve")


#: Screen directions of the vehicle's axes in an oblique sketch: forward up-right, left to the left, up up.
AXES = {"forward": (0.62, -0.5), "left": (-1.0, 0.0), "up": (0.0, -1.0)}
WORDS = {
    "forward": ("forward", 1), "backward": ("forward", -1), "to the left": ("left", 1), "to the right": ("left", -1),
    "up": ("up", 1), "down": ("up", -1), "towards the bow": ("forward", 1), "towards the stern": ("forward", -1),
    "to port": ("left", 1), "to starboard": ("left", -1), "towards the nose": ("forward", 1),
    "towards the tail": ("forward", -1), "to the left wing": ("left", 1), "to the right wing": ("left", -1),
}


def gyro_vectors(variant) -> str:
    """The key's vector sketch: spin ω, precession Ω and the reactive couple C = ω × Ω in the vehicle's axes,
    each as a double-headed arrow (the sign of a rotation vector), from the steps that name them."""
    steps = {s.name: s.value for s in variant.steps}
    d = Drawing()
    length = 110.0
    names = {"forward": "forward", "left": "left", "up": "up"}
    if any(word in str(steps.get("spin_vector", "")) for word in ("bow", "stern")):
        names = {"forward": "bow", "left": "port", "up": "up"}
    for axis, (ux, uy) in AXES.items():
        d.line((-ux * length * 0.5, -uy * length * 0.5), (ux * length * 1.25, uy * length * 1.25), THIN, dash="3 4",
               cls="axis")
        d.place([((ux * length * 1.25 + 6 * ux, uy * length * 1.25 + 14 if uy >= 0 else uy * length * 1.25 - 6),
                  "start" if ux > 0.1 else "end" if ux < -0.1 else "middle")], names[axis], size=13, style="italic")
    for step, symbol, scale in (("spin_vector", "ω", 0.95), ("precession_vector", "Ω", 0.75),
                                ("couple_vector", "C", 1.05)):
        axis, sign = WORDS[str(steps[step])]
        ux, uy = AXES[axis]
        tip = (ux * length * scale * sign, uy * length * scale * sign)
        arrow(d, (0, 0), tip, symbol, width=LINE * 1.8, cls="vector", double=True)
    d.place([((0, length * 0.9), "middle"), ((0, length * 1.05), "middle")],
            "C = ω × Ω, the gyroscopic couple on the vehicle", size=13, style="italic")
    return d.svg("Spin, precession and gyroscopic couple by the right-hand rule")
