"""Solve a template for values the user gives (`exgen solve ID --set d1=600mm ...`).

Instructors check textbook problems with it; the tests check the worked examples with it.
Values may be given in any unit of the right kind; a bare number is read in the template's unit.
"""
from __future__ import annotations

from decimal import Decimal

from .. import units
from ..draw.values import derived_value, failed_requirement, si_values
from ..errors import ExgenError, QuantityError, SolverFailure
from ..load.domains import PERCENT_UNITS, domain_of, drawn_values
from ..load.template import Template
from ..render.unicode_math import text_to_plain
from ..solve.variant import Variant, build_variant


def parse_settings(pairs: list[str]) -> dict[str, str]:
    """['d1=600mm', 'mu = 0.3'] -> {'d1': '600mm', 'mu': '0.3'}."""
    out = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise ExgenError(f"--set {pair!r}: write NAME=VALUE, e.g. --set d1=600mm")
        out[name.strip()] = value.strip()
    return out


def _exact(value: float) -> Decimal:
    """A float from a unit conversion, cleaned of binary noise (320.00000000000006 -> 320)."""
    return Decimal(f"{value:.12g}")


def given_values(template: Template, given: dict[str, str]) -> dict[str, Decimal | str]:
    """Each parameter's value in the template's own unit, from what the user typed."""
    names = {p.name for p in template.params}
    unknown = sorted(set(given) - names)
    # a parameter fixed in the template (`value:`) takes that value unless another is given
    given = {**{p.name: str(p.choices[0]) for p in template.params
                if not p.derived and not p.is_range and len(p.choices) == 1}, **given}
    missing = [p for p in template.params if p.name not in given and not p.derived]
    problems = []
    if unknown:
        problems.append(f"{template.id} has no parameter(s) {', '.join(unknown)}")
    if missing:
        listed = ", ".join(f"{p.name} ({text_to_plain(p.label) or 'value'}{', ' + p.unit if p.unit else ''})"
                           for p in missing)
        problems.append(f"give a value for {listed}")
    if problems:
        raise ExgenError("; ".join(problems))
    values = {}
    for spec in template.params:
        if spec.derived:
            values[spec.name] = _derived(spec, values, given.get(spec.name))
            continue
        text = given[spec.name]
        if spec.choices and all(isinstance(c, str) for c in spec.choices):
            if text not in spec.choices + spec.also_solves:
                raise ExgenError(f"{spec.name} must be one of {', '.join(spec.choices + spec.also_solves)} "
                                 f"(got {text!r})")
            values[spec.name] = text
            continue
        try:
            reading = units.parse_quantity(text)
            value = reading.value if reading.unit is None else units.convert(reading.value, reading.unit, spec.unit)
        except (QuantityError, ExgenError) as exc:
            raise ExgenError(f"{spec.name}={text}: {exc}") from exc
        domain = domain_of(spec)
        if value not in domain:
            requirement = domain.requirement(units.pretty_unit(spec.unit))
            raise ExgenError(f"{spec.name}={text}: {_describe(spec)} {requirement}")
        values[spec.name] = _exact(value)
    return values


def _describe(spec) -> str:
    return f"{spec.name} ({text_to_plain(spec.label)})" if spec.label else spec.name


def _derived(spec, values: dict, text: str | None) -> Decimal:
    """A parameter the template works out from others; a value the user gives must agree with it."""
    value = derived_value(spec.equals, values)
    if text is not None:
        try:
            reading = units.parse_quantity(text)
            typed = reading.value if reading.unit is None else units.convert(reading.value, reading.unit, spec.unit)
        except (QuantityError, ExgenError) as exc:
            raise ExgenError(f"{spec.name}={text}: {exc}") from exc
        if abs(typed - float(value)) > 1e-9 * max(abs(float(value)), 1.0):
            shown = f"{units.format_decimal(value)} {units.pretty_unit(spec.unit)}".strip()
            raise ExgenError(f"{spec.name} is worked out from the others ({spec.equals} = {shown}); "
                             f"{text!r} disagrees: leave it out or check the others")
    return value


def percent_warnings(template: Template, given: dict[str, str], values: dict) -> list[str]:
    """A bare number of at most 1 for a percentage the template draws above 1: a fraction meant as 90 %?"""
    warnings = []
    for spec in template.params:
        drawn, value = drawn_values(spec), values.get(spec.name)
        if spec.unit not in PERCENT_UNITS or spec.derived or not drawn or not isinstance(value, Decimal):
            continue
        typed = given.get(spec.name, "")
        if value <= 1 < min(drawn) and units.parse_quantity(typed).unit is None:
            warnings.append(f"{spec.name}={typed} is read as {typed} % (a bare number is read in %, and this "
                            f"template draws {min(drawn):g} to {max(drawn):g} %); for the fraction write "
                            f"{float(value) * 100:g}%")
    return warnings


def solve(template: Template, given: dict[str, str]) -> tuple[Variant, list[str]]:
    """The variant for the given values, and warnings for drawing constraints they break."""
    values = given_values(template, given)
    broken = failed_requirement(template, si_values(template, values))
    warnings = percent_warnings(template, given, values)
    warnings += [f"these values break the template's drawing constraint {broken!r}"] if broken else []
    try:
        variant = build_variant(template, values, check=False)
    except SolverFailure as exc:
        if not broken:
            raise
        raise ExgenError(f"{template.id}: these values break the template's constraint {broken!r}, and the solver "
                         f"cannot work from them ({exc.plain})") from None
    return variant, warnings + list(variant.warnings)
