"""The comparators of each answer type: each method against a table of near and far values."""
import math

import pytest

from exgen.answertypes import answer_type
from exgen.answertypes.angle import angle
from exgen.answertypes.choice import choice
from exgen.answertypes.integer import integer
from exgen.answertypes.number import numeric
from exgen.load.template import PartSpec, Tolerance


@pytest.mark.parametrize("given, expected, kwargs, ok", [
    (100.0, 100.0, {}, True),
    (100.9, 100.0, {}, True),
    (99.1, 100.0, {}, True),
    (101.1, 100.0, {}, False),
    (-100.5, -100.0, {}, True),
    (100.0, -100.0, {}, False),
    (0.0, 0.0, {}, True),
    (1e-9, 0.0, {}, False),
    (1e-9, 0.0, {"abs_tol": 1e-6}, True),
    (104.0, 100.0, {"rel": 0.05}, True),
    (math.nan, 100.0, {}, False),
    (math.inf, 100.0, {}, False),
    (100.0, math.nan, {}, False),
    # significant figures: within half a unit in the last figure asked for
    (168.8, 168.84, {"sig": 4}, True),
    (168.9, 168.86, {"sig": 4}, True),
    (168.9, 168.84, {"sig": 4}, False),
    (169.0, 168.84, {"sig": 4}, False),
    (170.0, 168.84, {"sig": 2}, True),
    (0.00124, 0.001236, {"sig": 3}, True),
])
def test_numeric(given, expected, kwargs, ok):
    assert numeric(given, expected, **kwargs) is ok


@pytest.mark.parametrize("given, expected, ok", [
    (218.0, 218.0, True),
    (-142.0, 218.0, True),        # the same direction
    (578.0, 218.0, True),
    (218.4, 218.0, True),
    (218.6, 218.0, False),
    (359.8, 0.1, True),           # across the wrap
    (0.2, 359.9, True),
    (180.0, 0.0, False),
    (math.nan, 0.0, False),
])
def test_angle(given, expected, ok):
    assert angle(given, expected) is ok


@pytest.mark.parametrize("given, expected, ok", [
    (4, 4, True), (4.0, 4, True), (3.0, 4, False), (4.000001, 4, False), (5, 4, False), (math.inf, 4, False),
])
def test_integer(given, expected, ok):
    assert integer(given, expected) is ok


@pytest.mark.parametrize("given, expected, aliases, ok", [
    ("increase", "increase", None, True),
    ("  Increase ", "increase", None, True),
    ("INCREASE", "increase", None, True),
    ("crossed-belt", "crossed belt", None, True),
    ("crossed_belt", "Crossed Belt", None, True),
    ("decrease", "increase", None, False),
    ("ccw", "anticlockwise", {"ccw": "anticlockwise"}, True),
    ("CCW", "anticlockwise", {"ccw": "anticlockwise"}, True),
    ("cw", "anticlockwise", {"ccw": "anticlockwise"}, False),
])
def test_choice(given, expected, aliases, ok):
    assert choice(given, expected, aliases) is ok


@pytest.mark.parametrize("spec, given, expected, ok", [
    (PartSpec("a", "x", "v", "m/s"), 5.04, 5.0, True),
    (PartSpec("a", "x", "v", "m/s"), 5.06, 5.0, False),
    (PartSpec("a", "x", "v", "m/s", tol=Tolerance(rel=0.0, abs=0.1)), 5.09, 5.0, True),
    (PartSpec("a", "x", "th", "deg", type="angle", tol=Tolerance(rel=0.0, abs=0.5)), -142.2, 218.0, True),
    # an angle asked in rad: the absolute tolerance is still in degrees
    (PartSpec("a", "x", "th", "rad", type="angle", tol=Tolerance(rel=0.0, abs=0.5)), -math.pi + 0.005, math.pi, True),
    (PartSpec("a", "x", "th", "rad", type="angle", tol=Tolerance(rel=0.0, abs=0.5)), 0.1, math.pi, False),
    (PartSpec("a", "x", "n", "", type="integer", tol=Tolerance(0.0)), 5.0, 5, True),
    (PartSpec("a", "x", "t", "", type="choice", options={"choices": ("up", "down")}), "Up", "up", True),
])
def test_for_part(spec, given, expected, ok):
    assert answer_type(spec).matches(given, expected, spec) is ok


def test_widened_comparator_accepts_what_the_plain_one_does_not():
    spec = PartSpec("a", "x", "v", "m/s")
    assert not answer_type(spec).matches(5.1, 5.0, spec)
    assert answer_type(spec).matches(5.1, 5.0, spec, widen=3)


@pytest.mark.parametrize("text, value", [("five", 5), ("Five belts.", 5), ("twelve teeth", 12), ("zero", 0)])
def test_a_count_may_be_written_in_words(text, value):
    spec = PartSpec("a", "the number of belts", "n", type="integer", tol=Tolerance(0.0))
    assert answer_type(spec).read(text, spec).value == value


@pytest.mark.parametrize("text", ["one two", "twentyone", "fivebelts"])
def test_a_count_in_words_is_one_word_for_one_number(text):
    from exgen.errors import FormatProblem

    spec = PartSpec("a", "the number of belts", "n", type="integer", tol=Tolerance(0.0))
    with pytest.raises(FormatProblem):
        answer_type(spec).read(text, spec)


@pytest.mark.parametrize("tol", [Tolerance(rel=0.01), Tolerance(rel=0.002, abs=0.05), Tolerance(rel=0.0, abs=0.5),
                                 Tolerance(rel=0.0, sig=3), Tolerance(rel=0.0, abs=1e-3, sig=2), Tolerance(rel=0.3)])
@pytest.mark.parametrize("widen", [0.2, 1.0, 3.0])
def test_no_value_a_number_matches_lies_beyond_its_reach(tol, widen):
    """`reach` bounds how far a matching expected value lies, so a caller may look no further: checked on
    values at, around and across its edge, of every size and sign, and around powers of ten (sig figures)."""
    import random

    spec = PartSpec("a", "x", "v", "N", tol=tol)
    kind = answer_type(spec)
    rng = random.Random(5)
    for _ in range(4000):
        given = rng.choice([1, -1]) * 10 ** rng.uniform(-4, 6) * rng.choice([1, 1, 0.99999, 1.00001])
        reach = kind.reach(given, spec, widen)
        if reach is None:
            continue
        for off in (reach, reach * 0.999999, reach * 1.000001, reach * 2, reach * 0.5, reach * rng.random()):
            for expected in (given - off, given + off, math.nextafter(given + off, math.inf),
                             math.nextafter(given - off, -math.inf)):
                if kind.matches(given, expected, spec, widen):
                    assert abs(expected - given) <= reach, (given, expected, reach)
    assert kind.reach(math.inf, spec, widen) is None
    assert (kind.reach(0.0, spec, widen) is None) is (tol.rel * widen >= 0.5)  # no useful bound so wide


def test_an_exact_type_reaches_no_further_than_its_value_and_a_direction_has_no_reach():
    count = PartSpec("a", "x", "n", "", type="integer", tol=Tolerance(0.0))
    assert answer_type(count).reach(5, count) == 0.0 and answer_type(count).matches(5.0, 5, count)
    turn = PartSpec("a", "x", "th", "deg", type="angle", tol=Tolerance(rel=0.0, abs=0.5))
    assert answer_type(turn).reach(10.0, turn) is None  # 370° is 10° as a direction
