"""Givens read off a figure, as a student reads them, for templates whose figure is the given: the
curve's corners are taken from the drawing and turned into times and torques by the scale its tick
labels print, so the second working shares nothing with the code that drew it but the picture."""
from __future__ import annotations

import math
import re

from exgen.figures import figure_svg
from svg_helpers import SVG, elements, root


def _ticks(svg: str) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """(x, value) of the time axis's labels and (y, value) of the torque axis's, from their positions."""
    along, up = [], []
    for text in root(svg).iter(f"{SVG}text"):
        if "tick" not in text.get("class", "").split():
            continue
        value = float(text.text)
        if text.get("text-anchor") == "end":              # the torque axis: labels right-aligned left of it
            up.append((float(text.get("y")) - 4, value))
        else:
            along.append((float(text.get("x")), value))
    return along, up


def _scale(marks: list[tuple[float, float]]) -> tuple[float, float]:
    """Value per px and the px of value 0, from the first and last labels."""
    (p0, v0), (p1, v1) = marks[0], marks[-1]
    per = (v1 - v0) / (p1 - p0)
    return per, p0 - v0 / per


def torque_time_reading(v) -> dict:
    """tau_0, tau_p, t1, t2, t3, t4 and T (SI) read off the torque-time grid."""
    svg = figure_svg(v)
    (path,) = elements(svg, "torque-curve", "path")
    corners = [(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))]
    along, up = _ticks(svg)
    per_s, x0 = _scale(sorted(along))
    per_nm, y0 = _scale(sorted(up))
    times = [round((x - x0) * per_s, 2) for x, _ in corners]          # read to 0.01 s on a 0.1 s grid
    torques = [round((y - y0) * per_nm, 1) for _, y in corners]       # to 0.1 N·m on a 5 N·m grid
    return {"tau_0": torques[0], "tau_p": torques[2], "t1": times[1], "t2": times[2], "t3": times[3],
            "t4": times[4], "T": times[5]}


def _polygon_area(points: list[tuple[float, float]]) -> float:
    """|area| of a closed polygon, by the shoelace formula."""
    return abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))) / 2


def loop_area_reading(v) -> dict:
    """A turning-moment diagram on a grid, read as a student counts it: the size of a square from the grid's
    lines, what a square stands for from the axes' labels, and each loop's area (and its heights at the grid
    lines inside it) from the curve between successive crossings of the mean line."""
    svg = figure_svg(v)
    (path,) = elements(svg, "torque-curve", "path")
    points = [(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))]
    (mean,) = elements(svg, "mean-line")
    zero = float(mean.get("y1"))
    xs = sorted({round(float(g.get("x1")), 3) for g in elements(svg, "grid") if g.get("x1") == g.get("x2")})
    cell = (xs[-1] - xs[0]) / (len(xs) - 1)
    along, up = [], []
    for text in root(svg).iter(f"{SVG}text"):
        if "tick" in text.get("class", "").split():
            value = float(text.text.replace("−", "-").replace("+", ""))
            (up if text.get("text-anchor") == "end" else along).append(
                (float(text.get("y")) - 4 if text.get("text-anchor") == "end" else float(text.get("x")), value))

    def per_square(marks) -> float:      # the labels' difference over the squares counted between them
        (p0, v0), (p1, v1) = sorted(marks)[0], sorted(marks)[-1]
        return abs(v1 - v0) / round(abs(p1 - p0) / cell)

    loops, current = [], [points[0]]
    for point in points[1:]:
        current.append(point)
        if abs(point[1] - zero) < 1e-6:
            loops.append(current)
            current = [point]
    areas = [round(2 * _polygon_area(loop) / cell ** 2) / 2 for loop in loops]      # counted to the half square
    heights = [[round(abs(y - zero) / cell) for _, y in loop[1:-1]] for loop in loops]
    first = "above" if min(y for _, y in loops[0]) < zero - 1e-6 else "below"
    return {"areas": areas, "heights": heights, "first": first,
            "Ts": per_square(up), "As": math.radians(per_square(along))}


