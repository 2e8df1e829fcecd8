"""Find every file in a submissions folder and decide whose each answer file is, from where it sits.

Identity comes from the file's place, as learning systems lay bulk downloads out: a folder or file
name holding the student's id ("A21001/answers.yaml", "A21001.yaml", "hw1_A21001_attempt2.csv"), or
a folder named by the student's full name ("Daniel Lim_12345_assignsubmission_file_/..."). What a file
says inside (`student:`, `code:`, `assignment:`) is only checked against that: a file in one student's
place that names another student, carries another sheet's code or answers another assignment is a
problem file, never graded for anyone. Every file found is either graded or listed with why not.
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from exgen.assignment import Student
from exgen.errors import SubmissionError
from exgen.outdir import MARKER

from .answers import Submission, read_submission
from .echo import shown
from .formats import SUFFIXES, file_kind
from .results import FileProblem

#: What a student id may look like (it names the feedback file): as exgen.assignment requires.
SAFE_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")
#: How deep below the submissions folder files are looked for, and how many at most.
MAX_DEPTH = 4
MAX_FILES = 5000

#: Files grading itself writes, never read back as answers.
OUTPUT_FILES = {"gradebook.csv", "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"}

HIDDEN = "a hidden file; skipped"
LINK = "a symbolic link; not followed"
IN_OUTPUT = "inside a folder exgen wrote ({folder}); skipped"
OUR_OUTPUT = "a gradebook written by exgen grade, not an answer file; skipped"
NOT_ANSWERS = "not an answer file ({kind}); answer files are {suffixes}"
TOO_DEEP = "more than {depth} folders down; skipped (put answer files at most {depth} folders down)"
TOO_MANY = "holds more than {limit} files; the rest were not looked at"
WHOSE_FILE = ("cannot tell whose file this is: its name and folders name no student {of} (name it <id>.yaml, "
              "or put it in a folder named by the id)")
SEVERAL = "its name or folders name several students ({students})"
OTHER_STUDENT = "sits in {owner}'s place (its name or folder) but says `student: {given}` inside (copied, or a mix-up?)"
OTHER_CODE = "carries the sheet code {given}, but {owner}'s sheet has {code}{whose} (copied, or a mix-up?)"
OTHER_ASSIGNMENT = "is for the assignment {given!r}, not {expected!r}"
NO_CODE = "The answer file carries no sheet code; it was graded against your own sheet."
NAMED_INSIDE = ("An answer file that names you inside, {files}, was not graded: its name and folder do not carry "
                "your id (name it {id}.yaml, or put it in a folder named {id}). Ask your instructor.")
DUPLICATE = "{student} handed in {count} files; graded the newest, {newest}"
OLDER_FILE = "an older file from {student}; {newest} was graded instead"


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


def answer_files(directory: Path) -> tuple[list[Path], list[FileProblem]]:
    """Files that may be answers, and every other file found with why it is skipped."""
    directory = Path(directory)
    found, skipped, seen = [], [], 0
    for folder, subfolders, names in os.walk(directory):
        here = Path(folder)
        depth = len(here.relative_to(directory).parts)
        if (here / MARKER).is_file() and here != directory:
            skipped.append(FileProblem(here, IN_OUTPUT.format(folder=here.name)))
            subfolders[:] = []
            continue
        for sub in sorted(subfolders):
            if (here / sub).is_symlink():
                skipped.append(FileProblem(here / sub, LINK))
        subfolders[:] = sorted(s for s in subfolders if not (here / s).is_symlink())
        if depth > MAX_DEPTH:
            skipped += [FileProblem(here / n, TOO_DEEP.format(depth=MAX_DEPTH)) for n in sorted(names)]
            subfolders[:] = []
            continue
        for name in sorted(names):
            seen += 1
            if seen > MAX_FILES:
                break
            path = here / name
            reason = _skipped(path, directory)
            if reason:
                skipped.append(FileProblem(path, reason))
            else:
                found.append(path)
        if seen > MAX_FILES:
            break
    if seen > MAX_FILES:
        skipped.append(FileProblem(directory, TOO_MANY.format(limit=MAX_FILES)))
    return found, skipped


def _skipped(path: Path, directory: Path) -> str:
    """Why a file is not read as answers, or "" if it is."""
    relative = path.relative_to(directory)
    if any(part.startswith(".") or part == "__MACOSX" for part in relative.parts):
        return HIDDEN
    if path.is_symlink():
        return LINK
    if path.name.lower() in OUTPUT_FILES:
        return OUR_OUTPUT
    if file_kind(path) is None:
        kind = path.suffix.lower() or "no extension"
        return NOT_ANSWERS.format(kind=shown(kind, 20), suffixes=", ".join(sorted(SUFFIXES)))
    return ""


def read_one(path: Path) -> tuple[Submission | None, str]:
    """An answer file read, or None and why it cannot be."""
    try:
        return read_submission(path), ""
    except SubmissionError as exc:
        return None, (f"line {exc.line}: {exc.detail}" if exc.line else exc.detail)


def collect(directory: Path, roster: list[Student] | None = None, *, assignment: str = "",
            codes: dict[str, str] | None = None, read_all=None) -> tuple[list[Entry], list[FileProblem]]:
    """Every student to grade (roster order, else by id) and every file not graded, with why.
    `codes` are the sheet codes issued (by student id); `assignment` the id the files must answer;
    `read_all(paths)` gives read_one of each path, in order (by default here, one after another)."""
    directory = Path(directory)
    known = {s.id: s for s in roster} if roster is not None else None
    files, problems = answer_files(directory)
    found: dict[str, list[Entry]] = {}
    claimed: dict[str, list[str]] = {}  # files no one's by their place that name a student inside
    for path, (submission, error) in zip(files, (read_all or _read_each)(files)):
        owner, why_not = whose(path.relative_to(directory), known)
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
    return entries, problems


def _read_each(paths: list[Path]):
    return map(read_one, paths)


def whose(relative: Path, known: dict[str, Student] | None) -> tuple[str, str]:
    """The student a file belongs to by where it sits (its folders, nearest first, then its name), or ""
    and why not."""
    names = [*reversed(relative.parts[:-1]), _stem(relative.name)]
    if known is None:  # no roster: the first folder, else the file name, if it is a valid id
        candidates = [relative.parts[0]] if len(relative.parts) > 1 else [_stem(relative.name)]
        owner = next((c for c in candidates if SAFE_ID.fullmatch(c)), "")
        return owner, "" if owner else WHOSE_FILE.format(of="by a valid id")
    for name in names:
        matches = _ids_in(name, known) or _names_in(name, known)
        if len(matches) == 1:
            return matches[0], ""
        if len(matches) > 1:
            return "", SEVERAL.format(students=", ".join(sorted(matches)[:5]))
    return "", WHOSE_FILE.format(of="on the roster")


def _on_roster(given: str, known: dict[str, Student] | None) -> str:
    """The roster id a file's `student:` names, or "" (only to tell that student, never to grade the file)."""
    by_folded = {sid.casefold(): sid for sid in known or {}}
    return by_folded.get(given.strip().casefold(), "")


