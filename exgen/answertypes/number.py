"""A number with a unit: right within a relative tolerance (1 % by default), an absolute floor, or
to a number of significant figures; any unit of the right kind is converted, a bare number is read
in the asked unit. Generic slips named: units confused, a wrong prefix, percent for fraction, the sign,
and rounding too early.
"""
from __future__ import annotations

import math

from .. import units
from ..errors import ExgenError
from ..load.template import PartSpec, Tolerance
from .base import AnswerType, Given, Mistake, Report, exact_quantity, finite
from .lms import NumericGap, wrong_numbers
from .quantity import accepted_units, in_unit, unit_name, units_of_kind

#: A number is right within 1 % (textbook working rounds to 3-4 figures) ...
REL_TOL = 0.01
#: ... or within this absolute floor, for answers that can be zero.
ABS_TOL = 0.0
#: With significant figures, the given value may differ by this many units in the last figure.
SIG_FIG_SLACK = 0.51
MAX_SIG = 15
#: Within this many tolerances a wrong answer is "close": most likely the right method rounded too early.
CLOSE_FACTOR = 3

#: A number shown in a hint is read with these prefixes too (k, m) when it is checked for giving an answer away:
#: kinds with one stored unit (N·s/m) are written with a prefix as well.
PREFIXES = (1.0, 1e3, 1e-3)

#: Units students confuse within one kind; a bare number matching the answer in another is named.
CONFUSABLE = (("deg", "rad"), ("rpm", "rad/s", "Hz"))
_WORDS = {"deg": "degrees", "rad": "radians", "rpm": "rpm", "rad/s": "rad_s", "Hz": "hz"}

UNIT_CONFUSED_BARE = ("{number} is the answer in {other}, but a bare number is read in {asked}, the unit asked. "
                      "Convert ({one}), or write the unit after the number.")
UNIT_CONFUSED_WRITTEN = ("{number} is the answer in {other}, not in {written}: the unit is wrong ({one}).")
WRONG_PREFIX = ("Your value is {factor} the expected one: check the unit prefix (k = 10³, M = 10⁶, m = 10⁻³); "
                "a bare number is read in {asked}.")
PERCENT_FOR_FRACTION = "That is a percentage, but a fraction is asked: divide by 100."
FRACTION_FOR_PERCENT = "That is a fraction, but a percentage is asked: multiply by 100 (or write the % sign)."
WRONG_SIGN = "Right size, wrong sign: check the direction you took as positive."
PREMATURE_ROUNDING = ("Close ({off} off), but outside the {tol} tolerance. If your method is right, rounding "
                      "too early is the likely cause: keep at least four significant figures in intermediate results.")
NOT_WITHIN = "not within {tol} of the expected value"
FORMAT_HINT = "write a number with an optional unit, such as \"{example}\""


def numeric(given: float, expected: float, rel: float = REL_TOL, abs_tol: float = ABS_TOL,
            sig: int | None = None) -> bool:
    """Within `rel` of the expected value or within `abs_tol` of it; with `sig`, within half a unit
    in the sig-th significant figure instead of `rel`."""
    if not (math.isfinite(given) and math.isfinite(expected)):
        return False
    error = abs(given - expected)
    if error <= abs_tol:
        return True
    if sig:
        return error <= sig_fig_tolerance(expected, sig)
    return error <= rel * abs(expected)


def sig_fig_tolerance(expected: float, sig: int) -> float:
    """Half a unit (a little more, for float noise) in the sig-th significant figure of `expected`."""
    if expected == 0:
        return 0.0
    power = math.floor(math.log10(abs(expected)))
    return SIG_FIG_SLACK * 10.0 ** (power - sig + 1)


