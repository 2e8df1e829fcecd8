"""The worked solution of a variant as data: the given values, then its lines and tables.

A line is symbol = formula = the formula with numbers = value [= the value in other units]. The
numbers are shown in the units the line is worked in: an angle in a trigonometric argument in
degrees; an angle in an exponent, or beside π, in radians; a speed ratio in the rpm it was set in,
when the step says so (Step.shown). A step shown in one unit and used elsewhere in another gets
both on its own line, so every number a reader meets has been shown. Numbers have four
significant figures, or more where four would not reproduce the line's value (a difference of
nearly equal numbers).
"""
from __future__ import annotations

import math
import weakref
from dataclasses import dataclass, replace
from typing import Any

from .. import units
from ..answertypes import answer_type
from ..errors import ExgenError
from ..load.template import default_symbol
from ..solve.derivation import Column, Table
from .arithmetic import NotArithmetic, evaluate
from .formula import Formula, FormulaError, parse, written
from .targets import MARKDOWN, PLAIN, SIG, number_parts
from .working import Plan, in_unit, kind, plan, used_in_si, values_of

MAX_SIG = 10


@dataclass(frozen=True)
class Number:
    """A number standing in a formula: its value in the unit it is shown in, and how it is written."""

    value: float
    sig: int = SIG
    degrees: bool = False
    exact: str | None = None     # a given value as printed ("0.33"), written as it is


@dataclass(frozen=True)
class Filled:
    """A formula with each slot filled: a LaTeX symbol, or a Number (`numbers`: the substituted form)."""

    formula: Formula
    fills: tuple
    numbers: bool = False

    def latex(self, number) -> str:
        """LaTeX with numbers written by `number(Number) -> str`."""
        return written(self.formula.latex, tuple(f if isinstance(f, str) else number(f) for f in self.fills),
                       self.numbers)


@dataclass(frozen=True)
class Quantity:
    value: Any
    unit: str
    sig: int = SIG   # figures: four, or as many as a later line substitutes it with


@dataclass(frozen=True)
class GivenLine:
    """A given value: 'N₁ = 570 rpm = 59.69 rad/s' (SI only when the working uses it in SI)."""

    name: str
    label: str
    symbol: str          # LaTeX
    printed: str         # as on the sheet, e.g. "570 rpm"
    si_text: str | None  # e.g. "59.69 rad/s", or None


@dataclass(frozen=True)
class WorkLine:
    """One step: symbol = formula = substituted = value [= the value in another unit]."""

    name: str
    symbol: str
    formula: Filled | None
    substituted: Filled | None
    values: tuple[Quantity, ...]
    note: str = ""
    parts: tuple[str, ...] = ()

    @property
    def value(self):
        return self.values[0].value

    @property
    def unit(self) -> str:
        return self.values[0].unit

    @property
    def pieces(self) -> tuple:
        """The members of the chain after the symbol."""
        return tuple(p for p in (self.formula, self.substituted) if p is not None) + self.values

    def chain(self, target) -> list[str]:
        """The pieces of the line in the target's math, symbol first, to be joined with ' = '."""
        return [target.math(self.symbol)] + [" ".join(target.terms(p)) for p in self.pieces]


@dataclass(frozen=True)
class TableBlock:
    title: str
    columns: tuple[Column, ...]
    rows: tuple[tuple, ...]        # cells: Quantity, str (text with $LaTeX$) or None
    total: tuple | None = None


@dataclass(frozen=True)
class Solution:
    given: tuple[GivenLine, ...]
    blocks: tuple  # WorkLine | TableBlock, in order

    @property
    def lines(self) -> tuple[WorkLine, ...]:
        return tuple(b for b in self.blocks if isinstance(b, WorkLine))


#: Each variant's worked solution, kept while the variant lives: a sheet's Markdown and PDF, sheet and
#: key, all read it (keyed by identity: a Variant holds mappings and has no hash).
_SOLVED: dict[int, Solution] = {}


