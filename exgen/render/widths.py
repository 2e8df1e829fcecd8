"""How wide a piece of a worked line is, in em of the body font: estimates made generous, so that a row
planned from them (exgen.render.equations) always fits the column. Typst measures nothing for us here:
an equation row is planned before it is typeset."""
from __future__ import annotations

from functools import lru_cache

from .formula import Arg, Cmd, Delim, FormulaError, Group, Paren, Script, Tok, parse

_CHAR = {"+": 1.3, "-": 1.3, "=": 1.6, "/": 0.5, "(": 0.4, ")": 0.4, "|": 0.3, ",": 0.3, ".": 0.3}
_CMD = {"times": 1.3, "cdot": 0.9, ",": 0.17, ";": 0.28, ":": 0.22, "quad": 1.0, "qquad": 2.0, "circ": 0.4,
        "lceil": 0.4, "rceil": 0.4, "pi": 0.6, "%": 0.8, " ": 0.3}


@lru_cache(maxsize=8192)
def term_width(latex: str) -> float:
    """A generous estimate of a term's width in em, in display style."""
    try:
        return _width(parse(latex).tree, 1.0)
    except FormulaError:
        return 0.55 * len(latex)


def _width(node, scale: float) -> float:
    if isinstance(node, Group):
        return sum(_width(i, scale) for i in node.items)
    if isinstance(node, Tok):
        if node.kind == "num":
            return 0.5 * len(node.text) * scale
        if node.kind == "space":
            return 0.0
        if node.kind == "cmd":
            if node.text in _CMD:
                return _CMD[node.text] * scale
            return (0.45 * len(node.text) + 0.3 if node.text in ("sin", "cos", "tan", "ln", "exp") else 0.65) * scale
        return _CHAR.get(node.text, 0.6) * scale
    if isinstance(node, Script):
        scripts = max(_width(x, scale * 0.7) for x in (node.sup, node.sub) if x is not None)
        return _width(node.base, scale) + scripts + 0.05
    if isinstance(node, Cmd):
        if node.name in ("frac", "dfrac", "tfrac"):
            inner = 1.0 if scale >= 1.0 else 0.75
            return max(_width(a, scale * inner) for a in node.args) + 0.4 * scale
        if node.name == "sqrt":
            return _width(node.args[0], scale) + 1.1 * scale
        text = node.args[0]
        return 0.0 if text.startswith("#") and text.endswith("#") else 0.5 * len(text) * scale  # a number's place
    if isinstance(node, (Delim, Paren)):
        return _width(node.body, scale) + 0.9 * scale
    if isinstance(node, Arg):
        return _width(node.body, scale) + 0.3 * scale
    return 0.6 * scale


def number_width(mantissa: str, exponent: str | None = None, degrees: bool = False) -> float:
    """A generous width in em of a number standing in a formula: its digits, a power of ten, a degree sign."""
    width = 0.5 * len(mantissa.lstrip("-")) + (0.9 if mantissa.startswith("-") else 0.0)
    return width + (2.8 + 0.35 * len(exponent) if exponent else 0.0) + (0.4 if degrees else 0.0)


def text_width(text: str) -> float:
    """Plain text (a value with its unit), by its length."""
    return 0.55 * len(text) + 0.5
