"""Strategies for fuzzing what students type and hand in (shared by tests/test_fuzz.py and benchmarks/fuzz.py).

Answer text: anything at all; quantity-like text built from the pieces students (and attackers) use:
unicode digits and minus signs, NBSP and thin spaces, RTL and zero-width marks, huge exponents, powers
of units, nested brackets; shapes of the other answer types (a size at an angle, choices, formulas);
and very long strings. Files: YAML, JSON and CSV documents of nested data holding such text, and bytes.
"""
from __future__ import annotations

import json

from hypothesis import strategies as st

DIGITS = "0123456789\u0660\u0661\u06f5\u0966\u096f\uff10\uff15\uff19\U0001d7ce\u00b2\u00b3\u00b9\u2070\u2079\u00bd"
MINUS = ["-", "+", "\u2212", "\u2013", "\u2012", "\u2010", "\ufe63", "\uff0d", "--", "+-", ""]
SPACES = ["", " ", "  ", "\u00a0", "\u2009", "\u202f", "\t", "\u3000", "\u200b"]
MARKS = ["", "\u200e", "\u200f", "\u202e", "\u202d", "\u2066", "\u2069", "\u061c", "\ufeff", "\u00ad", "\u0301"]
UNITS = ["", "N", "kN", "MN/m^2", "N*m", "N·m", "N⋅m", "kg m", "kg·mm", "kg*m^2", "m/s", "m/s²", "m/s^2", "rpm",
         "rev/min", "rad/s", "Hz", "deg", "°", "º", "rad", "%", "percent", "mm", "m", "cm", "in", "ft", "lbf",
         "kW", "W", "hp", "J", "kg", "g", "s", "min", "1/s", "s^-1", "m^9^9", "m**99", "m^(1/2)", "degC", "K",
         "µm", "μm", "Ω", "[length]", "__class__", "m.__class__", "m;N", "m)", "(m", "N m s kg A K mol cd"]
EXPONENTS = ["", "e3", "E-3", "e+308", "e309", "e-400", "e999999", "e", "E+", "×10^3", "x10^-3", "*10**5",
             " × 10⁻³", "e\u2212" + "3", "×10^999"]
WORDS = ["at", "@", "∠", "<", "remove", "add", "take away", "subtract", "open", "crossed", "clockwise",
         "counter-clockwise", "anticlockwise", "increase", "decrease", "same way", "opposite", "ccw", "cw"]
FORMULA_PIECES = ["K", "M", "m", "2", "3.5", "pi", "π", "sqrt(", "sin(", "exp(", "ln(", "log(", "(", ")",
                  "+", "-", "*", "/", "^", "**", "√", "²", "e", "1e308", "__import__", "os", "lambda", "x",
                  ",", " ", "⁻¹", "[", "]", "{", "}", "'", '"']


def number_text() -> st.SearchStrategy[str]:
    digits = st.text(alphabet=DIGITS + ".,_ ", min_size=0, max_size=14)
    return st.builds(lambda sign, d, e: f"{sign}{d}{e}", st.sampled_from(MINUS), digits, st.sampled_from(EXPONENTS))


def quantity_text() -> st.SearchStrategy[str]:
    """Numbers with units, spaces and invisible marks in between, optionally labelled ("θ = ...")."""
    return st.builds(
        lambda label, mark1, number, space, mark2, unit, tail: f"{label}{mark1}{number}{space}{mark2}{unit}{tail}",
        st.sampled_from(["", "θ = ", "T1=", "x =", "answer: "]), st.sampled_from(MARKS), number_text(),
        st.sampled_from(SPACES), st.sampled_from(MARKS), st.sampled_from(UNITS),
        st.sampled_from(["", " ", "\n", "\r\n", "\x00", ".", "?", " ok", " approx"]))


def shaped_text() -> st.SearchStrategy[str]:
    """Text in the shapes of the other answer types: a size at an angle, a choice, a formula."""
    polar = st.builds(lambda w, a, at, b: f"{w} {a} {at} {b}".strip(), st.sampled_from(["", "remove", "add"]),
                      quantity_text(), st.sampled_from(WORDS[:4]), quantity_text())
    choice = st.lists(st.sampled_from(WORDS), min_size=1, max_size=4).map(" ".join)
    formula = st.lists(st.sampled_from(FORMULA_PIECES), min_size=1, max_size=40).map("".join)
    return st.one_of(polar, choice, formula)


def long_text() -> st.SearchStrategy[str]:
    """Huge strings: a megabyte of digits, brackets, marks or words."""
    unit = st.sampled_from(["9", "(", ")", "\u202e", "m/", "x ", "1e9", "^9", "sqrt(", "\u0301", "é", " "])
    return st.builds(lambda u, n, head: head + u * n, unit, st.integers(300, 1_000_000),
                     st.sampled_from(["", "5 ", "remove ", "K*"]))


def answer_text() -> st.SearchStrategy[str]:
    return st.one_of(st.text(max_size=120), quantity_text(), shaped_text())


# ---- files ---------------------------------------------------------------------------------------

def _value(depth: int = 0):
    leaf = st.one_of(answer_text(), st.none(), st.booleans(), st.integers(), st.floats(allow_nan=True))
    if depth >= 3:
        return leaf
    return st.one_of(leaf, st.lists(_value(depth + 1), max_size=4),
                     st.dictionaries(st.text(max_size=12), _value(depth + 1), max_size=4))


def answer_data():
    """Data shaped like an answer file (header and answers) or not at all."""
    answers = st.dictionaries(st.sampled_from(["q1", "q2", "1", "Q1", "(a)", "x"]) | st.text(max_size=8),
                              st.dictionaries(st.sampled_from(["a", "b", "(c)", "d"]) | st.text(max_size=6),
                                              _value(2), max_size=5) | _value(2), max_size=4)
    shaped = st.fixed_dictionaries({"student": answer_text() | st.just("s001"), "answers": answers},
                                   optional={"code": answer_text(), "assignment": answer_text()})
    return st.one_of(shaped, _value(0))


def _yaml(data) -> str:
    import yaml

    return yaml.safe_dump(data, allow_unicode=True)


def _csv(data) -> str:
    rows = []
    if isinstance(data, dict):
        for slot, parts in (data.get("answers") or {}).items() if isinstance(data.get("answers"), dict) else []:
            for part, text in (parts.items() if isinstance(parts, dict) else [("a", parts)]):
                rows.append(f"{slot},{part},{text}")
    return "\n".join(rows)


def answer_file() -> st.SearchStrategy[tuple[str, bytes]]:
    """(suffix, bytes): a YAML, JSON or CSV rendering of answer-like data, a mangled one, or raw bytes."""
    def render(kind_data):
        kind, data, cut = kind_data
        text = {"yaml": _yaml, "json": lambda d: json.dumps(d, ensure_ascii=False), "csv": _csv}[kind](data)
        if cut:
            text = text[: len(text) * cut // 8]
        return (f".{kind}", text.encode("utf-8", "surrogatepass"))

    rendered = st.tuples(st.sampled_from(["yaml", "json", "csv"]), answer_data(), st.integers(0, 8)).map(render)
    raw = st.tuples(st.sampled_from([".yaml", ".json", ".csv"]), st.binary(max_size=400))
    return st.one_of(rendered, rendered, raw)
