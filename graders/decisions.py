"""Review decisions: what a lecturer settled by hand that the grader could not, kept in a plain YAML file
beside the graded output and applied by `exgen grade` on every run, so a reviewed mark is as reproducible
as an automatic one.

Two kinds. A *decision* is one student's answer to one part, accepted (full marks, or the points given) or
rejected (0), and holds for the answer text it was made on only: the text as results.json and the review
page show it (`cleaned`), so a student who resubmits something else is graded afresh and the decision is
reported as no longer matching. An *alias* is a spelling accepted for everyone on one part ("raises" for
"raises the bow"): the spelling is read as what it means before marking, and then graded as usual against
each student's own key.

The file is read with exgen's capped YAML reader (exgen.runtime.yamlfile, with caps sized for a large
class), checked field by field with file:line in every message, and written back in a stable order
(`dump`): questions, parts, students, spellings sorted, keys in one order, so a diff shows what changed.
The grading side (graders.review) matches each against a graded part (`Decision.matches`).
"""
from __future__ import annotations

import math
import os
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path

import yaml

from exgen.echo import shown
from exgen.runtime.yamlfile import YamlFileError, place, read_yaml

#: Where the decisions of `exgen grade --out OUT` are kept by default: OUT.decisions.yaml, beside the
#: folder (which a run replaces whole), never inside it, and never among the submissions.
SUFFIX = ".decisions.yaml"
ACCEPT, REJECT = "accept", "reject"
VERDICTS = (ACCEPT, REJECT)
#: What a student typed, as results.json keeps it and a decision quotes it (graders.record uses the same).
ANSWER_LENGTH = 200
#: A comment reaches the student's feedback page, a reason the report: each a sentence or two.
COMMENT_LENGTH, TEXT_LENGTH = 400, 1000
#: A class of 1,000 with every part of ten reviewed is 10,000 decisions of about 300 bytes.
MAX_BYTES = 16 * 1024 * 1024
MAX_ENTRIES = 400_000
WHAT = "a review decisions file"

HEADER = "# Review decisions for {assignment}: exgen grade applies them on every run.\n"
DECISION_KEYS = ("student", "question", "part", "template", "answer", "decision", "points", "comment", "reviewer",
                 "reason")
ALIAS_KEYS = ("question", "part", "template", "spelling", "means", "reviewer", "reason")
TOP_KEYS = ("assignment", "decisions", "aliases")


class DecisionsError(YamlFileError):
    """A decisions file that cannot be used as it is; names the file and line, and what to do."""


@dataclass(frozen=True)
class Decision:
    """One student's answer to one part, settled by hand. `points` None: the part's full marks (accept)."""

    student: str
    question: int
    part: str
    answer: str
    decision: str
    reviewer: str
    reason: str
    points: float | None = None
    comment: str = ""
    template: str = ""  # when given, the decision holds only while the question is this template
    line: int | None = field(default=None, compare=False)

    @property
    def key(self) -> tuple[str, int, str]:
        return (self.student, self.question, self.part)

    def matches(self, template: str, given: str) -> bool:
        """Whether the decision holds for this answer (the part already found by student, question and part):
        the same template, if it names one, and the same text as the student's, cleaned."""
        return (not self.template or self.template == template) and cleaned(given) == self.answer

    def points_for(self, max_points: float) -> float:
        """The points it gives a part of `max_points`."""
        if self.decision == REJECT:
            return 0.0
        return max_points if self.points is None else self.points


@dataclass(frozen=True)
class Alias:
    """A spelling of one part read as `means` for everyone (then graded against each student's key)."""

    question: int
    part: str
    template: str
    spelling: str
    means: str
    reviewer: str
    reason: str
    line: int | None = field(default=None, compare=False)

    @property
    def key(self) -> tuple[int, str, str]:
        return (self.question, self.part, spelling_key(self.spelling))

    def matches(self, given: str) -> bool:
        return spelling_key(given) == spelling_key(self.spelling)


