"""Figures: valid SVG, deterministic, drawn to the data, never printing an answer."""
import dataclasses
import math
import re

import pytest

from exgen import units
from exgen.errors import ExgenError
from exgen.figures import figure_svg
from exgen.figures.belts import belt_drive, compound_drive
from exgen.figures.metrics import FAMILY
from exgen.figures.svg import num, subscripted
from exgen.figures.tangents import belt_loop
from exgen.load.template import ParamSpec
from exgen.solve.variant import make_variant
from svg_helpers import SVG, circles, root, texts, variant_of

DRIVE = ParamSpec("drive", label="belt arrangement", choices=("open", "crossed"))










def figure_templates(bank):
    return [t for t in bank if t.figure]


@pytest.fixture(scope="module")
def flat(bank):
    return variant_of(bank, "belts.flat_belt_power", d1=400, d2=1000, X=2.5, N1=220)


def test_every_figure_template_gives_valid_svg_with_a_viewbox(bank):
    assert figure_templates(bank), "the bank has no template with a figure"
    for template in figure_templates(bank):
        for seed in range(4):
            svg = figure_svg(make_variant(template, seed))
            top = root(svg)
            assert top.tag == f"{SVG}svg"
            x0, y0, w, h = map(float, top.get("viewBox").split())
            assert w > 100 and h > 50, template.id
            assert top.get("font-family").startswith(f"'{FAMILY}'")


def test_template_without_figure_gives_none(bank):
    template = next((t for t in bank if not t.figure), None)
    if template is None:
        pytest.skip("every template has a figure")
    assert figure_svg(make_variant(template, 1)) is None


def test_same_variant_same_bytes(bank):
    for template in figure_templates(bank):
        assert figure_svg(make_variant(template, 7)) == figure_svg(make_variant(template, 7))


@pytest.mark.parametrize("d1, d2, x", [(400, 1000, 2.5), (300, 1600, 4.0), (800, 900, 2.0), (650, 1600, 2.6)])
def test_pulleys_are_drawn_to_the_data(bank, d1, d2, x):
    svg = belt_drive(variant_of(bank, "belts.flat_belt_power", d1=d1, d2=d2, X=x))
    (driver,), (driven,) = circles(svg, "driver"), circles(svg, "driven")
    r1, r2 = float(driver.get("r")), float(driven.get("r"))
    assert r2 / r1 == pytest.approx(d2 / d1, rel=2e-3)
    centres = float(driven.get("cx")) - float(driver.get("cx"))
    assert centres / r1 == pytest.approx(x * 1000 / (d1 / 2), rel=2e-3)


def test_labels_show_the_printed_values(flat):
    labels = texts(belt_drive(flat))
    for expected in ("d\u2081 = 400 mm", "d\u2082 = 1000 mm", "X = 2.5 m", "N\u2081 = 220 rpm", "Driver",
                     "Driven", "tight side"):
        assert expected in labels


def test_open_and_crossed_drives_differ(bank):
    open_ = variant_of(bank, "belts.flat_belt_power", extra=[DRIVE], drive="open")
    crossed = variant_of(bank, "belts.flat_belt_power", extra=[DRIVE], drive="crossed")
    a, b = belt_drive(open_), belt_drive(crossed)
    assert a != b
    assert "Open belt drive" in a and "Crossed belt drive" in b


def test_a_template_without_drive_is_open(flat):
    assert "<title>Open belt drive</title>" in belt_drive(flat)


def _on_circle(p, c, r):
    return math.hypot(p[0] - c[0], p[1] - c[1]) == pytest.approx(r, abs=1e-9)


def _perpendicular(p, c, q):
    radius = (p[0] - c[0], p[1] - c[1])
    run = (q[0] - p[0], q[1] - p[1])
    return abs(radius[0] * run[0] + radius[1] * run[1]) / (math.hypot(*radius) * math.hypot(*run)) < 1e-9


@pytest.mark.parametrize("crossed", [False, True])
@pytest.mark.parametrize("r1, r2, distance", [(20, 50, 200), (50, 20, 200), (30, 30, 100), (10, 120, 140)])
def test_belt_runs_are_exact_common_tangents(crossed, r1, r2, distance):
    c1, c2 = (0.0, 0.0), (distance, 0.0)
    loop = belt_loop(c1, r1, c2, r2, crossed)
    for (on2, on1) in (loop.tight, loop.slack[::-1]):
        assert _on_circle(on1, c1, r1) and _on_circle(on2, c2, r2)
        assert _perpendicular(on1, c1, on2) and _perpendicular(on2, c2, on1)
    expected = math.pi + 2 * math.asin((r1 + r2) / distance) if crossed else math.pi - 2 * math.asin((r2 - r1) / distance)
    assert loop.wrap1 == pytest.approx(expected)


