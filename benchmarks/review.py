"""A class graded, then graded again with review decisions: one for every answer the grader could not read,
and an alias for every choice part.

    python benchmarks/review.py [N] [JOBS]

N defaults to 600 students of benchmarks/class_all.yaml (eight problems, 35 parts), with the answers of
grade_class.py (60 % right; 5 % "abc", a format problem). Times writing the decisions file (save_decisions),
reading it back (load_decisions), and grading with and without it (grade_batch, JOBS processes, default 1);
wall and CPU, with the load average.
"""
from __future__ import annotations

import random
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import Clock, load  # noqa: E402
from grade_class import HERE, SECRET, filled_form  # noqa: E402

from exgen.answertypes import answer_type  # noqa: E402
from exgen.issue.assignment import Student, build_sheet, load_assignment  # noqa: E402
from exgen.load.bank import load_bank  # noqa: E402
from graders.decisions import ACCEPT, Alias, Decision, Decisions, cleaned, load_decisions, save_decisions  # noqa: E402
from graders.grade import grade_batch  # noqa: E402
from graders.results import UNREADABLE  # noqa: E402


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 600
    jobs = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    bank = load_bank()
    assignment = load_assignment(HERE / "class_all.yaml", bank)
    students = [Student(f"S{i:05d}", f"Student {i}") for i in range(n)]
    rng = random.Random(1)
    with tempfile.TemporaryDirectory() as work:
        handed = Path(work) / "handed"
        handed.mkdir()
        for student in students:
            form = filled_form(build_sheet(assignment, student, bank, SECRET), rng)
            (handed / f"{student.id}.yaml").write_text(form, encoding="utf-8")
        with Clock() as plain:
            batch = grade_batch(assignment, bank, SECRET, handed, roster=students, jobs=jobs)
        decisions = [Decision(s.student.id, q.number, p.part_id, cleaned(p.given), ACCEPT, "A. Lecturer",
                              "read by hand") for s in batch.sheets for q in s.questions for p in q.parts
                     if p.status == UNREADABLE]
        aliases = [Alias(number, part.id, spec.template, "abc", (answer_type(part).form_choices(part) or ("",))[0],
                         "A. Lecturer", "a spelling") for number, spec in enumerate(assignment.questions, start=1)
                   for part in bank.get(spec.template).parts if answer_type(part).form_choices(part)]
        path = Path(work) / "graded.decisions.yaml"
        with Clock() as saving:
            save_decisions(Decisions(assignment.id, tuple(decisions), tuple(aliases)), path)
        with Clock() as loading:
            found = load_decisions(path, assignment.id)
        with Clock() as reviewed:
            again = grade_batch(assignment, bank, SECRET, handed, roster=students, jobs=jobs, decisions=found)
        size = path.stat().st_size
    parts = sum(len(q.parts) for s in batch.sheets for q in s.questions)
    touched = sum(p.review is not None for s in again.sheets for q in s.questions for p in q.parts)
    print(f"{n} answer files ({parts} parts), --jobs {jobs}: {len(decisions)} decisions and {len(aliases)} aliases "
          f"({size / 1024:.0f} KiB), {touched} parts changed by review, {len(again.review.not_applied)} not applied")
    print(f"  save_decisions {saving}; load_decisions {loading}")
    print(f"  grade_batch without decisions {plain}; with them {reviewed}; {load()}")


if __name__ == "__main__":  # worker processes import this file
    main()
