"""Gyroscope and vibration answers that are wrong in a known way are named with the template's words:
rpm for rad/s, the diameter for the radius, I about the wrong axis, ω for f (a missing 2π), the
logarithmic decrement over the wrong number of cycles, the precession (so the effect) reversed, and a
gyroscopic couple added where it relieves."""
import pytest

from exgen import units
from exgen.answertypes import answer_type
from exgen.variant import make_variant
from graders.grade import grade_variant


def chapter_5_and_6(bank):
    return sorted(t.id for t in bank if t.chapter in (5, 6))


def as_text(value, part):
    """What a student would type for a recorded value: a word, a formula, or a number in the asked unit."""
    if isinstance(value, (int, float)):
        return units.format_quantity(value, part.unit, 6)
    return str(value)


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


def test_chapters_5_and_6_are_in_the_bank(bank):
    ids = chapter_5_and_6(bank)
    assert sum(i.startswith("gyroscopes.") for i in ids) >= 8


def test_every_named_mistake_is_recognised_with_its_own_words(bank):
    for template_id in chapter_5_and_6(bank):
        template = bank.get(template_id)
        seen = set()
        for seed in range(16):
            variant = make_variant(template, seed)
            for part in template.parts:
                recorded = variant.mistakes[part.id]
                for spec in part.mistakes:
                    if spec.when not in recorded:
                        continue
                    result = grade(variant, part.id, as_text(recorded[spec.when], part))
                    assert result.status == "wrong", (template_id, seed, part.id, spec.when)
                    same = [m.when for m in part.mistakes if m.when in recorded and
                            answer_type(part).matches(recorded[m.when], recorded[spec.when], part)]
                    assert result.mistake in same, (template_id, seed, part.id, spec.when, result.mistake)
                    if result.mistake == spec.when and spec.say:
                        assert result.message == spec.say
                    seen.add((part.id, spec.when))
        named = {(p.id, m.when) for p in template.parts for m in p.mistakes}
        assert named == seen, (template_id, named - seen)


def test_reversed_spring_feedback_holds_for_a_flywheel_turning_against_the_wheels(bank):
    """A student who gives the other spring has most likely taken the flywheel's spin from the road wheels'
    when the sheet says it turns the other way: the feedback must give the rule for that flywheel too,
    not only the wheels' direction (which would confirm the slip)."""
    template = bank.get("gyroscopes.vehicle_rotor_springs")
    variant = next(v for v in (make_variant(template, s) for s in range(40)) if v.param("spin").text == "opposite")
    wrong = "left" if variant.answers["f"].value == "right" else "right"
    result = grade(variant, "f", wrong)
    assert result.mistake == "precession_reversed"
    assert "opposite" in result.message and "to its right" in result.message
