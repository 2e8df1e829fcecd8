"""Grading one sheet: the key scores full marks, units, error carried forward, named mistakes."""
import dataclasses
import json
import math

import pytest

from exgen import units
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.load.mistake_messages import default_messages
from exgen.load.template import PartSpec
from exgen.render.answer_form import answer_form
from exgen.solve.variant import answer_for, make_variant, rerun
from graders.answers import Submission, read_submission
from graders.grade import grade_sheet, grade_variant
from graders.results import BLANK, CARRIED, CORRECT, UNREADABLE, WRONG

SECRET = b"x" * 32


def sheet_for(bank, templates, student="s001", points=None):
    questions = tuple(QuestionSpec(f"q{i}", t, points) for i, t in enumerate(templates, start=1))
    return build_sheet(Assignment("hw1", "Homework 1", questions), Student(student), bank, SECRET)


def fill(form: str, texts: dict) -> str:
    """The form with some answers typed in: texts is {slot: {part: text}}."""
    out, slot = [], None
    for line in form.splitlines():
        if line.startswith("  ") and not line.startswith("    ") and ":" in line:
            slot = line.split(":")[0].strip()
        elif line.startswith("    ") and slot in texts:
            part = line.split(":")[0].strip()
            if part in texts[slot]:
                line = line.replace('""', json.dumps(texts[slot][part], ensure_ascii=False), 1)
        out.append(line)
    return "\n".join(out) + "\n"


def grade_texts(sheet, texts: dict, code=None):
    return grade_sheet(sheet, Submission(None, sheet.student.id, "hw1", sheet.code if code is None else code, texts))


def part_result(result, slot, part):
    return next(p for p in result.question(slot).parts if p.part_id == part)


def flat(bank, seed=None):
    """The flat-belt problem; by default a draw whose mistake values are all well clear of the answers
    (5 %, or three tolerances for a part graded finely: creep is a real belt's 0.5-1 %)."""
    if seed is not None:
        return make_variant(bank.get("belts.flat_belt_power"), seed)
    template = bank.get("belts.flat_belt_power")

    def clear(part_id, mistake, answer):
        tol = template.part(part_id).tol.rel
        return abs(mistake / answer - 1) > (0.05 if tol >= 0.01 else 3 * tol)

    for seed in range(100):
        variant = make_variant(template, seed)
        if all(clear(p, m, variant.answers[p].value) for p, ms in variant.mistakes.items() for m in ms.values()):
            return variant
    raise AssertionError("no flat-belt draw with distinct mistakes")


# ---- the key and the blank form --------------------------------------------------------------

@pytest.mark.parametrize("student", [f"s{i:03d}" for i in range(12)])
def test_key_typed_into_the_form_grades_itself_at_full_marks(bank, tmp_path, student):
    sheet = sheet_for(bank, [t.id for t in bank], student)
    key = {q.slot: {pid: a.text for pid, a in q.variant.answers.items()} for q in sheet.questions}
    path = tmp_path / "answers.yaml"
    path.write_text(fill(answer_form(sheet), key), encoding="utf-8")
    result = grade_sheet(sheet, read_submission(path))
    wrong = [(q.template, p.part_id, p.given, p.message) for q in result.questions for p in q.parts if not p.correct]
    assert wrong == []
    assert result.points == pytest.approx(sheet.points) and result.percent == pytest.approx(100)
    assert result.warnings == ()


@pytest.mark.parametrize("seed", range(40))
def test_key_grades_itself_for_every_template(bank, seed):
    for template in bank:
        variant = make_variant(template, seed)
        result = grade_variant(variant, {pid: a.text for pid, a in variant.answers.items()})
        assert [p.part_id for p in result.parts if p.status != CORRECT] == [], template.id


def test_blank_form_scores_zero_with_one_message_per_part(bank, tmp_path):
    sheet = sheet_for(bank, [t.id for t in bank])
    path = tmp_path / "answers.yaml"
    path.write_text(answer_form(sheet), encoding="utf-8")
    result = grade_sheet(sheet, read_submission(path))
    parts = [p for q in result.questions for p in q.parts]
    assert result.points == 0 and len(parts) == sum(len(q.variant.template.parts) for q in sheet.questions)
    assert {(p.status, p.message) for p in parts} == {(BLANK, "no answer given")}