@dataclass(frozen=True)
class Decisions:
    """Every decision and alias of one assignment, in the file's stable order."""

    assignment: str
    decisions: tuple[Decision, ...] = ()
    aliases: tuple[Alias, ...] = ()
    path: Path | None = None

    def decision_for(self, student: str, question: int, part: str) -> Decision | None:
        return self._decisions.get((student, question, part))

    def aliases_for(self, question: int, part: str) -> tuple[Alias, ...]:
        return tuple(a for a in self.aliases if a.question == question and a.part == part)

    def with_decision(self, decision: Decision) -> Decisions:
        """These decisions with `decision` added, replacing any for the same student's same part."""
        kept = [d for d in self.decisions if d.key != decision.key]
        return replace(self, decisions=_sorted_decisions(kept + [decision]))

    def with_alias(self, alias: Alias) -> Decisions:
        """These decisions with `alias` added, replacing any for the same spelling of the same part."""
        kept = [a for a in self.aliases if a.key != alias.key]
        return replace(self, aliases=_sorted_aliases(kept + [alias]))

    def without_decision(self, student: str, question: int, part: str) -> Decisions:
        """These decisions without the one on this student's part (the same if there is none)."""
        return replace(self, decisions=tuple(d for d in self.decisions if d.key != (student, question, part)))

    def without_alias(self, question: int, part: str, spelling: str) -> Decisions:
        """These decisions without the alias for this spelling of the part (the same if there is none)."""
        key = (question, part, spelling_key(spelling))
        return replace(self, aliases=tuple(a for a in self.aliases if a.key != key))

    @property
    def _decisions(self) -> dict[tuple[str, int, str], Decision]:
        table = self.__dict__.get("_table")
        if table is None:
            table = {d.key: d for d in self.decisions}
            object.__setattr__(self, "_table", table)
        return table

    def __bool__(self) -> bool:
        return bool(self.decisions or self.aliases)


def default_path(out: Path) -> Path:
    """OUT.decisions.yaml for the graded folder OUT (graded/tutorial1 -> graded/tutorial1.decisions.yaml)."""
    out = Path(out)
    return out.with_name(out.name + SUFFIX)


def cleaned(text: str | None) -> str:
    """A student's text as results.json, the review page and a decision quote it: one line without control
    or bidi characters, at most ANSWER_LENGTH characters."""
    return shown(text or "", ANSWER_LENGTH)


def spelling_key(text: str | None) -> str:
    """What makes two spellings the same: case and spacing do not matter ("Raises", " raises ")."""
    return " ".join(cleaned(text).casefold().split())


# ---- reading ------------------------------------------------------------------------------------

def load_decisions(path: Path, assignment: str | None = None, *, missing_ok: bool = True) -> Decisions:
    """The decisions in `path`; none if the file does not exist and `missing_ok`. DecisionsError (one line,
    file:line) for anything the file holds that cannot be used, or decisions for another `assignment`."""
    path = Path(path)
    if not path.exists() and not path.is_symlink():
        if missing_ok:
            return Decisions(assignment or "", path=path)
        raise DecisionsError(path, "no such file")
    try:
        root, data = read_yaml(path, WHAT, max_bytes=MAX_BYTES, max_entries=MAX_ENTRIES)
    except YamlFileError as exc:
        raise DecisionsError(path, exc.detail, exc.line, exc.column) from None
    reader = _Reader(path, root)
    if data is None:
        return Decisions(assignment or "", path=path)
    if not isinstance(data, dict):
        reader.fail((), f"holds {_kind(data)}; {WHAT} is a mapping with `assignment:`, `decisions:` and `aliases:`")
    for key in data:
        if key not in TOP_KEYS:
            reader.fail((key,), f"`{shown(key, 40)}:` is not a key of {WHAT}; the keys are {', '.join(TOP_KEYS)}")
    found = reader.text(data, (), "assignment", required=True)
    if assignment is not None and found != assignment:
        reader.fail(("assignment",), f"these are decisions for the assignment {found!r}, not {assignment!r}: give "
                                     "the decisions file of this assignment (--decisions FILE)")
    decisions = [reader.decision(item, ("decisions", i)) for i, item in enumerate(reader.items(data, "decisions"))]
    aliases = [reader.alias(item, ("aliases", i)) for i, item in enumerate(reader.items(data, "aliases"))]
    reader.no_twice(decisions, "decisions", "a decision for {0} on question {1} ({2})")
    reader.no_twice(aliases, "aliases", "an alias for question {0} ({1}) spelled {2!r}")
    return Decisions(found, _sorted_decisions(decisions), _sorted_aliases(aliases), path)


