"""Engine figures (course text §2.3): the cranks of an in-line engine (side view with the cylinder
pitch, end view with the cranks at their angles, numbered), and the cylinder lines of radial and V
engines round their one crank. Cranks whose angles are asked are drawn as "?".
"""
from __future__ import annotations

import math

from .balancing import DIM_ROW, GAP, _si, _value
from .shafts import DISC_H, MIN_WIDTH, OUTLINE, ROW, Convention, Plane, Spoke, chain, end_view, fit_width, side_view
from .layout import text_box
from .svg import FONT_SIZE, LINE, NOTE_SIZE, THIN, Drawing, on_circle, pts
from .values import shown

STROKE_LINE = "0° (line of stroke)"
REACH = 100.0          # radial and V engines: crank plus connecting rod, drawn
BARREL_W = 26.0
CRANK_AT = math.radians(35)  # where the crank is drawn (any position: the resultants do not depend on it)


def _inline_side(d: Drawing, count: int, pitch: float, pitch_text: str):
    """Cranks numbered from one end at the cylinder pitch, the centre plane (the reference) marked,
    and the pitch dimensioned between each pair."""
    planes = [Plane(str(i + 1), i * pitch, "crank", (str(i + 1),)) for i in range(count)]
    x_of = side_view(d, planes, length_px=min(340.0, 90.0 * (count - 1)))
    chain(d, x_of, [(i * pitch, (i + 1) * pitch, pitch_text) for i in range(count - 1)], DIM_ROW)
    middle = x_of((count - 1) * pitch / 2)
    d.line((middle, -DISC_H - 2), (middle, DIM_ROW - 20), THIN, dash="10 3 2 3", cls="centre-plane")
    d.line((middle, DIM_ROW + 3), (middle, DIM_ROW + 10), THIN)  # broken round the pitch label
    d.text((middle, DIM_ROW + 10 + ROW), "centre plane (ref.)", size=NOTE_SIZE, style="italic")
    return x_of


def inline_cranks(variant) -> str:
    """Example 2.6: four cranks at given angles, cylinder pitch a; angles from the line of stroke."""
    d = Drawing()
    pitch = _si(variant, "a")
    _inline_side(d, 4, pitch, _value(variant, "a"))
    spokes = [Spoke(str(i), f"{i}: {_value(variant, f'theta{i}')}", 1.0, _si(variant, f"theta{i}"))
              for i in range(1, 5)]
    centre = (d.box[2] + GAP + OUTLINE, 0.0)
    end_view(d, centre, spokes, Convention(-math.pi / 2, True, STROKE_LINE), "angles in the direction of rotation")
    fit_width(d, MIN_WIDTH)
    return d.svg("Four-cylinder in-line engine: cylinder pitch and crank angles")


def inline_firing(variant) -> str:
    """Example 2.7: the cylinders numbered along the crankshaft, pitch a, and the firing order; the crank
    angles are to be found, so no end view."""
    order = str(shown(variant, "firing").value_text)
    count = len(order.split("-"))
    pitch = _si(variant, "a")
    d = Drawing()
    x_of = _inline_side(d, count, pitch, _value(variant, "a"))
    strokes = _value(variant, "strokes")
    y = d.box[3] + 22
    d.text((x_of(0.0), y), f"firing order {order}, {strokes}-stroke: crank angles ?", anchor="start",
           style="italic", cls="firing")
    fit_width(d, MIN_WIDTH)
    return d.svg(f"In-line engine with {count} cylinders, firing order {order}")


