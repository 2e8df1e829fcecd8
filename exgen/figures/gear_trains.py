"""Compound and reverted gear trains as side-view schematics (course text Figures 1.17, 1.18, 1.20, 1.21).

Shafts run across the figure as centre lines; each gear is a bar as tall as its pitch diameter,
drawn on its shaft; gears that mesh stand in one column with their bars touching at the pitch
line, and gears keyed to one shaft sit on one line. Pitch diameters and shaft spacings follow the
variant's data at one scale; data are labelled as printed, an unknown as "?".
"""
from __future__ import annotations

from dataclasses import dataclass

from .gears import fit_width
from .pulleys import CENTRE_DASH, need
from .svg import FONT_SIZE, LINE, THIN, Drawing, subscripted
from .values import choice, shown

FACE = 16.0        # px: a gear's face width
COLUMN = 170.0     # px between mesh columns (room for labels)
HEIGHT = 330.0     # px from the lowest to the highest gear
END = 70.0         # shaft beyond its outer gears
LABEL = FONT_SIZE
ROW = 17.0


@dataclass(frozen=True)
class Bar:
    """A gear seen side-on: on shaft `shaft`, in mesh column `column`, pitch radius `r` in metres."""

    shaft: str
    column: int
    r: float
    lines: tuple[str, ...]
    below: bool  # its labels go under its shaft line (the lower gear of a mesh), else above


def _draw(drawing: Drawing, levels: dict[str, float], spans: dict[str, tuple[float, float]], bars: list[Bar],
          scale: float) -> None:
    """Shafts as centre line and body, then the gears as bars with their labels beside them."""
    for name, y in levels.items():
        x0, x1 = spans[name]
        drawing.line((x0 - 12, y), (x1 + 12, y), THIN, dash=CENTRE_DASH, cls=f"shaft-centre {name}")
        drawing.line((x0, y), (x1, y), 2.4, cls=f"shaft {name}")
    for bar in bars:
        x, y, r = bar.column * COLUMN, levels[bar.shaft], bar.r * scale
        corners = [(x - FACE / 2, y - r), (x + FACE / 2, y - r), (x + FACE / 2, y + r), (x - FACE / 2, y + r)]
        drawing.polygon(corners, fill="white", width=LINE)
        lines = list(bar.lines)
        if bar.below:
            ys = [y + 6 + LABEL * 0.78 + i * ROW for i in range(len(lines))]
        else:
            ys = [y - 6 - LABEL * 0.24 - (len(lines) - 1 - i) * ROW for i in range(len(lines))]
        for i, (text, ty) in enumerate(zip(lines, ys)):
            drawing.text((x + FACE / 2 + 6, ty), text, anchor="start", weight="bold" if i == 0 else "")


def _vertical_dimension(drawing: Drawing, x: float, y0: float, y1: float, label: str) -> None:
    drawing.dimension((x, y0), (x, y1))
    drawing.text((x - 8, (y0 + y1) / 2 + 5), label, anchor="end", cls="label-C")


