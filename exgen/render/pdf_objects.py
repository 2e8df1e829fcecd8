"""The PDF objects of a typeset sheet, read one by one, and an incremental update that writes objects after it.

Adding the form reads about seventy small objects of a sheet (its pages, their annotations, structure
elements): pypdf parses an object in about 0.15 ms, which for a sheet cost more than the rest of the form
together. Here only the objects asked for are read, through the file's cross-reference table, by a reader
of the syntax Typst writes (ISO 32000 7.3: no streams are read, and a file with a cross-reference stream or
an earlier update is refused as not Typst's). What is read is written back as it was: names, numbers and
strings keep their bytes.

This reads exgen's own typesetter's output, never a student's file (graders.pdf_form reads those, with
pypdf and its limits).
"""
from __future__ import annotations

import io
import re


class PdfSyntaxError(ValueError):
    """The bytes are not a PDF object as Typst writes it."""


class Name(str):
    """A PDF name as written ("/Widget", "/application#2Fjson")."""


class Ref(int):
    """An indirect reference to object number `self` (generation 0, the only one Typst writes)."""


class Number(float):
    """A real number read from a file, written back with the digits it had."""

    def __new__(cls, text: bytes):
        number = super().__new__(cls, float(text))
        number.text = text
        return number


class String(bytes):
    """A string as written, with its delimiters: "(exgen-field:1.0)" or "<FEFF0041>"."""

    def text(self) -> str:
        """The string's characters (a text string: UTF-16 with its mark, else PDFDocEncoding read as Latin-1)."""
        data = bytes.fromhex(self[1:-1].decode("ascii")) if self.startswith(b"<") else _unescape(self[1:-1])
        if data.startswith(b"\xfe\xff"):
            return data[2:].decode("utf-16-be", "replace")
        return data.decode("latin-1")


class Stream:
    """A stream object to write: its dictionary (without /Length) and its bytes."""

    def __init__(self, entries: dict, data: bytes):
        self.entries, self.data = entries, data


# ---- reading ----------------------------------------------------------------------------------------

_TOKEN = re.compile(rb"""
    (?:\s|%[^\r\n]*)*                                   # white space and comments
    (?:(?P<delim><<|>>|\[|\])
      |(?P<name>/[^\s/\[\]()<>{}%]*)
      |(?P<ref>\d+)\s+0\s+R(?![^\s/\[\]()<>{}%])
      |(?P<int>[+-]?\d+)(?![.\d])
      |(?P<real>[+-]?(?:\d+\.\d*|\.\d+))
      |(?P<literal>\((?:[^()\\]|\\.|\((?:[^()\\]|\\.)*\))*\))   # a string, with parentheses nested once
      |(?P<hex><[0-9A-Fa-f\s]*>)
      |(?P<word>true|false|null|endobj|stream|obj))""", re.X | re.S)
_WORDS = {b"true": True, b"false": False, b"null": None}
_OBJECT = re.compile(rb"\s*(\d+)\s+(\d+)\s+obj")
_STARTXREF = re.compile(rb"startxref\s+(\d+)\s+%%EOF\s*$")
_SUBSECTION = re.compile(rb"\s*(\d+)\s+(\d+)\s*?(?:\r\n|\r|\n)")
_SPACE = re.compile(rb"\s")
_ESCAPES = {ord("n"): b"\n", ord("r"): b"\r", ord("t"): b"\t", ord("b"): b"\b", ord("f"): b"\f"}
MAX_NESTING = 64


class Reader:
    """A PDF's trailer and, on request, any of its objects, by its one cross-reference table."""

    def __init__(self, data: bytes):
        self.data = data
        found = _STARTXREF.search(data[-64:])
        if not found:
            raise PdfSyntaxError("the PDF does not end with a cross-reference offset")
        self.xref_offset = int(found.group(1))
        self._sections: list[tuple[int, int, int]] = []  # (first object, count, offset of its first entry)
        at = self.xref_offset
        if data[at:at + 4] != b"xref":
            raise PdfSyntaxError("the PDF has no cross-reference table where it says (a stream, or an update)")
        at += 4
        while True:
            section = _SUBSECTION.match(data, at)
            if not section:
                break
            first, count = int(section.group(1)), int(section.group(2))
            self._sections.append((first, count, section.end()))
            at = section.end() + 20 * count
        if not data.startswith(b"trailer", _skip_space(data, at)):
            raise PdfSyntaxError("the cross-reference table is not followed by a trailer")
        self.trailer, _ = self._value(_skip_space(data, at) + len(b"trailer"))
        if not isinstance(self.trailer, dict) or "/Prev" in self.trailer:
            raise PdfSyntaxError("the PDF has been updated since it was typeset")
        self._cache: dict[int, object] = {}

    def object(self, number: int):
        """Object `number`'s value (a dict, list, ...); a stream is not read."""
        if number in self._cache:
            return self._cache[number]
        offset = self._offset(number)
        header = _OBJECT.match(self.data, offset)
        if not header or int(header.group(1)) != number:
            raise PdfSyntaxError(f"object {number} is not where the cross-reference table puts it")
        value, at = self._value(header.end())
        word = _TOKEN.match(self.data, at)
        if not word or word.group("word") != b"endobj":
            raise PdfSyntaxError(f"object {number} is a stream or does not end")
        self._cache[number] = value
        return value

    def resolve(self, value):
        """The value itself, or the object it refers to."""
        return self.object(value) if isinstance(value, Ref) else value

    def _offset(self, number: int) -> int:
        for first, count, start in self._sections:
            if first <= number < first + count:
                entry = self.data[start + 20 * (number - first): start + 20 * (number - first) + 18]
                if entry[17:18] != b"n":
                    raise PdfSyntaxError(f"object {number} is free")
                return int(entry[:10])
        raise PdfSyntaxError(f"object {number} is not in the cross-reference table")

    def _value(self, at: int):
        """The value starting at `at`, and where it ends: tokens read by one scanner, containers built on a
        stack (a dictionary is collected as its keys and values, paired when it closes)."""
        scanner = _TOKEN.scanner(self.data, at)
        stack: list[tuple[bytes, list]] = [(b"", [])]
        while True:
            token = scanner.match()
            if token is None:
                raise PdfSyntaxError(f"no PDF object at byte {at}")
            kind = token.lastgroup
            text = token.group(kind)
            if kind == "delim":
                if text in (b"<<", b"["):
                    if len(stack) > MAX_NESTING:
                        raise PdfSyntaxError("objects nested too deep")
                    stack.append((text, []))
                    continue
                opened, items = stack.pop()
                if (opened, text) not in ((b"<<", b">>"), (b"[", b"]")) or not stack:
                    raise PdfSyntaxError(f"unbalanced {text.decode()} at byte {token.start(kind)}")
                value = items if text == b"]" else _paired(items)
            elif kind == "name":
                value = Name(text.decode("latin-1"))
            elif kind == "ref":
                value = Ref(int(text))
            elif kind == "int":
                value = int(text)
            elif kind == "real":
                value = Number(text)
            elif kind == "literal":
                value = String(text)
            elif kind == "hex":
                value = String(_SPACE.sub(b"", text))
            elif text in _WORDS:
                value = _WORDS[text]
            else:
                raise PdfSyntaxError(f"unexpected {text.decode()} at byte {token.start(kind)}")
            stack[-1][1].append(value)
            if len(stack) == 1:
                return value, token.end()