def primary_balance_cranks(variant) -> str:
    """Problem 2.1: cranks A to D; A and D given, B and C (mass and angle) unknown; reference plane B."""
    gaps = [_si(variant, k) for k in ("lAB", "lBC", "lCD")]
    z = [sum(gaps[:i]) for i in range(4)]
    outer = _value(variant, "m_out")
    lines = [("A", outer), ("B (ref.)", "m = ?"), ("C", "m = ?"), ("D", outer)]
    planes = [Plane(n, z[i], "crank", lines[i]) for i, n in enumerate("ABCD")]
    d = Drawing()
    x_of = side_view(d, planes)
    chain(d, x_of, [(z[i], z[i + 1], _value(variant, k)) for i, k in enumerate(("lAB", "lBC", "lCD"))], DIM_ROW)
    spokes = [Spoke("A", "A: 0°", 1.0, 0.0), Spoke("D", f"D: {_value(variant, 'phi')}", 1.0, _si(variant, "phi")),
              Spoke("B", "B: angle ?", 1.0, None), Spoke("C", "C: angle ?", 1.0, None)]
    centre = (d.box[2] + GAP + OUTLINE, 0.0)
    end_view(d, centre, spokes, Convention(-math.pi / 2, True, "0° (crank A)"), "angles in the direction of rotation")
    return d.svg("Four-crank engine: planes of the cranks and the outer cranks' angles")


def _cylinders(d: Drawing, alphas, ratio: float, names) -> float:
    """Cylinder barrels on lines at screen angles `alphas` round one crank at the origin, with their
    connecting rods to the crank pin and the pin's circle; returns the barrels' outer reach."""
    c = (0.0, 0.0)
    ratio = min(max(ratio, 2.5), 6.0)
    r = REACH / (ratio + 1)
    l = r * ratio
    crank = -math.pi / 2 + CRANK_AT
    pin = on_circle(c, r, crank)
    for alpha, name in zip(alphas, names):
        rel = crank - alpha
        x = r * math.cos(rel) + math.sqrt(l * l - (r * math.sin(rel)) ** 2)
        gudgeon = on_circle(c, x, alpha)
        ux, uy = math.cos(alpha), math.sin(alpha)
        nx, ny = -uy * BARREL_W / 2, ux * BARREL_W / 2
        inner, outer = l - r - 4, l + r + 24
        for side in (1, -1):
            a = (ux * inner + side * nx, uy * inner + side * ny)
            b = (ux * outer + side * nx, uy * outer + side * ny)
            d.line(a, b, LINE, cls=f"barrel barrel-{name}")
        cap_a = (ux * outer + nx, uy * outer + ny)
        cap_b = (ux * outer - nx, uy * outer - ny)
        d.line(cap_a, cap_b, LINE)
        d.line(c, on_circle(c, outer + 16, alpha), THIN, dash="10 3 2 3", cls=f"stroke-line line-{name}")
        piston = [(gudgeon[0] + s1 * nx * 0.85 + s2 * ux * 9, gudgeon[1] + s1 * ny * 0.85 + s2 * uy * 9)
                  for s1, s2 in ((1, -1), (1, 1), (-1, 1), (-1, -1))]
        d.polygon(piston, fill="white", width=LINE)
        d.line(pin, gudgeon, 2.0, cls="rod")
    d.circle(c, r, THIN, dash="4 3", cls="crank-circle")
    d.line(c, pin, 4.0, cls="crank")
    d.circle(pin, 4.0, LINE, fill="white")
    d.centre_mark(c, 8)
    _sense(d, c, r, alphas)
    return l + r + 24


def _sense(d: Drawing, c, r: float, alphas) -> None:
    """The crank's sense of rotation: an arrow round the crank axis with its ω, where neither crosses a
    rod, a barrel or a line of stroke (near the crank if there is room, else outside the cylinders)."""
    spacing = 2 * math.pi / len(alphas) if len(alphas) > 2 else math.pi
    middles = [a + spacing / 2 for a in alphas] + [a - spacing / 2 for a in alphas] + [math.pi / 2]
    for radius in (r + 10, r + 18, r + 28, REACH + 20, REACH + 40, REACH + 60):
        half = min(16.0, math.degrees(spacing) / 2 - 6)
        for middle in middles:
            mid = math.degrees(middle)
            arc = [on_circle(c, radius, math.radians(mid - half + 2 * half * k / 8)) for k in range(9)]
            at = on_circle(c, radius + 15, middle)
            box = text_box((at[0], at[1] + 5), "\u03c9", "middle", FONT_SIZE, italic=True)
            if not d.crosses(arc) and not d.clashes(box):
                d.rotation_arrow(c, radius, True, mid - half, mid + half)
                d.text((at[0], at[1] + 5), "\u03c9", style="italic", cls="omega")
                return
    raise ValueError("no room for the sense of rotation")


