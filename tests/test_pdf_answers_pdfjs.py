"""Sheets handed back as Firefox leaves them: filled in by pdf.js (Firefox's viewer) in headless Chromium and
saved, a class grades full marks; named mistakes typed into a box get their feedback; and pdf.js draws each
typed value in its box, from the appearance it wrote on saving.

Skipped, saying why, where no Chromium or no pdf.js is installed (.ci/run installs both: pdf.js with
`npm ci --prefix tests/pdfjs --omit=optional`, pinned by its lock file). With EXGEN_SCREENSHOTS set to a
folder, a filled page as pdf.js draws it is written there.
"""
from pathlib import Path

import pytest

from exgen.answertypes import answer_type
from graders.report import student_page
from graders.results import GRADED

from chromium import CHROMIUM, SHOTS, needs_chromium
from pdfjs_fill import MISSING, PdfJs, installed
from test_grade_issued import STUDENTS
from test_pdf_answers import grade, issued, key_answers, moodle_folder, sheet_of  # noqa: F401  (issued: a fixture)

playwright_api = pytest.importorskip("playwright.sync_api", reason="Playwright is not installed")
pytestmark = [needs_chromium, pytest.mark.skipif(not installed(), reason=MISSING)]


@pytest.fixture(scope="module")
def pdfjs():
    with playwright_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM)
        try:
            yield PdfJs(browser)
        finally:
            browser.close()


def test_a_class_filled_by_pdfjs_with_its_keys_grades_full_marks_from_a_bulk_download(issued, bank, tmp_path, pdfjs):
    handed = tmp_path / "download"
    for number, student in enumerate(STUDENTS):
        folder = handed / moodle_folder(student, number)
        folder.mkdir(parents=True)
        sheet = sheet_of(issued, bank, student.id)
        found = pdfjs.fill(issued / "students" / student.id / "sheet.pdf", key_answers(sheet), folder / "sheet.pdf")
        parts = {f"{q.slot}.{p.id}": p for q in sheet.questions for p in q.variant.template.parts}
        assert [name for name, _, _ in found] == list(parts)  # every box found, in reading order
        for name, kind, options in found:  # a choice is a drop-down of its choices, anything else a text box
            choices = answer_type(parts[name]).form_choices(parts[name])
            assert (kind, tuple(options)) == (("combobox", choices) if choices else ("text", ())), name
    batch = grade(issued, bank, handed)
    assert [(s.student.id, s.status, s.percent) for s in batch.sheets] == [(s.id, GRADED, 100.0) for s in STUDENTS]
    assert not batch.problems
    page = student_page(batch.assignment.title, batch.sheets[0])
    for name, text in key_answers(sheet_of(issued, bank, STUDENTS[0].id)).items():
        assert f"Read from your PDF's box {name}: `{text}`" in page


def test_named_mistakes_typed_into_the_boxes_by_pdfjs_get_their_feedback(issued, bank, tmp_path, pdfjs):
    handed = tmp_path / "handed"
    expected = {}
    for student in STUDENTS:
        sheet = sheet_of(issued, bank, student.id)
        values = key_answers(sheet)
        for question in sheet.questions:
            for part in question.variant.template.parts:
                recorded = question.variant.mistakes.get(part.id, {})
                named = [m.when for m in part.mistakes if m.when in recorded]
                if named:
                    values[f"{question.slot}.{part.id}"] = answer_type(part).text(recorded[named[0]], part)
                    expected[(student.id, question.slot, part.id)] = (named[0], recorded)
        (handed / student.id).mkdir(parents=True)
        pdfjs.fill(issued / "students" / student.id / "sheet.pdf", values, handed / student.id / "sheet.pdf")
    assert len(expected) >= 6
    batch = grade(issued, bank, handed)
    results = {(s.student.id, q.slot, p.part_id): p for s in batch.sheets for q in s.questions for p in q.parts}
    for where, (mistake, recorded) in expected.items():
        part = results[where]
        spec = next(q for q in sheet_of(issued, bank, where[0]).questions if q.slot == where[1]).variant.template \
            .part(where[2])
        same = [m.when for m in spec.mistakes if m.when in recorded
                and answer_type(spec).matches(recorded[m.when], recorded[mistake], spec)]
        assert part.status == "wrong" and part.mistake in same, (where, part.mistake, mistake)
        page = student_page(batch.assignment.title, next(s for s in batch.sheets if s.student.id == where[0]))
        assert part.message and part.message.split(".")[0][:40] in page


def test_pdfjs_draws_each_typed_value_in_its_box_and_nothing_in_an_empty_one(issued, bank, tmp_path, pdfjs):
    student = STUDENTS[0]
    sheet = sheet_of(issued, bank, student.id)
    values = key_answers(sheet)
    blank = next(iter(values))  # one box left empty
    del values[blank]
    pdfjs.fill(issued / "students" / student.id / "sheet.pdf", values, tmp_path / "filled.pdf")
    pages = pdfjs.render((tmp_path / "filled.pdf").read_bytes())
    ink = {name: dark for page in pages for name, dark in page["boxes"]}
    assert set(ink) == set(values) | {blank}
    assert ink[blank] == 0  # an empty box draws nothing above its line
    assert all(ink[name] >= 20 for name in values), ink  # every typed value is drawn (about 10 px a glyph)
    if SHOTS:
        shown = next(i for i, page in enumerate(pages) if len(page["boxes"]) >= 3)
        Path(SHOTS, "sheet-filled-pdfjs.png").write_bytes(pages[shown]["png"])
