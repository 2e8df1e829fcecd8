"""A Variant: one drawn problem, frozen. Every renderer and the grader read it; none change it."""
from __future__ import annotations

import traceback
from dataclasses import dataclass, field
from decimal import Decimal
from functools import cached_property
from pathlib import Path
from types import MappingProxyType
from typing import Any, Mapping

from .. import units
from ..answertypes import answer_type
from ..answertypes.base import MISTAKE_GAP
from ..draw.plausibility import Implausible, Reading, early_rejection, first_implausible, names_for, readings
from ..draw.values import draw_values, failed_requirement, generator, si_values
from ..errors import DrawError, ExgenError, InvalidDraw, NoAnswer, SolverFailure, TemplateError
from ..load.references import resolve
from ..load.template import PartSpec, Template, default_symbol
from ..load.mistake_messages import message_for
from ..load.text import STEPS, render_text
from .derivation import PLACEHOLDER, Derivation, Params, Step

#: How a warning for values a user gave says a named mistake would be marked right (exgen solve explains it).
MISTAKE_CLOSE = "lands within"
MISTAKE_IS_ANSWER = "gives the answer itself"

MAX_TRIES = 1000


@dataclass(frozen=True)
class ParamValue:
    """A given value as printed (exact) and in SI."""

    name: str
    exact: Decimal | str
    unit: str
    si: float | str
    label: str = ""
    symbol: str = ""

    @property
    def text(self) -> str:
        return units.format_decimal(self.exact) if isinstance(self.exact, Decimal) else self.exact

    def __str__(self) -> str:  # what {{ d1 }} prints in a statement
        shown = units.pretty_unit(self.unit)
        if not shown:
            return self.text
        return f"{self.text}{shown}" if shown in ("\u00b0", "%") else f"{self.text} {shown}"


@dataclass(frozen=True)
class Answer:
    """The expected answer of a part, in the unit the sheet asks for."""

    part: PartSpec
    value: Any
    si: Any
    step: Step

    @property
    def text(self) -> str:
        return answer_type(self.part).text(self.value, self.part)


@dataclass(frozen=True)
class Variant:
    template: Template
    seed: int | None
    params: tuple[ParamValue, ...]
    steps: tuple[Step, ...]
    answers: Mapping[str, Answer]
    mistakes: Mapping[str, Mapping[str, Any]]  # part id -> mistake name -> value in asked unit
    tries: int = field(default=1, compare=False)
    warnings: tuple[str, ...] = ()
    inserts: tuple = ()  # tables of the worked solution (derivation.Table)
    derived: tuple[Reading, ...] = ()  # the template's `report:` quantities, in their units
    worked_uses: frozenset[str] = frozenset()  # givens the solver read or a formula or table names

    @cached_property
    def statement(self) -> str:
        """The statement with this variant's values (written when first read: grading never reads it)."""
        return self._text(self.template.statement, "statement")

    @cached_property
    def asks(self) -> Mapping[str, str]:
        """What each part asks, with this variant's values (written when first read)."""
        return MappingProxyType({p.id: self._text(p.ask, f"parts.{p.id}.ask") for p in self.template.parts})

    @property
    def unused(self) -> frozenset[str]:
        """Givens its text and working leave out (one idler: the second's teeth), and those that only choose
        what the figure draws (`given: false`)."""
        self.statement, self.asks  # noqa: B018  (written, they note what they printed)
        used = self._printed | self.worked_uses
        drawn_only = {spec.name for spec in self.template.params if not spec.given}
        return frozenset(p.name for p in self.params if p.name not in used or p.name in drawn_only)

    @cached_property
    def _printed(self) -> set[str]:
        """Givens the statement and asks written so far printed or tested."""
        return set()

    def _text(self, text: str, key: str) -> str:
        try:
            return render_text(text, {p.name: _Watched(p, self._printed) for p in self.params})
        except Exception as exc:
            if not type(exc).__module__.startswith("jinja2"):
                raise
            # a text that a bank loaded without its full check let through (exgen.load.bank.load_bank)
            raise TemplateError(self.template.path, key, f"cannot be written: {exc}") from None

    def param(self, name: str) -> ParamValue:
        return next(p for p in self.params if p.name == name)

    @property
    def si(self) -> dict[str, Any]:
        return {p.name: p.si for p in self.params}

    def step(self, name: str) -> Step:
        return next(s for s in self.steps if s.name == name)

    def fill(self, text: str) -> str:
        """A text of the template shown beside this variant (a hint, a mistake's feedback) with its given
        values, as its statement has them, and its word steps under `steps` (exgen.load.text)."""
        return render_text(text, self.text_context)

    @property
    def text_context(self) -> dict[str, Any]:
        """What a hint or a mistake's feedback may name: each given, and under `steps` the steps whose values
        are words ("towards the bow", "left"); numbers stay the working's, which withholds what gives an
        answer away."""
        words = {s.name: s.value for s in self.steps if isinstance(s.value, str)}
        return {**{p.name: p for p in self.params}, STEPS: words}

    def mistake_message(self, part_id: str, name: str) -> str:
        """The feedback for the named mistake in a part: its `say:`, else the name's default text, written
        with this variant."""
        says = {m.when: m.say for m in self.template.part(part_id).mistakes}
        return self.fill(message_for(name, says.get(name, "")))


