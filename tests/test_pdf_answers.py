"""Sheets handed back as PDFs: filled in by PDFium (Chrome's and Edge's viewer) and saved, a class grades as
its answer files would; named mistakes typed into a box get their feedback; the document's identity is
checked as an answer file's; a PDF without typed answers, and every kind of hostile PDF, is listed with one
plain reason, inside the time bound of any answer file."""
import io
import time
import zlib
from pathlib import Path

import pypdfium2 as pdfium
import pypdfium2.raw as pdfium_raw
import pytest
from pypdf import PdfReader, PdfWriter
from pypdf.generic import DictionaryObject, NameObject, TextStringObject

from exgen.answertypes import answer_type
from exgen.errors import SubmissionError
from exgen.issue.assignment import build_sheet, load_assignment
from exgen.issue.generate import generate
from exgen.issue.manifest import read_manifest
from graders import pdf_form
from graders.answers import read_submission
from graders.grade import grade_issued
from graders.report import student_page
from graders.results import GRADED, PROBLEM_FILE, UNREADABLE_FILE
from pdfium_fill import fill
from test_grade_issued import EXAMPLES, STUDENTS

SECRET = b"pdf answers: 0a9b8c7d6e5f4a3b2c1d"


@pytest.fixture(scope="module")
def issued(tmp_path_factory, bank):
    """Tutorial 1 (numbers, a whole number and a drop-down) issued with its sheet PDFs."""
    root = tmp_path_factory.mktemp("issued-pdf")
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    generate(assignment, STUDENTS, bank, SECRET, root / "out", pdf=True, secret_source="a test")
    return root / "out"


def sheet_of(issued, bank, student_id):
    manifest = read_manifest(issued)
    return build_sheet(manifest.assignment, next(s for s in manifest.students if s.id == student_id), bank, SECRET)


def key_answers(sheet) -> dict[str, str]:
    """Every box's key answer, as the key prints it (a choice as its word)."""
    return {f"{q.slot}.{p}": a.text for q in sheet.questions for p, a in q.variant.answers.items()}


def moodle_folder(student, number: int) -> str:
    """Where Moodle's bulk download puts a student's files."""
    return f"{student.name}_{10000 + number}_assignsubmission_file_"


def grade(issued, bank, folder):
    return grade_issued(read_manifest(issued), bank, SECRET, folder)


@pytest.mark.parametrize("incremental", [False, True], ids=["rewritten", "incremental"])
def test_a_class_filled_by_pdfium_with_its_keys_grades_full_marks_from_a_bulk_download(issued, bank, tmp_path,
                                                                                       incremental):
    handed = tmp_path / "download"
    for number, student in enumerate(STUDENTS):
        folder = handed / moodle_folder(student, number)
        folder.mkdir(parents=True)
        sheet = sheet_of(issued, bank, student.id)
        typed = fill(issued / "students" / student.id / "sheet.pdf", key_answers(sheet), folder / "sheet.pdf",
                     incremental=incremental)
        assert typed == key_answers(sheet)  # every box found, every answer typed
    batch = grade(issued, bank, handed)
    assert [(s.student.id, s.status, s.percent) for s in batch.sheets] == [(s.id, GRADED, 100.0) for s in STUDENTS]
    assert not batch.problems
    page = student_page(batch.assignment.title, batch.sheets[0])
    sheet = sheet_of(issued, bank, STUDENTS[0].id)
    for name, text in key_answers(sheet).items():  # the student sees their own typing, box by box
        assert f"Read from your PDF's box {name}: `{text}`" in page


def test_named_mistakes_typed_into_the_boxes_get_their_feedback(issued, bank, tmp_path):
    handed = tmp_path / "handed"
    expected = {}
    for student in STUDENTS:
        sheet = sheet_of(issued, bank, student.id)
        values = key_answers(sheet)
        for question in sheet.questions:
            for part in question.variant.template.parts:
                recorded = question.variant.mistakes.get(part.id, {})
                named = [m.when for m in part.mistakes if m.when in recorded]
                if named:  # the first listed mistake this variant records, typed as the key would print it
                    values[f"{question.slot}.{part.id}"] = answer_type(part).text(recorded[named[0]], part)
                    expected[(student.id, question.slot, part.id)] = named[0]
        (handed / student.id).mkdir(parents=True)
        fill(issued / "students" / student.id / "sheet.pdf", values, handed / student.id / "sheet.pdf")
    assert len(expected) >= 6
    batch = grade(issued, bank, handed)
    results = {(s.student.id, q.slot, p.part_id): p for s in batch.sheets for q in s.questions for p in q.parts}
    for where, mistake in expected.items():
        part = results[where]
        assert part.status == "wrong" and part.mistake, where
        sheet = sheet_of(issued, bank, where[0])
        spec = next(q for q in sheet.questions if q.slot == where[1]).variant.template.part(where[2])
        recorded = next(q for q in sheet.questions if q.slot == where[1]).variant.mistakes[where[2]]
        same = [m.when for m in spec.mistakes if m.when in recorded
                and answer_type(spec).matches(recorded[m.when], recorded[mistake], spec)]
        assert part.mistake in same, (where, part.mistake, mistake)
        page = student_page(batch.assignment.title, next(s for s in batch.sheets if s.student.id == where[0]))
        assert part.message and part.message.split(".")[0][:40] in page


