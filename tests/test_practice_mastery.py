"""Mastery: an Elo rating of the student against the parts answered, its properties held over random
histories, what help costs, and the next problem drawn by weakness."""
import math
import random
from collections import Counter

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from practice.mastery import Evidence, Mastery, PartEvents, choose, mastery, problem_evidence

#: What the page states help costs, and the levels: a hint a quarter of its part (three quarters at most), the
#: worked solution half of each part not yet answered; mastered from 80 %, weak below 50 %.
HINT, HINTS_AT_MOST, SOLUTION, MASTERED, WEAK = 0.25, 0.75, 0.5, 80, 50


def right(n=1, parts=1):
    return [[Evidence(True, 1 / parts)] * parts] * n


def wrong(n=1, parts=1):
    return [[Evidence(False, 1 / parts)] * parts] * n


weights = st.floats(min_value=0.01, max_value=1.0)
problems = st.lists(st.lists(st.builds(Evidence, st.booleans(), weights), min_size=1, max_size=5), max_size=25)


def test_nothing_tried_is_an_even_guess_and_not_started():
    estimate = mastery([])
    assert estimate.mean == 0.5 and estimate.level == "not started" and estimate.text == "not started"


@pytest.mark.parametrize("parts", [1, 2, 3, 5])
def test_mastered_needs_five_right_problems_in_a_row_from_nothing(parts):
    assert mastery(right(4, parts)).level == "learning"
    assert mastery(right(5, parts)).level == "mastered"


def test_recent_problems_count_most():
    caught_up = mastery(wrong(5) + right(5))
    fell_behind = mastery(right(5) + wrong(5))
    assert caught_up.mean > 0.6 > 0.4 > fell_behind.mean
    assert fell_behind.level == "weak"


@settings(max_examples=300, deadline=None)
@given(problems, st.lists(st.builds(Evidence, st.booleans(), weights), min_size=1, max_size=4))
def test_a_right_answer_never_lowers_mastery_and_a_wrong_one_never_raises_it(history, new):
    """Within a problem or as a new one: a right (a) alone in a new problem lowered belts from 67 % to 66 %."""
    before = mastery(history).mean
    for k, evidence in enumerate(new):  # the new problem's evidence arriving piece by piece
        after = mastery(history + [new[:k + 1]]).mean
        assert after >= before if evidence.right else after <= before
        before = after


@settings(max_examples=300, deadline=None)
@given(problems, st.data())
def test_more_evidence_of_a_right_answer_never_shows_less(history, data):
    """Put any wrong answer of a history right, or give a right answer more weight, and the end shows no less."""
    if not any(history):
        return
    i = data.draw(st.integers(0, len(history) - 1))
    j = data.draw(st.integers(0, len(history[i]) - 1))
    old = history[i][j]
    better = [list(p) for p in history]
    better[i][j] = Evidence(True, old.weight)
    heavier = [list(p) for p in history]
    heavier[i][j] = Evidence(old.right, min(1.0, old.weight * data.draw(st.floats(1.0, 4.0))))
    assert mastery(better).mean >= mastery(history).mean - 1e-12
    moved = mastery(heavier).mean - mastery(history).mean
    assert moved >= -1e-12 if old.right else moved <= 1e-12


@settings(max_examples=200, deadline=None)
@given(problems, st.integers(1, 8))
def test_a_run_of_right_answers_shows_more_the_longer_it_is(history, n):
    runs = [mastery(history + right(k)).mean for k in range(n + 1)]
    assert runs == sorted(runs)
    falls = [mastery(history + wrong(k)).mean for k in range(n + 1)]
    assert falls == sorted(falls, reverse=True)


@settings(max_examples=500, deadline=None)
@given(st.floats(-8, 8))
def test_the_level_shown_is_read_from_the_percentage_shown(rating):
    estimate = Mastery(rating, 3)
    assert estimate.percent == math.floor(100 * estimate.mean + 1e-9) and estimate.text == f"{estimate.percent} %"
    expected = "mastered" if estimate.percent >= MASTERED else "weak" if estimate.percent < WEAK else "learning"
    assert estimate.level == expected


@pytest.mark.parametrize("mean, shown, level", [(0.796, "79 %", "learning"), (0.8, "80 %", "mastered"),
                                                (0.4999, "49 %", "weak"), (0.5, "50 %", "learning")])
