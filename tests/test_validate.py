"""What validate and the drawing rules check that an author cannot see in the YAML: a named mistake
kept apart from the answer (every answer type), `uses:` against the solver, steps named like givens,
mistakes without words."""
import shutil
from pathlib import Path

import pytest

from exgen.check.validate import validate_template
from exgen.errors import DrawError, ExgenError
from exgen.load.bank import load_template
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from graders.results import CARRIED, WRONG

SOLVERS = Path(__file__).parent / "fixtures" / "validate_solvers.py"
TEMPLATE = """\
id: demo.rules
title: Rules
solver: ./validate_solvers.py:{solver}
params:
  x: {{min: 1, max: 5, step: 0.01, unit: m}}
statement: A length of {{{{ x }}}}.
parts:
{parts}
"""


def template(tmp_path: Path, solver: str, parts: str):
    shutil.copy(SOLVERS, tmp_path)  # the template's solver, in the file beside it
    path = tmp_path / "t.yaml"
    path.write_text(TEMPLATE.format(solver=solver, parts=parts), encoding="utf-8")
    return load_template(path)


def test_a_named_mistake_never_gives_the_right_answer_of_any_type(bank):
    """v_belt_count (a) named `centrifugal_ignored`, whose count equalled the right one in half the draws."""
    template = bank.get("belts.v_belt_count")
    for seed in range(60):
        variant = make_variant(template, seed)
        assert variant.mistakes["a"].get("centrifugal_ignored") != variant.answers["a"].value


def test_a_named_mistake_that_always_lands_close_makes_the_template_undrawable(tmp_path):
    rules = template(tmp_path, "mistakes", "  - {id: a, ask: twice x, answer: double, unit: m, "
                                           "mistakes: [{when: always_close, say: x}]}")
    with pytest.raises(DrawError, match="the mistake 'always_close' lands within 3 times 1 % of the answer"):
        make_variant(rules, 1)


def test_a_mistake_recorded_if_apart_is_dropped_where_it_does_not_show(tmp_path):
    rules = template(tmp_path, "mistakes", "  - {id: a, ask: twice x, answer: double, unit: m, "
                                           "mistakes: [{when: sometimes_close, say: x}]}")
    variants = [make_variant(rules, seed) for seed in range(40)]
    shown = {v.param("x").si >= 3 for v in variants if "sometimes_close" in v.mistakes["a"]}
    assert shown == {True} and all(v.tries == 1 for v in variants)
    assert "always_close" not in variants[0].mistakes["a"]  # unnamed and too close: not offered as feedback


def test_validate_reports_mistakes_never_recorded_and_without_words(tmp_path):
    rules = template(tmp_path, "mistakes", "  - {id: a, ask: twice x, answer: double, unit: m, "
                                           "mistakes: [{when: no_words_for_this}, {when: never_recorded, say: x}]}")
    report = validate_template(rules, seeds=20)
    assert "part a: names mistake 'never_recorded', which the solver never records apart from the answer" \
        in report.problems
    assert "part a: mistake 'no_words_for_this' has no `say:` and no default message in " \
        "exgen/data/mistakes.yaml" in report.warnings


def test_uses_must_follow_the_solver(tmp_path):
    parts = ("  - {id: a, ask: twice x, answer: double, unit: m}\n"
             "  - {id: b, ask: three times x, answer: triple, unit: m, uses: [a]}")
    report = validate_template(template(tmp_path, "later_part_ignores_the_earlier", parts), seeds=10)
    assert report.problems == ["part b: uses (a), but its answer does not change when (a)'s does: "
                               "work from it, or drop it from `uses:`"]
    assert validate_template(template(tmp_path, "later_part_follows_the_earlier", parts), seeds=10).problems == []


def test_a_step_may_not_take_a_parameters_name(tmp_path):
    rules = template(tmp_path, "step_named_like_a_parameter", "  - {id: a, ask: x, answer: x, unit: m}")
    with pytest.raises(ExgenError, match="the solver names a step 'x' like a given value"):
        make_variant(rules, 0)


def test_a_wrong_choice_carries_forward_to_the_parts_worked_from_it(bank):
    """Car wheel reactions: (e)-(h) follow the axle the student said the engine loads in (c)."""
    from exgen.solve.variant import rerun

    variant = make_variant(bank.get("gyroscopes.car_wheel_reactions"), 5)
    right = variant.answers["c"].value
    wrong = "front" if right == "rear" else "rear"
    steps = {p: variant.answers[p].si for p in "abd"}
    names = {p: variant.template.part(p).answer for p in "abd"}
    carried = rerun(variant, {variant.template.part("c").answer: wrong, **{names[p]: steps[p] for p in steps}})
    answers = {p: variant.answers[p].text for p in "abd"}
    answers.update(c=wrong, e=f"{carried['R_fl'].value:.6g} N")
    parts = {r.part_id: r for r in grade_variant(variant, answers).parts}
    assert parts["c"].status == WRONG and parts["e"].status == CARRIED