def _paired(items: list) -> dict:
    if len(items) % 2 or not all(isinstance(k, Name) for k in items[::2]):
        raise PdfSyntaxError("a dictionary whose keys are not all names")
    return dict(zip(items[::2], items[1::2]))


def _skip_space(data: bytes, at: int) -> int:
    while at < len(data) and data[at] in b" \t\r\n\f\0":
        at += 1
    return at


def _unescape(body: bytes) -> bytes:
    out, at = bytearray(), 0
    while at < len(body):
        byte = body[at]
        if byte != 0x5C:
            out.append(byte)
            at += 1
            continue
        following = body[at + 1: at + 2]
        octal = re.match(rb"[0-7]{1,3}", body[at + 1: at + 4])
        if octal:
            out.append(int(octal.group(0), 8) & 0xFF)
            at += 1 + len(octal.group(0))
        elif following in (b"\r", b"\n"):  # a line continued
            at += 3 if body[at + 1: at + 3] == b"\r\n" else 2
        else:
            out += _ESCAPES.get(following[0], following) if following else b""
            at += 2
    return bytes(out)


# ---- writing ----------------------------------------------------------------------------------------

def serialised(value) -> bytes:
    """The PDF syntax of a value: read ones as they were written, new ones (str as text strings,
    floats to two decimals, enough for points on a page) written here."""
    if isinstance(value, Name):
        return value.encode("latin-1")
    if isinstance(value, Ref):
        return b"%d 0 R" % value
    if isinstance(value, bool):
        return b"true" if value else b"false"
    if isinstance(value, Number):
        return value.text
    if isinstance(value, int):
        return b"%d" % value
    if isinstance(value, float):
        return (b"%.2f" % value).rstrip(b"0").rstrip(b".") or b"0"
    if isinstance(value, String):
        return bytes(value)
    if isinstance(value, str):
        return text_string(value)
    if value is None:
        return b"null"
    if isinstance(value, dict):
        return b"<<" + b"".join(k.encode("latin-1") + b" " + serialised(v) for k, v in value.items()) + b">>"
    if isinstance(value, (list, tuple)):
        return b"[" + b" ".join(serialised(v) for v in value) + b"]"
    if isinstance(value, Stream):
        return (serialised({**value.entries, "/Length": len(value.data)}) + b"\nstream\n" + value.data
                + b"\nendstream")
    raise TypeError(f"no PDF form for {type(value).__name__}")


_PRINTABLE = re.compile(r"[ -~]*")


def text_string(text: str) -> bytes:
    """A PDF text string: printable ASCII as a literal string, anything else as UTF-16BE with its mark."""
    if _PRINTABLE.fullmatch(text):
        return b"(" + text.replace("\\", "\\\\").replace("(", "\\(").replace(")", "\\)").encode("ascii") + b")"
    return b"<" + ("\ufeff" + text).encode("utf-16-be").hex().upper().encode("ascii") + b">"


class Update:
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

    def write(self, original: Reader, trailer: dict) -> bytes:
        """The original file followed by these objects, their cross-reference section and a trailer
        (`trailer` with /Size and /Prev set here)."""
        out = io.BytesIO()
        out.write(original.data)
        if not original.data.endswith(b"\n"):
            out.write(b"\n")
        offsets = {}
        for number in sorted(self.objects):
            offsets[number] = out.tell()
            out.write(b"%d 0 obj\n%s\nendobj\n" % (number, serialised(self.objects[number])))
        start = out.tell()
        out.write(b"xref\n0 1\n0000000000 65535 f\r\n")  # the free list's head, as in every section
        for first, numbers in _runs(sorted(offsets)):
            out.write(b"%d %d\n" % (first, len(numbers)))
            out.writelines(b"%010d 00000 n\r\n" % offsets[n] for n in numbers)
        out.write(b"trailer\n" + serialised({**trailer, "/Size": self.size, "/Prev": original.xref_offset}) + b"\n")
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