def test_the_figure_and_the_level_agree_at_the_thresholds(mean, shown, level):
    """"Belts: 80 % (learning)" then "80 % (mastered)": the figure was rounded and the level was not."""
    estimate = Mastery(math.log(mean / (1 - mean)), 1)
    assert (estimate.text, estimate.level) == (shown, level)


def test_a_hint_costs_its_share_of_the_part_and_the_answer_gets_the_rest():
    evidence = problem_evidence([PartEvents(0.5, (10.0, True), (5.0,)), PartEvents(0.5, (20.0, True))])
    assert evidence == (Evidence(False, 0.5 * HINT), Evidence(True, 0.5 * (1 - HINT)), Evidence(True, 0.5))


def test_hints_after_the_first_answer_cost_nothing_and_their_cost_is_capped():
    after = problem_evidence([PartEvents(1.0, (10.0, False), (11.0, 12.0))])
    assert after == (Evidence(False, 1.0),)
    many = problem_evidence([PartEvents(1.0, (10.0, True), tuple(float(t) for t in range(8)))])
    assert sum(e.weight for e in many if not e.right) == pytest.approx(HINTS_AT_MOST)
    assert many[-1] == Evidence(True, pytest.approx(1 - HINTS_AT_MOST))


def test_the_solution_costs_the_parts_not_yet_answered_and_later_answers_count_nothing():
    evidence = problem_evidence([PartEvents(0.5, (1.0, True)), PartEvents(0.5, (9.0, True))], solution=5.0)
    assert evidence == (Evidence(True, 0.5), Evidence(False, 0.5 * SOLUTION))


def test_a_problem_left_alone_is_no_evidence():
    assert problem_evidence([PartEvents(0.5), PartEvents(0.5)]) == ()
    assert mastery(right(3) + [[]]) == mastery(right(3))


@settings(max_examples=200, deadline=None)
@given(problems, st.integers(1, 4), st.integers(0, 3))
def test_peeking_costs_what_the_page_states_and_less_than_failing(history, parts, hints):
    """Opening a hint and the solution without answering took governors from 53 % to 39 %: a whole failed problem."""
    share = 1 / parts
    peek = problem_evidence([PartEvents(share, None, tuple(float(h) for h in range(hints)))] +
                            [PartEvents(share) for _ in range(parts - 1)], solution=10.0)
    hint_cost = min(hints * HINT, HINTS_AT_MOST)
    stated = hint_cost + min(SOLUTION, 1 - hint_cost) + (parts - 1) * SOLUTION
    assert sum(e.weight for e in peek) == pytest.approx(stated * share) and not any(e.right for e in peek)
    failed = mastery(history + wrong(1, parts)).mean
    assert failed <= mastery(history + [list(peek)]).mean <= mastery(history).mean
    if hints < 2:
        assert failed < mastery(history + [list(peek)]).mean


def test_weak_topics_come_up_more_and_mastered_ones_still_now_and_then():
    rng = random.Random(12)
    candidates = {"belts": ["belts.a", "belts.b"], "gears": ["gears.a"], "vibration": ["vibration.a"]}
    topics = {"belts": mastery(wrong(4)), "gears": mastery(right(8))}  # vibration: not started
    counts = Counter(choose(candidates, topics, {}, rng).split(".")[0] for _ in range(3000))
    assert counts["belts"] > counts["vibration"] > counts["gears"] > 0
    weak, new, strong = (1 - topics["belts"].mean, 0.5, max(0.05, 1 - topics["gears"].mean))
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


def test_the_next_hint_costs_what_problem_evidence_will_charge():
    from practice.mastery import next_hint_cost

    assert [next_hint_cost(False, False, n) for n in range(5)] == [HINT, HINT, HINT, 0.0, 0.0]
    assert next_hint_cost(True, False, 0) == next_hint_cost(False, True, 0) == 0.0
    for shown in range(5):
        charged = problem_evidence([PartEvents(1.0, None, tuple(float(t) for t in range(shown + 1)))])
        before = problem_evidence([PartEvents(1.0, None, tuple(float(t) for t in range(shown)))])
        assert sum(e.weight for e in charged) - sum(e.weight for e in before) == \
            pytest.approx(next_hint_cost(False, False, shown))
