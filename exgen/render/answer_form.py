"""The answer file a student fills in: YAML, one per student, written next to the sheet.

    assignment: "hw1"
    student: "s001"
    code: "7F3A-19C2"
    answers:
      q1:   # Q1. Power transmitted by an open flat belt
        a: ""   # angle of contact on the smaller pulley [deg]

Each part's line ends with what its answer type expects, in [brackets]; a type with more to say
(how to write an expression) adds lines to the header. Read back untouched, every answer is blank
(graders.answers reads the file, and the CSV and JSON forms the header describes).
"""
from __future__ import annotations

import re

import yaml

from ..answertypes import answer_type
from .unicode_math import text_to_plain

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
#{notes}
# Instead of this file you may hand in CSV with one answer per row, slot,part,answer
# (for example: q1,a,168.8 deg), plus rows student,<your id> and code,<sheet code>;
# or JSON with the same keys as this file.
"""


def answer_form(sheet) -> str:
    """The YAML answer file for one student's sheet (exgen.issue.assignment.Sheet, as every renderer reads it);
    read back untouched, every answer is blank."""
    who = " ".join(x for x in (sheet.student.id, f"({sheet.student.name})" if sheet.student.name else "") if x)
    lines = [FORM_HEADER.format(title=_comment(sheet.assignment.title), who=_comment(who),
                                code=_comment(sheet.code), notes=_notes(sheet))]
    lines += [f"{key}: {_quoted(value)}" for key, value in
              (("assignment", sheet.assignment.id), ("student", sheet.student.id), ("code", sheet.code))]
    lines.append("answers:")
    for question in sheet.questions:
        template = question.variant.template
        lines.append(f"  {_key(question.slot)}:   # Q{question.number}. {_comment(text_to_plain(template.title))}")
        for part in template.parts:
            ask = _short_ask(text_to_plain(question.variant.asks.get(part.id, part.ask)))
            hint = answer_type(part).form_hint(part)
            lines.append(f"    {_key(part.id)}: \"\"   # {_comment(ask)} [{_comment(hint)}]")
    return "\n".join(lines) + "\n"


def _notes(sheet) -> str:
    """Each answer type's own lines, once, for the types on this sheet."""
    kinds = dict.fromkeys(answer_type(p) for q in sheet.questions for p in q.variant.template.parts)
    notes = [kind.form_note() for kind in kinds]
    return "".join(f"\n# {_comment(line)}" if line.strip() else "\n#"
                   for note in notes if note for line in note.splitlines() + [""])


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
