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

from .errors import DimensionError, ExgenError, QuantityError

UNIT_TABLE = "data/unit_table.tsv"
MAX_ANSWER_LENGTH = 80
MAX_UNIT_LENGTH = 40
_ANGLE_UNITS = ("radian",)

_TRANSLATE = str.maketrans({
    "\u2212": "-", "\u2013": "-", "\u2012": "-", "\u00a0": " ", "\u2009": " ", "\u202f": " ",
    "\u00b7": "*", "\u22c5": "*", "\u00d7": "x", "\u00b5": "u", "\u03bc": "u", "\u03a9": "ohm",
})
_NUMBER = r"[+-]?(?:\d{1,3}(?: \d{3})+(?:\.\d*)?|\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_TIMES_TEN = r"(?:\s*(?:x|\*|\\times)\s*10\s*(?:\^|\*\*)\s*\(?\s*([+-]?\d{1,3})\s*\)?)?"
_QUANTITY = re.compile(rf"\s*({_NUMBER}){_TIMES_TEN}\s*(.*?)\s*")
_UNIT_CHARS = re.compile(r"[A-Za-z%*/^0-9.()\s\-\u00b0]*")
_POWER = r"(?:\^|\*\*)"
_BIG_POWER = re.compile(rf"{_POWER}\s*\(?\s*[+-]?\s*\d{{2,}}")
_POWER_TOWER = re.compile(rf"{_POWER}[^A-Za-z]*?{_POWER}")  # m^9^9^9: pint would compute it
_HYPHEN_PRODUCT = re.compile(r"(?<=[A-Za-z])-(?=[A-Za-z])")  # N-m, kg-m^2, lbf-ft: a product
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
# "F = ", "θ ≈ ", "= ", "~": a label or an "about" before the number is no part of the answer
_LABEL = re.compile(r"^\s*(?:[A-Za-z\u0370-\u03ff][A-Za-z0-9_\u0370-\u03ff ]{0,11})?[=\u2248~]\s*")
_SUPERSCRIPTS = re.compile("[\u207a\u207b]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+")
_PLAIN_DIGITS = str.maketrans("\u207a\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079", "+-0123456789")


@lru_cache(maxsize=1)
def registry():
    """The one pint registry (built on first use: pint costs ~0.3 s to import and set up)."""
    import pint

    return pint.UnitRegistry()


@lru_cache(maxsize=1)
def aliases() -> dict[str, str]:
    """How people write units (`Nm`, `rev/min`) and what pint should read instead (data/unit_aliases.txt)."""
    text = resources.files("exgen").joinpath("data/unit_aliases.txt").read_text("utf-8")
    pairs = (line.split("=", 1) for line in text.splitlines() if line.strip() and not line.startswith("#"))
    return {a.strip(): b.strip() for a, b in pairs}


def _plain(text: str) -> str:
    """Unicode look-alikes to ASCII; superscripts to powers ("m²" -> "m^2", "10⁻³" -> "10^-3")."""
    text = _SUPERSCRIPTS.sub(lambda m: "^" + m.group().translate(_PLAIN_DIGITS), text)
    return text.translate(_TRANSLATE)


def normalise_unit(text: str) -> str:
    """Unicode and habits ("Nm", "N-m", "rev/min", "°") to a string pint reads."""
    text = _plain(text).strip()
    text = text.replace("\u00b0C", "degC").replace("\u00b0", "degree")
    text = _HYPHEN_PRODUCT.sub("*", text)
    compact = text.replace(" ", "")
    return aliases().get(compact, text)


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
    """Look a unit up once; raise QuantityError if pint does not know it. The units the bank uses are
    read from pint's answers stored in data/unit_table.tsv, so drawing and showing a problem need not
    build pint's registry (a third of a second); any other unit asks pint."""
    if not text or text in ("1", "dimensionless"):
        return UnitInfo("", 1.0, "dimensionless", 0)
    known = _unit_table().get(text)
    return known if known is not None else _ask_pint(text)


def known_units() -> tuple[str, ...]:
    """The units stored in data/unit_table.tsv: every unit the bank writes and those students commonly type."""
    return tuple(_unit_table())


def spelled(text: str) -> str:
    """A unit as pint spells it in full ("N*m" -> "newton * meter"), stored or asked."""
    known = _unit_table_rows().get(text)
    return known[1] if known is not None else _spell_with_pint(text)


@lru_cache(maxsize=1)
def _unit_table() -> dict[str, UnitInfo]:
    return {unit: info for unit, (info, _) in _unit_table_rows().items()}


@lru_cache(maxsize=1)
def _unit_table_rows() -> dict[str, tuple[UnitInfo, str]]:
    text = resources.files("exgen").joinpath(UNIT_TABLE).read_text("utf-8")
    rows = (line.split("\t") for line in text.splitlines() if line and not line.startswith("#"))
    return {unit: (UnitInfo(unit, float(factor), dims, int(angle)), name) for unit, factor, dims, angle, name in rows}


def unit_table(names) -> str:
    """The text of data/unit_table.tsv for these units, each as pint reads it (`python -m exgen.check.unit_table`)."""
    lines = ["# unit, factor to coherent SI, dimension, angles, pint's spelling: pint's answers, stored "
             "(python -m exgen.check.unit_table)"]
    for name in sorted(set(names) - {"", "1", "dimensionless"}):
        info = _ask_pint(name)
        lines.append(f"{name}\t{info.factor!r}\t{info.dims}\t{info.angle}\t{_spell_with_pint(name)}")
    return "\n".join(lines) + "\n"


