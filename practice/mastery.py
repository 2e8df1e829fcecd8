"""How well a student knows a topic, and which problem should come next. Pure functions over evidence.

The estimate is an Elo rating of the student against the parts answered (Pelánek, "Applications of the
Elo rating system in adaptive educational systems", Computers & Education 98, 2016): the chance of a
right first answer to a part is σ(θ), and each piece of evidence moves the rating by
    θ ← θ + K·w·(outcome − σ(θ)),
w being the share of a problem's marks it covers. Every part counts as of average difficulty (rating
0): practice runs for one student, offline, with no class to calibrate parts against. Mastery is σ(θ),
from 0.5 with nothing tried.

Why Elo: a right answer always raises the rating and a wrong one always lowers it (outcome − σ(θ) has
the outcome's sign), and since K·w/4 < 1 each update keeps the order of ratings, so a history with any
answer put right, or with more right evidence, never shows less. Bayesian knowledge tracing applies its
chance of learning after every attempt, so that a wrong answer raises a low estimate, and needs four
parameters per skill fitted to a class's data. A constant K forgets old evidence, so a student who has
caught up is seen to: with K = 0.9 five right problems in a row reach MASTERED from nothing, four do not.

Helping costs evidence, on the parts helped: each hint shown before a part's first answer counts as a
wrong answer on HINT_COST of the part (at most MAX_HINT_COST in all), the worked solution as a wrong
answer on SOLUTION_COST of every part not yet answered, and what is left of the part goes to its first
answer. A part answered after the worked solution counts for nothing more; a part left alone, unhelped,
is no evidence at all.

The next problem is drawn at random with weights 1 − mastery (at least FLOOR): first a topic, then a
template within it, so weak topics come up more, mastered ones less but still now and then, and one
not yet tried (0.5) between the two.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Iterable, Mapping, Sequence

K = 0.9
#: The levels, in whole percent as shown: from MASTERED a topic is mastered, below WEAK it is weak.
MASTERED = 80
WEAK = 50
FLOOR = 0.05
HINT_COST = 0.25
MAX_HINT_COST = 0.75
SOLUTION_COST = 0.5


@dataclass(frozen=True)
class Evidence:
    """One outcome on a share of a problem: right or wrong, on `weight` of the problem's marks."""

    right: bool
    weight: float


@dataclass(frozen=True)
class PartEvents:
    """What happened on one part of a problem, as the progress file records it (times in seconds)."""

    share: float                                # the part's share of the problem's marks
    first: tuple[float, bool] | None = None     # when the first readable answer came, and whether it was right
    hints: tuple[float, ...] = ()               # when each of its hints was shown


def problem_evidence(parts: Iterable[PartEvents], solution: float | None = None) -> tuple[Evidence, ...]:
    """A problem's evidence in the order it arose; `solution` is when the worked solution was first shown."""
    events: list[tuple[float, Evidence]] = []
    for part in parts:
        answered = part.first is not None and (solution is None or part.first[0] <= solution)
        until = part.first[0] if answered else (solution if solution is not None else math.inf)
        cost = 0.0
        for at in sorted(h for h in part.hints if h <= until):
            step = min(HINT_COST, MAX_HINT_COST - cost)
            if step <= 0:
                break
            cost += step
            events.append((at, Evidence(False, part.share * step)))
        if answered:
            events.append((part.first[0], Evidence(part.first[1], part.share * (1.0 - cost))))
        elif solution is not None:
            events.append((solution, Evidence(False, part.share * min(SOLUTION_COST, 1.0 - cost))))
    return tuple(e for _, e in sorted(events, key=lambda pair: pair[0]) if e.weight > 0)


def expected(rating: float) -> float:
    """The chance of a right first answer at this rating (a part of average difficulty)."""
    return 1.0 / (1.0 + math.exp(-rating))


@dataclass(frozen=True)
class Mastery:
    rating: float = 0.0
    problems: int = 0     # problems that gave evidence

    @property
    def mean(self) -> float:
        return expected(self.rating)

    @property
    def percent(self) -> int:
        """Mastery in whole percent, rounded down: what every page shows, and what its level is read from,
        so that a topic shown at 80 % is mastered and one at 79 % is not."""
        return math.floor(100 * self.mean + 1e-9)

    @property
    def text(self) -> str:
        return f"{self.percent} %" if self.problems else "not started"

    @property
    def level(self) -> str:
        return level(self.percent) if self.problems else "not started"


def level(percent: int) -> str:
    if percent >= MASTERED:
        return "mastered"
    return "learning" if percent >= WEAK else "weak"


def mastery(problems: Sequence[Sequence[Evidence]]) -> Mastery:
    """The estimate from a topic's (or template's) problems, oldest first, each its evidence in order."""
    estimate = Mastery()
    for evidence in problems:
        estimate = after(estimate, evidence)
    return estimate


def after(estimate: Mastery, evidence: Sequence[Evidence]) -> Mastery:
    """The estimate once one more problem's evidence is in."""
    rating = estimate.rating
    for e in evidence:
        rating += K * e.weight * (e.right - expected(rating))
    return Mastery(rating, estimate.problems + bool(evidence))


def next_hint_cost(answered: bool, solution: bool, hints: int) -> float:
    """What the next hint of a part costs, as a share of the part (problem_evidence's rule)."""
    if answered or solution:
        return 0.0
    return max(0.0, min(HINT_COST, MAX_HINT_COST - HINT_COST * hints))


_WORDS = {0.25: "a quarter", 0.5: "half", 0.75: "three quarters", 1.0: "all"}


def share_words(share: float) -> str:
    return _WORDS.get(share, f"{share:.0%}")


def costs() -> dict[str, str]:
    """What help costs, in the words the pages and the terminal say it before a student asks."""
    return {"hint": f"each hint costs {share_words(HINT_COST)} of its part's credit (at most "
                    f"{share_words(MAX_HINT_COST)})",
            "solution": f"the worked solution costs {share_words(SOLUTION_COST)} of the credit of every part not "
                        f"answered yet",
            "levels": f"mastered from {MASTERED} %, weak below {WEAK} % (rounded down)"}


def weight(estimate: Mastery) -> float:
    return max(FLOOR, 1.0 - estimate.mean)


def choose(candidates: Mapping[str, Sequence[str]], topics: Mapping[str, Mastery],
           templates: Mapping[str, Mastery], rng: random.Random, avoid: str | None = None) -> str:
    """A template id from `candidates` (topic -> template ids): a topic by its weakness, then a template
    of it by its own. `avoid` (the one just practised) is left out when anything else is possible."""
    pool = {topic: list(ids) for topic, ids in candidates.items() if ids}
    if avoid is not None and sum(len(ids) for ids in pool.values()) > 1:
        pool = {topic: [t for t in ids if t != avoid] for topic, ids in pool.items()}
        pool = {topic: ids for topic, ids in pool.items() if ids}
    if not pool:
        raise ValueError("no templates to choose from")
    names = sorted(pool)
    topic = rng.choices(names, [weight(topics.get(n, Mastery())) for n in names])[0]
    ids = sorted(pool[topic])
    return rng.choices(ids, [weight(templates.get(i, Mastery())) for i in ids])[0]
