"""A class's answer files graded: N students x an assignment, the filled-in YAML forms students hand back.

    python benchmarks/grade_class.py [N] [ASSIGNMENT]

N defaults to 2000, ASSIGNMENT to benchmarks/class_all.yaml (eight problems, 35 parts: 70,000 parts).
Answers are a mix: 60 % right, wrong by 7 %, a named mistake's value, blank, unreadable. Times what
`exgen grade` does: reading and grading the folder (grade_batch, on every core where the version has
--jobs), looking for signs of copying (where the version does), and writing the gradebooks, feedback
and reports (write_results); wall and CPU (this process and its workers), with the load average.
"""
from __future__ import annotations

import inspect
import random
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import Clock, load  # noqa: E402

from exgen.issue.assignment import Student, build_sheet, load_assignment  # noqa: E402
from exgen.issue.generate import default_jobs  # noqa: E402
from exgen.load.bank import load_bank  # noqa: E402
from exgen.render.answer_form import answer_form  # noqa: E402
from graders.grade import grade_batch  # noqa: E402
from graders.report import write_results  # noqa: E402

try:
    from graders.copying import signs_of_copying
except ImportError:  # versions before the copying report
    signs_of_copying = None

HERE = Path(__file__).parent
SECRET = b"benchmark secret, not a real one"


def answer(rng: random.Random, question, part_id: str) -> str:
    right = question.variant.answers[part_id]
    draw = rng.random()
    if draw < 0.6:
        return right.text
    if draw < 0.75 and isinstance(right.value, float):
        return f"{right.value * 1.07:.4g}"
    mistakes = question.variant.mistakes[part_id]
    if draw < 0.85 and mistakes:
        wrong = next(iter(mistakes.values()))
        return f"{wrong:.4g}" if isinstance(wrong, float) else str(wrong)
    return "" if draw < 0.95 else "abc"


def filled_form(sheet, rng: random.Random) -> str:
    """The sheet's answers.yaml with every part answered (the form has a `    part: ""` line for each)."""
    lines = answer_form(sheet).split("\n")
    for question in sheet.questions:
        at = next(i for i, line in enumerate(lines) if line.startswith(f"  {question.slot}:"))
        for part_id in question.variant.answers:
            at = next(i for i in range(at, len(lines)) if lines[i].startswith(f'    {part_id}: ""'))
            text = answer(rng, question, part_id).replace("\\", "\\\\").replace('"', '\\"')
            lines[at] = lines[at].replace('""', f'"{text}"', 1)
    return "\n".join(lines)


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    assignment_file = Path(sys.argv[2]) if len(sys.argv) > 2 else HERE / "class_all.yaml"
    bank = load_bank()
    assignment = load_assignment(assignment_file, bank)
    students = [Student(f"S{i:05d}", f"Student {i}") for i in range(n)]
    rng = random.Random(1)
    with tempfile.TemporaryDirectory() as work:
        handed = Path(work) / "handed"
        handed.mkdir()
        for student in students:
            form = filled_form(build_sheet(assignment, student, bank, SECRET), rng)
            (handed / f"{student.id}.yaml").write_text(form, encoding="utf-8")
        jobs = {"jobs": default_jobs()} if "jobs" in inspect.signature(grade_batch).parameters else {}
        with Clock() as grading:
            batch = grade_batch(assignment, bank, SECRET, handed, roster=students, **jobs)
        with Clock() as copying:
            signs = signs_of_copying(batch, assignment, bank, SECRET) if signs_of_copying else None
        with Clock() as writing:
            write_results(batch, Path(work) / "graded", *([signs] if signs is not None else []))
    parts = sum(len(q.parts) for s in batch.sheets for q in s.questions)
    clocks = (grading, copying, writing)
    print(f"grade {n} answer files ({parts} parts, --jobs {jobs.get('jobs', 1)}): "
          f"{sum(c.wall for c in clocks):.2f} s wall, {sum(c.cpu for c in clocks):.2f} s CPU "
          f"(grade_batch {grading}; signs of copying {copying}; write_results {writing}); {load()}")


if __name__ == "__main__":  # worker processes import this file
    main()
