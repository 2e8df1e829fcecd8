"""Linkage figures: drawn to each variant's data, links numbered for counting, nothing asked printed."""
import math

import pytest

from exgen.figures.kinematic import DASH
from exgen.figures.linkage_poses import joints
from exgen.figures.linkages import (coupler_point, fourbar, fourbar_as_drawn, fourbar_both_roots, fourbar_circuits,
                                    synthesis, synthesis_construction, synthesis_three, synthesis_three_construction)
from exgen.figures import figure_svg
from exgen.solve.variant import make_variant
from svg_helpers import SVG, circles, root, texts, variant_of


def pins(svg):
    return [(float(c.get("cx")), float(c.get("cy"))) for c in circles(svg, "pin")]


@pytest.mark.parametrize("theta2, circuit", [(75, "1"), (75, "2"), (200, "1"), (320, "2")])
def test_four_bar_is_drawn_to_scale_in_its_circuit(bank, theta2, circuit):
    variant = variant_of(bank, "linkages.fourbar_position", L1=250, L2=80, L3=260, L4=180, theta2=theta2,
                         circuit=circuit)
    found = pins(fourbar(variant))
    assert len(found) == 4
    # the four pins are A, B, C, D: their six distances are the links and diagonals, to one scale
    drawn = sorted(math.dist(p, q) for i, p in enumerate(found) for q in found[i + 1:])
    places = joints(0.25, 0.08, 0.26, 0.18, math.radians(theta2), int(circuit))
    expected = sorted(math.dist(places[p], places[q]) for p, q in ("AB", "BC", "CD", "DA", "AC", "BD"))
    assert expected[:4] != drawn[:4]
    scale = drawn[-1] / expected[-1]
    assert [x / scale for x in drawn] == pytest.approx(expected, rel=2e-3)
    assert {0.25, 0.08, 0.26, 0.18} <= {round(x, 6) for x in expected}


def test_key_figure_adds_the_other_circuit(bank):
    variant = variant_of(bank, "linkages.fourbar_position", L1=250, L2=80, L3=260, L4=180, theta2=75, circuit="1")
    sheet, key = fourbar(variant), fourbar_circuits(variant)
    assert "C′" in texts(key) and "C′" not in texts(sheet)
    assert len([e for e in root(key).iter(f"{SVG}line") if "other-circuit" in e.get("class", "")]) == 2


def test_every_value_a_sheet_figure_prints_is_given_data(bank):
    """So no figure carries an answer: each 'name = value' label shows a given value as printed."""
    for template_id in ("linkages.fourbar_position", "linkages.coupler_point", "linkages.slider_crank",
                        "linkages.grashof", "linkages.rocker_swing", "linkages.actuator_swing",
                        "linkages.two_position_synthesis", "linkages.three_position_synthesis",
                        "linkages.fourbar_both_roots", "linkages.slider_crank_both_roots",
                        "linkages.coupler_point_reading", "linkages.slider_crank_reading"):
        for seed in range(8):
            variant = make_variant(bank.get(template_id), seed)
            given = {str(p) for p in variant.params}
            for text in texts(_sheet_figure(variant)):
                value = text.split(" = ", 1)[1] if " = " in text else None
                if value and value not in ("0", "0, 0"):
                    assert value in given, (template_id, seed, text)


def _sheet_figure(variant):
    from exgen.figures import figure_svg
    return figure_svg(variant)


def test_coupler_point_figure_marks_p_and_the_origin(bank):
    variant = make_variant(bank.get("linkages.coupler_point"), 3)
    words = texts(coupler_point(variant))
    assert {"A", "B", "C", "P", "D (0, 0)"} <= set(words)
    assert any(w.startswith("CP = ") for w in words) and any(w.startswith("BP = ") for w in words)


def test_synthesis_key_shows_the_pivots_the_sheet_does_not(bank):
    variant = make_variant(bank.get("linkages.two_position_synthesis"), 2)
    assert "E" not in texts(synthesis(variant)) and {"E", "F"} <= set(texts(synthesis_construction(variant)))


@pytest.mark.parametrize("seed", range(6))
def test_both_roots_sheet_names_no_circuit_and_the_key_draws_the_other(bank, seed):
    variant = make_variant(bank.get("linkages.fourbar_both_roots"), seed)
    sheet, key = fourbar_as_drawn(variant), fourbar_both_roots(variant)
    assert "circuit" not in sheet.lower() and "C′" not in texts(sheet)
    assert "C′" in texts(key) and len([e for e in root(key).iter(f"{SVG}line")
                                       if "other-circuit" in (e.get("class") or "")]) == 2


@pytest.mark.parametrize("seed", range(6))
def test_slider_crank_roots_sheet_names_no_root_and_the_key_draws_the_other(bank, seed):
    from exgen.figures.slider_crank_roots import as_drawn, both_roots
    variant = make_variant(bank.get("linkages.slider_crank_both_roots"), seed)
    sheet, key = as_drawn(variant), both_roots(variant)
    assert "root" not in sheet.lower() and "C′" not in texts(sheet)
    assert "C′" in texts(key) and len([e for e in root(key).iter(f"{SVG}line")
                                       if "other-circuit" in (e.get("class") or "")]) == 1


