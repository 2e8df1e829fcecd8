"""What a figure may print: given values as the sheet prints them, and "?" for an unknown.

A figure is drawn to the variant's proportions, so an unknown still needs a size: it comes
from the solver's step of the same name, but its value is never printed (a sheet must not
carry an answer).
"""
from __future__ import annotations

from dataclasses import dataclass

from .svg import subscripted

UNKNOWN = "?"


@dataclass(frozen=True)
class Shown:
    """A quantity on a figure: its size in SI and the label text ('d₁ = 800 mm' or 'd₂ = ?')."""

    name: str
    si: float
    value_text: str

    @property
    def known(self) -> bool:
        return self.value_text != UNKNOWN

    def label(self, symbol: str | None = None) -> str:
        return f"{symbol or subscripted(self.name)} = {self.value_text}"


def shown(variant, name: str) -> Shown | None:
    """The param `name` as printed, else the step `name` as an unknown, else the first step named
    `name_...` (an unknown the parts ask several ways, e.g. d2_plain and d2_slip) as an unknown, else None."""
    for p in variant.params:
        if p.name == name:
            return Shown(name, _as_float(p.si), str(p))
    for s in variant.steps:
        if s.name == name:
            return Shown(name, _as_float(s.value), UNKNOWN)
    for s in variant.steps:
        if s.name.startswith(name + "_"):
            return Shown(name, _as_float(s.value), UNKNOWN)
    return None


def choice(variant, name: str, default: str) -> str:
    """A word-valued param (e.g. drive: open|crossed), or `default` when the template has none."""
    for p in variant.params:
        if p.name == name:
            return str(p.exact).strip().lower()
    return default


def _as_float(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return float("nan")
