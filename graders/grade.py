"""Grade answer files against the sheets they answer: one sheet, a directory, or what was issued.

Each student's sheet is rebuilt from (assignment, student, secret), so a student is always graded
against their own numbers; what an answer file says of itself is only checked, never trusted.
`grade_issued` first checks that the secret and every template are still what the manifest records,
and stops before any mark if not (unless forced, and then the batch carries the warning).
"""
from __future__ import annotations

import contextlib
import dataclasses
import inspect
from pathlib import Path
from typing import Callable, Iterable, Iterator, Mapping

from exgen.answertypes import answer_type
from exgen.errors import ExgenError
from exgen.issue.assignment import Assignment, Question, Sheet, Student, build_sheet
from exgen.issue.manifest import Manifest, ManifestError, issue_mismatches
from exgen.issue.roster import load_roster
from exgen.load.bank import Bank
from exgen.runtime import parallel
from exgen.solve.variant import Variant

from .answers import Submission
from .decisions import Decisions
from .echo import shown
from .collect import Entry, collect, read_one
from .marking import QuestionMarker
from .report import student_page
from .review import ReviewPlan, plan, summary
from .results import (GRADED, NO_SUBMISSION, NOT_GRADED, PROBLEM_FILE, UNREADABLE_FILE, BatchResult, Column,
                      FileProblem, QuestionResult, SheetResult)

CODE_MISMATCH = ("This answer file carries the sheet code {given}, but your sheet's code is {code}: it may "
                 "belong to another sheet. It was graded against your own sheet.")
OTHER_ASSIGNMENT = "This answer file is for the assignment {given!r}, not {expected!r}; it was graded as {expected!r}."
UNKNOWN_QUESTION = "The answer file answers {slots}, which your sheet does not ask; ignored."
UNKNOWN_PART = "The answer file answers {parts} of {slot}, which has no such part; ignored."
LISTED = 5  # names of unknown questions or parts quoted in one note; the rest are counted
NO_FILE = "No answer file was handed in."
UNREADABLE = "Your answer file could not be read: {reason}"
NO_SHEET = "The sheet could not be rebuilt for grading: {reason}"
REFUSED = "Your answer file {name} was not graded: it {reason}. Ask your instructor."
MISMATCH = ("not graded, nothing written: grading now would not give the marks of the sheets as issued: {problems}. "
            "Grade with the secret and templates they were issued with, or add --force to grade anyway")
FORCED = "Graded with --force although {problem}"
NOT_ISSUED = "{student} was not issued a sheet ({manifest})"

Progress = Callable[[Iterable, int], Iterable]
#: A class at least this large is read and graded in worker processes (with jobs > 1): starting them
#: costs about as much as grading a hundred or two files.
PARALLEL_FROM = 200


def grade_sheet(sheet: Sheet, submission: Submission, review: ReviewPlan | None = None) -> SheetResult:
    """Grade every part of every question, with the review decisions that match applied (graders.review);
    a differing sheet code is a warning, not a refusal."""
    warnings = list(submission.warnings)
    if submission.code and _norm(submission.code) != _norm(sheet.code):  # graded all the same
        warnings.append(CODE_MISMATCH.format(given=submission.code[:40], code=sheet.code))
    if submission.assignment and submission.assignment != sheet.assignment.id:
        warnings.append(OTHER_ASSIGNMENT.format(given=submission.assignment[:40], expected=sheet.assignment.id))
    answers, problems = _by_key(submission.answers), _by_key(submission.problems)
    results, used = [], set()
    for question in sheet.questions:
        key = next((k for k in (question.slot, str(question.number), f"q{question.number}")
                    if _norm(k) in answers or _norm(k) in problems), question.slot)
        used.add(_norm(key))
        given, trouble = _by_key(answers.get(_norm(key), {})), _by_key(problems.get(_norm(key), {}))
        parts = {_norm(p.id): p.id for p in question.variant.template.parts}
        unknown = [k for k in {**given, **trouble} if k and k not in parts]
        if unknown:
            warnings.append(UNKNOWN_PART.format(parts=_listed(unknown, "part"), slot=question.slot))
        marked = QuestionMarker(question, review.aliases_for(question.number) if review else None).mark(
            {parts[k]: v for k, v in given.items() if k in parts},
            {parts.get(k, k): v for k, v in trouble.items()})
        results.append(review.apply(sheet.student.id, marked) if review else marked)
    unknown = [k for k in {**answers, **problems} if k not in used]
    if unknown:
        warnings.append(UNKNOWN_QUESTION.format(slots=_listed(unknown, "")))
    mismatch = bool(submission.code) and _norm(submission.code) != _norm(sheet.code)
    return SheetResult(sheet.student, GRADED, sheet.points, sheet.code, tuple(results), tuple(warnings),
                       submission.path, mismatch)


