"""How the answer readers of every type fare on the fuzz strategies: inputs run and the slowest one.

    .venv/bin/python benchmarks/fuzz.py [EXAMPLES_PER_STRATEGY]   (default: the counts CI runs)

Runs the strategies of tests/fuzz_inputs.py through the same judge as tests/test_fuzz.py (every
registered answer type reads the text, then the grader's comparison and feedback), timing each input;
the slowest of each strategy is timed again (best of three, caches warm) to tell its cost from a busy
machine's noise.
"""
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from exgen.errors import SubmissionError  # noqa: E402
from fuzz_inputs import answer_file, long_text, quantity_text, shaped_text  # noqa: E402
from graders.answers import read_submission  # noqa: E402
from test_fuzz import COUNTS, FUZZ, judge  # noqa: E402

STRATEGIES = {"any": st.text(max_size=200), "quantity": quantity_text(), "shaped": shaped_text(),
              "long": long_text(), "files": None}


def run(name: str, strategy, count: int) -> list[tuple[float, str]]:
    timings = []

    @settings(max_examples=count, database=None, **FUZZ)
    @given(strategy)
    def one(text):
        start = time.perf_counter()
        judge(text)
        timings.append((time.perf_counter() - start, text))

    one()
    return timings


def run_files(count: int) -> list[tuple[float, str]]:
    """Answer files: read as grading reads them, then every answer judged."""
    folder, timings = Path(tempfile.mkdtemp()), []

    @settings(max_examples=count, database=None, **FUZZ)
    @given(answer_file())
    def one(suffix_bytes):
        suffix, data = suffix_bytes
        path = folder / f"s001{suffix}"
        path.write_bytes(data)
        start = time.perf_counter()
        try:
            for parts in read_submission(path).answers.values():
                for text in parts.values():
                    judge(text)
        except SubmissionError:
            pass
        timings.append((time.perf_counter() - start, data.decode("utf-8", "replace")))

    one()
    return timings


def retimed(text: str) -> float:
    """Best of three: a shared machine's scheduling is not the reader's cost."""
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        judge(text)
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    judge("5 N")  # units and registries loaded once, outside the timings
    total, worst_overall = 0, (0.0, "")
    for name in STRATEGIES:
        count = int(sys.argv[1]) if len(sys.argv) > 1 else COUNTS[name]
        timings = run_files(count) if name == "files" else run(name, STRATEGIES[name], count)
        total += len(timings)
        mean = sum(t for t, _ in timings) / len(timings)
        worst = max(timings)
        worst_overall = max(worst_overall, worst)
        again = "" if name == "files" else f", {retimed(worst[1]) * 1e3:.1f} ms timed again"
        print(f"{name:9} {len(timings):6} inputs x {len(judge('1'))} types: mean {mean * 1e3:5.2f} ms, slowest "
              f"{worst[0] * 1e3:6.1f} ms{again} ({len(worst[1])} chars: {worst[1][:32]!r})")
    print(f"total {total} inputs; slowest {worst_overall[0] * 1e3:.1f} ms "
          f"({len(worst_overall[1])} chars: {worst_overall[1][:40]!r})")


if __name__ == "__main__":
    main()
