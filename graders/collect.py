"""Find every file in a submissions folder and decide whose each answer file is, from where it sits.

Identity comes from the file's place, as learning systems lay bulk downloads out: a folder or file
name holding the student's id ("A21001/answers.yaml", "A21001.yaml", "hw1_A21001_attempt2.csv"), or
a folder named by the student's full name ("Daniel Lim_12345_assignsubmission_file_/..."). What a file
says inside (`student:`, `code:`, `assignment:`) is only checked against that: a file in one student's
place that names another student, carries another sheet's code or answers another assignment is a
problem file, never graded for anyone. Every file found is either graded or listed with why not.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache, partial
from pathlib import Path

from exgen.errors import SubmissionError
from exgen.issue.assignment import Student

from .answers import Submission, read_submission
from .echo import shown
from .formats import SUFFIXES
from .results import FileProblem
from .walk import LimitsReached, walk

#: What a student id may look like (it names the feedback file): as exgen.issue.assignment requires.
SAFE_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")

WHOSE_FILE = ("cannot tell whose file this is: its name and folders name no student {of} (name it <id>.yaml, "
              "or put it in a folder named by the id)")
SEVERAL = "its name or folders name several students ({students})"
OTHER_STUDENT = "sits in {owner}'s place (its name or folder) but says `student: {given}` inside (copied, or a mix-up?)"
OTHER_CODE = "carries the sheet code {given}, but {owner}'s sheet has {code}{whose} (copied, or a mix-up?)"
OTHER_ASSIGNMENT = "is for the assignment {given!r}, not {expected!r}"
NO_CODE = "The answer file carries no sheet code; it was graded against your own sheet."
NAMED_INSIDE = ("An answer file that names you inside, {files}, was not graded: its name and folder do not carry "
                "your id (name it {id}.yaml, or put it in a folder named {id}). Ask your instructor.")
DUPLICATE = "{student} handed in {count} files; graded the newest{holding}, {newest}"
OLDER_FILE = "an older file from {student}; {newest} was graded instead"
EMPTY_FILE = ("holds no answers (only its header, or every answer blank): not a submission beside {student}'s "
              "{newest}, which has answers and was graded instead")


@dataclass
class Entry:
    """One student's hand-in: the file graded (None: no submission), why it could not be read, or why
    it was refused (it names another student, another sheet or another assignment)."""

    student: Student
    path: Path | None = None
    submission: Submission | None = None
    error: str = ""
    refused: str = ""
    notes: list[str] = field(default_factory=list)


def read_one(path: Path) -> tuple[Submission | None, str]:
    """An answer file read, or None and why it cannot be."""
    try:
        return read_submission(path), ""
    except SubmissionError as exc:
        return None, (f"line {exc.line}: {exc.detail}" if exc.line else exc.detail)


def collect(directory: Path, roster: list[Student] | None = None, *, assignment: str = "",
            codes: dict[str, str] | None = None, read_all=None,
            accept_limits: bool = False) -> tuple[list[Entry], list[FileProblem], list[str]]:
    """Every student to grade (roster order, else by id), every file not graded with why, and the limits
    the walk reached (graders.walk): with any, LimitsReached is raised before a file is read, unless
    `accept_limits`. `codes` are the sheet codes issued (by student id); `assignment` the id the files must
    answer; `read_all(paths)` gives read_one of each path, in order (by default here, one after another)."""
    directory = Path(directory)
    known = {s.id: s for s in roster} if roster is not None else None
    index = _Roster(known) if known is not None else None
    walked = walk(directory, partial(_claims, index))
    if walked.limits and not accept_limits:
        raise LimitsReached(directory, walked.limits)
    files = walked.files
    problems = [_owned(p, directory, index) if p.path in walked.placed else p for p in walked.skipped]
    found: dict[str, list[Entry]] = {}
    claimed: dict[str, list[str]] = {}  # files no one's by their place that name a student inside
    for path, (submission, error) in zip(files, (read_all or _read_each)(files)):
        owner, why_not = whose(path.relative_to(directory), index)
        if not owner:  # say what the file holds, to help whoever sorts it out
            inside = (f" (it says `student: {shown(submission.student, 40)}` inside)" if submission and
                      submission.student else f" (and it cannot be read: {error})" if error else "")
            problems.append(FileProblem(path, why_not + inside))
            claim = _on_roster(submission.student, known) if submission else ""
            if claim:
                claimed.setdefault(claim, []).append(shown(path.name, 60))
            continue
        refused = _refusal(owner, submission, assignment, codes) if submission is not None else ""
        if error or refused:
            problems.append(FileProblem(path, error or refused, owner))
        student = known[owner] if known is not None else Student(owner)
        notes = [NO_CODE] if codes and submission is not None and not submission.code and not refused else []
        found.setdefault(owner, []).append(Entry(student, path, submission, error, refused, notes))
    entries = [_chosen(files, problems) for files in found.values()]
    if known is not None:
        entries += [Entry(s, notes=[NAMED_INSIDE.format(files=", ".join(claimed[sid]), id=sid)] if sid in claimed
                          else []) for sid, s in known.items() if sid not in found]
        order = {sid: i for i, sid in enumerate(known)}
        entries.sort(key=lambda e: order[e.student.id])
    else:
        entries.sort(key=lambda e: e.student.id)
    return entries, problems, walked.limits


def _owned(problem: FileProblem, directory: Path, index: _Roster | None) -> FileProblem:
    """A file the walk skipped, with the student whose place it is in, if it is one's."""
    if index is None:
        return problem
    owner = whose(problem.path.relative_to(directory), index)[0]
    return FileProblem(problem.path, problem.reason, owner) if owner else problem