def _spell_with_pint(text: str) -> str:
    return str(registry().parse_units(normalise_unit(text)))


def _ask_pint(text: str) -> UnitInfo:
    ureg = registry()
    try:
        unit = ureg.parse_units(normalise_unit(text))
        factor, root = ureg.get_root_units(unit)
        base = ureg.Quantity(1.0, unit).to_base_units()
    except Exception as exc:  # pint raises many kinds; all mean "not a unit we can read"
        raise QuantityError(f"unknown unit {text!r}") from exc
    angle = sum(int(p) for name, p in root._units.items() if name in _ANGLE_UNITS)
    return UnitInfo(text, float(base.magnitude), _canonical(unit.dimensionality), angle)


def _canonical(dimensionality) -> str:
    """One spelling per dimension: pint writes lbf as [length]*[mass]/... but N as [mass]*[length]/..."""
    if not dimensionality:
        return "dimensionless"
    return " * ".join(f"{name}^{power:g}" for name, power in sorted(dimensionality.items()))


#: Each kind of quantity, in a word a student understands, and the coherent SI unit solvers work it in
#: (pint spells only dimensions: `describe` finds the word by the unit's dimension; `si_unit` the unit).
SI_UNITS = {
    "length": "m", "mass": "kg", "time": "s", "angle": "rad", "angular speed": "rad/s", "frequency": "Hz",
    "speed": "m/s", "acceleration": "m/s^2", "angular acceleration": "rad/s^2", "force": "N",
    "torque or energy": "N*m", "power": "W", "pressure or stress": "N/m^2", "mass per unit length": "kg/m",
    "area": "m^2", "volume": "m^3", "density": "kg/m^3", "moment of inertia": "kg*m^2",
    "mass times radius": "kg*m", "stiffness": "N/m", "damping coefficient": "N*s/m", "pure number": "",
    "number per unit length": "1/m",
}
#: Units that are energies by name, where the dimension of torque and energy is one: their SI unit is J, not N·m.
ENERGY_WORDS = ("joule", "watt", "calorie", "btu", "erg", "electron_volt")


@lru_cache(maxsize=1)
def _kinds() -> dict[tuple[str, int], str]:
    infos = {kind: unit_info(unit) for kind, unit in SI_UNITS.items()}
    return {(info.dims, info.angle): kind for kind, info in infos.items()}


def describe(dims: str, angle: int = 0) -> str:
    """A word for a dimension that a student understands ("force", not "[length] * [mass] / [time] ** 2")."""
    kinds = _kinds()
    return kinds.get((dims, angle)) or kinds.get((dims, 0)) or f"quantity of dimension {dims}"


def si_unit(unit: str) -> str | None:
    """The SI unit a solver uses for a quantity printed in `unit`, or None if unknown (an energy in J)."""
    try:
        kind = unit_info(unit).kind
    except ExgenError:
        return None
    if kind == "torque or energy" and _names_an_energy(unit):
        return "J"
    return SI_UNITS.get(kind)


@lru_cache(maxsize=64)
def _names_an_energy(unit: str) -> bool:
    return any(word in spelled(unit) for word in ENERGY_WORDS)


def is_energy_unit(unit: str) -> bool:
    """Whether a unit of the dimension torque and energy share names an energy (J, kJ, W·s), not a torque (N·m)."""
    return _names_an_energy(unit)


#: Units that are rates by name count cycles: Hz is rev/s, where a bare 1/s says neither radians nor cycles.
CYCLE_WORDS = ("hertz", "revolution", "cycle", "count", "turn")


@lru_cache(maxsize=64)
def counts_cycles(unit: str) -> bool:
    """Whether an angle-free rate unit says it counts cycles (Hz, cps), unlike a bare 1/s or s⁻¹."""
    return any(word in spelled(unit) for word in CYCLE_WORDS)


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
    if _CONTROL.search(text):
        raise QuantityError("the answer contains control characters")
    cleaned = _plain(text).strip()
    cleaned = _LABEL.sub("", cleaned, count=1)
    if re.fullmatch(r"[+-]?\d{1,3},\d{3}(?:\D.*)?", cleaned):
        raise QuantityError(f"{text.strip()!r} is ambiguous: write it without the comma (or with a point for decimals)")
    cleaned = re.sub(r"^([+-]?\d+),(\d+)", r"\1.\2", cleaned)  # decimal comma
    match = _QUANTITY.fullmatch(cleaned)
    if not match:
        raise QuantityError(f"cannot read {text.strip()!r} as a number (with an optional unit)")
    number, power, unit = match.groups()
    try:
        value = float(number.replace(" ", "")) * (10.0 ** int(power) if power else 1.0)
    except OverflowError:
        value = math.inf
    if not math.isfinite(value):
        raise QuantityError(f"{text.strip()!r} is not a finite number")
    if not unit:
        return Reading(value, None)
    if len(unit) > MAX_UNIT_LENGTH or not _UNIT_CHARS.fullmatch(unit):
        raise QuantityError(f"cannot read the unit in {text.strip()!r}")
    if _BIG_POWER.search(unit) or _POWER_TOWER.search(unit):
        raise QuantityError(f"cannot read {text.strip()!r}: exponents above 9, or exponents of exponents, are not accepted")
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


_PRETTY = [("**", "^"), ("*", "\u00b7"), ("^2", "\u00b2"), ("^3", "\u00b3"), ("^4", "\u2074"),
           ("^-1", "\u207b\u00b9"), ("^-2", "\u207b\u00b2")]


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
