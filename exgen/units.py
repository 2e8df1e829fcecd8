"""Units at the edges: one pint registry, safe quantity parsing, conversion and display.

Physics runs on SI floats. This module turns printed or typed quantities into SI and back.
Angles get one rule pint lacks: pint treats the radian as dimensionless, so 1 Hz would
equal 1 rad/s. Here a unit without an angle in it counts cycles: Hz is rev/s for an
angular speed, and rad/s is 2*pi Hz for a frequency.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal
from functools import lru_cache
from importlib import resources

from .errors import DimensionError, QuantityError

MAX_ANSWER_LENGTH = 80
MAX_UNIT_LENGTH = 40
_ANGLE_UNITS = ("radian",)

_TRANSLATE = str.maketrans({
    "\u2212": "-", "\u2013": "-", "\u2012": "-", "\u00a0": " ", "\u2009": " ", "\u202f": " ",
    "\u00b7": "*", "\u22c5": "*", "\u00d7": "x", "\u00b5": "u", "\u03bc": "u", "\u03a9": "ohm",
    "\u00b2": "^2", "\u00b3": "^3", "\u207b": "^-", "\u00b9": "1", "\u2070": "0", "\u2074": "4",
    "\u2075": "5", "\u2076": "6", "\u2077": "7", "\u2078": "8", "\u2079": "9",
})
_NUMBER = r"[+-]?(?:\d{1,3}(?: \d{3})+(?:\.\d*)?|\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_TIMES_TEN = r"(?:\s*(?:x|\*|\\times)\s*10\s*(?:\^|\*\*)\s*\(?\s*([+-]?\d{1,3})\s*\)?)?"
_QUANTITY = re.compile(rf"\s*({_NUMBER}){_TIMES_TEN}\s*(.*?)\s*")
_UNIT_CHARS = re.compile(r"[A-Za-z%*/^0-9.()\s\-]*")
_LABEL = re.compile(r"^\s*[A-Za-z\u0370-\u03ff][A-Za-z0-9_\u0370-\u03ff ]{0,11}=\s*")
_SUPERSCRIPT_POWER = re.compile(r"\^-\s*(\d)")


@lru_cache(maxsize=1)
def registry():
    """The one pint registry (built on first use: pint costs ~0.3 s to import and set up)."""
    import pint

    return pint.UnitRegistry()


@lru_cache(maxsize=1)
def _aliases() -> dict[str, str]:
    text = resources.files("exgen").joinpath("data/unit_aliases.txt").read_text("utf-8")
    pairs = (line.split("=", 1) for line in text.splitlines() if line.strip() and not line.startswith("#"))
    return {a.strip(): b.strip() for a, b in pairs}


def normalise_unit(text: str) -> str:
    """Unicode and habits ("Nm", "rev/min", "°") to a string pint reads."""
    text = text.translate(_TRANSLATE).strip()
    text = text.replace("\u00b0C", "degC").replace("\u00b0", "degree")
    compact = text.replace(" ", "")
    return _aliases().get(compact, text)


@dataclass(frozen=True)
class UnitInfo:
    """What a unit is: its factor to coherent SI, its dimension and how many angles it holds."""

    text: str
    factor: float
    dims: str
    angle: int

    @property
    def kind(self) -> str:
        return describe(self.dims, self.angle)


@lru_cache(maxsize=512)
def unit_info(text: str) -> UnitInfo:
    """Look a unit up once; raise QuantityError if pint does not know it."""
    if not text or text in ("1", "dimensionless"):
        return UnitInfo("", 1.0, "dimensionless", 0)
    ureg = registry()
    try:
        unit = ureg.parse_units(normalise_unit(text))
        factor, root = ureg.get_root_units(unit)
        base = ureg.Quantity(1.0, unit).to_base_units()
    except Exception as exc:  # pint raises many kinds; all mean "not a unit we can read"
        raise QuantityError(f"unknown unit {text!r}") from exc
    angle = sum(int(p) for name, p in root._units.items() if name in _ANGLE_UNITS)
    return UnitInfo(text, float(base.magnitude), str(unit.dimensionality), angle)


_KINDS = {
    ("[length]", 0): "length", ("[mass]", 0): "mass", ("[time]", 0): "time",
    ("dimensionless", 0): "pure number", ("dimensionless", 1): "angle",
    ("1 / [time]", 1): "angular speed", ("1 / [time]", 0): "frequency",
    ("1 / [time] ** 2", 1): "angular acceleration", ("1 / [time] ** 2", 0): "rate of change of frequency",
    ("[length] / [time]", 0): "speed", ("[length] / [time] ** 2", 0): "acceleration",
    ("[length] * [mass] / [time] ** 2", 0): "force",
    ("[length] ** 2 * [mass] / [time] ** 2", 0): "torque or energy",
    ("[length] ** 2 * [mass] / [time] ** 3", 0): "power",
    ("[mass] / [length] / [time] ** 2", 0): "pressure or stress",
    ("[mass] / [length]", 0): "mass per unit length", ("[length] ** 2", 0): "area",
    ("[length] ** 3", 0): "volume", ("[mass] / [length] ** 3", 0): "density",
    ("[length] ** 2 * [mass]", 0): "moment of inertia", ("[length] * [mass]", 0): "mass times radius",
    ("[mass] / [time] ** 2", 0): "stiffness", ("[mass] / [time]", 0): "damping coefficient",
}


def describe(dims: str, angle: int = 0) -> str:
    """A word for a dimension that a student understands ("force", not "[length] * [mass] / [time] ** 2")."""
    return _KINDS.get((dims, angle)) or _KINDS.get((dims, 0)) or f"quantity of dimension {dims}"


def to_si(value: float, unit: str) -> float:
    return value * unit_info(unit).factor


def from_si(value: float, unit: str) -> float:
    return value / unit_info(unit).factor


def convert(value: float, from_unit: str, to_unit: str) -> float:
    """Convert between units of one dimension; angle-free rates count cycles (Hz = rev/s)."""
    src, dst = unit_info(from_unit), unit_info(to_unit)
    if src.dims != dst.dims:
        raise DimensionError(from_unit, src.kind, to_unit, dst.kind)
    result = value * src.factor / dst.factor
    if src.angle != dst.angle:
        if "[time]" not in dst.dims:
            raise DimensionError(from_unit, src.kind, to_unit, dst.kind)
        result *= (2 * math.pi) ** (dst.angle - src.angle)
    return result


def same_dimension(unit_a: str, unit_b: str) -> bool:
    a, b = unit_info(unit_a), unit_info(unit_b)
    return a.dims == b.dims and (a.angle == b.angle or "[time]" in a.dims)


@dataclass(frozen=True)
class Reading:
    """A typed quantity: its number and the unit written after it (None for a bare number)."""

    value: float
    unit: str | None


def parse_quantity(text: str) -> Reading:
    """Read "1.2 kN", "-3.5e2", "5 %", "θ = 168.8°" or "2.4 × 10^3 N" without evaluating anything."""
    if len(text) > MAX_ANSWER_LENGTH:
        raise QuantityError(f"answer longer than {MAX_ANSWER_LENGTH} characters")
    cleaned = _SUPERSCRIPT_POWER.sub(r"^-\1", text.translate(_TRANSLATE)).strip()
    cleaned = _LABEL.sub("", cleaned, count=1)
    if re.fullmatch(r"[+-]?\d{1,3},\d{3}(?:\D.*)?", cleaned):
        raise QuantityError(f"{text.strip()!r} is ambiguous: write it without the comma (or with a point for decimals)")
    cleaned = re.sub(r"^([+-]?\d+),(\d+)", r"\1.\2", cleaned)  # decimal comma
    match = _QUANTITY.fullmatch(cleaned)
    if not match:
        raise QuantityError(f"cannot read {text.strip()!r} as a number (with an optional unit)")
    number, power, unit = match.groups()
    value = float(number.replace(" ", "")) * (10.0 ** int(power) if power else 1.0)
    if not math.isfinite(value):
        raise QuantityError(f"{text.strip()!r} is not a finite number")
    if not unit:
        return Reading(value, None)
    if len(unit) > MAX_UNIT_LENGTH or not _UNIT_CHARS.fullmatch(unit.replace("degree", "deg")):
        raise QuantityError(f"cannot read the unit in {text.strip()!r}")
    unit_info(unit)  # raises QuantityError naming the unit
    return Reading(value, unit)


# ---- display ------------------------------------------------------------------------------

def format_number(value: float, sig: int = 4) -> str:
    """`value` to `sig` significant figures, plain notation unless very large or small."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    exponent = math.floor(math.log10(abs(value)))
    if exponent >= 7 or exponent < -4:
        mantissa = f"{value / 10 ** exponent:.{sig - 1}f}"
        return f"{mantissa}e{exponent}"
    decimals = sig - 1 - exponent
    if decimals > 0:
        return f"{value:.{decimals}f}"
    return str(int(round(value, decimals)))


def format_decimal(value: Decimal) -> str:
    """A drawn value exactly as printed: no exponent, no trailing zeros."""
    text = format(value.normalize(), "f")
    return text


_PRETTY = [("**", "^"), ("*", "\u00b7"), ("^2", "\u00b2"), ("^3", "\u00b3"), ("^-1", "\u207b\u00b9"),
           ("^-2", "\u207b\u00b2")]


def pretty_unit(unit: str) -> str:
    """'N*m' -> 'N·m', 'm/s^2' -> 'm/s²', 'deg' -> '°' for printing."""
    if unit in ("deg", "degree"):
        return "\u00b0"
    if unit in ("percent", "%"):
        return "%"
    for old, new in _PRETTY:
        unit = unit.replace(old, new)
    return unit


def format_quantity(value: float, unit: str, sig: int = 4) -> str:
    shown = pretty_unit(unit)
    number = format_number(value, sig)
    if not shown:
        return number
    return f"{number}{shown}" if shown in ("\u00b0", "%") else f"{number} {shown}"
