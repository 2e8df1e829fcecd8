"""Write a graded batch out: the gradebook CSV, one feedback page per student, and the instructor's report.

Everything is gathered before anything is written, into a folder swapped in when complete; text a
student typed is shortened and escaped wherever it lands (a Markdown page may end up as HTML in a learning system).
"""
from __future__ import annotations

import csv
import re
from collections import Counter
from pathlib import Path

from exgen.render.unicode_math import text_to_plain
from exgen.runtime.outdir import check_target, replacing

from .echo import look_alike, shown, shown_code
from .results import (BLANK, CARRIED, CORRECT, GRADED, UNREADABLE, WRONG, BatchResult, PartResult,
                      SheetResult)

MARK = {True: "\u2713", False: "\u2717"}
SHOWN_ANSWER_LENGTH = 60
#: Any message or note on a page: long enough for every message exgen writes, short for echoed text.
MESSAGE_LENGTH = 400
#: Longest unbroken run of characters kept in a message (a quoted answer of 200,000 digits is one run).
QUOTED_WORD = 48
#: Notes shown on one feedback page; the rest are counted.
NOTES_SHOWN = 10
COMMON_MISTAKES = 3
_ENTITY = re.compile(r"&(?=#?\w+;)")  # "&lt;" typed as text would show as "<" in HTML
_SPREADSHEET_FORMULA = ("=", "+", "-", "@", "\t", "\r")
KIND = "grade"  # the marker a folder of grading results carries (exgen.runtime.outdir)
CANVAS_GRADEBOOK, MOODLE_GRADES, PARTS = "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"


def write_results(batch: BatchResult, out_dir: Path, signs=(), canvas_id: str = "") -> dict[str, Path]:
    """gradebook.csv, the Canvas and Moodle gradebooks, parts.csv, feedback/<student>.md, report.md,
    results.json and the item analysis (HTML and Markdown) under `out_dir`; returns their paths. `signs`
    are the signs of copying found (graders.copying), reported and never marked. The folder is replaced
    whole when everything is written (exgen.runtime.outdir): never a new gradebook beside old feedback."""
    from .gradebooks import write_canvas_gradebook, write_moodle_grades, write_parts
    from .item_report import HTML, MARKDOWN, report_pages
    from .record import RESULTS, batch_record, write_record

    out_dir = Path(out_dir)
    check_target(out_dir, KIND)
    feedback = {s.student.id: _page(batch, s) for s in batch.sheets}
    report = report_page(batch)
    record = batch_record(batch, signs)
    pages = report_pages(record)
    with replacing(out_dir, KIND) as folder:
        (folder / "feedback").mkdir()
        write_gradebook(batch, folder / "gradebook.csv")
        write_canvas_gradebook(batch, folder / CANVAS_GRADEBOOK, canvas_id)
        write_moodle_grades(batch, folder / MOODLE_GRADES)
        write_parts(batch, folder / PARTS)
        for student_id, page in feedback.items():
            (folder / "feedback" / f"{student_id}.md").write_text(page, encoding="utf-8")
        (folder / "report.md").write_text(report, encoding="utf-8")
        write_record(record, folder / RESULTS)
        for name, text in pages.items():
            (folder / name).write_text(text, encoding="utf-8")
    return {"gradebook": out_dir / "gradebook.csv", "canvas gradebook": out_dir / CANVAS_GRADEBOOK,
            "moodle grades": out_dir / MOODLE_GRADES, "parts": out_dir / PARTS, "report": out_dir / "report.md",
            "item analysis": out_dir / HTML, "item analysis (Markdown)": out_dir / MARKDOWN,
            "results": out_dir / RESULTS, "feedback": out_dir / "feedback"}


# ---- gradebook ----------------------------------------------------------------------------------

def write_gradebook(batch: BatchResult, path: Path) -> None:
    header = ["student", "name", "email"] + [f"{c.slot} (/{_num(c.max_points)})" for c in batch.columns]
    header += ["total", "max", "percent", "status"]
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        for sheet in batch.sheets:
            graded = sheet.status == GRADED  # nothing graded is blank, never 0
            marks = []
            for column in batch.columns:
                question = sheet.question(column.slot)
                marks.append(_num(question.points if question else 0.0) if graded else "")
            writer.writerow([_cell(sheet.student.id), _cell(sheet.student.name), _cell(sheet.student.email),
                             *marks, _num(sheet.points) if graded else "", _num(sheet.max_points),
                             f"{sheet.percent:.1f}" if graded else "", sheet.status])


def _cell(text: str) -> str:
    """Text a spreadsheet will not run as a formula."""
    return "'" + text if text.startswith(_SPREADSHEET_FORMULA) else text


def _num(value: float) -> str:
    return f"{value:.2f}".rstrip("0").rstrip(".") if value else "0"


