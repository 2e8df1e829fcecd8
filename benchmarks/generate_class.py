"""A class set issued: N students x an assignment's problems, sheets and keys, Markdown + PDF + figures.

    python benchmarks/generate_class.py [N] [ASSIGNMENT] [--jobs J] [--no-key-pdf] [--no-pdf]

N defaults to 500, ASSIGNMENT to benchmarks/class_all.yaml (eight problems, every chapter); --jobs
defaults to one process per core, as `exgen generate` does. Prints wall and CPU time (this process
and its workers) and the load average it ran under. It runs against whichever exgen the Python
running it imports, so an older checkout can be measured with the same script.
"""
from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import Clock, load  # noqa: E402

from exgen.issue.assignment import Student, load_assignment  # noqa: E402
from exgen.issue.generate import default_jobs, generate  # noqa: E402
from exgen.load.bank import load_bank  # noqa: E402

HERE = Path(__file__).parent


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("n", nargs="?", type=int, default=500)
    parser.add_argument("assignment", nargs="?", default=str(HERE / "class_all.yaml"))
    parser.add_argument("--jobs", type=int, default=default_jobs())
    parser.add_argument("--no-key-pdf", action="store_true")
    parser.add_argument("--no-pdf", action="store_true")
    args = parser.parse_args()
    bank = load_bank()
    assignment = load_assignment(Path(args.assignment), bank)
    students = [Student(f"S{i:05d}", f"Student {i}") for i in range(args.n)]
    options = {"pdf": not args.no_pdf, "jobs": args.jobs}
    if args.no_key_pdf:
        options["key_pdf"] = False  # an option older versions lack: they fail here rather than mislead
    what = "Markdown only" if args.no_pdf else ("sheet PDFs, keys in Markdown" if args.no_key_pdf
                                                 else "sheet and key PDFs")
    with tempfile.TemporaryDirectory() as out, Clock() as clock:
        generate(assignment, students, bank, b"benchmark secret, not a real one", Path(out) / "set", **options)
    try:
        from exgen.runtime.allocator import faster_allocator  # an option older versions lack
        workers = faster_allocator() or "the system's malloc"
    except ImportError:
        workers = "the system's malloc"
    print(f"generate {args.n} students x {len(assignment.questions)} problems ({what}, --jobs {args.jobs}): "
          f"{clock}; {clock.wall / args.n * 1e3:.1f} ms/student; PDF workers with {workers}; {load()}")


if __name__ == "__main__":  # worker processes import this file
    main()
