"""Turn the bytes of an answer file (YAML, JSON or CSV) into plain data, treating every byte as hostile.

Each loader returns a Loaded: nested dicts of text (answers are kept exactly as typed, never
read as YAML floats, ints or booleans), the line of each key path it knows, and warnings. Nothing
is ever constructed from a tag; YAML aliases (the "billion laughs" bomb) are refused; nesting,
size and encoding are bounded. A file that cannot be read raises SubmissionError with the line.
"""
from __future__ import annotations

import codecs
import csv
import io
import json
import re
import time
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from exgen.errors import SubmissionError
from exgen.runtime.safefile import UnsafeFile, read_bytes

from .echo import shown

MAX_FILE_BYTES = 256 * 1024
MAX_DEPTH = 16
#: Keys, values and list items in one file: an honest answer file has a few hundred at most.
MAX_ENTRIES = 2000
#: Wall-clock bound on reading one file, whatever is in it.
READ_SECONDS = 2.0
#: Notes kept about one file (duplicate keys, ignored rows); the rest are counted.
MAX_WARNINGS = 10
SUFFIXES = {".yaml": "yaml", ".yml": "yaml", ".json": "json", ".csv": "csv", ".pdf": "pdf"}
#: Kinds read from their bytes by their loader, not as text first.
BINARY = {"pdf"}
#: Tags a YAML answer file may carry written out (!!str); anything else is refused, never built.
_CORE = "tag:yaml.org,2002:"
CSV_HEADER_KEYS = ("student", "assignment", "code")
CSV_COLUMN_NAMES = {"slot", "question", "q"}



@dataclass
class Loaded:
    data: object
    lines: dict[tuple, int] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    more_warnings: int = 0  # beyond MAX_WARNINGS: counted, not kept

    def line(self, *where) -> int | None:
        return self.lines.get(tuple(where))

    def warn(self, message: str) -> None:
        if len(self.warnings) < MAX_WARNINGS:
            self.warnings.append(message)
        else:
            self.more_warnings += 1

    def all_warnings(self) -> list[str]:
        more = [f"... and {self.more_warnings} more such notes"] if self.more_warnings else []
        return self.warnings + more


def file_kind(path: Path) -> str | None:
    """'yaml', 'json' or 'csv' by the file's suffix; an editor's extra '.txt' ("answers.yaml.txt") is
    looked through. None for anything else."""
    suffixes = [s.lower() for s in Path(path).suffixes[-2:]]
    if suffixes and suffixes[-1] == ".txt" and len(suffixes) == 2:
        suffixes = suffixes[:1]
    return SUFFIXES.get(suffixes[-1]) if suffixes else None


def read_text(path: Path, deadline: float | None = None) -> str:
    """The file as text: a regular file only (a pipe or device is never opened for reading), size-limited,
    read by the deadline (which covers the open), UTF-8 (or UTF-16 with its byte-order mark), no NUL bytes."""
    try:
        raw = read_bytes(path, MAX_FILE_BYTES, deadline, follow_links=False)
    except UnsafeFile as exc:
        raise SubmissionError(path, exc.reason) from None
    except OSError as exc:
        raise SubmissionError(path, f"cannot open the file: {exc.strerror or exc}") from exc
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return raw.decode("utf-16")
        except UnicodeDecodeError as exc:
            raise SubmissionError(path, f"not valid UTF-16 text ({exc.reason})") from exc
    if b"\x00" in raw:
        line = raw[: raw.index(b"\x00")].count(b"\n") + 1
        raise SubmissionError(path, "contains NUL bytes: this is a binary file, not a text answer file", line)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise SubmissionError(path, f"not UTF-8 text (byte 0x{raw[exc.start]:02x}); save the file as UTF-8", line) from exc


# ---- YAML ---------------------------------------------------------------------------------------

class _Refused(Exception):
    def __init__(self, message: str, mark=None):
        super().__init__(message)
        self.line = mark.line + 1 if mark is not None else None


#: libyaml's event parser when PyYAML has it (fast, C); the pure-Python one otherwise. Only events are
#: taken from it: the data is built here, so nothing is constructed from a tag and caps apply first.
_EventLoader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
_NULLS = ("~", "null", "Null", "NULL")


