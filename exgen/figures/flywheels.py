"""Turning-moment and torque-time diagrams drawn to each variant's data (course text chapter 3).

A loop diagram (Example 3.1, Problem 3.1) is drawn with each loop's area in proportion to its
printed area: every loop is a half-sine lobe whose width grows with the square root of its area
(above a floor that leaves room for its label), its height making up the rest. A torque-time
diagram (Example 3.2) is drawn to scale on both axes. Unknowns carry "?".
"""
from __future__ import annotations

import math
import string

from .svg import FONT_SIZE, THIN, Drawing, num, text_box
from ..errors import ExgenError
from .values import Shown, choice, shown

LOOPS_W = 560.0      # px across all the loops
LOOP_MIN_W = 74.0    # no loop narrower: its label must clear its neighbours'
LOOP_MAX_H = 78.0    # px from the mean line to the highest crest
LABEL_GAP = 24.0     # px from the mean line to the nearest area label, clear of the crossing letters
SAMPLES = 24         # points per lobe
TICK = 12            # tick label font size


def need(variant, name: str) -> Shown:
    """A positive size the figure cannot be drawn without (a parameter, or the step it stands for)."""
    found = shown(variant, name)
    if found is None or not math.isfinite(found.si) or found.si <= 0:
        raise ExgenError(f"{variant.template.id}: the figure needs a positive {name!r} "
                         "(a parameter, or a step when it is the unknown)")
    return found


def _loop_areas(variant) -> list[Shown]:
    areas, i = [], 1
    while shown(variant, f"a{i}") is not None:
        areas.append(need(variant, f"a{i}"))
        i += 1
    return areas


def loop_diagram(variant) -> str:
    """Torque against crank angle: alternate loops above and below the mean line, their areas
    printed, the crossings lettered A, B, C, ... from the start of the cycle."""
    areas = _loop_areas(variant)
    above = choice(variant, "first", "above") == "above"
    roots = [math.sqrt(a.si) for a in areas]
    spare = LOOPS_W - LOOP_MIN_W * len(areas)
    widths = [LOOP_MIN_W + spare * r / sum(roots) for r in roots]
    # a half-sine lobe of width w and height h has area 2wh/π: one scale for every loop
    scale = min(LOOP_MAX_H * w / a.si for w, a in zip(widths, areas))
    heights = [a.si * scale / w for w, a in zip(widths, areas)]

    drawing = Drawing()
    base = LOOP_MAX_H + 40.0  # the θ axis lies this far below the mean line
    drawing.line((-10, base), (LOOPS_W + 40, base), THIN, cls="axis")
    drawing.arrowhead((LOOPS_W + 40, base), (1, 0))
    drawing.text((LOOPS_W + 40, base + 18), "θ", anchor="end", style="italic")
    drawing.line((0, base + 6), (0, -LOOP_MAX_H - 34), THIN, cls="axis")
    drawing.arrowhead((0, -LOOP_MAX_H - 34), (0, -1))
    drawing.text((-6, -LOOP_MAX_H - 24), "T", anchor="end", style="italic")
    drawing.line((0, 0), (LOOPS_W + 26, 0), THIN, dash="6 4", cls="mean-line")
    drawing.text((LOOPS_W + 30, 5), "mean torque", anchor="start")

    x, path, letters = 0.0, ["M 0,0"], string.ascii_uppercase
    for i, (w, h, area) in enumerate(zip(widths, heights, areas)):
        up = above == (i % 2 == 0)
        sign = -1.0 if up else 1.0  # screen y grows downward
        for k in range(1, SAMPLES + 1):
            t = k / SAMPLES
            path.append(f"L {num(x + w * t)},{num(sign * h * math.sin(math.pi * t))}")
        drawing.extend(x, min(0.0, sign * h), x + w, max(0.0, sign * h))
        label_y = sign * max(h + 8.0, LABEL_GAP) + (0.0 if up else FONT_SIZE * 0.8)
        drawing.text((x + w / 2, label_y), area.value_text, cls="area-label")
        _crossing_letter(drawing, x, letters[i], below=up)
        x += w
    _crossing_letter(drawing, x, letters[len(areas)], below=above)  # as at A: the cycle repeats
    drawing.path(" ".join(path), cls="torque-curve")
    return drawing.svg("Turning-moment diagram: loop areas between the torque curve and the mean torque line")


