"""Reading every hostile file of the corpus (tests/hostile/): time per file, the slowest ones.

    .venv/bin/python benchmarks/hostile.py

Each file is read the way grading reads it (graders.answers.read_submission), best of three runs.
"""
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))

import hostile  # noqa: E402
from exgen.errors import SubmissionError  # noqa: E402
from graders.answers import read_submission  # noqa: E402


def main() -> None:
    folder = Path(tempfile.mkdtemp())
    rows = []
    for name, data in hostile.files().items():
        path = folder / name
        path.write_bytes(data)
        best, outcome = float("inf"), ""
        for _ in range(3):
            start = time.perf_counter()
            try:
                read_submission(path)
                outcome = "read"
            except SubmissionError as exc:
                outcome = exc.detail
            best = min(best, time.perf_counter() - start)
        rows.append((best, name, len(data), outcome))
    rows.sort(reverse=True)
    print(f"{len(rows)} hostile files, {sum(r[2] for r in rows) / 1024:.0f} KiB in all; "
          f"total {sum(r[0] for r in rows) * 1e3:.0f} ms")
    for seconds, name, size, outcome in rows[:8]:
        print(f"  {seconds * 1e3:7.1f} ms  {name:24} {size:7} bytes  {outcome[:60]}")


if __name__ == "__main__":
    main()
