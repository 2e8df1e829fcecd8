"""A malformed template fails loading with an error naming the file, the key and the line."""
from pathlib import Path

import pytest

from exgen.errors import BankError, UnknownTemplate
from exgen.load.bank import _load_bank, load_template

GOOD = """\
id: demo.good
title: A good template
chapter: 1
solver: belts:driven_speed
params:
  N1: {min: 720, max: 1800, step: 20, unit: rpm}
  d1: {min: 20, max: 50, step: 1, unit: cm}
  d2: {min: 40, max: 120, step: 5, unit: cm}
  G1: {choices: [1, 2], unit: percent}
  G2: {choices: [1, 2], unit: percent}
  t:  {value: 8, unit: mm}
require: ["d2 > d1"]
statement: A motor at {{ N1 }} drives a pulley of {{ d2 }} from one of {{ d1 }}.
parts:
  - {id: a, ask: the speed, answer: N2_slip, unit: rpm}
"""


def write(tmp_path: Path, text: str, name="t.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def problems(path: Path) -> list[str]:
    with pytest.raises(BankError) as info:
        load_template(path)
    return [str(e) for e in info.value.errors]


def test_good_template_loads(tmp_path):
    template = load_template(write(tmp_path, GOOD))
    assert template.id == "demo.good" and template.param("t").choices[0] == 8
    assert len(template.digest) == 64


@pytest.mark.parametrize("old, new, expected", [
    ("title: A good template\n", "", "t.yaml: title: is required"),
    ("chapter: 1", "chapter: one", "t.yaml:3:1: chapter: must be a whole number"),
    ("solver: belts:driven_speed", "solver: belts:no_such", "t.yaml:4:1: solver: exgen.solvers.belts has no function 'no_such'"),
    ("solver: belts:driven_speed", "solver: os:system", "t.yaml:4:1: solver: no module exgen.solvers.os"),
    ("step: 20, unit: rpm", "step: 7, unit: rpm", "t.yaml:6:29: parameter N1, step: (max - min) = 1080 is not a whole number of steps of 7"),
    ("min: 20, max: 50", "min: 50, max: 20", "t.yaml:7:3: parameter d1: needs min <= max and step > 0"),
    ("{min: 40, max: 120, step: 5, unit: cm}", "{min: 40, max: 120, stp: 5, unit: cm}", "t.yaml:8:27: parameter d2, stp: unknown key"),
    ("G1: {choices: [1, 2], unit: percent}", "G1: {choices: [1, 2], also_solves: [3], unit: percent}",
     "parameter G1, also_solves: only a parameter whose choices are words takes `also_solves:`"),
    ('["d2 > d1"]', '["d2 > d9"]', "t.yaml:12:11: require, condition 1: names no parameter: d9"),
    ('["d2 > d1"]', '["d2 >"]', "t.yaml:12:11: require, condition 1: cannot read 'd2 >' as an expression"),
    ("{{ d1 }}.", "{{ d3 }}.", "t.yaml:13:1: statement: refers to unknown parameter(s): d3"),
    ("{{ d1 }}.", "{{ d1 }.", "t.yaml:13:1: statement: template syntax error on line 1"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, type: vector}", "t.yaml:15:57: part (a), type: 'vector' is not one of"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, uses: [b]}", "t.yaml:15:57: part (a), uses: 'b' is not an earlier part"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, tol: {rel: -1}}", "t.yaml:15:63: part (a), tol.rel: must be a number >= 0"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, points: 0}", "t.yaml:15:57: part (a), points: must be a positive number"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, hints: first}", "t.yaml:15:57: part (a), hints: must be a list of hint"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, hints: [ok, 3]}", "t.yaml:15:57: part (a), hints: must be a list of hint"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, hints: ['{{ d9 }}']}",
     "t.yaml:15:65: part (a), hint 1: refers to unknown parameter(s): d9"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, mistakes: [{when: x, say: 'At {{ d9 }}.'}]}",
     "part (a), mistake 1, say: refers to unknown parameter(s): d9"),
    ("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, mistakes: [{when: x, say: 'At {{ d1 }.'}]}",
     "part (a), mistake 1, say: template syntax error on line 1"),
    ("  t:  {value: 8, unit: mm}", "  steps: {value: 8, unit: mm}", "'steps' is the name under which feedback and hints"),
])
def test_each_problem_names_file_line_column_and_key_as_an_author_reads_it(tmp_path, old, new, expected):
    assert old in GOOD
    found = problems(write(tmp_path, GOOD.replace(old, new)))
    assert any(expected in p for p in found), found


def test_a_say_may_name_the_givens_and_the_solvers_word_steps(tmp_path):
    text = GOOD.replace("answer: N2_slip, unit: rpm}", "answer: N2_slip, unit: rpm, mistakes: "
                        "[{when: x, say: '{{ d1 }} and {{ steps.anything }}'}]}")
    assert load_template(write(tmp_path, text)).parts[0].mistakes[0].say == "{{ d1 }} and {{ steps.anything }}"


