"""The notation of keys and messages, checked over the whole bank: one minus sign (U+2212) in typeset
text, products of a compound symbol bracketed, subscripts that cannot run into the next symbol."""
import re

from exgen.render.text import variant_text
from exgen.solve.variant import make_variant

SEEDS = range(6)
#: A hyphen-minus standing as a sign: before a digit, after no word, number or closing bracket.
HYPHEN_SIGN = re.compile(r"(?<![\w.)\]\-\u2080-\u2089\u2070-\u2079])-(?=\.?\d)")


def test_plain_keys_write_every_negative_number_with_the_minus_sign(bank):
    """'-1512' beside '(−1512.5)' mixed the two: the statement, the working, its notes and tables and the
    answers of every key use U+2212 alone."""
    found = []
    for template in bank:
        for seed in SEEDS:
            text = variant_text(make_variant(template, seed), key=True)
            for line in text.splitlines():
                if HYPHEN_SIGN.search(line):
                    found.append((template.id, seed, line.strip()))
    assert not found, (len(found), found[:6])


def test_a_slider_crank_s_figure_says_where_the_slider_is_in_english(bank):
    """'the slider below of the crank pivot' in the figure's description (the key's and QTI's alt text)."""
    from exgen.figures import figure_svg

    template = bank.get("linkages.slider_crank")
    seen = {}
    for seed in range(200):
        variant = make_variant(template, seed)
        svg = figure_svg(variant)
        title = re.search(r"<title[^>]*>([^<]*)</title>", svg) or re.search(r'aria-label="([^"]*)"', svg)
        text = title.group(1) if title else svg
        seen[re.search(r"slider (to the right of|to the left of|below|above|\w+ of)", text).group(1)] = text
        assert not re.search(r"\b(below|above) of\b", text), text
    assert {"to the right of", "to the left of", "below", "above"} <= set(seen), seen


def test_a_symbol_that_is_a_fraction_is_bracketed_as_a_factor(bank):
    """'v₂ = vv₂/v₁' read as v times v₂ over v₁: a step whose symbol is a ratio stands in brackets beside
    another factor, v(v₂/v₁), in every key's formulas."""
    from exgen.render.solution import solution
    from exgen.render.targets import PLAIN
    from exgen.render.unicode_math import latex_to_unicode

    found, seen = [], 0
    for template in bank:
        for seed in range(2):
            variant = make_variant(template, seed)
            for line in solution(variant).lines:
                if line.formula is None:
                    continue
                text = " ".join(PLAIN.terms(line.formula))
                for symbol in line.formula.fills:
                    if isinstance(symbol, str) and symbol.startswith(r"\frac") and len(line.formula.fills) > 1:
                        seen += 1
                        plain = latex_to_unicode(symbol)
                        if re.search(rf"(?<![(|\s=+−-]){re.escape(plain)}|{re.escape(plain)}(?![)|\s=+−-]|$)", text):
                            found.append((template.id, text))
    assert seen and not found, found[:5]


def test_a_double_prime_is_one_symbol_in_the_pdf(bank):
    """P'' was set as "P ′ ′" (Typst math P^(' ')): every step symbol with primes is written with Typst's
    own primes, before any subscript."""
    from exgen.render.mathtext import latex_to_typst

    symbols = {s.symbol for t in bank for s in make_variant(t, 1).steps if s.symbol and "''" in s.symbol}
    assert symbols
    for symbol in symbols | {"T_2''", "P'''"}:
        typst = latex_to_typst(symbol)
        assert not re.search(r"'\s+'", typst) and "^(" not in typst, (symbol, typst)


def test_a_one_letter_subscript_never_runs_into_the_next_symbol(bank):
    """'m_Bb²' read as m with subscript Bb: a subscript without a Unicode form is set off by a space when a symbol
    follows it directly (m_B b²), in every plain key."""
    found = []
    for template in bank:
        for seed in SEEDS[:3]:
            for line in variant_text(make_variant(template, seed), key=True).splitlines()[1:]:  # not the id
                if re.search(r"(?<![\w.])[^\W\d_]_[A-Za-z0-9](?=[A-Za-z0-9\u0370-\u03ff])", line):
                    found.append((template.id, seed, line.strip()))
    assert not found, (len(found), found[:5])


def test_no_label_in_the_working_reads_as_a_part(bank):
    """The epicyclic table's rows were (a), (b), (c) beside the parts (a)-(d): in every key's working and
    tables, a letter in brackets is a part's marker at the end of its line, never a row, symbol or note."""
    from exgen.render.text import key_lines

    found = []
    for template in bank:
        for seed in SEEDS[:3]:
            lines = key_lines(make_variant(template, seed))
            for line in lines[lines.index("Worked solution") + 1:lines.index("Answers")]:
                body = re.sub(r"(\s+\([a-z]\))+$", "", line)
                if re.search(r"\([a-h]\)", body):
                    found.append((template.id, seed, body.strip()))
    assert not found, (len(found), found[:5])


def test_every_symbol_a_worked_line_uses_is_defined_before(bank):
    """R₀ and R₉₀ stood in √(R₀² + R₉₀²) with no line of their own (the table's sums): every value a
    formula names is a given, an earlier line, or said in words by an earlier (or its own) line's note,
    in every key."""
    from exgen.render.solution import solution
    from exgen.render.unicode_math import latex_to_unicode, text_to_plain

    found = []
    for template in bank:
        for seed in SEEDS[:3]:
            variant = make_variant(template, seed)
            worked = solution(variant)
            known = {g.name for g in worked.given} | {p.name for p in variant.params}
            said = ""
            for line in worked.lines:
                said += " " + text_to_plain(line.note)
                if line.formula is not None:
                    for slot, symbol in zip(line.formula.formula.slots, line.formula.fills):
                        if slot.name not in known and latex_to_unicode(symbol) not in said:
                            found.append((template.id, seed, slot.name, latex_to_unicode(symbol)))
                known.add(line.name)
    assert not found, (len(found), sorted(set((f[0], f[3]) for f in found))[:10])


def test_the_points_a_governor_s_moments_are_taken_about_are_said_in_words(bank):
    """The Porter keys named I, Z and Y, which their figures do not mark: every key whose working takes
    moments about I says what X, I, Z and Y are, on or before the first line that names them."""
    from exgen.render.solution import solution
    from exgen.render.unicode_math import latex_to_unicode, text_to_plain

    checked = 0
    for template in bank:
        for seed in SEEDS[:2]:
            said = ""
            for line in solution(make_variant(template, seed)).lines:
                said += " " + text_to_plain(line.note)
                symbol = latex_to_unicode(line.symbol)
                if re.match(r"(XZ|IZ|IY|ZY)", symbol) or "about I" in said:
                    checked += 1
                    drawn = "XY" if "pivot C" in said else ""  # a Proell figure marks B and C itself
                    assert "instantaneous centre" in said and all(f"{p} is" in said or f"{p}," in said or
                                                                   f"pivot {p}" in said for p in "XIZY" if p not in drawn), \
                        (template.id, seed, symbol, said)
                    break
    assert checked
