"""LaTeX math -> MathML, which current browsers render themselves (no script, nothing fetched).

The conversion is latex2mathml's; what exgen writes (fractions, roots, scripts, Greek, \\text,
\\mathrm, \\left/\\right, \\vec, spacing, degrees) is all within what it reads, and a test converts
every template's statements, asks and worked solutions to keep it so. Two things are added here:
the converter copies the argument of \\text into the markup as it is, so '<', '>' and '&' there are
passed through as placeholders and written as entities after; and every result is checked to be
well-formed MathML before it reaches a page. Results are cached: symbols and formulas recur.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ElementTree
from functools import lru_cache
from html import escape

from .mathtext import MathError
from .unicode_math import latex_to_unicode

NAMESPACE = ' xmlns="http://www.w3.org/1998/Math/MathML"'
_TEXT_ARGUMENT = re.compile(r"(\\(?:text|textrm|mbox)\s*\{)([^{}]*)(\})")
_PLACEHOLDERS = {"&": "QxAMPxQ", "<": "QxLTxQ", ">": "QxGTxQ"}
_ENTITIES = {"QxAMPxQ": "&amp;", "QxLTxQ": "&lt;", "QxGTxQ": "&gt;"}
#: The elements a converted formula may hold (MathML Core's presentation elements).
ELEMENTS = frozenset({"math", "mrow", "mi", "mn", "mo", "mtext", "mspace", "msub", "msup", "msubsup", "mfrac",
                      "msqrt", "mroot", "mover", "munder", "munderover", "mstyle", "mtable", "mtr", "mtd",
                      "mpadded", "mphantom", "menclose", "merror", "ms", "semantics", "annotation"})


@lru_cache(maxsize=16384)
def latex_to_mathml(latex: str, display: bool = False) -> str:
    """One <math> element (inline, or a display block) for LaTeX math without dollars. MathError
    if the converter cannot read it."""
    from latex2mathml.converter import convert  # imported here: only pages with math need it

    guarded = _TEXT_ARGUMENT.sub(lambda m: m.group(1) + _guard(m.group(2)) + m.group(3), latex)
    try:
        element = convert(guarded, display="block" if display else "inline")
    except Exception as exc:  # the converter raises its own exception types, and IndexError on bad input
        raise MathError(latex, f"{type(exc).__name__}: {exc}") from None
    for placeholder, entity in _ENTITIES.items():
        element = element.replace(placeholder, entity)
    _check(latex, element)
    # inside an HTML document the namespace is implied; alttext is what a reader without MathML falls back on
    alt = escape(latex_to_unicode(latex), quote=True)
    return element.replace(NAMESPACE, f' alttext="{alt}"', 1)


def _guard(text: str) -> str:
    return "".join(_PLACEHOLDERS.get(ch, ch) for ch in text)


def _check(latex: str, element: str) -> None:
    """Well-formed, MathML elements only, and no LaTeX command left unread (shown as '\\foo')."""
    try:
        root = ElementTree.fromstring(element)
    except ElementTree.ParseError as exc:
        raise MathError(latex, f"the converter wrote malformed MathML ({exc})") from None
    for node in root.iter():
        name = node.tag.rpartition("}")[2]
        if name not in ELEMENTS:
            raise MathError(latex, f"the converter wrote <{name}>, which is not MathML")
        if name in ("mi", "mo") and (node.text or "").startswith("\\"):
            raise MathError(latex, f"the converter does not know {node.text}")
