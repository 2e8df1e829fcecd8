"""The sheet's answer form: a text field (a drop-down for a choice) on each part's answer line, added to the
typeset PDF as an incremental update.

Typst writes no form fields, so on a sheet with a form each answer line is a link to
`exgen-field:<question>.<part index>`: Typst writes it as a link annotation with the line's rectangle, listed
on its page, and tags it in the structure tree where the line is read (a /Link element whose object reference
names the annotation). Here each such annotation becomes the part's field: the same object, written again as
a widget with the same rectangle and structure parent, and its structure element becomes a /Form element, so
the fields are in the tagged PDF's reading order for screen readers (and for the Tab key: Typst sets each
page with annotations to tab in structure order). The typeset bytes are kept as they are and
the form is appended after them (new objects, the annotations, structure elements, catalog and document
information written again, a new cross-reference section), as a viewer saves a filled form: reading the PDF
whole and writing it anew would cost as much again as typesetting it.

Every field is an AcroForm field (no XFA, no JavaScript) with its own appearance stream, empty until a
student types, so a sheet prints exactly as it was typeset. Fields are named `<slot>.<part>` (a parent
field per question, a child per part), tooltipped with the question, the part and the unit asked, and
listed in reading order. The assignment, student and sheet code are written into the document
information, where grading checks them: never into a field a student could edit.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..errors import ExgenError
from .pdf_objects import Name, PdfSyntaxError, Reader, Ref, Stream, Update
from .targets import PLAIN

#: The links the layout makes of the answer lines (preamble.typ.j2, `answer-line`): question number, part index.
ANCHOR = re.compile(r"exgen-field:(\d+)\.(\d+)")
#: The document information keys the grader reads back.
INFO_KEYS = {"assignment": "/ExgenAssignment", "student": "/ExgenStudent", "code": "/ExgenCode"}
FONT = "/Helv"
#: What typed text looks like: Helvetica (every viewer has it), 10 pt, black.
APPEARANCE = f"{FONT} 10 Tf 0 g"
COMBO = 1 << 17  # field flag: a drop-down list
#: The deepest a page tree or a number tree of the typeset PDF is followed.
MAX_TREE_DEPTH = 32


class FormError(ExgenError, RuntimeError):
    """The typeset sheet does not hold the answer lines the sheet has."""


@dataclass(frozen=True)
class Anchor:
    """An answer line as Typst wrote it: its link annotation's object, page, rectangle and structure parent."""

    annotation: int
    page: int
    rect: tuple[float, ...]
    struct_parent: int | None


def add_form(typeset: bytes, sheet) -> bytes:
    """`typeset` (a sheet's PDF as Typst wrote it, its answer lines links to `exgen-field:`) with the answer
    form added and the sheet's identity in its document information."""
    try:
        return _add_form(Reader(typeset), sheet)
    except PdfSyntaxError as exc:
        raise FormError(f"the typeset PDF cannot take the form: {exc}") from None


def _add_form(reader: Reader, sheet) -> bytes:
    trailer = reader.trailer
    root_ref = trailer.get("/Root")
    root = dict(_dict(reader, root_ref, "catalog"))
    anchors = _anchors(reader, root)
    tagged = _parent_tree(reader, root)
    update = Update(int(trailer["/Size"]))
    font = update.add({"/Type": Name("/Font"), "/Subtype": Name("/Type1"), "/BaseFont": Name("/Helvetica"),
                       "/Encoding": Name("/WinAnsiEncoding")})
    fields, empty = [], {}
    for question in sheet.questions:
        kids: list[Ref] = []
        parent = update.add({"/T": question.slot, "/Kids": kids})
        fields.append(parent)
        for index, part in enumerate(question.variant.template.parts):
            anchor = anchors.pop((question.number, index), None)
            if anchor is None:
                raise FormError(f"the layout made no answer line for question {question.number} ({part.id})")
            x0, y0, x1, y1 = anchor.rect
            size = (round(x1 - x0, 2), round(y1 - y0, 2))
            if size not in empty:
                empty[size] = update.add(_appearance(*size, font))
            widget = _widget(question, part, [round(v, 2) for v in anchor.rect], parent, anchor.page, empty[size])
            if anchor.struct_parent is not None and tagged is not None:
                number, element = _form_element(reader, tagged, anchor)
                update.put(number, element)
                widget["/StructParent"] = anchor.struct_parent
            update.put(anchor.annotation, widget)
            kids.append(Ref(anchor.annotation))
    if anchors:
        raise FormError(f"the layout made answer lines for parts the sheet does not have: {sorted(anchors)}")
    root["/AcroForm"] = update.add({"/Fields": fields, "/DA": APPEARANCE, "/DR": {"/Font": {FONT: font}}})
    update.put(root_ref, root)
    info_ref = trailer.get("/Info")
    info = dict(_dict(reader, info_ref, "document information")) if isinstance(info_ref, Ref) else {}
    identity = {"assignment": sheet.assignment.id, "student": sheet.student.id, "code": sheet.code}
    info.update({INFO_KEYS[key]: value for key, value in identity.items()})
    if isinstance(info_ref, Ref):
        update.put(info_ref, info)
    else:
        info_ref = update.add(info)
    kept = {"/ID": trailer["/ID"]} if "/ID" in trailer else {}
    return update.write(reader, {"/Root": root_ref, "/Info": info_ref, **kept})


