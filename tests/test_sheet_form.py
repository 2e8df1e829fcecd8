"""The sheet PDF's answer form, read from the PDF as a viewer reads it and checked against where the layout
put each part: for every template, one field per part, in reading order, inside its part's region, named,
tooltipped and typed for its answer; each field tagged a /Form element in the structure tree, in reading order
(walked here, and checked by a PDF/UA checker); the identity in the document, never in a field; and a sheet
with its empty form prints exactly as the sheet without one."""
import io
import json
import shutil
import subprocess

import numpy
import pypdfium2 as pdfium
import pytest
import typst
from pypdf import PdfReader

from exgen.answertypes import answer_type
from exgen.figures import draw_figures
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.load.bank import load_bank
from exgen.render.bundle import join_pdfs
from exgen.render.pdf import sheet_pdf, sheet_typst
from exgen.render.pdf_form import COMBO, INFO_KEYS

SECRET = b"sheet form: 3c9e1a7f5b2d8046"
#: Every template, in bank order, on sheets for several students (so over several seeds each).
STUDENTS = [Student("F10001", "Ada Tan"), Student("F10002", "Bo Lim"), Student("F10003")]
# where every part's region landed, asked of the same source the sheet is typeset from
PROBE = "\n#context [#metadata(query(<exgen-part>).map(placed)) <probe>]\n"
TOLERANCE = 0.5  # pt: positions are rounded to hundredths when the fields are written


def every_template() -> Assignment:
    ids = sorted(load_bank().templates)
    return Assignment(id="all", title="Every template", questions=tuple(
        QuestionSpec(f"q{i}", tid) for i, tid in enumerate(ids, start=1)))


@pytest.fixture(scope="module", params=STUDENTS, ids=lambda s: s.id)
def issued(request, bank):
    """(sheet, the sheet PDF, the sheet PDF without the form, each part's region as the layout reports it)."""
    sheet = build_sheet(every_template(), request.param, bank, SECRET)
    figures = draw_figures(sheet)
    source = sheet_typst(sheet, figures, regions=True)  # the same layout: the region marks take no room
    regions: dict[tuple[int, int], dict] = {}
    for mark in json.loads(typst.query((source + PROBE).encode(), "<probe>", field="value", one=True)):
        regions.setdefault((mark["question"], mark["part"]), {})[mark["what"]] = mark
    return sheet, sheet_pdf(sheet, figures), regions


def widgets(pdf: bytes) -> list[tuple[int, dict, str]]:
    """(page index, widget, full name) of every widget, page by page, in each page's annotation order."""
    reader = PdfReader(io.BytesIO(pdf), strict=True)
    out = []
    for index, page in enumerate(reader.pages):
        for annot in page.get("/Annots") or []:
            annot = annot.get_object()
            if annot.get("/Subtype") == "/Widget":
                out.append((index, annot, f"{annot['/Parent'].get_object()['/T']}.{annot['/T']}"))
    return out


def test_one_field_per_part_in_reading_order_each_within_its_part_region(issued):
    sheet, pdf, regions = issued
    expected = [(q, i, f"{q.slot}.{p.id}") for q in sheet.questions for i, p in enumerate(q.variant.template.parts)]
    found = widgets(pdf)
    assert [name for _, _, name in found] == [name for _, _, name in expected]
    reader = PdfReader(io.BytesIO(pdf), strict=True)
    order = []
    for (page, widget, name), (question, index, _) in zip(found, expected):
        height = float(reader.pages[page].mediabox.top)
        x0, y0, x1, y1 = (float(v) for v in widget["/Rect"])
        top, bottom = height - y1, height - y0  # as the layout measures: from the page's top
        start, end = regions[(question.number, index)]["start"], regions[(question.number, index)]["end"]
        assert start["page"] - 1 == page == end["page"] - 1, name
        assert start["x"] - TOLERANCE <= x0 < x1 <= end["x"] + TOLERANCE, (name, (x0, x1), start, end)
        assert start["y"] - TOLERANCE <= top < bottom <= end["y"] + TOLERANCE, (name, (top, bottom), start, end)
        assert x1 - x0 >= 200 and bottom - top >= 14, name  # room for "1.234e3 N·m" at 10 pt
        order.append((page, top))
    assert order == sorted(order)  # reading order: down each page, page after page


