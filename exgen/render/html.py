"""The HTML target (render.targets): prose escaped, math as MathML made here from the same LaTeX.

Everything it returns is `markupsafe.Markup`, ready for a Jinja2 environment with autoescape on:
text written by exgen is escaped here once, and anything else a page shows (a student's answer,
a message quoting it) stays a plain string that the page escapes.
"""
from __future__ import annotations

from markupsafe import Markup, escape

from .mathml import latex_to_mathml
from .unicode_math import split_math, unescape_dollars
from .targets import Markdown


class Html(Markdown):
    """Math is composed as LaTeX (as for Markdown) and converted to MathML where it meets prose."""

    name = "html"

    def inline(self, math_source: str) -> Markup:
        return Markup(latex_to_mathml(math_source))

    def text(self, text: str) -> Markup:
        """A statement, ask, label or note: $LaTeX$ spans as MathML, the rest escaped; a blank line
        starts a new paragraph (the layout wraps the result in <p>)."""
        out = []
        for is_math, chunk in split_math(text):
            if is_math:
                out.append(latex_to_mathml(chunk))
            else:
                out.append(str(escape(unescape_dollars(chunk))).replace("\n\n", "</p><p>"))
        return Markup("".join(out))

    def prose(self, text: str) -> Markup:
        return escape(text)

    def equation(self, rows: list[list[str]]) -> Markup:
        """A worked line as display math, one block per planned row; a narrow screen scrolls a row
        sideways rather than breaking inside a fraction."""
        return Markup("".join(latex_to_mathml(" ".join(row), display=True) for row in rows))


HTML = Html()
