"""The practice core: fresh variants from the practice seed range and never twice, parts checked as the
grader checks them (named mistakes, error carried forward), hints, the solution, progress followed."""
import random
from pathlib import Path

import pytest

from exgen.answertypes import answer_type
from exgen.draw.seeds import PRACTICE_SEEDS
from exgen.errors import ExgenError
from exgen.figures import figure_svg
from exgen.issue.assignment import load_assignment
from exgen.load.bank import load_bank
from exgen.solve.variant import answer_for, make_variant, rerun
from practice.scope import Scope
from practice.session import NoProblem, Practice
from practice.store import Store

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TINY = """\
id: demo.tiny
title: A motor drives a pulley
chapter: 1
topic: demo
solver: belts:driven_speed
params:
  N1: {choices: [720, 740], unit: rpm}
  d1: {value: 20, unit: cm}
  d2: {value: 40, unit: cm}
  G1: {value: 1, unit: percent}
  G2: {value: 1, unit: percent}
  t:  {value: 8, unit: mm}
statement: A motor at {{ N1 }} drives a pulley of {{ d2 }} from one of {{ d1 }}, with slip.
parts:
  - id: a
    ask: the speed of the driven pulley
    answer: N2_slip
    unit: rpm
    hints: ["Speeds go inversely as the diameters: $N_2 = N_1 d_1/d_2$.", "Then take off the slip, from {{ N1 }}."]
"""


@pytest.fixture
def practice(tmp_path):
    return Practice(load_bank(), Store(tmp_path / "progress.sqlite3"), rng=random.Random(7))


@pytest.fixture
def tiny(tmp_path):
    folder = tmp_path / "bank"
    folder.mkdir()
    (folder / "tiny.yaml").write_text(TINY, encoding="utf-8")
    return Practice(load_bank([folder]), Store(tmp_path / "tiny.sqlite3"), rng=random.Random(1))


def text(part, value) -> str:
    return answer_type(part).text(value, part)


def test_problems_come_from_the_practice_seed_range_and_never_repeat_a_variant(tiny):
    scope = Scope("template", "demo.tiny")
    first, second = tiny.next_problem(scope), tiny.next_problem(scope)
    assert first.variant.seed in PRACTICE_SEEDS and second.variant.seed in PRACTICE_SEEDS
    assert {first.variant.param("N1").text, second.variant.param("N1").text} == {"720", "740"}
    with pytest.raises(ExgenError, match="you have met every variant of A motor drives a pulley"):
        tiny.next_problem(scope)


def test_a_problem_is_rebuilt_from_its_record(practice):
    problem = practice.next_problem(Scope("topic", "belts"))
    again = Practice(practice.catalogue.bank, Store(practice.store.path)).problem(problem.id)
    assert again.variant.params == problem.variant.params and again.scope == Scope("topic", "belts")
    with pytest.raises(NoProblem):
        practice.problem(problem.id + 1)


def test_an_assignment_limits_practice_to_its_templates(tmp_path):
    bank = load_bank()
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    practice = Practice(bank, Store(tmp_path / "p.sqlite3"), assignment, rng=random.Random(2))
    allowed = {q.template for q in assignment.questions}
    seen = {practice.next_problem(Scope()).template.id for _ in range(12)}
    assert seen <= allowed and len(seen) > 1
    with pytest.raises(ExgenError, match="in Tutorial 1"):
        practice.catalogue.choose(topic="gyroscopes")


def test_a_known_mistake_is_named_and_recorded(practice):
    problem = practice.next_problem(Scope("template", "belts.driven_speed_slip"))
    part = problem.template.parts[0]
    name, value = next(iter(problem.variant.mistakes[part.id].items()))
    result = practice.check(problem, part.id, text(part, value))
    assert result.status == "wrong" and result.mistake is not None
    check = practice.state(problem).checks[part.id]
    assert (check.status, check.mistake, check.answer) == ("wrong", result.mistake, text(part, value))


def test_a_later_part_worked_right_from_a_wrong_earlier_one_is_carried_forward(practice):
    problem = practice.next_problem(Scope("template", "belts.compound_drive"))
    variant, a, b = problem.variant, problem.template.part("a"), problem.template.part("b")
    wrong_a = variant.answers["a"].value * 1.1
    carried = answer_for(b, rerun(variant, answer_type(a).overrides(a, wrong_a, variant))).value
    assert practice.check(problem, "a", text(a, wrong_a)).status == "wrong"
    assert practice.check(problem, "b", text(b, carried)).status == "carried"
    assert practice.check(problem, "a", text(a, variant.answers["a"].value)).status == "correct"
    assert practice.check(problem, "b", text(b, carried)).status == "wrong"  # (a) is right now