def test_the_form_lists_each_question_s_parts_named_slot_dot_part(issued):
    sheet, pdf, _ = issued
    reader = PdfReader(io.BytesIO(pdf), strict=True)
    form = reader.trailer["/Root"]["/AcroForm"]
    assert "/XFA" not in form and not form.get("/NeedAppearances")
    names = [(f.get_object()["/T"], [k.get_object()["/T"] for k in f.get_object()["/Kids"]]) for f in form["/Fields"]]
    assert names == [(q.slot, [p.id for p in q.variant.template.parts]) for q in sheet.questions]
    assert len(set(reader.get_fields())) == len(reader.get_fields())


def test_each_field_tells_its_part_and_unit_and_a_choice_is_a_drop_down_of_its_choices(issued):
    sheet, pdf, _ = issued
    parts = {f"{q.slot}.{p.id}": (q, p) for q in sheet.questions for p in q.variant.template.parts}
    drop_downs = 0
    for _, widget, name in widgets(pdf):
        question, part = parts[name]
        tip = widget["/TU"]
        assert tip.startswith(f"Question {question.number} ({part.id}): ") and answer_type(part).hint(part) in tip
        choices = answer_type(part).form_choices(part)
        if choices:
            assert widget["/FT"] == "/Ch" and int(widget["/Ff"]) & COMBO and tuple(widget["/Opt"]) == choices
            drop_downs += 1
        else:
            assert widget["/FT"] == "/Tx"
        assert "/V" not in widget and "/A" not in widget and "/AA" not in widget
        appearance = widget["/AP"]["/N"].get_object()
        assert appearance.get_data().split() == [b"/Tx", b"BMC", b"EMC"]  # empty: prints nothing
    assert drop_downs >= 5  # every template's sheet: the bank's choice parts among them


def test_who_and_which_sheet_are_stored_in_the_document_not_in_a_field(issued):
    sheet, pdf, _ = issued
    reader = PdfReader(io.BytesIO(pdf), strict=True)
    info = reader.trailer["/Info"]
    assert (info[INFO_KEYS["assignment"]], info[INFO_KEYS["student"]], info[INFO_KEYS["code"]]) == \
           (sheet.assignment.id, sheet.student.id, sheet.code)
    assert all(name.count(".") == 1 and name.split(".")[0] in {q.slot for q in sheet.questions}
               for name in reader.get_fields() if "." in name)
    assert not reader.attachments  # the layout's places are gone from the catalog


# ---- the structure tree: where a screen reader finds each field ---------------------------------------

def structure(reader: PdfReader) -> tuple[list, dict[int, object]]:
    """The structure elements in reading order (depth first from the root, each naming as its parent the
    element that lists it), and the parent tree flattened (structure parent key -> element)."""
    root = reader.trailer["/Root"]["/StructTreeRoot"]
    order = list(_depth_first(root))
    parents, nodes = {}, [root["/ParentTree"].get_object()]
    while nodes:
        node = nodes.pop()
        nums = node.get("/Nums", [])
        parents.update((int(nums[i]), nums[i + 1].get_object()) for i in range(0, len(nums), 2))
        nodes += [k.get_object() for k in node.get("/Kids", [])]
    assert max(parents) < int(root["/ParentTreeNextKey"])
    return order, parents


def _kids(element) -> list:
    kids = element.get("/K")
    kids = kids.get_object() if kids is not None else []
    return [k.get_object() for k in (kids if isinstance(kids, list) else [kids])]


def _depth_first(element):
    for kid in _kids(element):
        if isinstance(kid, dict) and "/S" in kid:  # an element (marked content and object references are leaves)
            assert kid["/P"].get_object() == element
            yield kid
            yield from _depth_first(kid)


