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
