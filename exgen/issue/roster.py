"""The class list: a CSV file with a column of student ids (and names, emails, sections), as an instructor
or a learning system writes it.

What spreadsheets and learning systems write is understood: a comma, semicolon or tab between fields
(sniffed from the header, as answer CSVs are), UTF-8 with or without its byte-order mark, or UTF-16 with
one (Excel's "Unicode text"); the id under the header a learning system gives it ("ID number", "SIS User
ID", "Student ID", "Username"), the name as one column or as first and last names. What cannot be used
is refused with the line and column: another encoding (Latin-1: with what the bytes would read as), a row
with more fields than the header (a comma in a name), an id that is not a plain name, the same id twice,
or ids differing only in capitals (their folders would be one on Windows and macOS).
"""
from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import AssignmentError
from ..runtime.safefile import NotText, Unreadable, read_text
from .assignment import Student

MAX_BYTES = 16 * 1024 * 1024
READ_SECONDS = 10.0
_SAFE_ID = re.compile(r"\A[A-Za-z0-9][A-Za-z0-9._-]{0,63}\Z")
DELIMITERS = (",", ";", "\t")
DELIMITER_NAMES = {",": "comma", ";": "semicolon", "\t": "tab"}

#: Header names of each field, first found wins: exgen's own, then what learning systems export. Canvas's
#: "ID" is its internal number: its "SIS User ID", the institution's id, goes first.
ID_HEADERS = ("sis user id", "id", "id number", "idnumber", "student id", "student number", "student no",
              "matric", "matric no", "matric number", "matriculation number", "username", "user name",
              "login id", "sis login id", "user id")
NAME_HEADERS = ("name", "full name", "fullname", "student name", "student")
FIRST_HEADERS = ("first name", "firstname", "given name", "given names", "forename")
LAST_HEADERS = ("last name", "lastname", "surname", "family name")
EMAIL_HEADERS = ("email", "email address", "e-mail", "e-mail address", "mail")
SECTION_HEADERS = ("section", "sections", "group", "groups", "tutorial group", "class")

NO_ID = ("no column of student ids: the roster needs one headed `id` (or as a learning system heads it: "
         "ID number, SIS User ID, Student ID, Username); found {found}")


@dataclass(frozen=True)
class Roster:
    students: tuple[Student, ...]
    #: which header each field came from ("id" -> "ID number"), to say so when it is not exgen's own
    columns: dict
    delimiter: str = ","


def load_roster(path: Path) -> list[Student]:
    """The students of a class list (see the module); AssignmentError names the line and what to do."""
    return list(read_roster(path).students)


def read_roster(path: Path) -> Roster:
    path = Path(path)
    text = _text(path)
    lines = text.splitlines()
    header_line = next((n for n, line in enumerate(lines, start=1) if line.strip()), None)
    if header_line is None:
        raise AssignmentError(path, "the roster is empty: it needs a header line (id,name,email,section) and a "
                                    "line per student")
    delimiter = _delimiter(lines[header_line - 1])
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    try:
        rows = _rows(reader)
        header_at, header = next(rows)
        columns = _columns(path, header, header_at)
        students = _students(path, rows, columns, len(header), lines, delimiter)
    except csv.Error as exc:
        raise AssignmentError(path, f"not valid CSV: {exc}", reader.line_num or None) from None
    described = {field: "` + `".join(header[i] for i in (index if isinstance(index, tuple) else (index,)))
                 for field, index in columns.items()}
    return Roster(tuple(students), described, delimiter)


def _text(path: Path) -> str:
    try:
        return read_text(path, MAX_BYTES, READ_SECONDS)
    except NotText as exc:
        if exc.reason.startswith("not UTF-8"):
            raise _not_utf8(path, exc) from None
        raise AssignmentError(path, f"{exc.reason}; save the roster as CSV UTF-8", exc.line, exc.column) from None
    except Unreadable as exc:
        raise AssignmentError(path, "no such roster file" if exc.missing else
                              f"cannot read the roster: {exc.reason}") from None


def _not_utf8(path: Path, exc: NotText) -> AssignmentError:
    """Where the text stops being UTF-8, and what it says read as Windows-1252 (Latin-1), the likeliest."""
    raw = exc.raw
    start = exc.offset - exc.column + 1
    end = raw.find(b"\n", exc.offset)
    line_bytes = raw[start: end if end != -1 else len(raw)]
    try:
        read = line_bytes.decode("cp1252").strip()
    except UnicodeDecodeError:
        read = line_bytes.decode("latin-1").strip()
    word = next((w for w in re.split(r"[,;\t]", read) if any(ord(c) > 127 for c in w)), read)[:40]
    return AssignmentError(path, f"{exc.reason}: saved as Latin-1 or Windows-1252 it reads {word.strip()!r}; save "
                                 "the roster as CSV UTF-8 (in Excel: Save As, CSV UTF-8)", exc.line, exc.column)