def test_each_field_is_tagged_a_form_element_where_its_answer_line_is_read(issued):
    sheet, pdf, _ = issued
    reader = PdfReader(io.BytesIO(pdf), strict=True)
    order, parents = structure(reader)
    found = widgets(pdf)
    tagged = []
    for element in order:
        references = [k for k in _kids(element) if isinstance(k, dict) and k.get("/Type") == "/OBJR"]
        over_widgets = [r for r in references if r["/Obj"].get_object().get("/Subtype") == "/Widget"]
        if element["/S"] == "/Form":
            (reference,) = over_widgets
            tagged.append(reference.raw_get("/Obj").idnum)
            assert reference["/Pg"].get_object()["/Type"] == "/Page"
        else:
            assert not over_widgets, element["/S"]  # a widget is tagged /Form, never /Link
    ids = [widget.indirect_reference.idnum for _, widget, _ in found]
    assert tagged == ids  # one /Form element per field, read in the fields' order
    for page, widget, name in found:
        element = parents[int(widget["/StructParent"])]
        assert element["/S"] == "/Form" and widget["/TU"], name  # the field's element, and its spoken name
        assert reader.pages[page].get("/Tabs") == "/S"  # tabbing follows the structure
    assert not [a for p in reader.pages for a in p.get("/Annots") or [] if a.get_object()["/Subtype"] == "/Link"]


def test_a_pdf_ua_checker_finds_no_failure_the_form_adds(issued):
    """PDF/UA-1 as the page checker (veraPDF's rules) reads it: whatever Typst's sheet lacks (a figure's
    alternative text, the PDF/UA identification), the form adds no failure of its own."""
    checker = pytest.importorskip("page", reason="the PDF/UA checker page-validation is not installed")
    sheet, pdf, _ = issued

    def failed(document: bytes) -> set[str]:
        return {f.rule_id for f in checker.validate_pdf_bytes(document, profile="ua1").failures}

    without = failed(sheet_pdf(sheet, form=False))  # no widget there: no widget's rule can fail
    assert failed(pdf) <= without, failed(pdf) - without


# ---- the printed look -------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def two_ways(bank):
    """A sheet of Tutorial 1's kind (a drop-down on it) with and without its form."""
    from exgen.issue.assignment import load_assignment
    from test_grade_issued import EXAMPLES

    sheet = build_sheet(load_assignment(EXAMPLES / "tutorial1.yaml", bank), STUDENTS[0], bank, SECRET)
    figures = draw_figures(sheet)
    return sheet_pdf(sheet, figures), sheet_pdf(sheet, figures, form=False)


def rendered(pdf: bytes) -> list[numpy.ndarray]:
    """Every page as PDFium prints it: the form's appearance streams drawn."""
    document = pdfium.PdfDocument(pdf)
    document.init_forms()
    pages = [document[i].render(scale=1, may_draw_forms=True, draw_annots=True).to_numpy().copy()
             for i in range(len(document))]
    document.close()
    return pages


def test_an_empty_form_changes_no_pixel_of_the_printed_sheet(two_ways):
    with_form, without = two_ways
    assert b"/AcroForm" in with_form and b"/AcroForm" not in without
    pages, plain = rendered(with_form), rendered(without)
    assert len(pages) == len(plain)
    for page, expected in zip(pages, plain):
        assert numpy.array_equal(page, expected)


@pytest.mark.skipif(not shutil.which("pdftoppm"), reason="pdftoppm (poppler-utils) is not installed")
def test_poppler_prints_the_sheet_with_its_form_as_without(two_ways, tmp_path):
    pngs = []
    for name, pdf in zip(("form", "plain"), two_ways):
        (tmp_path / f"{name}.pdf").write_bytes(pdf)
        subprocess.run(["pdftoppm", "-png", "-r", "60", str(tmp_path / f"{name}.pdf"), str(tmp_path / name)], check=True)
        pngs.append(sorted(tmp_path.glob(f"{name}-*.png")))
    assert len(pngs[0]) == len(pngs[1]) >= 1
    assert all(a.read_bytes() == b.read_bytes() for a, b in zip(*pngs))


def test_a_print_bundle_leaves_the_forms_out(two_ways, tmp_path):
    paths = []
    for i in range(2):
        paths.append(tmp_path / f"s{i}.pdf")
        paths[-1].write_bytes(two_ways[0])
    join_pdfs(paths, tmp_path / "all.pdf")
    joined = PdfReader(tmp_path / "all.pdf")
    assert "/AcroForm" not in joined.trailer["/Root"] and not joined.get_fields()
    assert not any(a.get_object().get("/Subtype") == "/Widget" for p in joined.pages for a in p.get("/Annots") or [])
