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
    """One quantity, converted to `unit` (a bare number is already in it). A unit that cannot be read,
    or reads as another kind, but differs only in letter case from one unit of the asked kind is read
    as that unit: "1.2 KN", "12.8 kw", "3.2 hz", "62 NM", "5.2 M/S" (pint would take M for molar); never
    an m for M or M for m before a unit ("12.8 mw": milli or mega)."""
    try:
        return _in_unit(text, unit)
    except (QuantityError, WrongKind):
        meant = _case_meant(text, unit)
        if meant is None:
            raise
        return _in_unit(meant, unit)


def _case_meant(text: str, unit: str) -> str | None:
    """The answer with its unit written in the case of the one unit of the asked family it matches
    ignoring case; None when no unit or more than one (mW and MW) does."""
    typed = text.rstrip()
    if not unit or not typed[-1:].isalpha() and not typed[-1:].isdigit():
        return None
    family = family_of(unit)
    names = [name for other in family for name in written_as(other)]
    names += [written for written, meant in units.aliases().items() if meant.replace(" ", "") in family]
    found = {name for name in names if len(name) < len(typed)
             and typed[-len(name):].casefold() == name.casefold() and typed[-len(name):] != name
             and (typed[-len(name) - 1].isdigit() or typed[-len(name) - 1] in " .")
             and not _milli_or_mega(typed[-len(name):], name, names)}
    if len({units.normalise_unit(name).replace(" ", "*") for name in found}) != 1:
        return None
    name = min(found)
    return typed[:-len(name)] + name


def _milli_or_mega(typed: str, name: str, names) -> bool:
    """Whether the case slip is in an m or M before a unit: milli or mega, which nobody can tell."""
    return typed[0] != name[0] and name[0] in "mM" and name[1:].lstrip(" *") in names


def _in_unit(text: str, unit: str) -> tuple[units.Reading, float]:
    reading = read_quantity(text)
    if reading.unit is None:
        value = reading.value
    else:
        ambiguous = ambiguous_unit(reading, unit)
        if ambiguous:
            raise QuantityError(ambiguous)
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


def ambiguous_unit(reading: units.Reading, asked: str) -> str | None:
    """Why a unit of the asked dimension cannot be read as the asked quantity without a guess, naming
    both readings; None when it can. A torque and an energy share N·m = J, but J names an energy and
    N·m a torque; an angular speed in bare 1/s is radians or revolutions per second (SI's radian is 1,
    a student's 1/s is as often rev/s): converting either way would mark a right answer wrong or a
    wrong one right."""
    try:
        given, wanted = units.unit_info(reading.unit), units.unit_info(asked)
    except QuantityError:
        return None
    if given.dims != wanted.dims:
        return None
    if wanted.kind == "torque or energy":
        return _energy_or_torque(reading, given, asked, wanted)
    if wanted.angle > 0 and given.angle == 0 and "[time]^-" in given.dims and not units.counts_cycles(reading.unit):
        return _radians_or_revolutions(reading, given)
    return None


def _energy_or_torque(reading: units.Reading, given: units.UnitInfo, asked: str, wanted: units.UnitInfo) -> str | None:
    energy_written, energy_asked = units.is_energy_unit(reading.unit), units.is_energy_unit(asked)
    if energy_written == energy_asked:
        return None
    written, meant = units.pretty_unit(reading.unit), units.pretty_unit(asked)
    number = _number(reading.value * given.factor / wanted.factor)
    if energy_written:
        return f"{written} is an energy unit; a torque is in {meant}: write {number} {meant} if you mean the torque"
    return f"{written} is a torque unit; an energy is in {meant}: write {number} {meant} if you mean the energy"


_PER = {1.0: "s", 60.0: "min"}


def _radians_or_revolutions(reading: units.Reading, given: units.UnitInfo) -> str:
    written = units.pretty_unit(reading.unit)
    power = -int(given.dims.rsplit("^", 1)[1])
    per = _PER.get(round(given.factor ** (-1 / power), 9)) if power in (1, 2) else None
    if per is None:
        return (f"{written} could be radians or revolutions per unit time: write the unit with rad or rev "
                f"in it, such as rad/s or rev/s")
    tail = f"/{per}" + ("^2" if power == 2 else "")
    rad, rev = units.pretty_unit("rad" + tail), units.pretty_unit("rev" + tail)
    number = _number(reading.value)
    return (f"{written} could be {rad} or {rev}: write {number} {rad} if you mean radians per "
            f"{'second' if per == 's' else 'minute'}{' squared' if power == 2 else ''}, or {number} {rev} "
            f"if you mean revolutions")


def _number(value: float) -> str:
    """A number as a student would retype it: up to ten figures, no float noise (140.39999999999998)."""
    return format(value, ".10g")


def kind_of(unit: str) -> str:
    """A word for what a unit measures ("force", "length")."""
    try:
        return units.unit_info(unit).kind
    except QuantityError:
        return "unknown unit"


def unit_name(unit: str) -> str:
    """How a unit reads in a sentence: 'degrees' rather than a bare '°'."""
    shown = units.pretty_unit(unit)
    return {"\u00b0": "degrees", "%": "percent", "": "a pure number", "in": "inches"}.get(shown, shown)


def with_article(kind: str) -> str:
    return f"an {kind}" if kind[:1] in "aeiou" else f"a {kind}"


def wrong_kind_message(given_unit: str, asked_unit: str) -> str:
    """"'m' is a length, but a force is asked (in N)": both kinds named in words. A unit that measures
    nothing a student would name ('MM' reads as megamolar) is said to be no unit of the asked kind."""
    given, asked = kind_of(given_unit), kind_of(asked_unit)
    where = f" (in {unit_name(asked_unit)})" if asked_unit else ""
    if given.startswith("quantity of dimension"):
        return (f"'{given_unit}' is not a unit of {asked}: {with_article(asked)} is asked{where}, and unit "
                f"symbols are read with their capitals (m is milli, M is mega)")
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
    out: dict[str, float] = {}
    for other in (unit, *(u for u in family_of(unit) if u != unit)):
        factor = 1.0 if other == unit else units.convert(1.0, unit, other)
        for name in written_as(other):
            out.setdefault(name, factor)
    return tuple(out.items())


@lru_cache(maxsize=256)
def units_of_kind(unit: str) -> tuple[str, ...]:
    """Every unit a value of `unit`'s kind may be written in, `unit` first: the stored units (those the
    bank writes, the families of unit_families.txt, what students commonly type) of the same dimension,
    so pint is never asked. An angular speed's kind holds rad/s, rpm and Hz together (a student converts
    between them), a pure number's holds %, an angle's deg and rad."""
    try:
        units.unit_info(unit)
    except QuantityError:
        return (unit,)
    return (unit, *(other for other in units.known_units() if other != unit and units.same_dimension(other, unit)))


def family_of(unit: str) -> tuple[str, ...]:
    """The units of `unit`'s family (exgen/data/unit_families.txt), or the unit alone."""
    return next((f for f in unit_families() if unit in f), (unit,))


def written_as(unit: str) -> tuple[str, str]:
    """How a unit is typed: its printed name and with a space for the product ("kN·m", "kN m")."""
    return units.pretty_unit(unit), unit.replace("*", " ")
