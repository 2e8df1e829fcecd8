"""Balancing figures: valid SVG, deterministic, drawn to the data (positions, angles, conventions),
unknowns marked "?", and never an answer printed."""
import math
import re

import pytest

from exgen import units
from exgen.figures import figure_svg
from exgen.solve.variant import make_variant
from svg_helpers import SVG, elements, root, texts, variant_of

UP_CLOCKWISE = (-90.0, 1)          # 0° straight up, angles growing clockwise on the page
RIGHT_COUNTER = (0.0, -1)          # 0° to the right, angles growing counter-clockwise


def balancing_templates(bank):
    return [t for t in bank if t.id.startswith("balancing.")]










def spoke_angle(svg, name):
    """The page angle (degrees, y down) of a spoke, from the centre to its tip."""
    (line,) = elements(svg, f"spoke-{name}")
    x1, y1, x2, y2 = (float(line.get(k)) for k in ("x1", "y1", "x2", "y2"))
    return math.degrees(math.atan2(y2 - y1, x2 - x1))


def same_direction(a, b, tol=0.6):
    gap = (a - b) % 360
    return min(gap, 360 - gap) <= tol


def page_angle(convention, theta_deg):
    zero, sense = convention
    return zero + sense * theta_deg


def test_every_balancing_template_has_a_figure(bank):
    assert all(t.figure for t in balancing_templates(bank))


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_figures_are_valid_svg_with_a_viewbox_and_title(bank, seed):
    for template in balancing_templates(bank):
        svg = figure_svg(make_variant(template, seed))
        element = root(svg)
        assert element.tag == f"{SVG}svg", template.id
        _, _, width, height = map(float, element.get("viewBox").split())
        assert width >= 600 and height > 100, template.id
        assert element.find(f"{SVG}title").text, template.id


def test_same_variant_same_bytes_other_variants_other_figures(bank):
    for template in balancing_templates(bank):
        first = figure_svg(make_variant(template, 11))
        assert first == figure_svg(make_variant(template, 11)), template.id
        others = {figure_svg(make_variant(template, seed)) for seed in range(12, 16)}
        assert len(others | {first}) > 1, template.id


@pytest.mark.parametrize("theta2, theta3", [(90, 180), (40, 320), (160, 200)])
def test_static_disc_spokes_follow_the_angles_counter_clockwise_from_mass_1(bank, theta2, theta3):
    svg = figure_svg(variant_of(bank, "balancing.static_balance", theta2=theta2, theta3=theta3))
    assert same_direction(spoke_angle(svg, "1"), page_angle(RIGHT_COUNTER, 0))
    assert same_direction(spoke_angle(svg, "2"), page_angle(RIGHT_COUNTER, theta2))
    assert same_direction(spoke_angle(svg, "3"), page_angle(RIGHT_COUNTER, theta3))
    assert f"2: {theta2}\u00b0" in texts(svg) and f"3: {theta3}\u00b0" in texts(svg)


@pytest.mark.parametrize("angles", [(0, 90, 180), (45, 200, 330), (120, 10, 265)])
def test_two_plane_spokes_are_clockwise_from_the_upward_vertical(bank, angles):
    values = {f"theta{i}": a for i, a in enumerate(angles, start=1)}
    svg = figure_svg(variant_of(bank, "balancing.two_plane_balance", **values))
    for i, a in enumerate(angles, start=1):
        assert same_direction(spoke_angle(svg, str(i)), page_angle(UP_CLOCKWISE, a)), (i, a)
    if 0 in angles:  # the 0° line is named by the mass on it ...
        assert "0\u00b0" not in texts(svg) and "1: 0\u00b0" in texts(svg)
    else:  # ... or labelled
        assert "0\u00b0" in texts(svg)


def test_two_plane_positions_are_to_scale_from_the_left_end(bank):
    svg = figure_svg(variant_of(bank, "balancing.two_plane_balance", z1=0.1, zP=0.5, z2=1.0, z3=2.0, zQ=2.2))
    xs = {name: float(elements(svg, f"plane-{name}")[0].get("x1")) for name in ("1", "P", "2", "3", "Q")}
    scale = (xs["Q"] - xs["1"]) / (2.2 - 0.1)
    for name, z in (("P", 0.5), ("2", 1.0), ("3", 2.0)):
        assert xs[name] - xs["1"] == pytest.approx(scale * (z - 0.1), abs=0.02)
    assert {"0.1 m", "0.5 m", "2.2 m", "P (ref.)"} <= set(texts(svg))


