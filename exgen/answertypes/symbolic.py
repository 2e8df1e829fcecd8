"""A formula in declared symbols: "find the natural frequency in terms of K, M and m".

A part declares its symbols (`symbols: [K, M, m]`, or with the range each is sampled from:
`symbols: {K: [1000, 50000], M: [1, 20], m: [0.5, 10]}`). The solver records the expected formula as
a step whose value is an `Expression` (see docs/templates.md); a student's text is read by the
whitelist grammar of `expressions` and is right when it agrees with the expected formula, within
`tol: {rel: ...}` (0.1 % by default), at every one of a fixed set of points drawn in those ranges.
Equal values at eight scattered points is how equivalent forms are told apart from different ones
without algebra, so sqrt(2K/(3M+8m))/(2π), (2K/(3M+8m))^(1/2)/(2π) and 1/(2π)√(2K/(3M+8m)) are one answer.
"""
from __future__ import annotations

import hashlib
import math
import re
from functools import lru_cache
from typing import Mapping

from ..errors import NoAnswer
from ..load.template import PartSpec, Tolerance
from .base import AnswerType, Given, Mistake, Report
from .expressions import CONSTANTS, FUNCTIONS, MAX_LENGTH, Expression, listed

#: "f =", "ωₙ = ", "f_n=": a name for the answer before it (one '=' in all).
_LABEL = re.compile(r"^\s*[^\W\d][\w']{0,11}\s*=(?=[^=]*$)\s*")
#: "... Hz", "... rad/s": a frequency's unit after the expression.
_UNIT_AFTER = re.compile(r"\s+(?:Hz|rad\s*/\s*s(?:ec)?|1\s*/\s*s|s\s*\^\s*\(?-1\)?|s\u207b\u00b9|cps)\.?\s*$",
                         re.IGNORECASE)

REL_TOL = 1e-3
POINTS = 8                  # sets of symbol values every comparison uses
MIN_DEFINED = 4             # the expected formula must have a value at this many of them
DEFAULT_RANGE = (0.5, 5.0)  # a symbol declared without a range: positive, of order one
RESERVED = set(FUNCTIONS) | set(CONSTANTS) | {"log", "e"}

NOT_EQUIVALENT = "not equivalent to the expected expression (compared at {points} sets of values of {symbols})"
FORM_NOTE = (
    "Expressions: write them with + - * / ^ and brackets, and sqrt(), sin(), cos(), tan(), exp(), ln();\n"
    "pi (or π) for π. A number or symbol written next to another multiplies: 2K is 2*K, (a)(b) is (a)*(b).\n"
    "Use only the symbols listed on the answer's line; after / put a product in brackets: 1/(2K).")
FACTOR_2PI = ("Your expression is {factor} the right one: a factor 2π is missing or extra "
              "(an angular speed ω in rad/s is 2π times a frequency f in Hz).")
CONSTANT_FACTOR = "Your expression has the right form but is {factor} times the right one: check its constant factors."
RECIPROCAL = "Your expression is the reciprocal of the right one: it is upside down."
SQUARED = "Your expression is the square of the right one: a square root is missing."
ROOTED = "Your expression is the square root of the right one: it should not be under a root."
WRONG_SIGN = "Right size, wrong sign: check the direction you took as positive."


