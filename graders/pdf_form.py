"""Read a handed-in sheet PDF: the values typed into its form are the answers, as an answer file's are.

The form is the one exgen.render.pdf_form adds to every sheet: a field `<slot>.<part>` per part (a parent
field per question, a child per part), the assignment, student and sheet code in the document information.
Whatever a viewer did on saving (an incremental update, a rewrite), the field tree and its values are read
and nothing else: no content stream, no image, no script is parsed, decoded or run.

A PDF is hostile data like any answer file. It is refused, with one plain line, when it is larger than
MAX_PDF_BYTES, encrypted, carries JavaScript or actions, is not a PDF pypdf can read, holds more than
MAX_ENTRIES fields or nests them deeper than MAX_DEPTH; pypdf's own limits (stream sizes, array and
dictionary sizes, decompressed bytes) are lowered to what a sheet needs for the read; and the whole read,
inside pypdf too, stops at the same deadline as an answer file's (checked on every Python call, so no
loop of pypdf's can outlast it). A PDF with no form at all (printed and scanned, or flattened by a viewer)
is listed with the reason NO_FORM.
"""
from __future__ import annotations

import io
import logging
import sys
import time
from contextlib import contextmanager
from pathlib import Path

from exgen.errors import SubmissionError
from exgen.runtime.safefile import UnsafeFile, read_bytes

from .echo import shown
from .formats import MAX_DEPTH, MAX_ENTRIES, Loaded

#: A sheet is about 100 KiB; a viewer that rewrites it (embedding fonts) may make it a few times that.
MAX_PDF_BYTES = 8 * 1024 * 1024
#: The longest value kept from a field: an answer is a short line.
MAX_VALUE_LENGTH = 1000
#: The document information keys exgen.render.pdf_form writes.
INFO_KEYS = {"assignment": "/ExgenAssignment", "student": "/ExgenStudent", "code": "/ExgenCode"}

NO_FORM = "no typed answers in this PDF: was it printed or flattened?"
ALL_EMPTY = ("Every answer box of this PDF is empty: if you typed your answers, the viewer may not have saved "
             "them (save the PDF after typing, or hand in the answer file).")
ENCRYPTED = "the PDF is encrypted (protected by a password); save it without one"
SCRIPT = "the PDF carries JavaScript or actions, which a sheet never does; not read"
TOO_LONG = "the PDF took too long to read; a sheet's form is read in a moment"
TOO_MANY = f"the PDF has more than {MAX_ENTRIES} form fields: far more than a sheet's form"
TOO_DEEP = f"the PDF's form fields are nested more than {MAX_DEPTH} levels deep"
UNREADABLE = "not a readable PDF ({reason})"
OTHER_FIELD = "the PDF's box {name!r} is not one of the sheet's answers; ignored"

#: pypdf's limits for this read: what a sheet's form needs, far below pypdf's defaults (tens of MB).
_LIMITS = dict(
    maximum_declared_stream_length=MAX_PDF_BYTES, array_based_stream_maximum_output_length=MAX_PDF_BYTES,
    array_maximum_element_count=10 * MAX_ENTRIES, dictionary_maximum_element_count=MAX_ENTRIES,
    zlib_maximum_output_length=4 * MAX_PDF_BYTES, lzw_maximum_output_length=MAX_PDF_BYTES,
    run_length_maximum_output_length=MAX_PDF_BYTES, brotli_maximum_output_length=MAX_PDF_BYTES,
    jbig2_maximum_output_length=MAX_PDF_BYTES, stream_decoding_work_maximum_length=8 * MAX_PDF_BYTES,
    form_fields_maximum_entries=MAX_ENTRIES, form_fields_maximum_depth=MAX_DEPTH,
    page_tree_maximum_entries=MAX_ENTRIES, page_tree_maximum_depth=MAX_DEPTH, jbig2dec_binary=None,
)
#: Keys that make a PDF do something when opened or used.
_ACTIONS = ("/OpenAction", "/AA", "/JavaScript", "/JS")


