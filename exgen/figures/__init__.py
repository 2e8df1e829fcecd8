"""Figures for problems: SVG text drawn from a variant.

A template names the figure the student sees (`figure: belts:belt_drive` -> exgen.figures.belts.belt_drive,
or a function in a file of its bank folder, `figure: ./cam.py:cam_figure`: exgen.load.references) and, optionally, figures only its key shows (`key_figures: [polygons:two_plane_polygons]`: the
force and couple polygons the worked solution closes). Each function takes the variant and returns
an SVG document whose <title> is its caption. A sheet's figures are drawn once (`draw_figures`) and
the same text is written to every folder and embedded in every output.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..load.references import resolve, split

_TITLE = re.compile(r"<title>(.*?)</title>", re.DOTALL)


@dataclass(frozen=True)
class Drawn:
    """One drawn figure: the file it is written to, beside the sheet or key, and its SVG text."""

    name: str
    svg: str

    @property
    def title(self) -> str:
        found = _TITLE.search(self.svg)
        return found.group(1).strip() if found else ""


@dataclass(frozen=True)
class QuestionFigures:
    """A question's figures: the one on the sheet (also in the key), and those only the key shows."""

    sheet: Drawn | None = None
    key: tuple[Drawn, ...] = ()


def figure_svg(variant) -> str | None:
    """The SVG of the variant's sheet figure, or None when its template has none."""
    reference = variant.template.figure
    if not reference:
        return None
    return resolve(reference, "figures")(variant)


def key_figure_svgs(variant) -> list[tuple[str, str]]:
    """(function name, SVG) of each figure the variant's key shows beside the working."""
    return [(split(ref)[1], resolve(ref, "figures")(variant)) for ref in variant.template.key_figures]


def question_figures(slot: str, variant) -> QuestionFigures:
    svg = figure_svg(variant)
    sheet = Drawn(f"{slot}.svg", svg) if svg else None
    key = tuple(Drawn(f"{slot}-{name}.svg", svg) for name, svg in key_figure_svgs(variant))
    return QuestionFigures(sheet, key)


def draw_figures(sheet) -> dict[str, QuestionFigures]:
    """Every question's figures, drawn once, by slot ("q1")."""
    return {q.slot: question_figures(q.slot, q.variant) for q in sheet.questions}
