"""Fill a PDF's form the way Chrome and Edge do, with PDFium (pypdfium2), and save it.

Each field is focused, its text selected and replaced (a drop-down's entry is chosen by its index), and the
focus left, through PDFium's form-filling interface: PDFium then writes the value and its own appearance
stream, as when a student types into the sheet in the browser.
"""
from __future__ import annotations

import ctypes
from pathlib import Path

import pypdfium2 as pdfium
import pypdfium2.raw as raw


def _name(form, annot) -> str:
    size = raw.FPDFAnnot_GetFormFieldName(form, annot, None, 0)
    buffer = ctypes.create_string_buffer(size)
    raw.FPDFAnnot_GetFormFieldName(form, annot, ctypes.cast(buffer, ctypes.POINTER(raw.FPDF_WCHAR)), size)
    return buffer.raw[: size - 2].decode("utf-16-le")


def _options(form, annot) -> list[str]:
    out = []
    for i in range(raw.FPDFAnnot_GetOptionCount(form, annot)):
        size = raw.FPDFAnnot_GetOptionLabel(form, annot, i, None, 0)
        buffer = ctypes.create_string_buffer(size)
        raw.FPDFAnnot_GetOptionLabel(form, annot, i, ctypes.cast(buffer, ctypes.POINTER(raw.FPDF_WCHAR)), size)
        out.append(buffer.raw[: size - 2].decode("utf-16-le"))
    return out


def fields(path: Path) -> list[tuple[str, int, list[str]]]:
    """(full name, PDFium's field type, choices) of every field, page by page in annotation order."""
    return [(name, kind, options) for name, kind, options, _ in _walk(path, {}, None)]


def fill(path: Path, values: dict[str, str], out: Path, incremental: bool = False) -> dict[str, str]:
    """Type `values` (full field name -> text, or a choice's text) into the PDF at `path`, save it to `out`;
    returns what was typed where. A choice not in the drop-down is an error."""
    return {name: typed for name, _, _, typed in _walk(path, values, out, incremental) if typed is not None}


def _walk(path, values, out, incremental=False):
    document = pdfium.PdfDocument(str(path))
    document.init_forms()
    form = document.formenv.raw
    found = []
    for index in range(len(document)):
        page = document[index]
        for i in range(raw.FPDFPage_GetAnnotCount(page.raw)):
            annot = raw.FPDFPage_GetAnnot(page.raw, i)
            if raw.FPDFAnnot_GetSubtype(annot) != raw.FPDF_ANNOT_WIDGET:
                raw.FPDFPage_CloseAnnot(annot)
                continue
            name, kind = _name(form, annot), raw.FPDFAnnot_GetFormFieldType(form, annot)
            options = _options(form, annot) if kind == raw.FPDF_FORMFIELD_COMBOBOX else []
            typed = values.get(name)
            if typed is not None:
                raw.FORM_SetFocusedAnnot(form, annot)
                if kind == raw.FPDF_FORMFIELD_COMBOBOX:
                    raw.FORM_SetIndexSelected(form, page.raw, options.index(typed), True)
                else:
                    text = ctypes.create_string_buffer((typed + "\0").encode("utf-16-le"))
                    raw.FORM_SelectAllText(form, page.raw)
                    raw.FORM_ReplaceSelection(form, page.raw, ctypes.cast(text, raw.FPDF_WIDESTRING))
                raw.FORM_ForceToKillFocus(form)
            found.append((name, kind, options, typed))
            raw.FPDFPage_CloseAnnot(annot)
        page.close()
    if out is not None:
        document.save(str(out), flags=raw.FPDF_INCREMENTAL if incremental else 0)
    document.close()
    return found
