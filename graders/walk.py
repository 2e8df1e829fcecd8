"""Every entry of a submissions folder, told apart by name and type alone (nothing is opened here): the
answer files to read, and every other entry with why it is not read.

A student's file is found whatever else the folder holds. The walk goes first through the students'
places (a folder or file name that names a student), and no limit applies to an answer file there; the
limits apply to the rest (photos, junk, other folders): each such entry is listed by name up to
MAX_LISTED, then counted per folder. Folders are entered at any depth (a student's folder deep down is
still found), links are never followed, a folder met twice (a loop through a mount) is entered once,
and a pipe, device or socket is listed, never opened. A limit reached is said in `limits`: the caller
tells the user, since something there may have been missed.
"""
from __future__ import annotations

import os
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from exgen.errors import ExgenError
from exgen.runtime.outdir import MARKER
from exgen.runtime.safefile import kind_of

from .echo import shown
from .formats import SUFFIXES, file_kind
from .results import FileProblem

#: Answer files in no student's place are read (to say whose they claim to be) at most this far down.
MAX_DEPTH = 4
#: Entries in no student's place (and files that are no answer files) listed one by one; the rest are counted.
MAX_LISTED = 50_000
#: Names looked at in all, whatever they are: past this the walk stops.
MAX_NAMES = 1_000_000
#: Folders are entered at most this far down.
MAX_FOLDER_DEPTH = 256

#: Files grading itself writes, never read back as answers.
OUTPUT_FILES = {"gradebook.csv", "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"}

HIDDEN = "a hidden file; skipped"
HIDDEN_FOLDER = "a hidden folder; skipped with everything in it"
LINK = "a symbolic link; not followed"
SPECIAL = "{kind}, not a regular file; not opened"
IN_OUTPUT = "inside a folder exgen wrote ({folder}); skipped"
OUR_OUTPUT = "a gradebook written by exgen grade, not an answer file; skipped"
NOT_ANSWERS = "not an answer file ({kind}); answer files are {suffixes}"
TOO_DEEP = ("more than {depth} folders down in no student's place; not read (put answer files at most {depth} "
            "folders down, or in a folder named by the student's id)")
LOOP = "the same folder as {other} (a loop); not entered again"
UNREADABLE_FOLDER = "a folder that cannot be looked into: {reason}"
NOT_LISTED = "{count:,} more entries in no student's place here were not listed one by one"
LIMIT_LISTED = ("more than {limit:,} files and folders in no student's place: {count:,} were counted, not listed "
                "one by one (in {folders})")
LIMIT_NAMES = ("more than {limit:,} names in all: the walk stopped, and {count:,} folder(s) were not looked into "
               "(or only in part)")
NOT_ENTERED = "a folder not looked into: the walk stopped after {limit:,} names"
CUT_SHORT = "a folder looked into only in part: the walk stopped after {limit:,} names"
LIMIT_DEPTH = "folders more than {limit} levels down were not looked into ({folders})"
TOO_DEEP_FOLDER = "a folder more than {limit} levels down; not looked into"
ACCEPT = "--accept-limits"
LIMITS = ("not graded, nothing written: {folder}: {limits}. A student's file past a limit would be missed: "
          "move what was not handed in out of the folder, or add {flag} to grade anyway (report.md then lists "
          "what was not looked at)")

#: claims(parts, is_file): whether the last of the path's parts (a file's name without its suffixes) names a
#: student, which makes the file, or the folder and everything in it, that student's place.
Claims = Callable[[tuple[str, ...], bool], bool]


class LimitsReached(ExgenError):
    """A submissions folder in which a limit was reached, so a student's file may have been missed."""

    def __init__(self, folder: Path, limits: list[str]):
        self.folder, self.limits = folder, limits
        super().__init__(LIMITS.format(folder=folder, limits="; ".join(limits), flag=ACCEPT))


@dataclass
class Walked:
    """The answer files to read (sorted), every other entry with why (sorted), and the limits reached;
    `placed` are the entries skipped that are in a student's place."""

    files: list[Path] = field(default_factory=list)
    skipped: list[FileProblem] = field(default_factory=list)
    limits: list[str] = field(default_factory=list)
    placed: set[Path] = field(default_factory=set)


