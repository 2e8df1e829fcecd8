"""A solution as a sequence of named steps: the answers, the worked solution and ECF in one.

A solver is a plain function `solve(p, d)`: `p` holds the given data in SI, `d` is a
Derivation. Each `d.step(...)` records symbol, formula, value and unit and returns the value
the rest of the solution uses. When the grader re-runs a solver with `overrides`, a step
named there returns the student's value instead, so later steps follow from it (error
carried forward). `d.mistake(...)` records the value a known wrong method would give.
`d.table(...)` places a table in the worked solution where the course text works with one (a
balancing table, the tabular method of an epicyclic).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, NamedTuple

from ..errors import ExgenError, InvalidDraw
from ..load.template import default_symbol

PLACEHOLDER = re.compile(r"@([A-Za-z_][A-Za-z0-9_]*)")


class Step(NamedTuple):
    """One line of a worked solution. `formula` is LaTeX with @name placeholders.

    `shown`: the unit the key shows the value in, and works the formula in ("rpm" for a speed ratio,
    "in" for a diametral pitch); by default an angle is shown in degrees and anything else in SI.
    `symbolic`: False when the formula's symbols would only restate the left side (β = 2β/2): the key
    then shows it with numbers only. (A named tuple, not a frozen dataclass: a variant records a score of
    steps, and a frozen dataclass is several times slower to make.)
    """

    name: str
    symbol: str
    formula: str
    value: Any
    unit: str = ""
    note: str = ""
    overridden: bool = False
    shown: str = ""
    symbolic: bool = True


@dataclass(frozen=True)
class Column:
    """A table column: its heading (LaTeX) and the SI unit of its numbers (angles, rad, are shown in degrees)."""

    head: str
    unit: str = ""


@dataclass(frozen=True)
class Table:
    """A table in the worked solution, placed before step number `at`.

    A cell is a number (SI, in its column's unit), "@name" (the value of a step or given), text (with
    $LaTeX$), or None (blank). `total` is a last row, usually of sums ("Σ"). The steps a table shows
    get no line of their own, unless a part asks for them or they are listed in `shown`.
    """

    title: str
    columns: tuple[Column, ...]
    rows: tuple[tuple, ...]
    total: tuple | None = None
    at: int = 0
    shown: tuple[str, ...] = ()

    @property
    def names(self) -> set[str]:
        """The steps and givens the table shows."""
        cells = [c for row in self.rows + ((self.total,) if self.total else ()) for c in row]
        return {c[1:] for c in cells if isinstance(c, str) and PLACEHOLDER.fullmatch(c)}

    @property
    def hides(self) -> set[str]:
        return self.names - set(self.shown)


class Params:
    """The given data of one variant, in SI, read as attributes: `p.d1`. `read` collects the names the
    solver asked for, so that a key lists only the givens this variant uses (one idler or two)."""

    def __init__(self, values: dict[str, Any], symbols: dict[str, str]):
        self._values = dict(values)
        self._symbols = dict(symbols)
        self.read: set[str] = set()

    def __getattr__(self, name: str):
        try:
            value = self._values[name]
        except KeyError:
            raise AttributeError(f"no parameter named {name!r}") from None
        self.read.add(name)
        return value

    def __contains__(self, name: str) -> bool:
        return name in self._values

    def as_dict(self) -> dict[str, Any]:
        self.read.update(self._values)
        return dict(self._values)


class Derivation:
    """Collects steps and mistake values while a solver runs."""

    def __init__(self, params: Params, overrides: dict[str, float] | None = None, strict: bool = True):
        self.params = params
        self.strict = strict
        self.warnings: list[str] = []
        self.overrides = dict(overrides or {})
        self.steps: list[Step] = []
        self.mistakes: dict[str, dict[str, float]] = {}
        self.inserts: list[Table] = []
        self.if_apart: set[tuple[str, str]] = set()  # (step, mistake) named only where they show
        self._by_name: dict[str, Step] = {}

    def step(self, name: str, value, unit: str = "", *, symbol: str | None = None,
             formula: str = "", note: str = "", shown: str = "", symbolic: bool = True):
        """Record a step and return its value (or the override for it, when re-running for ECF)."""
        if name in self.params:
            raise ExgenError(f"the solver names a step {name!r} like a given value: rename the step, so that "
                             f"@{name} in a formula and an answer carried forward mean one thing")
        overridden = name in self.overrides
        if overridden:
            value = self.overrides[name]
        step = Step(name, symbol or default_symbol(name), formula, value, unit, note, overridden, shown, symbolic)
        self.steps.append(step)
        self._by_name[name] = step
        return value

    def constant(self, name: str, value: float, unit: str, note: str = "", symbol: str | None = None) -> float:
        """A constant (g) as a step of its own the first time a solution uses it, so that formulas
        write @g and the key shows g = 9.81 m/s² once, not a bare 9.81 in the working."""
        if name not in self._by_name:
            self.step(name, value, unit, symbol=symbol, note=note)
        return value

    def table(self, title: str, columns, rows, total=None, shown=()) -> Table:
        """Show steps and values as a table here, after the steps recorded so far (see Table)."""
        columns = tuple(c if isinstance(c, Column) else Column(*c) for c in columns)
        table = Table(title, columns, tuple(tuple(r) for r in rows), tuple(total) if total else None,
                      len(self.steps), tuple(shown))
        self.inserts.append(table)
        return table

    def mistake(self, step_name: str, mistake: str, value, *, if_apart: bool = False) -> None:
        """Record what `step_name` comes out as by the known wrong method `mistake`.

        A mistake a part names is kept apart from the part's answer in every draw (by the gap its answer
        type sets: exgen.answertypes.base.MISTAKE_GAP tolerances): draws where it lands closer are redrawn.
        With `if_apart`, for a slip that makes no difference in some configurations, such draws stand and
        the slip is simply not named in them."""
        self.mistakes.setdefault(step_name, {})[mistake] = value
        if if_apart:
            self.if_apart.add((step_name, mistake))

    def require(self, condition: bool, reason: str) -> None:
        """Reject the draw (it is retried) when the drawn data give an invalid problem.

        When solving for values a user gave (strict=False) the reason becomes a warning instead.
        """
        if not condition:
            if self.strict:
                raise InvalidDraw(reason)
            self.warnings.append(reason)

    def __getitem__(self, name: str) -> Step:
        return self._by_name[name]

    def __contains__(self, name: str) -> bool:
        return name in self._by_name

    # ---- worked-solution text ------------------------------------------------------------

    def symbol_of(self, name: str) -> str:
        if name in self._by_name:
            return self._by_name[name].symbol
        return self.params._symbols.get(name, default_symbol(name))

    def value_of(self, name: str):
        if name in self._by_name:
            return self._by_name[name].value
        return getattr(self.params, name)


def is_finite(value) -> bool:
    return isinstance(value, (int, float)) and math.isfinite(value)