def test_a_pdf_in_another_students_place_or_with_another_code_is_a_problem_file(issued, bank, tmp_path):
    handed = tmp_path / "handed"
    first, second, third = STUDENTS
    (handed / second.id).mkdir(parents=True)
    fill(issued / "students" / first.id / "sheet.pdf", key_answers(sheet_of(issued, bank, first.id)),
         handed / second.id / "sheet.pdf")  # first's sheet, handed in as second's
    writer = PdfWriter(clone_from=issued / "students" / third.id / "sheet.pdf")
    writer.add_metadata({pdf_form.INFO_KEYS["code"]: "0000-0000"})
    (handed / third.id).mkdir()
    writer.write(handed / third.id / "sheet.pdf")
    batch = grade(issued, bank, handed)
    status = {s.student.id: s.status for s in batch.sheets}
    assert status[second.id] == PROBLEM_FILE and status[third.id] == PROBLEM_FILE
    reasons = {p.student: p.reason for p in batch.problems}
    assert f"says `student: {first.id}` inside" in reasons[second.id]
    assert "carries the sheet code 0000-0000" in reasons[third.id]


def test_a_printed_or_flattened_pdf_is_listed_with_a_plain_reason(issued, bank, tmp_path):
    from exgen.render.pdf import sheet_pdf

    handed = tmp_path / "handed"
    first, second, _ = STUDENTS
    (handed / first.id).mkdir(parents=True)
    (handed / first.id / "scan.pdf").write_bytes(sheet_pdf(sheet_of(issued, bank, first.id), form=False))
    (handed / second.id).mkdir()
    fill(issued / "students" / second.id / "sheet.pdf", key_answers(sheet_of(issued, bank, second.id)),
         tmp_path / "filled.pdf")
    document = pdfium.PdfDocument(str(tmp_path / "filled.pdf"))
    document.init_forms()
    for i in range(len(document)):  # as "print to PDF" does: the typing becomes part of the page
        assert pdfium_raw.FPDFPage_Flatten(document[i].raw, pdfium_raw.FLAT_PRINT) != pdfium_raw.FLATTEN_FAIL
    document.save(str(handed / second.id / "sheet.pdf"))
    document.close()
    batch = grade(issued, bank, handed)
    status = {s.student.id: s.status for s in batch.sheets}
    assert status[first.id] == status[second.id] == UNREADABLE_FILE
    reasons = {p.student: p.reason for p in batch.problems}
    assert reasons[first.id] == reasons[second.id] == pdf_form.NO_FORM


def test_a_sheet_handed_back_untouched_grades_blank_with_a_note(issued, bank, tmp_path):
    handed = tmp_path / "handed"
    handed.mkdir()
    student = STUDENTS[0]
    (handed / f"{student.id}.pdf").write_bytes((issued / "students" / student.id / "sheet.pdf").read_bytes())
    batch = grade(issued, bank, handed)
    sheet = batch.sheets[0]
    assert sheet.status == GRADED and sheet.points == 0 and pdf_form.ALL_EMPTY in sheet.warnings
    assert "Your PDF's box q1.a was empty" in student_page(batch.assignment.title, sheet)


# ---- hostile PDFs -----------------------------------------------------------------------------------