def make_variant(template: Template, seed: int, max_tries: int = MAX_TRIES, rejected=None) -> Variant:
    """Draw until the constraints hold and the solver accepts the data (bounded tries).

    `rejected`, a Counter, counts why draws were turned down (for `exgen validate`)."""
    rng = generator(seed)
    reason = ""
    for attempt in range(1, max_tries + 1):
        values = draw_values(template, rng)
        try:
            return build_variant(template, values, seed=seed, tries=attempt)
        except InvalidDraw as exc:
            reason = str(exc)
            if rejected is not None:
                rejected[f"implausible {exc.what}" if isinstance(exc, Implausible) else reason] += 1
    raise DrawError(template.id, max_tries, reason)


def build_variant(template: Template, values: dict, *, seed: int | None = None, tries: int = 1,
                  check: bool = True) -> Variant:
    """Solve for given printed values; raise InvalidDraw if they break a constraint."""
    si = si_values(template, values)
    if check:
        broken = failed_requirement(template, si)
        if broken:
            raise InvalidDraw(f"requires {broken}")
        odd = early_rejection(template, si)
        if odd is not None:
            raise Implausible(odd)
    derivation = run_solver(template, si, strict=check, seed=seed)
    derived = readings(template, names_for(si, derivation.steps))
    odd = first_implausible(derived)
    if odd is not None and check:
        raise Implausible(odd)
    found_warnings = [r.complaint() for r in derived if not r.plausible]
    params = tuple(
        ParamValue(s.name, values[s.name], s.unit, si[s.name], s.label, s.symbol or default_symbol(s.name))
        for s in template.params
    )
    answers, mistakes = {}, {}
    for part in template.parts:
        try:
            answers[part.id] = answer_for(part, derivation)
        except NoAnswer as exc:  # an infinite or missing answer is the solver's defect, not a bad draw
            raise SolverFailure(template.id, exc, seed=seed, given="" if check else "the values given") from exc
        mistakes[part.id] = MappingProxyType(mistakes_apart(part, answers[part.id].value, derivation, check))
    return Variant(
        template=template, seed=seed, params=params, steps=tuple(derivation.steps),
        answers=MappingProxyType(answers), mistakes=MappingProxyType(mistakes),
        tries=tries, warnings=tuple(derivation.warnings) + tuple(found_warnings), inserts=tuple(derivation.inserts),
        derived=derived, worked_uses=frozenset(derivation.params.read | _named_in_working(derivation)),
    )


class _Watched:
    """A given as a text sees it, noting in `seen` that the text printed or tested it (a branch not
    taken, `{% if idlers.text == "2" %}...{{ tb }}`, leaves `tb` unseen)."""

    __slots__ = ("_value", "_seen")

    def __init__(self, value: ParamValue, seen: set[str]):
        self._value, self._seen = value, seen

    def __str__(self) -> str:
        self._seen.add(self._value.name)
        return str(self._value)

    def __getattr__(self, name: str):
        self._seen.add(self._value.name)
        return getattr(self._value, name)


def _named_in_working(derivation: Derivation) -> set[str]:
    """Givens a formula or a table of the working names as @name."""
    names = {m for step in derivation.steps for m in PLACEHOLDER.findall(step.formula or "")}
    return names.union(*(table.names for table in derivation.inserts))


