"""A key's line that adds and subtracts angles must give the value it shows.

A direction kept in (-180°, 180°] is right modulo a turn, and graded so, but a line such as
"θ₁ = β + ∠OAB₁ = 106.1° + 136.1° = -117.7°" reads as wrong arithmetic to a lecturer: the whole turn
that takes it there belongs in the formula. Every template's angle steps whose formulas are sums of
earlier angles and constants in degrees are evaluated here by their own arithmetic over drawn variants.
"""
from __future__ import annotations

import math
import re

from exgen.solve.variant import make_variant

SEEDS = range(60)
TOKEN = re.compile(r"\s*(@[A-Za-z_][A-Za-z0-9_]*|\d+(?:\.\d+)?\^\{?\\circ\}?|\d+(?:\.\d+)?|\\left\(|\\right\)|[-+()])")


def degrees_of(formula: str, angles: dict[str, float]) -> float | None:
    """The formula's value in degrees when it is only angles (@names, n^\\circ), signs and brackets."""
    parts, pos = [], 0
    while pos < len(formula):
        match = TOKEN.match(formula, pos)
        if not match:
            return None
        token, pos = match.group(1), match.end()
        if token.startswith("@"):
            if token[1:] not in angles:
                return None
            parts.append(f"({angles[token[1:]]!r})")
        elif "circ" in token:
            parts.append(token.split("^")[0])
        elif token[0].isdigit():
            return None                    # a plain number: not a sum of angles
        else:
            parts.append({"\\left(": "(", "\\right)": ")"}.get(token, token))
    if all(p in "+-()" for p in parts):
        return None
    return eval("".join(parts), {"__builtins__": {}})  # only numbers, signs and brackets reach here


def test_every_line_adding_angles_gives_the_value_shown(bank):
    wrong = []
    for template in bank:
        for seed in SEEDS:
            variant = make_variant(template, seed)
            angles = {p.name: math.degrees(p.si) for p in variant.params if p.unit == "deg"}
            for step in variant.steps:
                if step.unit != "rad" or not isinstance(step.value, float):
                    continue
                worked = degrees_of(step.formula, angles) if step.formula else None
                if worked is not None and abs(worked - math.degrees(step.value)) > 1e-6:
                    wrong.append((template.id, seed, step.name, step.formula, worked, math.degrees(step.value)))
                angles[step.name] = math.degrees(step.value)
    assert wrong == []
