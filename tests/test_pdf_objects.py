"""The reader of Typst's PDF objects that adding the form uses: every object of a typeset sheet and key
reads as pypdf reads it, is written back as it was read, and a file that is not as Typst writes it (an
update already appended, a cross-reference stream, a broken table) is refused with a reason."""
import io

import pytest
from pypdf import PdfReader
from pypdf.generic import (ArrayObject, BooleanObject, DictionaryObject, FloatObject, IndirectObject, NameObject,
                           NullObject, NumberObject, StreamObject)

from exgen.issue.assignment import Student, build_sheet, load_assignment
from exgen.render.pdf import key_pdf, sheet_pdf
from exgen.render.pdf_objects import Name, Number, PdfSyntaxError, Reader, Ref, String, Update, serialised

from test_grade_issued import EXAMPLES


@pytest.fixture(scope="module")
def typeset(bank):
    sheet = build_sheet(load_assignment(EXAMPLES / "tutorial2.yaml", bank), Student("P1", "Pat Lee (the 2nd)"), bank,
                        b"pdf objects: 5e1d9c3b7a2f4086")
    return {"sheet": sheet_pdf(sheet, form=False), "key": key_pdf(sheet)}


def plain(value):
    """A value of either reader in one form: names and strings as text, references as ("ref", n)."""
    if isinstance(value, (IndirectObject, Ref)):
        return ("ref", value.idnum if isinstance(value, IndirectObject) else int(value))
    if isinstance(value, String):
        return value.text()
    if isinstance(value, BooleanObject):
        return value.value
    if isinstance(value, bool):
        return value
    if isinstance(value, (NameObject, Name)):
        return str(value)
    if isinstance(value, (int, float, NumberObject, FloatObject)):
        return float(value)
    if value is None or isinstance(value, NullObject):
        return None
    if isinstance(value, (dict, DictionaryObject)):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, ArrayObject)):
        return [plain(v) for v in value]
    if isinstance(value, bytes):  # a byte string pypdf could not read as text
        return value.decode("latin-1")
    return str(value)


@pytest.mark.parametrize("kind", ["sheet", "key"])
def test_every_object_reads_as_pypdf_reads_it_and_is_written_back_as_read(typeset, kind):
    data = typeset[kind]
    ours, theirs = Reader(data), PdfReader(io.BytesIO(data), strict=True)
    assert plain(ours.trailer) == plain(theirs.trailer)
    streams = objects = 0
    for number in range(1, int(ours.trailer["/Size"])):
        expected = theirs.get_object(number)
        if isinstance(expected, StreamObject):
            with pytest.raises(PdfSyntaxError, match="stream"):
                ours.object(number)
            streams += 1
            continue
        value = ours.object(number)
        assert plain(value) == plain(expected), number
        assert serialised(Reader(document(serialised(value))).object(1)) == serialised(value), number
        objects += 1
    assert streams and objects > 50


def document(body: bytes) -> bytes:
    """A one-object PDF whose object 1 is `body`."""
    head = b"%PDF-1.7\n"
    obj = b"1 0 obj\n" + body + b"\nendobj\n"
    return (head + obj + b"xref\n0 2\n0000000000 65535 f\r\n%010d 00000 n\r\ntrailer\n<</Size 2/Root 1 0 R>>\n"
            b"startxref\n%d\n%%%%EOF\n" % (len(head), len(head) + len(obj)))


@pytest.mark.parametrize("body, expected", [
    (b"<</A(a \\(b\\) c)/B(nested (once) here)/C<FE FF 00 41>/D(\\101\\n\\\\)>>",
     {"/A": "a (b) c", "/B": "nested (once) here", "/C": "A", "/D": "A\n\\"}),
    (b"[1 0 R 2 3 0 R -4 .5 +6. 7.25]", [("ref", 1), 2.0, ("ref", 3), -4.0, 0.5, 6.0, 7.25]),
    (b"<< /K [ 0 0 R ] % a comment\n /Null null /T true /F false /Empty () /N /a#2Fb >>",
     {"/K": [("ref", 0)], "/Null": None, "/T": True, "/F": False, "/Empty": "", "/N": "/a#2Fb"}),
    (b"<</Border[0 0 0]/StructParent 0/Rect[127.76221 450.66635 368.7071 466.66635]>>",
     {"/Border": [0.0, 0.0, 0.0], "/StructParent": 0.0, "/Rect": [127.76221, 450.66635, 368.7071, 466.66635]}),
])
def test_the_syntax_typst_writes_reads_as_the_standard_says(body, expected):
    value = Reader(document(body)).object(1)
    assert plain(value) == expected
    assert plain(Reader(document(serialised(value))).object(1)) == expected  # written back as read


def test_numbers_keep_their_digits_and_new_floats_are_rounded_to_hundredths():
    value = Reader(document(b"[595.2756 0.000001 3]")).object(1)
    assert [type(v) for v in value] == [Number, Number, int]
    assert serialised(value) == b"[595.2756 0.000001 3]"
    assert serialised([12.3456, 7.0, 0.001]) == b"[12.35 7 0]"
    assert serialised({"/T": "q1", "/TU": "Qu\u2019estion"}) == \
        b"<</T (q1)/TU <FEFF0051007520190065007300740069006F006E>>>"


def updated(data: bytes) -> bytes:
    """The file with an incremental update appended (one object written again)."""
    reader = Reader(data)
    update = Update(int(reader.trailer["/Size"]))
    update.put(reader.trailer["/Root"], reader.object(reader.trailer["/Root"]))
    return update.write(reader, {"/Root": reader.trailer["/Root"]})


@pytest.mark.parametrize("change, reason", [
    (updated, "updated since it was typeset"),
    (lambda d: d[: len(d) // 2], "does not end with a cross-reference offset"),
    (lambda d: d.replace(b"\nxref\n", b"\nxrep\n"), "no cross-reference table"),
])
def test_a_pdf_not_as_typst_writes_it_is_refused(typeset, change, reason):
    with pytest.raises(PdfSyntaxError, match=reason):
        Reader(change(typeset["sheet"]))


def test_an_update_reads_back_in_pypdf_with_the_objects_it_replaced(typeset):
    data = updated(typeset["sheet"])
    reader = PdfReader(io.BytesIO(data), strict=True)
    assert len(reader.pages) == len(PdfReader(io.BytesIO(typeset["sheet"])).pages)
    assert data.startswith(typeset["sheet"]) and reader.trailer["/Root"]["/Pages"]["/Count"] >= 1


def test_a_string_holding_endobj_does_not_end_its_object_and_a_stray_byte_is_refused():
    assert plain(Reader(document(b"<</Title(the word endobj here)/N 1>>")).object(1)) == \
        {"/Title": "the word endobj here", "/N": 1.0}
    for broken in (b"<</A (unclosed>>", b"<</A 1 }>>", b"<</A [1 2>>", b"<</A 1 1 R>>", b"<<1 2>>"):
        with pytest.raises(PdfSyntaxError):
            Reader(document(broken)).object(1)
