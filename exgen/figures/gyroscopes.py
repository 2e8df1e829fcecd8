"""Gyroscope sketches drawn to each variant (course text chapter 5): a vehicle, ship or aircraft seen
from above on its curve, turning the way the sheet says, with the rotor's spin shown as the sheet
states it (a disc seen from the stated side with its sense of rotation), and the side or rear view
that carries the problem's dimensions. The curve's radius is labelled, not drawn to scale. No vector
that is part of the answer (precession, couple) is drawn on a sheet; the key's vector sketch
(`gyro_vectors`) shows them.
"""
from __future__ import annotations

import math

from .flywheels import need
from .svg import LINE, THIN, Drawing, pts
from .symbols import arrow, dimension, ground, spring
from .values import choice

R_PX = 170.0  # radius the path is drawn with (the real one is labelled)
SHADE = "#d8d8d8"


def curve(d: Drawing, at, turn: str, r_text: str, v_text: str = "", clear: float = 34.0) -> None:
    """The path of a vehicle heading up the page at `at`, curving to `turn` about a centre R_PX away,
    the centre marked and the radius labelled; the speed beside the path ahead."""
    s = 1 if turn == "right" else -1
    centre = (at[0] + s * R_PX, at[1])
    sweep = math.radians(60)
    behind = (centre[0] - s * R_PX * math.cos(math.radians(25)), at[1] + R_PX * math.sin(math.radians(25)))
    ahead = (centre[0] - s * R_PX * math.cos(sweep), at[1] - R_PX * math.sin(sweep))
    d.path(f"M {pts(behind)} A {R_PX} {R_PX} 0 0 {1 if s > 0 else 0} {pts(ahead)}", THIN, dash="7 5", cls="path")
    d.extend(min(behind[0], ahead[0]), ahead[1], max(behind[0], ahead[0]), behind[1])
    d.arrowhead(ahead, (s * math.sin(sweep), -math.cos(sweep)))  # the way the vehicle goes
    d.circle(centre, 2.5, THIN, fill="black", cls="centre")
    d.line(centre, (at[0] + s * clear, at[1]), THIN, cls="radius")
    mid = (centre[0] + at[0]) / 2 + s * clear / 2
    d.place([((mid, at[1] - 6), "middle"), ((mid, at[1] + 17), "middle"), ((mid + s * 20, at[1] - 6), "middle"),
             ((mid + s * 20, at[1] + 17), "middle")], r_text)
    d.place([((centre[0] + s * 10, at[1] + 18), "start" if s > 0 else "end")], "centre of turn", size=13, style="italic")
    if v_text:
        mid = (centre[0] - s * R_PX * math.cos(math.radians(45)), at[1] - R_PX * math.sin(math.radians(45)))
        d.place([((mid[0] - s * 14, mid[1]), "end" if s > 0 else "start"),
                 ((mid[0] + s * 14, mid[1] + 14), "start" if s > 0 else "end")], v_text)


def spin_disc(d: Drawing, c, clockwise: bool, caption: str, r: float = 24.0) -> None:
    """A rotor as seen from one end: a disc with its sense of rotation and a caption under it."""
    d.circle(c, r, LINE, fill=SHADE, cls="rotor")
    d.circle(c, 3, THIN, fill="white")
    d.rotation_arrow(c, r + 9, clockwise, -150, -30)
    d.place([((c[0], c[1] + r + 20), "middle")], caption, size=13, style="italic")


def car_body(d: Drawing, c, width: float, length: float, wheel: float = 14.0) -> list[tuple[float, float]]:
    """A road vehicle from above, heading up the page; returns its wheel centres (FL, FR, RL, RR)."""
    x0, y0 = c[0] - width / 2, c[1] - length / 2
    d.polygon([(x0, y0 + 8), (x0 + 8, y0), (x0 + width - 8, y0), (x0 + width, y0 + 8), (x0 + width, y0 + length),
               (x0, y0 + length)], fill="white", width=LINE)
    d.line((x0 + 6, y0 + length * 0.28), (x0 + width - 6, y0 + length * 0.28), THIN, cls="windscreen")
    wheels = [(x0, y0 + length * 0.18), (x0 + width, y0 + length * 0.18), (x0, y0 + length * 0.82),
              (x0 + width, y0 + length * 0.82)]
    for x, y in wheels:
        d.polygon([(x - 4, y - wheel / 2), (x + 4, y - wheel / 2), (x + 4, y + wheel / 2), (x - 4, y + wheel / 2)],
                  fill="black", width=0)
    return wheels


