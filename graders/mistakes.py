"""Name the mistake behind a wrong answer, so feedback says what went wrong and not only that it did.

Two sources, tried in order: (1) the template's mistakes, whose values the solver records
(`d.mistake(step, name, value)`) and which match with the part's own tolerance; the template's
`say:` wins over the default message here; (2) generic detectors shared by every topic (units
confused, a wrong prefix, percent and fraction, the sign, premature rounding).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterable, Mapping

from exgen import units
from exgen.errors import ExgenError
from exgen.template import PartSpec

from . import checks
from .reading import Given, unit_name

Matcher = Callable[[Any, Any], bool]


@dataclass(frozen=True)
class Mistake:
    name: str
    message: str


# ---- template mistakes: default feedback by the name a solver records -------------------------

MESSAGES: dict[str, str] = {
    # contact angle
    "crossed_formula": "That is the angle of contact of a crossed belt, π + 2α with sin α = (r₁ + r₂)/X. "
                       "This drive is open: θ = π − 2α with sin α = (r₂ − r₁)/X.",
    "open_formula": "That is the open-belt result. This drive is crossed: θ = π + 2α with sin α = (r₁ + r₂)/X, "
                    "the same on both pulleys.",
    "larger_pulley": "That is the angle of contact on the larger pulley. The smaller pulley has less wrap, "
                     "slips first, and so governs the drive.",
    "diameters_for_radii": "The diameters were used where the radii belong: sin α is worked out from the radii "
                           "(half the diameters).",
    "radii_swapped": "The other pulley's radius was used: each pulley's torque is (T₁ − T₂) times its own radius.",
    # speeds
    "rpm_as_rad_s": "The speed in rpm was used as if it were in rad/s: convert first, ω = 2πN/60.",
    "diameter_for_radius": "The diameter was used where the radius belongs (v = ωr; torque = force × radius).",
    "ratio_inverted": "A ratio is upside down. For pulleys N₂/N₁ = d₁/d₂ (the smaller pulley turns faster); "
                      "for a change, divide by the original value.",
    "slip_not_applied": "Slip was left out: it lowers the driven speed by the factor (1 − G/100).",
    "slip_one_pulley": "Slip happens on both pulleys: the total slip is G = G₁ + G₂, used once in (1 − G/100).",
    "slip_once": "Each drive in the train slips: apply (1 − G/100) once for every belt drive.",
    "slip_wrong_way": "Slip was applied the wrong way: it makes the driven pulley slower, a factor (1 − G/100), "
                      "not a division by it or (1 + G/100).",
    "thickness_forgotten": "The belt thickness was left out: the belt's mid-line runs on the diameters d + t.",
    "thickness_added_wrong": "The thickness was added wrongly: each effective diameter is d + t (the belt's "
                             "mid-line), added to both pulleys.",
    "thickness_not_subtracted": "The ratio gives the effective diameter d + t; subtract t to get the pulley's own "
                                "diameter.",
    # tensions and power
    "theta_in_degrees": "The angle of contact went into e^(μθ) in degrees; the formula needs θ in radians.",
    "flat_formula_on_v_belt": "That is the flat-belt result. In a V-groove the wedge raises the friction: "
                              "T₁/T₂ = e^(μθ / sin β).",
    "full_groove_angle": "The full groove angle was used: β in e^(μθ / sin β) is half the groove angle.",
    "centrifugal_ignored": "Centrifugal tension was left out: T_c = m v² takes part of the maximum tension, "
                           "so less is left to drive.",
    "tc_not_subtracted": "The friction relation holds for the tensions less the centrifugal tension: "
                         "(T₁ − T_c)/(T₂ − T_c) = e^(μθ).",
    "creep_ignored": "Creep was left out: an elastic belt's driven side runs slower, v₂ = v₁(1 − (T₁ − T₂)/(AE)).",
    "creep_added": "Creep was added instead of subtracted: it makes the driven side slower, not faster.",
    "tc_equals_tmax": "At maximum power the centrifugal tension is a third of the maximum tension, not all of it: "
                      "T_c = T_max/3, so v = √(T_max/(3m)).",
    "tc_half": "At maximum power T_c = T_max/3, not T_max/2.",
    # counts and choices
    "rounded_down": "A count of whole things was rounded down; too few cannot carry the load: round up.",
    "opposite": "That is the opposite of what happens; think through which way the change moves the result.",
}

#: When a solver records a mistake this registry does not know yet.
UNNAMED_MISTAKE = "That is what the method '{words}' gives, a known slip: check that step of your working."


def message_for(name: str, say: str = "") -> str:
    """The template's own text if it gives one, else the default for the name."""
    return say or MESSAGES.get(name) or UNNAMED_MISTAKE.format(words=name.replace("_", " "))