def test_hints_are_kept_in_order_and_filled_with_the_variants_values(tmp_path):
    from exgen.solve.variant import make_variant

    text = GOOD.replace("answer: N2_slip, unit: rpm}",
                        "answer: N2_slip, unit: rpm, hints: ['The ratio is $d_1/d_2$.', 'Start from {{ N1 }}.']}")
    template = load_template(write(tmp_path, text))
    assert template.parts[0].hints == ("The ratio is $d_1/d_2$.", "Start from {{ N1 }}.")
    variant = make_variant(template, 3)
    assert variant.fill(template.parts[0].hints[1]) == f"Start from {variant.param('N1')}."


def test_hints_do_not_change_a_templates_version(tmp_path):
    plain = load_template(write(tmp_path, GOOD, "plain.yaml"))
    hinted = load_template(write(tmp_path, GOOD.replace("N2_slip, unit: rpm}", "N2_slip, unit: rpm, hints: [Use the ratio.]}"),
                                 "h.yaml"))
    assert hinted.parts[0].hints and hinted.digest == plain.digest


def test_all_problems_in_a_file_are_reported_at_once(tmp_path):
    text = GOOD.replace("chapter: 1", "chapter: one").replace("{{ d1 }}.", "{{ d3 }}.").replace("title: A good template\n", "")
    assert len(problems(write(tmp_path, text))) == 3


def test_unknown_top_level_key(tmp_path):
    assert any("parmas: unknown key" in p for p in problems(write(tmp_path, GOOD + "parmas: {}\n")))


@pytest.mark.parametrize("text, expected", [
    ("id: [unclosed", "not valid YAML"),
    ("- just\n- a list\n", "a template file must be a mapping"),
    ("!!python/object/apply:os.system ['echo hi']", "not valid YAML"),
])
def test_not_a_template_at_all(tmp_path, text, expected):
    assert any(expected in p for p in problems(write(tmp_path, text)))


def test_duplicate_ids_across_files_are_reported(tmp_path):
    write(tmp_path, GOOD, "one.yaml")
    write(tmp_path, GOOD, "two.yaml")
    with pytest.raises(BankError, match="'demo.good' is also defined in"):
        _load_bank((tmp_path,))


def test_unknown_template_suggests(bank):
    with pytest.raises(UnknownTemplate, match="no template with id 'belts.flat_power'.*"):
        bank.get("belts.flat_power")


def test_packaged_bank_loads(bank):
    assert {t.id for t in bank} >= {
        "belts.flat_belt_power", "belts.v_belt_power", "belts.driven_pulley_diameter", "belts.driven_speed_slip",
        "belts.compound_drive", "belts.drive_geometry", "belts.max_power", "belts.v_belt_count"}


def test_a_light_load_leaves_code_and_texts_to_the_full_check_and_to_first_use(tmp_path):
    """`exgen list` and `show` load the bank without importing solvers or parsing texts: a wrong function
    or name passes the light load, fails the full one (validate, generate, grade), and is named when used."""
    from exgen.errors import ExgenError, TemplateError
    from exgen.solve.variant import make_variant

    path = write(tmp_path, GOOD.replace("{{ d1 }}.", "{{ d3 }}."))
    assert any("unknown parameter(s): d3" in p for p in problems(path))
    light = load_template(path, full=False)
    with pytest.raises(TemplateError, match=r"t\.yaml: statement: cannot be written: 'd3' is undefined"):
        make_variant(light, 1).statement

    path = write(tmp_path, GOOD.replace("belts:driven_speed", "belts:no_such"))
    assert any("has no function 'no_such'" in p for p in problems(path))
    with pytest.raises(ExgenError, match="exgen.solvers.belts has no function 'no_such'"):
        make_variant(load_template(path, full=False), 1)
    with pytest.raises(BankError, match="no module exgen.solvers.nowhere"):
        load_template(write(tmp_path, GOOD.replace("belts:driven_speed", "nowhere:f")), full=False)


def test_a_word_the_template_never_draws_can_still_be_solved(tmp_path, capsys):
    # also_solves: a textbook's own value no real machine has (Problem 2.4's firing order) is worked by
    # `exgen solve`, never drawn; any other word is refused naming every word it takes
    from exgen.check.given import given_values
    from exgen.errors import ExgenError
    from exgen.solve.variant import make_variant

    text = GOOD.replace("  t:  {value: 8, unit: mm}", "  t:  {value: 8, unit: mm}\n  belt: {choices: [flat, vee], also_solves: [rope]}")
    template = load_template(write(tmp_path, text))
    given = {"N1": "1000 rpm", "d1": "30 cm", "d2": "60 cm", "G1": "1", "G2": "1"}
    assert given_values(template, {**given, "belt": "rope"})["belt"] == "rope"
    with pytest.raises(ExgenError, match="belt must be one of flat, vee, rope"):
        given_values(template, {**given, "belt": "chain"})
    assert {make_variant(template, seed).param("belt").text for seed in range(40)} == {"flat", "vee"}
