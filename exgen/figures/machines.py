"""Geared machines seen from the side: a vehicle climbing a hill (Example 1.14) and a robot arm driven
through two gear pairs (Example 1.13). Values are printed as on the sheet; an unknown is "?" and an
unknown angle is drawn at a nominal size, never at its answer.
"""
from __future__ import annotations

import math

from .gears import gear_face
from .hoists import _square
from .svg import LINE, NOTE_SIZE, THIN, Drawing, on_circle, pts
from .values import shown

HILL = math.radians(9)        # drawn slope of a hill whose angle is asked
CAR_M = 4.2                   # a car's length in metres, for the scale of its wheels
CAR_PX = 240.0


def _along(origin, u, s: float):
    """The point s along direction u from origin."""
    return origin[0] + u[0] * s, origin[1] + u[1] * s


def _arrow(d: Drawing, tail, tip, width: float = THIN) -> None:
    d.line(tail, tip, width)
    d.arrowhead(tip, (tip[0] - tail[0], tip[1] - tail[1]))


def vehicle_on_hill(variant) -> str:
    """A car driving up a hill of unknown angle: wheels to the car's scale, speed, acceleration and the
    resistance along the slope, the mass at the centre of mass."""
    k = CAR_PX / CAR_M
    radius = shown(variant, "r")
    r = (radius.si if radius else 0.3) * k
    u = (math.cos(HILL), -math.sin(HILL))            # up the slope, to the right
    n = (-math.sin(HILL), -math.cos(HILL))           # away from the road surface
    foot = (0.0, 0.0)

    def road(s: float, h: float = 0.0):
        """s along the road from the hill's foot, h above its surface."""
        return foot[0] + u[0] * s + n[0] * h, foot[1] + u[1] * s + n[1] * h

    d = Drawing()
    top = road(560)
    d.line(foot, top, LINE, cls="road")
    d.line(foot, (top[0], foot[1]), THIN, cls="level")
    rear = 150.0
    body = [(rear, r * 0.9), (rear + CAR_PX, r * 0.9), (rear + CAR_PX, r + 30), (rear + 0.8 * CAR_PX, r + 38),
            (rear + 0.66 * CAR_PX, r + 68), (rear + 0.3 * CAR_PX, r + 68), (rear + 0.16 * CAR_PX, r + 40),
            (rear, r + 36)]
    d.polygon([road(s, h) for s, h in body], fill="white", width=LINE)
    for s in (rear + 0.18 * CAR_PX, rear + 0.82 * CAR_PX):  # in front of the body: wheels to the car's scale
        c = road(s, r)
        d.circle(c, r, LINE, fill="white", cls="wheel")
        d.circle(c, max(2.5, 0.25 * r), THIN)
    front_wheel = road(rear + 0.82 * CAR_PX, r)
    d.line(front_wheel, road(rear + 0.82 * CAR_PX), THIN, cls="radius")
    centre = road(rear + 0.5 * CAR_PX, r + 30)
    d.circle(centre, 4, THIN, fill="white", cls="centre-of-mass")
    mass = shown(variant, "m")
    d.place([((centre[0], centre[1] - 8), "middle"), ((centre[0] + 10, centre[1] + 5), "start")],
            mass.label() if mass else "m", cls="label-m")
    if radius:
        wheel = front_wheel
        d.place([((wheel[0] + 10, wheel[1] + r + 22), "start"), ((wheel[0] + r + 8, wheel[1] + 18), "start"),
                 ((wheel[0] + r + 8, wheel[1] + 34), "start")], radius.label(), cls="label-r")
    speed, accel, resist = shown(variant, "v"), shown(variant, "a"), shown(variant, "R")
    for h, value, name in ((r + 20, speed, "v"), (r + 56, accel, "a")):
        ahead = road(rear + CAR_PX + 24, h)
        _arrow(d, ahead, _along(ahead, u, 70))
        d.place([((ahead[0] + 36, ahead[1] - 14), "middle"), ((ahead[0] + 80, ahead[1] - 6), "start")],
                value.label() if value else name, cls=f"label-{name}")
    behind = road(rear - 14, r + 20)
    _arrow(d, behind, _along(behind, u, -70))
    d.place([((behind[0] - 36, behind[1] - 14), "middle"), ((behind[0] - 40, behind[1] + 22), "middle")],
            resist.label() if resist else "R", cls="label-R")
    arc = 90.0
    end = on_circle(foot, arc, -HILL)
    d.path(f"M {pts((foot[0] + arc, foot[1]))} A {arc} {arc} 0 0 0 {pts(end)}", THIN, cls="hill-angle")
    d.text((foot[0] + arc + 8, foot[1] - 3), "\u03b8 = ?", anchor="start", cls="label-theta")
    d.text((foot[0], foot[1] + 22), "hill not to scale: its angle is asked", anchor="start", size=NOTE_SIZE,
           style="italic")
    return d.svg("Vehicle climbing a hill of unknown angle")


