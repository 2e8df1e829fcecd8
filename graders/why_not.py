"""Why a wrong number that no known mistake explains is wrong, said so that it still teaches.

First, the worked step the value is (within the part's tolerance, read in any unit of the step's kind):
a step on the way to the answer ("one step short"), the answer to another part, a later step, a given,
or a step this part does not use, each named by its symbol and formula from the variant. Else a
factor the value is off by that has a usual cause (2, π, 2π, 60, 60/2π, g, a square or a root), else
which way and about how far it is off. Only ever words: the mark is the grader's, unchanged.
"""
from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from functools import lru_cache

from exgen import units
from exgen.answertypes.angle import angle
from exgen.answertypes.number import PREFIXES, REL_TOL
from exgen.answertypes.quantity import units_of_kind
from exgen.errors import ExgenError
from exgen.render.formula import FormulaError, parse, written
from exgen.render.targets import PLAIN
from exgen.solve.derivation import PLACEHOLDER

ON_THE_WAY = "Your value is {step}, a step on the way: {target} is worked out from it{more}."
OTHER_PART = "Your value is {step}, the answer to ({part}), not to this part."
LATER = "Your value is {step}, which is worked out from this part's answer: the answer comes before it."
GIVEN = "Your value is {step}, one of the givens: the answer is worked out from it."
UNUSED = "Your value is {step}, a value of the working that this part does not use."
FACTOR = "Your value is {times} the expected one, as {why}."
#: Factors with a usual cause, as (factor, what it suggests); each is also tried upside down.
FACTORS = (
    (2.0, "if a diameter were taken for a radius, or a factor of 2 left out or put in twice"),
    (math.pi, "if a diameter and a circumference were mixed up"),
    (2 * math.pi, "if a turn, 2π rad, were left out or put in twice (ω = 2πf)"),
    (60.0, "if minutes and seconds were mixed up"),
    (60.0 / (2 * math.pi), "if rpm were taken for rad/s, or rad/s for rpm"),
    (9.81, "if a mass were taken for a weight, or a weight for a mass (W = mg)"),
)
OFF = "Your value is about {amount} too {way}."
TIMES = "Your value is about {size} the expected one."
SIGN_AND_SIZE = "Your value has the wrong sign, and its size is off by about {amount} too."
SMALL = 1e-12  # a step this close to 0 matches too much to name


@dataclass(frozen=True)
class _Candidate:
    name: str
    value: float      # in `unit`
    unit: str
    given: bool


def why_not(variant, part, given) -> str | None:
    """A sentence on what a wrong, unexplained answer is, if anything useful can be said."""
    value, key = given.value, variant.answers[part.id].value
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in (value, key)):
        return None
    try:
        return _matching_step(variant, part, given) or _factor(part, value, key) or _off(part, value, key)
    except (ExgenError, FormulaError, ArithmeticError, ValueError, KeyError):
        return None


def _matching_step(variant, part, given) -> str | None:
    """The worked step (or given) nearest the student's number, among those it matches."""
    number = given.number if given.number is not None else given.value
    if number == 0:
        return None
    rel = part.tol.rel or REL_TOL
    answer = variant.answers[part.id].step.name
    best = None
    for candidate in _candidates(variant):
        if candidate.name == answer:
            continue
        gap = _gap(part, number, candidate, rel)
        if gap is not None and gap <= rel and (best is None or gap < best[0]):
            best = (gap, candidate)
    return _say(variant, part, best[1]) if best else None


def _gap(part, number: float, candidate: _Candidate, rel: float) -> float | None:
    """How far (relatively) the number, read in the unit of the candidate's kind that brings it nearest,
    lies from the candidate; None when they cannot be compared."""
    if part.type == "integer":
        return 0.0 if number == candidate.value else None
    if part.type == "angle":
        if units.unit_info(candidate.unit).angle != 1:
            return None
        target = units.convert(candidate.value, candidate.unit, "deg")
        return 0.0 if any(angle(units.convert(number, u, "deg"), target, 0.0, part.tol.abs or 0.5)
                          for u in units_of_kind("deg")) else None
    ratio = abs(candidate.value / number)  # the number is the candidate in a unit worth `ratio` of the candidate's
    factors = _factors(candidate.unit)
    near = factors[bisect.bisect_left(factors, ratio / (1 + rel)):bisect.bisect_right(factors, ratio / (1 - rel))]
    return min((abs(ratio / f - 1) for f in near), default=None)


@lru_cache(maxsize=256)
def _factors(unit: str) -> tuple[float, ...]:
    """What 1 in each unit of `unit`'s kind, with a k or m prefix or none, is in `unit`; sorted."""
    found = set()
    for other in units_of_kind(unit):
        try:
            one = units.convert(1.0, other, unit)
        except ExgenError:
            continue
        found.update(one * p for p in PREFIXES)
    return tuple(sorted(found))


def _candidates(variant) -> list[_Candidate]:
    """The steps and givens a number can be, leaving out those too near 0 to tell apart."""
    out = [_Candidate(s.name, float(s.value), s.unit or "", False) for s in variant.steps
           if _number(s.value) and abs(s.value) > SMALL]
    for p in variant.params:
        if _number(p.si) and p.unit is not None and abs(p.si) > SMALL:
            out.append(_Candidate(p.name, units.from_si(float(p.si), p.unit) if p.unit else float(p.si),
                                  p.unit or "", True))
    return out


