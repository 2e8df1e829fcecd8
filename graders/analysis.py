"""Item analysis of a graded batch (read from results.json): how the marks spread, and per part how
many got it right (facility), whether the students who did well overall got it right (point-biserial
discrimination), which named mistakes were made, and how often it was left blank.

Discrimination is the correlation between a part's score and the rest of the sheet's score (the part
itself left out, so a part is not correlated with itself): near 0 or below, the part does not separate
stronger from weaker students; a part nobody got right is more often a key problem than a hard part.
"""
from __future__ import annotations

import math
import statistics
from collections import Counter
from dataclasses import dataclass, field

GRADED = "graded"
RIGHT = ("correct", "carried")
#: A part with a discrimination below this is flagged (a common rule of thumb for classroom tests).
LOW_DISCRIMINATION = 0.2
BINS = 10


@dataclass(frozen=True)
class PartStats:
    slot: str
    part: str
    title: str
    n: int
    statuses: Counter
    facility: float | None
    discrimination: float | None
    mistakes: tuple[tuple[str, int], ...] = ()
    #: answers whose marks review changed (a decision or an alias), and the points that added (or took)
    reviewed: int = 0
    review_points: float = 0.0

    @property
    def label(self) -> str:
        return f"{self.slot} ({self.part})"

    @property
    def blank(self) -> int:
        return self.statuses["blank"]

    @property
    def right(self) -> int:
        return sum(self.statuses[s] for s in RIGHT)


@dataclass(frozen=True)
class Analysis:
    title: str
    max_points: float
    students: int
    status_counts: Counter
    percents: tuple[float, ...]
    histogram: tuple[int, ...]
    parts: tuple[PartStats, ...]
    signs: tuple[dict, ...] = ()
    problems: tuple[dict, ...] = ()
    warnings: tuple[str, ...] = ()
    sheet_warnings: tuple[tuple[str, str], ...] = field(default=())
    #: the decisions file graded with (results.json's "review"), None when there was none
    review: dict | None = None

    @property
    def reviewed(self) -> tuple[PartStats, ...]:
        """Parts where review changed some answer's marks."""
        return tuple(p for p in self.parts if p.reviewed)

    @property
    def mean(self) -> float | None:
        return statistics.fmean(self.percents) if self.percents else None

    @property
    def median(self) -> float | None:
        return statistics.median(self.percents) if self.percents else None

    @property
    def nobody_right(self) -> tuple[PartStats, ...]:
        """Parts some answered and none got right (a part everyone left blank is in most_blank)."""
        return tuple(p for p in self.parts if p.statuses["wrong"] and p.right == 0)

    @property
    def most_blank(self) -> tuple[PartStats, ...]:
        blank = [p for p in self.parts if p.blank]
        return tuple(sorted(blank, key=lambda p: (-p.blank, p.slot, p.part))[:5])

    @property
    def weak(self) -> tuple[PartStats, ...]:
        return tuple(p for p in self.parts if p.discrimination is not None and p.discrimination < LOW_DISCRIMINATION)


def analyse(record: dict) -> Analysis:
    graded = [s for s in record["sheets"] if s["status"] == GRADED]
    percents = tuple(100.0 * s["points"] / s["max_points"] if s["max_points"] else 0.0 for s in graded)
    titles = {c["slot"]: c["title"] for c in record["columns"]}
    order = [(c["slot"], p["id"]) for c in record["columns"] for p in c["parts"]]
    by_part: dict[tuple[str, str], list[tuple[dict, dict]]] = {key: [] for key in order}
    for sheet in graded:
        for part in sheet["parts"]:
            by_part.setdefault((part["slot"], part["part"]), []).append((sheet, part))
    parts = tuple(_part_stats(slot, part_id, titles.get(slot, slot), rows) for (slot, part_id), rows in by_part.items())
    return Analysis(
        title=record["assignment"]["title"], max_points=record["max_points"], students=len(record["sheets"]),
        status_counts=Counter(s["status"] for s in record["sheets"]), percents=percents,
        histogram=histogram(percents), parts=parts, signs=tuple(record.get("signs", ())),
        problems=tuple(record.get("problems", ())), warnings=tuple(record.get("warnings", ())),
        review=record.get("review") if isinstance(record.get("review"), dict) else None,
    )


def _part_stats(slot: str, part_id: str, title: str, rows: list[tuple[dict, dict]]) -> PartStats:
    statuses = Counter(part["status"] for _, part in rows)
    scores = [part["points"] / part["max_points"] if part["max_points"] else 0.0 for _, part in rows]
    rest = [sheet["points"] - part["points"] for sheet, part in rows]
    mistakes = Counter(part["mistake"] for _, part in rows if part.get("mistake"))
    changes = [part["points"] - part["review"]["points_before"] for _, part in rows if _changed(part)]
    return PartStats(slot, part_id, title, len(rows), statuses,
                     statistics.fmean(scores) if scores else None, point_biserial(scores, rest),
                     tuple(mistakes.most_common()), len(changes), sum(changes))


def _changed(part: dict) -> bool:
    """Whether review changed this answer's marks (results.json's "review" of a part)."""
    review = part.get("review")
    if not isinstance(review, dict) or not isinstance(review.get("points_before"), (int, float)):
        return False
    return abs(part["points"] - review["points_before"]) > 1e-12


def point_biserial(item: list[float], rest: list[float]) -> float | None:
    """Pearson's correlation of a part's scores (0 to 1; right or wrong gives the point-biserial) with
    the rest of each sheet's score; None when either does not vary."""
    n = len(item)
    if n < 3:
        return None
    mean_x, mean_y = statistics.fmean(item), statistics.fmean(rest)
    sxx = sum((x - mean_x) ** 2 for x in item)
    syy = sum((y - mean_y) ** 2 for y in rest)
    if sxx == 0 or syy == 0:
        return None
    sxy = sum((x - mean_x) * (y - mean_y) for x, y in zip(item, rest))
    return sxy / math.sqrt(sxx * syy)


def histogram(percents: tuple[float, ...], bins: int = BINS) -> tuple[int, ...]:
    """Counts of marks in [0, 10), [10, 20), ... [90, 100] percent."""
    counts = [0] * bins
    for p in percents:
        counts[min(bins - 1, max(0, int(p * bins / 100.0)))] += 1
    return tuple(counts)