def load_yaml(path: Path, text: str, deadline: float | None = None) -> Loaded:
    """Build plain data from the parser's events: no tags but the core ones, no aliases, at most
    MAX_DEPTH levels and MAX_ENTRIES entries, and no longer than the deadline allows."""
    loaded = Loaded(None)
    try:
        loaded.data = _YamlBuilder(loaded, deadline).build(yaml.parse(text, Loader=_EventLoader))
    except _Refused as exc:
        raise SubmissionError(path, str(exc), exc.line) from None
    except yaml.YAMLError as exc:
        problem = _yaml_problem(exc)
        if "nesting depth" in problem:  # libyaml's own bound, met while scanning ahead
            problem = f"nested more than {MAX_DEPTH} levels deep"
        raise SubmissionError(path, f"not valid YAML: {problem}", _yaml_line(exc, text)) from None
    if loaded.data is _EMPTY:
        raise SubmissionError(path, "the file is empty")
    return loaded


_EMPTY = object()


class _YamlBuilder:
    """Plain dicts, lists and text from a stream of YAML events; records the line of each key path."""

    def __init__(self, loaded: Loaded, deadline: float | None):
        self.loaded, self.deadline, self.entries = loaded, deadline, 0

    def build(self, events):
        root, stack, documents = _EMPTY, [], 0  # stack: [container, path, pending key or _EMPTY]
        for count, event in enumerate(events):
            if count % 256 == 0:
                _check_deadline(self.deadline, event.start_mark)
            if isinstance(event, yaml.DocumentStartEvent):
                documents += 1
                if documents > 1:
                    raise _Refused("not valid YAML: a second document starts here ('---'); an answer file "
                                   "holds one", event.start_mark)
                continue
            if isinstance(event, yaml.AliasEvent):
                raise _Refused("YAML aliases (*name) are not allowed in an answer file", event.start_mark)
            if isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                value = stack.pop()[0]
                if stack:
                    self._place(stack, value)
                else:
                    root = value
                continue
            if not isinstance(event, (yaml.ScalarEvent, yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                continue  # stream and document boundaries
            self._count(event)
            where = self._path(stack, event)
            if isinstance(event, yaml.ScalarEvent):
                value = self._scalar(event)
                if stack and isinstance(stack[-1][0], dict) and stack[-1][2] is _EMPTY:
                    self._key(stack[-1], value, event)
                    continue
                self.loaded.lines.setdefault(where, event.start_mark.line + 1)
                if stack:
                    self._place(stack, value)
                else:
                    root = value
                continue
            if stack and isinstance(stack[-1][0], dict) and stack[-1][2] is _EMPTY:
                raise _Refused("a key must be plain text", event.start_mark)
            self._check_tag(event, "map" if isinstance(event, yaml.MappingStartEvent) else "seq")
            if len(stack) + 1 > MAX_DEPTH:
                raise _Refused(f"nested more than {MAX_DEPTH} levels deep", event.start_mark)
            self.loaded.lines.setdefault(where, event.start_mark.line + 1)
            stack.append([{} if isinstance(event, yaml.MappingStartEvent) else [], where, _EMPTY])
        return root

    def _count(self, event) -> None:
        self.entries += 1
        if self.entries > MAX_ENTRIES:
            raise _Refused(f"more than {MAX_ENTRIES} entries: far more than an answer file holds", event.start_mark)

    @staticmethod
    def _path(stack, event) -> tuple:
        if not stack:
            return ()
        container, where, key = stack[-1]
        return where + ((key,) if isinstance(container, dict) else (len(container),))

    def _scalar(self, event):
        self._check_tag(event, "str", "int", "float", "bool", "null")
        if not event.style and event.value in _NULLS and event.tag is None:  # plain ~ or null: nothing typed
            return None
        return event.value

    @staticmethod
    def _check_tag(event, *allowed: str) -> None:
        if event.tag is not None and event.tag not in {_CORE + t for t in allowed} and event.tag != "!":
            raise _Refused(f"the YAML tag {shown(event.tag, 40)!r} is not allowed in an answer file", event.start_mark)

    def _key(self, frame, key, event) -> None:
        if not isinstance(key, str):
            raise _Refused("a key must be plain text", event.start_mark)
        key = key.strip()
        mapping, where = frame[0], frame[1]
        line = event.start_mark.line + 1
        if key in mapping:
            self.loaded.warn(f"line {line}: {shown(key, 40)!r} appears twice; the last one is used")
        self.loaded.lines[where + (key,)] = line
        frame[2] = key

    @staticmethod
    def _place(stack, value) -> None:
        container, _, key = stack[-1]
        if isinstance(container, dict):
            container[key] = value
            stack[-1][2] = _EMPTY
        else:
            container.append(value)


def _check_deadline(deadline: float | None, mark=None) -> None:
    if deadline is not None and time.perf_counter() > deadline:
        raise _Refused("the file took too long to read; an answer file is a few short lines", mark)


def _yaml_problem(exc: yaml.YAMLError) -> str:
    problem = getattr(exc, "problem", None) or getattr(exc, "reason", None) or str(exc).splitlines()[0]
    return " ".join(str(problem).split())


def _yaml_line(exc: yaml.YAMLError, text: str) -> int | None:
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    if mark is not None:
        return mark.line + 1
    position = getattr(exc, "position", None)  # a ReaderError (a character YAML does not allow)
    return text[:position].count("\n") + 1 if isinstance(position, int) else None


# ---- JSON ---------------------------------------------------------------------------------------

_JSON_TOKEN = re.compile(r'"[^"\\\n]*(?:\\.[^"\\\n]*)*"|[\[\]{}]')  # a string (skipped whole) or a bracket


def load_json(path: Path, text: str, deadline: float | None = None) -> Loaded:
    """Numbers stay the text typed (1.0e+3 is "1.0e+3"); NaN and Infinity stay text and read as unreadable.
    Nesting is measured on the text before anything is built."""
    _json_depth(path, text)
    loaded = Loaded(None)
    entries = 0

    def pairs(items):
        nonlocal entries
        entries += len(items)
        if entries > MAX_ENTRIES:
            raise _Refused(f"more than {MAX_ENTRIES} entries: far more than an answer file holds")
        out = {}
        for key, value in items:
            key = key.strip()
            if key in out:
                loaded.warn(f"{shown(key, 40)!r} appears twice; the last one is used")
            out[key] = value
        return out

    try:
        loaded.data = json.loads(text, parse_float=str, parse_int=str, parse_constant=str, object_pairs_hook=pairs)
    except _Refused as exc:
        raise SubmissionError(path, str(exc)) from None
    except json.JSONDecodeError as exc:
        raise SubmissionError(path, f"not valid JSON: {exc.msg}", exc.lineno) from None
    except RecursionError:
        raise SubmissionError(path, f"nested more than {MAX_DEPTH} levels deep") from None
    return loaded


def _json_depth(path: Path, text: str) -> None:
    """Refuse JSON nested deeper than MAX_DEPTH, with the line where it goes too deep."""
    depth = 0
    for match in _JSON_TOKEN.finditer(text):
        token = match.group()
        if token in "[{":
            depth += 1
            if depth > MAX_DEPTH:
                line = text.count("\n", 0, match.start()) + 1
                raise SubmissionError(path, f"nested more than {MAX_DEPTH} levels deep", line)
        elif token in "]}":
            depth -= 1


# ---- CSV ----------------------------------------------------------------------------------------

def load_csv(path: Path, text: str, deadline: float | None = None) -> Loaded:
    """Rows `slot,part,answer`; rows `student,<id>`, `assignment,<id>`, `code,<code>` give the header;
    an optional column-title row `slot,part,answer` (or `question,...`) is skipped."""
    first = text.split("\n", 1)[0]
    delimiter = ";" if first.count(";") > first.count(",") else ","
    data: dict = {"answers": {}}
    loaded = Loaded(data)
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    try:
        for count, row in enumerate(reader):
            line = reader.line_num
            if count >= MAX_ENTRIES:
                raise SubmissionError(path, f"more than {MAX_ENTRIES} rows: far more than an answer file holds", line)
            if count % 256 == 0:
                try:
                    _check_deadline(deadline)
                except _Refused as exc:
                    raise SubmissionError(path, str(exc), line) from None
            cells = [c.strip() for c in row]
            if not any(cells):
                continue
            head = cells[0].lower()
            if head in CSV_HEADER_KEYS and len(cells) >= 2 and not any(cells[2:]):
                data[head] = cells[1]
                loaded.lines[(head,)] = line
            elif head in CSV_COLUMN_NAMES and len(cells) >= 2 and cells[1].lower() == "part":
                continue
            elif len(cells) >= 3 and cells[0] and cells[1]:
                answer = delimiter.join(row[2:]).strip() if len(cells) > 3 else cells[2]
                slot = data["answers"].setdefault(cells[0], {})
                if cells[1] in slot:
                    loaded.warn(f"line {line}: {shown(cells[0], 20)} {shown(cells[1], 20)} answered twice; "
                                "the last one is used")
                slot[cells[1]] = answer
                loaded.lines[("answers", cells[0], cells[1])] = line
            else:
                loaded.warn(f"line {line}: not a row `slot,part,answer`; ignored")
    except csv.Error as exc:
        raise SubmissionError(path, f"not valid CSV: {exc}", reader.line_num or None) from None
    return loaded

