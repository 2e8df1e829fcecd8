"""Flywheel figures: loops drawn with areas in proportion to the data, torque-time drawn to scale."""
import math
import re

import pytest

from exgen.figures import figure_svg
from exgen.figures.flywheels import loop_diagram, torque_time
from exgen.figures.svg import text_box
from exgen.solve.variant import make_variant
from svg_helpers import elements, root, texts, variant_of

SVG = "{http://www.w3.org/2000/svg}"
EXAMPLE_3_1 = dict(a1=295, a2=685, a3=40, a4=340, a5=960, a6=270, first="above")


def _curve(svg: str) -> list[tuple[float, float]]:
    (path,) = elements(svg, "torque-curve", "path")
    return [(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))]


def _lobes(points):
    """Signed areas (up positive) of the stretches between returns to the mean line y = 0."""
    areas, area = [], 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        area += (x1 - x0) * -(y0 + y1) / 2
        if y1 == 0:
            areas.append(area)
            area = 0.0
    return areas


@pytest.mark.parametrize("template_id, count", [("flywheels.speed_fluctuation", 6), ("flywheels.flywheel_rim", 9)])
@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_loop_areas_are_in_proportion_to_the_data(bank, template_id, count, seed):
    variant = make_variant(bank.get(template_id), seed)
    lobes = _lobes(_curve(loop_diagram(variant)))
    data = [variant.param(f"a{i}").si for i in range(1, count + 1)]
    sign = 1 if variant.param("first").exact == "above" else -1
    assert len(lobes) == count
    for i, (lobe, area) in enumerate(zip(lobes, data)):
        assert lobe * sign * (-1) ** i > 0                     # alternately above and below, from the first
        assert abs(lobe) / abs(lobes[0]) == pytest.approx(area / data[0], rel=2e-3)


def test_example_3_1_labels(bank):
    variant = variant_of(bank, "flywheels.speed_fluctuation", **EXAMPLE_3_1)
    labels = texts(loop_diagram(variant))
    for expected in ("295 mm²", "685 mm²", "40 mm²", "340 mm²", "960 mm²", "270 mm²", "mean torque"):
        assert expected in labels
    assert set("ABCDEFG") <= set(labels)


def test_crossing_letters_sit_on_the_empty_side(bank):
    svg = loop_diagram(variant_of(bank, "flywheels.speed_fluctuation", **EXAMPLE_3_1))
    letters = {"".join(t.itertext()): float(t.get("y")) for t in root(svg).iter(f"{SVG}text")
               if t.get("class") == "crossing"}
    # loop 1 is above, so A's letter is below the line; B starts loop 2, below, so B's letter is above
    assert letters["A"] > 0 and letters["B"] < 0 and letters["C"] > 0 and letters["G"] > 0


def test_torque_time_is_drawn_to_scale(bank):
    variant = variant_of(bank, "flywheels.torque_time", tau_0=5.5, tau_p=44, t1=0.5, rise=0.2, dwell=0.2,
                         fall=0.2, idle=0.9)
    svg = torque_time(variant)
    points = _curve(svg)
    (x0, y0), (x1, _), (x2, y2), (x3, _), (x4, _), (x5, _) = points
    assert (x1 / x5, x2 / x5, x3 / x5, x4 / x5) == pytest.approx((0.25, 0.35, 0.45, 0.55), abs=1e-4)
    assert y2 / y0 == pytest.approx(44 / 5.5, rel=1e-3)
    labels = texts(svg)
    for expected in ("5.5 N·m", "44 N·m", "0.5 s", "0.7 s", "0.9 s", "1.1 s", "2 s", "mean torque = ?"):
        assert expected in labels
    (mean,) = elements(svg, "mean-line")
    assert float(mean.get("y1")) / y2 == pytest.approx(13.2 / 44, rel=1e-3)


@pytest.mark.parametrize("dwell", [0.0, 0.05])
def test_close_time_labels_do_not_touch(bank, dwell):
    variant = variant_of(bank, "flywheels.torque_time", t1=0.1, rise=0.1, dwell=dwell, fall=0.1, idle=2.0)
    ticks = [t for t in root(torque_time(variant)).iter(f"{SVG}text") if t.get("class") == "tick"]
    boxes = [(float(t.get("y")), text_box((float(t.get("x")), 0), t.text, "middle", 12)) for t in ticks]
    for i, (ya, a) in enumerate(boxes):
        for yb, b in boxes[i + 1:]:
            assert ya != yb or a.x1 <= b.x0 or b.x1 <= a.x0, (a, b)
    assert len(ticks) == (6 if dwell else 5)


