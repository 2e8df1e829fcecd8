"""Markdown sheets and keys (GitHub/Pandoc: math as $...$, figures as SVG files beside the file)."""
from __future__ import annotations

import re

from ..figures import draw_figures
from .context import sheet_context
from .jinja import render
from .targets import MARKDOWN


def _tidy(text: str) -> str:
    """At most one blank line between blocks (layouts stay readable with their own spacing)."""
    return re.sub(r"\n{3,}", "\n\n", text).strip() + "\n"


def _context(sheet, figures, key: bool) -> dict:
    """Figures are embedded by file name (written beside the Markdown by whoever writes it)."""
    figures = draw_figures(sheet) if figures is None else figures
    sheet_figures = {slot: f.sheet for slot, f in figures.items() if f.sheet}
    key_figures = {slot: [(d.name, d.title) for d in f.key] for slot, f in figures.items()} if key else {}
    return sheet_context(sheet, MARKDOWN, {slot: d.name for slot, d in sheet_figures.items()},
                         {slot: d.svg for slot, d in sheet_figures.items()}, key=key, key_figures=key_figures)


def sheet_markdown(sheet, figures=None) -> str:
    """The student's sheet; `figures` is the sheet's `draw_figures` (drawn here when not given; {} for none)."""
    return _tidy(render("sheet.md.j2", _context(sheet, figures, key=False)))


def key_markdown(sheet, figures=None) -> str:
    """The instructor's key: the sheet plus given data, worked solutions, key-only figures and answers."""
    return _tidy(render("key.md.j2", _context(sheet, figures, key=True)))
