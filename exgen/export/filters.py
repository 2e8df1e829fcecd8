"""Small filters the export layouts use to write values exactly as each format reads them."""
from __future__ import annotations

import base64
import math
from fractions import Fraction

from markupsafe import Markup, escape

#: Characters that end or start a Moodle cloze answer or feedback, written as character references:
#: the importer reads up to them before it decodes entities (qtype_multianswer_extract_question).
_CLOZE = {"}": "&#125;", "{": "&#123;", "~": "&#126;", "#": "&#35;"}


#: Significant figures a learning system is given: rounding to 12 moves a value by at most 5e-13 of itself,
#: far inside any tolerance a part grades with, and drops the 16th and 17th figures where the binary
#: noise of arithmetic shows (1500 × 27/60 computes as 675.0000000000002, 0.345 as 0.34500000000000003).
SIGNIFICANT = 12


def number(value) -> str:
    """The value to SIGNIFICANT figures, in the shortest text that reads back as that ("12.5",
    "0.00125", "1e-05", "675" for 675.0000000000002); whole numbers without a decimal point."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{value!r} is not a number a learning system can store")
    value = float(f"{value:.{SIGNIFICANT}g}")
    if value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return repr(value)


def cloze(html) -> Markup:
    """HTML for a Moodle cloze answer or feedback: escaped once more (the importer decodes entities
    once before storing it as HTML) and with { } ~ # as references, so the gap's syntax stays intact."""
    text = str(escape(str(html)))
    return Markup("".join(_CLOZE.get(ch, ch) for ch in text))


def sentence(text: str) -> str:
    """'not within 1 %' -> 'Not within 1 %.'"""
    text = str(text).strip()
    return text[:1].upper() + text[1:] + ("" if text.endswith((".", "!", "?")) or not text else ".")


def as_text(html) -> str:
    """HTML as plain text to be escaped where it is written (XML that carries HTML as a string)."""
    return str.__str__(html)


def b64(text: str) -> str:
    return base64.b64encode(text.encode("utf-8")).decode("ascii")


def category(name: str) -> str:
    """A name inside a Moodle category path, where '/' separates levels and '//' is a slash."""
    return " ".join(str(name).split()).replace("/", "//")


def fraction(value: Fraction | float) -> str:
    return number(float(value))


def moodle_units(accepted) -> list[tuple[str, float]]:
    """A numerical question's (unit name, multiplier) pairs as Moodle can match them. Moodle deletes every
    space from a response before it splits off the unit (qtype_numerical_answer_processor::apply_units)
    and then looks the rest up exactly, so "1.2 kN m" arrives as unit "kNm": a name with a space could
    never match. Each name is written without its spaces, and with '*' for them too ("kN*m"); the first
    of two names that come out the same is kept."""
    out: dict[str, float] = {}
    for name, multiplier in accepted:
        for written in ("".join(name.split()), "*".join(name.split())):
            out.setdefault(written, multiplier)
    return list(out.items())


FILTERS = {"num": number, "cloze": cloze, "b64": b64, "category": category, "fraction": fraction, "sentence": sentence,
           "text": as_text, "moodle_units": moodle_units}