def _anchors(reader: Reader, root: dict) -> dict[tuple[int, int], Anchor]:
    """(question number, part index) -> the link annotation Typst wrote for that answer line."""
    found: dict[tuple[int, int], Anchor] = {}
    for page in _pages(reader, root.get("/Pages")):
        for ref in reader.resolve(reader.object(page).get("/Annots")) or ():
            annot = reader.resolve(ref)
            if not isinstance(annot, dict) or annot.get("/Subtype") != "/Link":
                continue
            action = reader.resolve(annot.get("/A"))
            target = action.get("/URI") if isinstance(action, dict) else None
            matched = ANCHOR.fullmatch(target.text()) if hasattr(target, "text") else None
            if matched is None:
                continue
            key = (int(matched.group(1)), int(matched.group(2)))
            if key in found or not isinstance(ref, Ref):
                raise FormError(f"the layout made two answer lines for question {key[0]}, part {key[1] + 1}")
            parent = annot.get("/StructParent")
            found[key] = Anchor(ref, page, tuple(float(v) for v in annot["/Rect"]),
                                parent if isinstance(parent, int) else None)
    return found


def _pages(reader: Reader, node, depth: int = 0) -> list[Ref]:
    """The page objects of the page tree under `node`, in order."""
    if depth > MAX_TREE_DEPTH or not isinstance(node, Ref):
        raise FormError("the typeset PDF's page tree is not one the form can read")
    value = reader.object(node)
    if value.get("/Type") == "/Page":
        return [node]
    return [page for kid in reader.resolve(value.get("/Kids")) or () for page in _pages(reader, kid, depth + 1)]


def _parent_tree(reader: Reader, root: dict) -> dict[int, Ref] | None:
    """The tagged PDF's structure parents (the number tree /StructTreeRoot /ParentTree, flattened), or None
    for an untagged one."""
    tree = reader.resolve(root.get("/StructTreeRoot"))
    tree = reader.resolve(tree.get("/ParentTree")) if isinstance(tree, dict) else None
    if tree is None:
        return None
    out: dict[int, Ref] = {}
    nodes = [(tree, 0)]
    while nodes:
        node, depth = nodes.pop()
        if depth > MAX_TREE_DEPTH or not isinstance(node, dict):
            raise FormError("the typeset PDF's structure tree is not one the form can read")
        nums = reader.resolve(node.get("/Nums")) or []
        out.update((nums[i], nums[i + 1]) for i in range(0, len(nums) - 1, 2))
        nodes += [(reader.resolve(kid), depth + 1) for kid in reader.resolve(node.get("/Kids")) or ()]
    return out


def _form_element(reader: Reader, parents: dict[int, Ref], anchor: Anchor) -> tuple[Ref, dict]:
    """The /Link structure element that refers to the anchor's annotation, made the /Form element that
    refers to the field in its place (PDF/UA: a widget is tagged /Form, its /TU its name)."""
    ref = parents.get(anchor.struct_parent)
    element = reader.object(ref) if isinstance(ref, Ref) else None
    kids = reader.resolve(element.get("/K")) if isinstance(element, dict) else None
    kids = kids if isinstance(kids, list) else [kids]
    refers = any(isinstance(k, dict) and k.get("/Type") == "/OBJR" and k.get("/Obj") == anchor.annotation
                 for k in map(reader.resolve, kids))
    if not refers or element.get("/S") != "/Link":
        raise FormError(f"the typeset PDF tags answer line {anchor.annotation} in a way the form does not know")
    return ref, {**element, "/S": Name("/Form")}


def _dict(reader: Reader, ref, what: str) -> dict:
    value = reader.resolve(ref)
    if not isinstance(value, dict):
        raise FormError(f"the typeset PDF has no {what}")
    return value


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