class _TooLong(BaseException):
    """Raised inside pypdf at the deadline: a BaseException, so no `except Exception` in a library's
    error recovery can swallow it and carry on."""


def load_pdf(path: Path, text: str | None = None, deadline: float | None = None) -> Loaded:
    """The form's values as an answer file's data: {assignment, student, code, answers: {slot: {part: value}}}.
    `text` is unused (a PDF is read from its bytes); `deadline` bounds the whole read."""
    raw = read_pdf_bytes(path, deadline)
    try:
        with _until(deadline), _quiet_pypdf():
            return _read(path, raw)
    except _TooLong:
        raise SubmissionError(path, TOO_LONG) from None
    except RecursionError:
        raise SubmissionError(path, TOO_DEEP) from None
    except SubmissionError:
        raise
    except MemoryError:
        raise SubmissionError(path, UNREADABLE.format(reason="too large to read")) from None
    except Exception as exc:  # pypdf's errors, and whatever a broken file makes it raise
        raise SubmissionError(path, UNREADABLE.format(reason=_reason(exc))) from None


def read_pdf_bytes(path: Path, deadline: float | None = None) -> bytes:
    """The file's bytes, at most MAX_PDF_BYTES, checked to start as a PDF does; as every answer file, a regular
    file only, opened without blocking, by the deadline (exgen.runtime.safefile)."""
    try:
        raw = read_bytes(path, MAX_PDF_BYTES, deadline, follow_links=False)
    except UnsafeFile as exc:
        if exc.kind == "large":
            raise SubmissionError(path, f"the PDF is {exc.size:,} bytes or more; a sheet may be at most "
                                        f"{MAX_PDF_BYTES // (1024 * 1024)} MiB") from None
        raise SubmissionError(path, exc.reason) from None
    except OSError as exc:
        raise SubmissionError(path, f"cannot open the file: {exc.strerror or exc}") from exc
    if b"%PDF-" not in raw[:1024]:
        raise SubmissionError(path, "not a PDF (it does not start as one does)")
    return raw


def _read(path: Path, raw: bytes) -> Loaded:
    from pypdf import PdfReader, apply_configuration
    from pypdf.generic import DictionaryObject

    with apply_configuration(**_LIMITS):
        reader = PdfReader(io.BytesIO(raw), strict=False)
        if reader.is_encrypted:
            raise SubmissionError(path, ENCRYPTED)
        root = reader.trailer["/Root"].get_object()
        if not isinstance(root, DictionaryObject):
            raise SubmissionError(path, UNREADABLE.format(reason="it has no catalog"))
        names = _dict(root.get("/Names"))
        if any(key in root for key in _ACTIONS) or (names is not None and "/JavaScript" in names) or \
                any(_acts(page) for page in reader.pages):
            raise SubmissionError(path, SCRIPT)
        form = _dict(root.get("/AcroForm"))
        top = form.get("/Fields") if form is not None else None
        top = top.get_object() if top is not None else None
        if not isinstance(top, list) or not top:
            raise SubmissionError(path, NO_FORM)
        loaded = Loaded({"answers": {}})
        _fields(path, top, loaded)
        info = _dict(reader.trailer.get("/Info"))
        for key, name in INFO_KEYS.items():
            value = info.get(name) if info is not None else None
            value = value.get_object() if value is not None else None
            loaded.data[key] = str(value) if isinstance(value, str) else None
    answers = loaded.data["answers"]
    if not any(v.strip() for parts in answers.values() for v in parts.values() if isinstance(v, str)):
        loaded.warn(ALL_EMPTY)
    return loaded


