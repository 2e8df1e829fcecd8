"""An in-line engine's cranks drawn for their angles to be read off the figure (the course text's Example
2.6 gives its crank directions as a drawing, Figure 2.8): the end view carries a degree scale round the
cranks, from crank 1 in the direction of rotation, and no angle is written beside a crank.
"""
from __future__ import annotations

import math

from .engines import STROKE_LINE, _inline_side
from .balancing import GAP, _si, _value
from .shafts import MIN_WIDTH, fit_width
from .svg import FONT_SIZE, NOTE_SIZE, THIN, Drawing, on_circle

CRANK = 82.0          # px, the cranks' length in the end view: their dots close to the scale, to read against
SCALE_IN = 92.0       # px, the inner edge of the degree scale
MINOR, MAJOR = 5, 10  # degrees between short and long ticks
LABEL_EVERY = 30      # degrees between the scale's numbers
LABEL_AT = 114.0      # px, the scale's numbers
TICK_SIZE = 11


def _screen(degrees: float) -> float:
    """Screen angle of a crank angle: 0° straight up (the line of stroke), growing clockwise."""
    return math.radians(degrees) - math.pi / 2


def _protractor(d: Drawing, c) -> None:
    """The degree scale: a circle with a tick every 5°, a longer one every 10°, numbered every 30°."""
    d.circle(c, SCALE_IN, THIN, cls="scale")
    for degrees in range(0, 360, MINOR):
        a = _screen(degrees)
        long = degrees % MAJOR == 0
        d.line(on_circle(c, SCALE_IN, a), on_circle(c, SCALE_IN + (9 if long else 5), a), THIN * (0.9 if long else 0.6),
               cls="scale-tick")
    for degrees in range(LABEL_EVERY, 360, LABEL_EVERY):
        x, y = on_circle(c, LABEL_AT, _screen(degrees))
        d.text((x, y + 0.35 * TICK_SIZE), f"{degrees}", size=TICK_SIZE, cls="scale-label")


def inline_cranks_to_read(variant) -> str:
    """Example 2.6 with the crank angles read off the figure: the cylinder pitch a, and the end view with a
    degree scale from crank 1 (on the line of stroke) in the direction of rotation; the cranks numbered."""
    d = Drawing()
    _inline_side(d, 4, _si(variant, "a"), _value(variant, "a"))
    c = (d.box[2] + GAP + LABEL_AT + 14, 0.0)
    _protractor(d, c)
    d.text((c[0], c[1] - LABEL_AT - 2), STROKE_LINE, size=NOTE_SIZE, cls="zero-label")   # crank 1 lies on it
    d.centre_mark(c, 5)
    tips = []
    for i in range(1, 5):
        a = _screen(math.degrees(_si(variant, f"theta{i}")))
        tip = on_circle(c, CRANK, a)
        d.line(c, tip, 2.2, cls=f"spoke spoke-{i}")
        d.circle(tip, 4.0, fill="black", cls=f"mass mass-{i}")
        tips.append(a)
    for i, a in enumerate(tips, start=1):    # each number beside its crank, clear of the others
        across = (-math.sin(a), math.cos(a))
        spots = [on_circle(c, r, a) for r in (52, 40, 64, 30)]
        d.place([((x + side * 10 * across[0], y + side * 10 * across[1] + 0.35 * FONT_SIZE), "middle")
                 for x, y in spots for side in (1, -1)], str(i), weight="bold", cls=f"spoke-label label-{i}")
    # the sense of rotation: an arrow just inside the scale, from 0° towards 40°
    r = SCALE_IN - 6
    p0, p1 = on_circle(c, r, _screen(6)), on_circle(c, r, _screen(40))
    d.path(f"M {p0[0]:.2f},{p0[1]:.2f} A {r:.2f} {r:.2f} 0 0 1 {p1[0]:.2f},{p1[1]:.2f}", THIN, cls="sense")
    end = _screen(40)
    d.arrowhead(p1, (-math.sin(end), math.cos(end)), 7)
    d.text((c[0], c[1] + LABEL_AT + 24), "angles from crank 1 in the direction of rotation, scale in degrees",
           size=NOTE_SIZE, style="italic")
    fit_width(d, MIN_WIDTH)
    return d.svg("Four-cylinder in-line engine: cylinder pitch, and the cranks' end view on a degree scale")
