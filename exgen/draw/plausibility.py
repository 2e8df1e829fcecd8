"""Derived quantities a template reports (`report:`), and whether a drawn machine could exist.

A template's parameters are drawn one by one; what makes a machine real is often a quantity
derived from several of them (a belt's density from its mass per metre and section, a piston's
mean speed from stroke and revolutions). Declaring those quantities with the range real machines
keep them in lets the draw reject an impossible machine, `exgen solve` warn about one, and
`exgen validate` show an author what the template actually draws.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

from .. import units
from ..errors import ExgenError, InvalidDraw
from ..load import expr
from ..load.template import ReportSpec, Template


class Implausible(InvalidDraw):
    """A draw whose machine could not exist; grouped by the quantity when rejections are counted."""

    def __init__(self, reading: "Reading"):
        self.what = reading.spec.what
        super().__init__(reading.complaint())


@dataclass(frozen=True)
class Reading:
    """One reported quantity of one variant, in the unit the template reports it in."""

    spec: ReportSpec
    value: float

    @property
    def plausible(self) -> bool:
        slack = 1e-9 * max(abs(self.spec.low), abs(self.spec.high))  # 0.175/0.035 is 5.000000000000001
        return self.spec.low - slack <= self.value <= self.spec.high + slack

    def complaint(self) -> str:
        """'belt density 2812 kg/m³ is outside the plausible 1000-1500 kg/m³'."""
        unit = units.pretty_unit(self.spec.unit)
        return (f"{self.spec.what} {units.format_quantity(self.value, self.spec.unit)} is outside the plausible "
                f"{_number(self.spec.low)}-{_number(self.spec.high)}{' ' + unit if unit else ''}")


def _number(value: float) -> str:
    """A range bound as the template author wrote it: 0.1, 2, 1500."""
    return f"{value:g}"


def names_for(si_params: dict, steps) -> dict[str, float]:
    """Numeric values an expression may name: the parameters (SI), then the solver's steps."""
    names = {k: v for k, v in si_params.items() if isinstance(v, (int, float)) and not isinstance(v, bool)}
    for step in steps:
        if isinstance(step.value, (int, float)) and not isinstance(step.value, bool):
            names[step.name] = float(step.value)
    return names


@lru_cache(maxsize=1024)
def _tree(value: str):
    """The parsed expression (parsing costs more than evaluating: draws repeat it thousands of times)."""
    return expr.parse(value)


@lru_cache(maxsize=1024)
def _names(value: str) -> frozenset[str]:
    return frozenset(expr.names_in(_tree(value)))


def early_rejection(template: Template, si_params: dict) -> Reading | None:
    """The first implausible quantity that the parameters alone decide, checked before the solver runs
    (a rejected draw then costs an expression, not a derivation)."""
    names = names_for(si_params, ())
    ready = [spec for spec in template.report if _names(spec.value) <= names.keys()]
    if not ready:
        return None
    return first_implausible(readings(template, names, ready))


def readings(template: Template, names: dict[str, float], specs=None) -> tuple[Reading, ...]:
    """Every reported quantity of one variant; an expression naming nothing known is the template's error."""
    out = []
    for i, spec in enumerate(template.report if specs is None else specs):
        try:
            value = expr.evaluate(spec.value, names)  # compiled once per expression
        except expr.ExpressionError as exc:
            raise ExgenError(f"{template.id}: report[{i}] ({spec.what}): {exc}") from None
        except (ZeroDivisionError, ValueError, OverflowError):
            value = math.nan
        si = float(value)
        out.append(Reading(spec, units.from_si(si, spec.unit) if math.isfinite(si) else math.nan))
    return tuple(out)


def first_implausible(found: tuple[Reading, ...]) -> Reading | None:
    return next((r for r in found if not r.plausible), None)