class Number(AnswerType):
    name = "number"
    tol_keys = ("rel", "abs", "sig")
    default_tol = Tolerance(rel=REL_TOL, abs=ABS_TOL)

    def tolerance_from(self, values: dict, report: Report) -> Tolerance:
        """`sig` replaces the relative tolerance: "to 3 significant figures" is its own rule, so
        a part gives `rel` or `sig`, not both."""
        if "sig" in values:
            if "rel" in values:
                report(("tol",), "give `rel` or `sig`, not both: with `sig` an answer is right to that "
                                 "many significant figures, whatever its relative error")
            if not float(values["sig"]).is_integer() or not 1 <= values["sig"] <= MAX_SIG:
                report(("tol", "sig"), f"must be a whole number of figures from 1 to {MAX_SIG}")
                return self.default_tol
            return Tolerance(rel=0.0, abs=float(values.get("abs", ABS_TOL)), sig=int(values["sig"]))
        return super().tolerance_from(values, report)

    # ---- variants ----------------------------------------------------------------------------

    def expected(self, part: PartSpec, derivation) -> float:
        value = finite(part, self.step_value(part, derivation, part.answer))
        return units.convert(value, derivation[part.answer].unit, part.unit)

    def mistake_values(self, part: PartSpec, derivation) -> dict[str, float]:
        unit = derivation[part.answer].unit
        return {name: units.convert(float(value), unit, part.unit)
                for name, value in derivation.mistakes.get(part.answer, {}).items()
                if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)}

    def problem(self, value, part: PartSpec) -> str | None:
        if not (isinstance(value, float) and math.isfinite(value)):
            return f"answer {value!r} is not a finite number"
        return None

    def text(self, value, part: PartSpec) -> str:
        return units.format_quantity(value, part.unit)

    def worked_values(self, answer, step_name: str):
        return ((answer.value, answer.part.unit),)

    # ---- display -----------------------------------------------------------------------------

    def tolerance_text(self, part: PartSpec) -> str:
        """"1 %", "3 significant figures", "1 % or 0.5 N": the rule `matches` applies."""
        tol, pieces = part.tol, []
        if tol.sig:
            pieces.append(f"{tol.sig} significant figures")
        elif tol.rel:
            pieces.append(f"{100 * tol.rel:g} %")
        if tol.abs:
            pieces.append(exact_quantity(tol.abs, part.unit))
        return " or ".join(pieces) or "exact"

    # ---- grading -----------------------------------------------------------------------------

    def read(self, text: str, part: PartSpec) -> Given:
        reading, value = in_unit(text, part.unit)
        return Given(text, value, reading.value, reading.unit)

    def example(self, part: PartSpec) -> float:
        return 12.5

    def format_hint(self, part: PartSpec) -> str:
        return FORMAT_HINT.format(example=units.format_quantity(self.example(part), part.unit, 3))

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        tol = part.tol
        if tol.sig:
            return numeric(given, expected, 0.0, max(tol.abs, sig_fig_tolerance(expected, tol.sig)) * widen)
        return numeric(given, expected, tol.rel * widen, tol.abs * widen)

    def reach(self, value, part: PartSpec, widen: float = 1.0) -> float | None:
        """`matches` allows |given - expected| <= max(abs, rel |expected|) (with `sig`, rel is at most
        0.51 in the sig-th figure: 0.51 x 10^(1 - sig)), all widened; and |expected| <= |given| + that
        distance. A little more, for rounding."""
        if not (isinstance(value, (int, float)) and math.isfinite(value)):
            return None
        tol = part.tol
        rel = (SIG_FIG_SLACK * 10.0 ** (1 - tol.sig) if tol.sig else tol.rel) * widen
        if rel >= 0.5:
            return None
        distance = max(tol.abs * widen, rel * abs(value) / (1 - rel))
        return distance * (1 + 1e-6) + 4 * math.ulp(value)

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        return NOT_WITHIN.format(tol=self.tolerance_text(part))

    #: Whether a number in a hint is also read with a prefix (not for angles: degrees have none).
    prefixed = True

    def gives_away(self, value, answer) -> bool:
        part = answer.part
        return any(self.matches(value, answer.value, part) or self.matches(-value, answer.value, part)
                   for value in readings(value, part.unit, PREFIXES if self.prefixed else (1.0,)))

    def nudges(self, value, part: PartSpec) -> tuple[float, ...]:
        return (value * 1.02, value * 0.5, value * 2, -value) if value else (1.0, -1.0)

    def overrides(self, part: PartSpec, value, variant) -> dict[str, float]:
        return {part.answer: units.convert(float(value), part.unit, variant.step(part.answer).unit)}

    def slip(self, given: Given, expected, part: PartSpec) -> Mistake | None:
        if not isinstance(expected, (int, float)):
            return None
        for detect in self.detectors():
            try:
                found = detect(part, given, float(expected))
            except (ExgenError, ArithmeticError, ValueError):
                found = None
            if found:
                return found
        if self.matches(given.value, expected, part, CLOSE_FACTOR):
            return Mistake("premature_rounding", PREMATURE_ROUNDING.format(
                off=_percent(abs(given.value - expected) / abs(expected)) if expected else "slightly",
                tol=self.tolerance_text(part)))
        return None

    def detectors(self):
        return (self._unit_confused, self._wrong_prefix, self._percent_fraction, self._wrong_sign)

    def _unit_confused(self, part, given, expected) -> Mistake | None:
        written = given.unit or part.unit
        for group in CONFUSABLE:
            if not units.same_dimension(part.unit, group[0]):
                continue
            for other in group:
                if _same_unit(other, written):
                    continue
                if numeric(given.number, units.convert(expected, part.unit, other), max(part.tol.rel, REL_TOL)):
                    one = f"1 {units.pretty_unit(other)} = {units.format_quantity(units.convert(1.0, other, written), written)}"
                    text = UNIT_CONFUSED_BARE if given.bare else UNIT_CONFUSED_WRITTEN
                    return Mistake(f"{_word(other, group)}_for_{_word(written, group)}", text.format(
                        number=units.format_number(given.number), other=unit_name(other),
                        asked=unit_name(part.unit), written=unit_name(written), one=one))
        return None

    def _wrong_prefix(self, part, given, expected) -> Mistake | None:
        for power in (3, -3, 6, -6):
            if expected and self.matches(given.value, expected * 10.0 ** power, part):
                factor = f"{10 ** power:,} times" if power > 0 else f"1/{10 ** -power:,} of"
                return Mistake("wrong_prefix", WRONG_PREFIX.format(factor=factor, asked=unit_name(part.unit)))
        return None

    def _percent_fraction(self, part, given, expected) -> Mistake | None:
        info = units.unit_info(part.unit)
        if info.dims != "dimensionless" or info.angle:
            return None
        percent_asked = abs(info.factor - 0.01) < 1e-12
        if percent_asked and self.matches(given.value, expected / 100, part):
            return Mistake("fraction_for_percent", FRACTION_FOR_PERCENT)
        if not percent_asked and self.matches(given.value, expected * 100, part):
            return Mistake("percent_for_fraction", PERCENT_FOR_FRACTION)
        return None

    def _wrong_sign(self, part, given, expected) -> Mistake | None:
        if expected and self.matches(given.value, -expected, part):
            return Mistake("wrong_sign", WRONG_SIGN)
        return None

    # ---- learning systems ----------------------------------------------------------------------

    def lms_tolerance(self, part: PartSpec, value: float) -> float:
        """The absolute tolerance `matches` gives around `value`: a learning system knows no other kind."""
        tol = part.tol
        if tol.sig:
            return max(tol.abs, sig_fig_tolerance(value, tol.sig))
        return max(tol.abs, tol.rel * abs(value))

    def lms_gaps(self, part: PartSpec, value, mistakes) -> tuple[NumericGap, ...]:
        def tolerance(v: float) -> float:
            return self.lms_tolerance(part, v)

        right = float(value)
        return (NumericGap("", right, tolerance(right), units.pretty_unit(part.unit), units=accepted_units(part.unit),
                           wrong=wrong_numbers(mistakes, tolerance, (right,)),
                           otherwise=NOT_WITHIN.format(tol=self.tolerance_text(part))),)

    def sample_part(self) -> PartSpec:
        return PartSpec("a", "the power transmitted", "P", "kW", type=self.name, tol=self.default_tol)


def readings(number: float, unit: str, prefixes=(1.0,)):
    """What a number may stand for in `unit`: read in each unit of its kind (units_of_kind), and with each
    of `prefixes`. Nothing for a value that is not a finite number."""
    if isinstance(number, bool) or not isinstance(number, (int, float)) or not math.isfinite(number):
        return
    for other in units_of_kind(unit):
        try:
            value = units.convert(number, other, unit)
        except ExgenError:
            continue
        for prefix in prefixes:
            yield value * prefix


def _same_unit(a: str, b: str) -> bool:
    ia, ib = units.unit_info(a), units.unit_info(b)
    return ia.dims == ib.dims and ia.angle == ib.angle and abs(ia.factor / ib.factor - 1) < 1e-9


def _word(unit: str, group: tuple[str, ...]) -> str:
    return next((_WORDS[u] for u in group if _same_unit(u, unit)), unit.replace("/", "_"))


def _percent(fraction: float) -> str:
    return f"{units.format_number(100 * fraction, 2)} %"


TYPE = Number()
