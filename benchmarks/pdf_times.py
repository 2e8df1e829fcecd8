"""One key PDF and one sheet PDF: Typst source written from a drawn sheet, then compiled in-process.

    python benchmarks/pdf_times.py [STUDENTS] [ASSIGNMENT]

Medians over STUDENTS (default 20) sheets of ASSIGNMENT (default benchmarks/class_all.yaml): the whole
of key_pdf()/sheet_pdf() given the drawn sheet and its figures, and Typst's compile alone; and the sheet
without its answer form beside it (the form may add at most a tenth), each over other students' sheets.
"""
from __future__ import annotations

import inspect
import sys
import time
from pathlib import Path
from statistics import median

sys.path.insert(0, str(Path(__file__).parent))
from clock import allocator, load, median_ms  # noqa: E402

from exgen.issue.assignment import Student, build_sheet, load_assignment  # noqa: E402
from exgen.load.bank import load_bank  # noqa: E402
from exgen.render import pdf  # noqa: E402

HERE = Path(__file__).parent


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    assignment_file = Path(sys.argv[2]) if len(sys.argv) > 2 else HERE / "class_all.yaml"
    bank = load_bank()
    assignment = load_assignment(assignment_file, bank)
    # twice as many sheets as timed: "compile alone" typesets other students' sources than the whole runs did
    # (Typst keeps what it laid out: a document typeset a second time in one process costs almost nothing)
    sheets = [build_sheet(assignment, Student(f"S{i:05d}", f"Student {i}"), bank, b"benchmark secret, not a real one")
              for i in range(4 * n)]
    try:
        from exgen.figures import draw_figures
        drawn = [(s, draw_figures(s)) for s in sheets]
    except ImportError:  # older versions draw figures inside the renderers
        drawn = [(s, None) for s in sheets]

    def render(fn):
        return (lambda item: fn(item[0], item[1])) if drawn[0][1] is not None else (lambda item: fn(item[0]))

    print(f"{assignment.title}: {len(assignment.questions)} problems, medians of {n} students, in this process "
          f"({allocator()}; run with LD_PRELOAD=libjemalloc.so.2 for what exgen's PDF workers use); {load()}")
    for name in ("key", "sheet"):
        whole = median_ms(render(getattr(pdf, f"{name}_pdf")), drawn[:n])
        sources = [render(getattr(pdf, f"{name}_typst"))(item) for item in drawn[n:]]
        compile_only = median_ms(pdf.compile_pdf, sources)
        print(f"one {name} PDF: {whole[0]:6.1f} ms wall, {whole[1]:6.1f} ms CPU "
              f"(Typst compile alone {compile_only[0]:6.1f} ms wall, {compile_only[1]:6.1f} ms CPU)")
    if "form" in inspect.signature(pdf.sheet_pdf).parameters:
        # one sheet without its form, the next with it, and so on: each pair met the same load on the host,
        # whose speed drifts by a fifth within minutes, so the figure is the median of the pairs' ratios
        walls, cpus = {False: [], True: []}, {False: [], True: []}
        pdf.sheet_pdf(*drawn[2 * n])  # warm
        for i, (sheet, figures) in enumerate(drawn[2 * n + 1:]):  # sheets not typeset before
            form = bool(i % 2)
            wall, cpu = time.perf_counter(), time.process_time()
            pdf.sheet_pdf(sheet, figures, form=form)
            cpus[form].append((time.process_time() - cpu) * 1e3)
            walls[form].append((time.perf_counter() - wall) * 1e3)
        plain, with_form = ((median(walls[f]), median(cpus[f])) for f in (False, True))
        pairs = median(b / a for a, b in zip(cpus[False], cpus[True]))
        print(f"one sheet PDF without its form: {plain[0]:6.1f} ms wall, {plain[1]:6.1f} ms CPU; with it "
              f"{with_form[0]:6.1f} ms wall, {with_form[1]:6.1f} ms CPU (alternate sheets, {len(cpus[True])} "
              f"each): the form adds {100 * (with_form[1] / plain[1] - 1):+.1f} % CPU, "
              f"{100 * (pairs - 1):+.1f} % the median of the pairs")

if __name__ == "__main__":
    main()
