"""Linkages drawn to scale for their lengths to be measured (the course text's §7.9 question 1, "using the
scale provided by the dimensions on the figure, measure ..."; Problem 7.1, whose slider-crank is a figure):
one dimension is printed and every other length is read off the drawing with it as the scale, so no other
length is written. The drawing is large (a reading to half a millimetre on the page is a few millimetres of
the linkage); the key's figures draw the position asked, the lengths read written on the links.
"""
from __future__ import annotations

import math

from .. import units
from ..mechanics import linkages as lk
from ..mechanics.slider_cranks import slider_crank as solve_slider
from .kinematic import DASH, Sketch, centre_of, fit
from .linkages import _si, _step
from .svg import MAX_WIDTH, NOTE_SIZE, unit
from .symbols import dimension
from .values import choice

#: The box a measured drawing is fitted to, px: about 15 by 10.5 cm on the page, where 4 mm of the
#: linkages the bank draws is about 0.8 mm at the least (1.2 mm at the median), so a length read to half a
#: millimetre rounds to the right 10 mm. The whole figure is narrowed to print at the common scale.
READ_W, READ_H = 700.0, 480.0
PAD = 6.0   # px round a drawing (Drawing.svg)
#: The box of a key's figure, which is not measured.
KEY_W, KEY_H = 520.0, 340.0
SCALE_NOTE = "drawn to scale: measure lengths against the dimension given"


def _length(variant, name: str) -> str:
    """A length the key found, as the key prints it."""
    return f"{variant.step(name).value * 1000:.4g} mm"


def _dimension_beside(s: Sketch, a, b, text: str, points) -> None:
    """The dimension a-b drawn clear of the linkage on the side where its extension lines cross least of it,
    else where it reaches out least: only what lies across the dimension's own span counts."""
    (ux, uy) = unit((b[0] - a[0], b[1] - a[1]))
    nx, ny = uy, -ux                                  # the dimension's side=+1 normal (symbols.dimension)
    span = math.dist(a, b)
    across = [(p[0] - a[0]) * nx + (p[1] - a[1]) * ny for p in points
              if -20.0 <= (p[0] - a[0]) * ux + (p[1] - a[1]) * uy <= span + 20.0]
    offset = {side: max([0.0] + [side * x for x in across]) + 30.0 for side in (1, -1)}

    def crossed(side: int) -> int:   # what its extension lines would run through
        return sum(s.d.crosses([(p[0] + side * nx * 6, p[1] + side * ny * 6),
                                (p[0] + side * nx * offset[side], p[1] + side * ny * offset[side])]) for p in (a, b))

    side = min(offset, key=lambda k: (crossed(k), offset[k], -k))
    dimension(s.d, a, b, text, side=side, offset=offset[side])


#: Directions (page) a ground pivot's bracket may stand in from its pin, first preferred: below, above, aside.
BRACKET_WAYS = ((0.0, 1.0), (0.0, -1.0), (-1.0, 0.0), (1.0, 0.0), (-0.7071, 0.7071), (0.7071, 0.7071),
                (-0.7071, -0.7071), (0.7071, -0.7071))


def _ground_pivot_clear(s: Sketch, c) -> None:
    """A ground pivot whose bracket stands where it crosses least of what is drawn round its pin."""
    def crossed(way) -> int:
        ux, uy = way
        nx, ny = -uy, ux
        outline = [(c[0] + ux * along + nx * half, c[1] + uy * along + ny * half)
                   for along, half in ((7, -9), (26, -16), (26, 16), (7, 9))]
        return s.d.crosses(outline + outline[:1])

    s.ground_pivot(c, down=min(BRACKET_WAYS, key=crossed))


# ---- §7.9: the suspension --------------------------------------------------------------------

def _suspension(variant, theta2: float) -> dict[str, tuple[float, float]]:
    """D, A, B, C, P (m) of the suspension as drawn, at the crank angle theta2."""
    a = (_si(variant, "xA"), _si(variant, "yA"))
    turn = 1.0 if choice(variant, "circuit", "1") == "2" else -1.0
    pose = lk.plate_pose(a, _si(variant, "AB"), _si(variant, "BC"), _si(variant, "DC"), theta2, turn,
                         _si(variant, "PC"), _si(variant, "PB"), choice(variant, "side", "left") == "left")
    return {"D": (0.0, 0.0), "A": a, **pose}


def _draw_suspension(s: Sketch, page, dash: str = "") -> None:
    s.plate([page["B"], page["C"], page["P"]], dash=dash)
    s.bar(page["A"], page["B"], dash=dash)
    s.bar(page["C"], page["D"], dash=dash)
    if dash:
        for k in "BC":
            s.pin(page[k], dash="2 2")
        return
    s.pin(page["B"])
    s.pin(page["C"])
    s.dot(page["P"])