def _number(d: Drawing, names, alphas, outer: float) -> None:
    """Each cylinder's number beyond its barrel: on its line of stroke, or beside it where lines run on."""
    for name, alpha in zip(names, alphas):
        ux, uy = math.cos(alpha), math.sin(alpha)
        candidates = []
        for along in (outer + 26, outer + 14, outer + 40):
            for side in (0, 1, -1, 2, -2):
                x = ux * along - uy * side * 12
                y = uy * along + ux * side * 12
                candidates.append(((x, y + 5), "middle"))
        d.place(candidates, name, weight="bold", cls=f"cylinder cylinder-{name}")


def _data_lines(d: Drawing, lines) -> None:
    """The engine's data in a column to the right of the drawing."""
    x, y = d.box[2] + 36, d.box[1] + 40
    for text in lines:
        d.text((x, y), text, anchor="start", cls="data")
        y += 21


def _engine_data(variant) -> list[str]:
    return [f"stroke {_value(variant, 'S')}", f"connecting rods {_value(variant, 'l')}",
            f"{_value(variant, 'm')} per cylinder", f"speed {_value(variant, 'N')}"]


def radial_cylinders(variant) -> str:
    """Example 2.8: cylinders equally spaced round one crank, numbered clockwise from the top."""
    count = int(round(_si(variant, "ncyl")))
    alphas = [-math.pi / 2 + 2 * math.pi * i / count for i in range(count)]
    ratio = _si(variant, "l") / (_si(variant, "S") / 2)
    d = Drawing()
    names = [str(i + 1) for i in range(count)]
    outer = _cylinders(d, alphas, ratio, names)
    _number(d, names, alphas, outer)
    _data_lines(d, _engine_data(variant))
    fit_width(d, MIN_WIDTH)
    return d.svg(f"Radial engine with {count} cylinders on one crank")


def v_cylinders(variant) -> str:
    """Example 2.9: two cylinders at the V angle, one crank; the V angle marked."""
    v = _si(variant, "V")
    alphas = [-math.pi / 2 - v / 2, -math.pi / 2 + v / 2]
    ratio = _si(variant, "l") / (_si(variant, "S") / 2)
    d = Drawing()
    outer = _cylinders(d, alphas, ratio, ["1", "2"])
    radius = REACH + 78  # beyond the cylinder numbers
    a, b = on_circle((0, 0), radius, alphas[0]), on_circle((0, 0), radius, alphas[1])
    d.path(f"M {pts(a)} A {radius:.2f} {radius:.2f} 0 0 1 {pts(b)}", THIN, cls="v-angle")
    for alpha in alphas:  # the lines of stroke carried out to the angle's arc
        d.line(on_circle((0, 0), REACH + 40, alpha), on_circle((0, 0), radius + 6, alpha), THIN, dash="10 3 2 3")
    for tip, direction in ((a, alphas[0] - math.pi / 2), (b, alphas[1] + math.pi / 2)):
        d.arrowhead(tip, (math.cos(direction), math.sin(direction)), 7)
    d.extend(min(a[0], b[0]), -radius - 4, max(a[0], b[0]), -radius)
    d.text((0.0, -radius - 8), _value(variant, "V"), cls="v-label")
    _number(d, ["1", "2"], alphas, outer)
    _data_lines(d, _engine_data(variant))
    fit_width(d, MIN_WIDTH)
    return d.svg("V-twin engine: two cylinders on one crank")
