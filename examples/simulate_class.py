"""Simulate a class handing in tutorial 1: 200 students, answers with realistic mistakes, and planted
copies, then grade it and write the gradebooks and the item analysis.

    python examples/simulate_class.py OUT [--students 200] [--seed 7]

Each student has an ability; for each part they answer right with a chance that grows with it, else
make one of the part's named mistakes (the template's own, as a student who made it would type it),
else leave it blank, else give a wrong number of their own. One part has a planted mistake: exactly
PLANTED students make its first named mistake. Three copies are planted: a student who hands in the
answers of their neighbour's sheet (right for it, wrong for their own), two students who hand in the
same wrong work, and a student who hands in a classmate's file, sheet code and all. OUT/plan.json
records what was planted; OUT/graded/ holds what exgen found.
"""
from __future__ import annotations

import argparse
import json
import random
import sys
from collections import Counter
from pathlib import Path

from exgen.answertypes import answer_type
from exgen.issue.assignment import Student, build_sheet, load_assignment
from exgen.issue.generate import generate
from exgen.issue.manifest import read_manifest
from exgen.load.bank import load_bank
from graders.copying import signs_of_copying
from graders.grade import grade_issued
from graders.mistakes import template_mistake
from graders.report import write_results

ASSIGNMENT = Path(__file__).parent / "tutorial1.yaml"
SECRET = b"simulated class: a secret for this script only, never a course's"
FIRST = ["Aisyah", "Daniel", "Priya", "Haziq", "Mei Ling", "Arjun", "Farah", "Wei Jie", "Kavitha", "Amir"]
LAST = ["Rahman", "Lim", "Ramasamy", "Azmi", "Chen", "Nair", "Ismail", "Tan", "Pillai", "Yusof"]
PLANTED_PART = ("q3", "a")  # the flat belt's angle of contact: the crossed-belt formula is a classic
PLANTED = 37


