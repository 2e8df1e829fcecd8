"""Gear figures seen along the shafts: a gear pair, a simple train in a line, an epicyclic train.

Gears are drawn by the convention of gear drawings, an outside circle (solid) and a pitch circle
(chain line), with pitch radii in proportion to the teeth (one module per mesh) and meshing pitch
circles touching. Teeth and speeds come from the variant as printed; an unknown is drawn to its
solved size and labelled "?". A sense of rotation is drawn only where it is given.
"""
from __future__ import annotations

import math

from .pulleys import CENTRE_DASH, GAP, ROW, need
from .svg import FONT_SIZE, LINE, THIN, Drawing, on_circle, text_width
from .values import choice, shown

PAIR_W = 330.0      # px across a gear pair
TRAIN_W = 520.0     # px across a simple train
MAX_R = 110.0       # cap on a pitch radius
RING_R = 125.0      # pitch radius of an epicyclic ring
ARM_W = 5.0
#: Sheets print every figure at one width, so figures share a width (as the belt figures do)
#: and their labels print at one size.
MIN_WIDTH = 640.0


def fit_width(drawing: Drawing, minimum: float = MIN_WIDTH) -> None:
    """Widen the drawn extent evenly to at least `minimum` px."""
    x0, _, x1, _ = drawing.box
    if x1 - x0 < minimum:
        grow = (minimum - (x1 - x0)) / 2
        drawing.extend(x0 - grow, drawing.box[1], x1 + grow, drawing.box[1])


def gear_face(drawing: Drawing, c, r: float, teeth: float | None, cls: str) -> None:
    """A spur gear seen along its shaft: outside circle (one module beyond the pitch circle), pitch
    circle as a chain line, hub and centre mark. Filled white, so it hides what lies behind."""
    module = 2 * r / teeth if teeth and teeth > 0 else 0.05 * r
    drawing.circle(c, r + max(1.5, module), LINE, fill="white", cls=f"gear {cls}")
    drawing.circle(c, r, THIN, dash=CENTRE_DASH, cls=f"pitch {cls}")
    hub = max(3.0, 0.12 * r)
    drawing.circle(c, hub, THIN)
    drawing.centre_mark(c, hub + 4)


def teeth_label(variant, name: str) -> str:
    """'20 teeth', or '? teeth' when the count is asked."""
    value = shown(variant, name)
    return f"{value.value_text} teeth" if value is not None else ""


def _stack(drawing: Drawing, x: float, y: float, lines: list[str], bold_first: bool = True) -> float:
    """Lines centred on x from baseline y downwards, the first bold; returns the baseline after the last."""
    for i, text in enumerate(lines):
        drawing.text((x, y), text, weight="bold" if i == 0 and bold_first else "")
        y += ROW
    return y


def _dimension_below(drawing: Drawing, c1, c2, y: float, label: str) -> None:
    for c in (c1, c2):
        drawing.line((c[0], c[1]), (c[0], y + 6), THIN, dash=CENTRE_DASH)
    drawing.dimension((c1[0], y), (c2[0], y))
    drawing.text(((c1[0] + c2[0]) / 2, y + FONT_SIZE + 3), label, cls="label-C")


def gear_pair(variant) -> str:
    """Two external gears in mesh (§1.3.1-1.3.2), the driver on the left turning clockwise."""
    t1, t2 = need(variant, "t1"), need(variant, "t2")
    scale = min(PAIR_W / (2 * (t1.si + t2.si)), MAX_R / max(t1.si, t2.si))
    r1, r2 = t1.si * scale, t2.si * scale
    c1, c2 = (0.0, 0.0), (r1 + r2, 0.0)
    drawing = Drawing()
    gear_face(drawing, c1, r1, t1.si, "driver")
    gear_face(drawing, c2, r2, t2.si, "driven")
    drawing.rotation_arrow(c1, r1 + 14, True, 130, 230)
    drawing.rotation_arrow(c2, r2 + 14, False, -50, 50)
    speed = shown(variant, "N1")
    driver = ["Driver", teeth_label(variant, "t1")] + ([speed.label("\u03c9\u2081")] if speed else [])
    for i, text in enumerate(driver):  # left of the driver, clear of its rotation arrow
        drawing.text((c1[0] - r1 - 30, -ROW * (len(driver) - 1) / 2 + 5 + i * ROW), text, anchor="end",
                     weight="bold" if i == 0 else "")
    for i, text in enumerate(["Driven", teeth_label(variant, "t2")]):
        drawing.text((c2[0] + r2 + 30, -ROW / 2 + 5 + i * ROW), text, anchor="start", weight="bold" if i == 0 else "")
    low = max(r1, r2) + 22
    centre = shown(variant, "C")
    if centre is not None:
        _dimension_below(drawing, c1, c2, low, centre.label("C"))
    module = shown(variant, "m")
    if module is not None:
        drawing.text(((c1[0] + c2[0]) / 2, drawing.box[3] + ROW), f"module {module.label('m')}", cls="label-m")
    fit_width(drawing)
    return drawing.svg("Spur gear pair")


