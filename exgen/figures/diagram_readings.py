"""Diagrams drawn to scale on a grid, for questions whose givens are read off the figure (the course
text's Example 3.2 gives its torque-time diagram as a drawing, Problem 3.1 its turning-moment diagram):
every corner of the curve lies on a grid intersection, the scales are printed on the axes, and no value is
written beside the curve.
"""
from __future__ import annotations

import math
import string

from .flywheels import TICK, need
from .svg import LINE, THIN, Drawing, num
from .values import choice, shown

GRID_W = 500.0       # the time axis, px
GRID_H = 240.0       # the torque axis, px
TIME_STEP = 0.1      # s between vertical grid lines
TORQUE_STEP = 5.0    # N·m between horizontal grid lines


def _label_every(count: int, most: int) -> int:
    """Label every k-th grid line so that at most `most` labels stand on an axis."""
    return next(k for k in (1, 2, 5, 10, 20) if count / k <= most)


def torque_time_grid(variant) -> str:
    """The torque a machine needs over one cycle, a trapezoidal pulse on a base torque, on a 0.1 s by 5 N·m
    grid with the axes' scales marked: the times and torques are read from it."""
    t = {name: need(variant, name).si for name in ("t1", "t2", "t3", "t4", "T")}
    tau_0, tau_p = need(variant, "tau_0").si, need(variant, "tau_p").si
    columns = round(t["T"] / TIME_STEP)
    rows = 5 * (int(tau_p // (5 * TORQUE_STEP)) + 1)     # up to the next full line above the peak
    sx, sy = GRID_W / columns, GRID_H / rows

    def at(time: float, torque: float) -> tuple[float, float]:
        return time / TIME_STEP * sx, -torque / TORQUE_STEP * sy

    drawing = Drawing()
    for i in range(columns + 1):    # every 0.5 s a full line, the 0.1 s between dotted
        major = i % 5 == 0
        drawing.line((i * sx, 0), (i * sx, -rows * sy), THIN * (0.7 if major else 0.4), dash="" if major else "1 2",
                     cls="grid")
    for j in range(rows + 1):       # every 25 N·m a full line, the 5 N·m between dotted
        major = j % 5 == 0
        drawing.line((0, -j * sy), (columns * sx, -j * sy), THIN * (0.7 if major else 0.4), dash="" if major else "1 2",
                     cls="grid")
    drawing.line((0, 0), (columns * sx + 30, 0), THIN, cls="axis")
    drawing.arrowhead((columns * sx + 30, 0), (1, 0))
    drawing.line((0, 0), (0, -rows * sy - 24), THIN, cls="axis")
    drawing.arrowhead((0, -rows * sy - 24), (0, -1))
    every = _label_every(columns, 12)
    for i in range(0, columns + 1, every):
        drawing.text((i * sx, 18), f"{i * TIME_STEP:.1f}".rstrip("0").rstrip("."), size=TICK, cls="tick")
    drawing.text((columns * sx / 2, 38), "time t (s), grid 0.1 s", cls="axis-title")
    every = 5
    for j in range(0, rows + 1, every):
        drawing.text((-6, -j * sy + 4), f"{j * TORQUE_STEP:g}", anchor="end", size=TICK, cls="tick")
    drawing.text((6, -rows * sy - 14), "torque τ (N·m), grid 5 N·m", anchor="start", cls="axis-title")
    points = [(0.0, tau_0), (t["t1"], tau_0), (t["t2"], tau_p), (t["t3"], tau_p), (t["t4"], tau_0), (t["T"], tau_0)]
    drawing.path("M " + " L ".join(f"{num(a)},{num(b)}" for a, b in (at(*p) for p in points)), LINE * 1.4,
                 cls="torque-curve")
    return drawing.svg("Torque required by the machine over one cycle, to scale on a grid")


# ---- Problem 3.1: a turning-moment diagram's loops on a grid ------------------------------------

LOOP_GRID_W = 560.0    # the crank-angle axis, px
LOOP_CELL_MAX = 11.0   # px per square at most


def loop_grid(variant) -> str:
    """A multi-cylinder engine's turning moment over one cycle about the mean resistance line, on a grid
    whose squares' torque and crank angle the axes mark: the curve goes straight between grid crossings, the
    crossings are lettered above the grid, and no area is written: the loops are counted in squares."""
    from ..mechanics import grid_loops

    areas, i = [], 1
    while shown(variant, f"a{i}") is not None:
        areas.append(round(need(variant, f"a{i}").si))
        i += 1
    columns = round(need(variant, "columns").si)
    torque = need(variant, "Ts").si
    angle = math.degrees(need(variant, "cycle").si) / columns      # the θ axis spans the cycle
    above = choice(variant, "first", "above") == "above"
    widths = grid_loops.widths(areas, columns)
    profiles = [grid_loops.heights(max(a, w - 1), w) for a, w in zip(areas, widths)]
    ups = [above == (k % 2 == 0) for k in range(len(areas))]
    # a square clear of the highest and lowest loop, and at least to the full lines ±5 squares, which are labelled
    top = max([5] + [h + 1 for p, up in zip(profiles, ups) if up for h in p])
    bottom = max([5] + [h + 1 for p, up in zip(profiles, ups) if not up for h in p])
    cell = min(LOOP_CELL_MAX, LOOP_GRID_W / columns)
    major = columns // 12 if columns % 12 == 0 else 5     # a full line every 30° (or 60°) of the cycle

    drawing = Drawing()
    for i in range(columns + 1):
        full = i % major == 0
        drawing.line((i * cell, bottom * cell), (i * cell, -top * cell), THIN * (0.7 if full else 0.4),
                     dash="" if full else "1 2", cls="grid")
    drawing.extend(0, -top * cell, columns * cell, bottom * cell)
    for j in range(-top, bottom + 1):
        full = j % 5 == 0
        drawing.line((0, j * cell), (columns * cell, j * cell), THIN * (0.7 if full else 0.4),
                     dash="" if full else "1 2", cls="grid")
    drawing.line((0, 0), (columns * cell + 26, 0), THIN * 1.4, dash="6 4", cls="mean-line")
    drawing.text((columns * cell + 30, 4), "mean resistance line", anchor="start", size=TICK)
    base = bottom * cell
    for i in range(0, columns + 1, major * (2 if columns // major > 8 else 1)):
        drawing.text((i * cell, base + 16), f"{i * angle:g}", size=TICK, cls="tick")
    drawing.text((columns * cell / 2, base + 34), f"crank angle θ (°), grid {angle:g}°", cls="axis-title")
    for j in range(-(top // 5) * 5, bottom + 1, 5):
        drawing.text((-5, j * cell + 4), f"{-j * torque:+g}".replace("+0", "0").replace("-", "−"),
                     anchor="end", size=TICK, cls="tick")
    drawing.text((0, -top * cell - 24), f"torque about the mean line (N·m), grid {torque:g} N·m", anchor="start",
                 cls="axis-title")
    x, path = 0, ["M 0,0"]
    letters = string.ascii_uppercase
    for k, (profile, up) in enumerate(zip(profiles, ups)):
        sign = -1 if up else 1                       # screen y grows downward
        for h in (*profile, 0):
            x += 1
            path.append(f"L {num(x * cell)},{num(sign * h * cell)}")
        _crossing(drawing, (x - len(profile) - 1) * cell, letters[k], -top * cell)
    _crossing(drawing, x * cell, letters[len(profiles)], -top * cell)
    drawing.path(" ".join(path), LINE * 1.4, cls="torque-curve")
    return drawing.svg("Turning-moment diagram on a grid: the loops between the torque curve and the mean "
                       "resistance line, to be counted in squares")


def _crossing(drawing: Drawing, x: float, letter: str, top: float) -> None:
    """A crossing marked by a dot on the mean line and lettered above the grid, over its grid line (a letter
    inside the grid would sit on its lines)."""
    drawing.circle((x, 0), 2.2, fill="black", cls="crossing-dot")
    drawing.text((x, top - 6), letter, weight="bold", size=TICK, cls="crossing")
