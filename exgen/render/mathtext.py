"""Text with LaTeX math spans ($...$) for each output: Typst markup, Markdown, plain Unicode.

Templates and solvers write math as LaTeX. Typst gets it through `tex2typst` (cached: the
same symbols and formulas recur on every sheet); the prose around it is escaped so that a
`#`, `*`, `_`, `@` or `<` in a statement stays a character instead of becoming markup.
Markdown keeps the math as $...$ for GitHub, Pandoc and MathJax.
"""
from __future__ import annotations

import re
from functools import lru_cache

from ..errors import ExgenError
from .unicode_math import NEGATIVE_NUMBER, split_math, typeset_minus, unescape_dollars


_TYPST_ALWAYS = set("\\#*_$`<>@[]~")
_TYPST_LINE_START = re.compile(r"^([ \t]*)([=+\-/]|\d+\.(?=\s|$))", re.MULTILINE)
_MD_ALWAYS = set("\\`*_[]<>|$")
_MD_LINE_START = re.compile(r"^([ \t]*)(#|[+\-](?=\s)|\d+\.(?=\s))", re.MULTILINE)
_TYPST_ESCAPES = str.maketrans({ch: "\\" + ch for ch in _TYPST_ALWAYS})
_MD_ESCAPES = str.maketrans({ch: "\\" + ch for ch in _MD_ALWAYS})


class MathError(ExgenError, ValueError):
    """LaTeX that cannot be converted for an output; names the text."""

    def __init__(self, latex: str, reason: str):
        self.latex, self.reason = latex, reason
        super().__init__(f"cannot convert the math {latex!r}: {reason}")


@lru_cache(maxsize=8192)
def latex_to_typst(latex: str) -> str:
    """LaTeX math (without the dollars) -> Typst math (without the dollars)."""
    if not latex.strip():
        return ""
    import tex2typst  # only for Typst output: the terminal and Markdown never load it

    try:
        typst = tex2typst.tex2typst(latex)
    except ValueError as exc:
        raise MathError(latex, str(exc).splitlines()[0]) from None
    # P'' comes back as P^(' '), which Typst sets as two spaced apostrophes ("P ′ ′"); Typst's own P'' is P″
    # (T_2'' as T_2^(' '): the primes go before the subscript, as tex2typst writes T_2' as T'_2)
    return _SPACED_PRIMES.sub(lambda m: "'" * m.group(2).count("'") + (m.group(1) or ""), typst)


_SPACED_PRIMES = re.compile(r"(_\w+|_\([^()]*\))?\^\((\s*'(?:\s*')+\s*)\)")


@lru_cache(maxsize=16384)
def escape_typst(prose: str) -> str:
    """Plain text -> Typst markup that shows exactly that text (kept: labels, notes and units recur on
    every sheet)."""
    text = prose.translate(_TYPST_ESCAPES)
    text = text.replace("//", "/\\/").replace("/*", "/\\*").replace("-?", "-\\?")
    text = _DOTTED_UNIT.sub(_tight_unit, text)
    text = _NEGATIVE_NUMBER.sub("\u2212", text)
    # Typst turns ' after a digit into a prime, a glyph the body face lacks: "gear 1's" keeps an apostrophe,
    # and a prime ("l₃'") is written as one, which the layouts set from the math face
    text = _APOSTROPHE_AFTER_DIGIT.sub("\u2019", text)
    text = _PRIME_AFTER_DIGIT.sub("\u2032", text)
    return _TYPST_LINE_START.sub(lambda m: m.group(1) + _escape_marker(m.group(2)), text)


#: A hyphen before a digit that follows no word, number or closing bracket is a negative sign: Typst sets
#: it as a minus after a space but not after "(" or "[", so "(-100 mm, -190 mm)" mixed the two.
_NEGATIVE_NUMBER = NEGATIVE_NUMBER
_APOSTROPHE_AFTER_DIGIT = re.compile(r"(?<=\d)'(?=[A-Za-z])")
_PRIME_AFTER_DIGIT = re.compile("(?<=[0-9\u2080-\u2089])'")
#: A word with a middle dot in it, a unit such as N·m or kg·m²: the body font's dot stands spaced
#: ("N · m") where the key's math sets it tight, so the prose sets the math face's dot operator instead,
#: in a box that never breaks. (A fixed negative space round the body's dot closed up the regular face
#: but ran the bold face's narrower dot into the N of the keys' Answers table.)
#: A unit with a slash between letters ("kN/m", "kg/m³") is boxed too: a line may break after a slash, which
#: left "4.5 kN/" at a line's end and "m" on the next.
_DOTTED_UNIT = re.compile("\\S+\u00b7\\S+|\\S*[A-Za-z\u00b2\u00b3]/[A-Za-z]\\S*")  # not a spaced " · "
UNIT_DOT = '#text(font: "New Computer Modern Math")[\u22c5]'


def _tight_unit(match: re.Match) -> str:
    return "#box[" + match.group(0).replace("\u00b7", UNIT_DOT) + "]"


@lru_cache(maxsize=16384)
def escape_markdown(prose: str) -> str:
    """Plain text -> Markdown that shows exactly that text (no emphasis, links, lists or math)."""
    text = typeset_minus(prose).translate(_MD_ESCAPES)
    return _MD_LINE_START.sub(lambda m: m.group(1) + _escape_marker(m.group(2)), text)


def _escape_marker(marker: str) -> str:
    """A list or heading marker at the start of a line, made literal ("1." -> "1\\.", "-" -> "\\-")."""
    return marker[:-1] + "\\." if marker.endswith(".") else "\\" + marker


def text_to_typst(text: str) -> str:
    """A statement or ask with $LaTeX$ spans -> Typst markup with $Typst math$."""
    return "".join(f"${latex_to_typst(chunk)}$" if is_math else escape_typst(unescape_dollars(chunk))
                   for is_math, chunk in split_math(text))


def text_to_markdown(text: str) -> str:
    """A statement or ask with $LaTeX$ spans -> Markdown, the math kept as $LaTeX$."""
    return "".join(f"${chunk}$" if is_math else escape_markdown(unescape_dollars(chunk))
                   for is_math, chunk in split_math(text))


def typst_string(text: str) -> str:
    """A Typst string literal holding `text` exactly (used to embed SVG figures in the source)."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\r", "\\r")
    return '"' + escaped.replace("\t", "\\t") + '"'
