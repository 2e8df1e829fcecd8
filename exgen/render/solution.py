"""The worked solution of a variant as data: the given values and one line per solver step.

Every line is LaTeX (symbol, symbolic formula, the same with numbers substituted); a
renderer turns it into its own math with a Target (targets.py). Substituted numbers are the
SI values the solver used, to four significant figures, so each line can be checked by hand.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from .. import units
from ..answertypes import answer_type
from ..derivation import PLACEHOLDER, default_symbol, expand
from ..errors import ExgenError
from .targets import MARKDOWN, PLAIN

#: The coherent SI unit in which solvers work, by kind of quantity (units.describe).
SI_UNITS = {
    "length": "m", "mass": "kg", "time": "s", "angle": "rad", "angular speed": "rad/s", "frequency": "Hz",
    "speed": "m/s", "acceleration": "m/s^2", "angular acceleration": "rad/s^2", "force": "N",
    "torque or energy": "N*m", "power": "W", "pressure or stress": "N/m^2", "mass per unit length": "kg/m",
    "area": "m^2", "volume": "m^3", "density": "kg/m^3", "moment of inertia": "kg*m^2",
    "mass times radius": "kg*m", "stiffness": "N/m", "damping coefficient": "N*s/m", "pure number": "",
}
_ONLY_PLACEHOLDER = re.compile(r"^\s*@[A-Za-z_]\w*\s*$")


@dataclass(frozen=True)
class GivenLine:
    """A given value: 'N₁ = 570 rpm = 59.69 rad/s' (the SI part only when it differs)."""

    name: str
    label: str
    symbol: str          # LaTeX
    printed: str         # as on the sheet, e.g. "570 rpm"
    si_text: str | None  # e.g. "59.69 rad/s", or None when the printed value is already SI


@dataclass(frozen=True)
class WorkLine:
    """One step: symbol = formula = substituted = value [= answer in the asked unit]."""

    name: str
    symbol: str
    formula: str
    substituted: str
    value: Any
    unit: str
    note: str = ""
    parts: tuple[str, ...] = ()                 # parts whose answer this step is
    asked: tuple[tuple[Any, str], ...] = ()     # the answer again in each part's unit, when different

    def chain(self, target) -> list[str]:
        """The pieces of the line in the target's math, to be joined with ' = '."""
        pieces = [target.math(self.symbol)]
        pieces += [target.math(x) for x in (self.formula, self.substituted) if x]
        pieces.append(target.quantity(self.value, self.unit))
        pieces += [target.quantity(value, unit) for value, unit in self.asked]
        return pieces


@dataclass(frozen=True)
class Solution:
    given: tuple[GivenLine, ...]
    lines: tuple[WorkLine, ...]


def solution(variant) -> Solution:
    return Solution(given_lines(variant), work_lines(variant))


def si_unit(unit: str) -> str | None:
    """The SI unit a solver uses for a quantity printed in `unit`, or None if unknown."""
    try:
        return SI_UNITS.get(units.unit_info(unit).kind)
    except ExgenError:
        return None


def given_lines(variant) -> tuple[GivenLine, ...]:
    out = []
    for p in variant.params:
        si_text = None
        target = si_unit(p.unit) if p.unit else None
        if isinstance(p.si, (int, float)) and target is not None:
            if abs(units.convert(1.0, p.unit, target) - 1.0) > 1e-12:
                si_text = PLAIN.quantity(float(p.si), target)
        out.append(GivenLine(p.name, p.label, p.symbol or default_symbol(p.name), str(p), si_text))
    return tuple(out)


def _lookups(variant):
    steps = {s.name: s for s in variant.steps}
    params = {p.name: p for p in variant.params}

    def symbol_of(name: str) -> str:
        if name in steps:
            return steps[name].symbol
        if name in params:
            return params[name].symbol or default_symbol(name)
        return default_symbol(name)

    def value_of(name: str):
        if name in steps:
            return steps[name].value
        if name in params:
            return params[name].si
        raise ExgenError(f"{variant.template.id}: a formula refers to @{name}, which is neither a step nor a given")

    return symbol_of, value_of


def work_lines(variant) -> tuple[WorkLine, ...]:
    symbol_of, value_of = _lookups(variant)
    answered: dict[str, list[str]] = {}
    for part in variant.template.parts:
        for name in answer_type(part).steps(part):
            answered.setdefault(name, []).append(part.id)
    lines = []
    for step in variant.steps:
        formula = expand(step.formula, symbol_of) if step.formula else ""
        if formula.replace("\\,", "").replace(" ", "") == step.symbol.replace(" ", ""):
            formula = ""  # "m_1 r_1 = m_1 r_1" says nothing
        substituted = ""
        if step.formula and PLACEHOLDER.search(step.formula) and not _ONLY_PLACEHOLDER.match(step.formula):
            substituted = expand(step.formula, symbol_of, value_of, MARKDOWN.number)
            if substituted == MARKDOWN.number(step.value):
                substituted = ""
        parts = tuple(answered.get(step.name, ()))
        asked: list[tuple[Any, str]] = []
        for part_id in parts:
            answer = variant.answers[part_id]
            for entry in answer_type(answer.part).worked_values(answer, step.name):
                if entry[1] != step.unit and entry not in asked:
                    asked.append(entry)
        lines.append(WorkLine(step.name, step.symbol, formula, substituted, step.value, step.unit, step.note,
                              parts, tuple(asked)))
    return tuple(lines)