def test_bearings_figure_order_scale_and_angles(bank):
    v = variant_of(bank, "balancing.bearing_reactions", a=0.2, b=0.5, c=0.3, e=0.3, thetaB=60, thetaC=270)
    svg = figure_svg(v)
    xs = [sum(float(elements(svg, f"plane-{n}")[0].get(k)) for k in ("x1", "x2")) / 2 for n in "AXBYC"]
    assert xs == sorted(xs)
    gaps = [b - a for a, b in zip(xs, xs[1:])]
    assert gaps[0] / gaps[1] == pytest.approx(0.2 / 0.5, abs=0.01) and gaps[2] / gaps[3] == pytest.approx(1.0, abs=0.01)
    assert same_direction(spoke_angle(svg, "B"), page_angle(RIGHT_COUNTER, 60))
    assert same_direction(spoke_angle(svg, "C"), page_angle(RIGHT_COUNTER, 270))
    assert {"X (ref.)", "Y", "0.2 m", "0.5 m"} <= set(texts(svg))


def test_position_figure_marks_the_unknowns(bank):
    svg = figure_svg(variant_of(bank, "balancing.complete_balance_position", thetaA=130))
    assert same_direction(spoke_angle(svg, "A"), page_angle(RIGHT_COUNTER, 130))
    assert same_direction(spoke_angle(svg, "C"), page_angle(RIGHT_COUNTER, 0))
    assert not elements(svg, "spoke-B") and not elements(svg, "spoke-D")  # their angles are asked
    assert {"x = ?", "B: angle ?", "D: angle ?", "m = ?", "B (ref.)"} <= set(texts(svg))
    (d_plane,) = elements(svg, "plane-D")
    assert d_plane.get("stroke-dasharray")  # D's plane is not to scale


def test_masses_figure_marks_the_unknowns(bank):
    svg = figure_svg(variant_of(bank, "balancing.complete_balance_masses", thetaA=190, thetaC=100))
    assert same_direction(spoke_angle(svg, "A"), page_angle(RIGHT_COUNTER, 190))
    assert same_direction(spoke_angle(svg, "C"), page_angle(RIGHT_COUNTER, 100))
    assert not elements(svg, "spoke-D")
    assert {"A to D = ?", "D: angle ?", "A (ref.)"} <= set(texts(svg))
    assert texts(svg).count("m = ?") == 2


@pytest.mark.parametrize("angles", [(100, 30, 300, 200), (0, 180, 90, 270)])
def test_inline_cranks_at_their_angles_from_the_line_of_stroke(bank, angles):
    values = {f"theta{i}": a for i, a in enumerate(angles, start=1)}
    svg = figure_svg(variant_of(bank, "balancing.inline_engine_unbalance", **values))
    for i, a in enumerate(angles, start=1):
        assert same_direction(spoke_angle(svg, str(i)), page_angle(UP_CLOCKWISE, a))
    assert {"1", "2", "3", "4", "centre plane (ref.)"} <= set(texts(svg))


@pytest.mark.parametrize("order, strokes", [("1-3-4-2", 4), ("1-5-3-6-2-4", 4), ("1-2-4-5-3", 2)])
def test_firing_figure_numbers_the_cylinders_and_gives_the_order(bank, order, strokes):
    svg = figure_svg(variant_of(bank, "balancing.inline_engine_firing", firing=order, strokes=strokes))
    count = len(order.split("-"))
    assert {str(i) for i in range(1, count + 1)} <= set(texts(svg))
    assert f"firing order {order}, {strokes}-stroke: crank angles ?" in texts(svg)
    assert len(elements(svg, "plane")) == count
    assert not elements(svg, "spoke")  # the crank angles are part of the solution


def test_primary_balance_figure_draws_the_outer_cranks_only(bank):
    svg = figure_svg(variant_of(bank, "balancing.inline_primary_balance", phi=120))
    assert same_direction(spoke_angle(svg, "A"), page_angle(UP_CLOCKWISE, 0))
    assert same_direction(spoke_angle(svg, "D"), page_angle(UP_CLOCKWISE, 120))
    assert not elements(svg, "spoke-B") and not elements(svg, "spoke-C")
    assert {"B: angle ?", "C: angle ?", "B (ref.)"} <= set(texts(svg))


