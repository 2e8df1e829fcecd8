"""Printing a class set: every sheet in roster order in one PDF (each starting on a new leaf when
printed on both sides), every key in another; and progress a log can show."""
import io
from pathlib import Path

import pytest
from pypdf import PdfReader

from exgen.issue.assignment import Assignment, QuestionSpec, Student
from exgen.issue.generate import generate
from exgen.render.bundle import join_pdfs
from exgen.runtime.progress import _lines, progress

SECRET = b"a course secret used only by these tests"


@pytest.fixture(scope="module")
def issued(tmp_path_factory, bank):
    assignment = Assignment("print-test", "Printing", (QuestionSpec("q1", "belts.flat_belt_power"),))
    students = [Student("S2"), Student("S1"), Student("S3")]  # roster order, not sorted
    out = tmp_path_factory.mktemp("issued") / "out"
    generate(assignment, students, bank, SECRET, out, print_bundle=True)
    return out, students


def _text(reader, page):
    return reader.pages[page].extract_text() or ""


def test_the_bundle_holds_every_sheet_in_roster_order_each_on_a_new_leaf(issued):
    out, students = issued
    bundle = PdfReader(out / "print" / "sheets.pdf")
    page = 0
    for student in students:
        own = PdfReader(out / "students" / student.id / "sheet.pdf")
        assert student.id in _text(bundle, page)
        for i in range(len(own.pages)):
            assert _text(bundle, page + i) == _text(own, i)
        page += len(own.pages) + len(own.pages) % 2
        if len(own.pages) % 2:
            assert _text(bundle, page - 1).strip() == ""  # the blank back of an odd sheet
    assert page == len(bundle.pages) and page % 2 == 0


def test_the_keys_bundle_holds_every_key_in_the_same_order(issued):
    out, students = issued
    keys = PdfReader(out / "print" / "keys.pdf")
    firsts = [i for i in range(len(keys.pages)) if "Instructor key" in _text(keys, i) and
              any(s.id in _text(keys, i) for s in students)]
    order = [next(s.id for s in students if s.id in _text(keys, i)) for i in firsts]
    assert list(dict.fromkeys(order)) == [s.id for s in students]


def test_joining_without_duplex_keeps_the_pages_as_they_are(issued, tmp_path):
    out, students = issued
    paths = [out / "students" / s.id / "sheet.pdf" for s in students]
    pages = join_pdfs(paths, tmp_path / "all.pdf", duplex=False)
    assert pages == sum(len(PdfReader(p).pages) for p in paths)


class Clock:
    """A clock that advances a second each time it is read."""

    def __init__(self):
        self.now = 0.0

    def __call__(self):
        self.now += 1.0
        return self.now


def test_without_a_terminal_a_long_run_says_each_tenth_and_how_long_it_took():
    stream = io.StringIO()
    assert list(_lines(range(20), 20, "writing", stream, Clock())) == list(range(20))
    lines = stream.getvalue().splitlines()
    assert lines[0] == "writing: 2/20 (10 %)" and lines[-2] == "writing: 18/20 (90 %)"
    assert len(lines) == 10 and lines[-1] == "writing: 20/20 done in 21.0 s"


def test_a_quick_run_makes_no_noise():
    stream = io.StringIO()
    assert list(progress(range(50), 50, "drawing", stream)) == list(range(50))
    assert stream.getvalue() == ""


def test_print_needs_the_pdfs(tmp_path, capsys, monkeypatch):
    from exgen.cli import main

    monkeypatch.setenv("EXGEN_SECRET", "5f0c2d9a8b7e6f1a3c4d5e6f708192a3b4c5d6e7f8091a2b")
    assert main(["generate", "examples/tutorial1.yaml", "--out", str(tmp_path / "o"), "--print", "--no-pdf"]) == 1
    assert "--print" in capsys.readouterr().err