def vehicle_rotor(variant) -> str:
    """Example 5.1: the vehicle from above on its curve, and from the rear the flywheel's bearings on springs."""
    turn = choice(variant, "turn", "right")
    d = Drawing()
    car_body(d, (0, 0), 44, 80)
    d.line((-18, 4), (18, 4), LINE * 2, cls="flywheel-axle")
    d.polygon([(-4, -8), (4, -8), (4, 16), (-4, 16)], fill=SHADE, width=LINE)
    curve(d, (0, 0), turn, need(variant, "R").label("R"), need(variant, "v").label("v"))
    d.place([((0, -50), "middle"), ((-26, -38), "end"), ((26, -38), "start")], "front", size=13, style="italic")
    # the rear view, to the right of the plan (or left of it when the turn is to the right)
    ox = 215.0 if turn == "left" else -175.0  # beside the plan, away from the centre of turn
    l = need(variant, "l")
    half = 75.0
    base = 100.0
    for s in (-1, 1):
        x = ox + s * half
        d.polygon([(x - 9, 0), (x + 9, 0), (x + 9, 14), (x - 9, 14)], fill="white", width=LINE)
        spring(d, (x, 14), (x, base))
    ground(d, (ox, base), (1, 0), 2 * half + 60, side=-1)
    d.line((ox - half, 7), (ox + half, 7), LINE * 1.6, cls="axle")
    d.polygon([(ox - 7, -45), (ox + 7, -45), (ox + 7, 59), (ox - 7, 59)], fill=SHADE, width=LINE)
    d.text((ox - half - 16, 5), "left", anchor="end", size=13, style="italic")
    d.text((ox + half + 16, 5), "right", anchor="start", size=13, style="italic")
    k = need(variant, "K").label("K")
    d.place([((ox - half - 14, 60), "end")], k)
    d.place([((ox + half + 14, 60), "start")], k)
    dimension(d, (ox - half, base), (ox + half, base), l.label("l"), side=-1, offset=26)
    d.place([((ox, -58), "middle")], "seen from the rear", size=13, style="italic")
    d.place([((ox + 14, -30), "start"), ((ox - 14, -30), "end")],
            f"{need(variant, 'I').label('I')}, {need(variant, 'N').value_text}")
    return d.svg(f"Vehicle turning {turn}; flywheel bearings on springs, seen from the rear")


def ship_engine(variant) -> str:
    """Problem 5.1: the rotor between its bearings seen from the side (bow to the right), the ship's
    turn seen from above, and the rotor seen from the stern with its sense of rotation."""
    l, a = need(variant, "l"), need(variant, "a")
    turn = choice(variant, "turn", "left")
    d = Drawing()
    span = 300.0
    xa, xb = span / 2, -span / 2      # A forward (right), B aft (left)
    xg = xa - a.si / l.si * span
    d.line((xb - 30, 0), (xa + 30, 0), LINE * 1.6, cls="shaft")
    d.polygon([(xg - 40, -34), (xg + 40, -34), (xg + 40, 34), (xg - 40, 34)], fill=SHADE, width=LINE)
    for x, name in ((xa, "A"), (xb, "B")):
        d.polygon([(x - 10, 6), (x + 10, 6), (x + 14, 26), (x - 14, 26)], fill="white", width=LINE)
        ground(d, (x, 26), (1, 0), 40, side=-1)
        d.text((x + 20, 22), name, anchor="start", style="italic")
    d.circle((xg, 0), 3, THIN, fill="black", cls="cg")
    dimension(d, (xb, 30), (xa, 30), l.label("l"), side=-1, offset=40)
    dimension(d, (xg, 0), (xa, 0), a.label("a"), side=1, offset=52)
    arrow(d, (xa + 50, -60), (xa + 110, -60), "bow")
    spin_disc(d, (xb - 20, -110), choice(variant, "sense", "clockwise") == "clockwise", "rotor seen from the stern")
    d.place([((xg, -42), "middle"), ((xg, -84), "middle"), ((xg, 88), "middle")],
            f"{need(variant, 'm').label('m')}, {need(variant, 'k').label('k')}")
    ox, oy = xa + 130 if turn == "left" else xb - 170, 170
    _ship_plan(d, (ox, oy), 0.6)
    curve(d, (ox, oy), turn, need(variant, "R").label("R"), need(variant, "v").label("v"))
    return d.svg(f"Ship's engine rotor in bearings A and B; the ship turning {turn}")