@pytest.mark.parametrize("crossed", [False, True])
def test_crossed_runs_cross_and_open_runs_do_not(crossed):
    loop = belt_loop((0.0, 0.0), 30, (200.0, 0.0), 60, crossed)
    (a, b), (c, d) = loop.tight, loop.slack

    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    intersect = side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0
    assert intersect == crossed


def test_tangents_need_separate_pulleys():
    with pytest.raises(ValueError, match="overlap"):
        belt_loop((0.0, 0.0), 50, (60.0, 0.0), 50, crossed=True)


def test_unknown_diameters_are_drawn_to_size_and_labelled_with_a_question_mark(bank):
    variant = make_variant(bank.get("belts.v_belt_count"), 3)
    svg = figure_svg(variant)
    labels = texts(svg)
    assert "d\u2081 = ?" in labels and "d\u2082 = ?" in labels
    (driver,), (driven,) = circles(svg, "driver"), circles(svg, "driven")
    ratio = float(driven.get("r")) / float(driver.get("r"))
    assert ratio == pytest.approx(variant.step("d2").value / variant.step("d1").value, rel=2e-3)


def test_groove_angle_inset_for_v_belts(bank):
    variant = make_variant(bank.get("belts.v_belt_power"), 2)
    labels = texts(figure_svg(variant))
    assert f"2\u03b2 = {variant.param('groove')}" in labels
    assert "V-groove section" in labels


def _numbers(text: str) -> set[str]:
    return set(re.findall(r"\d+(?:\.\d+)?", text))


def test_no_answer_value_appears_on_a_figure(bank):
    for template in figure_templates(bank):
        for seed in range(6):
            variant = make_variant(template, seed)
            shown = set().union(*(_numbers(t) for t in texts(figure_svg(variant))))
            printed = set().union(*(_numbers(str(p)) for p in variant.params))
            for answer in variant.answers.values():
                if isinstance(answer.value, float):
                    for sig in (3, 4):
                        number = units.format_number(answer.value, sig)
                        assert number in printed or number not in shown, (template.id, seed, answer.part.id)


def test_compound_drive_draws_four_pulleys_to_scale(bank):
    variant = variant_of(bank, "belts.compound_drive", d1=500, d2=800, d3=450, d4=650, N1=1440)
    svg = compound_drive(variant)
    radii = [float(c.get("r")) for cls in ("motor", "d2", "d3", "countershaft") for c in circles(svg, cls)]
    assert len(radii) == 4
    for r, d in zip(radii, (500, 800, 450, 650)):
        assert r / radii[0] == pytest.approx(d / 500, rel=2e-3)
    labels = texts(svg)
    for expected in ("d\u2081 = 500 mm", "d\u2082 = 800 mm", "d\u2083 = 450 mm", "d\u2084 = 650 mm",
                     "N\u2081 = 1440 rpm", "N\u2082 = ?", "N\u2084 = ?", "Motor", "Main shaft", "Countershaft"):
        assert expected in labels
    assert 'stroke-dasharray="5 3"' in svg  # what d2 hides of d3 and the second belt


def test_missing_size_is_a_clear_error(bank, flat):
    template = dataclasses.replace(flat.template, params=tuple(p for p in flat.template.params if p.name != "d2"))
    broken = dataclasses.replace(flat, template=template, params=tuple(p for p in flat.params if p.name != "d2"))
    with pytest.raises(ExgenError, match="'d2'"):
        belt_drive(broken)


def test_a_drive_without_centre_distance_is_drawn_clear_and_not_dimensioned(bank):
    variant = make_variant(bank.get("belts.driven_speed_slip"), 3)
    svg = belt_drive(variant)
    labels = texts(svg)
    assert not any(t.startswith("X =") for t in labels) and "N\u2082 = ?" in labels
    assert any(t.startswith("belt ") and t.endswith(" thick") for t in labels)
    (driver,), (driven,) = circles(svg, "driver"), circles(svg, "driven")
    gap = float(driven.get("cx")) - float(driver.get("cx")) - float(driver.get("r")) - float(driven.get("r"))
    assert gap > 0.5 * max(float(driver.get("r")), float(driven.get("r")))


@pytest.mark.parametrize("value, text", [(12.5, "12.5"), (3.0, "3"), (-0.004, "0"), (-1.236, "-1.24"), (0.1, "0.1")])
def test_coordinates_are_short_and_stable(value, text):
    assert num(value) == text


@pytest.mark.parametrize("name, label", [("d1", "d\u2081"), ("N12", "N\u2081\u2082"), ("X", "X")])
def test_subscripted_names(name, label):
    assert subscripted(name) == label
