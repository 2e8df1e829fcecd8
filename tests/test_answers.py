"""Answer forms and reading answer files back (YAML, JSON, CSV): answers stay the text typed."""
import json

import pytest
import yaml

from exgen.errors import SubmissionError
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.answer_form import answer_form
from graders.answers import read_submission

SECRET = b"x" * 32


def sheet_for(bank, templates=("belts.flat_belt_power",), student=Student("s001", "Ann Lee"), title="Homework 1"):
    questions = tuple(QuestionSpec(f"q{i}", t) for i, t in enumerate(templates, start=1))
    return build_sheet(Assignment("hw1", title, questions), student, bank, SECRET)


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_untouched_form_reads_as_all_blank(bank, tmp_path):
    sheet = sheet_for(bank, [t.id for t in bank])
    sub = read_submission(write(tmp_path, "s001.yaml", answer_form(sheet)))
    assert (sub.student, sub.assignment, sub.code) == ("s001", "hw1", sheet.code)
    assert sub.problems == {} and sub.warnings == ()
    for question in sheet.questions:
        assert sub.answers[question.slot] == {p.id: "" for p in question.variant.template.parts}


def test_form_lines_give_ask_and_unit(bank):
    form = answer_form(sheet_for(bank))
    assert '    a: ""   # angle of contact on the smaller pulley [deg]' in form
    assert "[kW]" in form and "[N·m]" in form
    assert "a bare number is read in the unit" in form.lower()
    assert "slot,part,answer" in form  # the CSV alternative is documented


def test_form_shows_integer_and_choice_parts(bank):
    form = answer_form(sheet_for(bank, ["belts.v_belt_count"]))
    assert "[whole number]" in form and "[one of: increase, decrease]" in form


@pytest.mark.parametrize("text", [
    "a # b: c", "quote \" and ' and \\", "line\nbreak\r\nand\u2028sep\u2029x\x85y", "tab\there", "\x00\x07\x1b[31m",
    "- [ ] { } & * ! | > % @ `", "emoji \U0001f4a5 and \ufeff bom", "---\n...", "\ud800 lone surrogate",
])
def test_form_is_valid_yaml_whatever_the_text(bank, tmp_path, text):
    sheet = sheet_for(bank, student=Student("s001", text), title=text)
    form = answer_form(sheet)
    data = yaml.safe_load(form.encode("utf-8", "surrogatepass").decode("utf-8", "replace"))
    assert data["student"] == "s001" and set(data["answers"]["q1"]) == set("abcdefg")
    sub = read_submission(write(tmp_path, "f.yaml", form.encode("utf-8", "replace").decode("utf-8")))
    assert sub.answers["q1"]["a"] == ""


@pytest.mark.parametrize("typed, kept", [
    ("168.8 deg", "168.8 deg"),
    ("1.0e+3", "1.0e+3"),     # YAML 1.1 would read a float
    ("1e3", "1e3"),
    ("0x10", "0x10"),         # would be int 16
    ("yes", "yes"),           # would be True
    ("1_000", "1_000"),
    ("0o17", "0o17"),
    ("'5 kN'", "5 kN"),
    ('"5 kN"', "5 kN"),
    ("5 m/s # my comment", "5 m/s"),
    ("", ""),
    ("~", ""),
    ("null", ""),
    ("'null'", "null"),
    (".inf", ".inf"),
    ("2001-12-14", "2001-12-14"),  # would be a date
])
def test_yaml_answers_keep_the_text_typed(tmp_path, typed, kept):
    path = write(tmp_path, "s.yaml", f"student: s001\nanswers:\n  q1:\n    a: {typed}\n")
    assert read_submission(path).answers["q1"]["a"] == kept


@pytest.mark.parametrize("value, kept", [
    ('"168.8 deg"', "168.8 deg"), ("1.0e+3", "1.0e+3"), ("1000", "1000"), ("-0.5", "-0.5"),
    ("null", ""), ("NaN", "NaN"), ("Infinity", "Infinity"),
])
def test_json_answers_keep_the_text_typed(tmp_path, value, kept):
    path = write(tmp_path, "s.json", '{"student": "s001", "answers": {"q1": {"a": %s}}}' % value)
    assert read_submission(path).answers["q1"]["a"] == kept


