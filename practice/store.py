"""A student's practice progress in one SQLite file: problems served, every check of a part, hints
and worked solutions shown.

Write-ahead log, one transaction per change, and nothing ever deleted or rewritten: an interrupted
write loses at most that write. Every table only grows (rows are added, never changed), so a reader
can follow it by the ids it has not seen yet (practice.progress). A file that is damaged, locked by another writer, read-only or from a
newer exgen is reported in one line and left exactly as it was; it is never replaced.
"""
from __future__ import annotations

import os
import sqlite3
import sys
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from exgen.errors import ExgenError
from graders.echo import shown

DB_ENV = "EXGEN_PRACTICE_DB"
#: An answer as kept (and shown again in its box): one line, capped, with no control or bidi characters.
STORED_ANSWER = 200
SCHEMA_VERSION = 1
BUSY_SECONDS = 5.0  # how long a write waits for another writer before giving up
SCHEMA = """
CREATE TABLE problems (
    id INTEGER PRIMARY KEY,
    template TEXT NOT NULL,
    version TEXT NOT NULL,            -- the template's data digest when it was served
    seed TEXT NOT NULL,               -- decimal: practice seeds are larger than SQLite's integers
    variant TEXT NOT NULL,            -- digest of the printed values: no variant is served twice
    topic TEXT NOT NULL,
    chapter INTEGER NOT NULL,
    scope TEXT NOT NULL,              -- what the student asked to practise
    served REAL NOT NULL,
    UNIQUE (template, variant)
);
CREATE TABLE checks (
    id INTEGER PRIMARY KEY,
    problem INTEGER NOT NULL REFERENCES problems(id),
    part TEXT NOT NULL,
    answer TEXT NOT NULL,
    status TEXT NOT NULL,             -- graders.results: correct, carried, wrong, blank, unreadable
    mistake TEXT,                     -- the named mistake, when one was recognised
    message TEXT NOT NULL,
    seconds REAL NOT NULL,            -- since the problem was served or its previous check
    at REAL NOT NULL
);
CREATE INDEX checks_by_problem ON checks(problem);
CREATE TABLE hints (
    id INTEGER PRIMARY KEY,
    problem INTEGER NOT NULL REFERENCES problems(id),
    part TEXT NOT NULL,
    level INTEGER NOT NULL,           -- 1 for the first hint of the part's ladder
    at REAL NOT NULL,
    UNIQUE (problem, part, level)
);
CREATE TABLE solutions (
    id INTEGER PRIMARY KEY,
    problem INTEGER NOT NULL UNIQUE REFERENCES problems(id),
    at REAL NOT NULL                  -- when the worked solution was first shown
);
"""

DAMAGED = ("{path} is not a readable practice file ({reason}); it was left as it is. Move it aside to start "
           "a new one, or give another file with --db")
LOCKED = "{path} is busy: another exgen is writing to it. Nothing was lost; try again in a moment"
READ_ONLY = "cannot write to {path} ({reason}); nothing was changed. Give a writable file with --db"
FOREIGN = "{path} is an SQLite file of something else (it holds {tables}); it was left as it is. Give another file with --db"
NEWER = "{path} was written by a newer exgen (progress format {found}, this one reads {known}); it was left as it is"
CANNOT_OPEN = "cannot open the practice file {path} ({reason}). Give another file with --db"


class ProgressError(ExgenError):
    """The progress file cannot be used just now; says which file and why, and that it is unchanged."""


