"""Shared by the export tests: a pool of every template, the QTI schema, and a reader of Moodle's cloze
syntax written from the format's documentation (a gap is {weight:TYPE:alternative~alternative...}; an
alternative is [= or %n%]answer[#feedback]; an answer ends at an unescaped # ~ or }, a feedback at an
unescaped ~ or }; both are entity-decoded once on import)."""
from __future__ import annotations

import html
import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from exgen.export.filters import number
from exgen.export.pool import build_pool
from exgen.load.bank import load_bank

SCHEMAS = Path(__file__).parent / "schemas" / "qti21-catalog"
SECRET = b"0123456789abcdef-export-tests-secret"
VARIANTS = 2


def written(value: float) -> float:
    """A value as an export writes it (exgen.export.filters.number), read back."""
    return float(number(value))


@lru_cache(maxsize=1)
def every_template_pool():
    """Every template of the bank, VARIANTS variants each: the pool every export test checks."""
    bank = load_bank()
    specs = [(f"q{n}", t, t.points) for n, t in enumerate(bank, start=1)]
    return build_pool("Every template", "pool", specs, SECRET, VARIANTS)


@lru_cache(maxsize=1)
def qti_schema():
    """imsqti_v2p1.xsd and its imports, from the vendored copies only (no network)."""
    from lxml import etree

    class Vendored(etree.Resolver):
        def resolve(self, url, pubid, context):
            if url.startswith(("http://", "https://")):
                local = SCHEMAS / url.split("://", 1)[1]
                if local.is_file():
                    return self.resolve_filename(str(local), context)
                raise OSError(f"schema not vendored: {url}")
            return None

    parser = etree.XMLParser(no_network=True, resolve_entities=False)
    parser.resolvers.add(Vendored())
    return etree.XMLSchema(etree.parse(str(SCHEMAS / "www.imsglobal.org/xsd/imsqti_v2p1.xsd"), parser))


# ---- Moodle cloze ------------------------------------------------------------------------------

TYPES = {"NUMERICAL": "numerical", "NM": "numerical", "MULTICHOICE": "multichoice", "MC": "multichoice",
         "SHORTANSWER": "shortanswer", "SA": "shortanswer"}
NUMBER = re.compile(r"-?(?:[0-9]+[.,]?[0-9]*|[.,][0-9]+)(?:[eE][-+]?[0-9]+)?")
_START = re.compile(r"\{([0-9]*):([A-Z_]+):")


@dataclass
class Alternative:
    fraction: float
    answer: str
    feedback: str
    tolerance: float | None = None


@dataclass
class Subquestion:
    weight: int
    qtype: str
    alternatives: list


def _until(text: str, i: int, stops: str, guards: tuple[str, ...]) -> int:
    """The index of the first character in `stops` from i that no guard (a preceding text) escapes."""
    while i < len(text):
        if text[i] in stops and not any(text[:i].endswith(g) for g in guards):
            return i
        i += 1
    return i


def cloze_subquestions(text: str) -> list[Subquestion]:
    """Every gap of a cloze question text, as Moodle's importer would read it."""
    found, at = [], 0
    while True:
        match = _START.search(text, at)
        if not match:
            return found
        qtype = TYPES.get(match.group(2))
        assert qtype, f"unknown cloze type {match.group(2)}"
        i, alternatives = match.end(), []
        while True:
            fraction = 0.0
            if text.startswith("=", i):
                fraction, i = 1.0, i + 1
            elif text.startswith("%", i):
                end = text.index("%", i + 1)
                fraction, i = float(text[i + 1:end].replace(",", ".")) / 100, end + 1
            end = _until(text, i, "#~}", ("\\", "&", "&amp;"))
            answer, feedback = text[i:end], ""
            i = end
            if text.startswith("#", i):
                end = _until(text, i + 1, "~}", ("\\",))
                feedback, i = text[i + 1:end], end
            answer = html.unescape(answer).replace("\\}", "}").replace("\\#", "#")
            feedback = html.unescape(feedback).replace("\\}", "}").replace("\\#", "#")
            alternative = Alternative(fraction, answer, feedback)
            if qtype == "numerical" and answer != "*":
                value, _, tol = answer.partition(":")
                assert NUMBER.fullmatch(value) and (not tol or NUMBER.fullmatch(tol)), answer
                alternative.answer, alternative.tolerance = value, float(tol or 0)
            alternatives.append(alternative)
            assert i < len(text), "a gap is not closed"
            if text[i] == "}":
                break
            i += 1  # past "~"
        found.append(Subquestion(int(match.group(1) or 1), qtype, alternatives))
        at = i + 1