def robot_arm(variant) -> str:
    """The motor's gear 1 drives gear 2; gear 3 on gear 2's shaft drives gear 4 on the joint; the arm at
    its angle above the horizontal, its mass at its centre of mass, its angular acceleration upwards."""
    k12, k34 = shown(variant, "k12").si, shown(variant, "k34").si
    # to the ratios: gear 2 a clear ring round gear 3 on their shaft, yet short of the joint's shaft
    r4 = 46.0
    r3 = r4 / k34
    r2 = r3 + 22.0
    r1 = r2 / k12
    joint = (0.0, 0.0)
    middle = on_circle(joint, r3 + r4, math.radians(200))
    motor = on_circle(middle, r1 + r2, math.radians(235))
    d = Drawing()
    d.polygon(_square(motor, 1.35 * r1 + 8), fill="white", width=THIN)
    gear_face(d, middle, r2, None, "gear2")   # behind gear 4, in the plane of gear 1
    gear_face(d, motor, r1, None, "gear1")
    gear_face(d, joint, r4, None, "gear4")
    gear_face(d, middle, r3, None, "gear3")   # in front, meshing with gear 4
    theta, length, mass = shown(variant, "theta"), shown(variant, "L"), shown(variant, "m")
    angle = theta.si if theta else math.radians(30)
    l_px = 130 + 100 * min(1.0, max(0.0, ((length.si if length else 0.3) - 0.2) / 0.3))
    u = (math.cos(angle), -math.sin(angle))
    n = (-u[1], u[0])                                  # the arm's lower side
    tip = (u[0] * (l_px + 60), u[1] * (l_px + 60))
    half = 7.0
    outline = [(joint[0] + n[0] * half - u[0] * 14, joint[1] + n[1] * half - u[1] * 14),
               (tip[0] + n[0] * half, tip[1] + n[1] * half), (tip[0] - n[0] * half, tip[1] - n[1] * half),
               (joint[0] - n[0] * half - u[0] * 14, joint[1] - n[1] * half - u[1] * 14)]
    d.polygon(outline, fill="white", width=LINE)
    d.circle(joint, 5.0, LINE, fill="white")
    com = (u[0] * l_px, u[1] * l_px)
    d.circle(com, 5.0, THIN, fill="black", cls="centre-of-mass")
    # the arm's angle above the horizontal, at the joint
    d.line(joint, (r4 + 0.55 * l_px, 0.0), THIN, dash="10 3 2 3", cls="horizontal")
    arc = r4 + 0.3 * l_px
    end = on_circle(joint, arc, -angle)
    d.path(f"M {pts((arc, 0.0))} A {arc:.2f} {arc:.2f} 0 0 0 {pts(end)}", THIN, cls="arm-angle")
    # the arm's angular acceleration, upwards: an arrow round the joint beyond the arm's tip
    reach = l_px + 76
    d.rotation_arrow(joint, reach, False, -math.degrees(angle) - 22, -math.degrees(angle) + 2)
    labels = [
        ([(on_circle(joint, arc + 8 + k, -angle / 2), "start") for k in (0, 12, 24)]
         + [((arc + 6 + k, -6), "start") for k in (0, 14, 28)] + [((arc - 10, 18), "middle"), ((arc + 10, 18), "start")],
         theta.label("\u03b8") if theta else "\u03b8"),
        ([(on_circle(joint, reach + 14 + k, -angle - math.radians(14)), anchor)
          for k in (0, 12, 24, 36) for anchor in ("middle", "end", "start")], (lambda a: a.label("\u03b1") if a else "\u03b1")(shown(variant, "alpha_A"))),
        ([((com[0] + n[0] * k, com[1] + n[1] * k + 5), "start") for k in (14, 26, 40)]
         + [((com[0] - n[0] * k, com[1] - n[1] * k + 5), "end") for k in (14, 26, 40)]
         + [((com[0] + u[0] * t - n[0] * k, com[1] + u[1] * t - n[1] * k + 5), "end")
            for t in (30, 60, -30) for k in (16, 30)],
         f"{mass.label() if mass else 'm'} at {length.label() if length else 'L'} from the joint"),
    ]
    for candidates, text in (labels[2], labels[0], labels[1]):  # the longest first, while there is most room
        d.place(candidates, text)
    for c, r_in, r_out, name in ((motor, 0.0, r1, "1"), (middle, r3, r2, "2"), (middle, 0.0, r3, "3"),
                                 (joint, 0.0, r4, "4")):
        radii = [(r_in + r_out) / 2] if r_in else [0.55 * r_out, r_out + 12, r_out + 22]
        d.place([((c[0] + radius * math.cos(math.radians(a)), c[1] + radius * math.sin(math.radians(a)) + 5), "middle")
                 for radius in radii for a in range(135, 495, 30)], name, weight="bold", cls=f"gear-number gear-{name}")
    d.place([((motor[0], motor[1] - 1.35 * r1 - 14), "middle"), ((motor[0] - 1.35 * r1 - 12, motor[1] + 5), "end")],
            "Motor", weight="bold")
    notes = ["gear 1 on the motor, gears 2 and 3 on one shaft, gear 4 on the joint",
             f"speed ratios 1 : {shown(variant, 'k12').value_text} (gears 1 to 2) and "
             f"1 : {shown(variant, 'k34').value_text} (gears 3 to 4)"]
    y = d.box[3] + 22
    for note in notes:
        d.text((d.box[0], y), note, anchor="start", size=NOTE_SIZE, style="italic")
        y += 18
    return d.svg("Robot arm driven by a motor through two gear pairs")
