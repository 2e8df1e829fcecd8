"""How close a wrong answer must lie to another student's key to be a sign of copying, in numbers: a key
copied is typed to four figures or so, so it lies within a fifth of the part's tolerance of that key; a
wrong answer further off is near someone's key by chance and is no evidence."""
import pytest

from exgen.load.template import PartSpec, Tolerance
from graders.copying import _other_variant

FORCE = PartSpec("a", "the force", "F", unit="N", tol=Tolerance(rel=0.01))  # graded to 1 %


def evidence(typed: float) -> list[str]:
    """What s2's wrong answers say, when s1's keys are 100 N and 50 N and s2's are 120 N and 60 N."""
    keys = {("q1", "a"): {"s1": (100.0, FORCE), "s2": (120.0, FORCE)},
            ("q1", "b"): {"s1": (50.0, FORCE), "s2": (60.0, FORCE)}}
    answers = {("q1", "a"): {"s2": (typed, f"{typed} N")}, ("q1", "b"): {"s2": (50.0, "50 N")}}
    signs = _other_variant(answers, keys)
    return [line for sign in signs for line in sign["evidence"]]


@pytest.mark.parametrize("typed, sign", [
    (100.0, True), (100.19, True), (99.81, True),    # within 0.2 % of s1's key: a fifth of the 1 % tolerance
    (100.21, False), (99.79, False), (100.9, False),  # within the tolerance, but further than a fifth of it
])
def test_an_answer_is_a_copy_within_a_fifth_of_the_tolerance_of_the_other_key(typed, sign):
    found = evidence(typed)
    assert ("q1 (a): " + f"{typed} N is s1's answer" in " ".join(found)) is sign
    assert len(found) == (2 if sign else 0)  # two parts make a sign; one alone (b) does not
