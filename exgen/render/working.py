"""How each formula of a worked solution is worked: the unit each number stands in.

A value is shown in the unit the problem is set in (a given as printed, a step in its `shown`
unit; an angle in degrees). A formula uses those units where its arithmetic allows it: a
trigonometric argument always takes degrees, an exponent always radians and SI; an angle
computed from angles (2α, θ(1 + k)) or by an inverse function stays in degrees, one computed
from other quantities (ωt) is in radians; a step that asks for a unit (Step.shown) works its
formula in the units its data are shown in, as a ratio of speeds all in rpm does.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from .. import units
from ..errors import ExgenError, QuantityError
from ..load.template import default_symbol
from .formula import Formula

@lru_cache(maxsize=512)
def kind(unit: str) -> str:
    """'angle', 'number' (dimensionless, percent included) or 'dimensional'."""
    try:
        info = units.unit_info(unit)
    except (ExgenError, QuantityError):
        return "dimensional"
    if info.kind == "angle":
        return "angle"
    return "number" if info.dims == "dimensionless" and not info.angle else "dimensional"


# ---- what each value is, and how each formula is worked -----------------------------------------------

@dataclass(frozen=True)
class Value:
    name: str
    value: Any
    si: str             # the SI unit of `value`
    shown: str          # the unit the key shows it in
    symbol: str
    exact: str | None   # a given's printed number, when `shown` is its printed unit
    explicit: bool      # the solver chose `shown`

    @property
    def kind(self) -> str:
        return kind(self.si)


def values_of(variant) -> dict[str, Value]:
    out = {}
    for p in variant.params:
        si = units.si_unit(p.unit) if p.unit else ""
        numeric = isinstance(p.si, (int, float)) and not isinstance(p.si, bool)
        out[p.name] = Value(p.name, p.si, si or "", p.unit if numeric else "", p.symbol or default_symbol(p.name),
                             p.text if numeric else None, False)
    for s in variant.steps:
        default = "deg" if kind(s.unit) == "angle" else s.unit
        out[s.name] = Value(s.name, s.value, s.unit, s.shown or default, s.symbol, None, bool(s.shown))
    return out


@dataclass(frozen=True)
class Plan:
    """How a formula is worked: for each slot, the unit its number is shown in."""

    units: tuple[str, ...]
    angles_in_degrees: bool       # the formula computes an angle in degrees (else radians)
    printed: bool                 # non-angle quantities in the units they are shown in (else SI)


def plan(formula: Formula, step: Value, values: dict[str, Value]) -> Plan:
    plain = [s for s in formula.slots if not s.trig and not s.exponent]
    kinds = {s.index: values[s.name].kind for s in formula.slots}
    if formula.has_pi:
        degrees = False
    elif formula.has_degree:
        degrees = True
    elif step.kind == "angle":  # angle arithmetic (2α, θ(1 + k)) or an inverse function: degrees
        degrees = formula.inverse_first or not any(kinds[s.index] == "dimensional" for s in plain if not s.inverse)
    else:  # a ratio of angles may be worked in degrees; μθ, Tθ need radians
        degrees = step.kind == "number" and bool(plain) and all(kinds[s.index] == "angle" for s in plain)
    shown = {values[s.name].shown for s in plain if kinds[s.index] == "dimensional"}
    printed = (step.explicit and step.kind != "angle") or (
        step.kind == "number" and len(shown) == 1 and not any(values[s.name].shown == values[s.name].si
                                                              for s in plain if kinds[s.index] == "dimensional"))
    # in the shown units, unless two quantities of one kind are shown in different units (cm and mm)
    common: dict[str, set[str]] = {}
    for s in plain:
        if kinds[s.index] == "dimensional":
            common.setdefault(values[s.name].si, set()).add(values[s.name].shown)
    out = []
    for s in formula.slots:
        v = values[s.name]
        if kinds[s.index] == "angle":
            out.append("deg" if s.trig or (degrees and not s.exponent) else "rad")
        elif kinds[s.index] == "dimensional" and printed and not s.exponent and len(common.get(v.si, ())) == 1:
            out.append(v.shown)
        else:
            out.append(v.si)
    return Plan(tuple(out), degrees, printed)


def used_in_si(plans, values) -> set[str]:
    """Names whose number some formula uses in SI while the key shows them in another unit."""
    out = set()
    for formula, plan in plans.values():
        for slot, unit in zip(formula.slots, plan.units):
            v = values[slot.name]
            if unit == v.si and v.shown != v.si and v.kind != "number":
                out.add(slot.name)
    return out


def in_unit(value, unit: str, shown: str):
    if not isinstance(value, (int, float)) or isinstance(value, bool) or unit == shown:
        return value
    return units.convert(float(value), unit, shown)
