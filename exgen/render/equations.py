"""Where a long worked line breaks: at '=' with the left side aligned, then between top-level terms.

Typst does not break a display equation by itself, and an inline one breaks anywhere (inside
cos(2 × 5.411), inside a fraction's row). So the rows are planned here from an estimate of each
term's width, made generous so that a planned row always fits, and Typst aligns them:

    F₀ = m₁r₁ cos θ₁ + m₂r₂ cos θ₂
           + m₃r₃ cos θ₃
       = 0.525 cos 120° + ...
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from .formula import Arg, Cmd, Delim, FormulaError, Group, Paren, Script, Tok, parse
from .targets import PLAIN

#: Width of an equation row beside the part column, in em of the body font.
WIDTH = 38.0
EQUALS = 1.6       # " = " with its spacing
INDENT = 2.0       # a continued row (quad) is indented under the right-hand side

_CHAR = {"+": 1.3, "-": 1.3, "=": 1.6, "/": 0.5, "(": 0.4, ")": 0.4, "|": 0.3, ",": 0.3, ".": 0.3}
_CMD = {"times": 1.3, "cdot": 0.9, ",": 0.17, ";": 0.28, ":": 0.22, "quad": 1.0, "qquad": 2.0, "circ": 0.4,
        "lceil": 0.4, "rceil": 0.4, "pi": 0.6, "%": 0.8, " ": 0.3}


@dataclass(frozen=True)
class Segment:
    """Terms lo..hi-1 of piece `piece` (0 is the symbol); `start`: the piece begins here (write '= ')."""

    piece: int
    lo: int
    hi: int
    start: bool


def plan(sizes: list[list[float]], width: float = WIDTH) -> list[list[Segment]]:
    """Rows of segments for a line whose pieces (symbol first) are terms of the widths `sizes` (em)."""
    pieces = sizes
    lead = sum(sizes[0])
    rows: list[list[Segment]] = [[Segment(0, 0, len(pieces[0]), True)]]
    used = lead
    for k in range(1, len(pieces)):
        whole = EQUALS + sum(sizes[k])
        if used + whole > width and len(rows[-1]) > 1:
            rows.append([])
            used = lead
        if used + whole <= width:
            rows[-1].append(Segment(k, 0, len(pieces[k]), True))
            used += whole
            continue
        lo, start = 0, True  # longer than a row: break between its terms
        while lo < len(pieces[k]):
            hi, size = lo, (EQUALS if start else INDENT)
            while hi < len(pieces[k]) and (hi == lo or used + size + sizes[k][hi] <= width):
                size += sizes[k][hi]
                hi += 1
            rows[-1].append(Segment(k, lo, hi, start))
            used += size
            lo, start = hi, False
            if lo < len(pieces[k]):
                rows.append([])
                used = lead
    return rows


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


def rows(line, target) -> list[list[str]]:
    """A worked line as rows of the target's math, each starting '= ...' or continuing a term; one row for
    a target that wraps lines itself (Markdown, the terminal)."""
    if not hasattr(target, "sized_terms"):
        return [[target.math(line.symbol)] + ["= " + " ".join(target.terms(p)) for p in line.pieces]]
    written, sizes = [[target.math(line.symbol)]], [[term_width(line.symbol)]]
    for piece in line.pieces:
        sized = target.sized_terms(piece) if hasattr(piece, "formula") else \
            [(t, _quantity_width(piece)) for t in target.terms(piece)]
        written.append([t for t, _ in sized])
        sizes.append([w for _, w in sized])
    return [[("= " if seg.start and seg.piece else "") + " ".join(written[seg.piece][seg.lo:seg.hi]) for seg in row]
            for row in plan(sizes)]


def _quantity_width(piece) -> float:
    """A value, by the length of its plain writing."""
    return 0.55 * len(PLAIN.quantity(piece.value, piece.unit)) + 0.5
