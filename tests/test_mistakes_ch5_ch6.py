"""Gyroscope and vibration answers that are wrong in a known way are named with the template's words:
rpm for rad/s, the diameter for the radius, I about the wrong axis, ω for f (a missing 2π), the
logarithmic decrement over the wrong number of cycles, the precession (so the effect) reversed, and a
gyroscopic couple added where it relieves."""

from exgen.solve.variant import make_variant
from graders.grade import grade_variant


def chapter_5_and_6(bank):
    return sorted(t.id for t in bank if t.chapter in (5, 6))


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


def test_chapters_5_and_6_are_in_the_bank(bank):
    ids = chapter_5_and_6(bank)
    assert sum(i.startswith("gyroscopes.") for i in ids) >= 8


def test_reversed_spring_feedback_holds_for_a_flywheel_turning_against_the_wheels(bank):
    """A student who gives the other spring has most likely taken the flywheel's spin from the road wheels'
    when the sheet says it turns the other way: the feedback must give the rule for that flywheel too,
    not only the wheels' direction (which would confirm the slip)."""
    template = bank.get("gyroscopes.vehicle_rotor_springs")
    variant = next(v for v in (make_variant(template, s) for s in range(40)) if v.param("spin").text == "opposite")
    wrong = "left" if variant.answers["f"].value == "right" else "right"
    result = grade(variant, "f", wrong)
    assert result.mistake == "precession_reversed"
    assert "turns against the road wheels" in result.message  # written from this sheet's flywheel
    assert f"its spin vector points {variant.step('spin_vector').value}" in result.message
