"""Read one typed answer into a value in the unit the sheet asks for, without evaluating anything.

`exgen.units.parse_quantity` does the reading (and refuses power towers, overflows and control
characters); this module turns any failure into a QuantityError (a format problem) and converts
to the asked unit (a DimensionError is a wrong answer of the wrong kind, told apart from both).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from exgen import units
from exgen.errors import DimensionError, QuantityError
from exgen.template import PartSpec
from exgen.variant import Polar

_DEGREE_SIGNS = re.compile(r"\s*[\u00b0\u00ba\u02da](?![CF])")
_WORDS_BLANK = ("", "~", "null", "none", "-")
NUMERIC_TYPES = ("number", "angle", "integer")
_POLAR = re.compile(r"(?:(add|remove|subtract|take away)\s+)?(.+?)\s*(?:\bat\b|@|\u2220|<)\s*(.+)", re.IGNORECASE)
_REMOVE = ("remove", "subtract", "take away")


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
    shown = text.strip()
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
    if part.type == "polar":
        return _read_polar(text, part)
    reading, value = _in_unit(text, part.unit)
    return Given(text, value, reading.value, reading.unit)


def _in_unit(text: str, unit: str) -> tuple[units.Reading, float]:
    """One quantity, converted to `unit` (a bare number is already in it)."""
    reading = read_quantity(text)
    if reading.unit is None:
        value = reading.value
    else:
        try:
            value = units.convert(reading.value, reading.unit, unit)
        except (DimensionError, QuantityError):
            raise
        except Exception as exc:  # a unit pint parsed but cannot convert
            raise QuantityError(f"cannot read the unit in {text.strip()!r}") from exc
    if not math.isfinite(value):
        raise QuantityError(f"{text.strip()!r} is not a finite number")
    return reading, value


def _read_polar(text: str, part: PartSpec) -> Given:
    """"0.85 kg m at 218 deg", "remove 0.85 @ 38°", "0.85∠218": a magnitude at an angle (deg if bare)."""
    match = _POLAR.fullmatch(text.strip())
    if not match:
        raise QuantityError(f"cannot read {text.strip()!r} as a magnitude at an angle, such as "
                            f"\"{Polar(12.5, 30.0).text(part.unit)}\"")
    action, size_text, angle_text = match.groups()
    size_reading, size = _in_unit(size_text, part.unit)
    _, angle_deg = _in_unit(angle_text, "deg")
    if action and action.lower() in _REMOVE:
        size = -size
    return Given(text, Polar.of(size, angle_deg), size_reading.value, size_reading.unit)


def kind_of(unit: str) -> str:
    """A word for what a unit measures ("force", "length")."""
    try:
        return units.unit_info(unit).kind
    except QuantityError:
        return "unknown unit"


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
