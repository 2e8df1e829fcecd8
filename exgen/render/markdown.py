"""Markdown sheets and keys (GitHub/Pandoc: math as $...$, figures as SVG files beside the file)."""
from __future__ import annotations

import re

from ..figures import figure_svg
from .context import sheet_context
from .jinja import render
from .targets import MARKDOWN


def _svgs(sheet, figure_files: dict[str, str]) -> dict[str, str]:
    """The SVG text of each question that has a figure file, read for its caption."""
    return {q.slot: figure_svg(q.variant) or "" for q in sheet.questions if q.slot in figure_files}


def _tidy(text: str) -> str:
    """At most one blank line between blocks (layouts stay readable with their own spacing)."""
    return re.sub(r"\n{3,}", "\n\n", text).strip() + "\n"


def sheet_markdown(sheet, figure_files: dict[str, str]) -> str:
    """The student's sheet; `figure_files` maps a slot ("q1") to the SVG file's relative path."""
    context = sheet_context(sheet, MARKDOWN, figure_files, _svgs(sheet, figure_files), key=False)
    return _tidy(render("sheet.md.j2", context))


def key_markdown(sheet, figure_files: dict[str, str]) -> str:
    """The instructor's key: the sheet plus given data, worked solutions and an answers table."""
    context = sheet_context(sheet, MARKDOWN, figure_files, _svgs(sheet, figure_files), key=True)
    return _tidy(render("key.md.j2", context))
