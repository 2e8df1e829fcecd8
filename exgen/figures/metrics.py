"""Text metrics of the figures' font, so labels can be placed clear of each other and of the drawing.

Figures and sheets are set in one family, New Computer Modern, which ships inside Typst (GUST Font
License), so every PDF embeds the same font on any machine. Its glyph advances and ink extents are
kept in `font_metrics.json`, measured from that very font by Typst's own shaper; regenerate the
file after a Typst upgrade with `python -m exgen.figures.metrics` (a test checks it still matches).
Figures need only this table at run time: no font file, no font library.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

FAMILY = "New Computer Modern"
#: Signs the text face lacks, set from its math companion (same design, embedded by Typst too); the dot
#: of a unit (kg·m², N·s/m) is the math face's dot operator, set tight as in the sheet's prose and the keys.
MATH_FAMILY = "New Computer Modern Math"
FROM_MATH = "′″⋅"
#: What an SVG asks for: the family Typst embeds, then look-alikes a browser may have, then any serif.
SVG_FAMILY = "'New Computer Modern', 'Latin Modern Roman', 'CMU Serif', serif"
STYLES = ("regular", "bold", "italic", "bold-italic")
#: The characters measured: printable ASCII, Greek, and the signs figures print.
CHARACTERS = ("".join(chr(c) for c in range(0x20, 0x7F)) + "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩ"
              "αβγδεζηθικλμνξοπρστυφχψω°·×−–—±√→←′″⋅")
#: Width and ink of a character the table lacks: as wide and tall as the widest capitals.
UNKNOWN = (0.9, 0.75, 0.25)
TABLE = "font_metrics.json"


@dataclass(frozen=True)
class Ink:
    """A run of text at size 1: its advance width, and its ink above and below the baseline."""

    width: float
    above: float
    below: float


def style_name(bold: bool, italic: bool) -> str:
    return ("bold-" if bold else "") + "italic" if italic else ("bold" if bold else "regular")


@lru_cache(maxsize=1)
def _table() -> dict[str, dict[str, tuple[float, float, float]]]:
    data = json.loads(resources.files(__package__).joinpath(TABLE).read_text(encoding="utf-8"))
    return {style: {c: tuple(v) for c, v in zip(data["characters"], data["styles"][style])}
            for style in STYLES}


def measure(text: str, bold: bool = False, italic: bool = False) -> Ink:
    """The extent of `text` at font size 1 (multiply by the size in px), from the font's own metrics."""
    glyphs = _table()[style_name(bold, italic)]
    width, above, below = 0.0, 0.0, 0.0
    for char in text:
        advance, top, bottom = glyphs.get(char, UNKNOWN)
        width += advance
        above, below = max(above, top), max(below, bottom)
    return Ink(width, above, below)


def covered(text: str) -> bool:
    """Whether every character of `text` is in the table (a figure's text should be)."""
    return all(c in _table()["regular"] for c in text)


# ---- building the table (maintenance: needs the typst package, which exgen depends on anyway) ----

_MEASURE = """#let m(c, style, weight) = {{
  let family = if c in "{from_math}" {{ "{math_family}" }} else {{ "{family}" }}
  let t(top, bottom) = measure(text(font: family, size: 1000pt, style: style, weight: weight,
    top-edge: top, bottom-edge: bottom, fallback: false, c))
  (calc.round(t("baseline", "baseline").width.pt() / 1000, digits: 4),
   calc.round(calc.max(0, t("bounds", "baseline").height.pt()) / 1000, digits: 4),
   calc.round(calc.max(0, t("baseline", "bounds").height.pt()) / 1000, digits: 4))
}}
#let chars = {chars}
#context [#metadata((
{rows}
))<metrics>]
"""
_STYLE_ARGS = {"regular": ("normal", "regular"), "bold": ("normal", "bold"), "italic": ("italic", "regular"),
               "bold-italic": ("italic", "bold")}


def build_table() -> dict:
    """Measure every character in every style with Typst (the shaper and font the PDFs use)."""
    import typst

    chars = "(" + ", ".join(json.dumps(c, ensure_ascii=False) for c in CHARACTERS) + ",)"
    rows = "\n".join(f'  "{name}": chars.map(c => m(c, "{s}", "{w}")),' for name, (s, w) in _STYLE_ARGS.items())
    source = _MEASURE.format(family=FAMILY, math_family=MATH_FAMILY, from_math=FROM_MATH, chars=chars, rows=rows)
    styles = typst.query(source.encode("utf-8"), "<metrics>", field="value", one=True, ignore_system_fonts=True)
    if isinstance(styles, str):
        styles = json.loads(styles)
    return {"family": FAMILY, "unit": "em", "characters": CHARACTERS,
            "columns": ["advance", "ink above baseline", "ink below baseline"], "styles": styles}


def write_table(path=None) -> None:
    target = path or resources.files(__package__).joinpath(TABLE)
    with open(target, "w", encoding="utf-8") as out:
        json.dump(build_table(), out, ensure_ascii=False, separators=(",", ":"))
        out.write("\n")


if __name__ == "__main__":
    write_table()
    print(f"wrote {TABLE}")
