"""How well a student knows a topic, and which problem should come next. Pure functions over outcomes.

The estimate is an exponentially weighted success rate with a Beta(1, 1) prior: each problem's
credit (the share of its marks earned at the first try) counts with weight DECAY^k, k being how many
problems of the topic came after it, so
    mastery = (1 + Σ wₖ·creditₖ) / (2 + Σ wₖ).
Why this and not the others the literature offers: Bayesian knowledge tracing needs four parameters
per skill (prior, learn, slip, guess) fitted to a class's data, and Elo needs item difficulties
calibrated across many students; practice runs for one student, offline, with neither. A weighted
rate needs no calibration, forgets old evidence so that a student who has caught up is seen to have
(DECAY 0.8 remembers about the last five problems), and the prior keeps two lucky answers from
reading as mastery: five right in a row are needed to pass MASTERED from nothing.

The next problem is drawn at random with weights 1 − mastery (at least FLOOR): first a topic, then a
template within it, so weak topics come up more, mastered ones less but still now and then, and one
not yet tried (0.5) between the two.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Iterable, Mapping, Sequence

DECAY = 0.8
MASTERED = 0.8
WEAK = 0.5
FLOOR = 0.05
HINT_CREDIT = 0.5   # a part right after hints earns half its credit; after the worked solution, none


@dataclass(frozen=True)
class PartOutcome:
    """How a part went at the first readable answer."""

    points: float
    answered: bool = False      # a readable answer was checked
    right: bool = False         # that first answer was right (error carried forward counts)
    hinted: bool = False        # a hint was shown before it
    solution_first: bool = False  # the worked solution was shown before any answer


@dataclass(frozen=True)
class Outcome:
    """One problem as evidence: the credit earned, and how much of the problem it covers (0 to 1)."""

    credit: float
    weight: float


def problem_outcome(parts: Iterable[PartOutcome]) -> Outcome | None:
    """A problem's credit over the parts that show anything; None when none does (a problem skipped)."""
    total = earned = covered = 0.0
    for part in parts:
        total += part.points
        if part.solution_first:
            covered += part.points
        elif part.answered:
            covered += part.points
            earned += part.points * (HINT_CREDIT if part.hinted else 1.0) * part.right
    if covered == 0 or total == 0:
        return None
    return Outcome(earned / covered, covered / total)


@dataclass(frozen=True)
class Mastery:
    alpha: float = 1.0
    beta: float = 1.0
    problems: int = 0

    @property
    def mean(self) -> float:
        return self.alpha / (self.alpha + self.beta)

    @property
    def level(self) -> str:
        if self.problems == 0:
            return "not started"
        if self.mean >= MASTERED:
            return "mastered"
        return "learning" if self.mean >= WEAK else "weak"


def mastery(outcomes: Sequence[Outcome]) -> Mastery:
    """The estimate from a topic's (or template's) outcomes, oldest first."""
    alpha = beta = 1.0
    n = len(outcomes)
    for k, outcome in enumerate(outcomes):
        weight = DECAY ** (n - 1 - k) * outcome.weight
        alpha += weight * outcome.credit
        beta += weight * (1.0 - outcome.credit)
    return Mastery(alpha, beta, n)


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