def _crossing_letter(drawing: Drawing, x: float, letter: str, below: bool) -> None:
    """A crossing's letter just right of it, on the side of the mean line the next loop leaves empty."""
    drawing.text((x + 4, 17 if below else -5), letter, anchor="start", weight="bold", cls="crossing")


# ---- Example 3.2: torque against time ----------------------------------------------------------

PLOT_W = 480.0
PLOT_H = 170.0


def torque_time(variant) -> str:
    """The torque a machine needs over one cycle, a trapezoidal pulse on a base torque, drawn to scale."""
    t = {name: need(variant, name) for name in ("t1", "t2", "t3", "t4", "T")}
    tau_0, tau_p = need(variant, "tau_0"), need(variant, "tau_p")
    mean = shown(variant, "tau_M")
    sx, sy = PLOT_W / t["T"].si, PLOT_H / tau_p.si

    def at(time: float, torque: float) -> tuple[float, float]:
        return time * sx, -torque * sy

    drawing = Drawing()
    drawing.line((0, 0), (PLOT_W + 40, 0), THIN, cls="axis")
    drawing.arrowhead((PLOT_W + 40, 0), (1, 0))
    drawing.text((PLOT_W + 40, 34), "t", anchor="end", style="italic")
    drawing.line((0, 0), (0, -PLOT_H - 34), THIN, cls="axis")
    drawing.arrowhead((0, -PLOT_H - 34), (0, -1))
    drawing.text((8, -PLOT_H - 26), "τ", anchor="start", style="italic")
    points = [(0.0, tau_0.si), (t["t1"].si, tau_0.si), (t["t2"].si, tau_p.si), (t["t3"].si, tau_p.si),
              (t["t4"].si, tau_0.si), (t["T"].si, tau_0.si)]
    drawing.path("M " + " L ".join(f"{num(a)},{num(b)}" for a, b in (at(*p) for p in points)), cls="torque-curve")
    for time in ("t1", "t2", "t3", "t4", "T"):
        x = t[time].si * sx
        drawing.line((x, 0), (x, 5), THIN)
        if time in ("t2", "t3", "t4", "T"):
            y = -(tau_p.si if time in ("t2", "t3") else tau_0.si) * sy
            drawing.line((x, 0), (x, y), THIN, dash="2 3", cls="guide")
    times = [n for n in ("t1", "t2", "t3", "t4", "T") if n != "t3" or t["t3"].si > t["t2"].si]  # no dwell: one mark
    depth = _time_labels(drawing, [(0.0, "0")] + [(t[n].si * sx, t[n].value_text) for n in times])
    drawing.text((PLOT_W / 2, depth + 22), "time", cls="axis-title")
    for torque in (tau_0, tau_p):
        y = -torque.si * sy
        drawing.line((-4, y), (0, y), THIN)
        drawing.text((-8, y + 5), torque.value_text, anchor="end")
    if mean is not None:
        y = -mean.si * sy
        drawing.line((0, y), (PLOT_W + 10, y), THIN, dash="6 4", cls="mean-line")
        drawing.text((PLOT_W + 14, y + 5), mean.label("mean torque"), anchor="start")
    return drawing.svg("Torque required by the machine over one cycle")