def solution(variant) -> Solution:
    """The worked solution of a variant (worked once; a variant is frozen)."""
    key = id(variant)
    found = _SOLVED.get(key)
    if found is None:
        found = _solution(variant)
        try:
            weakref.finalize(variant, _SOLVED.pop, key, None)
        except TypeError:  # an object that cannot be watched (a test's stand-in) is not kept
            return found
        _SOLVED[key] = found
    return found


def _solution(variant) -> Solution:
    values = values_of(variant)
    plans = {}
    for step in variant.steps:
        if step.formula:
            formula = _parse(variant, step.formula)
            _check_names(variant, formula, values)
            plans[step.name] = (formula, plan(formula, values[step.name], values))
    in_si = used_in_si(plans, values)
    figures: dict[tuple[str, str], int] = {}
    for _ in range(MAX_SIG - SIG + 1):  # the figures only grow, and stop at MAX_SIG
        blocks = _blocks(variant, values, plans, in_si, figures)
        grown = _figures_used(blocks, plans)
        if grown == figures:
            break
        figures = grown
    return Solution(given_lines(variant, in_si, figures), tuple(blocks))


def _blocks(variant, values, plans, in_si, figures) -> list:
    hidden = set().union(*(i.hides for i in variant.inserts if isinstance(i, Table))) if variant.inserts else set()
    answered = _answered(variant)
    sums = _table_sums(variant)
    blocks, inserts = [], sorted(variant.inserts, key=lambda i: i.at)
    for number, step in enumerate(variant.steps):
        while inserts and inserts[0].at <= number:
            blocks.append(_insert(inserts.pop(0), values))
        if step.name in hidden and step.name not in answered:
            continue
        line = _line(variant, step, values, plans.get(step.name), in_si, answered, figures)
        blocks.append(_defining(line, plans.get(step.name), values, sums))
    blocks += [_insert(i, values) for i in inserts]
    return blocks


def _table_sums(variant) -> dict[str, str]:
    """Step -> where a table shows it, for the steps a table shows alone: "= Σ mr cos θ" for a cell of its
    Σ row, "in the table's column energy above U" for a cell of a row (no row label: a number in a hint
    may give an answer away)."""
    out = {}
    for insert in variant.inserts:
        if not isinstance(insert, Table):
            continue
        rows = [(row, False) for row in insert.rows] + ([(insert.total, True)] if insert.total else [])
        for row, total in rows:
            for cell, column in zip(row, insert.columns):
                if isinstance(cell, str) and cell.startswith("@") and cell[1:] in insert.hides:
                    head = column.head[:1].lower() + column.head[1:] if column.head[1:2].islower() else column.head
                    out.setdefault(cell[1:], f"= Σ {column.head}" if total else f"in the column {head}")
    return out


def _defining(line: WorkLine, planned, values, sums: dict[str, str]) -> WorkLine:
    """The line, its note saying what the table's sums it is the first to use stand for (R₀ = Σ mr cos θ):
    a symbol the key uses is defined where it is first met. `sums` loses the names it defines."""
    if planned is None:
        return line
    named = [s.name for s in planned[0].slots if s.name in sums]
    named = list(dict.fromkeys(named))
    if not named:
        return line
    said = ", ".join(f"${values[n].symbol}$ {sums.pop(n)}" for n in named)
    note = f"{line.note}; " if line.note else ""
    return replace(line, note=f"{note}from the table: {said}")


def _figures_used(blocks, plans) -> dict[tuple[str, str], int]:
    """(value, unit) -> the most figures any line substitutes it with, where that is more than four: a value
    shown on its own line (or among the givens) is then shown to as many, and every line substitutes it so,
    so a number a reader meets twice is written the same both times."""
    out: dict[tuple[str, str], int] = {}
    for line in blocks:
        if not isinstance(line, WorkLine) or line.substituted is None:
            continue
        for slot, unit, fill in zip(line.substituted.formula.slots, plans[line.name][1].units, line.substituted.fills):
            if isinstance(fill, Number) and fill.exact is None and fill.sig > SIG:
                out[slot.name, unit] = max(out.get((slot.name, unit), SIG), fill.sig)
    return out