def template_mistake(part: PartSpec, value: Any, recorded: Iterable[Mapping[str, Any]],
                     matches: Matcher) -> Mistake | None:
    """The first recorded mistake value the answer matches: those the template lists, in its order,
    then any others the solver records."""
    recorded = [r for r in recorded if r]
    says = {m.when: m.say for m in part.mistakes}
    names = list(says) + [n for r in recorded for n in r if n not in says]
    for name in dict.fromkeys(names):
        for values in recorded:
            if name in values and _safe_match(matches, value, values[name]):
                return Mistake(name, message_for(name, says.get(name, "")))
    return None


def _safe_match(matches: Matcher, given, expected) -> bool:
    try:
        return bool(matches(given, expected))
    except (TypeError, ValueError, ArithmeticError):
        return False


# ---- generic detectors -----------------------------------------------------------------------

#: Units students confuse within one kind; a bare number matching the answer in another is named.
CONFUSABLE = (("deg", "rad"), ("rpm", "rad/s", "Hz"))
_WORDS = {"deg": "degrees", "rad": "radians", "rpm": "rpm", "rad/s": "rad_s", "Hz": "hz"}
CLOSE_FACTOR = 3  # within 3x the tolerance: most likely the right method, rounded too early

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


OPPOSITE_SIDE = ("That direction is exactly opposite the right one. To add balancing mass, put it at the "
                 "angle found; half a turn away is where mass would be removed (write \"remove ... at ...\" "
                 "if that is what you mean).")
OPPOSITE_DIRECTION = "That direction is exactly opposite (180° from) the right one: check the sign of each component."
MIRRORED_ANGLE = ("Your angle is the mirror image of the right one: it is measured in the opposite sense. "
                  "Measure angles as the sheet says (from where, and which way round).")
WRONG_AXIS = ("Your angle is measured from the wrong reference line (a quarter turn out). "
              "The sheet says where 0° is and which way angles are measured.")
MAGNITUDE_ONLY = "The magnitude is right; the angle is not."
ANGLE_ONLY = "The angle is right; the magnitude is not."


def generic_mistake(part: PartSpec, given: Given, expected: float, matches: Matcher,
                    near: Matcher) -> Mistake | None:
    """The first generic slip that explains a wrong number (`near` is the part's widened comparator)."""
    if part.type == "polar":
        return _polar_slip(part, given.value, expected)
    if part.type not in ("number", "angle") or not isinstance(expected, (int, float)):
        return None
    if part.type == "angle":
        found = _direction_slip(given.value, units.convert(expected, part.unit, "deg") if part.unit else expected,
                                part, OPPOSITE_DIRECTION)
        if found:
            return found
    for detect in (_unit_confused, _wrong_prefix, _percent_fraction, _wrong_sign):
        try:
            found = detect(part, given, float(expected), matches)
        except (ExgenError, ArithmeticError, ValueError):
            found = None
        if found:
            return found
    if near(given.value, expected):
        return Mistake("premature_rounding", PREMATURE_ROUNDING.format(
            off=_percent(abs(given.value - expected) / abs(expected)) if expected else "slightly",
            tol=tolerance_text(part)))
    return None


def _direction_slip(given_deg, expected_deg, part: PartSpec, opposite: str,
                    scale: float = 1.0) -> Mistake | None:
    """An angle half a turn out, mirrored (measured the other way round), or a quarter turn out
    or measured from the other axis (90° - θ)."""
    if part.type == "angle" and part.unit:
        given_deg = units.convert(given_deg, part.unit, "deg")
    tol = max(part.tol.abs, 0.5)
    same = lambda a, b: checks.angle(a, b, 0.0, tol)  # noqa: E731
    if same(given_deg, expected_deg + 180):
        return Mistake("opposite_side", opposite)
    if not same(expected_deg, -expected_deg) and same(given_deg, -expected_deg):
        return Mistake("mirrored_angle", MIRRORED_ANGLE)
    if any(same(given_deg, e) for e in (expected_deg + 90, expected_deg - 90, 90 - expected_deg)):
        return Mistake("wrong_axis", WRONG_AXIS)
    return None


