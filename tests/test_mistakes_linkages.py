"""Chapter 7 answers that are wrong in a known way are named with the template's own words: the
other circuit or branch, γ for θ4, radians for degrees, the wrong pair in Grashof's sum, the ground
or a shared pin miscounted, higher pairs taken for lower ones."""
import pytest

from exgen import units
from exgen.answertypes import answer_type
from exgen.variant import make_variant
from graders.grade import grade_variant

TEMPLATES = ("linkages.mobility", "linkages.grashof", "linkages.fourbar_position", "linkages.coupler_point",
             "linkages.slider_crank", "linkages.rocker_swing", "linkages.actuator_swing",
             "linkages.two_position_synthesis")


def as_text(value, part):
    if isinstance(value, str):
        return value
    if isinstance(value, int):
        return str(value)
    return units.format_quantity(value, part.unit, 6)


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


@pytest.mark.parametrize("template_id", TEMPLATES)
def test_every_named_mistake_is_recognised_with_its_own_words(bank, template_id):
    template = bank.get(template_id)
    seen = set()
    for seed in range(30):
        variant = make_variant(template, seed)
        for part in template.parts:
            recorded = variant.mistakes[part.id]
            for spec in part.mistakes:
                if spec.when not in recorded:
                    continue
                result = grade(variant, part.id, as_text(recorded[spec.when], part))
                assert result.status == "wrong", (seed, part.id, spec.when, recorded[spec.when])
                same = [m.when for m in part.mistakes if m.when in recorded
                        and answer_type(part).matches(recorded[m.when], recorded[spec.when], part)]
                assert result.mistake in same, (seed, part.id, spec.when, result.mistake)
                if result.mistake == spec.when:
                    assert result.message == spec.say
                seen.add((part.id, spec.when))
    named = {(p.id, m.when) for p in template.parts for m in p.mistakes}
    assert named == seen, named - seen


def test_the_issue_s_named_mistakes_are_all_there(bank):
    names = {m.when for t in TEMPLATES for p in bank.get(t).parts for m in p.mistakes}
    assert {"wrong_circuit", "gamma_for_theta4", "theta4_for_gamma", "degrees_as_radians", "radians_for_degrees",
            "wrong_pair", "ground_not_counted", "shared_joint_counted_once"} <= names
