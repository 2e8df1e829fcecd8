"""Read one typed answer into a value in the unit the sheet asks for, without evaluating anything.

`exgen.units.parse_quantity` does the reading; this module guards it (power towers such as
"m^9^9^9" make pint compute huge integers, and "10^999" overflows), turns any failure into a
QuantityError (a format problem), and converts to the asked unit (a DimensionError is a wrong
answer of the wrong kind, told apart from both).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from exgen import units
from exgen.errors import DimensionError, QuantityError
from exgen.template import PartSpec

#: Exponents pint may see: at most two digits, never an exponent of an exponent.
_POWER = r"(?:\^|\*\*)"
_POWER_TOWER = re.compile(rf"{_POWER}[^A-Za-z]*?{_POWER}")
_BIG_EXPONENT = re.compile(rf"{_POWER}\s*\(?\s*[+-]?\s*\d{{3,}}")
_DEGREE_SIGNS = re.compile(r"\s*[\u00b0\u00ba\u02da](?![CF])")
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
_WORDS_BLANK = ("", "~", "null", "none", "-")
NUMERIC_TYPES = ("number", "angle", "integer")


@dataclass(frozen=True)
class Given:
    """A readable answer: the text as typed, the value in the asked unit, and how it was written."""

    text: str
    value: float | str
    number: float | None = None  # the number as typed, before conversion
    unit: str | None = None      # the unit as typed; None for a bare number read in the asked unit

    @property
    def bare(self) -> bool:
        return self.unit is None


def is_blank(text: str | None) -> bool:
    return text is None or text.strip().lower() in _WORDS_BLANK


def read_quantity(text: str) -> units.Reading:
    """parse_quantity behind a guard: every failure, whatever raised it, is a QuantityError."""
    if len(text) > units.MAX_ANSWER_LENGTH:
        raise QuantityError(f"answer longer than {units.MAX_ANSWER_LENGTH} characters")
    if _CONTROL.search(text):
        raise QuantityError("the answer contains control characters")
    shown = text.strip()
    if _POWER_TOWER.search(text) or _BIG_EXPONENT.search(text):
        raise QuantityError(f"cannot read {shown!r}: exponents of exponents and powers above 99 are not accepted")
    cleaned = _DEGREE_SIGNS.sub(" deg", text)
    try:
        return units.parse_quantity(cleaned)
    except QuantityError as exc:
        raise QuantityError(str(exc).replace(repr(cleaned.strip()), repr(shown))) from None
    except Exception as exc:  # pint and float() raise many kinds; all mean "cannot read"
        raise QuantityError(f"cannot read {shown!r} as a number (with an optional unit)") from exc


def read_answer(text: str, part: PartSpec) -> Given:
    """The answer to `part` in its asked unit; QuantityError if unreadable, DimensionError if of the wrong kind."""
    if part.type == "choice":
        return Given(text, " ".join(text.split()))
    reading = read_quantity(text)
    if reading.unit is None:
        value = reading.value
    else:
        try:
            value = _convert(reading.value, reading.unit, part.unit)
        except (DimensionError, QuantityError):
            raise
        except Exception as exc:  # a unit pint parsed but cannot convert
            raise QuantityError(f"cannot read the unit in {text.strip()!r}") from exc
    if not math.isfinite(value):
        raise QuantityError(f"{text.strip()!r} is not a finite number")
    return Given(text, value, reading.value, reading.unit)


def _convert(value: float, from_unit: str, to_unit: str) -> float:
    """units.convert, also when pint spells one dimension in two orders: it writes lbf, kgf and hp as
    '[length] * [mass] ...' but N and W as '[mass] * [length] ...', which units.convert calls different."""
    try:
        return units.convert(value, from_unit, to_unit)
    except DimensionError:
        src, dst = units.unit_info(from_unit), units.unit_info(to_unit)
        if src.angle == dst.angle and _canonical_dims(src.dims) == _canonical_dims(dst.dims):
            return value * src.factor / dst.factor
        raise


def kind_of(unit: str) -> str:
    """A word for what a unit measures ("force", "length")."""
    try:
        return units.unit_info(unit).kind
    except QuantityError:
        return "unknown unit"


def _canonical_dims(dims: str) -> str:
    """'[mass] * [length] / [time] ** 2' -> '[length] * [mass] / [time] ** 2' (factors sorted)."""
    head, *below = [p.strip() for p in dims.split(" / ")]
    above = sorted(f.strip() for f in head.split(" * ")) if head != "1" else ["1"]
    return " / ".join([" * ".join(above), *sorted(below)])


def unit_name(unit: str) -> str:
    """How a unit reads in a sentence: 'degrees' rather than a bare '°'."""
    shown = units.pretty_unit(unit)
    return {"\u00b0": "degrees", "%": "percent", "": "a pure number"}.get(shown, shown)


def with_article(kind: str) -> str:
    return f"an {kind}" if kind[:1] in "aeiou" else f"a {kind}"


def wrong_kind_message(exc: DimensionError, asked_unit: str) -> str:
    """"'m' is a length, but a force is asked (in N)": both kinds named in words."""
    given, asked = kind_of(exc.given_unit), kind_of(asked_unit)
    where = f" (in {unit_name(asked_unit)})" if asked_unit else ""
    return f"'{exc.given_unit}' is {with_article(given)}, but {with_article(asked)} is asked{where}"
