"""Belt drive figures, drawn to the variant's proportions (course text §1.2, Problem 1.4).

Pulleys are circles of the drawn diameters at the drawn centre distance, one scale for the
whole figure; the belt follows the exact common tangents. Values come from the variant as
printed on the sheet; an unknown is drawn to its solved size and labelled "?".
"""
from __future__ import annotations

from .groove import groove_inset
from .pulleys import (ARC_GAP, BELT_GAP, BELT_W, GAP, belt_motion, centre_distance, circle_path, diameter_mark,
                      hidden, label_stack, need, pulley, run_label)
from .svg import NOTE_SIZE, Drawing, subscripted
from .tangents import belt_loop
from .values import Shown, choice, shown

GEOM_W = 420.0       # px from the driver's far rim to the driven pulley's far rim
COMPOUND_W = 560.0   # the same for the two stages of a compound drive
MAX_D_PX = 250.0     # cap on a pulley's drawn diameter
STAGE_GAP = 0.6      # compound drive: clear space between pulleys, as a fraction of the largest diameter


def belt_drive(variant) -> str:
    """An open or crossed belt drive with d₁, d₂, X, the speeds and the tight side. Where the centre
    distance is not data, the pulleys are drawn a clear space apart and it is not dimensioned; a belt
    thickness is noted under the drive."""
    d1, d2 = need(variant, "d1"), need(variant, "d2")
    x = shown(variant, "X")
    if x is None or not x.si > 0:
        x = Shown("X", (d1.si + d2.si) / 2 + STAGE_GAP * 1.6 * max(d1.si, d2.si), "")
    n1, n2, groove = shown(variant, "N1"), shown(variant, "N2"), shown(variant, "groove")
    crossed = choice(variant, "drive", "open") == "crossed"
    span = GEOM_W if groove is None else GEOM_W - 60  # leave room for the groove inset
    scale = min(span / (d1.si / 2 + x.si + d2.si / 2), MAX_D_PX / max(d1.si, d2.si))
    r1, r2 = d1.si / 2 * scale, d2.si / 2 * scale
    rb1, rb2 = r1 + BELT_GAP, r2 + BELT_GAP
    c1, c2 = (0.0, 0.0), (x.si * scale, 0.0)

    drawing = Drawing()
    loop = belt_loop(c1, rb1, c2, rb2, crossed)
    pulley(drawing, c1, r1, "driver")
    pulley(drawing, c2, r2, "driven")
    drawing.path(loop.path, BELT_W, cls="belt")
    diameter_mark(drawing, c1, r1)
    diameter_mark(drawing, c2, r2)
    # Rotation arrows on the free sides: the driver turns clockwise; a crossed belt reverses the driven.
    drawing.rotation_arrow(c1, rb1 + ARC_GAP, True, 130, 230)
    drawing.rotation_arrow(c2, rb2 + ARC_GAP, not crossed, -50, 50)
    drawing.text((-rb1 - ARC_GAP - GAP, 5), d1.label(), anchor="end", cls="label-d1")
    drawing.text((c2[0] + rb2 + ARC_GAP + GAP, 5), d2.label(), anchor="start", cls="label-d2")
    runs = (loop.tight, loop.slack)
    label_stack(drawing, c1, rb1, ["Driver"] + ([n1.label()] if n1 else []), runs)
    label_stack(drawing, c2, rb2, ["Driven"] + ([n2.label()] if n2 else []), runs)
    if crossed:
        k = rb1 / (rb1 + rb2)  # the runs cross this far along from the driver
        belt_motion(drawing, loop, ((1 - k) / 2, (1 + k) / 2))
        run_label(drawing, loop.tight, (1 - k) / 2, "tight side", below=False)
    else:
        belt_motion(drawing, loop, (0.5, 0.5))
        run_label(drawing, loop.tight, 0.5, "tight side", below=True)
    if x.value_text:
        centre_distance(drawing, c1, rb1, c2, rb2, drawing.box[3] + 14, x.label("X"))
    thickness = shown(variant, "t")
    if thickness is not None:
        drawing.text(((c1[0] + c2[0]) / 2, drawing.box[3] + 22), f"belt {thickness.value_text} thick",
                     size=NOTE_SIZE, style="italic", cls="label-t")
    if groove is not None:
        groove_inset(drawing, drawing.box[2] + 16, drawing.box[1], groove.si, groove.label("2\u03b2"))
    kind = "Crossed" if crossed else "Open"
    return drawing.svg(f"{kind} {'V-belt' if groove is not None else 'belt'} drive")


def compound_drive(variant) -> str:
    """Two belt stages (Problem 1.4): motor d₁ -> main shaft d₂; d₃ on the main shaft -> countershaft d₄.

    Seen along the shafts, d₂ is in front of d₃ on the main shaft: what it hides of d₃ and of
    the second belt is drawn dashed. Centre distances are not data here; they are chosen
    from the diameters so both belts show clearly.
    """
    d = [need(variant, f"d{i}") for i in range(1, 5)]
    largest = max(q.si for q in d)
    x1 = (d[0].si + d[1].si) / 2 + STAGE_GAP * largest
    x2 = (d[2].si + d[3].si) / 2 + STAGE_GAP * largest
    scale = min(COMPOUND_W / (d[0].si / 2 + x1 + x2 + d[3].si / 2), MAX_D_PX / largest)
    r = [q.si / 2 * scale for q in d]
    rb = [v + BELT_GAP for v in r]
    motor, main, counter = (0.0, 0.0), (x1 * scale, 0.0), ((x1 + x2) * scale, 0.0)

    drawing = Drawing()
    back = belt_loop(main, rb[2], counter, rb[3])
    pulley(drawing, main, r[2], "d3")
    pulley(drawing, counter, r[3], "countershaft")
    drawing.path(back.path, BELT_W, cls="belt")
    front = belt_loop(motor, rb[0], main, rb[1])
    pulley(drawing, main, r[1], "d2")
    hidden(drawing, "behind-d2", main, r[1], [(circle_path(main, r[2]), 1.0), (back.path, 1.6)])
    pulley(drawing, motor, r[0], "motor")
    drawing.path(front.path, BELT_W, cls="belt")
    for loop in (front, back):
        belt_motion(drawing, loop, (0.5, 0.5))
    diameter_mark(drawing, motor, r[0])
    # Nearly level, so the tags sit where no belt runs: d₂ left of the main shaft, d₃ right of it.
    diameter_mark(drawing, main, r[1], 25, subscripted("d2"), "left", inside=r[2] > r[1])
    diameter_mark(drawing, main, r[2], -25, subscripted("d3"), "right")
    diameter_mark(drawing, counter, r[3])
    drawing.rotation_arrow(motor, rb[0] + ARC_GAP, True, 130, 230)
    drawing.rotation_arrow(counter, rb[3] + ARC_GAP, True, -50, 50)

    runs = (front.tight, front.slack, back.tight, back.slack)
    speeds = [shown(variant, name) for name in ("N1", "N2", "N4")]
    titles = ("Motor", "Main shaft", "Countershaft")
    for c, radius, title, speed in zip((motor, main, counter), (rb[0], max(rb[1], rb[2]), rb[3]), titles, speeds):
        label_stack(drawing, c, radius, [title] + ([speed.label()] if speed else []), runs)
    below = ([d[0].label()], [d[1].label(), d[2].label()], [d[3].label()])
    for c, radius, lines in zip((motor, main, counter), (rb[0], max(rb[1], rb[2]), rb[3]), below):
        label_stack(drawing, c, radius, lines, runs, above=False)
    return drawing.svg("Compound belt drive: motor, main shaft and countershaft")
