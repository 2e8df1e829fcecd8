"""Math and prose for each output: LaTeX -> Typst, escaping, LaTeX -> Unicode."""
import json

import pytest
import typst

from exgen.figures.metrics import FAMILY
from exgen.render.mathtext import (UNIT_DOT, MathError, escape_markdown, escape_typst, latex_to_typst, split_math,
                                   text_to_markdown, text_to_typst, typst_string)
from exgen.render.unicode_math import latex_to_unicode, text_to_plain


@pytest.mark.parametrize("latex, expected", [
    (r"\operatorname{cosec}\theta", 'op("cosec") theta'),
    (r"\sin^{-1}\frac{r_2 - r_1}{X}", "sin^(-1) (r_2 - r_1)/X"),
    (r"\frac{T_1}{T_2}", "(T_1)/(T_2)"),
    (r"\frac{800}{2}", "800/2"),
    (r"T_{\mathrm{max}}", "T_upright(m a x)"),
    (r"v_{\mathrm{opt}}", "v_upright(o p t)"),
    (r"\omega_1", "omega_1"),
    (r"e^{\mu\,\theta}", "e^(mu thin theta)"),
    (r"\pi - 2\,\alpha", "pi - 2 thin alpha"),
    (r"0.25 \times 3.106", "0.25 times 3.106"),
    (r"\sqrt{\frac{T}{3\,m}}", "sqrt(T/(3 thin m))"),
    (r"\left\lceil \frac{P}{P_b} \right\rceil", "ceil(P/(P_b))"),
    (r"\Delta P / P", r"Delta P \/ P"),
    (r"d_{2,\max}", "d_(2, max)"),
    (r"\text{rpm}", '"rpm"'),
    (r"\alpha\beta\Omega", "alpha beta Omega"),
    ("", ""),
])
def test_latex_to_typst(latex, expected):
    assert latex_to_typst(latex) == expected


def test_bad_latex_names_the_math():
    with pytest.raises(MathError, match=r"\\frac\{a"):
        latex_to_typst(r"\frac{a")


@pytest.mark.parametrize("text, chunks", [
    ("no math", [(False, "no math")]),
    ("a $x_1$ b", [(False, "a "), (True, "x_1"), (False, " b")]),
    ("$a$$b$", [(True, "a"), (True, "b")]),
    (r"costs \$5 and $ y $", [(False, r"costs \$5 and "), (True, "y")]),
    ("one $ dollar", [(False, "one $ dollar")]),
])
def test_split_math(text, chunks):
    assert split_math(text) == chunks


@pytest.mark.parametrize("prose, escaped", [
    ("plain words, 3.5 m", "plain words, 3.5 m"),
    ("#set page", r"\#set page"),
    ("*bold* and _it_", r"\*bold\* and \_it\_"),
    ("a <label> @ref", r"a \<label\> \@ref"),
    ("[x] ~ `code`", r"\[x\] \~ \`code\`"),
    ("back\\slash", "back\\\\slash"),
    ("http://x // y /* z", r"http:/\/x /\/ y /\* z"),
    ("= heading", r"\= heading"),
    ("- item", r"\- item"),
    ("+ item", r"\+ item"),
    ("2. step", r"2\. step"),
    ("line\n- item", "line\n\\- item"),
    ("x-? y", r"x-\? y"),
    ("mm² N·m θ", f"mm² #box[N{UNIT_DOT}m] θ"),   # tight and unbroken, like the key's math N·m
    ("(kg·m²)", f"#box[(kg{UNIT_DOT}m²)]"),
    ("course · title", "course · title"),
])
def test_escape_typst(prose, escaped):
    assert escape_typst(prose) == escaped


def _units_with_a_slash():
    from exgen.load.bank import load_bank
    from exgen.units import pretty_unit

    shown = {pretty_unit(p.unit) for t in load_bank() for p in t.params if getattr(p, "unit", None)}
    return sorted(u for u in shown if "/" in u)


def test_no_unit_the_bank_prints_breaks_at_its_slash():
    """"4.5 kN/m" in a statement never ends a line at "kN/" with "m" on the next: set justified in columns
    of many widths, after words of many lengths, no line of any unit with a slash ends at the slash."""
    import io

    import pypdf

    units = _units_with_a_slash()
    assert {"kN/m", "m/s", "kg/m³", "N/mm", "km/h", "N·s/m"} <= set(units)
    body = "\n\n".join(escape_typst("x" * i + f" a spring of stiffness 4.5 {unit} is attached at B")
                        for unit in units for i in range(12))
    broken = []
    for width in range(40, 70, 2):
        source = (f'#set page(width: {width}mm, height: auto, margin: 1mm)\n#set par(justify: true)\n'
                  f'#set text(font: "{FAMILY}", size: 10pt)\n{body}').encode()
        pages = pypdf.PdfReader(io.BytesIO(typst.compile(source))).pages
        broken += [line for page in pages for line in page.extract_text().splitlines() if line.rstrip().endswith("/")]
    assert not broken, broken[:5]


@pytest.mark.parametrize("weight", ["regular", "bold"])
def test_a_units_dot_keeps_clear_of_its_letters_in_either_weight(weight):
    """The keys' Answers table sets units in bold: the dot of N·m must add width there as in the body text,
    never overlap the N (a fixed negative space that closes up the regular face's wide dot did)."""
    unit = escape_typst("kN·m")
    source = (f'#set text(font: "{FAMILY}", size: 10pt, weight: "{weight}")\n'
              f'#context [#metadata(measure[{unit}].width.pt() - measure[kNm].width.pt()) <m>]').encode()
    extra = json.loads(typst.query(source, "<m>", field="value", one=True))
    assert 1.0 < extra < 3.5   # points at 10 pt: a visible dot, set tight


