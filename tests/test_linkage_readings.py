"""Linkages measured off their drawings are graded from what the student measured: a length read right but
not rounded, or misread, is carried into the positions worked from it; the angle a crank is turned the
wrong way is named. (What the figure draws and what the key answers, read back off the SVG, are
tests/test_figures_linkages.py's and tests/test_mistake_values_ch5_ch7.py's.)"""
import pytest

from exgen.answertypes import answer_type
from exgen.solve.variant import answer_for, make_variant, rerun
from graders.grade import grade_variant

SUSPENSION = "linkages.coupler_point_reading"
SLIDER_CRANK = "linkages.slider_crank_reading"


def worked_from(variant, readings: dict[str, float]) -> dict[str, str]:
    """Every part's answer as typed by a student who measured `readings` (part id -> mm) and worked the rest
    right from them."""
    template = variant.template
    overrides = {template.part(k).answer: mm / 1000 for k, mm in readings.items()}
    again = rerun(variant, overrides)
    typed = {}
    for part in template.parts:
        value = readings[part.id] if part.id in readings else answer_for(part, again).value
        typed[part.id] = f"{value:g} mm" if part.id in readings else answer_type(part).text(value, part)
    return typed


@pytest.mark.parametrize("template_id, off", [(SUSPENSION, {"a": 3, "b": -2.5, "e": 3.5}),
                                              (SLIDER_CRANK, {"a": -3, "c": 2})])
@pytest.mark.parametrize("seed", range(5))
def test_lengths_read_within_a_few_millimetres_and_worked_from_score_full_marks(bank, template_id, off, seed):
    # a student who did not round to the whole 10 mm: each reading right, and so is every part worked from them
    variant = make_variant(bank.get(template_id), seed)
    readings = {k: variant.answers[k].value + d for k, d in off.items()}
    result = grade_variant(variant, worked_from(variant, readings))
    assert all(r.status in ("correct", "carried") for r in result.parts), [(r.part_id, r.message) for r in result.parts]
    assert result.points == result.max_points


@pytest.mark.parametrize("seed", range(5))
def test_a_length_misread_by_a_division_costs_that_part_only(bank, seed):
    variant = make_variant(bank.get(SUSPENSION), seed)
    readings = {"c": variant.answers["c"].value + 10}          # the rocker read a whole 10 mm long
    try:
        typed = worked_from(variant, readings)
    except Exception:  # noqa: BLE001  (a rocker 10 mm longer may not assemble: no working to carry)
        pytest.skip("the misread linkage does not assemble at this crank angle")
    statuses = {r.part_id: r.status for r in grade_variant(variant, typed).parts}
    assert statuses["c"] == "wrong"
    assert all(statuses[k] in ("correct", "carried") for k in statuses if k != "c"), statuses
    assert {k for k, s in statuses.items() if s == "carried"}, "the positions move with the rocker read"


@pytest.mark.parametrize("seed", range(6))
def test_the_crank_turned_the_wrong_way_is_named(bank, seed):
    variant = make_variant(bank.get(SLIDER_CRANK), seed)
    wrong = variant.mistakes["d"]["turned_other_way"]
    part_d = variant.template.part("d")
    result = grade_variant(variant, {"d": answer_type(part_d).text(wrong, part_d)})
    (part,) = [r for r in result.parts if r.part_id == "d"]
    assert part.status == "wrong" and part.mistake == "turned_other_way"
    sense = str(variant.param("sense"))
    assert f"a {sense} turn" in part.message
