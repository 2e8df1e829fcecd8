"""One key PDF and one sheet PDF: Typst source written from a drawn sheet, then compiled in-process.

    python benchmarks/pdf_times.py [STUDENTS] [ASSIGNMENT]

Medians over STUDENTS (default 20) sheets of ASSIGNMENT (default benchmarks/class_all.yaml): the whole
of key_pdf()/sheet_pdf() given the drawn sheet and its figures, and Typst's compile alone.
"""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import allocator, load, median_ms  # noqa: E402

from exgen.assignment import Student, build_sheet, load_assignment  # noqa: E402
from exgen.bank import load_bank  # noqa: E402
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
              for i in range(2 * n)]
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


if __name__ == "__main__":
    main()