# ---- feedback -----------------------------------------------------------------------------------

def _page(batch: BatchResult, sheet: SheetResult) -> str:
    """The sheet's feedback page: as written where it was graded, if that was this very sheet."""
    made = batch.pages.get(sheet.student.id)
    return made[1] if made is not None and made[0] is sheet else feedback_page(batch, sheet)


def feedback_page(batch: BatchResult, sheet: SheetResult) -> str:
    return student_page(batch.assignment.title, sheet)


def student_page(title: str, sheet: SheetResult) -> str:
    """One student's feedback page, for an assignment of this title."""
    who = sheet.student.id + (f" ({_escape(sheet.student.name)})" if sheet.student.name else "")
    lines = [f"# Feedback: {_escape(title)}", "",
             f"Student: {who}" + (f" · Sheet code: {sheet.code}" if sheet.code else ""),
             f"Total: **{_num(sheet.points)} / {_num(sheet.max_points)}** ({sheet.percent:.1f} %)"
             + ("" if sheet.status == GRADED else f" · {sheet.status}"), ""]
    for warning in sheet.warnings[:NOTES_SHOWN]:
        lines += [f"> **Note:** {_escape(warning)}", ""]
    if len(sheet.warnings) > NOTES_SHOWN:
        lines += [f"> **Note:** ... and {len(sheet.warnings) - NOTES_SHOWN} more notes like these.", ""]
    from_pdf = sheet.path is not None and sheet.path.suffix.lower() == ".pdf"  # quote each box as it was read
    for question in sheet.questions:
        lines += [f"## Q{question.number}. {_escape(question.title)} ({_num(question.points)} / "
                  f"{_num(question.max_points)})", ""]
        for part in question.parts:
            lines += _part_block(part, f"{question.slot}.{part.part_id}" if from_pdf else "")
    return "\n".join(lines).rstrip() + "\n"


def _part_block(part: PartResult, box: str = "") -> list[str]:
    """A part's mark, what was given (`box`: the PDF field it was read from) and what was expected."""
    if box:
        given = (f"Read from your PDF's box {_shown(box, 40)}: `{_shown(part.given)}`" if part.given.strip()
                 else f"Your PDF's box {_shown(box, 40)} was empty")
    else:
        given = "Your answer: " + (f"`{_shown(part.given)}`" if part.given.strip() else "(blank)")
    return [
        f"**({part.part_id}) {MARK[part.correct]} {_num(part.points)} / {_num(part.max_points)}**: {_escape(part.ask, 2000)}  ",
        f"{given} · expected: {part.expected}  ",
        _escape(_sentence(part.message)), "",
    ]


def _shown(text: str, limit: int = SHOWN_ANSWER_LENGTH) -> str:
    """A student's text, safe inside a Markdown code span and as HTML: one line, short, no backticks or tags."""
    return shown_code(text, limit)


def _where(path: Path, base: Path | None) -> str:
    try:
        return str(path.relative_to(base)) if base else str(path)
    except ValueError:
        return str(path)


def _escape(text: str, limit: int = MESSAGE_LENGTH) -> str:
    """Any text on a page (messages quote what students typed): its math in plain Unicode, one line,
    capped, and harmless as Markdown and as HTML without writing entities a reader of the file would
    see (the page shows ‹stream end›, not &lt;stream end&gt;)."""
    text = look_alike(shown(text_to_plain(str(text)), limit, word=QUOTED_WORD))
    return _ENTITY.sub("\uff06", text) if "&" in text else text


def _sentence(message: str) -> str:
    message = message.strip()
    return (message[:1].upper() + message[1:] + ("" if message.endswith((".", "!", "?")) else ".")) if message else ""


# ---- the instructor's report --------------------------------------------------------------------