def _flatten(node) -> str:
    """The characters a queried Typst content value shows."""
    if isinstance(node, list):
        return "".join(_flatten(n) for n in node)
    func = node.get("func")
    if func in ("text", "symbol"):
        return node["text"]
    if func == "space":
        return " "
    if func == "sequence":
        return _flatten(node["children"])
    raise AssertionError(f"unexpected markup in escaped text: {node}")


@pytest.mark.parametrize("prose", [
    "#let x = 1", "*not bold*", "_not italic_", "$not math$", "<not-a-label>", "@not-a-ref", "[not content]",
    "~ nbsp", "` raw`", r"back\slash", "// not a comment", "/* not a comment */", "= not a heading",
    "- not a list", "+ not an enum", "3. not numbered", "a -? b", "T_max = 2 kN",
])
def test_escaped_prose_typesets_as_itself(prose):
    source = f"#metadata[{escape_typst(prose)}] <m>".encode()
    value = json.loads(typst.query(source, "<m>", field="value", one=True))
    assert _flatten(value) == prose


@pytest.mark.parametrize("prose, shown", [
    ("A at (-100 mm, -190 mm)", "A at (−100 mm, −190 mm)"),   # Typst makes the second a minus by itself
    ("MN at -5° and [-3, 4]", "MN at −5° and [−3, 4]"),
    ("steps 2-60 mm, eqs 7.5-7.6, a-3", "steps 2-60 mm, eqs 7.5-7.6, a-3"),   # ranges and names keep their hyphen
])
def test_a_negative_number_is_set_with_a_minus_sign_wherever_it_stands(prose, shown):
    source = f"#metadata[{escape_typst(prose)}] <m>".encode()
    assert _flatten(json.loads(typst.query(source, "<m>", field="value", one=True))) == shown


@pytest.mark.parametrize("prose, escaped", [
    ("plain 3.5 m", "plain 3.5 m"),
    ("*a* _b_ `c`", r"\*a\* \_b\_ \`c\`"),
    ("[link](x) <tag> a|b", r"\[link\](x) \<tag\> a\|b"),
    ("costs $5", r"costs \$5"),
    ("# not a heading", r"\# not a heading"),
    ("- not a list", r"\- not a list"),
    ("1. not a list", r"1\. not a list"),
    ("a - b, a # b", "a - b, a # b"),
])
def test_escape_markdown(prose, escaped):
    assert escape_markdown(prose) == escaped


@pytest.mark.parametrize("text, typst_out, markdown_out, plain_out", [
    ("Use $g = 9.81$ m/s².", "Use $g = 9.81$ #box[m/s².]", "Use $g = 9.81$ m/s².", "Use g = 9.81 m/s²."),
    (r"Find $\theta_1$ for T_max", r"Find $theta_1$ for T\_max", r"Find $\theta_1$ for T\_max", "Find θ₁ for T_max"),
    (r"price \$5", r"price \$5", r"price \$5", "price $5"),
    (r"$\operatorname{cosec}\alpha$", '$op("cosec") alpha$', r"$\operatorname{cosec}\alpha$", "cosec α"),
])
def test_text_with_math_for_each_output(text, typst_out, markdown_out, plain_out):
    assert text_to_typst(text) == typst_out
    assert text_to_markdown(text) == markdown_out
    assert text_to_plain(text) == plain_out


@pytest.mark.parametrize("latex, expected", [
    (r"T_{\mathrm{max}}", "Tₘₐₓ"),
    (r"\operatorname{cosec}\theta", "cosec θ"),
    (r"\sin^{-1}\frac{r_2 - r_1}{X}", "sin⁻¹((r₂ − r₁)/X)"),
    (r"\frac{T_1}{T_2}", "T₁/T₂"),
    (r"e^{\mu\,\theta}", "e^(μθ)"),
    (r"\pi - 2\,\alpha", "π − 2α"),
    (r"\left\lceil \frac{P}{P_b} \right\rceil", "⌈P/P_b⌉"),
    (r"\sqrt{x}", "√x"),
    (r"-3.2 \times 10^{8}", "−3.2 × 10⁸"),
    (r"x^2 + y_{12}", "x² + y₁₂"),
    (r"\Delta P / P", "ΔP/P"),
    (r"\text{power}", "power"),
    # a fraction followed by a factor is bracketed, or written as a vulgar fraction: "1/2I" reads 1/(2I)
    (r"\tfrac{1}{2} I(\omega_1^2 - \omega_2^2)", "½I(ω₁² − ω₂²)"),
    (r"\tfrac{1}{2}(M g)\,IY", "½(Mg)IY"),
    (r"\frac{a}{b}\,c", "(a/b)c"),
    (r"\frac{F}{m r}\sin\theta", "(F/(mr)) sin θ"),
    (r"\frac{a}{b} + c", "a/b + c"),
    (r"\frac{1}{2} \times 3", "1/2 × 3"),
    (r"\frac{1}{2}3", "(1/2)3"),
    (r"\angle OAB_1", "∠OAB₁"),   # the actuator's key: the angle in triangle OAB
    (r"\unknowncommand", r"\unknowncommand"),
])
def test_latex_to_unicode(latex, expected):
    assert latex_to_unicode(latex) == expected


@pytest.mark.parametrize("text", ['<svg a="1">\n\\x</svg>', "tab\there", 'quote " and \\'])
def test_typst_string_round_trips(text):
    source = f"#metadata({typst_string(text)}) <m>".encode()
    assert json.loads(typst.query(source, "<m>", field="value", one=True)) == text
