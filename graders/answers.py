"""Answer files handed back: reading what comes back, whatever the format.

The form itself is written by exgen.render.answer_form. Students may return it as YAML, or JSON
with the same keys, or CSV with one answer per row (`slot,part,answer`, e.g. `q1,a,168.8 deg`) and
optional rows `student,<id>`, `assignment,<id>` and `code,<code>`; a title row `slot,part,answer` is
skipped. Or they hand back the sheet PDF itself, its form typed into (graders.pdf_form). Whatever the format, an answer is kept as the text typed; a part whose answer is not a
single value is "unreadable", not the file.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

from exgen.errors import SubmissionError

from .echo import shown
from .formats import BINARY, READ_SECONDS, SUFFIXES, Loaded, file_kind, load_csv, load_json, load_yaml, read_text

HEADER_KEYS = ("assignment", "student", "code")
MAX_HEADER_LENGTH = 200


def load_pdf(path: Path, text: str | None = None, deadline: float | None = None) -> Loaded:
    """A sheet PDF's typed answers (graders.pdf_form, which reads with the formats' caps: imported only
    when a PDF is read)."""
    from .pdf_form import load_pdf as load

    return load(path, text, deadline)


#: Each kind of answer file's reader, by the kind its name says (formats.SUFFIXES).
LOADERS = {"yaml": load_yaml, "json": load_json, "csv": load_csv, "pdf": load_pdf}


@dataclass(frozen=True)
class Submission:
    """A read answer file. `answers` holds the text typed; `problems` holds why a part (or, under the
    part key "", a whole question) could not be read."""

    path: Path | None
    student: str = ""
    assignment: str = ""
    code: str = ""
    answers: dict[str, dict[str, str]] = field(default_factory=dict)
    problems: dict[str, dict[str, str]] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()


def read_submission(path: Path, seconds: float = READ_SECONDS) -> Submission:
    """Read an answer file (.yaml/.yml, .json, .csv, or a sheet PDF with its form filled in) in at most about
    `seconds`; SubmissionError if it cannot be read at all."""
    path = Path(path)
    kind = file_kind(path)
    if kind is None:
        raise SubmissionError(path, f"not an answer file: expected {', '.join(sorted(SUFFIXES))}")
    deadline = time.perf_counter() + seconds
    loaded = LOADERS[kind](path, None if kind in BINARY else read_text(path, deadline), deadline)
    return _submission(path, loaded)


def _submission(path: Path, loaded: Loaded) -> Submission:
    data, warnings = loaded.data, loaded.all_warnings()
    if not isinstance(data, dict):
        raise SubmissionError(path, f"the file holds {_what(data)}; it must be a mapping with "
                                    "`student`, `code` and `answers`", loaded.line())
    header = {}
    for key in HEADER_KEYS:
        value = data.get(key)
        if value is None:
            header[key] = ""
        elif isinstance(value, str) and len(value) <= MAX_HEADER_LENGTH:
            header[key] = value.strip()
        else:
            header[key] = ""
            warnings.append(f"`{key}` is {_what(value)}, not a short text; ignored")
    if "answers" in data:
        block = data["answers"] if data["answers"] is not None else {}
    else:  # a file without the `answers:` key: questions at the top level
        block = {k: v for k, v in data.items() if k not in HEADER_KEYS}
    if not isinstance(block, dict):
        raise SubmissionError(path, f"`answers` holds {_what(block)}; it must map each question to its parts",
                              loaded.line("answers"))
    answers: dict[str, dict[str, str]] = {}
    problems: dict[str, dict[str, str]] = {}
    where = ("answers",) if "answers" in data else ()
    for slot, parts in block.items():
        slot = str(slot)
        if parts is None:
            continue
        if not isinstance(parts, dict):
            problems.setdefault(slot, {})[""] = _at(f"the answers to {slot} are {_what(parts)}, not part: answer lines",
                                                   loaded.line(*where, slot))
            continue
        for part, value in parts.items():
            part = str(part)
            if value is None:
                answers.setdefault(slot, {})[part] = ""
            elif isinstance(value, str):
                answers.setdefault(slot, {})[part] = value
            else:
                problems.setdefault(slot, {})[part] = _at(f"the answer is {_what(value)}, not a single value",
                                                         loaded.line(*where, slot, part))
    return Submission(path, header["student"], header["assignment"], header["code"], answers, problems,
                      tuple(warnings))


def _what(value) -> str:
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list):
        return "a list"
    if value is None:
        return "nothing"
    if isinstance(value, bool):
        return "true/false"
    return "text" if isinstance(value, str) else f"a {type(value).__name__}"


def _at(message: str, line: int | None) -> str:
    return f"{message} (line {line})" if line else message

