"""A key lists the givens its variant uses, and only those: one idler drawn, no second idler's teeth."""
import pytest

from exgen.errors import InvalidDraw, SolverFailure
from exgen.figures import figure_svg
from exgen.load.bank import load_bank
from exgen.render.solution import solution
from exgen.render.text import variant_text
from exgen.solve.variant import build_variant, make_variant

TEMPLATE_IDS = sorted(t.id for t in load_bank())


def _with_idlers(template, count: int):
    return next(v for v in (make_variant(template, seed) for seed in range(200)) if v.param("idlers").text == str(count))


def test_a_train_with_one_idler_lists_no_second_idler(bank):
    template = bank.get("gears.simple_train")
    one, two = _with_idlers(template, 1), _with_idlers(template, 2)
    assert "tb" not in {g.name for g in solution(one).given}
    assert "second idler" not in variant_text(one, key=True)
    assert "tb" in {g.name for g in solution(two).given} and "second idler" in variant_text(two, key=True)


def _other_values(spec, value) -> list:
    """Other allowed values of a drawn given, the ends of its range included (a text may test for a zero)."""
    if spec.derived:
        return []
    if spec.is_range:
        near = [value - spec.step, value + spec.step, spec.min, spec.max]
        return list(dict.fromkeys(v for v in near if spec.min <= v <= spec.max and v != value))
    return [c for c in spec.choices if c != value]


def _face(variant):
    """What a variant shows of its givens besides its figure: its text and every step's value and formula."""
    return (variant.statement, tuple(variant.asks.values()),
            tuple((s.name, repr(s.value), s.formula) for s in variant.steps))


def _changes(variant, other) -> bool:
    """Whether `other` shows anything differently from `variant` (the figure drawn only when the rest agrees)."""
    return _face(other) != _face(variant) or figure_svg(other) != figure_svg(variant)


def _changes_with(template, variant, values) -> bool:
    try:
        return _changes(variant, build_variant(template, values, check=False))
    except (InvalidDraw, SolverFailure):
        return True  # the solver could not work without it: it is used


@pytest.mark.parametrize("template_id", TEMPLATE_IDS)
def test_a_given_is_listed_exactly_when_changing_it_changes_the_problem(bank, template_id):
    """Independent of how the variant tracks use: change one given alone to each of a few other values (the
    others, those worked out from it included, held) and see whether the statement, the asks, the working or
    the figure change."""
    template = bank.get(template_id)
    for seed in (0, 1):
        variant = make_variant(template, seed)
        values = {p.name: p.exact for p in variant.params}
        listed = {g.name for g in solution(variant).given}
        for spec in template.params:
            others = _other_values(spec, values[spec.name])
            if not others:
                continue
            changed = any(_changes_with(template, variant, {**values, spec.name: other}) for other in others)
            if not spec.given:  # it only chooses what the figure draws: never listed, and it does draw something
                assert spec.name not in listed and changed, (seed, spec.name)
                continue
            assert (spec.name in listed) == changed, (
                f"seed {seed}: {spec.name} is {'listed' if spec.name in listed else 'left out'} but changing it "
                f"{'changes' if changed else 'does not change'} the problem")
