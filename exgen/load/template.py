"""The typed form of a template file: what a problem draws, asks and accepts.

Instances are built once by `exgen.load.bank` (which validates them) and never change.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from decimal import Decimal
from functools import lru_cache
from pathlib import Path
from typing import Any, Mapping


@dataclass(frozen=True)
class ParamSpec:
    """One given quantity: drawn from a stepped range or a list of choices, printed in `unit`."""

    name: str
    unit: str = ""
    label: str = ""
    symbol: str = ""
    min: Decimal | None = None
    max: Decimal | None = None
    step: Decimal | None = None
    choices: tuple = ()
    equals: str = ""  # a given worked out from earlier ones (e.g. the loop that closes a cycle)
    domain: str = ""  # the values that make physical sense, as an interval (exgen.load.domains); "" derives it
    given: bool = True  # False: it only chooses what the figure draws (the figure is the given), not a key's given
    # words `exgen solve` accepts besides the choices, never drawn: a textbook's own value no real machine has
    also_solves: tuple = ()

    @property
    def derived(self) -> bool:
        return bool(self.equals)

    @property
    def is_range(self) -> bool:
        return self.step is not None

    @property
    def count(self) -> int:
        """How many distinct values the parameter can take."""
        if self.is_range:
            return int((self.max - self.min) / self.step) + 1
        return len(self.choices)

    def value_at(self, index: int):
        """The index-th allowed value, exact (Decimal for ranges, the choice itself otherwise)."""
        if self.is_range:
            return self.min + self.step * index
        return self.choices[index]


@dataclass(frozen=True)
class Tolerance:
    """How far an answer may be from the key: `rel` of it, within `abs` of it, or (with `sig`) to that
    many significant figures. What each means for a type, and its default, is the type's (exgen.answertypes);
    the defaults here are a number's (1 %)."""

    rel: float = 0.01
    abs: float = 0.0
    sig: int | None = None

    def as_dict(self) -> dict:
        return {k: v for k, v in (("rel", self.rel), ("abs", self.abs), ("sig", self.sig)) if v}


@dataclass(frozen=True)
class MistakeSpec:
    """A known wrong answer: `when` names a value the solver computes; `say` is the feedback."""

    when: str
    say: str = ""


@dataclass(frozen=True)
class PartSpec:
    """One question of a template: what is asked, the step that answers it, and how it is graded.
    `options` holds what only its answer type reads (a choice's `choices`, a polar answer's `angle`)."""

    id: str
    ask: str
    answer: str
    unit: str = ""
    type: str = "number"
    tol: Tolerance = field(default_factory=Tolerance)
    points: float = 1.0
    mistakes: tuple[MistakeSpec, ...] = ()
    uses: tuple[str, ...] = ()
    options: Mapping[str, Any] = field(default_factory=dict)
    hints: tuple[str, ...] = ()  # a ladder of hints for practice, first to last (text with $LaTeX$)

    def __post_init__(self):
        object.__setattr__(self, "options", dict(self.options))  # a copy: nobody else's dict to change


@dataclass(frozen=True)
class ReportSpec:
    """A derived quantity a template reports, with the range a real machine keeps it in.

    `value` is an expression over the parameters and solver steps (SI); `unit` is the unit the
    value and `low`..`high` are written in. A draw outside the range is rejected; `exgen solve`
    warns instead, and `exgen validate` prints the range each quantity was drawn over.
    """

    what: str
    value: str
    unit: str
    low: float
    high: float


@dataclass(frozen=True)
class Template:
    id: str
    title: str
    chapter: int
    section: str
    params: tuple[ParamSpec, ...]
    require: tuple[str, ...]
    solver: str
    statement: str
    parts: tuple[PartSpec, ...]
    figure: str | None = None
    key_figures: tuple[str, ...] = ()  # figures only the key shows, beside the working
    source: str = ""
    topic: str = ""
    path: Path | None = None
    bank_dir: Path | None = None  # the folder of templates it was loaded from, which may hold its own code
    digest: str = ""  # sha256 of the parsed data (exgen.load.versions.data_digest); its full version: template_version
    report: tuple[ReportSpec, ...] = ()

    def param(self, name: str) -> ParamSpec:
        return next(p for p in self.params if p.name == name)

    def part(self, part_id: str) -> PartSpec:
        return next(p for p in self.parts if p.id == part_id)

    @property
    def points(self) -> float:
        return sum(p.points for p in self.parts)


GREEK = {
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda",
    "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega",
    "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
}


@lru_cache(maxsize=4096)
def default_symbol(name: str) -> str:
    """The LaTeX symbol of a parameter or step that gives none, made from its name: mu -> \\mu, d1 -> d_1, T_max -> T_{\\mathrm{max}}, omega_2 -> \\omega_2."""
    if "_" in name:
        base, sub = name.split("_", 1)
    else:
        match = re.fullmatch(r"(.*?[A-Za-z])(\d+)", name)
        base, sub = match.groups() if match else (name, "")
    head = f"\\{base}" if base in GREEK else base
    if not sub:
        return head
    if sub in GREEK:
        sub = f"\\{sub}"
    elif len(sub) > 1 and not sub.isdigit():
        sub = r"\mathrm{" + sub + "}"
    return f"{head}_{{{sub}}}" if len(sub) > 1 else f"{head}_{sub}"