def _stem(name: str) -> str:
    """The name without its answer-file suffixes ("A21001.yaml.txt" -> "A21001")."""
    path = Path(name)
    while path.suffix.lower() in (*SUFFIXES, ".txt") and path.stem:
        path = Path(path.stem)
    return path.name


def _ids_in(name: str, known: dict[str, Student]) -> list[str]:
    """Roster ids that appear in `name` as a whole token (not inside a longer run of letters and digits)."""
    if name in known:
        return [name]
    by_lower = {sid.lower(): sid for sid in known}
    return sorted({by_lower[m.group(1).lower()] for m in _id_pattern(tuple(by_lower)).finditer(name)})


@lru_cache(maxsize=4)
def _id_pattern(ids: tuple[str, ...]) -> re.Pattern:
    """One pattern for every id of a roster, longest first, each between non-alphanumerics."""
    alternatives = "|".join(re.escape(i) for i in sorted(ids, key=len, reverse=True))
    return re.compile(rf"(?<![A-Za-z0-9])({alternatives})(?![A-Za-z0-9])", re.IGNORECASE)


def _names_in(name: str, known: dict[str, Student]) -> list[str]:
    """Students whose full name starts the folder name, as "Full Name_12345_assignsubmission_file_"."""
    lowered = " ".join(name.lower().replace("_", " _ ").split())
    out = []
    for sid, student in known.items():
        full = " ".join(student.name.lower().split())
        if full and (lowered == full or lowered.startswith(full + " _")):
            out.append(sid)
    return out


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
    """The file graded for one student: the newest readable one not refused (else the newest)."""
    if len(entries) == 1:
        return entries[0]
    ordered = sorted(entries, key=lambda e: (not (e.refused or e.error), _mtime(e.path), e.path.name))
    chosen = ordered[-1]
    sid = chosen.student.id
    others = [e for e in ordered[:-1] if not e.refused and not e.error]
    if others:
        chosen.notes.append(DUPLICATE.format(student=sid, count=len(others) + 1, newest=chosen.path.name))
        problems += [FileProblem(e.path, OLDER_FILE.format(student=sid, newest=chosen.path.name), sid) for e in others]
    return chosen


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0