def _delimiter(header: str) -> str:
    """The delimiter that splits the header into the most fields (a comma when none splits it)."""
    counts = {d: header.count(d) for d in DELIMITERS}
    best = max(DELIMITERS, key=lambda d: counts[d])
    return best if counts[best] else ","


def _rows(reader):
    """(line where the record starts, its cells stripped) for every record that is not blank."""
    line = 1
    for row in reader:
        cells = [c.strip() for c in row]
        if any(cells):
            yield line, cells
        line = reader.line_num + 1


def _header_name(cell: str) -> str:
    return " ".join(cell.replace("_", " ").strip().strip('"').lower().split())


def _columns(path: Path, header: list[str], line: int) -> dict:
    """Which cell of a row holds each field: an index, or for a name made of first and last names a pair."""
    names = [_header_name(c) for c in header]
    found = {}
    for field, candidates in (("id", ID_HEADERS), ("email", EMAIL_HEADERS), ("section", SECTION_HEADERS),
                              ("name", NAME_HEADERS)):
        index = next((names.index(c) for c in candidates if c in names), None)
        if index is not None:
            found[field] = index
    if "id" not in found:
        shown = ", ".join(h for h in header if h) or "no header"
        raise AssignmentError(path, NO_ID.format(found=shown[:200]), line)
    if "name" not in found or found["name"] == found["id"]:
        first = next((names.index(c) for c in FIRST_HEADERS if c in names), None)
        last = next((names.index(c) for c in LAST_HEADERS if c in names), None)
        found.pop("name", None)
        if first is not None or last is not None:
            found["name"] = tuple(i for i in (first, last) if i is not None)
    return found


def _students(path: Path, rows, columns: dict, width: int, lines: list[str], delimiter: str) -> list[Student]:
    students, seen, folded = [], {}, {}
    for line, cells in rows:
        extra = [c for c in cells[width:] if c]
        if extra:
            raise AssignmentError(path, f"this row has {len(cells)} fields, but the header names {width}: a "
                                        f"{DELIMITER_NAMES[delimiter]} inside a name or another field? Put that field "
                                        f"in double quotes (\"Lim{delimiter} Daniel\")", line,
                                  _column(lines, line, width, delimiter))

        def cell(field: str) -> str:
            index = columns.get(field)
            if isinstance(index, tuple):
                return " ".join(cells[i] for i in index if i < len(cells) and cells[i])
            return cells[index] if index is not None and index < len(cells) else ""

        sid = cell("id")
        column = _column(lines, line, columns["id"], delimiter)
        if not sid:
            raise AssignmentError(path, "no student id on this line (its id column is empty)", line, column)
        if not _SAFE_ID.match(sid):
            raise AssignmentError(path, f"student id {sid[:40]!r} must be letters, digits, '.', '_' or '-', starting "
                                        "with a letter or digit (it names the student's folders)", line, column)
        if sid in seen:
            raise AssignmentError(path, f"student id {sid!r} appears twice (first on line {seen[sid]})", line, column)
        other = folded.get(sid.casefold())
        if other is not None:
            raise AssignmentError(path, f"student id {sid!r} is {other[0]!r} of line {other[1]} in other capitals: "
                                        "their folders would be one on Windows and macOS; give each student an id "
                                        "of their own", line, column)
        seen[sid], folded[sid.casefold()] = line, (sid, line)
        students.append(Student(sid, cell("name"), cell("email"), cell("section")))
    if not students:
        raise AssignmentError(path, "the roster lists no students: a line per student below the header")
    return students


def _column(lines: list[str], line: int, field: int, delimiter: str) -> int | None:
    """The column where field number `field` starts on a line (quotes respected), for an error's place."""
    if not 1 <= line <= len(lines):
        return None
    text, index, quoted = lines[line - 1], 0, False
    if field == 0:
        return 1
    for position, char in enumerate(text):
        if char == '"':
            quoted = not quoted
        elif char == delimiter and not quoted:
            index += 1
            if index == field:
                return position + 2
    return len(text) + 1