def _polar_slip(part: PartSpec, given, expected) -> Mistake | None:
    """Which half of a magnitude-at-angle answer is wrong, and why the angle might be."""
    size_right = checks.numeric(given.magnitude, expected.magnitude, part.tol.rel)
    angle_right = checks.angle(given.angle_deg, expected.angle_deg, 0.0, part.tol.abs)
    if size_right and not angle_right:
        return _direction_slip(given.angle_deg, expected.angle_deg, part, OPPOSITE_SIDE) or \
            Mistake("angle_wrong", MAGNITUDE_ONLY)
    if angle_right and not size_right:
        return Mistake("magnitude_wrong", ANGLE_ONLY)
    return None


def _same_unit(a: str, b: str) -> bool:
    ia, ib = units.unit_info(a), units.unit_info(b)
    return ia.dims == ib.dims and ia.angle == ib.angle and abs(ia.factor / ib.factor - 1) < 1e-9


def _word(unit: str, group: tuple[str, ...]) -> str:
    return next((_WORDS[u] for u in group if _same_unit(u, unit)), unit.replace("/", "_"))


def _unit_confused(part, given, expected, matches) -> Mistake | None:
    written = given.unit or part.unit
    for group in CONFUSABLE:
        if not units.same_dimension(part.unit, group[0]):
            continue
        for other in group:
            if _same_unit(other, written):
                continue
            if checks.numeric(given.number, units.convert(expected, part.unit, other), max(part.tol.rel, checks.REL_TOL)):
                one = f"1 {units.pretty_unit(other)} = {units.format_quantity(units.convert(1.0, other, written), written)}"
                text = UNIT_CONFUSED_BARE if given.bare else UNIT_CONFUSED_WRITTEN
                return Mistake(f"{_word(other, group)}_for_{_word(written, group)}", text.format(
                    number=units.format_number(given.number), other=unit_name(other),
                    asked=unit_name(part.unit), written=unit_name(written), one=one))
    return None


def _wrong_prefix(part, given, expected, matches) -> Mistake | None:
    if part.type != "number":
        return None
    for power in (3, -3, 6, -6):
        if expected and matches(given.value, expected * 10.0 ** power):
            factor = f"{10 ** power:,} times" if power > 0 else f"1/{10 ** -power:,} of"
            return Mistake("wrong_prefix", WRONG_PREFIX.format(factor=factor, asked=unit_name(part.unit)))
    return None


def _percent_fraction(part, given, expected, matches) -> Mistake | None:
    info = units.unit_info(part.unit)
    if info.dims != "dimensionless" or info.angle:
        return None
    percent_asked = abs(info.factor - 0.01) < 1e-12
    if percent_asked and matches(given.value, expected / 100):
        return Mistake("fraction_for_percent", FRACTION_FOR_PERCENT)
    if not percent_asked and matches(given.value, expected * 100):
        return Mistake("percent_for_fraction", PERCENT_FOR_FRACTION)
    return None


def _wrong_sign(part, given, expected, matches) -> Mistake | None:
    if part.type == "number" and expected and matches(given.value, -expected):
        return Mistake("wrong_sign", WRONG_SIGN)
    return None


def _percent(fraction: float) -> str:
    return f"{units.format_number(100 * fraction, 2)} %"


def tolerance_text(part: PartSpec) -> str:
    """"1 %", "3 significant figures" or "0.5°": the tolerance as a student reads it."""
    tol = part.tol
    if part.type == "polar":
        return f"{100 * tol.rel:g} % in size and {units.format_quantity(tol.abs, 'deg')} in angle"
    if tol.sig:
        return f"{tol.sig} significant figures"
    if tol.rel:
        return f"{100 * tol.rel:g} %"
    return units.format_quantity(tol.abs, "deg" if part.type == "angle" else part.unit)
