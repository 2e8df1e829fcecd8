"""Find the answer files in a directory and decide whose each one is.

Files may lie in the directory itself or one folder down (as learning systems download them:
"s001/answers.yaml"). A file names its student (`student:`); if it does not, its file name or
its folder does ("s001.yaml", "s001/answers.yaml", or with a roster "s001_answers.yaml"). Files that cannot be read, belong to no one on the roster, or are
one of several from one student are reported, never fatal: the batch goes on.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from exgen.assignment import Student
from exgen.errors import SubmissionError

from .answers import Submission, read_submission
from .formats import SUFFIXES
from .results import FileProblem

#: What a student id may look like (it names the feedback file): as exgen.assignment requires.
SAFE_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,63}")

#: Files grading itself writes, never read back as answers.
OUTPUT_FILES = {"gradebook.csv"}

NOT_ON_ROSTER = "student {student!r} is not on the roster; the file was skipped"
WHOSE_FILE = "cannot tell whose file this is: it names no valid student id and neither does its file name"
BAD_ID = "the file names the student {given!r}, which is not a valid id; used {student!r} from the file name"
DUPLICATE = "{student} handed in {count} files; graded the newest, {newest}"
OLDER_FILE = "an older file from {student}; {newest} was graded instead"


@dataclass
class Entry:
    """One student's hand-in: the file graded (None: no submission) and what went wrong reading it."""

    student: Student
    path: Path | None = None
    submission: Submission | None = None
    error: str = ""
    notes: list[str] = field(default_factory=list)


def answer_files(directory: Path) -> list[Path]:
    """Answer files in `directory` and its immediate folders; hidden ones and our own outputs skipped."""
    directory = Path(directory)
    found = []
    for path in sorted(directory.glob("*")) + sorted(directory.glob("*/*")):
        hidden = any(p.startswith(".") for p in path.relative_to(directory).parts)
        if path.suffix.lower() in SUFFIXES and path.name not in OUTPUT_FILES and not hidden and path.is_file():
            found.append(path)
    return found


def collect(directory: Path, roster: list[Student] | None = None) -> tuple[list[Entry], list[FileProblem]]:
    """Every student to grade (roster order, else by id) and every problem file."""
    known = {s.id: s for s in roster} if roster is not None else None
    found: dict[str, list[Entry]] = {}
    problems: list[FileProblem] = []
    for path in answer_files(directory):
        try:
            submission, error = read_submission(path), ""
        except SubmissionError as exc:
            submission, error = None, (f"line {exc.line}: {exc.detail}" if exc.line else exc.detail)
        student_id, note = _whose(path, submission, known, Path(directory))
        if not student_id or (known is not None and student_id not in known):
            unmatched = NOT_ON_ROSTER.format(student=student_id) if student_id else WHOSE_FILE
            problems.append(FileProblem(path, f"{error} ({unmatched})" if error else unmatched))
            continue
        if error:
            problems.append(FileProblem(path, error, student_id))
        student = known[student_id] if known is not None else Student(student_id)
        found.setdefault(student_id, []).append(Entry(student, path, submission, error, [note] if note else []))
    entries = [_newest(files, problems) for files in found.values()]
    if known is not None:
        entries += [Entry(s) for sid, s in known.items() if sid not in found]
        order = {sid: i for i, sid in enumerate(known)}
        entries.sort(key=lambda e: order[e.student.id])
    else:
        entries.sort(key=lambda e: e.student.id)
    return entries, problems


def _whose(path: Path, submission: Submission | None, known: dict | None, directory: Path) -> tuple[str, str]:
    """The student id for a file, and a note if the file's own id had to be passed over."""
    given = submission.student if submission is not None else ""
    if given and SAFE_ID.fullmatch(given):
        return given, ""
    names = [path.parent.name, path.stem] if path.parent != directory else [path.stem]
    from_name = next((sid for sid in (_id_from_name(n, known) for n in names) if sid), "")
    if given and from_name:
        return from_name, BAD_ID.format(given=given[:80], student=from_name)
    return from_name, ""


def _id_from_name(stem: str, known: dict | None) -> str:
    """'s001' -> 's001'; with a roster also 's001_answers' -> 's001' (the longest id the name starts with)."""
    if known is not None:
        if stem in known:
            return stem
        prefixes = [sid for sid in known if stem.startswith(sid) and not stem[len(sid)].isalnum()]
        if prefixes:
            return max(prefixes, key=len)
    return stem if SAFE_ID.fullmatch(stem) else ""


def _newest(entries: list[Entry], problems: list[FileProblem]) -> Entry:
    if len(entries) == 1:
        return entries[0]
    entries = sorted(entries, key=lambda e: (_mtime(e.path), e.path.name))
    newest = entries[-1]
    sid = newest.student.id
    newest.notes.append(DUPLICATE.format(student=sid, count=len(entries), newest=newest.path.name))
    for older in entries[:-1]:
        problems.append(FileProblem(older.path, OLDER_FILE.format(student=sid, newest=newest.path.name), sid))
    return newest


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0
