"""One small object per output format: how it writes math, a quantity and a line of prose.

The context builder and the worked solution are written once against this interface;
Markdown, Typst and the terminal differ only here.
"""
from __future__ import annotations

import math
import re

from .. import units
from .mathtext import escape_markdown, escape_typst, latex_to_typst, text_to_markdown, text_to_plain, text_to_typst
from .unicode_math import latex_to_unicode

SIG = 4
_EXPONENT = re.compile(r"^(-?[\d.]+)e(-?\d+)$")
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
_PLAIN_UNITS = ("\u00b0", "%")  # written straight after the number


def number_parts(value, sig: int = SIG) -> tuple[str, str | None]:
    """(mantissa, exponent or None) of a number to `sig` figures; ints stay exact."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"not a number: {value!r}")
    if isinstance(value, int):
        return str(value), None
    text = units.format_number(value, sig)
    match = _EXPONENT.match(text)
    mantissa, exponent = (match.group(1), match.group(2)) if match else (text, None)
    if "." in mantissa:  # an exact value needs no padding zeros: 0.35, not 0.3500
        trimmed = mantissa.rstrip("0").rstrip(".")
        if math.isclose(float(trimmed) * 10.0 ** int(exponent or 0), value, rel_tol=1e-12, abs_tol=0.0):
            mantissa = trimmed
    return mantissa, exponent


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _latex_of(value) -> str | None:
    """The LaTeX of a value that is not a number but writes itself as math (a formula answer)."""
    latex = getattr(value, "latex", None)
    return latex() if callable(latex) else None


class Markdown:
    """GitHub/Pandoc Markdown: math stays LaTeX between dollars."""

    name = "markdown"

    def math(self, latex: str) -> str:
        return latex

    def inline(self, math_source: str) -> str:
        return f"${math_source}$"

    def number(self, value, sig: int = SIG) -> str:
        if not _is_number(value):
            return self.math(_latex_of(value)) if _latex_of(value) else r"\text{" + str(value) + "}"
        mantissa, exponent = number_parts(value, sig)
        return f"{mantissa} \\times 10^{{{exponent}}}" if exponent else mantissa

    def quantity(self, value, unit: str, sig: int = SIG) -> str:
        shown = units.pretty_unit(unit)
        number = self.number(value, sig)
        if shown == "\u00b0":
            return number + r"^{\circ}"
        if shown == "%":
            return number + r"\%"
        return f"{number}\\ \\text{{{shown}}}" if shown else number

    def text(self, text: str) -> str:
        return text_to_markdown(text)

    def prose(self, text: str) -> str:
        return escape_markdown(text)


class Typst:
    """Typst markup: math converted from LaTeX, prose escaped."""

    name = "typst"

    def math(self, latex: str) -> str:
        return latex_to_typst(latex)

    def inline(self, math_source: str) -> str:
        return f"${math_source}$"

    def number(self, value, sig: int = SIG) -> str:
        if not _is_number(value):
            if _latex_of(value):  # a formula answer
                return self.math(_latex_of(value))
            return '"' + str(value).replace("\\", "\\\\").replace('"', '\\"') + '"'
        mantissa, exponent = number_parts(value, sig)
        return f"{mantissa} times 10^({exponent})" if exponent else mantissa

    def quantity(self, value, unit: str, sig: int = SIG) -> str:
        shown = units.pretty_unit(unit)
        number = self.number(value, sig)
        if shown in _PLAIN_UNITS:
            return f'{number}"{shown}"'
        return f'{number} thin "{shown}"' if shown else number

    def text(self, text: str) -> str:
        return text_to_typst(text)

    def prose(self, text: str) -> str:
        return escape_typst(text)


class Plain:
    """The terminal: Unicode, no markup."""

    name = "plain"

    def math(self, latex: str) -> str:
        return latex_to_unicode(latex)

    def inline(self, math_source: str) -> str:
        return math_source

    def number(self, value, sig: int = SIG) -> str:
        if not _is_number(value):
            return self.math(_latex_of(value)) if _latex_of(value) else str(value)
        mantissa, exponent = number_parts(value, sig)
        return f"{mantissa}×10{exponent.translate(_SUPERSCRIPT)}" if exponent else mantissa

    def quantity(self, value, unit: str, sig: int = SIG) -> str:
        shown = units.pretty_unit(unit)
        number = self.number(value, sig)
        if shown in _PLAIN_UNITS:
            return number + shown
        return f"{number} {shown}" if shown else number

    def text(self, text: str) -> str:
        return text_to_plain(text)

    def prose(self, text: str) -> str:
        return text


MARKDOWN, TYPST, PLAIN = Markdown(), Typst(), Plain()
