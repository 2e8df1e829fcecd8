"""The terminal view of a variant."""
import pytest

from exgen.render.text import variant_text
from exgen.render.unicode_math import text_to_plain
from exgen.solve.variant import make_variant


@pytest.mark.parametrize("template_id", ["belts.flat_belt_power", "belts.v_belt_count", "belts.compound_drive"])
def test_sheet_view_and_key_view(bank, template_id):
    if template_id not in {t.id for t in bank}:
        pytest.skip(f"{template_id} not in the bank")
    variant = make_variant(bank.get(template_id), 5)
    student = variant_text(variant)
    assert variant.template.title in student
    assert " ".join(text_to_plain(variant.statement).split()[:6]) in " ".join(student.split())
    for part in variant.template.parts:
        assert f"({part.id}) " in student
    assert "Worked solution" not in student and "Answers" not in student
    key = variant_text(variant, key=True)
    assert key.startswith(student)
    assert "Given" in key and "Worked solution" in key
    for part_id, answer in variant.answers.items():
        assert f"({part_id}) {answer.text}" in key


def test_units_asked_and_worked_lines(bank):
    variant = make_variant(bank.get("belts.flat_belt_power"), 5)
    text = variant_text(variant, key=True)
    assert "[answer in deg]" in text and "[answer in kW]" in text
    assert "r₁ = d₁/2 = " in text
    assert "(a)" in text.split("Worked solution")[1]
