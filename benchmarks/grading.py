"""Grading throughput: N students x tutorial1 (4 questions, 16 parts), answers a mix of right, wrong, ECF, blank."""
import json
import random
import shutil
import sys
import tempfile
import time
from exgen.issue.assignment import load_assignment, Student, build_sheet
from exgen.load.bank import load_bank
from exgen.render.answer_form import answer_form
from graders.answers import read_submission
from graders.grade import grade_batch, grade_sheet
from graders.report import write_results
from pathlib import Path

n = int(sys.argv[1]) if len(sys.argv) > 1 else 300
assignment_file = sys.argv[2] if len(sys.argv) > 2 else "tutorial1.yaml"
bank = load_bank()
assignment = load_assignment(Path(Path(__file__).parent.parent / "examples" / "tutorial1.yaml"), bank)
secret = b"b" * 32
work = Path(tempfile.mkdtemp()) / "subs"; shutil.rmtree(work, ignore_errors=True); work.mkdir(parents=True)
rng = random.Random(1)
t0 = time.perf_counter()
students = [Student(f"s{i:05d}") for i in range(n)]
for st in students:
    sheet = build_sheet(assignment, st, bank, secret)
    answers = {}
    for q in sheet.questions:
        answers[q.slot] = {}
        for pid, a in q.variant.answers.items():
            r = rng.random()
            if r < 0.6: text = a.text
            elif r < 0.75 and isinstance(a.value, float): text = f"{a.value * 1.07:.4g}"
            elif r < 0.85 and q.variant.mistakes[pid]:
                m = list(q.variant.mistakes[pid].values())[0]
                text = f"{m:.4g}" if isinstance(m, float) else str(m)
            elif r < 0.95: text = ""
            else: text = "abc"
            answers[q.slot][pid] = text
    (work / f"{st.id}.json").write_text(json.dumps({"student": st.id, "code": sheet.code, "answers": answers}))
t1 = time.perf_counter()
batch = grade_batch(assignment, bank, secret, work, roster=students)
t2 = time.perf_counter()
write_results(batch, work.parent / "out")
t3 = time.perf_counter()
parts = sum(len(q.parts) for s in batch.sheets for q in s.questions)
print(f"{n} students, {parts} parts: setup {t1-t0:.2f}s; grade_batch {t2-t1:.2f}s "
      f"({n/(t2-t1):.0f} sheets/s, {parts/(t2-t1):.0f} parts/s); write_results {t3-t2:.2f}s")
print(batch.summary())
# where the time goes
sheet = build_sheet(assignment, students[0], bank, secret)
sub = read_submission(work / f"{students[0].id}.json")
k = 200
t = time.perf_counter();  [build_sheet(assignment, students[0], bank, secret) for _ in range(k)]; tb = (time.perf_counter()-t)/k
t = time.perf_counter();  [read_submission(work / f"{students[0].id}.json") for _ in range(k)]; tr = (time.perf_counter()-t)/k
t = time.perf_counter();  [grade_sheet(sheet, sub) for _ in range(k)]; tg = (time.perf_counter()-t)/k
print(f"per sheet: build_sheet {tb*1e3:.2f} ms, read_submission {tr*1e3:.2f} ms, grade_sheet {tg*1e3:.2f} ms")
