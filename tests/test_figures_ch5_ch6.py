"""Gyroscope and vibration figures: one per template, deterministic, drawn to the variant (the turn's
side, the rotor's sense, the stated view, the decay's cycles, the shaft's steps), unknowns marked "?",
no answer printed; the key's vector sketch agrees with the worked solution's directions."""
import math
import re

import pytest

from exgen.figures import figure_svg, key_figure_svgs
from exgen.figures.gyro_vehicles import AXES, WORDS
from exgen.solve.variant import make_variant
from svg_helpers import SVG, circles, elements, root, texts, variant_of


def chapter_5_and_6(bank):
    return [t for t in bank if t.chapter in (5, 6)]


def test_every_template_has_a_figure_drawn_the_same_each_time(bank):
    templates = chapter_5_and_6(bank)
    assert len(templates) >= 19
    for template in templates:
        assert template.figure, template.id
        variant = make_variant(template, 3)
        assert figure_svg(variant) == figure_svg(make_variant(template, 3))
        assert root(figure_svg(variant)).tag == f"{SVG}svg"


@pytest.mark.parametrize("seed", range(6))
def test_no_figure_prints_an_answer(bank, seed):
    for template in chapter_5_and_6(bank):
        variant = make_variant(template, seed)
        shown = " | ".join(texts(figure_svg(variant)))
        for part_id, answer in variant.answers.items():
            if isinstance(answer.value, float):
                assert answer.text not in shown, (template.id, seed, part_id, answer.text)


def _centre_of_turn(svg):
    (centre,) = circles(svg, "centre")
    return float(centre.get("cx"))


@pytest.mark.parametrize("template_id", ["gyroscopes.vehicle_rotor_springs", "gyroscopes.aircraft_turning",
                                         "gyroscopes.ship_turbine", "gyroscopes.car_wheel_reactions"])
def test_the_path_curves_the_way_the_vehicle_turns(bank, template_id):
    for turn in ("left", "right"):
        svg = figure_svg(variant_of(bank, template_id, turn=turn))
        assert (_centre_of_turn(svg) > 0) == (turn == "right"), (template_id, turn)
        assert f"turning {turn}" in root(svg).find(f"{SVG}title").text


def _rotation_sweeps(svg):
    """The sweep flag of each rotation arrow: 1 is clockwise on the page."""
    return [int(re.search(r"A \S+ \S+ 0 [01] ([01])", p.get("d")).group(1)) for p in elements(svg, "rotation", "path")]


@pytest.mark.parametrize("template_id, view", [("gyroscopes.ship_turbine", "stern"), ("gyroscopes.ship_turbine", "bow"),
                                               ("gyroscopes.aircraft_turning", "rear"),
                                               ("gyroscopes.aircraft_turning", "front")])
def test_the_rotor_turns_as_stated_seen_from_the_stated_side(bank, template_id, view):
    for sense in ("clockwise", "counter-clockwise"):
        svg = figure_svg(variant_of(bank, template_id, sense=sense, view=view))
        assert _rotation_sweeps(svg) == [1 if sense == "clockwise" else 0]
        assert any(f"seen from the {view}" in t for t in texts(svg))


def test_the_motorcycle_leans_at_its_unknown_angle(bank):
    for template_id in ("gyroscopes.motorcycle_banking", "gyroscopes.motorcycle_heel"):
        svg = figure_svg(make_variant(bank.get(template_id), 2))
        assert "θ = ?" in texts(svg)


def test_the_decay_plot_marks_the_amplitudes_and_the_cycles_between_them(bank):
    for n in (1, 3, 5):
        svg = figure_svg(variant_of(bank, "vibration.log_decrement", n=n, a1=40, a_r=5))
        labels = texts(svg)
        last = "a" + str(n + 1).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
        assert "a₁ = 40 mm" in labels and f"{last} = 5 mm" in labels
        assert f"{n} cycle{'s' if n > 1 else ''}" in labels
        (envelope,) = elements(svg, "envelope", "path")
        points = [tuple(map(float, p.split())) for p in re.findall(r"[-\d.]+ [-\d.]+", envelope.get("d"))]
        axis_y = max(y for _, y in points) + 1  # the envelope decays towards the axis, never below it
        heights = [axis_y - y for _, y in points]
        assert heights == sorted(heights, reverse=True)


def test_the_stepped_shaft_is_drawn_to_its_lengths_with_the_unknown_diameter_marked(bank):
    variant = variant_of(bank, "vibration.stepped_shaft", l1=0.2, l2=0.4, l3=0.6)
    svg = figure_svg(variant)
    labels = texts(svg)
    assert "d₃ = ?" in labels and "l₁ = 0.2 m" in labels and "l₃ = 0.6 m" in labels
    xs = sorted({round(float(e.get("x1")), 1) for e in elements(svg, "extension")})
    widths = [b - a for a, b in zip(xs, xs[1:])]
    assert widths == pytest.approx([w / 1.2 * 420 for w in (0.2, 0.4, 0.6)], abs=0.2)


def test_springs_are_drawn_in_series_or_in_parallel(bank):
    for arrangement, count in (("series", 2), ("parallel", 2)):
        svg = figure_svg(variant_of(bank, "vibration.spring_mass", arrangement=arrangement))
        springs = elements(svg, "spring", "path")
        xs = {round(float(re.match(r"M ([-\d.]+)", s.get("d")).group(1))) for s in springs}
        assert len(springs) == count and len(xs) == (1 if arrangement == "series" else 2)


@pytest.mark.parametrize("seed", range(8))
def test_the_key_sketch_draws_the_solution_s_vectors(bank, seed):
    for template in chapter_5_and_6(bank):
        if not template.key_figures:
            continue
        variant = make_variant(template, seed)
        (name, svg), = key_figure_svgs(variant)
        arrows = elements(svg, "vector")
        assert len(arrows) == 3
        for line, step in zip(arrows, ("spin_vector", "precession_vector", "couple_vector")):
            axis, sign = WORDS[variant.step(step).value]
            dx, dy = float(line.get("x2")) - float(line.get("x1")), float(line.get("y2")) - float(line.get("y1"))
            ux, uy = AXES[axis]
            assert (dx * ux + dy * uy) * sign > 0 and abs(dx * uy - dy * ux) < 1e-6 * math.hypot(dx, dy) + 0.02


@pytest.mark.parametrize("seed", range(8))
def test_the_rail_cars_wheel_radius_is_dimensioned_from_rail_to_axle(bank, seed):
    """'r = 370 mm' stood beside the axle with nothing measured; the radius is a dimension line from the rail
    head up to the axle, beside the label."""
    from exgen.figures import figure_svg
    from exgen.figures.checks import labels, strokes

    variant = make_variant(bank.get("gyroscopes.rail_car_limiting_speed"), seed)
    svg = figure_svg(variant)
    scale = 200 / variant.si["x"]
    label = next(l for l in labels(svg) if l.text.startswith("r = "))
    segments, _ = strokes(svg)
    near = [(p, q) for p, q in segments if abs(p[0] - q[0]) < 1e-6
            and abs(abs(p[1] - q[1]) - variant.si["r"] * scale) < 0.5
            and min(abs(p[0] - label.box.x0), abs(p[0] - label.box.x1)) < 30]
    assert near, (seed, label.text)
