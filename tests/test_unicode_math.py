"""Plain-text math over what templates write: no LaTeX command survives, no word of a text runs into the
next, and a fraction's bar is never left for the reader to guess (a/(2π), not a/2π)."""
import re

import pytest

from exgen.load.bank import load_bank
from exgen.load.mistake_messages import message_for
from exgen.render.text import variant_text
from exgen.render.unicode_math import latex_to_unicode, split_math, text_to_plain
from exgen.solve.variant import make_variant

TEMPLATE_IDS = sorted(t.id for t in load_bank())
LEFTOVER = re.compile(r"\\[A-Za-z]+|\\[^A-Za-z\s]")
COMMAND = re.compile(r"\\([A-Za-z]+)")
WORDS = {"sin", "cos", "tan", "cot", "sec", "csc", "cosec", "arcsin", "arccos", "arctan", "sinh", "cosh", "tanh",
         "ln", "log", "exp", "max", "min", "lim", "det"}  # commands that print as the word they are
TEXT_ARGUMENT = re.compile(r"\\(?:text|textrm|mathrm|mbox|operatorname)\{([^{}]*)\}")


def _math_sources(variant) -> list[str]:
    """Every piece of LaTeX a variant's outputs convert: math in its prose, and its working's symbols and formulas."""
    template = variant.template
    prose = [template.title, template.source, variant.statement, *variant.asks.values(),
             *(p.label for p in variant.params), *(s.note for s in variant.steps)]
    for part in template.parts:
        prose += [variant.fill(h) for h in part.hints]
        prose += [message_for(m.when, m.say) for m in part.mistakes]
    for table in variant.inserts:
        prose += [table.title, *(c for row in table.rows for c in row if isinstance(c, str))]
    math = [chunk for text in prose for is_math, chunk in split_math(text or "") if is_math]
    math += [s.symbol for s in variant.steps] + [p.symbol for p in variant.params]
    math += [re.sub(r"@(\w+)", lambda m: variant.param(m[1]).symbol if m[1] in variant.si else variant.step(m[1]).symbol,
                    s.formula) for s in variant.steps if s.formula]
    math += [c.head for table in variant.inserts for c in table.columns]
    return [m for m in math if m]


@pytest.mark.parametrize("template_id", TEMPLATE_IDS)
def test_every_template_text_converts_completely(bank, template_id):
    template = bank.get(template_id)
    for seed in (0, 1, 2):
        variant = make_variant(template, seed)
        key = variant_text(variant, key=True)
        hints = [text_to_plain(variant.fill(h)) for part in template.parts for h in part.hints]
        for text in [key, *hints]:
            assert not LEFTOVER.search(text), (seed, LEFTOVER.search(text)[0], text[:200])
        for latex in _math_sources(variant):
            plain = latex_to_unicode(latex)
            assert not LEFTOVER.search(plain), (seed, latex, plain)
            outside = COMMAND.sub(" ", latex)
            for name in set(COMMAND.findall(latex)) - WORDS:  # nor as a bare word: \ddot x as "ddotx"
                assert plain.count(name) <= outside.count(name), (seed, latex, plain)
            for words in TEXT_ARGUMENT.findall(latex):
                if len(words.split()) > 1:  # a text of several words keeps its spaces
                    assert " ".join(words.split()) in plain, (seed, latex, plain)


@pytest.mark.parametrize("latex, expected", [
    (r"\text{spring in tension}", "spring in tension"),
    (r"\text{sense} = \text{counter-clockwise}", "sense = counter-clockwise"),  # a hyphen, not a minus
    (r"\text{the {first} idler's}", "the first idler's"),
    (r"T_{\text{in out}}", "T_(in out)"),  # a space stops the letters being set as subscripts
    (r"\int_0^{2\pi} T\,d\theta", "∫₀^(2π)Tdθ"),
    (r"m\ddot{x} + K x = 0", "mẍ + Kx = 0"),
    (r"\angle OAB_1", "∠OAB₁"),
    (r"\sqrt[3]{x}", "∛x"),
    (r"\left. \frac{a}{b} \right|_0", "a/b|₀"),
    (r"\unknowncommand", r"\unknowncommand"),  # a gap in the table shows
])
def test_latex_to_unicode_covers(latex, expected):
    assert latex_to_unicode(latex) == expected


@pytest.mark.parametrize("latex, expected", [
    (r"\frac{a}{2\pi}", "a/(2π)"),            # not (a/2)π
    (r"\frac{T}{I\,\alpha}", "T/(Iα)"),
    (r"\frac{a}{1.2 \times 10^{5}}", "a/(1.2 × 10⁵)"),
    (r"\frac{a}{-2}", "a/(−2)"),
    (r"\frac{a}{\sin\theta}", "a/(sin θ)"),
    (r"\frac{a}{\text{time taken}}", "a/(time taken)"),
    (r"\frac{a+b}{c}", "(a + b)/c"),
    (r"\frac{1}{2} I\omega^2", "½Iω²"),    # not 1/(2Iω²)
    (r"\frac{1}{2} 3", "(1/2)3"),
    (r"\omega_1 \frac{d_1}{d_2} (1 - G)", "ω₁(d₁/d₂)(1 − G)"),
    (r"\sqrt{a\,b}", "√(ab)"),
    # one factor, or a product over one, needs nothing
    (r"\frac{2\pi N}{60}", "2πN/60"), (r"\frac{T_1}{T_2}", "T₁/T₂"), (r"\frac{x}{\omega_{\mathrm{max}}^2}", "x/ωₘₐₓ²"),
    (r"\frac{N}{\left(a + b\right)}", "N/(a + b)"), (r"\frac{(-800)}{1.46}", "(−800)/1.46"), (r"\sqrt{x}", "√x"),
    (r"\frac{a}{b} \times c", "a/b × c"),
])
def test_a_fraction_reads_one_way(latex, expected):
    assert latex_to_unicode(latex) == expected
