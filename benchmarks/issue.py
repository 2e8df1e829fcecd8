"""Issuing cost: per-sheet rendering times, then a whole generate run for N students."""
import statistics
import sys
import tempfile
import time
from pathlib import Path

from exgen.assignment import Student, build_sheet, load_assignment
from exgen.bank import load_bank
from exgen.generate import default_jobs, generate
from exgen.render.markdown import key_markdown, sheet_markdown
from exgen.render.pdf import key_pdf, sheet_pdf

def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    bank = load_bank()
    assignment = load_assignment(Path(__file__).parent.parent / "examples" / "tutorial1.yaml", bank)
    secret = b"benchmark secret, not a real one"
    students = [Student(f"S{i:05d}", f"Student {i}") for i in range(n)]


    def median_ms(fn, items):
        fn(items[0])  # warm caches (tex2typst, fonts)
        times = []
        for item in items:
            start = time.perf_counter()
            fn(item)
            times.append((time.perf_counter() - start) * 1e3)
        return f"median {statistics.median(times):6.2f} ms, max {max(times):6.2f} ms"


    sample = students[:30]
    print(f"assignment: {assignment.title}, {len(assignment.questions)} questions")
    print(f"build_sheet     {median_ms(lambda s: build_sheet(assignment, s, bank, secret), sample)}")
    sheets = [build_sheet(assignment, s, bank, secret) for s in sample]
    for name, fn in [("sheet_markdown", lambda s: sheet_markdown(s, {})), ("key_markdown", lambda s: key_markdown(s, {})),
                     ("sheet_pdf", sheet_pdf), ("key_pdf", key_pdf)]:
        print(f"{name:15s} {median_ms(fn, sheets)}")

    for pdf, jobs in ((False, 1), (True, 1), (True, default_jobs())):
        with tempfile.TemporaryDirectory() as out:
            start = time.perf_counter()
            generate(assignment, students, bank, secret, Path(out), pdf=pdf, jobs=jobs)
            took = time.perf_counter() - start
        kind = f"with PDF, {jobs} process(es)" if pdf else "Markdown only"
        print(f"generate {n} students ({kind}): {took:.2f} s, {took / n * 1e3:.1f} ms/student")


if __name__ == "__main__":  # generate() starts worker processes that import this file
    main()