class _Reader:
    """Checks each field of the file, naming its line."""

    def __init__(self, path: Path, root):
        self.path, self.root = path, root

    def fail(self, keys: tuple, message: str):
        if self.root is None:
            line, column = None, None
        elif keys:
            line, column = place(self.root, keys)
        else:
            line, column = self.root.start_mark.line + 1, self.root.start_mark.column + 1
        raise DecisionsError(self.path, message, line, column)

    def items(self, data: dict, key: str) -> list:
        value = data.get(key)
        if value is None:
            return []
        if not isinstance(value, list):
            self.fail((key,), f"`{key}:` holds {_kind(value)}; it must be a list (each item starting with `- `)")
        return value

    def mapping(self, item, keys: tuple, allowed: tuple[str, ...], what: str) -> dict:
        if not isinstance(item, dict):
            self.fail(keys, f"{what} holds {_kind(item)}; it must be `key: value` lines ({', '.join(allowed)})")
        for key in item:
            if key not in allowed:
                self.fail(keys + (key,), f"`{shown(key, 40)}:` is not a field of {what}; the fields are "
                                         f"{', '.join(allowed)}")
        return item

    def text(self, item: dict, keys: tuple, name: str, *, required: bool = False, limit: int = TEXT_LENGTH,
             empty: bool = False) -> str:
        value = item.get(name)
        if value is None:
            if required:
                self.fail(keys, f"`{name}:` is missing")
            return ""
        if not isinstance(value, str):
            self.fail(keys + (name,), f"`{name}:` is {_kind(value)}; write it as text in quotes "
                                      f"({name}: \"{shown(value, 30)}\")")
        if len(value) > limit:
            self.fail(keys + (name,), f"`{name}:` is {len(value):,} characters long; at most {limit:,}")
        if required and not empty and not value.strip():
            self.fail(keys + (name,), f"`{name}:` is empty")
        return value

    def question(self, item: dict, keys: tuple) -> int:
        value = item.get("question")
        if value is None:
            self.fail(keys, "`question:` is missing (the question's number, as on the sheet)")
        if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 1000:
            self.fail(keys + ("question",), f"`question:` is {shown(repr(value), 30)}; it is the question's number "
                                            "as on the sheet (1, 2, ...)")
        return value

    def part(self, item: dict, keys: tuple) -> str:
        value = item.get("part")
        if isinstance(value, int) and not isinstance(value, bool):
            self.fail(keys + ("part",), f"`part:` is the number {value}; a part is named by its letter (part: b)")
        return self.text(item, keys, "part", required=True, limit=40).strip().strip("().").strip()

    def decision(self, item, keys: tuple) -> Decision:
        item = self.mapping(item, keys, DECISION_KEYS, "a decision")
        verdict = self.text(item, keys, "decision", required=True, limit=20).strip().lower()
        if verdict not in VERDICTS:
            self.fail(keys + ("decision",), f"`decision:` is {shown(verdict, 30)!r}; it is accept or reject")
        points = item.get("points")
        if points is not None:
            if verdict == REJECT:
                self.fail(keys + ("points",), "a rejected answer scores 0: remove `points:`")
            if isinstance(points, bool) or not isinstance(points, (int, float)) or not math.isfinite(points) \
                    or points < 0:
                self.fail(keys + ("points",), f"`points:` is {shown(repr(points), 30)}; it is a number of points, "
                                              "0 or more (leave it out for the part's full marks)")
            points = float(points)
        answer = item.get("answer")
        if answer is None:
            self.fail(keys, "`answer:` is missing: the student's text the decision was made on (\"\" for a blank)")
        answer = self.text(item, keys, "answer", required=True, limit=ANSWER_LENGTH, empty=True)
        if answer != cleaned(answer):
            self.fail(keys + ("answer",), "`answer:` is not the text as results.json shows it (one line, without "
                                          "control characters, spaces not doubled): copy it from there")
        return Decision(
            student=self.text(item, keys, "student", required=True, limit=200).strip(),
            question=self.question(item, keys), part=self.part(item, keys), answer=answer, decision=verdict,
            reviewer=self.text(item, keys, "reviewer", required=True, limit=200),
            reason=self.text(item, keys, "reason", required=True),
            points=points, comment=self.text(item, keys, "comment", limit=COMMENT_LENGTH),
            template=self.text(item, keys, "template", limit=200).strip(), line=place(self.root, keys)[0])

    def alias(self, item, keys: tuple) -> Alias:
        item = self.mapping(item, keys, ALIAS_KEYS, "an alias")
        spelling = self.text(item, keys, "spelling", required=True, limit=ANSWER_LENGTH)
        means = self.text(item, keys, "means", required=True, limit=ANSWER_LENGTH)
        if spelling_key(spelling) == spelling_key(means):
            self.fail(keys + ("means",), "`means:` is the spelling itself: an alias reads a spelling as another")
        return Alias(question=self.question(item, keys), part=self.part(item, keys),
                     template=self.text(item, keys, "template", required=True, limit=200).strip(),
                     spelling=spelling, means=means,
                     reviewer=self.text(item, keys, "reviewer", required=True, limit=200),
                     reason=self.text(item, keys, "reason", required=True), line=place(self.root, keys)[0])

    def no_twice(self, items: list, section: str, what: str) -> None:
        first: dict[tuple, int] = {}
        for i, item in enumerate(items):
            if item.key in first:
                earlier = items[first[item.key]].line
                self.fail((section, i), f"{what.format(*item.key)} is here twice (first on line {earlier}): "
                                        "keep one")
            first[item.key] = i


