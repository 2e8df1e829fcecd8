"""A sentence that names exactly one choice reads as that choice ("to the left", "Left.", "It is not
balanced."); one that names none, two, or says "not" outside the choice's own words stays a format problem,
so a student is asked to write one word rather than marked on a guess."""
import pytest

from exgen.answertypes import answer_type
from exgen.errors import FormatProblem
from exgen.load.template import PartSpec


def read(text: str, *choices: str):
    spec = PartSpec("a", "which?", "x", type="choice", options={"choices": choices})
    return answer_type(spec).read(text, spec)


@pytest.mark.parametrize("text, choices, meant", [
    ("Left.", ("left", "right"), "left"),
    ("to the left", ("left", "right"), "left"),
    ("'left'", ("left", "right"), "left"),
    ("the left spring is stretched", ("left", "right"), "left"),
    ("Left (tension)", ("left", "right"), "left"),
    ("It is not balanced.", ("balanced", "not balanced"), "not balanced"),   # the longer choice holds "not"
    ("the engine is balanced", ("balanced", "not balanced"), "balanced"),
    ("it is a double rocker", ("crank-rocker", "double-rocker", "double-crank"), "double-rocker"),
    ("crossing b", ("A", "B", "C"), "B"),
    ("the counter clockwise one", ("clockwise", "counter-clockwise"), "counter-clockwise"),
])
def test_a_sentence_naming_one_choice_reads_as_it(text, choices, meant):
    spec = PartSpec("a", "which?", "x", type="choice", options={"choices": choices})
    given = read(text, *choices)
    assert answer_type(spec).matches(given.value, meant, spec)
    assert all(not answer_type(spec).matches(given.value, c, spec) for c in choices if c != meant)


@pytest.mark.parametrize("text, choices", [
    ("left, right", ("left", "right")),
    ("not left", ("left", "right")),
    ("a crank-rocker, not a double-rocker", ("crank-rocker", "double-rocker")),
    ("B and D", ("A", "B", "C", "D")),
    ("leftward", ("left", "right")),
    ("it changes", ("increase", "decrease")),
    ("", ("left", "right")),
])
def test_none_two_or_a_negation_is_still_a_format_problem(text, choices):
    with pytest.raises(FormatProblem):
        read(text, *choices)
