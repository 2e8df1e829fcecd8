"""Diagrams drawn to scale on a grid, for questions whose givens are read off the figure (the course
text's Example 3.2 gives its torque-time diagram as a drawing): every corner of the curve lies on a grid
intersection, the scales are printed on the axes, and no value is written beside the curve.
"""
from __future__ import annotations

from .flywheels import TICK, need
from .svg import LINE, THIN, Drawing, num

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