def test_points_scale_with_the_question(bank):
    sheet = sheet_for(bank, ["belts.flat_belt_power"], points=14)
    v = sheet.questions[0].variant
    result = grade_texts(sheet, {"q1": {"a": v.answers["a"].text}})
    assert part_result(result, "q1", "a").points == pytest.approx(2.0)
    assert result.max_points == 14


# ---- units -------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def force_variant(bank):
    """The flat-belt problem asking for the tight-side tension in N."""
    template = dataclasses.replace(bank.get("belts.flat_belt_power"),
                                   parts=(PartSpec("t", "the tight-side tension", "T1", "N"),))
    return make_variant(template, 7)


@pytest.mark.parametrize("factor, unit, status", [
    (1, "N", CORRECT), (1e-3, "kN", CORRECT), (1e-3, " kN", CORRECT), (1, "", CORRECT), (1e-6, "MN", CORRECT),
    (1 / 4.4482216, "lbf", CORRECT), (1 / 9.80665, "kgf", CORRECT), (1e-3, "", WRONG), (1, "m", WRONG), (1, "kg", WRONG), (1, "N*m", WRONG),
    (1, "N-m", WRONG),
])
def test_any_unit_of_the_right_kind_is_accepted(force_variant, factor, unit, status):
    value = force_variant.answers["t"].value * factor
    result = grade_variant(force_variant, {"t": f"{value:.6g} {unit}".strip()})
    assert result.parts[0].status == status


def test_wrong_kind_names_both_kinds(force_variant):
    part = grade_variant(force_variant, {"t": "3 m"}).parts[0]
    assert part.status == WRONG and part.mistake == "wrong_kind" and part.points == 0
    assert part.message == "'m' is a length, but a force is asked (in N)"


@pytest.mark.parametrize("typed, status, mistake", [
    ("{rpm:.5g}", CORRECT, None),
    ("{rpm:.5g} rpm", CORRECT, None),
    ("{rad_s:.5g} rad/s", CORRECT, None),
    ("{hz:.5g} Hz", CORRECT, None),            # Hz counts revolutions per second
    ("{hz:.5g} rev/s", CORRECT, None),
    ("{rad_s:.5g}", WRONG, "rad_s_for_rpm"),   # a bare number is read in rpm
    ("{rad_s:.5g} Hz", WRONG, "rad_s_for_hz"), # rad/s are not Hz
    ("{hz:.5g} rad/s", WRONG, "hz_for_rad_s"),
    ("{rpm:.5g} rad/s", WRONG, "rpm_for_rad_s"),
    ("{rpm:.5g} m/s", WRONG, "wrong_kind"),
])
def test_rpm_rad_s_and_hz_are_distinct(bank, typed, status, mistake):
    variant = make_variant(bank.get("belts.driven_speed_slip"), 3)
    rpm = variant.answers["a"].value
    text = typed.format(rpm=rpm, rad_s=rpm * math.pi / 30, hz=rpm / 60)
    part = grade_variant(variant, {"a": text}).parts[0]
    assert (part.status, part.mistake) == (status, mistake), part.message


@pytest.mark.parametrize("typed, status, mistake", [
    ("{pct:.4g}", CORRECT, None), ("{pct:.4g} %", CORRECT, None), ("{pct:.4g}%", CORRECT, None),
    ("{frac:.4g}", WRONG, "fraction_for_percent"),
])
def test_percent_parts(bank, typed, status, mistake):
    variant = make_variant(bank.get("belts.v_belt_count"), 11)
    pct = variant.answers["c"].value
    part = grade_variant(variant, {"c": typed.format(pct=pct, frac=pct / 100)}).parts[2]
    assert (part.status, part.mistake) == (status, mistake), part.message


# ---- error carried forward ---------------------------------------------------------------------

def carried_value(variant, part_id, **student):
    """What `part_id` comes to from the student's (wrong) earlier answers, in the asked unit."""
    template = variant.template
    overrides = {template.part(p).answer: units.convert(v, template.part(p).unit, variant.step(template.part(p).answer).unit)
                 for p, v in student.items()}
    return answer_for(template.part(part_id), rerun(variant, overrides)).value