def simple_train(variant) -> str:
    """Figure 1.16: driver, one or two idlers and the driven gear in a line, all of one module."""
    names = ["t1", "ta"] + (["tb"] if int(need(variant, "idlers").si) == 2 else []) + ["t2"]
    teeth = [need(variant, n).si for n in names]
    scale = min(TRAIN_W / (2 * sum(teeth)), MAX_R / max(teeth))
    radii = [t * scale for t in teeth]
    centres, x = [], 0.0
    for i, r in enumerate(radii):
        x += r if i == 0 else radii[i - 1] + r
        centres.append((x, 0.0))
    drawing = Drawing()
    titles = ["Driver"] + ["Idler"] * (len(names) - 2) + ["Driven"]
    for c, r, t, title in zip(centres, radii, teeth, titles):
        gear_face(drawing, c, r, t, title.lower())
    clockwise = choice(variant, "sense1", "clockwise") == "clockwise"
    drawing.rotation_arrow(centres[0], radii[0] + 12, clockwise, 120, 240)  # only the driver's sense is given
    # The span is dimensioned above the gears, so its centre lines stay clear of the labels below.
    y_dim = -max(radii) - 18
    for c in (centres[0], centres[-1]):
        drawing.line(c, (c[0], y_dim - 6), THIN, dash=CENTRE_DASH)
    drawing.dimension((centres[0][0], y_dim), (centres[-1][0], y_dim))
    drawing.text(((centres[0][0] + centres[-1][0]) / 2, y_dim - 6), "C = ?", cls="label-C")
    speed = shown(variant, "N1")
    drawing.text((centres[0][0], y_dim - 6 - ROW), speed.label("\u03c9\u2081") if speed else "", anchor="middle")
    drawing.text((centres[-1][0], y_dim - 6 - ROW), "\u03c9\u2082 = ?", anchor="middle")
    _label_row(drawing, centres, radii, titles, [teeth_label(variant, n) for n in names])
    module = shown(variant, "m")
    if module is not None:
        drawing.text(((centres[0][0] + centres[-1][0]) / 2, drawing.box[3] + ROW), f"all gears {module.label('m')}")
    fit_width(drawing)
    return drawing.svg(f"Simple gear train with {len(names) - 2} idler{'s' if len(names) > 3 else ''}")


def _label_row(drawing: Drawing, centres, radii, titles, teeth) -> None:
    """Title and teeth under each gear; a label that would run into its neighbour's drops a row."""
    base = max(radii) + 26
    rows: list[float] = []
    last_right = -math.inf
    for c, title, count in zip(centres, titles, teeth):
        half = max(text_width(title), text_width(count)) / 2
        drop = c[0] - half < last_right + GAP
        y = base + (2 * ROW + 4 if drop and not (rows and rows[-1] > base) else 0)
        _stack(drawing, c[0], y, [title, count])
        rows.append(y)
        last_right = c[0] + half if not drop else last_right
    drawing.extend(0, 0, 0, max(rows) + ROW)