def raw_pdf(objects: dict[int, bytes], trailer: bytes = b"/Root 1 0 R") -> bytes:
    """A PDF of these objects (number -> body) with a classic cross-reference table."""
    out = io.BytesIO()
    out.write(b"%PDF-1.7\n")
    offsets = {}
    for number in sorted(objects):
        offsets[number] = out.tell()
        out.write(b"%d 0 obj\n%s\nendobj\n" % (number, objects[number]))
    start = out.tell()
    size = max(objects) + 1
    out.write(b"xref\n0 %d\n0000000000 65535 f\r\n" % size)
    for n in range(1, size):
        out.write(b"%010d 00000 n\r\n" % offsets[n] if n in offsets else b"0000000000 65535 f\r\n")
    out.write(b"trailer\n<< /Size %d %s >>\nstartxref\n%d\n%%%%EOF\n" % (size, trailer, start))
    return out.getvalue()


def catalog(fields: bytes) -> dict[int, bytes]:
    return {1: b"<< /Type /Catalog /Pages 2 0 R /AcroForm << /Fields %s >> >>" % fields,
            2: b"<< /Type /Pages /Kids [] /Count 0 >>"}


def many_fields() -> bytes:
    count = pdf_form.MAX_ENTRIES + 500
    objects = catalog(b"[" + b" ".join(b"%d 0 R" % (10 + i) for i in range(count)) + b"]")
    objects.update({10 + i: b"<< /T (f%d) /FT /Tx /V (1) >>" % i for i in range(count)})
    return raw_pdf(objects)


def cyclic_fields() -> bytes:
    """A question field whose kids are itself, its parent and a part that lists the question again."""
    objects = catalog(b"[3 0 R]")
    objects[3] = b"<< /T (q1) /Kids [3 0 R 4 0 R] >>"
    objects[4] = b"<< /T (a) /FT /Tx /V (168.8 deg) /Parent 3 0 R /Kids [3 0 R] >>"
    return raw_pdf(objects)


def deep_fields() -> bytes:
    depth = 60
    objects = catalog(b"[10 0 R]")
    objects.update({10 + i: b"<< /T (f%d) /Kids [%d 0 R] >>" % (i, 11 + i) for i in range(depth)})
    objects[10 + depth] = b"<< /T (last) /FT /Tx /V (1) >>"
    return raw_pdf(objects)


def deep_arrays() -> bytes:
    objects = catalog(b"[3 0 R]")
    objects[3] = b"<< /T (q1) /FT /Tx /V " + b"[" * 20000 + b"]" * 20000 + b" >>"
    return raw_pdf(objects)


def decompression_bomb() -> bytes:
    """The form's field inside an object stream that inflates to 64 MB (its compressed bytes: about 64 KB)."""
    header = b"5 0 "
    body = b"<< /T (q1) /FT /Tx /V (1) >>" + b" " * (64 * 1024 * 1024)
    packed = zlib.compress(header + body, 9)
    out = io.BytesIO()
    out.write(b"%PDF-1.7\n")
    offsets = {}
    for number, body_bytes in ((1, b"<< /Type /Catalog /Pages 2 0 R /AcroForm << /Fields [5 0 R] >> >>"),
                               (2, b"<< /Type /Pages /Kids [] /Count 0 >>"),
                               (4, b"<< /Type /ObjStm /N 1 /First %d /Filter /FlateDecode /Length %d >>\nstream\n"
                                % (len(header), len(packed)) + packed + b"\nendstream")):
        offsets[number] = out.tell()
        out.write(b"%d 0 obj\n%s\nendobj\n" % (number, body_bytes))
    offsets[6] = out.tell()
    rows = [(0, 0, 65535), (1, offsets[1], 0), (1, offsets[2], 0), (0, 0, 0), (1, offsets[4], 0), (2, 4, 0),
            (1, offsets[6], 0)]
    table = b"".join(bytes([t]) + a.to_bytes(4, "big") + b.to_bytes(2, "big") for t, a, b in rows)
    out.write(b"6 0 obj\n<< /Type /XRef /Size 7 /W [1 4 2] /Root 1 0 R /Length %d >>\nstream\n" % len(table)
              + table + b"\nendstream\nendobj\n")
    out.write(b"startxref\n%d\n%%%%EOF\n" % offsets[6])
    return out.getvalue()


def sheet_bytes(issued) -> bytes:
    return (issued / "students" / STUDENTS[0].id / "sheet.pdf").read_bytes()


def encrypted(issued) -> bytes:
    return rewritten(issued, lambda w: w.encrypt("secret", algorithm="RC4-128"))


def script(source: str) -> DictionaryObject:
    return DictionaryObject({NameObject("/S"): NameObject("/JavaScript"), NameObject("/JS"): TextStringObject(source)})