def _time_labels(drawing: Drawing, marks: list[tuple[float, str]]) -> float:
    """Tick labels under the time axis, each in the first row where it touches no other; returns
    the depth below the axis they take."""
    rows: list[float] = []
    for x, text in marks:
        box = text_box((x, 0), text, "middle", TICK)
        row = next((i for i, right in enumerate(rows) if box.x0 > right + 3), len(rows))
        if row == len(rows):
            rows.append(-math.inf)
        drawing.text((x, 20 + 14 * row), text, size=TICK, cls="tick")
        rows[row] = box.x1
    return 20 + 14 * (len(rows) - 1)


# ---- Problems 3.2 and 3.5: a turning moment given as an equation -------------------------------

CURVE_W, CURVE_H = 480.0, 150.0
LINE_W = 1.3
CURVE_POINTS = 241


def turning_moment_curve(variant) -> str:
    """The engine's turning moment over one revolution, drawn from its equation about the line T₀, with
    the fluctuating resisting torque dashed where the problem has one."""
    from ..mechanics.turning_moment import TrigTorque

    t0 = need(variant, "T0")
    n = int(round(need(variant, "n").si))
    b = shown(variant, "b")
    c = shown(variant, "c")
    engine = TrigTorque(t0.si, ((n, b.si if b else 0.0, c.si if c else 0.0),))
    r = shown(variant, "r")
    resisting = TrigTorque(t0.si, ((1, r.si, 0.0),)) if r is not None else None
    thetas = [2 * math.pi * k / (CURVE_POINTS - 1) for k in range(CURVE_POINTS)]
    curves = [engine] + ([resisting] if resisting else [])
    low = min(min(curve.at(t) for t in thetas) for curve in curves)
    high = max(max(curve.at(t) for t in thetas) for curve in curves)
    sy = CURVE_H / (high - min(low, 0.0) or 1.0)
    sx = CURVE_W / (2 * math.pi)

    def at(theta: float, torque: float) -> tuple[float, float]:
        return theta * sx, -torque * sy

    drawing = Drawing()
    base = -min(low, 0.0) * sy  # the θ axis at T = 0
    drawing.line((0, base), (CURVE_W + 30, base), THIN, cls="axis")
    drawing.arrowhead((CURVE_W + 30, base), (1, 0))
    drawing.text((CURVE_W + 30, base + 20), "θ", anchor="end", style="italic")
    drawing.line((0, base), (0, -high * sy - 30), THIN, cls="axis")
    drawing.arrowhead((0, -high * sy - 30), (0, -1))
    drawing.text((8, -high * sy - 22), "T", anchor="start", style="italic")
    for k in range(5):
        x = k * CURVE_W / 4
        drawing.line((x, base), (x, base + 5), THIN)
        drawing.text((x, base + 20), f"{90 * k}°", size=TICK, cls="tick")
    y0 = -t0.si * sy
    drawing.line((0, y0), (CURVE_W + 10, y0), THIN, dash="8 3 2 3", cls="mean-line")
    drawing.place([((-8, y0 + 5), "end")], t0.label("T₀"))
    drawing.path("M " + " L ".join(f"{num(a)},{num(b_)}" for a, b_ in (at(t, engine.at(t)) for t in thetas)),
                 cls="torque-curve")
    if resisting is not None:
        drawing.path("M " + " L ".join(f"{num(a)},{num(b_)}" for a, b_ in (at(t, resisting.at(t)) for t in thetas)),
                     THIN, dash="3 3", cls="resisting-curve")
    # a legend above the plot, clear of both curves
    top = -high * sy - 30
    entries = [("engine's turning moment", LINE_W, "")] + ([("resisting torque", THIN, "3 3")] if resisting else [])
    x = CURVE_W - 120
    for k, (name, width, dash) in enumerate(entries):
        y = top - 18 * (len(entries) - 1 - k)
        drawing.line((x, y - 4), (x + 28, y - 4), width, dash=dash, cls="legend")
        drawing.text((x + 34, y), name, anchor="start", cls="legend-label")
    return drawing.svg("The turning moment over one revolution" + (", with the fluctuating resisting torque dashed"
                                                                    if resisting is not None else ""))