def epicyclic(variant) -> str:
    """Figure 1.19: sun, three planets on an arm, and the ring, seen along the common axis."""
    ts, tp, t_ring = need(variant, "ts"), need(variant, "tp"), need(variant, "tR")
    scale = RING_R / t_ring.si
    r_s, r_p, r_r = ts.si * scale, tp.si * scale, t_ring.si * scale
    fixed = choice(variant, "fixed", "ring")
    driver = choice(variant, "driver", "arm")
    driven_member = "arm" if driver == "arm" else ("ring" if fixed == "sun" else "sun")
    drawing = Drawing()
    rim = r_r + 16
    drawing.circle((0, 0), rim, LINE, cls="ring")
    drawing.circle((0, 0), r_r - max(1.5, 2 * r_r / t_ring.si), LINE, cls="ring")
    drawing.circle((0, 0), r_r, THIN, dash=CENTRE_DASH, cls="pitch ring")
    orbit = r_s + r_p
    planets = [on_circle((0, 0), orbit, math.radians(a)) for a in (-90, 30, 150)]
    for c in planets:
        gear_face(drawing, c, r_p, tp.si, "planet")
    gear_face(drawing, (0, 0), r_s, ts.si, "sun")
    for c in planets:
        drawing.line((0, 0), c, ARM_W, cls="arm")
    drawing.circle((0, 0), ARM_W, LINE, fill="white")
    _hatch_fixed(drawing, fixed, r_s, rim)
    sense = choice(variant, "sense_in", "clockwise") == "clockwise"
    radius, start, end = _input_arc(driven_member, r_s, r_p, rim)
    drawing.rotation_arrow((0, 0), radius, sense, start, end)
    speed = shown(variant, "N_in")
    notes = {fixed: "fixed", driven_member: f"input, {speed.value_text}" if speed else "input"}
    # Ring and planets are named on the right, sun and arm on the left, each by a leader line.
    columns = {1: [("ring", on_circle((0, 0), rim, math.radians(-35)), teeth_label(variant, "tR")),
                   ("planets", on_circle(planets[1], r_p, math.radians(-10)), teeth_label(variant, "tp"))],
               -1: [("sun", on_circle((0, 0), r_s, math.radians(215)), teeth_label(variant, "ts")),
                    ("arm", (planets[2][0] * 0.8, planets[2][1] * 0.8), "")]}
    for side, entries in columns.items():
        x = side * (rim + 36)
        for i, (member, point, teeth) in enumerate(entries):
            y = -rim * 0.55 + i * rim * 1.1
            lines = [f"{member}: {teeth}" if teeth else member] + [notes[m] for m in notes if m == member]
            drawing.line(point, (x - side * 4, y - 5), THIN, cls="leader")
            for k, text in enumerate(lines):
                drawing.text((x, y + k * ROW), text, anchor="start" if side > 0 else "end", cls=f"label-{member}")
    fit_width(drawing)
    return drawing.svg(f"Epicyclic gear train, the {fixed} fixed")


def _input_arc(member: str, r_s: float, r_p: float, rim: float) -> tuple[float, float, float]:
    """(radius, start, end) of the rotation arrow on the input: the arm's along the planets' orbit in the
    gap below the sun, the sun's just outside it, the ring's outside its rim."""
    orbit = r_s + r_p
    gap = 60 - math.degrees(math.asin(min(1.0, (r_p + 6) / orbit)))  # half the free angle between planets
    span = max(8.0, 0.7 * gap)
    if member == "arm":
        return orbit, 90 - span, 90 + span
    if member == "sun":  # planets touch the sun only at 30 and 150 degrees
        return r_s + 8, 60, 120
    return rim + 12, -70, -20


def _hatch_fixed(drawing: Drawing, fixed: str, r_sun: float, rim: float) -> None:
    """Ground hatching: short strokes outside the ring's rim, or across the sun's hub."""
    if fixed == "ring":
        for k in range(36):
            a = math.radians(k * 10)
            p = on_circle((0, 0), rim, a)
            q = on_circle((0, 0), rim + 9, a + math.radians(5))
            drawing.line(p, q, THIN, cls="ground")
        return
    h = r_sun * 0.45
    for k in range(-3, 4):
        off = k * h / 3.5
        drawing.line((off - h * 0.5, h * 0.5), (off + h * 0.5, -h * 0.5), THIN, cls="ground")
