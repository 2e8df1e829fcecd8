"""results.json: everything a grading run found, per student and part, for `exgen report` to read back
(item analysis and the signs of copying are computed from it, never from the feedback pages)."""
from __future__ import annotations

import json
from pathlib import Path

from exgen.errors import ExgenError
from exgen.runtime.outdir import recover

from .decisions import ANSWER_LENGTH, cleaned
from .echo import shown
from .results import DECISION, BatchResult, Review, ReviewSummary

RESULTS = "results.json"
FORMAT = 1
#: What a student typed, and the names of files they handed in, as kept here: one line, capped, with no
#: control or bidi characters (other programs read this file and show what it says).
GIVEN_LENGTH, PATH_LENGTH = ANSWER_LENGTH, 300  # a review decision quotes what was typed as kept here
MESSAGE_LENGTH = 400


def batch_record(batch: BatchResult, signs: list[dict] | tuple = ()) -> dict:
    """The batch as plain data: the questions and their parts, each student's marks and answers, the
    files not graded, warnings, and the signs of copying found."""
    columns = []
    for column in batch.columns:
        sample = next((q for s in batch.sheets for q in s.questions if q.slot == column.slot), None)
        kinds = {part_id: (kind, choices) for part_id, kind, choices in column.kinds}
        columns.append({"number": column.number, "slot": column.slot, "template": column.template,
                        "title": sample.title if sample else column.template, "max_points": column.max_points,
                        "parts": [{"id": p.part_id, "max_points": p.max_points,
                                   "type": kinds.get(p.part_id, ("", ()))[0],
                                   "choices": list(kinds.get(p.part_id, ("", ()))[1])}
                                  for p in (sample.parts if sample else ())]})
    sheets = []
    for sheet in batch.sheets:
        s = sheet.student
        sheets.append({
            "student": {"id": s.id, "name": s.name, "email": s.email, "section": s.section},
            "status": sheet.status, "points": sheet.points, "max_points": sheet.max_points, "code": sheet.code,
            "code_mismatch": sheet.code_mismatch, "file": _path(sheet.path),
            "parts": [{"slot": q.slot, "part": p.part_id, "status": p.status, "points": p.points,
                       "max_points": p.max_points, "given": cleaned(p.given), "expected": p.expected,
                       "mistake": p.mistake, "message": shown(p.message, MESSAGE_LENGTH), "review": _review(p.review)}
                      for q in sheet.questions for p in q.parts],
        })
    return {"format": FORMAT,
            "assignment": {"id": batch.assignment.id, "title": batch.assignment.title, "course": batch.assignment.course},
            "max_points": batch.max_points, "columns": columns, "sheets": sheets,
            "problems": [{"path": _path(p.path), "reason": shown(p.reason, 1000), "student": p.student}
                         for p in batch.problems],
            "warnings": list(batch.warnings), "limits": list(batch.limits), "signs": list(signs),
            "review": _summary(batch.review)}


def _review(review: Review | None) -> dict | None:
    """What review did to a part: by a decision or an alias, what the grader gave before, who and why."""
    if review is None:
        return None
    data = {"by": review.by, "status_before": review.status_before, "points_before": review.points_before,
            "reviewer": shown(review.reviewer, 200), "reason": shown(review.reason, 1000), "line": review.line}
    if review.by == DECISION:
        data.update(decision=review.decision, comment=shown(review.comment, MESSAGE_LENGTH))
    else:
        data.update(spelling=cleaned(review.spelling), means=cleaned(review.means))
    return data


def _summary(summary: ReviewSummary | None) -> dict | None:
    """The decisions file the batch was graded with, how many it holds, and those not applied."""
    if summary is None:
        return None
    return {"file": _path(summary.path), "decisions": summary.decisions, "aliases": summary.aliases,
            "applied": summary.applied,
            "not_applied": [{"line": n.line, "what": shown(n.what, 200), "why": shown(n.why, 1000)}
                            for n in summary.not_applied]}


def _path(path: Path | None) -> str:
    return shown(str(path), PATH_LENGTH) if path else ""


def write_record(record: dict, path: Path) -> None:
    """Compact: an indented dump takes Python's pure-Python encoder, six times slower (0.8 s for a class of
    600); `python -m json.tool results.json` shows it indented."""
    path.write_text(json.dumps(record, ensure_ascii=False, separators=(",", ":")) + "\n", encoding="utf-8")


def read_record(folder: Path) -> dict:
    """results.json of a folder `exgen grade` wrote; ExgenError says what is wrong."""
    if not Path(folder).exists():  # an interrupted rerun may have left it aside
        recover(Path(folder).parent if Path(folder).name == RESULTS else Path(folder))
    path = Path(folder) / RESULTS if Path(folder).is_dir() else Path(folder)
    try:
        record = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ExgenError(f"{path}: no such file; give the folder `exgen grade` wrote (its --out)") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ExgenError(f"{path}: cannot read the grading results: {exc}") from None
    if not isinstance(record, dict) or record.get("format") != FORMAT or "sheets" not in record:
        raise ExgenError(f"{path}: not grading results written by this version of exgen grade")
    return record