def _kind(value) -> str:
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, bool):
        return "true/false"
    if isinstance(value, (int, float)):
        return "a number"
    return "text" if isinstance(value, str) else f"a {type(value).__name__}"


# ---- writing ------------------------------------------------------------------------------------

def _sorted_decisions(items) -> tuple[Decision, ...]:
    return tuple(sorted(items, key=lambda d: (d.question, d.part, d.student)))


def _sorted_aliases(items) -> tuple[Alias, ...]:
    return tuple(sorted(items, key=lambda a: (a.question, a.part, spelling_key(a.spelling), a.spelling)))


def as_data(decisions: Decisions) -> dict:
    """The file's content as plain data, in its stable order; empty fields left out."""
    def decision(d: Decision) -> dict:
        data = {"student": d.student, "question": d.question, "part": d.part}
        if d.template:
            data["template"] = d.template
        data.update(answer=d.answer, decision=d.decision)
        if d.points is not None:
            data["points"] = int(d.points) if float(d.points).is_integer() else d.points
        if d.comment:
            data["comment"] = d.comment
        data.update(reviewer=d.reviewer, reason=d.reason)
        return data

    def alias(a: Alias) -> dict:
        return {"question": a.question, "part": a.part, "template": a.template, "spelling": a.spelling,
                "means": a.means, "reviewer": a.reviewer, "reason": a.reason}

    return {"assignment": decisions.assignment,
            "decisions": [decision(d) for d in _sorted_decisions(decisions.decisions)],
            "aliases": [alias(a) for a in _sorted_aliases(decisions.aliases)]}


class _Dumper(yaml.SafeDumper):
    """Block YAML with list items indented under their key, as people write them."""

    def increase_indent(self, flow=False, indentless=False):
        return super().increase_indent(flow, False)


def dump(decisions: Decisions) -> str:
    """The file's text: a header line, then plain block YAML, one key a line, in the stable order."""
    body = yaml.dump(as_data(decisions), Dumper=_Dumper, sort_keys=False, allow_unicode=True,
                     default_flow_style=False, width=10_000, indent=2)
    return HEADER.format(assignment=shown(decisions.assignment, 200)) + body


def save_decisions(decisions: Decisions, path: Path | None = None) -> Path:
    """Write the file whole or not at all (a temporary file beside it, then renamed over it), so an
    interrupted write never leaves half a file of decisions."""
    path = Path(path or decisions.path)
    text = dump(decisions)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".writing", dir=path.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="\n") as out:
            out.write(text)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path
