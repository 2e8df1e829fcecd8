"""The worked solution as data, and the per-format quantity writers it relies on."""
import math
from decimal import Decimal
from types import SimpleNamespace

import pytest

from exgen.load.template import PartSpec
from exgen.render.solution import solution
from exgen.render.targets import MARKDOWN, PLAIN, TYPST, number_parts
from exgen.solve.derivation import Column, Step, Table
from exgen.solve.variant import Answer, ParamValue, make_variant
from exgen.units import si_unit


def fake_variant(steps, params=(), parts=(), answers=None, inserts=()):
    template = SimpleNamespace(id="test.fake", parts=tuple(parts))
    return SimpleNamespace(template=template, steps=tuple(steps), params=tuple(params), answers=answers or {},
                           inserts=tuple(inserts), unused=frozenset())


def param(name, exact, unit, si, symbol=""):
    return ParamValue(name, Decimal(exact), unit, si, "", symbol or name)


@pytest.mark.parametrize("unit, expected", [
    ("mm", "m"), ("rpm", "rad/s"), ("kN", "N"), ("MN/m^2", "N/m^2"), ("kW", "W"), ("deg", "rad"),
    ("percent", ""), ("kg/m", "kg/m"), ("mm^2", "m^2"), ("1/in", "1/m"), ("not-a-unit", None),
    ("kN*m", "N*m"), ("kJ", "J"), ("MJ", "J"), ("kW*h", "J"),   # an energy in joules, a torque in N·m
])
def test_si_unit(unit, expected):
    assert si_unit(unit) == expected


def test_given_shows_si_only_where_the_working_uses_it():
    params = [param("N1", "570", "rpm", 59.69026041820607, r"\omega_1"), param("X", "2.8", "m", 2.8),
              param("N2", "300", "rpm", 31.41592653589793, r"\omega_2"), param("r", "150", "mm", 0.15)]
    steps = [Step("v", "v", r"@N1\,@r", 8.95353906273091, "m/s"),
             Step("n", "n", r"\frac{@N2}{@N1}", 0.5263157894736842, "")]
    given = {g.name: g for g in solution(fake_variant(steps, params)).given}
    assert given["N1"].printed == "570 rpm" and given["N1"].si_text == "59.69 rad/s"
    assert given["N1"].symbol == r"\omega_1" and given["r"].si_text == "0.15 m"
    assert given["X"].si_text is None and given["N2"].si_text is None  # N2 is worked in rpm only
    n = solution(fake_variant(steps, params)).lines[1]
    assert " = ".join(n.chain(PLAIN)) == "n = ω₂/ω₁ = 300/570 = 0.5263"


def test_an_angle_is_worked_in_degrees_and_in_radians_where_the_arithmetic_needs_them():
    part = PartSpec("a", "the angle", "theta", unit="deg")
    alpha = math.asin(0.15 / 2.8)
    steps = [Step("alpha", r"\alpha", r"\sin^{-1}\frac{@r}{@X}", alpha, "rad"),
             Step("theta", r"\theta", r"180^\circ - 2\,@alpha", math.pi - 2 * alpha, "rad"),
             Step("R", "R", r"e^{@mu\,@theta}", math.exp(0.3 * (math.pi - 2 * alpha)), "")]
    params = [param("r", "150", "mm", 0.15), param("X", "2.8", "m", 2.8), param("mu", "0.3", "", 0.3, r"\mu")]
    answer = Answer(part, math.degrees(math.pi - 2 * alpha), math.pi - 2 * alpha, steps[1])
    alpha, theta, ratio = solution(fake_variant(steps, params, [part], {"a": answer})).lines
    assert " = ".join(alpha.chain(PLAIN)) == "α = sin⁻¹(r/X) = sin⁻¹(0.15/2.8) = 3.071°"
    assert " = ".join(theta.chain(PLAIN)) == "θ = 180° − 2α = 180° − 2 × 3.071° = 173.9° = 3.034 rad"
    assert theta.parts == ("a",) and [q.unit for q in theta.values] == ["deg", "rad"]
    assert " = ".join(ratio.chain(PLAIN)) == "R = e^(μθ) = e^(0.3 × 3.034) = 2.485"
    assert theta.chain(TYPST)[-2] == '173.9"°"'
    assert theta.chain(MARKDOWN)[2] == r"180^{\circ} - 2 \times 3.071^{\circ}"


def test_trig_arguments_are_degrees_and_bracketed_when_they_are_products():
    steps = [Step("F", "F", r"@F1 \cos 2\,@theta1 + @F1 \sin @theta1", 1.0, "N")]
    params = [param("F1", "10", "N", 10.0), param("theta1", "30", "deg", 0.5235987755982988)]
    line = solution(fake_variant(steps, params)).lines[0]
    assert line.chain(MARKDOWN)[2] == r"10 \cos \left(2 \times 30^{\circ}\right) + 10 \sin 30^{\circ}"


