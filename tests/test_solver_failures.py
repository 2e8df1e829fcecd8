"""A solver's crash is a defect that speaks, never a redraw: only a `require:`, a solver's `d.require` or an
InvalidDraw it raises by name turns a draw down. `exgen validate` names the template, the seed, the exception
and where it rose, and fails; `show` and `solve` say it in one line; grading says why no credit was carried
forward when the working breaks down on a student's own earlier answers."""
import shutil
from pathlib import Path

import pytest

from exgen.check.validate import validate_template
from exgen.cli import main
from exgen.draw.values import draw_values, generator
from exgen.errors import SolverFailure
from exgen.issue.assignment import Assignment, QuestionSpec, Student
from exgen.load.bank import load_template
from exgen.mechanics import belts
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from graders.report import report_page
from graders.results import GRADED, WRONG, BatchResult, Column, SheetResult

SOLVERS = Path(__file__).parent / "fixtures" / "validate_solvers.py"
TEMPLATE = """\
id: demo.crash
title: Crash
solver: ./validate_solvers.py:{solver}
params:
  x: {{min: 1, max: 5, step: 0.01, unit: m}}
statement: A length of {{{{ x }}}}.
parts:
  - {{id: a, ask: twice x, answer: double, unit: m}}
"""


def fixture_template(tmp_path, solver: str):
    shutil.copy(SOLVERS, tmp_path)  # the template's solver, in the file beside it
    path = tmp_path / "t.yaml"
    path.write_text(TEMPLATE.format(solver=solver), encoding="utf-8")
    return load_template(path)


@pytest.fixture
def crash_when_mu_is_035(monkeypatch):
    """The flat belt's tension ratio made to crash for μ = 0.35, a third of the draws."""
    right = belts.tension_ratio

    def tension_ratio(mu, theta, groove_half_angle=None):
        if mu == 0.35:
            raise ValueError("math domain error")
        return right(mu, theta, groove_half_angle)

    monkeypatch.setattr(belts, "tension_ratio", tension_ratio)


def test_a_crash_is_raised_as_a_defect_not_redrawn(tmp_path):
    template = fixture_template(tmp_path, "crashes_below_two")
    crashing = next(seed for seed in range(40) if _x(template, seed) < 2)
    with pytest.raises(SolverFailure) as info:
        make_variant(template, crashing)
    message = str(info.value)
    assert message.startswith(f"demo.crash, seed {crashing}: the solver failed with ZeroDivisionError: ")
    assert "validate_solvers.py:" in message and "in crashes_below_two" in message


def test_a_rejection_raised_by_name_is_redrawn(tmp_path):
    template = fixture_template(tmp_path, "rejects_below_two")
    variants = [make_variant(template, seed) for seed in range(40)]
    assert all(v.param("x").si >= 2 for v in variants) and any(v.tries > 1 for v in variants)


def test_validate_fails_and_names_the_seed_the_exception_and_where(tmp_path):
    report = validate_template(fixture_template(tmp_path, "crashes_below_two"), seeds=20)
    assert not report.ok
    assert report.problems and all(
        p.startswith("seed ") and "ZeroDivisionError" in p and "validate_solvers.py" in p for p in report.problems)


def test_validate_catches_a_belt_solver_crashing_on_a_third_of_the_draws(bank, crash_when_mu_is_035, capsys):
    report = validate_template(bank.get("belts.flat_belt_power"), seeds=30)
    assert not report.ok
    assert any("the solver failed with ValueError: math domain error at " in p and "exgen/solvers/belts.py" in p
               for p in report.problems), report.problems
    assert main(["validate", "belts.flat_belt_power", "--seeds", "12"]) == 1
    out = capsys.readouterr().out
    assert "FAIL belts.flat_belt_power" in out and "math domain error" in out


def test_show_says_a_crash_in_one_line(bank, crash_when_mu_is_035, capsys):
    template = bank.get("belts.flat_belt_power")
    seed = next(s for s in range(40) if _first_draw(template, s)["mu"] == "0.35")
    assert main(["show", "belts.flat_belt_power", "--seed", str(seed)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"exgen: belts.flat_belt_power, seed {seed}: the solver failed")
    assert "Traceback" not in err


def test_solve_says_in_one_line_that_the_physics_refuses_the_values(capsys):
    """A press whose flywheel holds less than a pressing takes: the speed it would be left with has no value."""
    argv = ["solve", "flywheels.punching_press", "--set", "P=2kW", "--set", "I=20kg*m^2", "--set", "N=150rpm",
            "--set", "E=40kJ", "--set", "t=1s"]
    assert main(argv) == 1
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("exgen: flywheels.punching_press: the solver cannot work from the "
                                               "values given: the flywheel would stop")


def test_grading_says_why_no_credit_was_carried_forward(bank):
    """An angle of contact of 10⁶° overflows e^(μθ): the power worked from it has no value, and the feedback
    and the report say so instead of marking the power plainly wrong."""
    variant = make_variant(bank.get("belts.flat_belt_power"), 3)
    result = grade_variant(variant, {"a": "1000000 deg", "b": variant.answers["b"].text, "c": "1 kW"})
    part = next(p for p in result.parts if p.part_id == "c")
    assert part.status == WRONG
    assert part.message.endswith("No credit could be carried forward from your (a): the working cannot be carried "
                                 "on from it")
    assert part.not_carried.startswith("OverflowError: math range error at exgen/mechanics/belts.py:")
    right = next(p for p in result.parts if p.part_id == "b")
    assert not right.not_carried and right.message == "correct"


def test_the_report_lists_each_part_not_carried_and_why(bank, tmp_path):
    variant = make_variant(bank.get("belts.flat_belt_power"), 3)
    question = grade_variant(variant, {"a": "1000000 deg", "c": "1 kW", "d": "1 kW"})
    sheet = SheetResult(Student("s1"), GRADED, question.max_points, questions=(question,))
    assignment = Assignment("hw", "Homework", (QuestionSpec("q1", variant.template.id),))
    page = report_page(BatchResult(assignment, (Column(1, "q1", variant.template.id, question.max_points),), (sheet,)))
    section = page.split("## Error carried forward not worked", 1)[1]
    assert "- s1, q1 (c): OverflowError: math range error at exgen/mechanics/belts.py:" in section
    assert "- s1, q1 (d): OverflowError" in section


def test_a_type_error_in_a_comparison_is_raised_not_marked_wrong(bank, monkeypatch):
    """A defect in an answer type speaks: it is not taken for a wrong answer."""
    from exgen.answertypes import number

    def broken(self, given, expected, part, widen=1.0):
        raise TypeError("unsupported operand")

    monkeypatch.setattr(number.Number, "matches", broken)
    variant = make_variant(bank.get("belts.flat_belt_power"), 3)
    with pytest.raises(TypeError, match="unsupported operand"):
        grade_variant(variant, {"b": "5 m/s"})


def test_a_key_error_while_carrying_forward_is_raised_not_taken_for_no_credit(bank, monkeypatch):
    from exgen.answertypes import number

    def broken(self, part, value, variant):
        raise KeyError("theta")

    monkeypatch.setattr(number.Number, "overrides", broken)
    variant = make_variant(bank.get("belts.flat_belt_power"), 3)
    with pytest.raises(KeyError):
        grade_variant(variant, {"a": "150 deg", "c": "1 kW"})


def _x(template, seed) -> float:
    return float(_first_draw(template, seed)["x"])


def _first_draw(template, seed) -> dict:
    return {k: str(v) for k, v in draw_values(template, generator(seed)).items()}