def test_csv_with_header_rows_and_title_row(tmp_path):
    path = write(tmp_path, "s.csv", "\ufeffstudent,s001\ncode,ABCD-1234\nslot,part,answer\nq1,a,168.8 deg\n"
                                    "q1,b,\"5,24 m/s\"\nq2,a,1,500\n\nq1,c\n")
    sub = read_submission(path)
    assert (sub.student, sub.code) == ("s001", "ABCD-1234")
    assert sub.answers == {"q1": {"a": "168.8 deg", "b": "5,24 m/s"}, "q2": {"a": "1,500"}}
    assert any("line 8" in w for w in sub.warnings)  # the short row is reported, not dropped silently


def test_csv_with_semicolons(tmp_path):
    path = write(tmp_path, "s.csv", "student;s001\nq1;a;168,8 deg\n")
    assert read_submission(path).answers == {"q1": {"a": "168,8 deg"}}


@pytest.mark.parametrize("suffix, text", [
    (".yaml", "student: s001\nanswers:\n  q1:\n    a: [1, 2]\n    b: {x: 1}\n    c: 5 N\n"),
    (".json", '{"student": "s001", "answers": {"q1": {"a": [1, 2], "b": {"x": 1}, "c": "5 N"}}}'),
])
def test_non_scalar_answer_is_unreadable_for_that_part_only(tmp_path, suffix, text):
    sub = read_submission(write(tmp_path, "s" + suffix, text))
    assert sub.answers["q1"] == {"c": "5 N"}
    assert "a list" in sub.problems["q1"]["a"] and "a mapping" in sub.problems["q1"]["b"]
    if suffix == ".yaml":
        assert "line 4" in sub.problems["q1"]["a"]


def test_question_that_is_not_a_mapping_is_unreadable_as_a_whole(tmp_path):
    sub = read_submission(write(tmp_path, "s.yaml", "student: s001\nanswers:\n  q1: 5 N\n  q2: [a, b]\n"))
    assert "text" in sub.problems["q1"][""] and "a list" in sub.problems["q2"][""]


def test_json_booleans_are_unreadable_answers(tmp_path):
    sub = read_submission(write(tmp_path, "s.json", '{"answers": {"q1": {"a": true}}}'))
    assert "true/false" in sub.problems["q1"]["a"]


def test_questions_at_the_top_level_without_answers_key(tmp_path):
    sub = read_submission(write(tmp_path, "s.yaml", "student: s001\nq1:\n  a: 5 N\n"))
    assert sub.answers == {"q1": {"a": "5 N"}}


def test_duplicate_keys_warn_and_the_last_wins(tmp_path):
    sub = read_submission(write(tmp_path, "s.yaml", "answers:\n  q1:\n    a: 1\n    a: 2\n"))
    assert sub.answers["q1"]["a"] == "2" and any("twice" in w for w in sub.warnings)
    sub = read_submission(write(tmp_path, "s.json", '{"answers": {"q1": {"a": "1", "a": "2"}}}'))
    assert sub.answers["q1"]["a"] == "2" and any("twice" in w for w in sub.warnings)


def test_header_that_is_not_text_is_ignored_with_a_warning(tmp_path):
    sub = read_submission(write(tmp_path, "s.yaml", "student: [a, b]\nanswers: {}\n"))
    assert sub.student == "" and any("student" in w for w in sub.warnings)


def test_utf16_with_bom_is_read(tmp_path):
    path = tmp_path / "s.yaml"
    path.write_bytes("student: s001\nanswers:\n  q1:\n    a: 5 N\n".encode("utf-16"))
    assert read_submission(path).answers == {"q1": {"a": "5 N"}}


def test_json_form_round_trip(tmp_path):
    data = {"student": "s001", "assignment": "hw1", "code": "X", "answers": {"q1": {"a": "1 N"}}}
    assert read_submission(write(tmp_path, "s.json", json.dumps(data))).answers == {"q1": {"a": "1 N"}}


def test_unknown_suffix_is_refused(tmp_path):
    with pytest.raises(SubmissionError, match="not an answer file"):
        read_submission(write(tmp_path, "s.txt", "a: 1"))


def test_missing_file_names_the_file(tmp_path):
    with pytest.raises(SubmissionError, match="nope.yaml"):
        read_submission(tmp_path / "nope.yaml")
