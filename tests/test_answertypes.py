"""Every answer type, through the registry: found, loaded from YAML with file:line errors, read safely,
and one tolerance rule for what the key prints and what the grader applies."""
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exgen.answertypes import answer_type, names, read, registry
from exgen.errors import BankError, FormatProblem, WrongKind
from exgen.load.bank import load_template
from exgen.load.template import PartSpec, Tolerance

KINDS = sorted(registry())

TEMPLATE = """\
id: demo.types
title: Answer types
solver: belts:driven_speed
params:
  N1: {min: 720, max: 1800, step: 20, unit: rpm}
  d1: {min: 20, max: 50, step: 1, unit: cm}
  d2: {min: 60, max: 120, step: 5, unit: cm}
  G1: {choices: [1, 2], unit: percent}
  G2: {choices: [1, 2], unit: percent}
  t:  {value: 8, unit: mm}
statement: A motor at {{ N1 }} drives a pulley of {{ d2 }} from one of {{ d1 }}.
parts:
  - {id: a, ask: the speed, answer: N2_slip, unit: rpm, PART}
"""


def load(tmp_path: Path, part: str):
    path = tmp_path / "t.yaml"
    path.write_text(TEMPLATE.replace("PART", part), encoding="utf-8")
    return load_template(path)


def problems(tmp_path: Path, part: str) -> list[str]:
    with pytest.raises(BankError) as info:
        load(tmp_path, part)
    return [str(e) for e in info.value.errors]


def test_the_registry_finds_every_type():
    assert {"number", "angle", "integer", "choice", "polar"} <= set(names())
    assert all(answer_type(name).name == name for name in names())
    with pytest.raises(KeyError, match="is not an answer type; the types are angle, choice"):
        answer_type("vector")


@pytest.mark.parametrize("kind", KINDS)
def test_a_type_reads_back_what_it_prints(kind):
    answers = answer_type(kind)
    part = answers.sample_part()
    value = answers.example(part)
    reading = read(answers.text(value, part), part)
    assert answers.matches(reading.value, value, part)
    for text in (answers.hint(part), answers.form_hint(part), answers.tolerance_text(part), answers.format_hint(part)):
        assert text and "\n" not in text


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("text", ["x" * 1_000_000, "(" * 100_000, "__import__('os').system('ls')",
                                  "9^9^9^9", "\x00\x01", "1e999999", "", "   "])
def test_a_hostile_answer_is_a_format_problem_of_every_type(kind, text):
    part = answer_type(kind).sample_part()
    with pytest.raises((FormatProblem, WrongKind)):
        read(text, part)


@pytest.mark.parametrize("kind", KINDS)
@settings(max_examples=200, deadline=None)
@given(text=st.text(max_size=120))
def test_any_text_is_read_or_refused_with_a_reason(kind, text):
    part = answer_type(kind).sample_part()
    try:
        read(text, part)
    except (FormatProblem, WrongKind) as exc:
        assert str(exc)


# ---- significant figures: the key says what the grader does ------------------------------------

def test_sig_replaces_the_relative_tolerance(tmp_path):
    part = load(tmp_path, "tol: {sig: 3}").part("a")
    answers = answer_type(part)
    assert part.tol == Tolerance(rel=0.0, abs=0.0, sig=3)
    assert answers.tolerance_text(part) == "3 significant figures"
    assert answers.matches(1004.0, 1000.0, part)       # 1.00e3 to three figures
    assert not answers.matches(1006.0, 1000.0, part)   # 1.01e3: within 1 %, but not to three figures
    assert answers.matches(0.00124, 0.0012361, part) and not answers.matches(0.00123, 0.0012361, part)
    assert "1 %" in answers.wrong_message(read("1006", part), load(tmp_path, "tol: {rel: 0.01}").part("a"))
    assert answers.wrong_message(read("1006", part), part) == "not within 3 significant figures of the expected value"


def test_sig_with_an_absolute_floor(tmp_path):
    part = load(tmp_path, "tol: {sig: 2, abs: 0.5}").part("a")
    assert answer_type(part).tolerance_text(part) == "2 significant figures or 0.5 rpm"
    assert answer_type(part).matches(0.4, 0.0, part)


@pytest.mark.parametrize("part, message", [
    ("tol: {sig: 3, rel: 0.01}", "part (a), tol: give `rel` or `sig`, not both"),
    ("tol: {sig: 2.5}", "part (a), tol.sig: must be a whole number of figures from 1 to 15"),
    ("tol: {sig: 0}", "part (a), tol.sig: must be a whole number of figures from 1 to 15"),
    ("tol: {rel: 0.01, deg: 1}", "part (a), tol.deg: not a tolerance of a number answer; expected one of rel, abs, sig"),
    ("type: angle, tol: {sig: 3}", "part (a), tol.sig: not a tolerance of an angle answer; expected one of rel, abs"),
    ("type: integer, tol: {rel: 0.01}", "part (a), tol: an integer answer is graded exactly; remove `tol:`"),
    ("type: choice", "part (a), choices: a choice answer needs its list of choices"),
    ("type: polar", "part (a), angle: a polar answer needs `angle:`, the step holding its angle"),
    ("choices: [a, b]", "part (a), choices: unknown key"),
    ("tol: 0.01", "part (a), tol: must be a mapping such as {rel: 0.01}"),
])
def test_a_type_checks_its_own_keys_with_file_line_and_column(tmp_path, part, message):
    found = problems(tmp_path, part)
    assert any(re.search(rf"t\.yaml:13:\d+: {re.escape(message)}", p) for p in found), found


