"""Parameters worked out from others (`equals:`): exact, printed like any given, checked when loading."""
import re
from decimal import Decimal
from pathlib import Path

import pytest

from exgen.check.given import solve
from exgen.draw.values import draw_values, generator
from exgen.errors import BankError, ExgenError
from exgen.load.bank import load_template

TEMPLATE = """\
id: demo.derived
title: Driven speed with a derived pulley
chapter: 1
solver: belts:driven_speed
params:
  N1: {min: 720, max: 1800, step: 20, unit: rpm}
  d1: {min: 20.5, max: 50, step: 0.5, unit: cm}
  d2: {equals: "2 * d1 + 10.25", unit: cm, label: driven pulley diameter}
  G1: {choices: [1, 2], unit: percent}
  G2: {choices: [1, 2], unit: percent}
  t:  {value: 8, unit: mm}
statement: A motor at {{ N1 }} drives a pulley of {{ d2 }} from one of {{ d1 }}.
parts:
  - {id: a, ask: the speed, answer: N2_slip, unit: rpm}
"""


def load(tmp_path: Path, text: str = TEMPLATE):
    path = tmp_path / "t.yaml"
    path.write_text(text, encoding="utf-8")
    return load_template(path)


def test_derived_value_is_exact_decimal_arithmetic(tmp_path):
    template = load(tmp_path)
    for seed in range(50):
        values = draw_values(template, generator(seed))
        assert values["d2"] == 2 * values["d1"] + Decimal("10.25")


def test_a_derived_parameter_takes_no_random_draw(tmp_path):
    with_derived = load(tmp_path)
    plain = load(tmp_path, TEMPLATE.replace('  d2: {equals: "2 * d1 + 10.25", unit: cm, label: driven pulley diameter}\n', "")
                 .replace(" drives a pulley of {{ d2 }}", ""))
    a, b = draw_values(with_derived, generator(7)), draw_values(plain, generator(7))
    assert {k: v for k, v in a.items() if k != "d2"} == {k: v for k, v in b.items() if k != "d2"}


def test_solve_works_it_out_and_checks_a_value_given_for_it(tmp_path):
    template = load(tmp_path)
    given = {"N1": "1200 rpm", "d1": "40 cm", "G1": "2", "G2": "1", "t": "8 mm"}
    variant, _ = solve(template, given)
    assert variant.param("d2").text == "90.25" and str(variant.param("d2")) == "90.25 cm"
    solve(template, {**given, "d2": "902.5 mm"})               # agrees: accepted
    with pytest.raises(ExgenError, match=r"d2 is worked out from the others \(2 \* d1 \+ 10.25 = 90.25 cm\)"):
        solve(template, {**given, "d2": "90 cm"})


@pytest.mark.parametrize("formula, expected", [
    ('"2 * d9"', "parameter d2, equals: names no earlier numeric parameter: d9"),
    ('"2 * G1x"', "parameter d2, equals: names no earlier numeric parameter: G1x"),
    ('"2 *"', "parameter d2, equals: cannot read '2 *' as an expression"),
])
def test_a_bad_formula_names_the_key_and_line(tmp_path, formula, expected):
    with pytest.raises(BankError) as info:
        load(tmp_path, TEMPLATE.replace('"2 * d1 + 10.25"', formula))
    assert any(expected in str(e) and re.search(r":8:\d+: ", str(e)) for e in info.value.errors), info.value.errors


def test_a_derived_parameter_may_use_only_earlier_ones(tmp_path):
    text = TEMPLATE.replace('d2: {equals: "2 * d1 + 10.25"', 'd2: {equals: "2 * N1x"')
    with pytest.raises(BankError, match="names no earlier numeric parameter"):
        load(tmp_path, text)
