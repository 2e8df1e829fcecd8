"""MathML for QTI 2.1 items: the MathML the practice pages show (exgen.render.mathml, made from the
same LaTeX as the keys), put back in its namespace.

Each <math> declares the MathML namespace as its default, so an item body dropped as it is into an
HTML page (text/html) still renders, where an `m:` prefix would not. QTI 2.1 imports MathML 2; what
the converter writes for exgen's formulas (presentation elements, `display`, `alttext`, `stretchy`,
`fence`, `form`, `mspace width`) is all within it, and the export tests validate every item of every
template against the schema, so nothing is rewritten here: a formula MathML 2 rejected would fail
them rather than be mangled quietly.
"""
from __future__ import annotations

from functools import lru_cache

from ..render.mathml import latex_to_mathml

MATHML = "http://www.w3.org/1998/Math/MathML"


@lru_cache(maxsize=16384)
def qti_math(latex: str, display: bool = False) -> str:
    """One <math> element in the MathML namespace for LaTeX math without dollars (MathError if the
    converter cannot read it)."""
    element = latex_to_mathml(latex, display)
    return element.replace("<math ", f'<math xmlns="{MATHML}" ', 1)
