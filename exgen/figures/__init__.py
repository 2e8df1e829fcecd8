"""Figures for problems: SVG text drawn from a variant, named by a template's `figure:` key."""
from __future__ import annotations

from ..variant import resolve


def figure_svg(variant) -> str | None:
    """The SVG of the variant's figure ('belts:belt_drive' -> exgen.figures.belts.belt_drive), or None."""
    reference = variant.template.figure
    if not reference:
        return None
    return resolve(reference, "figures")(variant)
