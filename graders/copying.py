"""Signs of copying, which per-student numbers make visible: a submission right for another student's
numbers and wrong for its own, the same wrong answers from two students whose numbers differ, a file
carrying another student's sheet code. Each sign is evidence to look at, listed in the report with what
was found; nothing here changes a mark.

An answer counts as evidence only when it is distinctive: when few students' keys (or answers) share
it. A count of belts or a choice between two words is shared by half the class and says nothing.
"""
from __future__ import annotations

import bisect
import math
from collections import defaultdict
from typing import Any

from exgen.answertypes import answer_type
from exgen.errors import ExgenError
from exgen.issue.assignment import Assignment, build_sheet

from .answers import read_submission
from .echo import shown
from .results import GRADED, PROBLEM_FILE, WRONG, BatchResult

#: What a student typed, quoted in the evidence: one line, this long at most, nothing that hides or reorders text.
QUOTED = 60
#: A pair is a sign when this many parts give evidence.
MIN_PARTS = 2
#: An answer is distinctive when at most this many students' keys (or wrong answers) share it.
MAX_SHARED = 2
#: Keys whose value lies this far (relatively) from an answer are never compared with it.
WINDOW = 0.05
#: An answer copied from another sheet is that sheet's key as typed (to four figures or so): it must lie
#: within this fraction of the part's tolerance of it, so a wrong answer near someone's key by chance is not taken.
COPIED = 0.2

OTHER_VARIANT = "answers_match_another_sheet"
IDENTICAL_WRONG = "identical_wrong_answers"
OTHER_CODE = "another_students_sheet_code"


def signs_of_copying(batch: BatchResult, assignment: Assignment, bank, secret: bytes,
                     codes: dict[str, str] | None = None) -> list[dict]:
    """Every sign found in a graded batch, strongest first. Sheets are rebuilt from the secret, so a
    student's answers can be compared with everyone's numbers."""
    keys = _keys(batch, assignment, bank, secret)
    answers = _answers(batch, keys)
    signs = _other_variant(answers, keys) + _identical_wrong(answers) + _other_code(batch, codes or {})
    return sorted(signs, key=lambda s: (-s["strength"], s["kind"], s["students"]))


def _keys(batch, assignment, bank, secret) -> dict[tuple[str, str], dict[str, tuple[Any, Any]]]:
    """(slot, part) -> student -> (expected value, part spec), for every student on the roster: read from
    the results of the sheets graded (grading built them), built again from the secret for the others."""
    out: dict[tuple[str, str], dict[str, tuple[Any, Any]]] = defaultdict(dict)
    for result in batch.sheets:
        if result.status == GRADED and all(p.value is not None for q in result.questions for p in q.parts):
            for question in result.questions:
                specs = {spec.id: spec for spec in bank.get(question.template).parts}
                for part in question.parts:
                    out[(question.slot, part.part_id)][result.student.id] = (part.value, specs[part.part_id])
            continue
        try:
            sheet = build_sheet(assignment, result.student, bank, secret)
        except ExgenError:
            continue
        for question in sheet.questions:
            for part in question.variant.template.parts:
                out[(question.slot, part.id)][result.student.id] = (question.variant.answers[part.id].value, part)
    return out


def _answers(batch, keys) -> dict[tuple[str, str], dict[str, tuple[Any, str]]]:
    """(slot, part) -> student -> (the value read, the text typed), for every wrong answer graded."""
    out: dict[tuple[str, str], dict[str, tuple[Any, str]]] = defaultdict(dict)
    for sheet in batch.sheets:
        if sheet.status != GRADED:
            continue
        for question in sheet.questions:
            for part in question.parts:
                found = keys.get((question.slot, part.part_id), {}).get(sheet.student.id)
                if part.status != WRONG or found is None:
                    continue
                spec = found[1]
                try:
                    value = answer_type(spec).read(part.given, spec).value
                except (ExgenError, ValueError, ArithmeticError, TypeError):
                    continue
                out[(question.slot, part.part_id)][sheet.student.id] = (value, shown(part.given, QUOTED))
    return out


def _matches(spec, given, expected, widen: float = 1.0) -> bool:
    try:
        return bool(answer_type(spec).matches(given, expected, spec, widen))
    except (TypeError, ValueError, ArithmeticError):
        return False


def _reach(spec, value) -> float | None:
    """How far from `value` a key it matches as a copy can lie (the answer type's bound), if known."""
    try:
        return answer_type(spec).reach(value, spec, COPIED)
    except (TypeError, ValueError, ArithmeticError):
        return None


def _near(index, value, reach: float | None = None) -> list[tuple[Any, list[str]]]:
    """(key, the students who have it) for every key within WINDOW of `value`, and within `reach` of it
    when the answer type bounds how far a matching key can lie (every key, for values that are not numbers)."""
    values, groups, others = index
    if not _is_number(value):
        return groups + others
    low, high = value - WINDOW * abs(value) - 1e-12, value + WINDOW * abs(value) + 1e-12
    if reach is not None:
        low, high = max(low, value - reach), min(high, value + reach)
    return [groups[i] for i in range(bisect.bisect_left(values, low), bisect.bisect_right(values, high))] + others


