"""Solving a template for a textbook problem's data in the tests: the answers, the variant and its warnings."""
from exgen.check.given import solve
from exgen.cli import solution_json


def solved(bank, template_id, **given):
    """The variant for the values given, each part's answer (in the unit asked), and the warnings."""
    variant, warnings = solve(bank.get(template_id), {k: str(v) for k, v in given.items()})
    return variant, {part: answer.value for part, answer in variant.answers.items()}, warnings


def answers(bank, template_id, **given):
    """Each part's answer (in the unit asked), the variant, and the warnings for the values given."""
    variant, got, warnings = solved(bank, template_id, **given)
    return got, variant, warnings


def steps(variant):
    """Every step's value by name (SI, or the step's own unit)."""
    return {s.name: s.value for s in variant.steps}


def step(variant, name):
    return variant.step(name).value


def printed_steps(bank, template_id, **given):
    """Every step `exgen solve --json` prints, by name, in SI (angles in radians)."""
    variant, _, _ = solved(bank, template_id, **given)
    return {s["name"]: s["value"] for s in solution_json(variant)["steps"]}


def answers_and_steps(bank, template_id, **given):
    """Each part's answer, every step's value by name, and the warnings for the values given."""
    got, variant, warnings = answers(bank, template_id, **given)
    return got, steps(variant), warnings