def _read_each(paths: list[Path]):
    return map(read_one, paths)


def _claims(index: _Roster | None, parts: tuple[str, ...], is_file: bool) -> bool:
    """Whether the last of a path's parts names a student (graders.walk.Claims): with a roster, an id or
    full name in it; without, a top-level file or folder named as an id."""
    name = _stem(parts[-1]) if is_file else parts[-1]
    if index is None:
        return len(parts) == 1 and bool(SAFE_ID.fullmatch(name))
    return bool(index.ids_in(name) or index.names_in(name))


def whose(relative: Path, index: _Roster | None) -> tuple[str, str]:
    """The student a file belongs to by where it sits (its folders, nearest first, then its name), or ""
    and why not."""
    names = [*reversed(relative.parts[:-1]), _stem(relative.name)]
    if index is None:  # no roster: the first folder, else the file name, if it is a valid id
        candidates = [relative.parts[0]] if len(relative.parts) > 1 else [_stem(relative.name)]
        owner = next((c for c in candidates if SAFE_ID.fullmatch(c)), "")
        return owner, "" if owner else WHOSE_FILE.format(of="by a valid id")
    for name in names:
        matches = index.ids_in(name) or index.names_in(name)
        if len(matches) == 1:
            return matches[0], ""
        if len(matches) > 1:
            return "", SEVERAL.format(students=", ".join(sorted(matches)[:5]))
    return "", WHOSE_FILE.format(of="on the roster")


def _on_roster(given: str, known: dict[str, Student] | None) -> str:
    """The roster id a file's `student:` names, or "" (only to tell that student, never to grade the file)."""
    by_folded = {sid.casefold(): sid for sid in known or {}}
    return by_folded.get(given.strip().casefold(), "")


_STRIPPED = frozenset((*SUFFIXES, ".txt"))


def _stem(name: str) -> str:
    """The name without its answer-file suffixes ("A21001.yaml.txt" -> "A21001")."""
    while True:  # as Path(name).suffix and .stem, in plain string steps (every name of a folder passes here)
        dot = name.rfind(".")
        if dot <= 0 or dot == len(name) - 1 or name[dot:].lower() not in _STRIPPED:
            return name
        name = name[:dot]


