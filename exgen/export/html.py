"""HTML for learning systems: the render targets (render.targets) the exports write statements,
asks and worked solutions with, and the one layout of a worked solution.

Moodle and Canvas typeset LaTeX between \\( \\) and \\[ \\] with MathJax (Moodle's MathJax filter is on
by default; docs/lms.md says why Canvas gets LaTeX too), so their HTML keeps the math as LaTeX. A QTI
2.1 item is XHTML whose schema admits MathML 2: its math is MathML made from the same LaTeX, which
browsers lay out themselves. Every method returns `markupsafe.Markup`: prose is escaped here once and
the layouts run with autoescaping on.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import jinja2
from markupsafe import Markup, escape

from ..render.targets import Markdown
from ..render.unicode_math import split_math, unescape_dollars
from .mathml2 import qti_math

LAYOUTS = Path(__file__).parent / "templates"


def _paragraphs(text: str) -> str:
    """Escaped prose with a blank line as a paragraph break (the layout wraps the whole in <p>)."""
    return str(escape(text)).replace("\n\n", "</p><p>")


class LatexHtml(Markdown):
    """HTML whose math is LaTeX between \\( \\) (inline) and \\[ \\] (display), for MathJax."""

    name = "latex-html"
    #: How a worked line is delimited (Canvas's own below).
    display = ("\\[", "\\]")

    def inline(self, math_source: str) -> Markup:
        return Markup("\\(") + escape(math_source) + Markup("\\)")

    def text(self, text: str) -> Markup:
        return Markup("".join(str(self.inline(chunk)) if is_math else _paragraphs(unescape_dollars(chunk))
                              for is_math, chunk in split_math(text)))

    def prose(self, text: str) -> Markup:
        return escape(text)

    def equation(self, rows: list[list[str]]) -> Markup:
        opening, closing = self.display
        return Markup(opening) + escape(" ".join(piece for row in rows for piece in row)) + Markup(closing)


class CanvasHtml(LatexHtml):
    """LaTeX HTML for Canvas, which loads MathJax only for text holding \\( (or $$), never for \\[ alone: a
    worked line is \\(\\displaystyle ...\\) in its own paragraph, so a solution of display lines alone
    (a key with no givens) is typeset too."""

    name = "canvas-html"
    display = ("\\(\\displaystyle ", "\\)")


class MathmlXhtml(Markdown):
    """XHTML whose math is MathML (QTI 2.1 allows MathML 2 in item bodies and feedback): composed as
    LaTeX, as for the keys, and converted where it meets prose (exgen.export.mathml2)."""

    name = "mathml-xhtml"

    def inline(self, math_source: str) -> Markup:
        return Markup(qti_math(math_source))

    def text(self, text: str) -> Markup:
        return Markup("".join(qti_math(chunk) if is_math else _paragraphs(unescape_dollars(chunk))
                              for is_math, chunk in split_math(text)))

    def prose(self, text: str) -> Markup:
        return escape(text)

    def equation(self, rows: list[list[str]]) -> Markup:
        """A worked line as display math, one block per planned row (as on the practice pages)."""
        return Markup("".join(qti_math(" ".join(row), display=True) for row in rows))


LATEX_HTML, CANVAS_HTML, MATHML_XHTML = LatexHtml(), CanvasHtml(), MathmlXhtml()


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