def _ground_pivots(s: Sketch, page) -> None:
    """A and D on the frame, each bracket where it is clearest of what is drawn (the dimension included)."""
    _ground_pivot_clear(s, page["A"])
    _ground_pivot_clear(s, page["D"])


def suspension_to_scale(variant) -> str:
    """§7.9's suspension at the crank angle it is drawn at, to scale: A straight above D by the one dimension
    AD, the coupler a triangular plate BCP; every other length is measured."""
    world = _suspension(variant, _si(variant, "drawn"))

    def draw(width: float) -> Sketch:
        frame = fit(list(world.values()), width, READ_H)
        page = {k: frame(v) for k, v in world.items()}
        s = Sketch()
        _draw_suspension(s, page)
        _dimension_beside(s, page["A"], page["D"], str(variant.param("yA")), list(page.values()))
        _ground_pivots(s, page)
        s.corner_axes()
        _joint_labels(s, page)
        _note_below(s, SCALE_NOTE)
        return s

    return _as_wide_as_prints(draw).svg("Four-bar suspension with a triangular coupler plate BCP, drawn to scale; "
                                        "D at the origin")


def _as_wide_as_prints(draw, width: float = READ_W) -> Sketch:
    """The drawing `draw(width)` makes with the linkage fitted to `width`, narrowed until the whole figure,
    dimension, labels and axes included, prints at the common scale (MAX_WIDTH): the larger, the better read."""
    while True:
        s = draw(width)
        x0, _, x1, _ = s.d.box
        if x1 - x0 + 2 * PAD <= MAX_WIDTH or width < READ_W / 4:
            return s
        width -= x1 - x0 + 2 * PAD - MAX_WIDTH + 1.0


def suspension_at_theta2(variant) -> str:
    """For the key: the suspension at the crank angle asked, the lengths read on its links, the position
    the sheet draws dashed."""
    world = {"D": (0.0, 0.0), "A": (_si(variant, "xA"), _si(variant, "yA"))}
    world.update({k: (_step(variant, f"x{k}"), _step(variant, f"y{k}")) for k in "BCP"})
    drawn = _suspension(variant, _si(variant, "drawn"))
    theta2 = _si(variant, "theta2")

    def draw(width: float) -> Sketch:
        frame = fit(list(world.values()) + list(drawn.values()), width, KEY_H)
        page = {k: frame(v) for k, v in world.items()}
        s = Sketch()
        _draw_suspension(s, {k: frame(v) for k, v in drawn.items()}, dash=DASH)
        _draw_suspension(s, page)
        _ground_pivots(s, page)
        radius = max(14.0, min(30.0, 0.45 * math.dist(page["A"], page["B"])))
        s.reference_line(page["A"], radius + 22)
        s.arc(page["A"], radius, 0.0, theta2)
        s.corner_axes()
        _joint_labels(s, page)
        middle, plate = centre_of([page[k] for k in "ABCD"]), centre_of([page[k] for k in "BCP"])
        for (p, q), name, centre in ((("A", "B"), "L2", middle), (("C", "D"), "L4", middle),
                                     (("B", "C"), "L3", plate), (("C", "P"), "CP", plate), (("B", "P"), "BP", plate)):
            s.link_label(page[p], page[q], _length(variant, name), centre)
        s.angle_label(page["A"], radius, 0.0, theta2, f"θ₂ = {variant.param('theta2')}")
        return s

    return _as_wide_as_prints(draw, KEY_W).svg("The suspension at the crank angle asked, with the lengths read; "
                                               "as drawn on the sheet, dashed")


def _joint_labels(s: Sketch, page) -> None:
    linkage = centre_of([page[k] for k in "ABCD"])
    for key in "ABC":
        s.joint_label(page[key], key, linkage)
    s.joint_label(page["D"], "D (0, 0)", linkage)
    s.joint_label(page["P"], "P", centre_of([page[k] for k in "BCP"]))


# ---- Problem 7.1: the offset slider-crank ---------------------------------------------------

def _slider_crank(variant, theta2: float) -> dict[str, tuple[float, float]]:
    """A, B, C, P and the foot F of A on the line of slide (m), at the crank angle theta2."""
    where = choice(variant, "slider", "right")
    offset, tip = _si(variant, "offset"), _si(variant, "piston")
    pos = solve_slider(_si(variant, "AB"), _si(variant, "L3"), offset, theta2, "horizontal", where)
    toward = 1.0 if where == "right" else -1.0
    return {"A": (0.0, 0.0), "B": pos.b, "C": pos.c, "P": (pos.c[0] + toward * tip, pos.c[1]), "F": (0.0, -offset)}