def grade_issued(manifest: Manifest, bank: Bank, secret: bytes, submissions_dir: Path, *, secret_source: str = "",
                 force: bool = False, roster: list[Student] | None = None,
                 progress: Progress | None = None, jobs: int = 1, accept_limits: bool = False,
                 decisions: Decisions | None = None) -> BatchResult:
    """Grade the answers to what a manifest records: its questions, its roster (or the part of it given),
    its sheet codes. A different secret, a changed template or solver, or a student never issued a sheet
    stops the run with ManifestError before any mark, unless `force`d (then the batch carries warnings)."""
    problems = issue_mismatches(manifest, bank, secret, secret_source or "the secret given")
    issued = {s.id: s for s in manifest.students}
    students = list(manifest.students) if roster is None else [issued.get(s.id, s) for s in roster]
    problems += [NOT_ISSUED.format(student=s.id, manifest=manifest.path.name) for s in students if s.id not in issued]
    if problems and not force:
        raise ManifestError(manifest.path, MISMATCH.format(problems="; ".join(problems)))
    batch = grade_batch(manifest.assignment, bank, secret, submissions_dir, roster=students, progress=progress,
                        codes=manifest.codes, jobs=jobs, accept_limits=accept_limits, decisions=decisions)
    return dataclasses.replace(batch, warnings=tuple(FORCED.format(problem=p) for p in problems))


def grade_batch(assignment: Assignment, bank: Bank, secret: bytes, submissions_dir: Path,
                roster: list[Student] | Path | None = None, progress: Progress | None = None,
                codes: dict[str, str] | None = None, jobs: int = 1, accept_limits: bool = False,
                decisions: Decisions | None = None) -> BatchResult:
    """Grade every answer file in a directory; one broken file never stops the rest. `codes` are the
    sheet codes issued, by student (from the manifest); without them each sheet's own code is used.
    A folder in which the walk reaches a limit (a student's file may be missed there) raises
    graders.walk.LimitsReached before any file is read, unless `accept_limits`; the batch then carries them.
    With jobs > 1 and at least PARALLEL_FROM files, they are read and graded in that many processes
    (the same results, in the same order). `decisions` (graders.decisions) are applied where they match;
    the batch lists those that match nothing graded."""
    if isinstance(roster, (str, Path)):
        roster = load_roster(Path(roster))
    columns = tuple(Column(i, spec.slot, spec.template, spec.points or bank.get(spec.template).points,
                           _kinds(bank.get(spec.template)))
                    for i, spec in enumerate(assignment.questions, start=1))
    max_points = sum(c.max_points for c in columns)
    review = plan(decisions, assignment, bank)
    shared = (assignment, bank, secret, max_points, codes or {}, review)
    with contextlib.ExitStack() as stack:
        workers = []

        def read_all(paths):  # the pool starts once there are enough files to pay for it
            if jobs > 1 and len(paths) >= PARALLEL_FROM:
                workers.append(stack.enter_context(parallel.pool(jobs, shared)))
                return workers[0].map(read_one, paths, chunksize=32)
            return map(read_one, paths)

        entries, problems, limits = collect(Path(submissions_dir), roster, assignment=assignment.id, codes=codes,
                                            read_all=read_all, accept_limits=accept_limits)
        pages: dict[str, tuple[SheetResult, str]] = {}
        if workers:
            graded = _keeping_pages(workers[0].map(_grade_in_worker, entries, chunksize=16), pages)
        else:
            issued = codes or {}
            graded = (_grade_entry(entry, assignment, bank, secret, max_points, issued.get(entry.student.id), review)
                      for entry in entries)
        sheets = _gather(_with_progress(progress, graded, len(entries)), entries, problems, submissions_dir)
    batch = BatchResult(assignment, columns, tuple(sheets), tuple(problems), Path(submissions_dir), pages=pages,
                        limits=tuple(limits))
    return dataclasses.replace(batch, review=summary(review, batch)) if review else batch