def _ship_plan(d: Drawing, c, scale: float = 1.0) -> None:
    """A ship's hull from above, bow up the page."""
    w, h = 34 * scale, 110 * scale
    x, y = c
    d.path(f"M {x - w / 2:.2f} {y + h / 2:.2f} L {x - w / 2:.2f} {y - h / 6:.2f} Q {x - w / 2:.2f} {y - h / 2.6:.2f} "
           f"{x:.2f} {y - h / 2:.2f} Q {x + w / 2:.2f} {y - h / 2.6:.2f} {x + w / 2:.2f} {y - h / 6:.2f} "
           f"L {x + w / 2:.2f} {y + h / 2:.2f} Z", LINE, fill="white", cls="hull")
    d.extend(x - w / 2, y - h / 2, x + w / 2, y + h / 2)


def ship_turbine(variant) -> str:
    """Problem 5.4: the ship from above on its turn, its pitch from the side, and the rotor seen from
    the stated end with its sense of rotation."""
    turn = choice(variant, "turn", "right")
    view = choice(variant, "view", "stern")
    d = Drawing()
    _ship_plan(d, (0, 0))
    d.polygon([(-5, 0), (5, 0), (5, 34), (-5, 34)], fill=SHADE, width=LINE)
    curve(d, (0, 0), turn, need(variant, "R").label("R"), need(variant, "v").label("v"))
    d.place([((0, -66), "middle"), ((-24, -50), "end"), ((24, -50), "start")], "bow", size=13, style="italic")
    ox = 170.0 if turn == "left" else -236.0  # beside the plan, away from the centre of turn
    # side view: the hull level (full) and pitched bow-up by the amplitude (dashed, exaggerated)
    phi = need(variant, "phi")
    hull = [(-100, -18), (92, -18), (112, -32), (100, 12), (-88, 12), (-100, 0)]
    cy, tilt = 60.0, math.radians(9)

    def turned(p, angle):
        return (ox + p[0] * math.cos(angle) + p[1] * math.sin(angle), cy - p[0] * math.sin(angle) + p[1] * math.cos(angle))

    d.line((ox - 130, cy), (ox + 140, cy), THIN, dash="2 3", cls="waterline")
    d.polygon([turned(p, 0) for p in hull], fill="white", width=LINE)
    d.path("M " + " L ".join(pts(turned(p, tilt)) for p in hull + hull[:1]), THIN, dash="5 4", cls="pitched")
    d.path(f"M {ox + 150} {cy} A 150 150 0 0 0 {ox + 150 * math.cos(tilt):.2f} {cy - 150 * math.sin(tilt):.2f}",
           THIN, cls="angle")
    d.place([((ox + 156, cy - 6), "start")], f"±{phi.value_text}")
    d.place([((ox, cy + 38), "middle")], f"pitching, period {need(variant, 'T').value_text}", size=13, style="italic")
    d.place([((ox + 100, cy + 30), "middle"), ((ox + 120, cy - 50), "middle")], "bow", size=13, style="italic")
    spin_disc(d, (ox, -70), choice(variant, "sense", "clockwise") == "clockwise", f"rotor seen from the {view}")
    d.place([((ox + 40, -76), "start"), ((ox - 40, -76), "end")], need(variant, "N").value_text)
    return d.svg(f"Ship turning {turn}, pitching, and its turbine rotor seen from the {view}")


def aircraft(variant) -> str:
    """Problem 5.2: the aircraft from above on its turn, and its propeller seen from the stated side."""
    turn = choice(variant, "turn", "left")
    view = choice(variant, "view", "rear")
    d = Drawing()
    d.polygon([(-6, -48), (6, -48), (6, 40), (-6, 40)], fill="white", width=LINE)
    d.polygon([(-70, -8), (70, -8), (70, 6), (-70, 6)], fill="white", width=LINE)
    d.polygon([(-24, 30), (24, 30), (24, 38), (-24, 38)], fill="white", width=LINE)
    d.line((-20, -52), (20, -52), LINE * 2, cls="propeller")
    curve(d, (0, 0), turn, need(variant, "R").label("R"), need(variant, "v").label("v"), clear=76)
    d.place([((-26, -50), "end"), ((26, -50), "start"), ((0, -62), "middle")], "nose", size=13, style="italic")
    ox = 300.0 if turn == "left" else -320.0
    spin_disc(d, (ox, 0), choice(variant, "sense", "clockwise") == "clockwise", f"propeller seen from the {view}", 30)
    d.place([((ox, -52), "middle")], need(variant, "N").value_text)
    return d.svg(f"Aircraft turning {turn}; its propeller seen from the {view}")