@pytest.mark.parametrize("seed", [1, 2, 3, 12345])
def test_wrong_a_with_c_done_right_from_it_gets_cs_marks(bank, seed):
    variant = flat(bank, seed)
    a = variant.answers["a"].value * 0.93
    c = carried_value(variant, "c", a=a)
    assert not math.isclose(c, variant.answers["c"].value, rel_tol=0.01)
    result = grade_variant(variant, {"a": f"{a:.5g}", "b": variant.answers["b"].text, "c": f"{c:.4g} kW"})
    part_a, _, part_c = result.parts[:3]
    assert part_a.status == WRONG and part_a.points == 0
    assert part_c.status == CARRIED and part_c.points == part_c.max_points
    assert part_c.message == "correct from your (a)"


def test_both_used_parts_wrong(bank):
    variant = flat(bank)
    a, b = variant.answers["a"].value * 0.95, variant.answers["b"].value * 1.2
    d = carried_value(variant, "d", a=a, b=b)
    result = grade_variant(variant, {"a": f"{a:.5g}", "b": f"{b:.5g}", "d": f"{d:.5g}"})
    assert result.parts[3].status == CARRIED and result.parts[3].message == "correct from your (a) and (b)"


def test_right_answer_still_right_when_the_earlier_part_is_wrong(bank):
    variant = flat(bank)
    result = grade_variant(variant, {"a": "100", "c": variant.answers["c"].text})
    assert result.parts[2].status == CORRECT


def test_no_carry_forward_from_a_blank_or_unreadable_part(bank):
    variant = flat(bank)
    c = carried_value(variant, "c", a=variant.answers["a"].value * 0.9)
    for a in ("", "abc"):
        assert grade_variant(variant, {"a": a, "c": f"{c:.5g}"}).parts[2].status == WRONG


@pytest.mark.parametrize("zero", ["0", "0.0", "1e-999999", "-0"])
def test_zeros_everywhere_earn_nothing_by_carrying_forward(bank, zero):
    variant = flat(bank)
    result = grade_variant(variant, {p.id: zero for p in variant.template.parts})
    assert result.points == 0 and CARRIED not in {p.status for p in result.parts}


@pytest.mark.parametrize("a", ["0", "-500", "1e30", "360", "0.000001 rad"])
def test_a_solver_that_fails_on_the_students_values_means_no_carry_forward(bank, a):
    variant = flat(bank)
    result = grade_variant(variant, {"a": a, "c": "1 kW", "d": variant.answers["d"].text})
    assert result.parts[2].status == WRONG and result.parts[3].status == CORRECT


# ---- named mistakes ----------------------------------------------------------------------------

def test_crossed_belt_angle_gets_the_crossed_formula_message(bank):
    variant = flat(bank)
    crossed = variant.mistakes["a"]["crossed_formula"]
    part = grade_variant(variant, {"a": f"{crossed:.4g}"}).parts[0]
    assert part.mistake == "crossed_formula"
    assert part.message == variant.template.part("a").mistakes[0].say  # the template's own words


def test_bare_radians_for_a_degree_part_gets_the_radians_message(bank):
    variant = flat(bank)
    radians = math.radians(variant.answers["a"].value)
    part = grade_variant(variant, {"a": f"{radians:.4g}"}).parts[0]
    assert part.mistake == "radians_for_degrees"
    assert "rad" in part.message and "degrees" in part.message
    assert grade_variant(variant, {"a": f"{radians:.4g} rad"}).parts[0].status == CORRECT


@pytest.mark.parametrize("part_id, typed, mistake", [
    ("b", "{m[b][rpm_as_rad_s]:.4g}", "rpm_as_rad_s"),
    ("c", "{m[c][theta_in_degrees]:.4g}", "theta_in_degrees"),
    ("c", "{w[c]:.5g}", "wrong_prefix"),                  # W where kW is asked
    ("c", "{w[c]:.5g} kW", "wrong_prefix"),
    ("d", "-{a[d]:.4g}", "wrong_sign"),
    ("d", "{m[d][centrifugal_ignored]:.4g}", "centrifugal_ignored"),
    ("b", "{close[b]:.4g}", "premature_rounding"),
    ("f", "{m[f][radii_swapped]:.4g}", "radii_swapped"),
    ("b", "{far[b]:.4g}", None),
])
def test_wrong_answers_are_named(bank, part_id, typed, mistake):
    variant = flat(bank)
    values = {p: a.value for p, a in variant.answers.items()}
    text = typed.format(m=variant.mistakes, a=values, w={p: v * 1000 for p, v in values.items()},
                        close={p: v * 1.02 for p, v in values.items()}, far={p: v * 1.5 for p, v in values.items()})
    part = next(p for p in grade_variant(variant, {part_id: text}).parts if p.part_id == part_id)
    assert part.status == WRONG and part.mistake == mistake, part.message
    if mistake is None:
        assert part.message == "not within 1 % of the expected value. Your value is about 50 % too large."