class Symbolic(AnswerType):
    name = "symbolic"
    part_keys = ("symbols",)
    tol_keys = ("rel",)
    default_tol = Tolerance(rel=REL_TOL, abs=0.0)

    def load_options(self, spec: Mapping, report: Report) -> dict:
        given = spec.get("symbols")
        if isinstance(given, list):
            given = {name: None for name in given}
        if not isinstance(given, dict) or not given:
            report(("symbols",), "a symbolic answer needs `symbols:`, e.g. [K, M, m] or {K: [1000, 50000], M: [1, 20]}")
            return {"symbols": (), "ranges": ()}
        names, ranges = [], []
        for name, span in given.items():
            name = str(name)
            if not name.isidentifier() or name in RESERVED or name.startswith("_"):
                report(("symbols", name), "a symbol is a plain name (letters, digits, _) that is not a function or pi")
                continue
            if span is None:
                span = DEFAULT_RANGE
            if not (isinstance(span, (list, tuple)) and len(span) == 2 and all(_is_number(x) for x in span)
                    and 0 < span[0] < span[1] and math.isfinite(span[1])):
                report(("symbols", name), "a range is [low, high] with 0 < low < high: the values compared at")
                continue
            names.append(name)
            ranges.append((name, float(span[0]), float(span[1])))
        return {"symbols": tuple(names), "ranges": tuple(ranges)}

    # ---- variants ----------------------------------------------------------------------------

    def mistake_values(self, part: PartSpec, derivation) -> dict[str, Expression]:
        found = derivation.mistakes.get(part.answer, {})
        return {name: value for name, value in found.items() if isinstance(value, Expression)}

    def expected(self, part: PartSpec, derivation) -> Expression:
        value = self.step_value(part, derivation, part.answer)
        if not isinstance(value, Expression):
            raise NoAnswer(f"part {part.id}: answer {value!r} is not an Expression")
        return value

    def problem(self, value, part: PartSpec) -> str | None:
        undeclared = value.names() - set(part.options["symbols"])
        if undeclared:
            return f"answer {value} uses {listed(sorted(undeclared))}, not among the part's symbols"
        if sum(v is not None for v in _values(value, part.options["ranges"])) < MIN_DEFINED:
            return f"answer {value} has no value at most of the points it is compared at: give its symbols ranges"
        return None

    def text(self, value: Expression, part: PartSpec) -> str:
        return str(value)

    # ---- display -----------------------------------------------------------------------------

    def hint(self, part: PartSpec) -> str:
        return f"an expression in {listed(part.options['symbols'])}"

    def form_hint(self, part: PartSpec) -> str:
        return f"expression in {', '.join(part.options['symbols'])}; e.g. {self.example(part)}"

    def form_note(self) -> str:
        return FORM_NOTE

    def tolerance_text(self, part: PartSpec) -> str:
        return f"any equivalent form, within {100 * part.tol.rel:g} %"

    def key_text(self, answer, target) -> str:
        return target.inline(target.math(answer.value.latex()))

    # ---- grading -----------------------------------------------------------------------------

    def read(self, text: str, part: PartSpec) -> Given:
        """The expression, without a name for it before ("f = ...") or a frequency's unit after ("... Hz"):
        students copy both from their working."""
        bare = _UNIT_AFTER.sub("", _LABEL.sub("", text, count=1), count=1) if len(text) <= MAX_LENGTH else text
        return Given(text, Expression.parse(bare, part.options["symbols"]))

    def example(self, part: PartSpec) -> Expression:
        """A form unlike any physics answer, in the part's own symbols: 2*a^2/(3*b)."""
        names = part.options["symbols"] or ("x",)
        return Expression.parse(f"2*{names[0]}^2/(3*{names[-1]})", names)

    def format_hint(self, part: PartSpec) -> str:
        return f"write an expression in {listed(part.options['symbols'])}, such as {self.example(part)}"

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        pairs = _pairs(given, expected, part)
        if pairs is None:
            return False
        rel = part.tol.rel * widen
        floor = 1e-12 * max(abs(e) for _, e in pairs)
        return all(abs(g - e) <= rel * abs(e) + floor for g, e in pairs)

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        return NOT_EQUIVALENT.format(points=POINTS, symbols=listed(part.options["symbols"]))

    def slip(self, given: Given, expected, part: PartSpec) -> Mistake | None:
        """A constant factor out (2π above all), upside down, squared or square-rooted."""
        pairs = _pairs(given.value, expected, part)
        if pairs is None or any(e == 0 or g == 0 for g, e in pairs):
            return None
        rel = max(part.tol.rel, REL_TOL)

        def constant(values) -> float | None:
            return values[0] if all(math.isclose(v, values[0], rel_tol=rel) for v in values) else None

        factor = constant([g / e for g, e in pairs])
        if factor is not None:
            if math.isclose(factor, -1, rel_tol=rel):
                return Mistake("wrong_sign", WRONG_SIGN)
            for size, words in ((2 * math.pi, "2π times"), (1 / (2 * math.pi), "1/(2π) of")):
                if math.isclose(factor, size, rel_tol=rel):
                    return Mistake("factor_2pi", FACTOR_2PI.format(factor=words))
            return Mistake("constant_factor", CONSTANT_FACTOR.format(factor=f"{factor:.4g}"))
        if all(math.isclose(g * e, 1, rel_tol=rel) for g, e in pairs):
            return Mistake("reciprocal", RECIPROCAL)
        if all(math.isclose(g, e * e, rel_tol=rel) for g, e in pairs):
            return Mistake("missing_root", SQUARED)
        if all(g > 0 and math.isclose(g * g, e, rel_tol=rel) for g, e in pairs):
            return Mistake("extra_root", ROOTED)
        return None

    def nudges(self, value: Expression, part: PartSpec) -> tuple[Expression, ...]:
        return tuple(Expression(("mul", ("num", k), value.tree), value.symbols) for k in (1.02, 2.0))

    def overrides(self, part: PartSpec, value: Expression, variant) -> dict[str, Expression]:
        """The student's formula takes the expected one's place: later steps evaluate it."""
        return {part.answer: value}

    #: Core Moodle, QTI 2.1 and Canvas compare numbers and strings only (STACK and Formulas are Moodle plugins).
    lms_missing = ("a formula, graded by its values at points: no core question type of Moodle, QTI 2.1 or Canvas "
                   "checks equivalent forms")

    def sample_part(self) -> PartSpec:
        names = ("K", "M", "m")
        return PartSpec("a", "the natural frequency in terms of K, M and m", "f_expr", type=self.name,
                        tol=self.default_tol,
                        options={"symbols": names, "ranges": tuple((n, *DEFAULT_RANGE) for n in names)})


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _pairs(given, expected, part: PartSpec) -> list[tuple[float, float]] | None:
    """(given, expected) at each point where the expected formula has a value; None when the given
    one has none where it should, or too few points are left to compare at."""
    ranges = part.options["ranges"]
    pairs = []
    for g, e in zip(_values(given, ranges), _values(expected, ranges)):
        if e is None:
            continue
        if g is None:
            return None
        pairs.append((g, e))
    return pairs if len(pairs) >= MIN_DEFINED else None


@lru_cache(maxsize=4096)
def _values(expression: Expression, ranges: tuple) -> tuple[float | None, ...]:
    """The expression at each comparison point (None where it has no finite value)."""
    out = []
    for point in _points(ranges):
        try:
            out.append(expression(**point))
        except (ValueError, ArithmeticError, KeyError):
            out.append(None)
    return tuple(out)


@lru_cache(maxsize=256)
def _points(ranges: tuple) -> tuple[dict[str, float], ...]:
    """POINTS sets of values, log-uniform in each symbol's range; the same in any process on any day."""
    seed = int.from_bytes(hashlib.sha256(repr(ranges).encode()).digest()[:8], "big")
    import numpy as np  # only where formulas are compared: reading the bank does not need it

    rng = np.random.Generator(np.random.PCG64(seed))
    draws = {name: np.exp(rng.uniform(math.log(low), math.log(high), POINTS)) for name, low, high in ranges}
    return tuple({name: float(values[i]) for name, values in draws.items()} for i in range(POINTS))


TYPE = Symbolic()
