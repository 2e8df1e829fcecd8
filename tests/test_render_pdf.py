"""PDF sheets and keys: Typst source from layouts, compiled in-process, byte-for-byte repeatable."""
import pytest

from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.mathtext import escape_typst
from exgen.render.pdf import PdfError, compile_pdf, key_pdf, key_typst, sheet_pdf, sheet_typst

TEMPLATES = ("belts.flat_belt_power", "belts.compound_drive", "belts.v_belt_count")


@pytest.fixture(scope="module")
def sheet(bank):
    specs = tuple(QuestionSpec(f"q{i}", t) for i, t in enumerate(TEMPLATES, start=1) if t in {x.id for x in bank})
    assignment = Assignment(id="tut1", title="Tutorial 1", questions=specs, course="BMCM 2723", due="1 Dec")
    return build_sheet(assignment, Student("A123", "Nur Aina"), bank, b"x" * 32)


def test_sheet_pdf_is_a_repeatable_pdf(sheet):
    first = sheet_pdf(sheet)
    assert first.startswith(b"%PDF")
    assert sheet_pdf(sheet) == first


def test_key_pdf_is_a_repeatable_pdf(sheet):
    first = key_pdf(sheet)
    assert first.startswith(b"%PDF")
    assert key_pdf(sheet) == first


def test_sheet_source_has_the_student_questions_and_figures(sheet):
    source = sheet_typst(sheet)
    for expected in ("Nur Aina", "A123", escape_typst(sheet.code), "1 Dec", "Page #counter(page).display()"):
        assert expected in source
    for q in sheet.questions:
        assert f"#question-heading({q.number}," in source
        for part in q.variant.template.parts:
            assert f"([{part.id}], [" in source
    figures = sum(1 for q in sheet.questions if q.variant.template.figure)
    assert source.count("#svg-figure(") == figures and 'format: "svg"' in source


def test_sheet_source_has_no_answers(sheet):
    source = sheet_typst(sheet)
    assert "INSTRUCTOR KEY" not in source and "Worked solution" not in source
    for q in sheet.questions:
        for answer in q.variant.answers.values():
            assert f"[*{escape_typst(answer.text)}*]" not in source


def test_key_source_has_answers_and_working(sheet):
    source = key_typst(sheet)
    assert "INSTRUCTOR KEY" in source
    assert source.count("#section[Worked solution]") == len(sheet.questions)
    for q in sheet.questions:
        for answer in q.variant.answers.values():
            assert f"[*{escape_typst(answer.text)}*]" in source


def test_markup_in_names_is_printed_not_run(bank):
    assignment = Assignment(id="t", title='#panic("no") *t*', questions=(QuestionSpec("q1", "belts.drive_geometry"),),
                            course="$x$ <y> @z")
    sheet = build_sheet(assignment, Student("s1", "_Ann_ [Lee] // not a comment"), bank, b"y" * 32)
    assert sheet_pdf(sheet).startswith(b"%PDF")
    assert r"\_Ann\_ \[Lee\] /\/ not a comment" in sheet_typst(sheet)


def test_typst_failure_names_the_document():
    with pytest.raises(PdfError, match="cannot typeset the test: "):
        compile_pdf("#unknown-function()", "the test")


def test_a_failed_document_leaves_the_next_one_whole(sheet):
    """One compiler serves a thread's documents: a document Typst refused must not stay in it."""
    good = sheet_pdf(sheet)
    with pytest.raises(PdfError):
        compile_pdf("#unknown-function()", "the test")
    assert sheet_pdf(sheet) == good


def test_each_thread_typesets_the_same_bytes(sheet):
    from concurrent.futures import ThreadPoolExecutor

    source = sheet_typst(sheet)
    with ThreadPoolExecutor(3) as threads:
        made = list(threads.map(lambda _: compile_pdf(source), range(3)))
    assert made[0] == made[1] == made[2] == compile_pdf(source)