def planted_copies(n: int) -> dict[str, tuple[str, str]]:
    """Who copies whom, placed through a class of n: a copier who hands in the answers of the next
    student's sheet; two who hand in the same wrong work; one who hands in the next student's own file."""
    def pair(i: int) -> tuple[str, str]:
        return f"S{i:04d}", f"S{i + 1:04d}"

    return {"answers_match_another_sheet": pair(max(1, n // 12)), "identical_wrong_answers": pair(n * 3 // 5),
            "another_students_sheet_code": pair(n * 3 // 4)}


def roster(n: int) -> list[Student]:
    return [Student(f"S{i:04d}", f"{FIRST[i % 10]} {LAST[(i // 10) % 10]}", f"s{i:04d}@student.example.edu",
                    f"S{1 + i % 2}") for i in range(1, n + 1)]


def answer_text(part, value) -> str:
    return answer_type(part).text(value, part)


def wrong_number(part, value, rng: random.Random) -> str | None:
    """A wrong answer of the student's own: the right number off by 10-60 % (numbers only)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    wrong = value * rng.choice([rng.uniform(0.4, 0.9), rng.uniform(1.1, 1.6)]) if value else 1
    return answer_text(part, max(value + 1, round(wrong)) if isinstance(value, int) else float(wrong))


def named_mistake(question, part) -> tuple[str, str] | None:
    """The text of the part's first listed mistake this variant records, and the name the grader gives it."""
    values = question.variant.mistakes.get(part.id, {})
    for spec in part.mistakes:
        if spec.when in values:
            value = values[spec.when]
            found = template_mistake(part, value, [values], lambda g, e, w=1.0: answer_type(part).matches(g, e, part, w))
            return answer_text(part, value), found.name if found else spec.when
    return None


def simulate(out: Path, students: int = 200, seed: int = 7) -> dict:
    rng = random.Random(seed)
    bank = load_bank()
    assignment = load_assignment(ASSIGNMENT, bank)
    class_list = roster(students)
    generate(assignment, class_list, bank, SECRET, out / "issued", pdf=False)
    sheets = {s.id: build_sheet(assignment, s, bank, SECRET) for s in class_list}
    handed = out / "handed"
    handed.mkdir(parents=True, exist_ok=True)
    copies = planted_copies(students)
    copying = {s for pair in copies.values() for s in pair}
    planted_ids = set(rng.sample([s.id for s in class_list if s.id not in copying], PLANTED))
    mistakes: Counter = Counter()
    files: dict[str, dict] = {}
    for student in class_list:
        ability = rng.betavariate(5, 2.5)
        answers: dict[str, dict[str, str]] = {}
        for question in sheets[student.id].questions:
            answers[question.slot] = {}
            for part in question.variant.template.parts:
                value = question.variant.answers[part.id].value
                key = (question.slot, part.id)
                named = named_mistake(question, part)
                if key == PLANTED_PART:
                    text = named[0] if student.id in planted_ids else answer_text(part, value)
                    if student.id in planted_ids:
                        mistakes[(*key, named[1])] += 1
                else:
                    roll = rng.random()
                    if roll < 0.25 + 0.7 * ability:
                        text = answer_text(part, value)
                    elif named and roll < 0.25 + 0.7 * ability + 0.12:
                        text = named[0]
                        mistakes[(*key, named[1])] += 1
                    elif roll > 0.97:
                        text = ""
                    else:
                        text = wrong_number(part, value, rng) or answer_text(part, value)
                answers[question.slot][part.id] = text
        files[student.id] = {"assignment": assignment.id, "student": student.id, "code": sheets[student.id].code,
                             "answers": answers}
    _plant_copies(files, sheets, rng, mistakes, copies)
    for student_id, content in files.items():
        (handed / f"{student_id}.json").write_text(json.dumps(content, indent=1), encoding="utf-8")
    plan = {"students": students, "planted_part": list(PLANTED_PART), "planted": PLANTED,
            "mistakes": [[*k, n] for k, n in sorted(mistakes.items())],
            "copies": {kind: list(pair) for kind, pair in copies.items()}}
    (out / "plan.json").write_text(json.dumps(plan, indent=1), encoding="utf-8")
    manifest = read_manifest(out / "issued")
    batch = grade_issued(manifest, bank, SECRET, handed)
    signs = signs_of_copying(batch, manifest.assignment, bank, SECRET, manifest.codes)
    write_results(batch, out / "graded", signs)
    return plan


def _plant_copies(files, sheets, rng, mistakes: Counter, copies: dict) -> None:
    """Overwrite the planted students' files (their own mistakes no longer counted)."""
    neighbour, same_work, other_file = (copies[k] for k in ("answers_match_another_sheet", "identical_wrong_answers",
                                                             "another_students_sheet_code"))
    for student_id in neighbour[:1] + same_work[1:] + other_file[:1]:
        _uncount(files[student_id], sheets[student_id], mistakes)
    copier, source = neighbour
    files[copier]["answers"] = {q.slot: {p.id: answer_text(p, q.variant.answers[p.id].value)
                                         for p in q.variant.template.parts} for q in sheets[source].questions}
    first, second = same_work
    _uncount(files[first], sheets[first], mistakes)
    work = {}
    for question in sheets[first].questions:
        work[question.slot] = {}
        for part in question.variant.template.parts:
            value = question.variant.answers[part.id].value
            work[question.slot][part.id] = wrong_number(part, value, rng) or answer_text(part, value)
    files[first]["answers"] = work
    files[second]["answers"] = json.loads(json.dumps(work))
    taker, owner = other_file
    files[taker] = {**files[owner], "student": ""}


def _uncount(content, sheet, mistakes: Counter) -> None:
    for question in sheet.questions:
        for part in question.variant.template.parts:
            named = named_mistake(question, part)
            if named and content["answers"][question.slot][part.id] == named[0]:
                mistakes[(question.slot, part.id, named[1])] -= 1


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--students", type=int, default=200, help="at least 50")
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args(argv)
    plan = simulate(args.out, args.students, args.seed)
    print(f"{plan['students']} students simulated; graded into {args.out / 'graded'} "
          f"(item-analysis.html, canvas_gradebook.csv, moodle_grades.csv)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