@pytest.mark.parametrize("seed", range(6))
def test_three_position_key_puts_each_pivot_where_its_bisectors_cross(bank, seed):
    variant = make_variant(bank.get("linkages.three_position_synthesis"), seed)
    sheet, key = synthesis_three(variant), synthesis_three_construction(variant)
    assert {"M₃", "N₃"} <= set(texts(sheet)) and "E" not in texts(sheet)
    assert {"E", "F"} <= set(texts(key))
    # a link from each pivot to each of its pin's three positions, and the two chords whose bisectors cross there
    bars = [e for e in root(key).iter(f"{SVG}line") if "synthesised" in (e.get("class") or "")]
    chords = [e for e in root(key).iter(f"{SVG}line") if "chord" in (e.get("class") or "")]
    assert len(chords) == 4 and len(bars) >= 6


@pytest.mark.parametrize("template_id, seed", [(t, s) for t in ("linkages.mobility", "linkages.mobility_exceptions")
                                                for s in range(12)])
def test_mobility_diagram_numbers_every_link(bank, template_id, seed):
    variant = make_variant(bank.get(template_id), seed)
    svg = figure_svg(variant)
    labels = root(svg).iter(f"{SVG}text")
    numbers = [("".join(t.itertext()), t.get("class", "")) for t in labels]
    moving = sorted(int(n) for n, cls in numbers if cls == "link-number")
    links = variant.answers["a"].value
    assert moving == list(range(2, links + 1))
    assert any(n == "1" and cls == "ground-number" for n, cls in numbers)


READINGS = {"linkages.coupler_point_reading": ("yA", {"AB": "AB", "BC": "BC", "DC": "DC", "CP": "PC", "BP": "PB"}),
            "linkages.slider_crank_reading": ("L3", {"AB": "AB", "offset": "offset", "CP": "piston"})}


@pytest.mark.parametrize("template_id", sorted(READINGS))
@pytest.mark.parametrize("seed", range(8))
def test_a_linkage_to_be_measured_is_drawn_to_scale_with_one_dimension_and_no_other_length(bank, template_id, seed):
    # what a reader measures off the drawing, scaled by its one dimension, is what was drawn; the only numbers
    # on it are that dimension, the joint D's coordinates and the crank angle a slider-crank is drawn at
    import figure_readings

    variant = make_variant(bank.get(template_id), seed)
    dimension, drawn = READINGS[template_id]
    svg = _sheet_figure(variant)
    read = (figure_readings.suspension_reading if "coupler" in template_id else figure_readings.slider_crank_reading)(variant)
    assert {k: read[k] for k in drawn} == pytest.approx({k: float(variant.param(p).si) for k, p in drawn.items()})
    numbers = {t for t in texts(svg) if any(ch.isdigit() for ch in t)}
    allowed = {str(variant.param(dimension)), "D (0, 0)"} | ({str(variant.param("drawn"))} if "slider" in template_id else set())
    assert numbers <= allowed and str(variant.param(dimension)) in numbers, numbers - allowed


@pytest.mark.parametrize("template_id", sorted(READINGS))
def test_a_measured_linkage_s_key_draws_the_position_asked_with_the_lengths_read(bank, template_id):
    from exgen.figures import key_figure_svgs

    for seed in range(4):
        variant = make_variant(bank.get(template_id), seed)
        ((_, key),) = key_figure_svgs(variant)
        lengths = {t for t in texts(key) if t.endswith(" mm")}
        read = {f"{variant.answers[p.id].value:.4g} mm" for p in variant.template.parts if p.unit == "mm" and p.tol.rel == 0}
        assert lengths == read
        dashed = [e for e in root(key).iter(f"{SVG}line") if "link" in (e.get("class") or "").split()
                  and e.get("stroke-dasharray") == DASH]
        assert len(dashed) == 2, "the sheet's pose: its crank and its coupler or rocker, dashed"


@pytest.mark.parametrize("template_id", sorted(READINGS))
def test_a_linkage_to_be_measured_is_drawn_large_enough_to_read_to_its_tolerance(bank, template_id):
    # the readings are graded within 4 mm and drawn to whole 10 mm: 4 mm of the linkage is about 0.8 mm or more
    # on the printed page (figures print at PT_PER_PX, 1 pt = 0.3528 mm), where a ruler reads to half of one
    import figure_readings
    from exgen.figures.svg import PT_PER_PX

    on_page = []
    for seed in range(40):
        svg = _sheet_figure(make_variant(bank.get(template_id), seed))
        on_page.append(0.004 / figure_readings._metres_per_px(svg) * PT_PER_PX * 25.4 / 72)
    assert min(on_page) >= 0.79, min(on_page)