def _parse(variant, latex: str) -> Formula:
    try:
        return parse(latex)
    except FormulaError as exc:
        raise ExgenError(f"{variant.template.id}: cannot read the formula {latex!r}: {exc}") from None


def _check_names(variant, formula: Formula, values) -> None:
    for slot in formula.slots:
        if slot.name not in values:
            raise ExgenError(f"{variant.template.id}: a formula refers to @{slot.name}, which is neither a step "
                             f"nor a given")


def _answered(variant) -> dict[str, list[str]]:
    answered: dict[str, list[str]] = {}
    for part in variant.template.parts:
        for name in answer_type(part).steps(part):
            answered.setdefault(name, []).append(part.id)
    return answered


def given_lines(variant, in_si=frozenset(), figures=None) -> tuple[GivenLine, ...]:
    """The givens this variant uses, in the template's order (a second idler's teeth only with two idlers)."""
    out, unused = [], variant.unused
    for p in variant.params:
        if p.name in unused:
            continue
        si_text = None
        target = units.si_unit(p.unit) if p.unit else None
        if p.name in in_si and isinstance(p.si, (int, float)) and target is not None:
            si_text = PLAIN.quantity(float(p.si), target, (figures or {}).get((p.name, target), SIG))
        out.append(GivenLine(p.name, p.label, p.symbol or default_symbol(p.name), str(p), si_text))
    return tuple(out)


def _line(variant, step, values, planned, in_si, answered, figures) -> WorkLine:
    me = values[step.name]
    formula = substituted = None
    first_unit = me.shown
    if planned:
        parsed, plan = planned
        if (me.kind == "angle" and not plan.angles_in_degrees) or (me.kind == "dimensional" and not plan.printed) \
                or me.kind == "number":  # a ratio is worked as a fraction; a percentage follows it
            first_unit = me.si
        symbols = tuple(values[s.name].symbol for s in parsed.slots)
        if step.symbolic and not _restates(parsed, symbols, step.symbol):
            formula = Filled(parsed, symbols)
        if parsed.slots and not _restates_value(parsed, values):
            substituted = _substituted(parsed, plan, values, step, first_unit, figures)

    def quantity(unit: str) -> Quantity:
        return Quantity(in_unit(step.value, step.unit, unit), unit, figures.get((step.name, unit), SIG))

    shown = [quantity(first_unit)]
    extra = [me.shown, me.si] if step.name in in_si or first_unit != me.shown else []
    for part_id in answered.get(step.name, ()):
        answer = variant.answers[part_id]
        extra += [unit for _, unit in answer_type(answer.part).worked_values(answer, step.name)]
    for unit in extra:
        if isinstance(step.value, (int, float)) and not isinstance(step.value, bool) and unit and \
                unit not in (q.unit for q in shown) and units.same_dimension(unit, step.unit or ""):
            shown.append(quantity(unit))
    if substituted is None and formula is not None and not formula.formula.slots:
        formula = formula if _latex_of(formula) != MARKDOWN.number(step.value) else None
    return WorkLine(step.name, step.symbol, formula, substituted, tuple(shown), step.note,
                    tuple(answered.get(step.name, ())))


def _restates_value(formula: Formula, values) -> bool:
    """'x = @y' or 'φ₃ = −@θ₃' with θ₃ ≥ 0: the numbers would only write the value again ('= −14.56° = −14.56°');
    '−@b' with b < 0 keeps them ('= −(−3050) = 3050')."""
    if len(formula.slots) != 1 or formula.latex.replace(" ", "").lstrip("+-") != "@" + formula.slots[0].name:
        return False
    value = values[formula.slots[0].name].value
    return not formula.latex.strip().startswith("-") or (isinstance(value, (int, float)) and value >= 0)