def _fields(path: Path, top: list, loaded: Loaded) -> None:
    """Every terminal field's value, under its question and part (its parent's name and its own); a field
    is visited once however often it is referred to, so a cycle of /Kids ends."""
    from pypdf.generic import IndirectObject

    seen: set[int] = set()
    count = 0
    stack = [(ref, (), None, None) for ref in reversed(top)]  # (field, names above, inherited /FT, /V)
    while stack:
        ref, above, kind, value = stack.pop()
        if isinstance(ref, IndirectObject):
            if ref.idnum in seen:
                continue
            seen.add(ref.idnum)
        field = _dict(ref)
        if field is None:
            continue
        count += 1
        if count > MAX_ENTRIES:
            raise SubmissionError(path, TOO_MANY)
        if _acts(field):
            raise SubmissionError(path, SCRIPT)
        name = field.get("/T")
        names = above + (str(name.get_object()),) if name is not None else above
        if len(names) > MAX_DEPTH:
            raise SubmissionError(path, TOO_DEEP)
        kind = field.get("/FT", kind)
        value = field.get("/V", value)
        kids = field.get("/Kids")
        kids = kids.get_object() if kids is not None else None
        named_kids = [k for k in kids if _has_name(k) and not (isinstance(k, IndirectObject) and k.idnum in seen)] \
            if isinstance(kids, list) else []  # a kid already read (a cycle) is not read again
        if named_kids:
            stack += [(k, names, kind, value) for k in reversed(named_kids)]
        elif names:
            _answer(loaded, names, value)


def _answer(loaded: Loaded, names: tuple[str, ...], value) -> None:
    """A field's value under answers[slot][part]: its question's name and its own (the last of its names)."""
    if len(names) < 2:
        loaded.warn(OTHER_FIELD.format(name=shown(names[0], 40)))
        return
    slot, part = ".".join(names[:-1]), names[-1]
    loaded.data["answers"].setdefault(slot, {})[part] = _value(value)


def _value(value):
    """The text typed (a choice's text), "" for nothing, or a list when a field holds several values
    (the answer then reads as "not a single value")."""
    if value is None:
        return ""
    value = value.get_object()
    if isinstance(value, bytes):  # a string that is not text: its bytes as Latin-1, to be shown and refused
        return value.decode("latin-1")[:MAX_VALUE_LENGTH]
    if isinstance(value, list):
        return [str(v)[:MAX_VALUE_LENGTH] for v in value[:MAX_ENTRIES]]
    text = str(value)
    if text.startswith("/") and type(value).__name__ == "NameObject":  # a check box's state
        text = text[1:]
    return text[:MAX_VALUE_LENGTH]


def _has_name(kid) -> bool:
    """A kid that is a field of its own (it has a name), not only its parent's widget."""
    kid = _dict(kid)
    return kid is not None and "/T" in kid


def _acts(obj) -> bool:
    """Whether a field or page carries an action or additional actions (a sheet's never do)."""
    return any(key in obj for key in ("/A", "/AA"))


def _dict(obj):
    from pypdf.generic import DictionaryObject

    obj = obj.get_object() if obj is not None else None
    return obj if isinstance(obj, DictionaryObject) else None


@contextmanager
def _until(deadline: float | None):
    """Raise _TooLong on the first Python call after `deadline`, in this thread, in any code (pypdf's
    included); a tracer already set (a debugger, coverage) goes on being called."""
    if deadline is None:
        yield
        return
    previous = sys.gettrace()

    def trace(frame, event, arg):
        if time.perf_counter() > deadline:
            raise _TooLong
        return previous(frame, event, arg) if previous is not None else None

    sys.settrace(trace)
    try:
        yield
    finally:
        sys.settrace(previous)


@contextmanager
def _quiet_pypdf():
    """pypdf's warnings about a broken file are not the user's business: the file is refused, or read."""
    logger = logging.getLogger("pypdf")
    level = logger.level
    logger.setLevel(logging.ERROR + 10)
    try:
        yield
    finally:
        logger.setLevel(level)


def _reason(exc: BaseException) -> str:
    text = " ".join(str(exc).split()) or type(exc).__name__
    return shown(text, 120)