def test_mistake_value_from_the_carried_forward_derivation(bank):
    variant = flat(bank)
    a = variant.answers["a"].value * 0.9
    ecf = rerun(variant, {"theta": math.radians(a)})
    slip = ecf.mistakes["P_light"]["theta_in_degrees"] / 1000
    part = grade_variant(variant, {"a": f"{a:.5g}", "c": f"{slip:.5g}"}).parts[2]
    assert part.mistake == "theta_in_degrees"


def test_a_mistake_without_say_gets_the_default_message(bank):
    variant = make_variant(bank.get("belts.compound_drive"), 5)
    value = variant.mistakes["a"]["slip_not_applied"]
    part = grade_variant(variant, {"a": f"{value:.5g}"}).parts[0]
    assert part.mistake == "slip_not_applied" and part.message == default_messages()["slip_not_applied"]


@pytest.mark.parametrize("typed, status, text", [
    ("{n}", CORRECT, "correct"), ("{n}.0", CORRECT, "correct"), ("{n}.5", WRONG, "whole number"),
    ("{up}", WRONG, "not the expected whole number"), ("{n} belts", CORRECT, "correct"),
    ("{n} V-belts", CORRECT, "correct"), ("{up} belts", WRONG, "not the expected whole number"),
    ("{n} kg", WRONG, "a mass"), ("{n} belts and 2", UNREADABLE, "format problem"),
])
def test_integer_part(bank, typed, status, text):
    variant = make_variant(bank.get("belts.v_belt_count"), 11)
    n = variant.answers["a"].value
    part = grade_variant(variant, {"a": typed.format(n=n, up=n + 3)}).parts[0]
    assert part.status == status and text in part.message


@pytest.mark.parametrize("typed, status", [("increase", None), ("DECREASE", None), ("maybe", UNREADABLE)])
def test_choice_part(bank, typed, status):
    variant = make_variant(bank.get("belts.v_belt_count"), 11)
    right = variant.answers["b"].value
    wrong = "decrease" if right == "increase" else "increase"
    part = grade_variant(variant, {"b": typed}).parts[1]
    if status is None:
        expected = CORRECT if typed.lower() == right else WRONG
        assert part.status == expected
        if expected == WRONG:
            assert part.mistake == "opposite" and typed.lower() == wrong
    else:
        assert part.status == status and "\"increase\" or \"decrease\"" in part.message


# ---- the sheet as a whole ----------------------------------------------------------------------

def test_code_mismatch_is_a_warning_and_the_students_own_sheet_is_graded(bank):
    sheet = sheet_for(bank, ["belts.flat_belt_power"])
    key = {"q1": {pid: a.text for pid, a in sheet.questions[0].variant.answers.items()}}
    result = grade_texts(sheet, key, code="ZZZZ-0000")
    assert result.percent == pytest.approx(100)
    assert result.code_mismatch and any("ZZZZ-0000" in w and sheet.code in w for w in result.warnings)


def test_lenient_keys_and_unknown_entries(bank):
    sheet = sheet_for(bank, ["belts.flat_belt_power"])
    v = sheet.questions[0].variant
    result = grade_texts(sheet, {"Q1": {"(a)": v.answers["a"].text, "B": v.answers["b"].text, "z": "1"},
                                 "q9": {"a": "1"}})
    assert [p.status for p in result.question("q1").parts[:2]] == [CORRECT, CORRECT]
    assert any("'z'" in w for w in result.warnings) and any("'q9'" in w for w in result.warnings)


def test_whole_question_unreadable(bank):
    sheet = sheet_for(bank, ["belts.flat_belt_power"])
    result = grade_sheet(sheet, Submission(None, "s001", problems={"q1": {"": "not part: answer lines"}}))
    assert {p.status for p in result.question("q1").parts} == {UNREADABLE}
    assert "format problem" in result.question("q1").parts[0].message
