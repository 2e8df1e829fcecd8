"""LaTeX to MathML for the browser: every template's text and worked solution converts, to well-formed
MathML with nothing left as raw LaTeX; prose is escaped and text inside math cannot break out."""
import re
import xml.etree.ElementTree as ElementTree

import pytest

from exgen.issue.assignment import Question
from exgen.load.bank import load_bank
from exgen.render.context import question_context
from exgen.render.html import HTML
from exgen.render.mathml import latex_to_mathml
from exgen.render.mathtext import MathError
from exgen.solve.variant import make_variant

TEMPLATE_IDS = sorted(t.id for t in load_bank())
SEEDS = (0, 2**64 + 1, 2**64 + 77)  # one sheet seed, two from the practice range


def strings(value):
    """Every text of a layout's context; a given's symbol is LaTeX the layout writes as inline math."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from strings(HTML.inline(item) if key == "symbol" else item)
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from strings(item)


def check_html(fragment: str) -> int:
    """The fragment parses as XML (MathML inside escaped prose) and holds no LaTeX command; returns how
    many <math> elements it has."""
    root = ElementTree.fromstring(f"<div><p>{fragment}</p></div>")  # text() separates paragraphs with </p><p>
    for node in root.iter():
        assert not (node.text or "").lstrip().startswith("\\"), ElementTree.tostring(node, encoding="unicode")
    text = "".join(root.itertext())
    assert not re.search(r"\\(frac|text|mathrm|sqrt|left|right|omega|theta|alpha|times|circ)\b", text), text
    return sum(1 for node in root.iter() if node.tag == "math")


@pytest.mark.parametrize("template_id", TEMPLATE_IDS)
def test_every_statement_ask_and_worked_line_converts_to_mathml(bank, template_id):
    maths = 0
    for seed in SEEDS:
        variant = make_variant(bank.get(template_id), seed)
        context = question_context(Question(1, "q1", variant, variant.template.points), HTML, None, None, key=True)
        for fragment in strings(context):
            maths += check_html(str(fragment))
    assert maths > 0


def test_a_display_line_is_a_block_with_a_fraction_and_a_text_alternative():
    out = latex_to_mathml(r"\omega_2 = \omega_1\,\frac{d_1}{d_2}", display=True)
    assert out.startswith('<math alttext="ω₂ = ω₁d₁/d₂" display="block">') and "<mfrac>" in out


@pytest.mark.parametrize("latex", [r"\text{a < b & c > d}", r"\text{<script>alert(1)</script>}"])
def test_text_inside_math_is_escaped(latex):
    out = latex_to_mathml(latex)
    ElementTree.fromstring(out)
    assert "<script" not in out and "&lt;" in out


@pytest.mark.parametrize("latex", [r"\frac{a}{", r"x^", r"\nosuchcommand{x}"])
def test_latex_the_converter_cannot_read_is_an_error_naming_it(latex):
    with pytest.raises(MathError, match=re.escape(repr(latex))):
        latex_to_mathml(latex)


def test_prose_is_escaped_and_math_spans_become_mathml():
    out = str(HTML.text('Tension <b>"T"</b> & $T_1 > T_2$ costs \\$5.\n\nNext.'))
    assert out.startswith("Tension &lt;b&gt;&#34;T&#34;&lt;/b&gt; &amp; <math")
    assert "costs $5.</p><p>Next." in out