@dataclass
class _Walk:
    directory: Path
    claims: Claims
    out: Walked = field(default_factory=Walked)
    listed: int = 0
    names: int = 0
    counted: dict[Path, int] = field(default_factory=dict)  # entries not listed, by the folder they are in
    too_deep: list[Path] = field(default_factory=list)
    seen: dict[tuple[int, int], Path] = field(default_factory=dict)
    not_looked_into: int = 0  # folders (wholly or in part) once MAX_NAMES was reached

    def run(self) -> Walked:
        places: deque = deque()  # folders in a student's place, walked first: (folder, parts)
        others: deque = deque([(self.directory, ())])
        self._first_met(self.directory)
        while places or others:
            in_place = bool(places)
            folder, parts = places.popleft() if in_place else others.popleft()
            if self.names >= MAX_NAMES:
                left = [folder] + [f for f, _ in places] + [f for f, _ in others]
                self.out.skipped += [FileProblem(f, NOT_ENTERED.format(limit=MAX_NAMES)) for f in left]
                self.not_looked_into += len(left)
                break
            for entry in self._entries(folder):
                self.names += 1
                child = parts + (entry.name,)
                is_dir = _is_dir(entry)
                mine = in_place or self.claims(child, not is_dir)
                listed = mine or self._listing(folder)
                if is_dir and not _hidden(entry.name):
                    self._folder(entry, child, places if mine else others, listed)
                elif listed:
                    self._entry(entry, child, mine)
        self._finish()
        return self.out

    def _listing(self, folder: Path) -> bool:
        """Whether one more entry in no student's place is listed by name (else it is counted)."""
        self.listed += 1
        if self.listed <= MAX_LISTED:
            return True
        self.counted[folder] = self.counted.get(folder, 0) + 1
        return False

    def _entries(self, folder: Path) -> list:
        """The folder's entries by name, at most as many as are left of MAX_NAMES (a folder of millions is
        not held in memory whole: what is past the limit is said)."""
        budget, entries = MAX_NAMES - self.names, []
        try:
            with os.scandir(folder) as listing:
                for entry in listing:
                    if len(entries) == budget:
                        self.out.skipped.append(FileProblem(folder, CUT_SHORT.format(limit=MAX_NAMES)))
                        self.not_looked_into += 1
                        break
                    entries.append(entry)
        except OSError as exc:
            self.out.skipped.append(FileProblem(folder, UNREADABLE_FOLDER.format(reason=exc.strerror or exc)))
        return sorted(entries, key=lambda e: e.name)

    def _folder(self, entry, parts: tuple[str, ...], queue: deque, listed: bool) -> None:
        """Queue a folder to enter, unless exgen wrote it, it is too deep or it was met before (then it is
        listed, if entries here are still listed by name)."""
        path = Path(entry.path)
        if len(parts) > MAX_FOLDER_DEPTH:
            self.too_deep.append(path)
            reason = TOO_DEEP_FOLDER.format(limit=MAX_FOLDER_DEPTH)
        elif (path / MARKER).is_file():
            reason = IN_OUTPUT.format(folder=shown(entry.name, 60))
        else:
            first = self._first_met(path, entry)
            if first is None:
                queue.append((path, parts))
                return
            reason = LOOP.format(other=shown(str(_relative(first, self.directory)), 200))
        if listed:
            self.out.skipped.append(FileProblem(path, reason))

    def _first_met(self, path: Path, entry=None) -> Path | None:
        """Record a folder by its device and inode: None the first time, else the folder first met there."""
        try:
            info = entry.stat(follow_symlinks=False) if entry is not None else os.stat(path)
        except OSError:
            return None
        key = (info.st_dev, info.st_ino)
        first = self.seen.get(key)
        if first is None:
            self.seen[key] = path
        return first

    def _entry(self, entry, parts: tuple[str, ...], mine: bool) -> None:
        path = Path(entry.path)
        reason = _why_not(entry, parts, mine)
        if reason:
            self.out.skipped.append(FileProblem(path, reason))
            if mine:
                self.out.placed.add(path)
        else:
            self.out.files.append(path)

    def _finish(self) -> None:
        if self.not_looked_into:
            self.out.limits.append(LIMIT_NAMES.format(limit=MAX_NAMES, count=self.not_looked_into))
        for folder, count in self.counted.items():
            self.out.skipped.append(FileProblem(folder, NOT_LISTED.format(count=count)))
        if self.counted:
            folders = ", ".join(shown(str(_relative(f, self.directory)), 60) for f in list(self.counted)[:3])
            more = f" and {len(self.counted) - 3} more" if len(self.counted) > 3 else ""
            self.out.limits.append(LIMIT_LISTED.format(limit=MAX_LISTED, count=sum(self.counted.values()),
                                                       folders=folders + more))
        if self.too_deep:
            folders = ", ".join(shown(str(_relative(f, self.directory)), 60) for f in self.too_deep[:3])
            self.out.limits.append(LIMIT_DEPTH.format(limit=MAX_FOLDER_DEPTH, folders=folders))
        self.out.files.sort(key=lambda p: p.parts)
        self.out.skipped.sort(key=lambda p: p.path.parts)


def walk(directory: Path, claims: Claims) -> Walked:
    """The answer files under `directory` and every other entry with why it is not read (see the module)."""
    return _Walk(Path(directory), claims).run()


def _why_not(entry, parts: tuple[str, ...], mine: bool) -> str:
    """Why an entry that is not a folder to enter is not read as answers, or "" if it is."""
    name = entry.name
    if _hidden(name):
        return HIDDEN_FOLDER if _is_dir(entry) else HIDDEN
    if _is_link(entry):
        return LINK
    if not _is_file(entry):
        try:
            mode = entry.stat(follow_symlinks=False).st_mode
        except OSError:
            mode = 0
        return SPECIAL.format(kind=kind_of(mode))
    if name.lower() in OUTPUT_FILES:
        return OUR_OUTPUT
    if file_kind(name) is None:
        kind = os.path.splitext(name)[1].lower() or "no extension"
        return NOT_ANSWERS.format(kind=shown(kind, 20), suffixes=", ".join(sorted(SUFFIXES)))
    if not mine and len(parts) - 1 > MAX_DEPTH:
        return TOO_DEEP.format(depth=MAX_DEPTH)
    return ""


def _hidden(name: str) -> bool:
    return name.startswith(".") or name == "__MACOSX"


def _is_dir(entry) -> bool:
    try:
        return entry.is_dir(follow_symlinks=False)
    except OSError:
        return False


def _is_file(entry) -> bool:
    try:
        return entry.is_file(follow_symlinks=False)
    except OSError:
        return False


def _is_link(entry) -> bool:
    try:
        return entry.is_symlink()
    except OSError:
        return False


def _relative(path: Path, base: Path) -> Path:
    try:
        return path.relative_to(base)
    except ValueError:
        return path
