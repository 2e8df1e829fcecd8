"""Reading a typed quantity into the asked unit, for the types whose answers are numbers with units.

`exgen.units.parse_quantity` does the reading (and refuses power towers, overflows and control
characters); here every failure becomes a QuantityError (a format problem), and a unit of another
kind a WrongKind that names both kinds in words ("'m' is a length, but a force is asked (in N)").
"""
from __future__ import annotations

import math
import re
from functools import lru_cache
from importlib import resources

from .. import units
from ..errors import DimensionError, QuantityError, WrongKind

_DEGREE_SIGNS = re.compile(r"\s*[\u00b0\u00ba\u02da](?![CF])")


def read_quantity(text: str) -> units.Reading:
    """parse_quantity behind a guard: every failure, whatever raised it, is a QuantityError."""
    if len(text) > units.MAX_ANSWER_LENGTH:  # before any pattern: `\s*°` is quadratic in a long run of spaces
        raise QuantityError(f"answer longer than {units.MAX_ANSWER_LENGTH} characters")
    shown = text.strip()
    cleaned = _DEGREE_SIGNS.sub(" deg", text)
    try:
        return units.parse_quantity(cleaned)
    except QuantityError as exc:
        raise QuantityError(str(exc).replace(repr(cleaned.strip()), repr(shown))) from None
    except Exception as exc:  # pint and float() raise many kinds; all mean "cannot read"
        raise QuantityError(f"cannot read {shown!r} as a number (with an optional unit)") from exc


def in_unit(text: str, unit: str) -> tuple[units.Reading, float]:
    """One quantity, converted to `unit` (a bare number is already in it)."""
    reading = read_quantity(text)
    if reading.unit is None:
        value = reading.value
    else:
        try:
            value = units.convert(reading.value, reading.unit, unit)
        except DimensionError as exc:
            raise WrongKind(wrong_kind_message(exc.given_unit, unit)) from None
        except QuantityError:
            raise
        except Exception as exc:  # a unit pint parsed but cannot convert
            raise QuantityError(f"cannot read the unit in {text.strip()!r}") from exc
    if not math.isfinite(value):
        raise QuantityError(f"{text.strip()!r} is not a finite number")
    return reading, value


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


def wrong_kind_message(given_unit: str, asked_unit: str) -> str:
    """"'m' is a length, but a force is asked (in N)": both kinds named in words."""
    given, asked = kind_of(given_unit), kind_of(asked_unit)
    where = f" (in {unit_name(asked_unit)})" if asked_unit else ""
    return f"'{given_unit}' is {with_article(given)}, but {with_article(asked)} is asked{where}"


@lru_cache(maxsize=1)
def unit_families() -> tuple[tuple[str, ...], ...]:
    """The families of units a learning system may accept for one another (exgen/data/unit_families.txt)."""
    text = resources.files("exgen").joinpath("data/unit_families.txt").read_text("utf-8")
    return tuple(tuple(line.split()) for line in text.splitlines() if line.strip() and not line.startswith("#"))


def accepted_units(unit: str) -> tuple[tuple[str, float], ...]:
    """(name as typed, multiplier) for the asked unit (1) and the others of its family: an answer in
    `name` is the value in the asked unit times the multiplier. Each unit under its printed name and,
    where that differs, as typed with a space for the product ("kN·m" and "kN m")."""
    if not unit:
        return ()
    family = next((f for f in unit_families() if unit in f), (unit,))
    out: dict[str, float] = {}
    for other in (unit, *(u for u in family if u != unit)):
        factor = 1.0 if other == unit else units.convert(1.0, unit, other)
        for name in (units.pretty_unit(other), other.replace("*", " ")):
            out.setdefault(name, factor)
    return tuple(out.items())