def report_page(batch: BatchResult) -> str:
    counts = batch.by_status()
    lines = [f"# Grading report: {_escape(batch.assignment.title)}", ""]
    for warning in batch.warnings:  # graded with --force: impossible to miss
        lines += [f"> **WARNING:** {_escape(warning, 1000)}", ""]
    for limit in batch.limits:  # graded with --accept-limits: a file past a limit may be missed
        lines += [f"> **WARNING:** graded with --accept-limits although a limit was reached in the submissions "
                  f"folder: {_escape(limit, 1000)}; a student's file there may have been missed", ""]
    lines += [f"Sheets: {len(batch.sheets)} ({', '.join(f'{n} {s}' for s, n in sorted(counts.items())) or 'none'})"]
    summary = batch.percent_summary()
    if summary:
        lines.append(f"Marks of graded sheets: mean {summary[0]:.1f} %, median {summary[1]:.1f} % "
                     f"(out of {_num(batch.max_points)} points)")
    lines += ["", "## Parts", "",
              "| Question | Part | Correct | of which carried | Wrong | Blank | Unreadable | Most common mistakes |",
              "|---|---|---:|---:|---:|---:|---:|---|"]
    lines += _item_rows(batch)
    lines += _reviewed(batch)
    lines += _not_carried(batch)
    left = [s for s in batch.sheets if s.status != GRADED]
    if left:
        lines += ["", "## Not in the Canvas and Moodle gradebooks", "",
                  "Nothing of theirs was graded, so they have no row there, and importing keeps the grade they have:", ""]
        lines += [f"- {_shown(s.student.id, 80)}: {s.status}" for s in left]
    warned = [s for s in batch.sheets if s.code_mismatch]
    if warned:
        lines += ["", "## Sheet code warnings", ""] + [f"- {s.student.id}" for s in warned]
    lines += ["", "## Files not graded", "", "Every file in the submissions folder is either graded or listed here.", ""]
    lines += [f"- `{_shown(_where(p.path, batch.submissions), 200)}`{' (' + p.student + ')' if p.student else ''}: "
              f"{_escape(p.reason)}" for p in batch.problems] or ["None."]
    return "\n".join(lines) + "\n"


def _reviewed(batch: BatchResult) -> list[str]:
    """The decisions file graded with: per part how many answers' marks review changed, and every decision
    or alias that matched nothing graded (so changed nothing)."""
    review = batch.review
    if review is None:
        return []
    lines = ["", "## Review", "",
             f"Graded with the review decisions in `{_shown(str(review.path), 300)}`: {review.decisions} decision(s), "
             f"{review.aliases} alias(es), which marked {review.applied} answer(s).", ""]
    changed: dict[tuple[int, str, str], list[float]] = {}
    for sheet in batch.sheets:
        if sheet.status != GRADED:
            continue
        for question in sheet.questions:
            for part in question.parts:
                if part.changed_by_review:
                    changed.setdefault((question.number, question.slot, part.part_id), []).append(
                        part.points - part.review.points_before)
    if changed:
        lines += ["| Question | Part | Answers whose marks review changed | Points |", "|---|---|---:|---:|"]
        lines += [f"| {slot} | {part} | {len(d)} | {sum(d):+g} |" for (_, slot, part), d in sorted(changed.items())]
    else:
        lines.append("No mark was changed by review.")
    if review.not_applied:
        lines += ["", "### Not applied", "",
                  "These match nothing graded (the student handed in something else since, or the question changed), "
                  "so they changed no mark:", ""]
        lines += [f"- `{_shown(where_in(review.path, n.line), 300)}`: {_escape(n.what)}: {_escape(n.why, 1000)}"
                  for n in review.not_applied]
    return lines


def where_in(path, line: int | None) -> str:
    """'file:12' (or the file alone) for a place in the decisions file."""
    return f"{path}:{line}" if line else str(path)


def _not_carried(batch: BatchResult) -> list[str]:
    """Parts where the working could not be carried on from a student's wrong earlier answers, and why:
    the student's feedback says no credit was carried forward; this says what stopped it."""
    rows = [f"- {s.student.id}, {q.slot} ({p.part_id}): {_escape(p.not_carried, 1000)}"
            for s in batch.sheets for q in s.questions for p in q.parts if p.not_carried]
    if not rows:
        return []
    return ["", "## Error carried forward not worked", "",
            "The working could not be carried on from these students' own earlier answers, so no credit was "
            "carried forward (each student's feedback says so):", ""] + rows


def _item_rows(batch: BatchResult) -> list[str]:
    """Per part, over graded sheets: how many got it right, and the mistakes most often named."""
    tally: dict[tuple[int, str, str], Counter] = {}
    mistakes: dict[tuple[int, str, str], Counter] = {}
    for sheet in batch.sheets:
        if sheet.status != GRADED:
            continue
        for question in sheet.questions:
            for part in question.parts:
                key = (question.number, question.slot, part.part_id)
                tally.setdefault(key, Counter())[part.status] += 1
                if part.mistake:
                    mistakes.setdefault(key, Counter())[part.mistake] += 1
    rows = []
    for key in sorted(tally):
        count = tally[key]
        total = sum(count.values())
        common = ", ".join(f"{name} ({n})" for name, n in mistakes.get(key, Counter()).most_common(COMMON_MISTAKES))
        rows.append(f"| {key[1]} | {key[2]} | {_pct(count[CORRECT] + count[CARRIED], total)} | "
                    f"{count[CARRIED]} | {count[WRONG]} | {count[BLANK]} | {count[UNREADABLE]} | {common or '-'} |")
    return rows


def _pct(n: int, total: int) -> str:
    return f"{100 * n / total:.0f} % ({n}/{total})" if total else "-"

