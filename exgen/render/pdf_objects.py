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

#: One token: a delimiter, a name, a string (parentheses nested once), a hex string, a comment, a run of
#: regular characters (a number, a keyword), or any other byte (a stray parenthesis, brace: refused).
_TOKENS = re.compile(rb"<<|>>|\[|\]|/[^\s/\[\]()<>{}%]*|\((?:[^()\\]|\\.|\((?:[^()\\]|\\.)*\))*\)"
                     rb"|<[0-9A-Fa-f\s]*>|%[^\r\n]*|[^\s/\[\]()<>{}%]+|\S", re.S)  # \S: any other byte, refused
_INTEGER = re.compile(rb"[+-]?\d+")
_REAL = re.compile(rb"[+-]?(?:\d+\.\d*|\.\d+)")
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
        at = _skip_space(data, at)
        end = data.find(b"startxref", at)
        if not data.startswith(b"trailer", at) or end < 0:
            raise PdfSyntaxError("the cross-reference table is not followed by a trailer")
        self.trailer = parse(data[at + len(b"trailer"):end])
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
        start = end = header.end()
        while True:  # to its "endobj" (a string holding the word ends no object: the next one is tried)
            end = self.data.find(b"endobj", end)
            if end < 0:
                raise PdfSyntaxError(f"object {number} does not end")
            try:
                value = parse(self.data[start:end])
                break
            except PdfSyntaxError as exc:
                if "stream" in str(exc):
                    raise PdfSyntaxError(f"object {number} is a stream") from None
                end += len(b"endobj")
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


def parse(text: bytes):
    """The one PDF value `text` holds: tokens found by one regular expression, containers built on a stack (a
    dictionary collected as its keys and values, paired when it closes, a reference from the two integers
    before its R)."""
    stack: list[tuple[bytes, list]] = [(b"", [])]
    for token in _TOKENS.findall(text):
        first = token[0]
        if first == 0x2F:  # /
            value = Name(token.decode("latin-1"))
        elif token in (b"<<", b"["):
            if len(stack) > MAX_NESTING:
                raise PdfSyntaxError("objects nested too deep")
            stack.append((token, []))
            continue
        elif token in (b">>", b"]"):
            opened, items = stack.pop()
            if (opened, token) not in ((b"<<", b">>"), (b"[", b"]")) or not stack:
                raise PdfSyntaxError(f"unbalanced {token.decode()}")
            value = items if token == b"]" else _paired(items)
        elif (first == 0x28 and len(token) > 1) or (first == 0x3C and len(token) > 1):  # ( or <
            value = String(token if first == 0x28 else _SPACE.sub(b"", token))
        elif first == 0x25:  # a comment
            continue
        elif token == b"R":
            items = stack[-1][1]
            if len(items) < 2 or type(items[-1]) is not int or type(items[-2]) is not int or items[-1] != 0:
                raise PdfSyntaxError("a reference that is not to an object of generation 0")
            items[-2:] = [Ref(items[-2])]
            continue
        elif token.isdigit() or _INTEGER.fullmatch(token):
            value = int(token)
        elif token in _WORDS:
            value = _WORDS[token]
        elif _REAL.fullmatch(token):
            value = Number(token)
        else:
            raise PdfSyntaxError(f"unexpected {token[:20].decode('latin-1')!r}" + (" (a stream)" if token == b"stream" else ""))
        stack[-1][1].append(value)
    if len(stack) != 1 or len(stack[0][1]) != 1:
        raise PdfSyntaxError("not one complete PDF value")
    return stack[0][1][0]


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
    out: list[bytes] = []
    _write(value, out)
    return b"".join(out)


def _write(value, out: list) -> None:
    kind = type(value)
    if kind is dict:
        out.append(b"<<")
        for key, item in value.items():
            out.append(key.encode("latin-1"))
            out.append(b" ")
            _write(item, out)
        out.append(b">>")
    elif kind is list or kind is tuple:
        out.append(b"[")
        for i, item in enumerate(value):
            if i:
                out.append(b" ")
            _write(item, out)
        out.append(b"]")
    elif kind is Stream:
        _write({**value.entries, "/Length": len(value.data)}, out)
        out += (b"\nstream\n", value.data, b"\nendstream")
    else:
        out.append(_ATOMS[kind](value) if kind in _ATOMS else _atom(value))


def _atom(value) -> bytes:
    for kind, write in _ATOMS.items():  # a subclass of one of the kinds (an IntEnum, a str subclass)
        if isinstance(value, kind) and kind is not bool:
            return write(value)
    raise TypeError(f"no PDF form for {type(value).__name__}")


_ATOMS = {
    Name: lambda v: v.encode("latin-1"),
    Ref: lambda v: b"%d 0 R" % v,
    bool: lambda v: b"true" if v else b"false",
    Number: lambda v: v.text,
    int: lambda v: b"%d" % v,
    float: lambda v: (b"%.2f" % v).rstrip(b"0").rstrip(b".") or b"0",
    String: bytes,
    str: lambda v: text_string(v),
    type(None): lambda v: b"null",
}


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
