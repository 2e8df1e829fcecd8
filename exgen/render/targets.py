"""One small object per output format: how it writes math, a quantity and a line of prose.

The context builder and the worked solution are written once against this interface;
Markdown, Typst and the terminal differ only here.
"""
from __future__ import annotations

import math
import re
from functools import lru_cache

from .. import units
from .formula import terms, written
from .mathtext import escape_markdown, escape_typst, latex_to_typst, text_to_markdown, text_to_typst
from .unicode_math import latex_to_unicode, text_to_plain, typeset_minus
from .widths import number_width, term_width

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


def _pieces(target, piece) -> list[str]:
    """A member of a worked line as terms (a long line breaks between them): a symbol (LaTeX), a
    Quantity, or a Filled formula."""
    if isinstance(piece, str):
        return [target.math(piece)]
    if hasattr(piece, "formula"):
        return target.formula_terms(piece)
    return [target.quantity(piece.value, piece.unit, getattr(piece, "sig", SIG))]


def _latex_slot(target, number) -> str:
    text = number.exact if number.exact is not None else target.number(number.value, number.sig)
    if number.degrees:
        text += target.DEGREE
    return f"({text})" if text.startswith("-") else text


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

    DEGREE = r"^{\circ}"

    def slot(self, number) -> str:
        return _latex_slot(self, number)

    def terms(self, piece) -> list[str]:
        return _pieces(self, piece)

    def formula_terms(self, filled) -> list[str]:
        return terms(filled.latex(self.slot))

    def equation(self, rows: list[list[str]]) -> str:
        """A worked line as one line of inline math (Markdown viewers wrap it themselves)."""
        return " ".join(piece for row in rows for piece in row)


_UNIT_POWER = re.compile("([⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+)")
_PLAIN_POWER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")


def _typst_unit(shown: str) -> str:
    """'kg·m²' -> '"kg·m"^(2)': a unit's powers as math attachments. Inside math, the superscript
    digits of a quoted unit would be set by the prose show rule on the baseline ("mm2")."""
    out = []
    for i, piece in enumerate(_UNIT_POWER.split(shown)):
        if i % 2:
            out.append(f"^({piece.translate(_PLAIN_POWER)})")
        elif piece:
            out.append(f'"{piece}"')
    return "".join(out)


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
        return f"{number} thin {_typst_unit(shown)}" if shown else number

    def text(self, text: str) -> str:
        return text_to_typst(text)

    def prose(self, text: str) -> str:
        return escape_typst(text)

    def slot(self, number) -> str:
        text = number.exact if number.exact is not None else self.number(number.value, number.sig)
        if " " in text:
            text = f"({text})"
        if number.degrees:
            text += "°"
        return f"({text})" if text.startswith("-") else text

    def terms(self, piece) -> list[str]:
        return _pieces(self, piece)

    def formula_terms(self, filled) -> list[str]:
        """The formula's Typst, converted once per formula and set of symbols, then numbers filled in."""
        return [term for term, _ in self.sized_terms(filled)]

    def sized_terms(self, filled) -> list[tuple[str, float]]:
        """Each term of the formula in Typst, with its estimated width in em (for breaking long lines)."""
        marked = _marked(filled.formula.latex, tuple(f if isinstance(f, str) else None for f in filled.fills),
                         filled.numbers)
        numbers = {str(i): (self.slot(f), _number_width(f)) for i, f in enumerate(filled.fills) if not isinstance(f, str)}
        out = []
        for term, width, slots in _typst_terms(marked):
            out.append((_MARKER.sub(lambda m: numbers[m.group(1)][0], term),
                        width + sum(numbers[i][1] for i in slots)))
        return out

    def equation(self, rows: list[list[str]]) -> str:
        """The body of a display equation: rows aligned at the first '=', a row that continues a long
        right-hand side indented under it."""
        out = []
        for i, row in enumerate(rows):
            if i == 0:
                out.append(row[0] + (" &" + " ".join(row[1:]) if len(row) > 1 else ""))
            else:
                out.append(("&" if row[0].startswith("= ") else '&quad "" ') + " ".join(row))
        return " \\\n  ".join(out)


_MARKER = re.compile(r'"#(\d+)#"')
_LATEX_MARKER = re.compile(r"\\text\{#(\d+)#\}")


def _marked(latex: str, symbols: tuple, numbers: bool) -> str:
    """The formula's LaTeX with each number's place held by a marker, \\text{#3#}: one per template."""
    return written(latex, tuple(symbol or rf"\text{{#{i}#}}" for i, symbol in enumerate(symbols)), numbers)


@lru_cache(maxsize=8192)
def _typst_terms(marked: str) -> tuple[tuple[str, float, tuple[str, ...]], ...]:
    """(Typst, width in em without its numbers, the markers it holds) of each term."""
    return tuple((latex_to_typst(term), term_width(term), tuple(_LATEX_MARKER.findall(term))) for term in terms(marked))


def _number_width(number) -> float:
    mantissa, exponent = number_parts(number.value, number.sig) if number.exact is None else (number.exact, None)
    return number_width(mantissa, exponent, number.degrees)


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
        mantissa = typeset_minus(mantissa)
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
        return typeset_minus(text)

    DEGREE = r"^{\circ}"

    def slot(self, number) -> str:
        return _latex_slot(MARKDOWN, number)

    def terms(self, piece) -> list[str]:
        return _pieces(self, piece)

    def formula_terms(self, filled) -> list[str]:
        return [latex_to_unicode(filled.latex(self.slot))]

    def equation(self, rows: list[list[str]]) -> str:
        return " ".join(piece for row in rows for piece in row)


MARKDOWN, TYPST, PLAIN = Markdown(), Typst(), Plain()