def _grade_in_worker(entry: Entry) -> tuple[SheetResult, str]:
    """The sheet graded, and its feedback page written here too: the pages are written in parallel, not
    one after another by the process that writes the results."""
    assignment, bank, secret, max_points, codes, review = parallel.shared()
    result = _grade_entry(entry, assignment, bank, secret, max_points, codes.get(entry.student.id), review)
    return result, student_page(assignment.title, result)


def _keeping_pages(graded: Iterable[tuple[SheetResult, str]], pages: dict) -> Iterator[SheetResult]:
    for result, page in graded:
        pages[result.student.id] = (result, page)
        yield result


def _gather(graded: Iterable[SheetResult], entries: list[Entry], problems: list[FileProblem],
            submissions_dir: Path) -> list[SheetResult]:
    """The sheets' results in entry order; a sheet that could not be rebuilt is also a problem file."""
    sheets = []
    for entry, sheet_result in zip(entries, graded):
        if sheet_result.status == NOT_GRADED:
            problems.append(FileProblem(entry.path or Path(submissions_dir), sheet_result.warnings[-1],
                                        entry.student.id))
        sheets.append(sheet_result)
    return sheets


def grade_variant(variant: Variant, answers: Mapping[str, str]) -> QuestionResult:
    """One variant graded on its own (part id -> text), at the template's own points."""
    question = Question(1, "q1", variant, variant.template.points)
    parts = {_norm(p.id): p.id for p in variant.template.parts}
    return QuestionMarker(question).mark({parts[_norm(k)]: v for k, v in answers.items() if _norm(k) in parts})


def _with_progress(progress: Progress | None, items: Iterable, total: int) -> Iterable:
    """`progress(iterable, total)`; a wrapper that also wants a label gets "grading"."""
    if progress is None:
        return items
    try:
        wanted = len(inspect.signature(progress).parameters)
    except (TypeError, ValueError):
        wanted = 2
    return progress(items, total, "grading") if wanted >= 3 else progress(items, total)


def _grade_entry(entry: Entry, assignment: Assignment, bank: Bank, secret: bytes, max_points: float,
                 code: str | None = None, review: ReviewPlan | None = None) -> SheetResult:
    notes = tuple(entry.notes)
    if entry.path is None:  # a note says why, when a file naming the student was found elsewhere
        return SheetResult(entry.student, NO_SUBMISSION, max_points, warnings=notes or (NO_FILE,))
    if entry.submission is None:
        return SheetResult(entry.student, UNREADABLE_FILE, max_points,
                           warnings=notes + (UNREADABLE.format(reason=entry.error),), path=entry.path)
    if entry.refused:
        return SheetResult(entry.student, PROBLEM_FILE, max_points, code=code or "", path=entry.path,
                           warnings=notes + (REFUSED.format(name=entry.path.name, reason=entry.refused),))
    try:
        sheet = build_sheet(assignment, entry.student, bank, secret)
    except ExgenError as exc:
        return SheetResult(entry.student, NOT_GRADED, max_points, warnings=notes + (NO_SHEET.format(reason=exc),),
                           path=entry.path)
    if code:  # the code printed on the sheet as issued
        sheet = dataclasses.replace(sheet, code=code)
    result = grade_sheet(sheet, entry.submission, review)
    return dataclasses.replace(result, warnings=notes + result.warnings)


def _kinds(template) -> tuple[tuple[str, str, tuple[str, ...]], ...]:
    return tuple((p.id, p.type, tuple(answer_type(p).form_choices(p) or ())) for p in template.parts)


def _listed(names: list[str], noun: str) -> str:
    """"part 'x'", "parts 'x', 'y' and 3 more": at most LISTED names, each shortened."""
    quoted = [repr(shown(n, 20)) for n in names[:LISTED]]
    more = len(names) - LISTED
    text = ", ".join(quoted) + (f" and {more} more" if more > 0 else "")
    if len(quoted) > 1 and more <= 0:
        text = ", ".join(quoted[:-1]) + " and " + quoted[-1]
    return f"{noun}{'s' if len(names) > 1 else ''} {text}" if noun else text


def _norm(key: str) -> str:
    """'(a)', 'a)', ' A ' -> 'a'; 'Q1' -> 'q1': how students write part and question names."""
    return str(key).strip().strip("().:").strip().lower()


def _by_key(mapping: Mapping[str, object]) -> dict[str, object]:
    return {_norm(k): v for k, v in mapping.items()}
