"""Answer files: the form a student fills in, and reading what comes back.

The form is YAML, one per student, written next to the sheet:

    assignment: "hw1"
    student: "s001"
    code: "7F3A-19C2"
    answers:
      q1:   # Q1. Power transmitted by an open flat belt
        a: ""   # angle of contact on the smaller pulley [deg]

Students may instead return JSON with the same keys, or CSV with one answer per row
(`slot,part,answer`, e.g. `q1,a,168.8 deg`) and optional rows `student,<id>`, `assignment,<id>`
and `code,<code>`; a title row `slot,part,answer` is skipped. Whatever the format, an answer is
kept as the text typed; a part whose answer is not a single value is "unreadable", not the file.
"""
from __future__ import annotations

import re
import time
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from exgen.assignment import Sheet
from exgen.errors import SubmissionError

from .echo import shown
from .formats import LOADERS, READ_SECONDS, SUFFIXES, Loaded, file_kind, read_text

HEADER_KEYS = ("assignment", "student", "code")
MAX_HEADER_LENGTH = 200
#: Characters YAML forbids or reads as line breaks; a comment must hold none of them.
_NOT_IN_COMMENT = re.compile("[^\x09\x20-\x7e\xa0-\u2027\u202a-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")

_PLAIN_KEY = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}")
_YAML11_WORDS = {"y", "n", "yes", "no", "on", "off", "true", "false", "null"}

FORM_HEADER = """\
# Answer file for {title}
# Student: {who}    Sheet code: {code}
#
# How to answer: type each answer between the quotes after its part, as a number with an
# optional unit: "168.8 deg", "5.24 m/s", "1.2e3 N". A bare number is read in the unit shown
# in [brackets] at the end of the line; any unit of the right kind is accepted ("0.85 kN"
# where N is shown, "2.94 rad" where deg is shown). Leave "" for a part you do not answer.
# Keep the quotes, and do not change the assignment, student and code lines.
#
# Instead of this file you may hand in CSV with one answer per row, slot,part,answer
# (for example: q1,a,168.8 deg), plus rows student,<your id> and code,<sheet code>;
# or JSON with the same keys as this file.
"""


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


# ---- the form -----------------------------------------------------------------------------------

def answer_form(sheet: Sheet) -> str:
    """The YAML answer file for one student's sheet; read back untouched, every answer is blank."""
    who = " ".join(x for x in (sheet.student.id, f"({sheet.student.name})" if sheet.student.name else "") if x)
    lines = [FORM_HEADER.format(title=_comment(sheet.assignment.title), who=_comment(who),
                                code=_comment(sheet.code))]
    lines += [f"{key}: {_quoted(value)}" for key, value in
              (("assignment", sheet.assignment.id), ("student", sheet.student.id), ("code", sheet.code))]
    lines.append("answers:")
    for question in sheet.questions:
        template = question.variant.template
        lines.append(f"  {_key(question.slot)}:   # Q{question.number}. {_comment(template.title)}")
        for part in template.parts:
            ask = _short_ask(question.variant.asks.get(part.id, part.ask))
            lines.append(f"    {_key(part.id)}: \"\"   # {_comment(ask)} [{_comment(_unit_hint(part))}]")
    return "\n".join(lines) + "\n"


def _key(text: str) -> str:
    """A key as typed when plain YAML reads it as that text everywhere ("q1", "a"), else quoted."""
    plain = _PLAIN_KEY.fullmatch(text) and text.lower() not in _YAML11_WORDS
    return text if plain else _quoted(text)


def _quoted(text: str) -> str:
    """A YAML double-quoted scalar for any text."""
    return yaml.safe_dump(str(text), default_style='"', allow_unicode=True, width=10**6).strip()


def _comment(text: str) -> str:
    """Text safe inside a YAML comment: one line, no characters YAML rejects."""
    return " ".join(_NOT_IN_COMMENT.sub(" ", str(text)).split())


def _short_ask(ask: str) -> str:
    ask = " ".join(ask.split())
    return ask[4:] if ask.lower().startswith("the ") else ask


def _unit_hint(part) -> str:
    if part.type == "choice":
        return "one of: " + ", ".join(part.choices)
    if part.type == "integer":
        return f"whole number{' of ' + part.unit if part.unit else ''}"
    if part.type == "polar":
        return f"{part.unit or 'size'} at deg, e.g. 1.5 {part.unit} at 218 deg"
    return part.unit or "pure number"


# ---- reading what comes back --------------------------------------------------------------------

def read_submission(path: Path, seconds: float = READ_SECONDS) -> Submission:
    """Read an answer file (.yaml/.yml, .json or .csv) in at most about `seconds`; SubmissionError if it
    cannot be read at all."""
    path = Path(path)
    kind = file_kind(path)
    if kind is None:
        raise SubmissionError(path, f"not an answer file: expected {', '.join(sorted(SUFFIXES))}")
    deadline = time.perf_counter() + seconds
    loaded = LOADERS[kind](path, read_text(path), deadline)
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

