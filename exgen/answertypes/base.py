"""What every answer type provides, with the defaults most types share.

A type is a small object (one module each, `TYPE = ...` at module level, found by the registry in
`__init__`): it checks a part's YAML at bank load, finds the expected answer and the known mistake
values among a solver's steps, shows the answer on the sheet, in the answer file and in the key, reads
what a student typed (a format problem is not a wrong answer), compares, and names generic slips.
Loaders, variants, validate, renderers and the grader ask the type and never branch on its name.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

from .. import units
from ..errors import ExgenError, FormatProblem, NoAnswer
from ..load.template import PartSpec, Tolerance

#: A named mistake must land at least this many tolerances from the right answer; any closer and
#: a student who made it could be marked right (see `AnswerType.apart`).
MISTAKE_GAP = 3.0
#: Typed answers longer than this are refused before any reading (quantities: exgen.units).
MAX_ANSWER_LENGTH = 200

#: `report(keys, message)`: a problem with the part's YAML at these keys (below the part).
Report = Callable[[tuple, str], None]


@dataclass(frozen=True)
class Given:
    """A readable answer: the text as typed, the value in the asked form, and how it was written."""

    text: str
    value: Any
    number: float | None = None  # the number as typed, before conversion
    unit: str | None = None      # the unit as typed; None for a bare number read in the asked unit

    @property
    def bare(self) -> bool:
        return self.unit is None


@dataclass(frozen=True)
class Mistake:
    """A recognised wrong answer: a short name (for statistics) and the feedback a student reads."""

    name: str
    message: str


class AnswerType:
    """The defaults; a type overrides what differs. `part` is always the PartSpec being answered."""

    name = ""
    #: YAML keys a part of this type may carry besides the common ones (id, ask, answer, unit, ...).
    part_keys: tuple[str, ...] = ()
    #: Keys its `tol:` accepts; none means the type is graded exactly.
    tol_keys: tuple[str, ...] = ()
    default_tol = Tolerance(rel=0.0, abs=0.0)

    # ---- bank loading ---------------------------------------------------------------------

    def load_options(self, spec: Mapping, report: Report) -> dict:
        """The type's own settings from the part's YAML (its `part_keys`), checked."""
        return {}

    def load_tolerance(self, spec, report: Report) -> Tolerance:
        """The part's `tol:` over the type's defaults; every problem is reported, never raised."""
        if spec is None:
            return self.default_tol
        if not self.tol_keys:
            report(("tol",), f"{_article(self.name)} {self.name} answer is graded exactly; remove `tol:`")
            return self.default_tol
        if not isinstance(spec, dict):
            report(("tol",), "must be a mapping such as {rel: 0.01}")
            return self.default_tol
        values = {}
        for key, value in spec.items():
            if key not in self.tol_keys:
                report(("tol", key), f"not a tolerance of {_article(self.name)} {self.name} answer; "
                                     f"expected one of {', '.join(self.tol_keys)}")
            elif isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= 0:
                report(("tol", key), "must be a number >= 0")
            else:
                values[key] = value
        return self.tolerance_from(values, report)

    def tolerance_from(self, values: dict, report: Report) -> Tolerance:
        """The Tolerance for checked `tol:` values (a type with rules between keys checks them here)."""
        base = self.default_tol
        return Tolerance(rel=float(values.get("rel", base.rel)), abs=float(values.get("abs", base.abs)),
                         sig=int(values["sig"]) if values.get("sig") else base.sig)

    # ---- variants: the expected answer and the mistake values, from the solver's steps -------

    def steps(self, part: PartSpec) -> tuple[str, ...]:
        """The solver steps the answer is read from."""
        return (part.answer,)

    def expected(self, part: PartSpec, derivation) -> Any:
        """The answer in the form it is asked (NoAnswer when the solver's steps hold none)."""
        return self.step_value(part, derivation, part.answer)

    def mistake_values(self, part: PartSpec, derivation) -> dict[str, Any]:
        """What each known mistake recorded on the answer's step gives, in the asked form."""
        return dict(derivation.mistakes.get(part.answer, {}))

    def step_value(self, part: PartSpec, derivation, name: str) -> Any:
        """The value of the solver's step `name` (ExgenError naming the part when the solver records none)."""
        if name not in derivation:
            raise ExgenError(f"{name!r} (answer of part {part.id}) is not a step the solver records")
        return derivation[name].value

    def problem(self, value, part: PartSpec) -> str | None:
        """What is wrong with an expected answer, if anything (validate checks every draw)."""
        return None

    def text(self, value, part: PartSpec) -> str:
        """The answer as plain text, as the key prints it and a student could type it."""
        return f"{value} {units.pretty_unit(part.unit)}".strip()

    # ---- what the sheet, the answer file and the key show ------------------------------------

    def hint(self, part: PartSpec) -> str:
        """After the question on the sheet: what the answer must look like ("answer in kW")."""
        return f"answer in {asked_unit(part)}" if part.unit else "a pure number"

    def form_hint(self, part: PartSpec) -> str:
        """At the end of the part's line in the answer file, in [brackets]: the unit as the question prints it
        (N·m, not N*m), degrees as deg."""
        return asked_unit(part) or "pure number"

    def form_note(self) -> str:
        """Lines for the answer file's header when the sheet has parts of this type ("" for none)."""
        return ""

    def form_choices(self, part: PartSpec) -> tuple[str, ...] | None:
        """The choices a sheet's form offers for the part (a drop-down), or None for a box to type into."""
        return None

    def tolerance_text(self, part: PartSpec) -> str:
        """The tolerance the grader applies, in words: the key prints it and feedback quotes it."""
        return "exact"

    def key_text(self, answer, target) -> str:
        """The expected answer in a key, written for `target` (render.targets)."""
        return target.prose(self.text(answer.value, answer.part))

    def worked_values(self, answer, step_name: str) -> tuple[tuple[Any, str], ...]:
        """The answer again in the part's unit, after the worked line of `step_name` (when it differs)."""
        return ()

    # ---- grading -----------------------------------------------------------------------------

    def read(self, text: str, part: PartSpec) -> Given:
        """What the student typed, in the asked form. FormatProblem if it cannot be read;
        WrongKind if it reads as an answer of another kind (a length where a force is asked)."""
        raise NotImplementedError

    def format_hint(self, part: PartSpec) -> str:
        """How to write an answer, for a format problem's message ("write one of ...")."""
        return f"write an answer such as \"{self.text(self.example(part), part)}\""

    def example(self, part: PartSpec) -> Any:
        """A value of this type, to show how an answer is written."""
        raise NotImplementedError

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        """Right within the part's tolerance (scaled by `widen`, to tell "close" from "wrong")."""
        return given == expected

    def reach(self, value, part: PartSpec, widen: float = 1.0) -> float | None:
        """How far from `value` an expected value that `value` `matches` (with `widen`) can lie, at most:
        a caller comparing one answer with a class's keys sorted by value looks only that far. None
        when no such bound holds (values that are not numbers, or a tolerance that is not a distance)."""
        return None

    def apart(self, mistake, answer, part: PartSpec) -> bool:
        """A named mistake is far enough from the right answer that neither can pass for the other:
        outside MISTAKE_GAP times the tolerance (for an exact type: different)."""
        try:
            return not self.matches(mistake, answer, part, MISTAKE_GAP)
        except (TypeError, ValueError, ArithmeticError):
            return True

    def gives_away(self, value, answer) -> bool:
        """Whether a value shown to a student (a hint's value, a number in a formula) would hand them
        `answer`: a number read in any unit of the answer's kind, with either sign, right within the
        part's tolerance (a choice: the word itself). False for types nothing shown can give away."""
        return False

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        """Why a wrong answer no mistake explains is wrong."""
        return "not the expected answer"

    def slip(self, given: Given, expected, part: PartSpec) -> Mistake | None:
        """A generic slip that explains a wrong answer (units confused, the sign, ...), if any."""
        return None

    def nudges(self, value, part: PartSpec) -> tuple:
        """Other values of this type, nearest first, to check that a later part follows this one
        (validate: a count or a choice worked from it changes only past some threshold); empty when
        answers of this type are never carried forward."""
        return ()

    def overrides(self, part: PartSpec, value, variant) -> dict[str, Any]:
        """Step values (in the steps' units) that put the student's answer into the derivation, for
        error carried forward; empty when an answer of this type cannot be carried."""
        return {}

    # ---- learning systems ----------------------------------------------------------------------

    #: Why a part of this type has no form a learning system can grade (exports leave it out, saying so).
    lms_missing = "no learning-system response can grade it"

    def lms_gaps(self, part: PartSpec, value, mistakes: Mapping[str, tuple[Any, str]]) -> tuple:
        """The gaps (exgen.answertypes.lms) an export writes for this part: the expected `value` and the
        named `mistakes` (name -> (value, feedback)) in the asked form. NoLmsForm when there are none."""
        from .lms import NoLmsForm

        raise NoLmsForm(self.lms_missing)

    def sample_part(self) -> PartSpec:
        """A typical part of this type, for tests that cover every registered type."""
        return PartSpec("a", "the answer", "x", type=self.name, tol=self.default_tol)


def refuse_long(text: str, limit: int = MAX_ANSWER_LENGTH) -> str:
    """The text, if it is short enough to read at all."""
    if len(text) > limit:
        raise FormatProblem(f"answer longer than {limit} characters")
    return text


def finite(part: PartSpec, value) -> float:
    """A solver value that must be a finite number; NoAnswer (the solver's defect) otherwise."""
    if isinstance(value, bool) or not (isinstance(value, (int, float)) and math.isfinite(value)):
        raise NoAnswer(f"part {part.id}: answer {value!r} is not a finite number")
    return float(value)


def exact_quantity(value: float, unit: str) -> str:
    """A tolerance as written in a template: 0.5 deg is "0.5°", not "0.5000°"."""
    shown = units.pretty_unit(unit)
    number = f"{value:g}"
    if not shown:
        return number
    return f"{number}{shown}" if shown in ("\u00b0", "%") else f"{number} {shown}"


def asked_unit(part: PartSpec) -> str:
    """The unit an answer is asked in, as the sheet writes it ('deg', 'kW', 'N·m')."""
    # "in" is spelt out: never "answer in in"
    return {"deg": "deg", "degree": "deg", "percent": "%", "in": "inches"}.get(part.unit, units.pretty_unit(part.unit)) \
        if part.unit else ""


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"
