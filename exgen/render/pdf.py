"""PDF sheets and keys: Typst source from layouts, compiled in-process (no TeX, no temp files).

Figures are embedded in the source as SVG text. The output depends only on the sheet: no
date is written, and only the fonts that ship inside Typst are used, so the same sheet
gives the same bytes on any machine.
"""
from __future__ import annotations

import threading

import typst

from ..errors import ExgenError
from ..figures import draw_figures
from ..figures.metrics import FAMILY
from .context import sheet_context
from .jinja import render
from .targets import TYPST


#: On the sheet's last page, above the footer rule: never a page of its own.
CLOSING = "Type your answers into the boxes of this PDF and save it, or write them on a printed copy or in the answer file."


class PdfError(ExgenError, RuntimeError):
    """Typst could not compile a sheet; names the sheet and Typst's message."""

    def __init__(self, what: str, message: str):
        self.what, self.message = what, message
        super().__init__(f"cannot typeset {what}: {message}")


def _context(sheet, key: bool, figures=None, form: bool = False, regions: bool = False) -> dict:
    """Figures are embedded as SVG text; `figures` is the sheet's `draw_figures` (drawn here when not given)."""
    figures = draw_figures(sheet) if figures is None else figures
    svgs = {slot: f.sheet.svg for slot, f in figures.items() if f.sheet}
    key_figures = {slot: [(d.svg, d.title) for d in f.key] for slot, f in figures.items()} if key else {}
    context = sheet_context(sheet, TYPST, svgs, svgs, key=key, key_figures=key_figures)
    a, s = sheet.assignment, sheet.student
    kind = "Instructor key" if key else "Tutorial sheet"
    context["doc_title"] = f"{kind}: {a.title} ({s.id})"
    context["doc_author"] = a.course or a.title
    context["font"] = FAMILY  # the figures' family: one typeface for text and figures
    pieces = [TYPST.prose(a.course), TYPST.prose(a.title), f"Sheet {TYPST.prose(sheet.code)}"]
    if key:
        pieces.insert(0, "*Instructor key*")
    context["footer_left"] = " · ".join(p for p in pieces if p)
    context["closing"] = "" if key else CLOSING
    context["form"], context["form_regions"] = form, regions
    return context


def sheet_typst(sheet, figures=None, form: bool = True, regions: bool = False) -> str:
    """The Typst source of the student's sheet; with `form`, its answer lines report where they land (and
    with `regions`, where each part's region is: what the tests check the form's fields against)."""
    return render("sheet.typ.j2", _context(sheet, False, figures, form, regions))


def key_typst(sheet, figures=None) -> str:
    """The Typst source of the instructor's key."""
    return render("key.typ.j2", _context(sheet, True, figures))


_local = threading.local()


def _compiler() -> typst.Compiler:
    """This thread's Typst compiler, made once: a new one per document reads Typst's fonts again (about 4 ms a
    sheet and 9 ms a key of the same bytes)."""
    compiler = getattr(_local, "compiler", None)
    if compiler is None:
        compiler = _local.compiler = typst.Compiler(ignore_system_fonts=True)
    return compiler


def compile_pdf(source: str, what: str = "a document") -> bytes:
    try:
        return _compiler().compile(input=source.encode("utf-8"), format="pdf")
    except typst.TypstError as exc:
        raise PdfError(what, str(exc).strip().splitlines()[0] if str(exc).strip() else repr(exc)) from exc


def sheet_pdf(sheet, figures=None, form: bool = True) -> bytes:
    """The student's sheet; with `form`, a form to type the answers into, on the sheet's answer lines."""
    what = f"the sheet of {sheet.student.id}"
    typeset = compile_pdf(sheet_typst(sheet, figures, form), what)
    if not form:
        return typeset
    from .pdf_form import FormError, add_form

    try:
        return add_form(typeset, sheet)
    except FormError as exc:
        raise PdfError(what, str(exc)) from exc


def key_pdf(sheet, figures=None) -> bytes:
    return compile_pdf(key_typst(sheet, figures), f"the key of {sheet.student.id}")