def test_defaults_come_from_the_type(tmp_path):
    assert load(tmp_path, "points: 1").part("a").tol == answer_type("number").default_tol
    assert load(tmp_path, "type: angle").part("a").tol == answer_type("angle").default_tol
    assert PartSpec("a", "x", "v").tol == answer_type("number").default_tol


@pytest.mark.parametrize("kind", KINDS)
def test_other_answers_tried_for_uses_differ_from_the_answer(kind):
    """validate nudges an earlier answer to check that a part which `uses:` it follows it."""
    answers = answer_type(kind)
    part = answers.sample_part()
    value = answers.example(part)
    assert all(other != value for other in answers.nudges(value, part))


@pytest.mark.parametrize("kind", KINDS)
def test_a_sheet_form_offers_choices_exactly_where_a_learning_system_does(kind):
    """The form's drop-down comes from the type (never from its options): the same choices an export
    offers, each read back as itself; a type without choices gets a box to type into."""
    from exgen.answertypes.lms import NoLmsForm

    answers = answer_type(kind)
    part = answers.sample_part()
    offered = answers.form_choices(part)
    value = answers.example(part)
    try:
        gaps = answers.lms_gaps(part, value, {})
    except NoLmsForm:
        gaps = ()
    listed = [g.choices for g in gaps if getattr(g, "kind", "") == "choice"]
    if offered is None:
        assert not listed
        return
    assert listed == [offered] and value in offered
    for choice in offered:
        assert answers.matches(read(choice, part).value, choice, part)
        assert [c for c in offered if answers.matches(read(choice, part).value, c, part)] == [choice]


def _answer(part: PartSpec, value):
    from types import SimpleNamespace

    return SimpleNamespace(part=part, value=value)


@pytest.mark.parametrize("part, key, shown, gives", [
    (PartSpec("c", "f", "f", "Hz", type="number", tol=Tolerance(rel=0.01)), 7.49, 47.08, True),    # ω in rad/s
    (PartSpec("c", "f", "f", "Hz", type="number", tol=Tolerance(rel=0.01)), 7.49, 449.6, True),    # in rpm
    (PartSpec("c", "f", "f", "Hz", type="number", tol=Tolerance(rel=0.01)), 7.49, 7.49, True),
    (PartSpec("c", "f", "f", "Hz", type="number", tol=Tolerance(rel=0.01)), 7.49, 8.0, False),
    (PartSpec("b", "q", "q", "N*m", type="number", tol=Tolerance(rel=0.01)), 822.0, 0.822, True),  # kN·m
    (PartSpec("b", "q", "q", "N*m", type="number", tol=Tolerance(rel=0.01)), 822.0, -822.0, True),
    (PartSpec("e", "η", "e", "", type="number", tol=Tolerance(rel=0.01)), 0.85, 85.0, True),       # percent
    (PartSpec("a", "θ", "t", "deg", type="angle", tol=Tolerance(abs=0.5)), 168.8, 2.946, True),    # radians
    (PartSpec("a", "θ", "t", "deg", type="angle", tol=Tolerance(abs=0.5)), 168.8, -191.2, True),   # a turn less
    (PartSpec("a", "θ", "t", "deg", type="angle", tol=Tolerance(abs=0.5)), 30.0, -30.0, False),    # mirrored
    (PartSpec("n", "n", "n", "", type="integer"), 4, 4.0, True),
    (PartSpec("n", "n", "n", "", type="integer"), 4, 400.0, False),  # a count is no percentage
    (PartSpec("k", "k", "k", "", type="choice", options={"choices": ("clockwise", "anticlockwise")}),
     "clockwise", "Clockwise", True),
    (PartSpec("k", "k", "k", "", type="choice", options={"choices": ("clockwise", "anticlockwise")}),
     "clockwise", 1.0, False),
])
def test_a_value_shown_gives_an_answer_away_in_any_unit_of_its_kind(part, key, shown, gives):
    assert answer_type(part).gives_away(shown, _answer(part, key)) is gives


def test_either_half_of_a_polar_answer_is_given_away():
    from exgen.answertypes.polar import Polar

    part = PartSpec("a", "m r", "mr", "kg*m", type="polar", tol=Tolerance(rel=0.01, abs=0.5),
                    options={"angle": "theta"})
    answer = _answer(part, Polar(0.57, 48.0))
    kind = answer_type(part)
    assert kind.gives_away(570.0, answer) and kind.gives_away(0.8378, answer) and kind.gives_away(48.2, answer)
    assert not kind.gives_away(0.6, answer)