def mistakes_apart(part: PartSpec, answer, derivation: Derivation, check: bool = True) -> dict[str, Any]:
    """The part's mistake values, each far enough from the answer that neither passes for the other
    (MISTAKE_GAP times the tolerance; for an exact type, any difference). A mistake the part names that
    lands closer rejects the draw (with `check`; else it is a warning, for values a user gave): a student
    who made it would be marked right, and the sheet would not test what the part says it tests. One
    recorded `if_apart`, or one the part does not name, is dropped instead."""
    kind = answer_type(part)
    named = {m.when for m in part.mistakes}
    steps = kind.steps(part)
    kept = {}
    for name, wrong in mistakes_for(part, derivation).items():
        if kind.apart(wrong, answer, part):
            kept[name] = wrong
        elif name in named and not any((s, name) in derivation.if_apart for s in steps):
            tolerance = kind.tolerance_text(part)
            reason = (f"part {part.id}: the mistake {name!r} {MISTAKE_IS_ANSWER}" if tolerance == "exact" else
                      f"part {part.id}: the mistake {name!r} {MISTAKE_CLOSE} {MISTAKE_GAP:g} times {tolerance} of "
                      f"the answer")
            if check:
                raise InvalidDraw(reason)
            derivation.warnings.append(reason)
    return kept


def run_solver(template: Template, si: dict, overrides: dict | None = None, strict: bool = True,
               seed: int | None = None) -> Derivation:
    """The template's derivation for SI values. Only InvalidDraw (a `d.require` or a rejection the solver
    raises by name) says the values give no problem; anything else the solver raises is its defect,
    raised as SolverFailure naming the template, the seed, the exception and where it rose."""
    symbols = {s.name: s.symbol or default_symbol(s.name) for s in template.params}
    derivation = Derivation(Params(si, symbols), overrides, strict)
    solver = resolve(template.solver, "solvers")
    try:
        solver(derivation.params, derivation)
    except ExgenError:
        raise
    except Exception as exc:  # noqa: BLE001  (every other exception is a defect, reported as one)
        given = "" if strict else "other earlier answers" if overrides else "the values given"
        raise SolverFailure(template.id, exc, where_raised(exc, solver), seed, given) from exc
    return derivation


def where_raised(exc: BaseException, solver=None) -> str:
    """'exgen/mechanics/flywheels.py:160 in speed_after (from exgen/solvers/flywheels.py:88 in punching_press)':
    the line that raised, and the solver's line that led there (in exgen.solvers or the solver's own file)."""
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if f.name != "run_solver"]
    if not frames:
        return ""
    raised = frames[-1]
    own = getattr(getattr(solver, "__code__", None), "co_filename", None)
    solver = next((f for f in reversed(frames) if Path(f.filename).parent.name == "solvers" or f.filename == own),
                  raised)
    text = f"{_short(raised.filename)}:{raised.lineno} in {raised.name}"
    return text if solver is raised else f"{text} (from {_short(solver.filename)}:{solver.lineno} in {solver.name})"


_ROOT = Path(__file__).resolve().parent.parent.parent  # the folder holding the exgen package


def _short(filename: str) -> str:
    path = Path(filename).resolve()
    return path.relative_to(_ROOT).as_posix() if path.is_relative_to(_ROOT) else filename


def answer_for(part: PartSpec, derivation: Derivation) -> Answer:
    """The expected answer of a part, as its type reads it from the solver's steps."""
    if part.answer not in derivation:
        raise ExgenError(f"{part.answer!r} (answer of part {part.id}) is not a step the solver records")
    step = derivation[part.answer]
    return Answer(part, answer_type(part).expected(part, derivation), step.value, step)


def mistakes_for(part: PartSpec, derivation: Derivation) -> dict[str, Any]:
    """The value each known mistake recorded for a part's steps gives, in the asked form."""
    return answer_type(part).mistake_values(part, derivation)


def rerun(variant: Variant, overrides: dict[str, float]) -> Derivation:
    """The variant's derivation with some steps replaced (SI values), for error carried forward."""
    return run_solver(variant.template, variant.si, overrides, strict=False, seed=variant.seed)
