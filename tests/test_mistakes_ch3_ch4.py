"""Flywheel and governor answers that are wrong in a known way are named in feedback, with the
template's words or the shared default: rpm not converted, a ± band taken for the total, mm² scaled by
one axis only, friction on the wrong side, the sensitivity inverted, and every other listed slip."""
import pytest

from exgen import units
from exgen.answertypes import answer_type
from exgen.mistake_messages import default_messages
from exgen.variant import make_variant
from graders.grade import grade_variant

TEMPLATES = sorted(t for t in __import__("exgen.bank", fromlist=["load_bank"]).load_bank().templates
                   if t.startswith(("flywheels.", "governors.")))


def as_text(value, part):
    return value if isinstance(value, str) else units.format_quantity(value, part.unit, 6)


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


@pytest.mark.parametrize("template_id", TEMPLATES)
def test_every_named_mistake_is_recognised_with_its_own_words(bank, template_id):
    template = bank.get(template_id)
    seen = set()
    for seed in range(12):
        variant = make_variant(template, seed)
        for part in template.parts:
            recorded = variant.mistakes[part.id]
            for spec in part.mistakes:
                if spec.when not in recorded or recorded[spec.when] == variant.answers[part.id].value:
                    continue
                result = grade(variant, part.id, as_text(recorded[spec.when], part))
                assert result.status == "wrong", (seed, part.id, spec.when)
                same = [m.when for m in part.mistakes if m.when in recorded and
                        answer_type(part).matches(recorded[m.when], recorded[spec.when], part)]
                assert result.mistake in same, (seed, part.id, spec.when, result.mistake)
                if result.mistake == spec.when:
                    assert result.message == (spec.say or default_messages()[spec.when])
                seen.add((part.id, spec.when))
    named = {(p.id, m.when) for p in template.parts for m in p.mistakes}
    assert named <= seen, named - seen


def test_every_mistake_named_has_words(bank):
    """No flywheel or governor part falls back on the general "a known slip" line."""
    missing = {(t, p.id, m.when) for t in TEMPLATES for p in bank.get(t).parts for m in p.mistakes
               if not m.say and m.when not in default_messages()}
    assert not missing


@pytest.mark.parametrize("template_id, part_id, mistake, words", [
    ("flywheels.speed_fluctuation", "d", "rpm_as_rad_s", "rpm"),
    ("flywheels.turning_moment_equation", "b", "plus_minus_read_as_total", "±"),
    ("flywheels.speed_fluctuation", "c", "one_scale_only", "both axes"),
    ("governors.porter_friction", "b", "friction_wrong_side", "opposes"),
    ("governors.porter_dead_load", "d", "sensitivity_inverted", "ω/(ω₁ − ω₂)"),
])
def test_the_five_slips_of_chapters_3_and_4(bank, template_id, part_id, mistake, words):
    variant = make_variant(bank.get(template_id), 4)
    part = bank.get(template_id).part(part_id)
    result = grade(variant, part_id, as_text(variant.mistakes[part_id][mistake], part))
    assert result.status == "wrong" and result.mistake == mistake and words in result.message
