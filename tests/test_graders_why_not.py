"""Why an unexplained wrong number is wrong: the worked step it is, over every template and many draws;
else a factor with a usual cause, else which way and how far. Marks never change."""
import math

import pytest

from exgen.answertypes import answer_type
from exgen.load.bank import load_bank
from exgen.render.targets import PLAIN
from exgen.solve.variant import make_variant
from graders import marking
from graders.grade import grade_variant
from graders.results import WRONG

BANK = load_bank()
SEEDS = range(101, 109)


def graded(variant, part_id, text):
    return next(p for p in grade_variant(variant, {part_id: text}).parts if p.part_id == part_id)


@pytest.mark.parametrize("template_id", sorted(BANK.templates))
def test_a_worked_value_typed_for_another_part_is_named_as_that_step(template_id):
    """Typing a step's value (as the working shows it) into a number part it does not answer is wrong, and,
    unless a known mistake explains it, the feedback names that step or one as near."""
    template = BANK.get(template_id)
    for seed in SEEDS:
        variant = make_variant(template, seed)
        steps = {s.name: s for s in variant.steps}
        for part in template.parts:
            if part.type != "number":
                continue
            kind, answer = answer_type(part), variant.answers[part.id]
            for step in variant.steps:
                if not isinstance(step.value, float) or step.value == 0 or step.name == answer.step.name:
                    continue
                result = graded(variant, part.id, f"{step.value:.6g}")
                if result.status != WRONG or result.mistake is not None:
                    continue
                assert "Your value is" in result.message, (seed, part.id, step.name, result.message)
                named = result.message.split("Your value is ", 1)[1]
                symbol = PLAIN.math(step.symbol)
                if not named.startswith(symbol + " ") and not named.startswith(symbol + ","):
                    # another step (or given) of the same value, in some unit of its kind, was named
                    assert any(named.startswith(PLAIN.math(s.symbol)) for s in steps.values()) or \
                        any(named.startswith(PLAIN.math(p.symbol)) for p in variant.params), result.message


@pytest.mark.parametrize("template_id", sorted(BANK.templates))
def test_the_feedback_never_changes_a_mark(template_id, monkeypatch):
    template = BANK.get(template_id)
    for seed in SEEDS[:3]:
        variant = make_variant(template, seed)
        answers = {p.id: _wrongish(variant.answers[p.id], k) for k, p in enumerate(template.parts)}
        with_words = grade_variant(variant, answers)
        monkeypatch.setattr(marking, "why_not", lambda *args: None)
        without = grade_variant(variant, answers)
        monkeypatch.undo()
        for a, b in zip(with_words.parts, without.parts):
            assert (a.status, a.points, a.mistake) == (b.status, b.points, b.mistake)
            assert all(sentence in a.message for sentence in b.message.split(". "))  # only words added


def _wrongish(answer, k):
    value = answer.value
    if isinstance(value, float):
        return f"{value * (1.37, 0.61, 2 * math.pi, -1.2, 3.3)[k % 5]:.5g}"
    return answer.text


@pytest.fixture
def beam():
    return make_variant(BANK.get("vibration.beam_two_springs"), 3)


def test_the_answer_to_another_part_is_named_with_its_part(beam):
    q = beam.step("q").value
    message = graded(beam, "c", f"{q:.4g}").message
    assert message.endswith("Your value is q = K(a² + b²), the answer to (b), not to this part.")


def test_a_step_on_the_way_says_what_is_worked_out_from_it(beam):
    ball = beam.step("I_ball").value
    assert graded(beam, "a", f"{ball:.4g}").message.endswith("Your value is I_(ball) = m_B b², a step on the way: "
                                                              "I_O is worked out from it.")
    beam_only = beam.step("I_beam").value
    assert "a value of the working that this part does not use" in graded(beam, "b", f"{beam_only:.4g}").message


def test_a_step_in_another_unit_of_its_kind_is_still_recognised(beam):
    q = beam.step("q").value  # N·m; typed in kN·m's number
    assert "the answer to (b)" in graded(beam, "c", f"{q / 1000:.4g}").message


@pytest.mark.parametrize("times, said", [
    (2, "twice the expected one, as if a diameter were taken for a radius"), (0.5, "half the expected one"),
    (math.pi, "π times the expected one, as if a diameter and a circumference"),
    (9.81, "g times the expected one, as if a mass were taken for a weight"), (1 / 9.81, "1/g of the expected one"),
    (60, "60 times the expected one, as if minutes and seconds"), (2 * math.pi, "2π times"),
    (60 / (2 * math.pi), "60/(2π) times the expected one, as if rpm were taken for rad/s"),
    (math.sqrt(0.1991) / 0.1991, "about the square root of"),
])
def test_a_factor_with_a_usual_cause_is_named(beam, times, said):
    result = graded(beam, "a", f"{beam.answers['a'].value * times:.5g}")  # (a) is 0.1991 kg·m²
    assert result.mistake is None and said in result.message, result.message


@pytest.mark.parametrize("times, said", [(1.23, "about 20 % too large"), (0.93, "about 7 % too small"),
                                         (4.2, "about 4 times the expected one"), (-1.5, "the wrong sign")])
def test_otherwise_which_way_and_roughly_how_far(bank, times, said):
    variant = make_variant(bank.get("vibration.beam_two_springs"), 3)
    result = graded(variant, "c", f"{variant.answers['c'].value * times:.5g}")
    assert result.status == WRONG and said in result.message, result.message