def test_substitution_is_skipped_when_it_adds_nothing():
    steps = [Step("T1", "T_1", "@T_max", 2800.0, "N"), Step("k", "k", r"\pi/2", 1.5707963267948966, ""),
             Step("s", "s", "@T1 + 0", 2800.0, "N")]
    variant = fake_variant(steps, [param("T_max", "2.8", "kN", 2800.0, r"T_{\mathrm{max}}")])
    t1, k, s = solution(variant).lines
    assert t1.formula.latex(None) == r"T_{\mathrm{max}}" and t1.substituted is None
    assert k.chain(MARKDOWN) == ["k", r"\pi /2", "1.571"] and k.substituted is None
    assert s.chain(PLAIN)[2] == "2800 + 0"


def test_more_figures_where_four_would_not_reproduce_the_value():
    steps = [Step("P1", "P_1", "", 10770.2, "W"), Step("P2", "P_2", "", 10936.9, "W"),
             Step("change", "c", r"\frac{@P2}{@P1} - 1", 10936.9 / 10770.2 - 1, "", shown="percent")]
    change = solution(fake_variant(steps)).lines[2]
    assert change.chain(PLAIN)[2] == "10936.9/10770.2 − 1"  # 10940/10770 − 1 would give 1.58 %
    assert change.chain(PLAIN)[-1] == "1.548%"


def test_a_table_shows_its_steps_in_place_of_their_lines():
    steps = [Step("mr1", "m_1 r_1", r"@m\,@r", 1.5, "kg*m"), Step("B", "B", r"2\,@mr1", 3.0, "kg*m")]
    table = Table("Planes", (Column("Plane"), Column("$m r$", "kg*m"), Column(r"$\theta$", "rad")),
                  (("1", "@mr1", 0.5235987755982988),), ("Σ", "@mr1", None), at=1)
    params = [param("m", "3", "kg", 3.0), param("r", "0.5", "m", 0.5)]
    blocks = solution(fake_variant(steps, params, inserts=[table])).blocks
    assert [type(b).__name__ for b in blocks] == ["TableBlock", "WorkLine"]
    assert blocks[0].rows[0][1].value == 1.5 and blocks[0].rows[0][2].value == pytest.approx(30.0)
    assert blocks[0].rows[0][2].unit == "deg" and blocks[0].total[2] is None


def test_integer_and_word_values():
    parts = [PartSpec("a", "belts", "n", type="integer"), PartSpec("b", "more or less", "trend", type="choice",
                                                                    options={"choices": ("increase", "decrease")})]
    steps = [Step("n", "n", r"\left\lceil @x \right\rceil", 4, ""), Step("trend", r"\text{power}", "", "increase")]
    answers = {"a": Answer(parts[0], 4, 4, steps[0]), "b": Answer(parts[1], "increase", "increase", steps[1])}
    variant = fake_variant(steps, [param("x", "3.2", "", 3.2)], parts, answers)
    n, trend = solution(variant).lines
    assert n.chain(PLAIN) == ["n", "⌈x⌉", "⌈3.2⌉", "4"] and n.values[1:] == ()
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
    (3e8, "N/m^2", r"3 \times 10^{8}\ \text{N/m²}", '3 times 10^(8) thin "N/m"^(2)', "3×10⁸ N/m²"),
    (493.96, "N*m", r"494.0\ \text{N·m}", '494.0 thin "N·m"', "494.0 N·m"),
    (0.7872, "kg*m^2", r"0.7872\ \text{kg·m²}", '0.7872 thin "kg·m"^(2)', "0.7872 kg·m²"),
    (9.81, "m/s^2", r"9.81\ \text{m/s²}", '9.81 thin "m/s"^(2)', "9.81 m/s²"),
    (2.1, "", "2.1", "2.1", "2.1"),
])
def test_quantities_per_target(value, unit, md, typ, plain):
    assert (MARKDOWN.quantity(value, unit), TYPST.quantity(value, unit), PLAIN.quantity(value, unit)) == (md, typ, plain)


def test_every_bank_template_has_a_worked_solution(bank):
    for template in bank:
        variant = make_variant(template, 11)
        worked = solution(variant)
        answered = {p for line in worked.lines for p in line.parts}
        assert answered == {p.id for p in template.parts}, template.id
        for line in worked.lines:
            for target in (PLAIN, TYPST, MARKDOWN):
                assert all(line.chain(target)), (template.id, line.name)