def crank_angles(v) -> list[float]:
    """The four cranks' angles (rad) read off the end view, as a protractor reads them: from the scale's zero
    (straight up, the line of stroke) clockwise, the direction the figure's arrow turns, to the nearest degree."""
    out = []
    for i in range(1, 5):
        (spoke,) = elements(figure_svg(v), f"spoke-{i}")
        dx = float(spoke.get("x2")) - float(spoke.get("x1"))
        dy = float(spoke.get("y2")) - float(spoke.get("y1"))
        out.append(math.radians(round(math.degrees(math.atan2(dx, -dy))) % 360))
    return out


# ---- linkages drawn to scale (§7.9 question 1, Problem 7.1) ----------------------------------------

def _centre(e) -> tuple[float, float]:
    return float(e.get("cx")), float(e.get("cy"))


def _joints(svg: str) -> dict[str, tuple[float, float]]:
    """Each lettered joint's centre (a pin's circle, or the dot of a point), by its letter: each label goes to
    the joint nearest it, the nearest pairs first, as a reader matches letters to pins."""
    spots = [_centre(c) for c in root(svg).iter(f"{SVG}circle") if set(c.get("class", "").split()) & {"pin", "point"}]
    spots = list(dict.fromkeys((round(x, 2), round(y, 2)) for x, y in spots))      # a ground pivot's pin drawn twice
    shift = {"start": 0.5, "middle": 0.0, "end": -0.5}       # a label's middle, from its anchor (8.5 px a letter)
    labels = [(t.text.split()[0], float(t.get("x")) + shift[t.get("text-anchor", "middle")] * 8.5 * len(t.text),
               float(t.get("y")) - 5) for t in elements(svg, "joint-label", "text")]
    pairs = sorted((math.dist((x, y), spot), letter, spot) for letter, x, y in labels for spot in spots)
    found: dict[str, tuple[float, float]] = {}
    for _, letter, spot in pairs:
        if letter not in found and spot not in found.values():
            found[letter] = spot
    return found


def _metres_per_px(svg: str) -> float:
    """The scale the one dimension sets: its printed length over the length of its line, the distance between
    its two extension lines' outer ends (each drawn the same 4 px past the dimension line)."""
    ends = [(float(e.get("x2")), float(e.get("y2"))) for e in elements(svg, "extension")]
    (label,) = elements(svg, "dim", "text")
    value, unit = label.text.split()
    return float(value) * {"mm": 1e-3, "m": 1.0}[unit] / math.dist(*ends)


def _world(point, origin) -> tuple[float, float]:
    """Page px (y down) to a frame with y up, from `origin`."""
    return point[0] - origin[0], origin[1] - point[1]


def _to_10_mm(length_m: float) -> float:
    return round(length_m * 100) / 100


def suspension_reading(v) -> dict:
    """The suspension's lengths (m) read off its drawing with the dimension AD as the scale, each rounded to a
    whole 10 mm as the sheet says; and which side of B -> D its pin C, and of B -> C its point P, is drawn on."""
    svg = figure_svg(v)
    joints = _joints(svg)
    scale = _metres_per_px(svg)
    length = {name: _to_10_mm(math.dist(joints[name[0]], joints[name[1]]) * scale)
              for name in ("AB", "BC", "DC", "CP", "BP")}
    w = {k: _world(p, joints["D"]) for k, p in joints.items()}

    def left_of(a, b, point) -> bool:
        return (b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0]) > 0

    return {**length, "C_left_of_BD": left_of(w["B"], w["D"], w["C"]), "P_left_of_BC": left_of(w["B"], w["C"], w["P"])}


def slider_crank_reading(v) -> dict:
    """The crank AB, the piston CP and the offset of the line of slide below A (m), read off the drawing with
    the dimension BC as the scale and rounded to a whole 10 mm."""
    svg = figure_svg(v)
    joints = _joints(svg)
    scale = _metres_per_px(svg)
    (slide,) = elements(svg, "line-of-slide")
    return {"AB": _to_10_mm(math.dist(joints["A"], joints["B"]) * scale),
            "CP": _to_10_mm(math.dist(joints["C"], joints["P"]) * scale),
            "offset": _to_10_mm((float(slide.get("y1")) - joints["A"][1]) * scale)}
