"""The sheet's answer form: a text field (a drop-down for a choice) on each part's answer line, added to the
typeset PDF as an incremental update.

Typst writes no form fields, so the sheet's layout reports where each answer line landed (page, position
and size, attached to the PDF as data by `field-places()` in the preamble) and the fields are set on those
places here. The typeset bytes are kept as they are and the form is appended after them (new objects, the
catalog, pages and document information written again, a new cross-reference section), as a viewer saves
a filled form: reading the PDF whole and writing it anew would cost as much again as typesetting it.

Every field is an AcroForm field (no XFA, no JavaScript) with its own appearance stream, empty until a
student types, so a sheet prints exactly as it was typeset. Fields are named `<slot>.<part>` (a parent
field per question, a child per part), tooltipped with the question, the part and the unit asked, and
listed in reading order. The assignment, student and sheet code are written into the document
information, where grading checks them: never into a field a student could edit.
"""
from __future__ import annotations

import io
import json
import re

from pypdf import PdfReader
from pypdf.generic import ArrayObject, DictionaryObject, IndirectObject, NameObject, PdfObject, TextStringObject

from ..errors import ExgenError
from .targets import PLAIN

#: Where the layout's places arrive, as an attachment of the typeset PDF (removed from the catalog here).
PLACES = "exgen-fields.json"
#: The document information keys the grader reads back.
INFO_KEYS = {"assignment": "/ExgenAssignment", "student": "/ExgenStudent", "code": "/ExgenCode"}
FONT = "/Helv"
#: What typed text looks like: Helvetica (every viewer has it), 10 pt, black.
APPEARANCE = f"{FONT} 10 Tf 0 g"
COMBO = 1 << 17  # field flag: a drop-down list
TAB_ORDER = "/R"  # fields tabbed through in rows, as they are read


class FormError(ExgenError, RuntimeError):
    """The typeset sheet does not report the answer lines the sheet has."""


def add_form(typeset: bytes, sheet) -> bytes:
    """`typeset` (a sheet's PDF as Typst wrote it, with its answer lines' places attached) with the answer
    form added and the sheet's identity in its document information."""
    reader = PdfReader(io.BytesIO(typeset), strict=True)  # Typst's own output: no repairs to look for
    places = _places(reader)
    update = _Update(int(reader.trailer["/Size"]))
    font = update.add({"/Type": Name("/Font"), "/Subtype": Name("/Type1"), "/BaseFont": Name("/Helvetica"),
                       "/Encoding": Name("/WinAnsiEncoding")})
    pages = list(reader.pages)
    annots: dict[int, list[Ref]] = {}
    fields, empty = [], {}
    for question in sheet.questions:
        kids: list[Ref] = []
        parent = update.add({"/T": question.slot, "/Kids": kids})
        fields.append(parent)
        for index, part in enumerate(question.variant.template.parts):
            place = places.get((question.number, index))
            if place is None:
                raise FormError(f"the layout reports no answer line for question {question.number} ({part.id})")
            page_index = int(place["page"]) - 1
            if not 0 <= page_index < len(pages):
                raise FormError(f"the answer line of question {question.number} ({part.id}) is on no page")
            top = float(pages[page_index].mediabox.top)
            x, y, w, h = (float(place[k]) for k in ("x", "y", "w", "h"))
            size = (round(w, 2), round(h, 2))
            if size not in empty:
                empty[size] = update.add(_appearance(*size, font))
            x += float(place["dx"])  # the mark is where the line with "Answer:" starts, on its baseline
            rect = [round(v, 2) for v in (x, top - y, x + w, top - y + h)]
            ref = update.add(_widget(question, part, rect, parent, pages[page_index].indirect_reference.idnum,
                                     empty[size]))
            kids.append(ref)
            annots.setdefault(page_index, []).append(ref)
    for page_index, refs in annots.items():
        page = pages[page_index]
        copy = DictionaryObject(page)
        copy[NameObject("/Annots")] = ArrayObject([*_existing(page.get("/Annots")), *(r.pypdf() for r in refs)])
        copy[NameObject("/Tabs")] = NameObject(TAB_ORDER)
        update.put(page.indirect_reference.idnum, copy)
    form = update.add({"/Fields": fields, "/DA": APPEARANCE, "/DR": {"/Font": {FONT: font}}})
    root_ref = reader.trailer.raw_get("/Root")
    root = DictionaryObject(reader.trailer["/Root"])
    root[NameObject("/AcroForm")] = form.pypdf()
    _drop_places(root)
    update.put(root_ref.idnum, root)
    info_ref = reader.trailer.raw_get("/Info")
    info = DictionaryObject(reader.trailer["/Info"]) if isinstance(info_ref, IndirectObject) else DictionaryObject()
    identity = {"assignment": sheet.assignment.id, "student": sheet.student.id, "code": sheet.code}
    for key, value in identity.items():
        info[NameObject(INFO_KEYS[key])] = TextStringObject(value)
    if isinstance(info_ref, IndirectObject):
        update.put(info_ref.idnum, info)
        info = Ref(info_ref.idnum)
    else:
        info = update.add(info)
    ids = reader.trailer.get("/ID")
    return update.write(typeset, Ref(root_ref.idnum), info, ids)