def compound_train(variant) -> str:
    """Example 1.7: gears 2-3, 4-5 and 6-7 in mesh; 3 with 4 and 5 with 6 on common shafts; four shafts in a plane."""
    inch = 0.0254
    d2, d4, d7 = (need(variant, n).si for n in ("d2", "d4", "d7"))
    d3, d5, d6 = (need(variant, n).si for n in ("d3", "d5", "d6"))
    total = (d2 + d3 + d4 + d5 + d6 + d7) / 2
    scale = HEIGHT / (total + (d2 + d7) / 2)
    levels = {"s2": 0.0}
    levels["s34"] = levels["s2"] - (d2 + d3) / 2 * scale
    levels["s56"] = levels["s34"] - (d4 + d5) / 2 * scale
    levels["s7"] = levels["s56"] - (d6 + d7) / 2 * scale

    def pitch(name):
        value = shown(variant, name)
        return f"Pd = {value.si * inch:g} teeth/in" if value is not None else ""  # as the statement writes it

    def teeth(name):
        return f"{subscripted(name)} = {shown(variant, name).value_text}"

    def dia(name):
        return shown(variant, name).label()

    speed = shown(variant, "N2")
    given = f"{speed.value_text} {choice(variant, 'sense2', '')}".strip() if speed else "driven"
    bars = [Bar("s2", 0, d2 / 2, ("Gear 2", teeth("t2"), pitch("P23"), given), True),
            Bar("s34", 0, d3 / 2, ("Gear 3", dia("d3")), False),
            Bar("s34", 1, d4 / 2, ("Gear 4", teeth("t4"), pitch("P45")), True),
            Bar("s56", 1, d5 / 2, ("Gear 5", dia("d5")), False),
            Bar("s56", 2, d6 / 2, ("Gear 6", dia("d6")), True),
            Bar("s7", 2, d7 / 2, ("Gear 7", teeth("t7"), pitch("P67"), "\u03c9\u2087 = ?"), False)]
    spans = {"s2": (-END, 0.0), "s34": (0.0, COLUMN), "s56": (COLUMN, 2 * COLUMN), "s7": (2 * COLUMN, 2 * COLUMN + END)}
    drawing = Drawing()
    _draw(drawing, levels, spans, bars, scale)
    _vertical_dimension(drawing, -END - 24, levels["s2"], levels["s7"], "C = ?")
    drawing.line((-END - 30, levels["s7"]), (2 * COLUMN - 24, levels["s7"]), THIN, dash=CENTRE_DASH)
    fit_width(drawing)
    return drawing.svg("Compound gear train: gears 2 to 7 on four shafts")


def reverted_train(variant) -> str:
    """Example 1.8: A and B in line, geared through a parallel shaft C; module m₁ for 1-2, m₂ for 3-4."""
    m1, m2 = need(variant, "m1").si, need(variant, "m2").si
    t1, t2, t3, t4 = (need(variant, n).si for n in ("t1", "t2", "t3", "t4"))
    centre = m1 * (t1 + t2) / 2
    scale = HEIGHT / (centre + m1 * t2 / 2 + max(m1 * t1, m2 * t4) / 2)
    levels = {"A": 0.0, "B": 0.0, "C": -centre * scale}
    gap = COLUMN / 2
    spans = {"A": (-END, gap - 10), "B": (gap + 10, COLUMN + END), "C": (-20.0, COLUMN + 20)}

    def teeth(name):
        return f"{subscripted(name)} = {shown(variant, name).value_text}"

    def module(name):
        return f"module {shown(variant, name).value_text}"

    speed = shown(variant, "NA")
    bars = [Bar("A", 0, m1 * t1 / 2, ("Gear 1", teeth("t1"), module("m1"), f"A turns at {speed.value_text}" if speed else ""), True),
            Bar("C", 0, m1 * t2 / 2, ("Gear 2", teeth("t2"), module("m1")), False),
            Bar("C", 1, m2 * t3 / 2, ("Gear 3", teeth("t3"), module("m2")), False),
            Bar("B", 1, m2 * t4 / 2, ("Gear 4", teeth("t4"), module("m2"), "B turns at ?"), True)]
    drawing = Drawing()
    _draw(drawing, levels, spans, bars, scale)
    _vertical_dimension(drawing, -END - 40, levels["A"], levels["C"], "A to C = ?")
    for name, x, anchor in (("A", -END - 18, "end"), ("B", COLUMN + END + 18, "start"), ("C", COLUMN + 38, "start")):
        y = levels[name]
        drawing.place([((x, y + 5), anchor), ((x, y - 6), anchor), ((x, y + 20), anchor)], name, weight="bold",
                      cls=f"shaft-name {name}")
    drawing.line((-END - 46, levels["C"]), (-32.0, levels["C"]), THIN, dash=CENTRE_DASH)
    fit_width(drawing)
    return drawing.svg("Reverted gear train: shafts A and B in line, geared through C")