def _index(per_student: dict[str, tuple[Any, Any]]):
    """Keys that are numbers sorted, one student each; the others with the students who share each, so
    that a choice half the class has is compared once, not once per student."""
    numbers = sorted((v, s) for s, (v, _) in per_student.items() if _is_number(v))
    shared: dict[Any, tuple[Any, list[str]]] = {}
    others = []
    for student, (value, _) in per_student.items():
        if _is_number(value):
            continue
        try:
            shared.setdefault((type(value), value), (value, []))[1].append(student)
        except TypeError:  # a value that cannot be a dictionary key is compared on its own
            others.append((value, [student]))
    return [v for v, _ in numbers], [(v, [s]) for v, s in numbers], list(shared.values()) + others


def _other_variant(answers, keys) -> list[dict]:
    """Students whose wrong answers are another student's right ones (and that student's alone)."""
    evidence: dict[tuple[str, str], list[tuple[str, str, str]]] = defaultdict(list)
    for (slot, part_id), wrong in answers.items():
        per_student = keys[(slot, part_id)]
        index = _index(per_student)
        for student, (value, typed) in wrong.items():
            spec = per_student[student][1]
            near = _near(index, value, _reach(spec, value))
            owners = [other for key, students in near if _matches(spec, value, key, COPIED)
                      for other in students if other != student]
            if not owners or len(owners) > MAX_SHARED:
                continue
            for owner in owners:
                evidence[(student, owner)].append((slot, part_id,
                    f"{slot} ({part_id}): {typed} is {owner}'s answer "
                    f"({_text(spec, per_student[owner][0])}); {student}'s is {_text(spec, per_student[student][0])}"))
    return [{"kind": OTHER_VARIANT, "students": [a, b], "strength": len(found),
             "summary": f"{a} handed in {len(found)} answers that are wrong for {a}'s sheet and right for {b}'s",
             "evidence": [line for _, _, line in found], "parts": _parts(found, [a])}
            for (a, b), found in _strongest(evidence).items()]


def _parts(found: list[tuple[str, str, str]], students: list[str]) -> list[dict]:
    """The parts a sign rests on, for each student whose answers they are: what `exgen review` lists."""
    return [{"student": s, "slot": slot, "part": part} for s in students for slot, part, _ in found]


def _strongest(evidence: dict[tuple[str, str], list[tuple[str, str, str]]]) -> dict[tuple[str, str], list]:
    """Per copier, the pairs with at least MIN_PARTS parts no stronger pair explains: answers copied from
    one sheet also match a third student whose numbers happen to be the same in those parts."""
    kept: dict[tuple[str, str], list] = {}
    explained: dict[str, set[str]] = defaultdict(set)
    for (a, b), found in sorted(evidence.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        parts = {(slot, part) for slot, part, _ in found}
        if len(parts - explained[a]) >= MIN_PARTS:
            kept[(a, b)] = found
            explained[a] |= parts
    return kept


def _identical_wrong(answers) -> list[dict]:
    """Pairs of students giving the same wrong values, though their numbers differ."""
    evidence: dict[tuple[str, str], list[tuple[str, str, str]]] = defaultdict(list)
    for (slot, part_id), wrong in answers.items():
        groups: dict[Any, list[str]] = defaultdict(list)
        for student, (value, _) in wrong.items():
            key = _rounded(value)
            if key is not None:
                groups[key].append(student)
        for students in groups.values():
            if 2 <= len(students) <= MAX_SHARED:
                a, b = sorted(students)
                evidence[(a, b)].append((slot, part_id, f"{slot} ({part_id}): both answered {wrong[a][1]}"))
    return [{"kind": IDENTICAL_WRONG, "students": [a, b], "strength": len(found),
             "summary": f"{a} and {b} gave the same {len(found)} wrong answers, though their numbers differ",
             "evidence": [line for _, _, line in found], "parts": _parts(found, [a, b])}
            for (a, b), found in evidence.items() if len(found) >= MIN_PARTS]


def _other_code(batch, codes: dict[str, str]) -> list[dict]:
    """Files in one student's place carrying another sheet's code (graded for no one, or with a warning)."""
    whose = {_code(c): s for s, c in codes.items() if c}
    out = []
    for sheet in batch.sheets:
        if sheet.path is None or not (sheet.code_mismatch or sheet.status == PROBLEM_FILE):
            continue
        try:
            code = read_submission(sheet.path).code
        except ExgenError:
            continue
        own = codes.get(sheet.student.id, sheet.code)
        if not code or _code(code) == _code(own):
            continue
        owner = whose.get(_code(code), "")
        students = [sheet.student.id] + ([owner] if owner else [])
        code = shown(code, QUOTED, word=20)
        out.append({"kind": OTHER_CODE, "students": students, "strength": 10,
                    "summary": f"{sheet.student.id}'s file carries the sheet code {code}, "
                               + (f"which is {owner}'s" if owner else "which is no one's sheet"),
                    "evidence": [f"{shown(sheet.path.name, QUOTED)}: code {code}; {sheet.student.id}'s sheet has {own}"],
                    "parts": []})
    return out


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _rounded(value):
    """A wrong answer's value to four significant figures (0 and non-numbers say nothing)."""
    if not _is_number(value) or value == 0:
        return None
    return float(f"{value:.4g}")


def _text(spec, value) -> str:
    try:
        return answer_type(spec).text(value, spec)
    except (TypeError, ValueError, ArithmeticError):
        return str(value)


def _code(text: str) -> str:
    return "".join(ch for ch in str(text) if ch.isalnum()).upper()
