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
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from exgen.errors import SubmissionError

MAX_FILE_BYTES = 256 * 1024
MAX_DEPTH = 16
SUFFIXES = {".yaml": "yaml", ".yml": "yaml", ".json": "json", ".csv": "csv"}
#: Tags a YAML answer file may carry (implicit or written out); anything else is refused, never built.
_CORE = "tag:yaml.org,2002:"
ALLOWED_TAGS = {_CORE + t for t in ("str", "int", "float", "bool", "null", "map", "seq")}
CSV_HEADER_KEYS = ("student", "assignment", "code")
CSV_COLUMN_NAMES = {"slot", "question", "q"}



@dataclass
class Loaded:
    data: object
    lines: dict[tuple, int] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)

    def line(self, *where) -> int | None:
        return self.lines.get(tuple(where))


def read_text(path: Path) -> str:
    """The file as text: size-limited, UTF-8 (or UTF-16 with its byte-order mark), no NUL bytes."""
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise SubmissionError(path, f"the file is {size:,} bytes; an answer file may be at most "
                                        f"{MAX_FILE_BYTES // 1024} KiB")
        with path.open("rb") as handle:
            raw = handle.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise SubmissionError(path, f"cannot open the file: {exc.strerror or exc}") from exc
    if len(raw) > MAX_FILE_BYTES:
        raise SubmissionError(path, f"an answer file may be at most {MAX_FILE_BYTES // 1024} KiB")
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


class _Loader(yaml.SafeLoader):
    """Composes nodes only: no implicit typing (a scalar stays the text typed), no aliases, bounded depth."""

    yaml_implicit_resolvers: dict = {}

    def __init__(self, stream):
        super().__init__(stream)
        self._depth = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            raise _Refused("YAML aliases (*name) are not allowed in an answer file", self.peek_event().start_mark)
        self._depth += 1
        try:
            if self._depth > MAX_DEPTH:
                raise _Refused(f"nested more than {MAX_DEPTH} levels deep", self.peek_event().start_mark)
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1


def load_yaml(path: Path, text: str) -> Loaded:
    loader = None
    try:
        loader = _Loader(text)  # the reader checks every character here
        node = loader.get_single_node()
    except _Refused as exc:
        raise SubmissionError(path, str(exc), exc.line) from None
    except yaml.YAMLError as exc:
        raise SubmissionError(path, f"not valid YAML: {_yaml_problem(exc)}", _yaml_line(exc, text)) from None
    except RecursionError:
        raise SubmissionError(path, "nested too deeply") from None
    finally:
        if loader is not None:
            loader.dispose()
    if node is None:
        raise SubmissionError(path, "the file is empty")
    loaded = Loaded(None)
    try:
        loaded.data = _plain(node, (), loaded)
        return loaded
    except _Refused as exc:
        raise SubmissionError(path, str(exc), exc.line) from None


def _plain(node, where: tuple, loaded: Loaded):
    """A node as dicts, lists and text; records the line of each key path."""
    if node.tag not in ALLOWED_TAGS:
        raise _Refused(f"the YAML tag {node.tag!r} is not allowed in an answer file", node.start_mark)
    loaded.lines.setdefault(where, node.start_mark.line + 1)
    if isinstance(node, yaml.ScalarNode):
        if node.style is None and node.value in ("~", "null", "Null", "NULL"):
            return None
        return node.value
    if isinstance(node, yaml.SequenceNode):
        return [_plain(item, where + (i,), loaded) for i, item in enumerate(node.value)]
    out = {}
    for key_node, value_node in node.value:
        if not isinstance(key_node, yaml.ScalarNode) or key_node.tag not in ALLOWED_TAGS:
            raise _Refused("a key must be plain text", key_node.start_mark)
        key = key_node.value.strip()
        line = key_node.start_mark.line + 1
        if key in out:
            loaded.warnings.append(f"line {line}: {key!r} appears twice; the last one is used")
        loaded.lines[where + (key,)] = line
        out[key] = _plain(value_node, where + (key,), loaded)
    return out


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

def load_json(path: Path, text: str) -> Loaded:
    """Numbers stay the text typed (1.0e+3 is "1.0e+3"); NaN and Infinity stay text and read as unreadable."""
    loaded = Loaded(None)

    def pairs(items):
        out = {}
        for key, value in items:
            key = key.strip()
            if key in out:
                loaded.warnings.append(f"{key!r} appears twice; the last one is used")
            out[key] = value
        return out

    try:
        loaded.data = json.loads(text, parse_float=str, parse_int=str, parse_constant=str, object_pairs_hook=pairs)
    except json.JSONDecodeError as exc:
        raise SubmissionError(path, f"not valid JSON: {exc.msg}", exc.lineno) from None
    except RecursionError:
        raise SubmissionError(path, "nested too deeply") from None
    return loaded


# ---- CSV ----------------------------------------------------------------------------------------

def load_csv(path: Path, text: str) -> Loaded:
    """Rows `slot,part,answer`; rows `student,<id>`, `assignment,<id>`, `code,<code>` give the header;
    an optional column-title row `slot,part,answer` (or `question,...`) is skipped."""
    first = text.split("\n", 1)[0]
    delimiter = ";" if first.count(";") > first.count(",") else ","
    data: dict = {"answers": {}}
    loaded = Loaded(data)
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    try:
        for row in reader:
            line = reader.line_num
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
                    loaded.warnings.append(f"line {line}: {cells[0]} {cells[1]} answered twice; the last one is used")
                slot[cells[1]] = answer
                loaded.lines[("answers", cells[0], cells[1])] = line
            else:
                loaded.warnings.append(f"line {line}: not a row `slot,part,answer`; ignored")
    except csv.Error as exc:
        raise SubmissionError(path, f"not valid CSV: {exc}", reader.line_num or None) from None
    return loaded


LOADERS = {"yaml": load_yaml, "json": load_json, "csv": load_csv}
