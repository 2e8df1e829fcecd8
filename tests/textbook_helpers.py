"""Solving a template for a textbook problem's data in the tests: the answers, the variant and its warnings."""
from exgen.solve import solve


def answers(bank, template_id, **given):
    """Each part's answer (in the unit asked), the variant, and the warnings for the values given."""
    variant, warnings = solve(bank.get(template_id), {k: str(v) for k, v in given.items()})
    return {part: answer.value for part, answer in variant.answers.items()}, variant, warnings


def steps(variant):
    """Every step's value by name (SI, or the step's own unit)."""
    return {s.name: s.value for s in variant.steps}
