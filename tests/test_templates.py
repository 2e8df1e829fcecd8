"""Every template, over many seeds: valid draws, finite answers, consistent ECF, a key that grades itself."""
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from exgen.check.validate import check_variant, validate_template
from exgen.load.bank import load_bank
from exgen.solve.variant import make_variant

TEMPLATE_IDS = sorted(t.id for t in load_bank())


@pytest.mark.parametrize("template_id", TEMPLATE_IDS)
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(min_value=0, max_value=2**65 - 1))  # sheets below 2^64, practice above
def test_any_seed_gives_a_valid_problem_whose_key_scores_full_marks(bank, template_id, seed):
    variant = make_variant(bank.get(template_id), seed)
    assert check_variant(variant) == []


@pytest.mark.parametrize("template_id", TEMPLATE_IDS)
def test_template_validates_cleanly(bank, template_id):
    report = validate_template(bank.get(template_id), seeds=150)
    assert report.problems == [] and report.warnings == []
    assert report.distinct > 0.95
