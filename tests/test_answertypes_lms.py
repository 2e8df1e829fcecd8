"""What each answer type becomes in a learning system (AnswerType.lms_gaps): asked of the registry, for
every registered type, with the tolerance the grader applies written as the absolute one formats know."""
from fractions import Fraction

import pytest

from exgen.answertypes import answer_type, registry
from exgen.answertypes.lms import NoLmsForm, wrong_numbers
from exgen.answertypes.polar import Polar
from exgen.load.template import PartSpec, Tolerance

SAMPLE_VALUES = {"number": 12.5, "angle": 218.0, "integer": 4, "choice": "increase", "polar": Polar(1.5, 30.0)}


@pytest.mark.parametrize("name", sorted(registry()))
def test_every_type_gives_gaps_or_says_why_it_cannot(name):
    kind = answer_type(name)
    part = kind.sample_part()
    if name not in SAMPLE_VALUES:
        with pytest.raises(NoLmsForm) as caught:
            kind.lms_gaps(part, None, {})
        assert str(caught.value)
        return
    gaps = kind.lms_gaps(part, SAMPLE_VALUES[name], {})
    assert gaps and sum(g.share for g in gaps) == 1


def test_a_number_is_right_within_its_relative_tolerance_or_its_floor_as_an_absolute_one():
    kind = answer_type("number")
    part = PartSpec("a", "P", "P", "kW", tol=Tolerance(rel=0.02, abs=0.5))
    (gap,) = kind.lms_gaps(part, 10.0, {})
    assert gap.tolerance == 0.5 and gap.unit == "kW"
    (gap,) = kind.lms_gaps(part, 100.0, {})
    assert gap.tolerance == pytest.approx(2.0)
    assert gap.units[0] == ("kW", 1.0) and ("W", 1000.0) in gap.units
    assert gap.otherwise == "not within 2 % or 0.5 kW of the expected value"


def test_significant_figures_become_half_a_unit_in_the_last_figure():
    part = PartSpec("a", "P", "P", "kW", tol=Tolerance(rel=0.0, sig=3))
    (gap,) = answer_type("number").lms_gaps(part, 123.456, {})
    assert gap.tolerance == pytest.approx(0.51)


def test_an_angle_is_also_right_a_turn_either_way():
    kind = answer_type("angle")
    part = kind.sample_part()
    (gap,) = kind.lms_gaps(part, 350.0, {"mirrored": (10.0, "measured the other way")})
    assert gap.values == (350.0, -10.0, 710.0) and gap.tolerance == 0.5
    assert [w.value for w in gap.wrong] == [10.0]


def test_a_whole_number_is_exact():
    (gap,) = answer_type("integer").lms_gaps(answer_type("integer").sample_part(), 4, {"rounded_down": (3, "round up")})
    assert gap.tolerance == 0 and gap.whole and gap.wrong[0].value == 3.0


def test_a_polar_answer_is_two_numbers_for_half_the_marks_each_and_its_mistakes_go_to_the_wrong_half():
    kind = answer_type("polar")
    part = kind.sample_part()
    mistakes = {"opposite": (Polar(1.5, 210.0), "opposite"), "scalar_sum": (Polar(2.5, 30.0), "added as numbers")}
    size, direction = kind.lms_gaps(part, Polar(1.5, 30.0), mistakes)
    assert (size.key, direction.key) == ("size", "angle") and size.share == direction.share == Fraction(1, 2)
    assert size.tolerance == pytest.approx(0.015) and direction.tolerance == 0.5
    assert [w.name for w in size.wrong] == ["scalar_sum"] and [w.name for w in direction.wrong] == ["opposite"]
    assert direction.values == (30.0, -330.0, 390.0)


def test_a_polar_gap_names_no_slip_whose_window_meets_the_right_one():
    """A gap reads one half: a size just outside the tolerance, typed with the right angle, must not be told
    of a slip whose size is as near (it differs in its angle), nor an angle of a slip whose angle is."""
    kind = answer_type("polar")
    part = kind.sample_part()                      # 1 % in size, 0.5° in angle
    key = Polar(100.0, 30.0)
    mistakes = {"near_size": (Polar(101.5, 200.0), "near in size"), "near_angle": (Polar(300.0, 30.8), "near in angle"),
                "apart": (Polar(103.0, 32.0), "apart in both")}
    size, direction = kind.lms_gaps(part, key, mistakes)
    assert [w.name for w in size.wrong] == ["near_angle", "apart"]
    assert [w.name for w in direction.wrong] == ["near_size", "apart"]
    just_out = key.magnitude * (1 + 1.001 * part.tol.rel)
    assert not any(abs(just_out - w.value) <= w.tolerance for w in size.wrong)


def test_a_choice_carries_the_first_mistake_that_leads_to_each_wrong_choice():
    kind = answer_type("choice")
    part = kind.sample_part()
    (gap,) = kind.lms_gaps(part, "increase", {"a": ("decrease", "first"), "b": ("Decrease", "second")})
    assert gap.correct == "increase" and [(w.value, w.message) for w in gap.wrong] == [("decrease", "first")]


def test_mistakes_that_would_pass_for_the_answer_or_for_an_earlier_mistake_are_left_out():
    mistakes = {"near": (10.05, "near"), "far": (20.0, "far"), "again": (20.1, "again"), "nan": (float("nan"), "x"),
                "text": ("word", "x")}
    found = wrong_numbers(mistakes, lambda v: 0.01 * abs(v), (10.0,))
    assert [w.name for w in found] == ["far"]
    assert found[0].tolerance == pytest.approx(0.2)
