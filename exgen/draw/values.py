"""Seeded drawing of "nice" parameter values: exact, stepped, and the same on every machine.

Values are chosen by index from each parameter's list of allowed values using the raw
64-bit output of PCG64, so the stream does not depend on how a numpy version maps bits to
integers. Values are Decimals exactly as printed on the sheet (what a student reads is exactly what the solver used).
"""
from __future__ import annotations

from decimal import Decimal

import numpy as np

from ..load import expr
from ..load.template import Template
from ..units import to_si

_TWO_64 = 1 << 64


def generator(seed: int) -> np.random.Generator:
    return np.random.Generator(np.random.PCG64(seed))


def uniform_index(rng: np.random.Generator, n: int) -> int:
    """An unbiased integer in [0, n) from raw 64-bit draws (rejection of the biased tail)."""
    limit = (_TWO_64 // n) * n
    while True:
        raw = int(rng.bit_generator.random_raw())
        if raw < limit:
            return raw % n


def draw_values(template: Template, rng: np.random.Generator) -> dict[str, Decimal | str]:
    """One candidate set of printed values, in the template's parameter order."""
    values: dict[str, Decimal | str] = {}
    for p in template.params:
        values[p.name] = derived_value(p.equals, values) if p.derived else p.value_at(uniform_index(rng, p.count))
    return values


def derived_value(formula: str, values: dict) -> Decimal:
    """An `equals:` parameter from the printed values of earlier ones, to 12 significant figures:
    exact for the sums and multiples of stepped values it is meant for (a loop that closes a cycle)."""
    numbers = {k: float(v) for k, v in values.items() if isinstance(v, Decimal)}
    return Decimal(f"{float(expr.evaluate(formula, numbers)):.12g}")


def si_values(template: Template, values: dict) -> dict[str, float | str]:
    """Printed values to SI floats; text choices stay text."""
    out = {}
    for spec in template.params:
        value = values[spec.name]
        out[spec.name] = to_si(float(value), spec.unit) if isinstance(value, Decimal) else value
    return out


def failed_requirement(template: Template, si: dict) -> str | None:
    """The first `require:` condition the values break, or None."""
    numeric = {k: v for k, v in si.items() if isinstance(v, float)}
    for condition in template.require:
        if not expr.evaluate(condition, numeric):
            return condition
    return None
