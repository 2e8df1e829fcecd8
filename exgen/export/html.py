"""HTML for learning systems: the render targets (render.targets) the exports write statements,
asks and worked solutions with, and the one layout of a worked solution.

Moodle and Canvas typeset LaTeX between \\( \\) and \\[ \\] with MathJax (Moodle's MathJax filter is on
by default; Canvas renders it in quiz text), so their HTML keeps the math as LaTeX. A QTI 2.1 item is
XHTML that any delivery engine must show: its math is written in Unicode (θ = π − 2α, T₁/T₂), which
needs no MathJax and no MathML support. Every method returns `markupsafe.Markup`: prose is escaped
here once and the layouts run with autoescaping on.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import jinja2
from markupsafe import Markup, escape

from ..render.targets import Markdown, Plain
from ..render.unicode_math import latex_to_unicode, split_math, unescape_dollars

LAYOUTS = Path(__file__).parent / "templates"


def _paragraphs(text: str) -> str:
    """Escaped prose with a blank line as a paragraph break (the layout wraps the whole in <p>)."""
    return str(escape(text)).replace("\n\n", "</p><p>")


class LatexHtml(Markdown):
    """HTML whose math is LaTeX between \\( \\) (inline) and \\[ \\] (display), for MathJax."""

    name = "latex-html"

    def inline(self, math_source: str) -> Markup:
        return Markup("\\(") + escape(math_source) + Markup("\\)")

    def text(self, text: str) -> Markup:
        return Markup("".join(str(self.inline(chunk)) if is_math else _paragraphs(unescape_dollars(chunk))
                              for is_math, chunk in split_math(text)))

    def prose(self, text: str) -> Markup:
        return escape(text)

    def equation(self, rows: list[list[str]]) -> Markup:
        return Markup("\\[") + escape(" ".join(piece for row in rows for piece in row)) + Markup("\\]")


class UnicodeHtml(Plain):
    """XHTML whose math is plain Unicode text: shown as it is by any engine."""

    name = "unicode-html"

    def inline(self, math_source: str) -> Markup:
        return escape(math_source)

    def text(self, text: str) -> Markup:
        return Markup("".join(str(escape(latex_to_unicode(chunk))) if is_math else _paragraphs(unescape_dollars(chunk))
                              for is_math, chunk in split_math(text)))

    def prose(self, text: str) -> Markup:
        return escape(text)

    def equation(self, rows: list[list[str]]) -> Markup:
        return escape(" ".join(piece for row in rows for piece in row))


LATEX_HTML, UNICODE_HTML = LatexHtml(), UnicodeHtml()


@lru_cache(maxsize=1)
def environment() -> jinja2.Environment:
    """Every export layout: autoescaped (text is escaped unless a target made it Markup), strict."""
    from .filters import FILTERS

    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(LAYOUTS)), undefined=jinja2.StrictUndefined, autoescape=True,
        trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True,
    )
    env.filters.update(FILTERS)
    return env


def render(layout: str, **context) -> str:
    return environment().get_template(layout).render(context)
