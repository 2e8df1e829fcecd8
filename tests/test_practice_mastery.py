"""Mastery: a weighted success rate with a Beta(1, 1) prior, and the next problem drawn by weakness."""
import random
from collections import Counter

import pytest

from practice.mastery import Mastery, Outcome, PartOutcome, choose, mastery, problem_outcome


def right(n=1):
    return [Outcome(1.0, 1.0)] * n


def wrong(n=1):
    return [Outcome(0.0, 1.0)] * n


def test_nothing_tried_is_an_even_guess_and_not_started():
    estimate = mastery([])
    assert estimate.mean == 0.5 and estimate.level == "not started"


def test_mastered_needs_five_right_in_a_row_from_nothing():
    """Mastered from 0.8: four right give (1 + 0.8⁰ + ... + 0.8³)/(2 + the same) = 3.952/4.952 = 0.798."""
    assert mastery(right(4)).mean == pytest.approx(3.952 / 4.952) and mastery(right(4)).level == "learning"
    assert mastery(right(5)).mean == pytest.approx(4.3616 / 5.3616) and mastery(right(5)).level == "mastered"


def test_recent_problems_count_most():
    caught_up = mastery(wrong(5) + right(5))
    fell_behind = mastery(right(5) + wrong(5))
    assert caught_up.mean > 0.6 > 0.4 > fell_behind.mean
    assert fell_behind.level == "weak"


def test_the_estimate_is_the_weighted_rate_with_its_prior():
    """Right, then wrong: the older problem counts 0.8, the latest 1, over the prior Beta(1, 1)."""
    estimate = mastery([Outcome(1.0, 1.0), Outcome(0.0, 1.0)])
    assert estimate.alpha == pytest.approx(1.8) and estimate.beta == pytest.approx(2)
    assert estimate.mean == pytest.approx(1.8 / 3.8)


@pytest.mark.parametrize("parts, expected", [
    ([PartOutcome(1, answered=True, right=True), PartOutcome(1, answered=True, right=False)], Outcome(0.5, 1.0)),
    ([PartOutcome(2, answered=True, right=True, hinted=True), PartOutcome(2)], Outcome(0.5, 0.5)),  # half after hints
    ([PartOutcome(1, answered=True, right=True), PartOutcome(1, solution_first=True)], Outcome(0.5, 1.0)),
    ([PartOutcome(1), PartOutcome(1)], None),  # skipped: no evidence either way
])
def test_a_problem_counts_the_parts_that_show_something(parts, expected):
    assert problem_outcome(parts) == expected


def test_weak_topics_come_up_more_and_mastered_ones_still_now_and_then():
    rng = random.Random(12)
    candidates = {"belts": ["belts.a", "belts.b"], "gears": ["gears.a"], "vibration": ["vibration.a"]}
    topics = {"belts": mastery(wrong(4)), "gears": mastery(right(8))}  # vibration: not started
    counts = Counter(choose(candidates, topics, {}, rng).split(".")[0] for _ in range(3000))
    assert counts["belts"] > counts["vibration"] > counts["gears"] > 0
    weak, new, strong = (1 - topics["belts"].mean, 0.5, max(0.05, 1 - topics["gears"].mean))  # a floor of 0.05
    assert counts["belts"] / 3000 == pytest.approx(weak / (weak + new + strong), abs=0.03)


def test_within_a_topic_the_weaker_template_comes_up_more():
    rng = random.Random(3)
    counts = Counter(choose({"gears": ["gears.a", "gears.b"]}, {}, {"gears.a": mastery(right(6)),
                                                                   "gears.b": mastery(wrong(3))}, rng)
                     for _ in range(2000))
    assert counts["gears.b"] > 3 * counts["gears.a"] > 0


def test_the_template_just_practised_is_avoided_when_another_exists():
    rng = random.Random(5)
    assert {choose({"belts": ["belts.a", "belts.b"]}, {}, {}, rng, avoid="belts.a") for _ in range(50)} == {"belts.b"}
    assert choose({"belts": ["belts.a"]}, {}, {}, rng, avoid="belts.a") == "belts.a"


def test_level_words():
    assert Mastery(1, 1, 0).level == "not started"
    assert Mastery(9, 1, 8).level == "mastered"
    assert Mastery(2, 1, 1).level == "learning"
    assert Mastery(1, 3, 2).level == "weak"