def _places(reader: PdfReader) -> dict[tuple[int, int], dict]:
    """(question number, part index) -> the answer line's page, where its line starts on its baseline (x, and y
    from the page's top), how far right of that it starts (dx), and its size, in pt."""
    found = reader.attachments.get(PLACES)
    if not found:
        raise FormError("the layout attached no answer lines' places")
    return {(int(p["question"]), int(p["part"])): p for p in json.loads(found[0])}


def _widget(question, part, rect, parent: "Ref", page: int, appearance: "Ref") -> dict:
    """A part's field and its widget (one dictionary), empty, printable, with the part and unit as tooltip."""
    from ..answertypes import answer_type

    ask = " ".join(PLAIN.text(question.variant.asks.get(part.id, part.ask)).split())
    widget = {
        "/Type": Name("/Annot"), "/Subtype": Name("/Widget"), "/Parent": parent, "/T": part.id,
        "/TU": f"Question {question.number} ({part.id}): {ask} [{answer_type(part).hint(part)}]",
        "/Rect": rect, "/P": Ref(page),
        "/F": 4,  # printed (empty, it prints nothing)
        "/DA": APPEARANCE,
        "/MK": {},  # no border, no background: the printed line is the box
        "/AP": {"/N": appearance},
    }
    choices = answer_type(part).form_choices(part)
    if choices:
        widget.update({"/FT": Name("/Ch"), "/Ff": COMBO, "/Opt": list(choices)})
    else:
        widget["/FT"] = Name("/Tx")
    return widget


def _appearance(width: float, height: float, font: "Ref") -> "Stream":
    """An empty field's look: nothing, marked as a text field's content (where a viewer puts what is typed)."""
    return Stream({"/Type": Name("/XObject"), "/Subtype": Name("/Form"), "/BBox": [0, 0, width, height],
                   "/Resources": {"/Font": {FONT: font}}}, b"/Tx BMC\nEMC\n")


def _existing(annots) -> list:
    if annots is None:
        return []
    annots = annots.get_object()
    return list(annots) if isinstance(annots, ArrayObject) else []


def _drop_places(root: DictionaryObject) -> None:
    """The catalog without the attached places (the only file Typst attaches to a sheet)."""
    names = root.get("/Names")
    if names is None:
        return
    names = DictionaryObject(names.get_object())
    names.pop("/EmbeddedFiles", None)
    if names:
        root[NameObject("/Names")] = names
    else:
        del root["/Names"]
    files = root.get("/AF")
    if files is not None:  # associated files (PDF/A-3), where Typst lists attachments too
        del root["/AF"]


class Name(str):
    """A PDF name, written as it is ("/Widget"): only the plain names written here."""


class Ref(int):
    """An indirect reference to object number `self`."""

    def pypdf(self) -> IndirectObject:
        return IndirectObject(int(self), 0, None)


