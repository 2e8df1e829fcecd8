"""The worked solution as data, and the per-format quantity writers it relies on."""
from decimal import Decimal
from types import SimpleNamespace

import pytest

from exgen.derivation import Step
from exgen.render.solution import si_unit, solution
from exgen.render.targets import MARKDOWN, PLAIN, TYPST, number_parts
from exgen.template import PartSpec
from exgen.variant import Answer, ParamValue, make_variant


def fake_variant(steps, params=(), parts=(), answers=None):
    template = SimpleNamespace(id="test.fake", parts=tuple(parts))
    return SimpleNamespace(template=template, steps=tuple(steps), params=tuple(params), answers=answers or {})


def param(name, exact, unit, si, symbol=""):
    return ParamValue(name, Decimal(exact), unit, si, "", symbol or name)


@pytest.mark.parametrize("unit, expected", [
    ("mm", "m"), ("rpm", "rad/s"), ("kN", "N"), ("MN/m^2", "N/m^2"), ("kW", "W"), ("deg", "rad"),
    ("percent", ""), ("kg/m", "kg/m"), ("mm^2", "m^2"), ("not-a-unit", None),
])
def test_si_unit(unit, expected):
    assert si_unit(unit) == expected


def test_given_shows_si_only_when_it_differs():
    variant = fake_variant([], [param("N1", "570", "rpm", 59.69026041820607, r"\omega_1"),
                                param("X", "2.8", "m", 2.8), param("mu", "0.25", "", 0.25),
                                param("G", "2", "percent", 0.02)])
    given = {g.name: g for g in solution(variant).given}
    assert given["N1"].printed == "570 rpm" and given["N1"].si_text == "59.69 rad/s"
    assert given["N1"].symbol == r"\omega_1"
    assert given["X"].si_text is None and given["mu"].si_text is None
    assert given["G"].si_text == "0.02"


def test_lines_show_formula_substitution_value_and_answer_in_the_asked_unit():
    part = PartSpec("a", "the angle", "theta", unit="deg")
    steps = [Step("alpha", r"\alpha", "", 0.0178581, "rad"),
             Step("theta", r"\theta", r"\pi - 2\,@alpha", 3.1058765, "rad", note="on the smaller pulley")]
    answer = Answer(part, 177.9536, 3.1058765, steps[1])
    variant = fake_variant(steps, parts=[part], answers={"a": answer})
    alpha, theta = solution(variant).lines
    assert alpha.formula == "" and alpha.substituted == "" and alpha.parts == ()
    assert theta.formula == r"\pi - 2\,\alpha"
    assert theta.substituted == r"\pi - 2 \times 0.01786"
    assert theta.parts == ("a",) and theta.asked == ((177.9536, "deg"),)
    assert " = ".join(theta.chain(PLAIN)) == "θ = π − 2α = π − 2 × 0.01786 = 3.106 rad = 178.0°"
    assert theta.chain(TYPST)[-1] == '178.0"°"'
    assert theta.chain(MARKDOWN)[-2:] == [r"3.106\ \text{rad}", r"178.0^{\circ}"]


def test_substitution_is_skipped_when_it_adds_nothing():
    steps = [Step("T1", "T_1", "@T_max", 2800.0, "N"), Step("k", "k", r"\pi/2", 1.5707963, ""),
             Step("s", "s", "@T1 + 0", 2800.0, "N")]
    variant = fake_variant(steps, [param("T_max", "2.8", "kN", 2800.0, r"T_{\mathrm{max}}")])
    t1, k, s = solution(variant).lines
    assert t1.formula == r"T_{\mathrm{max}}" and t1.substituted == ""
    assert k.formula == r"\pi/2" and k.substituted == ""
    assert s.substituted == "2800 + 0"


def test_integer_and_word_values():
    parts = [PartSpec("a", "belts", "n", type="integer"), PartSpec("b", "more or less", "trend", type="choice",
                                                                    options={"choices": ("increase", "decrease")})]
    steps = [Step("n", "n", r"\left\lceil @x \right\rceil", 4, ""), Step("trend", r"\text{power}", "", "increase")]
    answers = {"a": Answer(parts[0], 4, 4, steps[0]), "b": Answer(parts[1], "increase", "increase", steps[1])}
    variant = fake_variant(steps, [param("x", "3.2", "", 3.2)], parts, answers)
    n, trend = solution(variant).lines
    assert n.chain(PLAIN) == ["n", "⌈x⌉", "⌈3.2⌉", "4"] and n.asked == ()
    assert trend.chain(PLAIN) == ["power", "increase"]
    assert trend.chain(MARKDOWN)[-1] == r"\text{increase}"
    assert trend.chain(TYPST)[-1] == '"increase"'


def test_a_value_that_writes_itself_as_latex_is_shown_as_math():
    class Formula:
        def latex(self):
            return r"\frac{1}{2\pi}\sqrt{\frac{K}{M}}"

    latex = Formula().latex()
    (line,) = solution(fake_variant([Step("f_expr", "f_n", "", Formula(), "")])).lines
    assert line.chain(MARKDOWN) == ["f_n", latex]
    assert line.chain(TYPST)[-1] == TYPST.math(latex) and line.chain(PLAIN)[-1] == PLAIN.math(latex)


def test_a_formula_naming_nothing_is_an_error():
    variant = fake_variant([Step("y", "y", r"2\,@ghost", 1.0, "")])
    with pytest.raises(Exception, match="@ghost"):
        solution(variant)


@pytest.mark.parametrize("value, parts", [
    (0.35, ("0.35", None)), (0.1750000001, ("0.1750", None)), (1900.0, ("1900", None)),
    (3.0999999, ("3.100", None)), (3e8, ("3", "8")), (12345678.0, ("1.235", "7")), (7, ("7", None)),
    (-0.5, ("-0.5", None)), (1 / 3, ("0.3333", None)),
])
def test_number_parts(value, parts):
    assert number_parts(value) == parts


@pytest.mark.parametrize("value, unit, md, typ, plain", [
    (23.876, "m/s", r"23.88\ \text{m/s}", '23.88 thin "m/s"', "23.88 m/s"),
    (177.96, "deg", r"178.0^{\circ}", '178.0"°"', "178.0°"),
    (2.5, "percent", r"2.5\%", '2.5"%"', "2.5%"),
    (3e8, "N/m^2", r"3 \times 10^{8}\ \text{N/m²}", '3 times 10^(8) thin "N/m²"', "3×10⁸ N/m²"),
    (493.96, "N*m", r"494.0\ \text{N·m}", '494.0 thin "N·m"', "494.0 N·m"),
    (2.1, "", "2.1", "2.1", "2.1"),
])
def test_quantities_per_target(value, unit, md, typ, plain):
    assert (MARKDOWN.quantity(value, unit), TYPST.quantity(value, unit), PLAIN.quantity(value, unit)) == (md, typ, plain)


def test_every_bank_template_has_a_worked_solution(bank):
    for template in bank:
        variant = make_variant(template, 11)
        worked = solution(variant)
        assert len(worked.lines) == len(variant.steps)
        answered = {p for line in worked.lines for p in line.parts}
        assert answered == {p.id for p in template.parts}, template.id
        for line in worked.lines:
            for target in (PLAIN, TYPST, MARKDOWN):
                assert all(line.chain(target)), (template.id, line.name)