def _stroke_line_angles(svg):
    out = []
    for line in elements(svg, "stroke-line"):
        x1, y1, x2, y2 = (float(line.get(k)) for k in ("x1", "y1", "x2", "y2"))
        out.append(math.degrees(math.atan2(y2 - y1, x2 - x1)) % 360)
    return out


@pytest.mark.parametrize("count", [3, 5, 9])
def test_radial_cylinders_are_equally_spaced_from_the_top(bank, count):
    svg = figure_svg(variant_of(bank, "balancing.radial_engine", ncyl=count))
    angles = _stroke_line_angles(svg)
    expected = [(-90 + 360 * i / count) % 360 for i in range(count)]
    assert len(angles) == count and all(same_direction(a, e, 0.05) for a, e in zip(angles, expected))
    assert {str(i) for i in range(1, count + 1)} <= set(texts(svg))


@pytest.mark.parametrize("v", [40, 60, 90, 120])
def test_v_engine_lines_of_stroke_are_the_v_angle_apart(bank, v):
    svg = figure_svg(variant_of(bank, "balancing.v_engine", V=v))
    a, b = _stroke_line_angles(svg)
    assert same_direction(b - a, v, 0.05) and same_direction((a + b) / 2, 270, 0.05)  # symmetric about the vertical
    assert f"{v}\u00b0" in texts(svg)


def _numbers(strings):
    return {m for s in strings for m in re.findall(r"\d+(?:\.\d+)?", s)}


@pytest.mark.parametrize("seed", range(6))
def test_no_answer_is_printed_on_a_figure(bank, seed):
    for template in balancing_templates(bank):
        variant = make_variant(template, seed)
        svg = figure_svg(variant)
        # a degree scale's numbers are what an angle is read against, not an answer written down
        scale = [t.text for t in elements(svg, "scale-label", "text")]
        shown = [t for t in texts(svg) if t not in scale]
        printed = _numbers([variant.statement, *variant.asks.values()])
        on_figure = _numbers(shown)
        for answer in variant.answers.values():
            value = answer.value
            candidates = []
            if hasattr(value, "magnitude"):
                candidates = [value.magnitude, value.angle_deg]
            elif isinstance(value, float) and value != 0.0:
                candidates = [value]
            elif isinstance(value, str):
                assert value not in shown, (template.id, seed, value)
            for x in candidates:
                for sig in (3, 4):
                    number = units.format_number(x, sig)
                    assert number in printed or number not in on_figure, (template.id, seed, answer.part.id, number)


@pytest.mark.parametrize("seed", range(8))
def test_cranks_to_be_read_stand_on_their_scale_s_divisions_and_no_angle_is_written(bank, seed):
    # the end view is the given of the crank angles: each crank points at its angle on the degree scale (0°
    # straight up, clockwise), that angle is one of the scale's long ticks, and the only numbers written are
    # the scale's own (every 30°) and the pitch
    variant = make_variant(bank.get("balancing.inline_engine_angles_read"), seed)
    svg = figure_svg(variant)
    cx, cy = _end_view_centre(svg)
    marks = elements(svg, "scale-tick")
    widest = max(float(t.get("stroke-width")) for t in marks)
    long_ticks = {round(math.degrees(math.atan2(float(t.get("x1")) - cx, cy - float(t.get("y1"))))) % 360
                  for t in marks if float(t.get("stroke-width")) == widest}
    assert long_ticks == set(range(0, 360, 10))
    for i in range(1, 5):
        drawn = round(spoke_angle(svg, str(i)) + 90) % 360
        assert drawn == round(variant.param(f"theta{i}").si * 180 / math.pi) % 360 and drawn in long_ticks
    numbers = [t for t in texts(svg) if re.search(r"\d", t)]
    allowed = {str(k) for k in range(30, 360, 30)} | {"1", "2", "3", "4", variant.param("a").text + " mm",
                                                     "0° (line of stroke)",
                                                     "angles from crank 1 in the direction of rotation, scale in degrees"}
    assert set(numbers) <= allowed, set(numbers) - allowed


def _end_view_centre(svg):
    (scale,) = elements(svg, "scale", "circle")
    return float(scale.get("cx")), float(scale.get("cy"))