def _say(variant, part, candidate: _Candidate) -> str:
    step = _named(variant, candidate.name)
    if candidate.given:
        return GIVEN.format(step=step)
    answered = [p.id for p in variant.template.parts if p.id != part.id and variant.answers[p.id].step.name == candidate.name]
    if answered:
        return OTHER_PART.format(step=step, part=answered[0])
    target = variant.answers[part.id].step.name
    distance = _distance(variant, target, candidate.name)
    if distance is not None:
        more = "" if distance == 1 else f", {distance - 1} more step{'s' if distance > 2 else ''} on"
        return ON_THE_WAY.format(step=step, target=_plain(variant.step(target).symbol), more=more)
    if _distance(variant, candidate.name, target) is not None:
        return LATER.format(step=step)
    return UNUSED.format(step=step)


def _named(variant, name: str) -> str:
    """'ωₙ = √(q/I_O)': a step's symbol and its formula in symbols; a given's symbol and what it is."""
    symbols = {**{p.name: p.symbol for p in variant.params}, **{s.name: s.symbol for s in variant.steps}}
    found = next((s for s in variant.steps if s.name == name), None)
    if found is None:
        param = variant.param(name)
        return _plain(param.symbol) + (f" ({PLAIN.text(param.label)})" if param.label else "")
    if not found.formula or not PLACEHOLDER.search(found.formula):
        return _plain(found.symbol)
    return _with_formula(found.symbol, found.formula, tuple(symbols[n] for n in _slots(found.formula)))


@lru_cache(maxsize=4096)
def _with_formula(symbol: str, formula: str, fills: tuple[str, ...]) -> str:
    """Written once per template's step: every variant of a template names its steps alike."""
    return f"{_plain(symbol)} = {_plain(written(formula, fills))}"


@lru_cache(maxsize=4096)
def _plain(latex: str) -> str:
    return PLAIN.math(latex)


@lru_cache(maxsize=4096)
def _slots(latex: str) -> tuple[str, ...]:
    return tuple(slot.name for slot in parse(latex).slots)


def _distance(variant, later: str, earlier: str) -> int | None:
    """How many steps lead from `earlier` to `later` through the formulas, or None if none do."""
    formulas = {s.name: s.formula or "" for s in variant.steps}
    frontier, seen, depth = {later}, {later}, 0
    while frontier:
        depth += 1
        frontier = {used for name in frontier for used in PLACEHOLDER.findall(formulas.get(name, ""))} - seen
        if earlier in frontier:
            return depth
        seen |= frontier
    return None


def _factor(part, value: float, key: float) -> str | None:
    if key == 0 or value == 0 or part.type in ("integer", "angle"):
        return None
    rel = max(part.tol.rel or REL_TOL, REL_TOL)
    ratio = abs(value / key)
    for factor, why in FACTORS:
        if abs(ratio / factor - 1) <= rel:
            return FACTOR.format(times=_times(factor), why=why)
        if abs(ratio * factor - 1) <= rel:
            return FACTOR.format(times=_fraction(factor), why=why)
    if abs(key) > 0 and not 0.5 < abs(key) < 2:  # a square and a root are close to the value itself near 1
        if abs(abs(value) / key ** 2 - 1) <= 2 * rel:
            return FACTOR.format(times="about the square of", why="if a square root were left out")
        if abs(abs(value) / math.sqrt(abs(key)) - 1) <= rel:
            return FACTOR.format(times="about the square root of", why="if a root were taken where the square belongs")
    return None


def _times(factor: float) -> str:
    return {2.0: "twice"}.get(factor, f"{_factor_name(factor)} times")


def _fraction(factor: float) -> str:
    return {2.0: "half"}.get(factor, f"1/{_factor_name(factor)} of")


def _factor_name(factor: float) -> str:
    names = {math.pi: "π", 2 * math.pi: "2π", 60.0: "60", 60.0 / (2 * math.pi): "60/(2π)", 9.81: "g"}
    return next((n for f, n in names.items() if abs(f - factor) < 1e-12), f"{factor:g}")


def _off(part, value: float, key: float) -> str | None:
    """Which way and roughly how far: coarse enough not to hand over the answer."""
    if key == 0 or part.type == "angle":
        return None
    if (value < 0) != (key < 0) and value != 0:
        return SIGN_AND_SIZE.format(amount=_amount(abs(value) / abs(key)))
    ratio = value / key
    way = "large" if abs(value) > abs(key) else "small"
    if ratio >= 2 or 0 < ratio <= 0.5:
        times = ratio if ratio >= 2 else 1 / ratio
        return TIMES.format(size=f"{_round(times)} times" if ratio >= 2 else f"1/{_round(times)} of")
    return OFF.format(amount=_amount(ratio), way=way)


def _amount(ratio: float) -> str:
    off = abs(ratio - 1) * 100
    if off < 10:
        return f"{max(1, round(off))} %"
    return f"{round(off, -1):.0f} %"


def _round(times: float) -> str:
    return f"{times:.0f}" if times >= 3 else f"{times:.1f}"


def _number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