def _restates(formula: Formula, symbols, symbol: str) -> bool:
    """'m₁r₁ = m₁r₁' says nothing."""
    def bare(latex: str) -> str:
        return latex.replace("\\,", "").replace(" ", "").replace("{", "").replace("}", "")

    return bare(written(formula.latex, tuple(symbols))) == bare(symbol)


def _latex_of(filled: Filled) -> str:
    return filled.latex(lambda n: MARKDOWN.number(n.value))


def _substituted(formula: Formula, plan: Plan, values, step, first_unit: str, figures) -> Filled:
    """The formula with numbers, to as many figures as it takes to reproduce the line's value as shown,
    and each number to at least the figures it is shown with elsewhere (`figures`)."""
    def numbers(sig):
        out = []
        for slot, unit in zip(formula.slots, plan.units):
            v = values[slot.name]
            if v.exact is not None and unit == v.shown:
                out.append(Number(float(v.exact), SIG, unit == "deg", v.exact))
            else:
                out.append(Number(in_unit(v.value, v.si, unit), max(sig, figures.get((slot.name, unit), SIG)),
                                  unit == "deg"))
        return tuple(out)

    if not isinstance(step.value, float):
        return Filled(formula, numbers(SIG), True)
    angle = kind(step.unit) == "angle"
    expected = in_unit(step.value, step.unit, first_unit)
    own = figures.get((step.name, first_unit), SIG)
    for sig in range(SIG, MAX_SIG + 1):
        fills = numbers(sig)
        got = line_value(Filled(formula, fills, True))
        if got is None:
            return Filled(formula, numbers(SIG), True)
        turn = in_unit(2 * math.pi, "rad", first_unit) if angle else 0.0
        if reproduces(in_unit(got, "rad", first_unit) if angle else got, expected, sig=own, turn=turn):
            return Filled(formula, fills, True)
    return Filled(formula, numbers(SIG), True)


def reproduces(got: float, shown: float, sig: int = SIG, turn: float = 0.0) -> bool:
    """True if `got` is `shown` to within one unit in its last significant figure. For an angle, `turn` is
    a whole turn in its unit (360 or 2π): whole turns between the two do not count (−117.7° is 242.3°)."""
    if turn:
        got = shown + math.remainder(got - shown, turn)
    if got == shown or (shown == 0 and abs(got) < 1e-9):  # a sum that cancels leaves float noise
        return True
    if not (math.isfinite(got) and math.isfinite(shown)):
        return False
    size = max(abs(shown), abs(got))
    return abs(got - shown) <= 10.0 ** (math.floor(math.log10(size)) - sig + 1) * 1.0001


def line_value(filled: Filled) -> float | None:
    """What the substituted formula gives with its numbers as written (angles worked in radians), or
    None when it is not plain arithmetic."""
    try:
        return evaluate(filled.formula, {i: shown_value(n) for i, n in enumerate(filled.fills)})
    except (NotArithmetic, ArithmeticError, ValueError):
        return None


def shown_value(number: Number) -> float:
    """A number's value as written (rounded as shown), in radians if written in degrees."""
    if number.exact is not None:
        value = float(number.exact)
    else:
        mantissa, exponent = number_parts(number.value, number.sig)
        value = float(mantissa) * 10.0 ** int(exponent or 0)
    return math.radians(value) if number.degrees else value


def _insert(insert, values):
    return TableBlock(insert.title, insert.columns, tuple(_row(r, insert.columns, values) for r in insert.rows),
                      _row(insert.total, insert.columns, values) if insert.total else None)


def _row(row, columns, values) -> tuple:
    out = []
    for cell, column in zip(row, columns):
        if isinstance(cell, str) and cell.startswith("@") and cell[1:] in values:
            cell = values[cell[1:]].value
        if isinstance(cell, (int, float)) and not isinstance(cell, bool):
            unit = "deg" if kind(column.unit) == "angle" else column.unit
            cell = Quantity(in_unit(cell, column.unit, unit), unit)
        out.append(cell)
    return tuple(out)