def test_figures_are_deterministic(bank):
    for template_id in ("flywheels.speed_fluctuation", "flywheels.flywheel_rim", "flywheels.torque_time"):
        template = bank.get(template_id)
        assert figure_svg(make_variant(template, 11)) == figure_svg(make_variant(template, 11))


def test_turning_moment_curve_is_the_equation(bank):
    variant = variant_of(bank, "flywheels.turning_moment_equation", T0=14500, b=2300, c=-1900, n=2)
    svg = figure_svg(variant)
    points = _curve(svg)
    (mean,) = elements(svg, "mean-line")
    y0 = float(mean.get("y1"))
    ys = [y for _, y in points]
    swing = (max(ys) - min(ys)) / 2
    # the curve swings √(b² + c²) either side of T₀, drawn to the same scale as T₀ above the axis
    assert swing / abs(y0 - max(float(e.get("y1")) for e in elements(svg, "axis"))) == pytest.approx(
        2983.3 / 14500, rel=2e-3)
    assert (max(ys) + min(ys)) / 2 == pytest.approx(y0, abs=0.05)
    assert "T₀ = 14500 N·m" in texts(svg)


def test_fluctuating_resistance_is_drawn_dashed(bank):
    variant = variant_of(bank, "flywheels.fluctuating_resistance", T0=5000, b=1500, n=3, r=600)
    svg = figure_svg(variant)
    (resisting,) = elements(svg, "resisting-curve", "path")
    assert resisting.get("stroke-dasharray") and "resisting torque" in texts(svg)


@pytest.mark.parametrize("seed", range(6))
def test_a_torque_time_diagram_to_be_read_has_every_corner_on_its_grid(bank, seed):
    # the figure is the given: each corner of the pulse stands where a vertical and a horizontal grid line cross
    variant = make_variant(bank.get("flywheels.torque_time_reading"), seed)
    svg = figure_svg(variant)
    grid = elements(svg, "grid")
    xs = {round(float(g.get("x1")), 2) for g in grid if g.get("x1") == g.get("x2")}
    ys = {round(float(g.get("y1")), 2) for g in grid if g.get("y1") == g.get("y2")}
    for x, y in _curve(svg):
        assert min(abs(x - g) for g in xs) < 0.02 and min(abs(y - g) for g in ys) < 0.02, (x, y)


@pytest.mark.parametrize("seed", range(8))
def test_a_loop_diagram_to_be_read_has_every_corner_on_its_grid_and_no_area_written(bank, seed):
    # the figure is the given of the loops: each corner of the curve stands on a grid crossing, each loop's
    # area counts to the drawn area in whole squares, and the only numbers written are the axes' scales
    variant = make_variant(bank.get("flywheels.loop_area_reading"), seed)
    svg = figure_svg(variant)
    grid = elements(svg, "grid")
    xs = sorted({float(g.get("x1")) for g in grid if g.get("x1") == g.get("x2")})
    ys = {float(g.get("y1")) for g in grid if g.get("y1") == g.get("y2")}
    cell = (xs[-1] - xs[0]) / (len(xs) - 1)
    points = _curve(svg)
    for x, y in points:
        assert min(abs(x - g) for g in xs) < 0.02 and min(abs(y - g) for g in ys) < 0.02, (x, y)
    drawn = [abs(a) / cell ** 2 for a in _lobes(points)]
    # to the drawing's precision (its coordinates are written to 0.01 px)
    assert drawn == pytest.approx([float(variant.param(f"a{i}").text) for i in range(1, 10)], abs=0.01)
    torque, angle = variant.param("Ts").si, variant.param("As").si
    for label in root(svg).iter(f"{SVG}text"):
        kind = label.get("class", "")
        if kind == "tick":      # a multiple of 5 squares of torque, or of 4-6 squares of crank angle
            value = float(label.text.replace("−", "-"))
            assert value % (5 * torque) == 0 or round(value / math.degrees(angle)) % 4 == 0 or \
                round(value / math.degrees(angle)) % 5 == 0, label.text
        elif kind == "crossing":
            assert re.fullmatch("[A-J]", label.text)
        else:
            assert not re.search(r"\d", label.text.replace(variant.param("Ts").text, "").replace(
                f"{math.degrees(angle):g}", "")), label.text