def default_path() -> Path:
    """$EXGEN_PRACTICE_DB, else the per-user data folder: ~/.local/share/exgen (or $XDG_DATA_HOME),
    %APPDATA%\\exgen on Windows, ~/Library/Application Support/exgen on macOS."""
    if os.environ.get(DB_ENV):
        return Path(os.environ[DB_ENV]).expanduser()
    if sys.platform == "win32":
        base = Path(os.environ.get("APPDATA") or Path.home() / "AppData" / "Roaming")
    elif sys.platform == "darwin":
        base = Path.home() / "Library" / "Application Support"
    else:
        base = Path(os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share")
    return base / "exgen" / "practice.sqlite3"


@dataclass(frozen=True)
class ProblemRow:
    id: int
    template: str
    seed: int
    variant: str
    topic: str
    chapter: int
    scope: str
    served: float


@dataclass(frozen=True)
class CheckRow:
    problem: int
    part: str
    answer: str
    status: str
    mistake: str | None
    message: str
    seconds: float
    at: float


@dataclass(frozen=True)
class HintRow:
    problem: int
    part: str
    level: int
    at: float


@dataclass(frozen=True)
class SolutionRow:
    problem: int
    at: float


class Store:
    """The progress file. One connection per thread (the web server answers from several)."""

    def __init__(self, path: Path, busy_seconds: float = BUSY_SECONDS):
        self.path, self.busy_seconds = Path(path), busy_seconds
        self._local = threading.local()
        with self._errors():
            if not self.path.parent.is_dir():
                self.path.parent.mkdir(parents=True, exist_ok=True)
            connection = self._connection()
            verdict = connection.execute("PRAGMA quick_check").fetchone()[0]
            if verdict != "ok":
                raise ProgressError(DAMAGED.format(path=self.path, reason=verdict))
            found = connection.execute("PRAGMA user_version").fetchone()[0]
            if found > SCHEMA_VERSION:
                raise ProgressError(NEWER.format(path=self.path, found=found, known=SCHEMA_VERSION))
            if found < SCHEMA_VERSION:
                tables = [r[0] for r in connection.execute("SELECT name FROM sqlite_master WHERE type = 'table'")]
                if tables and found == 0:
                    raise ProgressError(FOREIGN.format(path=self.path, tables=", ".join(sorted(tables)[:5])))
                with self.transaction() as db:
                    if db.execute("PRAGMA user_version").fetchone()[0] == 0:  # another process may have won
                        for statement in filter(str.strip, SCHEMA.split(";")):
                            db.execute(statement)
                        db.execute(f"PRAGMA user_version = {SCHEMA_VERSION}")
            connection.execute("PRAGMA journal_mode = WAL")  # kept in the file; only once it is known to be ours

    # ---- connections, transactions and what their errors mean -------------------------------

    def _connection(self) -> sqlite3.Connection:
        connection = getattr(self._local, "connection", None)
        if connection is None:
            connection = sqlite3.connect(self.path, timeout=self.busy_seconds, isolation_level=None)
            # In WAL mode NORMAL never corrupts the file; a power cut may lose the last moments' answers.
            # FULL would wait for the disk at every answer checked.
            connection.execute("PRAGMA synchronous = NORMAL")
            connection.execute("PRAGMA foreign_keys = ON")
            self._local.connection = connection
        return connection

    @contextmanager
    def _errors(self):
        """sqlite3's errors as one line naming the file; the file itself is never touched."""
        try:
            yield
        except sqlite3.Error as exc:
            raise ProgressError(_meaning(exc, self.path)) from None

    @contextmanager
    def transaction(self):
        """BEGIN IMMEDIATE ... COMMIT: all of a change or none of it."""
        with self._errors():
            db = self._connection()
            db.execute("BEGIN IMMEDIATE")
            try:
                yield db
            except BaseException:
                db.execute("ROLLBACK")
                raise
            db.execute("COMMIT")

    def _read(self, sql: str, args: tuple = ()) -> list[tuple]:
        with self._errors():
            return self._connection().execute(sql, args).fetchall()

    def close(self) -> None:
        connection = getattr(self._local, "connection", None)
        if connection is not None:
            connection.close()
            self._local.connection = None

    # ---- writing ----------------------------------------------------------------------------

    def add_problem(self, template, seed: int, variant: str, scope: str) -> int | None:
        """Record a problem served; None if this variant of the template was served before."""
        with self.transaction() as db:
            cursor = db.execute(
                "INSERT OR IGNORE INTO problems (template, version, seed, variant, topic, chapter, scope, served) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                (template.id, template.digest, str(seed), variant, template.topic or template.id.split(".")[0],
                 template.chapter, scope, time.time()))
            return cursor.lastrowid if cursor.rowcount else None

    def add_check(self, problem: int, part: str, answer: str, status: str, mistake: str | None,
                  message: str) -> CheckRow:
        """Record a checked answer, timed from the problem's previous check (or from when it was served)."""
        now = time.time()
        with self.transaction() as db:
            since = db.execute("SELECT max(at) FROM checks WHERE problem = ?", (problem,)).fetchone()[0] or \
                db.execute("SELECT served FROM problems WHERE id = ?", (problem,)).fetchone()[0]
            row = CheckRow(problem, part, shown(answer, STORED_ANSWER), status, mistake, message,
                           max(0.0, now - since), now)
            db.execute("INSERT INTO checks (problem, part, answer, status, mistake, message, seconds, at) "
                       "VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                       (row.problem, row.part, row.answer, row.status, row.mistake, row.message, row.seconds, row.at))
        return row

    def add_hint(self, problem: int, part: str, level: int) -> None:
        with self.transaction() as db:
            db.execute("INSERT OR IGNORE INTO hints (problem, part, level, at) VALUES (?, ?, ?, ?)",
                       (problem, part, level, time.time()))

    def show_solution(self, problem: int) -> None:
        with self.transaction() as db:
            db.execute("INSERT OR IGNORE INTO solutions (problem, at) VALUES (?, ?)", (problem, time.time()))

    # ---- reading: by problem, or every row after the last id a reader has seen --------------

    def problem(self, problem_id: int) -> ProblemRow | None:
        rows = self._read(f"SELECT {_PROBLEM} FROM problems WHERE id = ?", (problem_id,))
        return _problem(rows[0]) if rows else None

    def variants_served(self, template_id: str) -> set[str]:
        return {r[0] for r in self._read("SELECT variant FROM problems WHERE template = ?", (template_id,))}

    def last_template(self) -> str | None:
        rows = self._read("SELECT template FROM problems ORDER BY id DESC LIMIT 1")
        return rows[0][0] if rows else None

    def checks(self, problem: int) -> list[CheckRow]:
        return [CheckRow(*r) for r in self._read(f"SELECT {_CHECK} FROM checks WHERE problem = ? ORDER BY id",
                                                 (problem,))]

    def hints(self, problem: int) -> list[HintRow]:
        return [HintRow(*r) for r in self._read(f"SELECT {_HINT} FROM hints WHERE problem = ? ORDER BY id",
                                                (problem,))]

    def solution_shown(self, problem: int) -> bool:
        return self.solution_at(problem) is not None

    def solution_at(self, problem: int) -> float | None:
        """When the problem's worked solution was first shown; None if it was not."""
        rows = self._read("SELECT at FROM solutions WHERE problem = ?", (problem,))
        return rows[0][0] if rows else None

    def after(self, last: dict[str, int]) -> dict[str, list]:
        """Rows of every table with ids above `last[table]` (0 for all), as (id, row) pairs, in one read."""
        out = {}
        with self._errors():
            db = self._connection()
            db.execute("BEGIN")  # one snapshot: a check is never seen without its problem
            try:
                for table, (columns, make) in _TABLES.items():
                    rows = db.execute(f"SELECT id, {columns} FROM {table} WHERE id > ? ORDER BY id",
                                      (last.get(table, 0),)).fetchall()
                    out[table] = [(r[0], make(r[1:])) for r in rows]
            finally:
                db.execute("COMMIT")
        return out


_PROBLEM = "id, template, seed, variant, topic, chapter, scope, served"
_CHECK = "problem, part, answer, status, mistake, message, seconds, at"
_HINT = "problem, part, level, at"


def _problem(row: tuple) -> ProblemRow:
    values = list(row)
    values[2] = int(values[2])
    return ProblemRow(*values)


_TABLES = {
    "problems": (_PROBLEM, _problem),
    "checks": (_CHECK, lambda r: CheckRow(*r)),
    "hints": (_HINT, lambda r: HintRow(*r)),
    "solutions": ("problem, at", lambda r: SolutionRow(*r)),
}


def _meaning(exc: sqlite3.Error, path: Path) -> str:
    text = str(exc)
    lowered = text.lower()
    if "locked" in lowered or "busy" in lowered:
        return LOCKED.format(path=path)
    if "not a database" in lowered or "malformed" in lowered or "corrupt" in lowered:
        return DAMAGED.format(path=path, reason=text)
    if "readonly" in lowered or "read-only" in lowered or "disk is full" in lowered or "full" in lowered:
        return READ_ONLY.format(path=path, reason=text)
    if "unable to open" in lowered:
        return CANNOT_OPEN.format(path=path, reason=text)
    return f"the practice file {path}: {text}"
