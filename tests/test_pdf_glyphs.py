"""Every character the bank prints in a sheet's or key's prose has a glyph in the face it is set in.

Typst falls back to a font of its own for a character the body face lacks (New Computer Modern's italic
has no ≈, and no diaeresis over θ), and the PDF then shows that character in another typeface. The
prose of every template over many seeds is gathered (statements, asks, givens' labels in the upright
face, and the key's answers; the worked solution's notes and the answer hints in italic) and set through the sheets' own preamble, where show rules
send what the face lacks (primes, script digits) to the math face or the body's digits.
"""
from __future__ import annotations

import os
import re

from exgen.answertypes import answer_type
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.pdf import compile_pdf, key_typst
from exgen.render.mathtext import escape_typst
from exgen.solve.variant import make_variant

SEEDS = range(int(os.environ.get("EXGEN_GLYPH_SEEDS", "12")))
MATH = re.compile(r"\$[^$]*\$")
CLUSTER = re.compile(r".[\u0300-\u036f]*", re.DOTALL)
FACES = {"NewCM10", "NewCMMath"}


def _clusters(text: str) -> set[str]:
    """The non-ASCII characters (with their combining marks) of a text's prose, its $math$ left out."""
    return {c for c in CLUSTER.findall(MATH.sub(" ", text)) if not c.isascii() and not c.isspace()}


def _printed(bank) -> dict[str, dict[str, str]]:
    """For the upright and the italic face: each character printed in it, and one place it comes from."""
    faces: dict[str, dict[str, str]] = {"upright": {}, "italic": {}}
    for template in bank:
        for seed in SEEDS:
            variant = make_variant(template, seed)
            where = f"{template.id} seed {seed}"
            upright = [variant.statement, *variant.asks.values(), *(p.label for p in variant.params),
                       *(a.text for a in variant.answers.values())]
            for text in upright:
                for c in _clusters(text or ""):
                    faces["upright"].setdefault(c, where)
            for step in variant.steps:
                for c in _clusters(step.note or ""):
                    faces["italic"].setdefault(c, f"{where}, the note of {step.name}")
        for part in template.parts:
            for c in _clusters(answer_type(part).hint(part)):
                faces["italic"].setdefault(c, f"{template.id}, the answer hint of ({part.id})")
    return faces


def _base(bank) -> str:
    template = next(iter(bank))
    sheet = build_sheet(Assignment(id="g", title="G", questions=(QuestionSpec("q1", template.id),)),
                        Student("s1"), bank, b"k" * 32)
    return key_typst(sheet)


def _families(source: str) -> set[str]:
    pdf = compile_pdf(source)
    return {name.decode().split("+", 1)[-1].split("-")[0] for name in re.findall(rb"/BaseFont\s*/([A-Za-z0-9+-]+)", pdf)}


def _set(face: str, clusters) -> str:
    body = " ".join(escape_typst(c) for c in sorted(clusters))
    return f'\n#text(style: "{"italic" if face == "italic" else "normal"}")[{body}]\n'


def test_every_printed_character_is_in_the_face_it_is_set_in(bank):
    base = _base(bank)
    assert _families(base) <= FACES  # the base key itself is one family
    printed = _printed(bank)
    assert printed["upright"] and printed["italic"]
    missing = []
    for face, clusters in printed.items():
        if _families(base + _set(face, clusters)) <= FACES:
            continue
        for c in sorted(clusters):  # only on failure: which characters, and where each comes from
            if not _families(base + _set(face, [c])) <= FACES:
                missing.append(f"{c!r} (U+{ord(c[0]):04X}) in {face} text, from {clusters[c]}")
    assert missing == []
