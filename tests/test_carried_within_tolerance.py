"""A later part worked from earlier answers that were right but not the key's own value (a length read off a
drawing, a figure rounded) is right: over the whole bank, each part is graded with every number or angle it
uses moved to near the edge of its tolerance, and with its own answer worked from those values."""
import math

import pytest

from exgen.answertypes import answer_type
from exgen.errors import ExgenError
from exgen.load.bank import load_bank
from exgen.solve.variant import answer_for, make_variant, rerun
from graders.grade import grade_variant

SEEDS = range(4)
#: How far into its tolerance an earlier answer is moved: far enough that later parts worked from it can fall
#: outside their own tolerance, near enough that rounding it to the key's figures keeps it right.
SHARE = 0.7


def nudged(value, part):
    """The value moved SHARE of its tolerance up, for numbers and angles without a significant-figure rule."""
    kind, tol = answer_type(part), part.tol
    if kind.name not in ("number", "angle") or tol.sig or not isinstance(value, float):
        return None
    step = max(tol.abs, tol.rel * abs(value))
    if kind.name == "angle":
        step = max(tol.abs, tol.rel * abs(value * kind._to_deg(part))) / kind._to_deg(part)
    return value + SHARE * step if step else None


@pytest.mark.parametrize("template_id", sorted(load_bank().templates))
def test_a_part_worked_from_earlier_answers_right_within_tolerance_is_right(bank, template_id):
    template = bank.get(template_id)
    checked = 0
    for seed in SEEDS:
        variant = make_variant(template, seed)
        for part in (p for p in template.parts if p.uses):
            answers, overrides = {}, {}
            for used_id in part.uses:
                used = template.part(used_id)
                moved = nudged(variant.answers[used_id].value, used)
                if moved is None:
                    continue
                kind = answer_type(used)
                answers[used_id] = kind.text(moved, used)
                read = kind.read(answers[used_id], used).value
                overrides.update(kind.overrides(used, read, variant))
            if not answers:
                continue
            try:
                worked = answer_for(part, rerun(variant, overrides))
            except ExgenError:        # the working refuses the moved values: nothing to carry
                continue
            if isinstance(worked.value, float) and not math.isfinite(worked.value):
                continue
            answers[part.id] = answer_type(part).text(worked.value, part)
            result = next(r for r in grade_variant(variant, answers).parts if r.part_id == part.id)
            assert result.status in ("correct", "carried"), (seed, part.id, answers, result.message)
            checked += 1
    if any(nudged(0.5, p) is not None for q in template.parts for p in map(template.part, q.uses)):
        assert checked, "no part of this template was checked"
