"""Flywheel and governor answers that are wrong in a known way are named in feedback, with the
template's words or the shared default: rpm not converted, a ± band taken for the total, mm² scaled by
one axis only, friction on the wrong side, the sensitivity inverted, and every other listed slip."""
import pytest

from exgen import units
from exgen.solve.variant import make_variant
from graders.grade import grade_variant

TEMPLATES = sorted(t for t in __import__("exgen.load.bank", fromlist=["load_bank"]).load_bank().templates
                   if t.startswith(("flywheels.", "governors.")))


def as_text(value, part):
    return value if isinstance(value, str) else units.format_quantity(value, part.unit, 6)


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


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