class Stream:
    def __init__(self, entries: dict, data: bytes):
        self.entries, self.data = entries, data


def _serialised(value) -> bytes:
    """The PDF syntax of a form object: pypdf's writer names and escapes character by character, which
    for a sheet's fields costs more than the rest of adding them."""
    if isinstance(value, PdfObject):  # an object read by pypdf (a catalog, a page, the document information)
        out = io.BytesIO()
        value.write_to_stream(out)
        return out.getvalue()
    if isinstance(value, Name):
        return value.encode("ascii")
    if isinstance(value, Ref):
        return b"%d 0 R" % value
    if isinstance(value, bool):
        return b"true" if value else b"false"
    if isinstance(value, int):
        return b"%d" % value
    if isinstance(value, float):
        return (b"%.2f" % value).rstrip(b"0").rstrip(b".") or b"0"
    if isinstance(value, str):
        return _text(value)
    if isinstance(value, dict):
        return b"<<" + b"".join(k.encode("ascii") + b" " + _serialised(v) for k, v in value.items()) + b">>"
    if isinstance(value, (list, tuple)):
        return b"[" + b" ".join(_serialised(v) for v in value) + b"]"
    if isinstance(value, Stream):
        return (_serialised({**value.entries, "/Length": len(value.data)}) + b"\nstream\n" + value.data
                + b"\nendstream")
    raise TypeError(f"no PDF form for {type(value).__name__}")


_PRINTABLE = re.compile(r"[ -~]*")


def _text(text: str) -> bytes:
    """A PDF text string: printable ASCII as a literal string, anything else as UTF-16BE with its mark."""
    if _PRINTABLE.fullmatch(text):
        return b"(" + text.replace("\\", "\\\\").replace("(", "\\(").replace(")", "\\)").encode("ascii") + b")"
    return b"<" + ("\ufeff" + text).encode("utf-16-be").hex().upper().encode("ascii") + b">"


class _Update:
    """The objects of an incremental update: new ones numbered from the file's /Size, and replacements."""

    def __init__(self, size: int):
        self.size, self.objects = size, {}

    def add(self, obj) -> Ref:
        ref = Ref(self.size)
        self.objects[self.size] = obj
        self.size += 1
        return ref

    def put(self, number: int, obj) -> None:
        self.objects[number] = obj

    def write(self, original: bytes, root: Ref, info: Ref, ids) -> bytes:
        """`original` followed by these objects, their cross-reference section and a trailer."""
        out = io.BytesIO()
        out.write(original)
        if not original.endswith(b"\n"):
            out.write(b"\n")
        offsets = {}
        for number in sorted(self.objects):
            offsets[number] = out.tell()
            out.write(b"%d 0 obj\n%s\nendobj\n" % (number, _serialised(self.objects[number])))
        start = out.tell()
        out.write(b"xref\n0 1\n0000000000 65535 f\r\n")  # the free list's head, as in every section
        for first, numbers in _runs(sorted(offsets)):
            out.write(b"%d %d\n" % (first, len(numbers)))
            out.writelines(b"%010d 00000 n\r\n" % offsets[n] for n in numbers)
        trailer = {"/Size": self.size, "/Root": root, "/Info": info, "/Prev": _startxref(original)}
        if ids is not None:
            trailer["/ID"] = ids
        out.write(b"trailer\n" + _serialised(trailer) + b"\n")
        out.write(b"startxref\n%d\n%%%%EOF\n" % start)
        return out.getvalue()


def _runs(numbers: list[int]):
    """Consecutive object numbers grouped: [3, 4, 9] -> (3, [3, 4]), (9, [9])."""
    run: list[int] = []
    for n in numbers:
        if run and n != run[-1] + 1:
            yield run[0], run
            run = []
        run.append(n)
    if run:
        yield run[0], run


_STARTXREF = re.compile(rb"startxref\s+(\d+)\s+%%EOF\s*$")


def _startxref(pdf: bytes) -> int:
    found = _STARTXREF.search(pdf[-64:])
    if not found:
        raise FormError("the typeset PDF does not end with a cross-reference offset")
    return int(found.group(1))