class _Roster:
    """A roster's ids and full names, looked up in file and folder names."""

    def __init__(self, known: dict[str, Student]):
        self.known = known
        self.by_lower = {sid.lower(): sid for sid in known}
        self.pattern = _id_pattern(tuple(self.by_lower))
        self.by_name: dict[str, list[str]] = {}
        for sid, student in known.items():
            full = " ".join(student.name.lower().split())
            if full:
                self.by_name.setdefault(full, []).append(sid)

    def ids_in(self, name: str) -> list[str]:
        """Roster ids that appear in `name` as a whole token (not inside a longer run of letters and digits)."""
        if name in self.known:
            return [name]
        if not self.by_lower:
            return []
        return sorted({self.by_lower[m.group(1).lower()] for m in self.pattern.finditer(name)})

    def names_in(self, name: str) -> list[str]:
        """Students whose full name is the folder name, or starts it as "Full Name_12345_assignsubmission_file_"."""
        if not self.by_name:
            return []
        lowered = " ".join(name.lower().replace("_", " _ ").split())
        found = set(self.by_name.get(lowered, ()))
        cut = lowered.find(" _")
        while cut != -1:
            found.update(self.by_name.get(lowered[:cut], ()))
            cut = lowered.find(" _", cut + 1)
        return sorted(found)


@lru_cache(maxsize=4)
def _id_pattern(ids: tuple[str, ...]) -> re.Pattern:
    """One pattern for every id of a roster, longest first, each between non-alphanumerics."""
    alternatives = "|".join(re.escape(i) for i in sorted(ids, key=len, reverse=True))
    return re.compile(rf"(?<![A-Za-z0-9])({alternatives})(?![A-Za-z0-9])", re.IGNORECASE)


def _refusal(owner: str, submission: Submission, assignment: str, codes: dict[str, str] | None) -> str:
    """Why a readable file in `owner`'s place is not graded, or ""."""
    given = submission.student.strip()
    if given and given.casefold() != owner.casefold():
        return OTHER_STUDENT.format(owner=owner, given=shown(given, 40))
    if assignment and submission.assignment and submission.assignment.strip().casefold() != assignment.casefold():
        return OTHER_ASSIGNMENT.format(given=shown(submission.assignment, 40), expected=assignment)
    issued = (codes or {}).get(owner, "")
    if issued and submission.code and _code(submission.code) != _code(issued):
        whose_code = next((sid for sid, c in (codes or {}).items() if _code(c) == _code(submission.code)), "")
        return OTHER_CODE.format(given=shown(submission.code, 20), owner=owner, code=issued,
                                 whose=f" ({whose_code}'s sheet has {shown(submission.code, 20)})" if whose_code else "")
    return ""


def _code(text: str) -> str:
    """'7f3a 19c2', '7F3A-19C2' -> '7F3A19C2': how a code may be typed."""
    return re.sub(r"[^0-9A-Za-z]", "", text).upper()


def _chosen(entries: list[Entry], problems: list[FileProblem]) -> Entry:
    """The file graded for one student: the newest readable one not refused that holds an answer; a file
    holding none (only `student:`, or the blank form) is no submission beside one that does, whatever its
    date. With no such file, the newest readable one, else the newest."""
    if len(entries) == 1:
        return entries[0]
    ordered = sorted(entries, key=lambda e: (_usable(e), _answered(e), _mtime(e.path), e.path.name))
    chosen = ordered[-1]
    sid, newest = chosen.student.id, chosen.path.name
    others = [e for e in ordered[:-1] if _usable(e)]
    if others:
        holding = " holding answers" if _answered(chosen) and any(not _answered(e) for e in others) else ""
        chosen.notes.append(DUPLICATE.format(student=sid, count=len(others) + 1, newest=newest, holding=holding))
        problems += [FileProblem(e.path, (EMPTY_FILE if _answered(chosen) and not _answered(e) else OLDER_FILE)
                                 .format(student=sid, newest=newest), sid) for e in others]
    return chosen


def _usable(entry: Entry) -> bool:
    return entry.submission is not None and not entry.refused and not entry.error


def _answered(entry: Entry) -> bool:
    """Whether a file holds anything typed as an answer (a blank answer is nothing)."""
    submission = entry.submission
    return submission is not None and (any(text.strip() for parts in submission.answers.values()
                                           for text in parts.values()) or any(submission.problems.values()))


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0
