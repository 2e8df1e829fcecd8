"""Givens read off a figure, as a student reads them, for templates whose figure is the given: the
curve's corners are taken from the drawing and turned into times and torques by the scale its tick
labels print, so the second working shares nothing with the code that drew it but the picture."""
from __future__ import annotations

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
