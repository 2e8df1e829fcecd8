"""Where a long worked line breaks: at '=' with the left side aligned, then between top-level terms.

Typst does not break a display equation by itself, and an inline one breaks anywhere (inside
cos(2 × 5.411), inside a fraction's row). So the rows are planned here from an estimate of each
term's width (exgen.render.widths), made generous so that a planned row always fits, and Typst aligns them:

    F₀ = m₁r₁ cos θ₁ + m₂r₂ cos θ₂
           + m₃r₃ cos θ₃
       = 0.525 cos 120° + ...
"""
from __future__ import annotations

from dataclasses import dataclass

from .targets import PLAIN, SIG
from .widths import term_width, text_width

#: Width of an equation row beside the part column, in em of the body font.
WIDTH = 38.0
EQUALS = 1.6       # " = " with its spacing
INDENT = 2.0       # a continued row (quad) is indented under the right-hand side



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


def rows(line, target) -> list[list[str]]:
    """A worked line as rows of the target's math, each starting '= ...' or continuing a term; one row for
    a target that wraps lines itself (Markdown, the terminal)."""
    if not hasattr(target, "sized_terms"):
        return [[target.math(line.symbol)] + ["= " + " ".join(target.terms(p)) for p in line.pieces]]
    written, sizes = [[target.math(line.symbol)]], [[term_width(line.symbol)]]
    for piece in line.pieces:
        sized = target.sized_terms(piece) if hasattr(piece, "formula") else \
            [(t, text_width(PLAIN.quantity(piece.value, piece.unit, getattr(piece, "sig", SIG)))) for t in target.terms(piece)]
        written.append([t for t, _ in sized])
        sizes.append([w for _, w in sized])
    return [[("= " if seg.start and seg.piece else "") + " ".join(written[seg.piece][seg.lo:seg.hi]) for seg in row]
            for row in plan(sizes)]
