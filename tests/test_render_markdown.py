"""Markdown sheets and keys: what a student sees, and what only the instructor sees."""
import re

import pytest

from exgen import units
from exgen.answertypes import answer_type
from exgen.figures import draw_figures
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.markdown import key_markdown, sheet_markdown
from exgen.render.mathtext import text_to_markdown
from exgen.render.targets import MARKDOWN
from exgen.render.unicode_math import typeset_minus
from exgen.solve.variant import make_variant

SECRET = b"x" * 32


@pytest.fixture(scope="module")
def sheet(bank):
    specs = tuple(QuestionSpec(f"q{i}", t.id, 10.0 if i == 2 else None) for i, t in enumerate(bank, start=1))
    assignment = Assignment(id="tut1", title="Tutorial 1: Belts", questions=specs, course="BMCM 2723",
                            due="2026-12-01", instructions="Use $g = 9.81$ m/s² and *four* figures.")
    return build_sheet(assignment, Student("A123", "Nur Aina"), bank, SECRET)


@pytest.fixture(scope="module")
def figures(sheet):
    return draw_figures(sheet)


@pytest.fixture(scope="module")
def student_md(sheet, figures):
    return sheet_markdown(sheet, figures)


@pytest.fixture(scope="module")
def key_md(sheet, figures):
    return key_markdown(sheet, figures)


def _numbers(text):
    return set(re.findall(r"\d+(?:\.\d+)?", text))


def test_header(sheet, student_md):
    for expected in ("Nur Aina", "A123", sheet.code, "2026-12-01", "BMCM 2723", "Tutorial 1: Belts",
                     "Use $g = 9.81$ m/s² and \\*four\\* figures."):
        assert expected in student_md
    assert f"{sheet.points:g} marks" in student_md


def test_every_statement_ask_and_figure(sheet, figures, student_md):
    for q in sheet.questions:
        v = q.variant
        assert f"## Question {q.number} (" in student_md
        assert text_to_markdown(v.statement) in student_md
        for p in v.params:
            if f"{{{{ {p.name} }}}}" in v.template.statement:
                assert typeset_minus(str(p)) in student_md  # a negative given with the minus sign
        for part in v.template.parts:
            assert f"**({part.id})** {text_to_markdown(v.asks[part.id])}" in student_md
        if figures[q.slot].sheet:
            assert f"]({figures[q.slot].sheet.name})" in student_md


def test_marks_follow_the_question_scale(sheet, student_md):
    scaled = sheet.questions[1]
    assert f"## Question 2 (10 marks)" in student_md
    first = scaled.variant.template.parts[0]
    assert f"({units.format_number(first.points * scaled.scale, 3).rstrip('0').rstrip('.')} mark" in student_md


def test_no_answer_on_the_sheet(sheet, student_md):
    assert "INSTRUCTOR" not in student_md and "Worked solution" not in student_md
    printed = _numbers(student_md.split("## Question")[0])
    for q in sheet.questions:
        printed |= _numbers(q.variant.statement) | set().union(*(_numbers(a) for a in q.variant.asks.values()))
    for q in sheet.questions:
        for answer in q.variant.answers.values():
            # a whole number, a word or a zero can occur in prose by chance
            if isinstance(answer.value, float) and answer.value != 0:
                assert answer.text not in student_md
                number = units.format_number(answer.value, 4)
                assert number in printed or number not in _numbers(student_md), (q.slot, answer.part.id)


def test_key_holds_answers_given_data_and_working(sheet, key_md):
    assert key_md.startswith("# INSTRUCTOR KEY")
    for q in sheet.questions:
        assert q.variant.template.id.replace("_", "\\_") in key_md
        for answer in q.variant.answers.values():
            assert f"**{answer_type(answer.part).key_text(answer, MARKDOWN)}**" in key_md  # a formula prints as math
        # this question's own section: another question's given may read the same (t_1 = 0.6 s in two of them)
        section = re.search(rf"^## Question {q.number} .*?(?=^## |\Z)", key_md, re.M | re.S).group(0)
        for p in q.variant.params:
            assert (f"| ${p.symbol}$ | {typeset_minus(str(p))}" in section) == (p.name not in q.variant.unused), \
                (q.variant.template.id, p.name)
    assert key_md.count("### Worked solution") == len(sheet.questions)


def test_student_text_is_escaped(bank):
    assignment = Assignment(id="t", title="A *title* with _marks_", questions=(QuestionSpec("q1", "belts.drive_geometry"),))
    sheet = build_sheet(assignment, Student("s1", "[Robert] <Bobby> | Tables"), bank, SECRET)
    md = sheet_markdown(sheet, {})
    assert r"A \*title\* with \_marks\_" in md and r"\[Robert\] \<Bobby\> \| Tables" in md


def test_same_sheet_same_markdown(sheet, figures, student_md):
    assert sheet_markdown(sheet, figures) == student_md


def test_key_of_a_hand_built_variant(bank):
    from exgen.issue.assignment import Question, Sheet
    from exgen.solve.variant import build_variant

    template = bank.get("belts.drive_geometry")
    values = {p.name: p.exact for p in make_variant(template, 2).params}
    variant = build_variant(template, values)
    sheet = Sheet(Assignment(id="t", title="T", questions=()), Student("s1"), "CODE", (Question(1, "q1", variant, 4.0),))
    key = key_markdown(sheet, {})
    assert "seed None" not in key and "belts.drive\\_geometry" in key
