"""Mastery per topic and per template, followed from the progress file as it grows.

Every table of the file only grows, so the tracker reads the rows it has not seen yet (by id) and
keeps, per problem, what mastery needs: each part's first readable answer, when each of its hints was
shown, and when the worked solution was. Mastery is worked out from these events, never stored, so a
file written by any exgen is read with today's model. Any process may write meanwhile (a terminal and a browser on the
same file): what it wrote is read at the next refresh.
"""
from __future__ import annotations

import threading
from dataclasses import dataclass, field

from graders.results import CARRIED, CORRECT, WRONG

from .mastery import Evidence, Mastery, PartEvents, after, problem_evidence
from .store import Store

READABLE = (CORRECT, CARRIED, WRONG)  # a blank or unreadable answer is not evidence


@dataclass
class _Problem:
    template: str
    topic: str
    chapter: int
    first: dict[str, tuple[bool, float]] = field(default_factory=dict)  # part -> (right, when)
    hinted: dict[str, list[float]] = field(default_factory=dict)       # part -> when each hint was shown
    solution: float | None = None
    checks: int = 0
    seconds: float = 0.0


@dataclass(frozen=True)
class Row:
    """One line of the progress table: a topic or a template."""

    name: str
    chapter: int
    mastery: Mastery
    problems: int     # problems served
    checks: int       # answers checked
    seconds: float    # time spent answering


class Progress:
    """Follows a store; `points(template_id)` gives a template's part points (None if no longer in the bank)."""

    def __init__(self, store: Store, points):
        self.store, self.points = store, points
        self._last: dict[str, int] = {}
        self._problems: dict[int, _Problem] = {}
        self._evidence: dict[int, tuple[Evidence, ...]] = {}   # kept until the problem's rows change
        self._changes: dict[int, int] = {}                     # problem -> how often its rows changed
        self._folds: dict[tuple[str, str], list[tuple[int, int, Mastery]]] = {}  # group -> (problem, change, after)
        self._tables: dict[str, dict[str, Row]] = {}     # kept until any row is added
        self._lock = threading.Lock()

    def refresh(self) -> None:
        with self._lock:
            new = self.store.after(self._last)
            for table, rows in new.items():
                if rows:
                    self._last[table] = rows[-1][0]
                    self._tables.clear()
                    for _, row in rows:
                        changed = getattr(row, "problem", None) or row.id
                        self._evidence.pop(changed, None)
                        self._changes[changed] = self._changes.get(changed, 0) + 1
            for problem_id, row in new["problems"]:
                self._problems[problem_id] = _Problem(row.template, row.topic, row.chapter)
            for _, check in new["checks"]:
                record = self._problems.get(check.problem)
                if record is None:
                    continue
                record.checks += 1
                record.seconds += check.seconds
                if check.status in READABLE and check.part not in record.first:
                    record.first[check.part] = (check.status in (CORRECT, CARRIED), check.at)
            for _, hint in new["hints"]:
                record = self._problems.get(hint.problem)
                if record is not None:
                    record.hinted.setdefault(hint.part, []).append(hint.at)
            for _, shown in new["solutions"]:
                record = self._problems.get(shown.problem)
                if record is not None and record.solution is None:
                    record.solution = shown.at

    def evidence(self, record: _Problem) -> tuple[Evidence, ...]:
        """A problem's evidence (practice.mastery), each part weighted by its share of the marks."""
        points = self.points(record.template) or {p: 1.0 for p in {*record.first, *record.hinted}}
        total = sum(points.values()) or 1.0
        parts = []
        for part_id, worth in points.items():
            first = record.first.get(part_id)
            parts.append(PartEvents(worth / total, (first[1], first[0]) if first else None,
                                    tuple(record.hinted.get(part_id, ()))))
        return problem_evidence(parts, record.solution)

    def table(self, by: str) -> dict[str, Row]:
        """Rows by topic (`by="topic"`) or by template id (`by="template"`), after a refresh."""
        self.refresh()
        with self._lock:
            if by in self._tables:
                return self._tables[by]
            grouped: dict[str, list[int]] = {}
            for problem_id in sorted(self._problems):
                record = self._problems[problem_id]
                grouped.setdefault(record.topic if by == "topic" else record.template, []).append(problem_id)
            rows = {}
            for name, ids in grouped.items():
                records = [self._problems[i] for i in ids]
                rows[name] = Row(name, records[0].chapter, self._fold((by, name), ids), len(records),
                                 sum(r.checks for r in records), sum(r.seconds for r in records))
            self._tables[by] = rows
            return rows

    def _fold(self, group: tuple[str, str], ids: list[int]) -> Mastery:
        """The group's mastery, its problems' evidence folded in order; the part of the fold before the first
        problem whose rows changed is kept (new rows are nearly always the latest problem's)."""
        kept = self._folds.get(group, [])
        same = 0
        while same < min(len(kept), len(ids)) and kept[same][:2] == (ids[same], self._changes.get(ids[same], 0)):
            same += 1
        fold = kept[:same]
        estimate = fold[-1][2] if fold else Mastery()
        for problem_id in ids[same:]:
            estimate = after(estimate, self._of(problem_id))
            fold.append((problem_id, self._changes.get(problem_id, 0), estimate))
        self._folds[group] = fold
        return estimate

    def _of(self, problem_id: int) -> tuple[Evidence, ...]:
        if problem_id not in self._evidence:
            self._evidence[problem_id] = self.evidence(self._problems[problem_id])
        return self._evidence[problem_id]