def _draw_slider_crank(s: Sketch, page, dash: str = "") -> None:
    s.thin(page["C"], page["P"], width=6.0 if not dash else 2.0, dash=dash, cls="piston")
    s.bar(page["A"], page["B"], dash=dash)
    s.bar(page["B"], page["C"], dash=dash)
    direction = unit((page["P"][0] - page["C"][0], page["P"][1] - page["C"][1]))
    s.slider_block(page["C"], direction, dash=dash)
    s.pin(page["B"], dash="2 2" if dash else "")
    if not dash:
        s.dot(page["P"])


GUIDE_DEPTH = 24.0   # px below the line of slide that its hatched ground takes


def _guide(s: Sketch, page, extent) -> list[tuple[float, float]]:
    """The line of slide through F along x, from the crank pivot's side past the tip, hatched below it;
    the corners of what it takes up."""
    y = page["F"][1]
    x0, x1 = min(extent) - 30, max(extent) + 30
    s.guide((x0, y), (x1, y), (0.0, 1.0))
    return [(x, y + GUIDE_DEPTH) for x in (x0, *extent, x1)]


def _note_below(s: Sketch, text: str) -> None:
    """An italic note centred under everything drawn so far."""
    x0, _, x1, y1 = s.d.box
    s.d.text(((x0 + x1) / 2, y1 + 22), text, size=NOTE_SIZE, style="italic", cls="scale-note")


def _crank_marks(s: Sketch, page, theta2: float) -> float:
    """The offset of the line of slide below A, the crank's angle marked from +x and A's ground pivot;
    the radius of the angle's arc, for its label."""
    s.thin(page["A"], page["F"], dash="4 3", cls="offset")
    radius = max(16.0, min(34.0, 0.45 * math.dist(page["A"], page["B"])))
    s.reference_line(page["A"], radius + 24)
    s.arc(page["A"], radius, 0.0, theta2)
    _ground_pivot_clear(s, page["A"])
    return radius


def _slider_crank_labels(s: Sketch, page) -> tuple[float, float]:
    """The axes' glyph and the joints' letters; the middle of the linkage they are placed away from."""
    s.corner_axes()
    middle = centre_of([page[k] for k in "ABC"])
    for key in "ABC":
        s.joint_label(page[key], key, middle)
    s.joint_label(page["P"], "P", page["C"], 13)
    return middle


def slider_crank_to_scale(variant) -> str:
    """Problem 7.1's offset slider-crank at the angle it is drawn at, to scale: the crank's angle marked, the
    coupler BC the one dimension; the crank, the offset of the line of slide and the piston are measured."""
    drawn = _si(variant, "drawn")
    world = _slider_crank(variant, drawn)

    def draw(width: float) -> Sketch:
        frame = fit(list(world.values()), width, READ_H * 0.6)
        page = {k: frame(v) for k, v in world.items()}
        s = Sketch()
        ground = _guide(s, page, [p[0] for p in page.values()] + [page["B"][0], page["C"][0]])
        _draw_slider_crank(s, page)
        radius = _crank_marks(s, page, drawn)
        _dimension_beside(s, page["B"], page["C"], str(variant.param("L3")), list(page.values()) + ground)
        _slider_crank_labels(s, page)
        s.angle_label(page["A"], radius, 0.0, drawn, str(variant.param("drawn")))
        _note_below(s, SCALE_NOTE)
        return s

    return _as_wide_as_prints(draw).svg("Offset slider-crank drawn to scale, its crank at the angle marked")


def slider_crank_turned(variant) -> str:
    """For the key: the slider-crank with its crank turned to θ2, the lengths read on its links, the
    position the sheet draws dashed."""
    theta2 = _step(variant, "theta2")
    world = _slider_crank(variant, theta2)
    before = _slider_crank(variant, _si(variant, "drawn"))
    turned = units.format_quantity(math.degrees(lk.wrap(theta2)), "deg").replace("-", "\u2212")

    def draw(width: float) -> Sketch:
        frame = fit(list(world.values()) + list(before.values()), width, KEY_H * 0.6)
        page = {k: frame(v) for k, v in world.items()}
        s = Sketch()
        _guide(s, page, [frame(p)[0] for p in (*world.values(), *before.values())])
        _draw_slider_crank(s, {k: frame(v) for k, v in before.items()}, dash=DASH)
        _draw_slider_crank(s, page)
        radius = _crank_marks(s, page, theta2)
        middle = _slider_crank_labels(s, page)
        for (p, q), name in ((("A", "B"), "L2"), (("C", "P"), "tip"), (("A", "F"), "L1")):
            s.link_label(page[p], page[q], _length(variant, name), middle)
        s.angle_label(page["A"], radius, 0.0, theta2, f"θ₂ = {turned}")
        return s

    return _as_wide_as_prints(draw, KEY_W).svg("The slider-crank with its crank turned, the lengths read; as drawn "
                                               "on the sheet, dashed")
