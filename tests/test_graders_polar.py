"""Answers that are a magnitude at an angle: equivalent angles, add or remove, and which half is wrong."""
import pytest

from exgen.answertypes import read
from exgen.answertypes.choice import choice, choice_aliases
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from graders.mistakes import generic_mistake


@pytest.fixture(scope="module")
def variant(bank):
    return make_variant(bank.get("balancing.static_balance"), 4)  # 572.9 kg mm at 48.00 deg


def grade(variant, text):
    return next(r for r in grade_variant(variant, {"a": text}).parts if r.part_id == "a")


@pytest.mark.parametrize("text", [
    "572.9 kg mm at 48 deg", "572.9 kg·mm at 48°", "0.5729 kg m @ 48", "572.9 at 48.3", "572.9∠48",
    "572.9 at -312", "572.9 at 408 deg", "remove 572.9 at 228", "Remove 572.9 kg mm at 228°", "-572.9 at 228",
    "572.9 at 0.8378 rad",
    # a pair, as written in working: the angle carries its unit
    "(572.9 kg mm, 48°)", "572.9 kg mm, 48 deg", "mr = 572.9 kg mm; θ = 48°", "572.9 kg mm 48°", "0,5729 kg m, 48°",
    "remove 572.9 kg mm, 228°",
])
def test_equivalent_answers_are_right(variant, text):
    assert variant.answers["a"].text == "572.9 kg\u00b7mm at 48.00\u00b0"
    result = grade(variant, text)
    assert result.status == "correct", result.message


@pytest.mark.parametrize("text, mistake, words", [
    ("572.9 at 228", "resultant_not_balance", "goes opposite it"),  # the template names it first
    ("572.9 at 312", "mirrored_angle", "mirror image"),
    ("572.9 at 42", "wrong_axis", "wrong reference line"),
    ("572.9 at 138", "wrong_axis", "wrong reference line"),
    ("572.9 at 100", "angle_wrong", "magnitude is right"),
    ("600 at 48", "magnitude_wrong", "angle is right"),
])
def test_wrong_halves_are_named(variant, text, mistake, words):
    result = grade(variant, text)
    assert result.status == "wrong" and result.mistake == mistake and words in result.message


def test_scalar_sum_is_named(variant):
    total = sum(m * r for m, r in ((3.5, 100), (6, 110), (5.5, 160)))  # kg mm, added as numbers
    result = grade(variant, f"{total} at 48")
    assert result.mistake == "scalar_sum"


@pytest.mark.parametrize("text", ["572.9", "at 48", "572.9 at", "572.9 kg at 48", "572.9 at 48 m", "572.9, 48",
                                  "572.9 48", "1 2 48°"])
def test_incomplete_or_wrong_kind(variant, text):
    result = grade(variant, text)
    assert result.points == 0 and result.status in ("unreadable", "wrong")


def test_half_a_turn_out_is_named_generically_when_no_template_mistake_explains_it(variant):
    part = variant.template.part("a")
    found = generic_mistake(part, read("572.9 at 228", part), variant.answers["a"].value)
    assert found.name == "opposite_side" and "remove" in found.message


@pytest.mark.parametrize("given, expected", [
    ("CCW", "counter-clockwise"), ("anti-clockwise", "counter-clockwise"), ("cw", "clockwise"),
    ("Unbalanced", "not balanced"), ("Counter Clockwise", "counter-clockwise"),
    ("Raise the bow", "raises the bow"), ("nose down", "lowers the nose"), ("to Starboard", "starboard"),
    ("rear axle", "rear"), ("None", "no effect"), ("relieve", "relieves"), ("right spring", "right"),
])
def test_choice_aliases(given, expected):
    assert choice(given, expected, choice_aliases())


def test_every_alias_names_a_choice_some_template_offers(bank):
    offered = {c for t in bank for p in t.parts for c in p.options.get("choices", ())}
    assert {alias: meant for alias, meant in choice_aliases().items() if meant not in offered} == {}


def test_an_error_in_a_polar_part_is_carried_forward(variant):
    # (a) wrong size, (b) = that size / b, worked correctly from it: (b) earns its marks.
    results = {r.part_id: r for r in grade_variant(variant, {"a": "600 kg mm at 48", "b": f"{600 / 110:.4f} kg"}).parts}
    assert results["a"].status == "wrong" and results["b"].status == "carried"
    assert results["b"].points == results["b"].max_points and "from your (a)" in results["b"].message


def test_a_zero_has_no_direction():
    """A polygon that closes gives 0 at any angle: the secondary force of a primary-balanced engine drawn at
    the crank angles (not doubled) is 0, whatever angle a student writes with it."""
    from exgen.answertypes.polar import Polar, polar

    assert polar(Polar(0.0, 37.0), Polar(0.0, 180.0)) and not polar(Polar(0.0, 37.0), Polar(1e-3, 37.0))
    assert not polar(Polar(5.0, 37.0), Polar(5.0, 180.0))


def test_the_secondary_drawn_at_the_crank_angles_is_named_as_that_slip(bank):
    template = bank.get("balancing.inline_primary_balance")
    variant = make_variant(template, 3)
    assert variant.mistakes["c"]["secondary_not_doubled"].magnitude == 0.0
    result = next(r for r in grade_variant(variant, {"c": "0 N at 90 deg"}).parts if r.part_id == "c")
    assert result.mistake == "secondary_not_doubled"