def rewritten(issued, change) -> bytes:
    """The sheet read and written again by pypdf, `change(writer)` made first."""
    writer = PdfWriter(clone_from=io.BytesIO(sheet_bytes(issued)))
    change(writer)
    out = io.BytesIO()
    writer.write(out)
    return out.getvalue()


def with_javascript(issued) -> bytes:
    return rewritten(issued, lambda w: w.root_object.__setitem__(NameObject("/OpenAction"), script("app.alert(1)")))


def with_field_action(issued) -> bytes:
    def change(writer):  # a keystroke script on the first box
        box = writer.root_object["/AcroForm"]["/Fields"][0].get_object()["/Kids"][0].get_object()
        box[NameObject("/AA")] = DictionaryObject({NameObject("/K"): script("app.beep()")})
    return rewritten(issued, change)


def broken_xref(issued) -> bytes:
    """Every cross-reference keyword and offset spoiled: only a scan of the whole file finds the objects."""
    data = sheet_bytes(issued)
    return data.replace(b"startxref", b"startxreF").replace(b"\nxref\n", b"\nxrep\n")


def wrong_offsets(issued) -> bytes:
    """The last cross-reference offset pointing into the middle of the file (a viewer's botched save)."""
    data = sheet_bytes(issued)
    at = data.rindex(b"startxref")
    return data[:at] + b"startxref\n%d\n%%%%EOF\n" % (len(data) // 2)


HOSTILE = {  # name: (how to make it, what the reason must say; None: read, or refused with any plain reason)
    "huge": (lambda issued: b"%PDF-1.7\n" + b"%" * (pdf_form.MAX_PDF_BYTES + 1), "a sheet may be at most"),
    "not a PDF": (lambda issued: b"PK\x03\x04 a zip file named .pdf", "not a PDF"),
    "truncated": (lambda issued: sheet_bytes(issued)[: len(sheet_bytes(issued)) // 3], None),
    "encrypted": (encrypted, pdf_form.ENCRYPTED),
    "JavaScript": (with_javascript, pdf_form.SCRIPT),
    "a script on a box": (with_field_action, pdf_form.SCRIPT),
    "broken xref": (broken_xref, None),
    "wrong xref offset": (wrong_offsets, None),
    "thousands of fields": (lambda issued: many_fields(), pdf_form.TOO_MANY),
    "cyclic fields": (lambda issued: cyclic_fields(), None),
    "fields nested deep": (lambda issued: deep_fields(), pdf_form.TOO_DEEP),
    "arrays nested deep": (lambda issued: deep_arrays(), None),
    "decompression bomb": (lambda issued: decompression_bomb(), "not a readable PDF"),
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_a_hostile_pdf_is_read_or_refused_with_one_plain_reason(issued, tmp_path, name):
    make, reason = HOSTILE[name]
    path = tmp_path / "A21003.pdf"
    path.write_bytes(make(issued))
    try:
        submission = read_submission(path)
    except SubmissionError as exc:
        assert exc.detail and "\n" not in exc.detail and len(exc.detail) < 300, exc.detail
        if reason is not None:
            assert reason in exc.detail, exc.detail
        return
    assert reason is None, f"read, though it should be refused: {reason}"
    assert isinstance(submission.answers, dict)


def test_a_cycle_of_fields_is_read_once(tmp_path):
    path = tmp_path / "A21003.pdf"
    path.write_bytes(cyclic_fields())
    assert read_submission(path).answers == {"q1": {"a": "168.8 deg"}}


def test_the_time_bound_stops_the_read_inside_pypdf(issued, tmp_path):
    """The bound is checked on every call, pypdf's included: a read given no time at all stops at once."""
    path = tmp_path / "A21003.pdf"
    path.write_bytes(sheet_bytes(issued))
    with pytest.raises(SubmissionError, match="took too long"):
        pdf_form.load_pdf(path, None, time.perf_counter() - 1)
    assert read_submission(path).student == STUDENTS[0].id  # with the usual bound, the same file reads


def test_the_time_bound_leaves_a_tracer_already_set_in_place(issued, tmp_path):
    import sys

    calls = []

    def tracer(frame, event, arg):
        calls.append(event)

    path = tmp_path / "A21003.pdf"
    path.write_bytes(sheet_bytes(issued))
    sys.settrace(tracer)
    try:
        pdf_form.load_pdf(path, None, time.perf_counter() + 10)
        assert sys.gettrace() is tracer
    finally:
        sys.settrace(None)
    assert calls  # it went on being called during the read