def test_an_unreadable_answer_is_a_format_problem_and_no_evidence(practice):
    problem = practice.next_problem(Scope("template", "belts.compound_drive"))
    result = practice.check(problem, "a", "about seven hundred")
    assert result.status == "unreadable" and "format problem" in result.message
    assert practice.table("topic")["belts"].mastery.problems == 0
    assert practice.check(problem, "a", "   ").status == "blank"  # not recorded
    assert len(practice.store.checks(problem.id)) == 1
    with pytest.raises(ExgenError, match="no part 'z'"):
        practice.check(problem, "z", "1")


def test_the_template_hints_come_first_filled_with_the_variant(tiny):
    problem = tiny.next_problem(Scope("template", "demo.tiny"))
    first = tiny.next_hint(problem, "a")
    assert first[0] == 1 and first[1].text.startswith("Speeds go inversely")
    assert tiny.next_hint(problem, "a")[1].text == f"Then take off the slip, from {problem.variant.param('N1')}."
    assert tiny.next_hint(problem, "a") is None
    assert tiny.state(problem).hints == {"a": 2}


def test_the_default_hints_are_the_steps_towards_the_part_then_its_formula_without_its_result(practice):
    problem = practice.next_problem(Scope("template", "belts.flat_belt_power"))
    worked = practice.worked(problem)
    answering = next(line for line in worked.lines if "a" in line.parts)
    ladder = practice.hints(problem, "a")
    assert [h.line.name for h in ladder[:-1]] == [line.name for line in worked.lines[:worked.lines.index(answering)]]
    last = ladder[-1].line
    assert last.name == answering.name and last.values == () and last.parts == ()
    assert last.substituted == answering.substituted  # the givens put in: θ = 180° − 2 × 5.123°
    later = practice.hints(problem, "c")  # from after (b)'s line
    answered_b = next(i for i, line in enumerate(worked.lines) if "b" in line.parts)
    assert later[0].line.name == worked.lines[answered_b + 1].name


def test_a_step_the_part_is_not_worked_from_is_no_hint(practice):
    """The slip is worked out first, but the speed without slip does not use it: its hint is the formula."""
    problem = practice.next_problem(Scope("template", "belts.driven_speed_slip"))
    worked = practice.worked(problem)
    assert worked.lines[0].name == "G" and not worked.lines[0].parts
    assert [h.line.name for h in practice.hints(problem, "a")] == ["N2_ideal"]
    with_slip = practice.hints(problem, "b")
    assert with_slip[-1].line.name == "N2_slip" and with_slip[-1].line.values == ()


def test_hints_and_the_solution_cost_credit(practice):
    scope = Scope("template", "belts.driven_speed_slip")
    clean = practice.next_problem(scope)
    for part in clean.template.parts:
        practice.check(clean, part.id, clean.variant.answers[part.id].text)
    full = practice.table("template")["belts.driven_speed_slip"].mastery
    helped = practice.next_problem(scope)
    practice.show_solution(helped)
    for part in helped.template.parts:
        practice.check(helped, part.id, helped.variant.answers[part.id].text)
    after = practice.table("template")["belts.driven_speed_slip"].mastery
    assert full.mean > 0.5 and after.mean < full.mean and after.problems == 2


def test_two_front_ends_on_one_file_see_each_others_progress(practice):
    other = Practice(practice.catalogue.bank, Store(practice.store.path))
    assert other.table("topic") == {}
    problem = practice.next_problem(Scope("topic", "gears"))
    part = problem.template.parts[0]
    practice.check(problem, part.id, problem.variant.answers[part.id].text)
    assert other.table("topic")["gears"].checks == 1


def test_every_template_in_the_bank_can_be_practised_and_every_part_has_a_hint(practice):
    for template in practice.catalogue.templates:
        problem = practice.next_problem(Scope("template", template.id))
        part = template.parts[-1]
        assert practice.check(problem, part.id, problem.variant.answers[part.id].text).correct, template.id
        for part in template.parts:
            assert practice.hints(problem, part.id), f"{template.id} ({part.id}) has no hint: give it hints:"


def test_a_figure_drawn_ahead_is_served_with_the_variant_it_was_drawn_for(tiny, bank):
    import time

    from practice.ahead import Ahead

    template = bank.get("belts.compound_drive")
    practice = Practice(bank, tiny.store)
    practice.ahead = Ahead()
    try:
        practice.ahead.fill([template])
        for _ in range(1200):
            if template.id in practice.ahead._ready:
                break
            time.sleep(0.05)
        seed, made = practice.ahead._ready[template.id]
        problem = practice.next_problem(Scope("template", template.id))
        assert problem.variant.seed == seed
        assert practice.figure(problem) == made["figure"] == figure_svg(make_variant(template, seed))
    finally:
        practice.ahead.close()
