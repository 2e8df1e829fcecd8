"""How the answer readers of every type fare on the fuzz strategies: inputs run and the slowest one.

    .venv/bin/python benchmarks/fuzz.py [EXAMPLES_PER_STRATEGY]   (default: the counts CI runs)

Runs the strategies of tests/fuzz_inputs.py through the same judge as tests/test_fuzz.py (every
registered answer type reads the text, then the grader's comparison and feedback), timing each input.
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from fuzz_inputs import long_text, quantity_text, shaped_text  # noqa: E402
from test_fuzz import COUNTS, FUZZ, judge  # noqa: E402

STRATEGIES = {"any": st.text(max_size=200), "quantity": quantity_text(), "shaped": shaped_text(),
              "long": long_text()}


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


def main() -> None:
    judge("5 N")  # units and registries loaded once, outside the timings
    total, slowest = 0, (0.0, "")
    for name, strategy in STRATEGIES.items():
        count = int(sys.argv[1]) if len(sys.argv) > 1 else COUNTS[name]
        timings = run(name, strategy, count)
        worst = max(timings)
        total += len(timings)
        slowest = max(slowest, worst)
        mean = sum(t for t, _ in timings) / len(timings)
        print(f"{name:9} {len(timings):6} inputs x {len(judge('1'))} types: mean {mean * 1e3:6.2f} ms, "
              f"slowest {worst[0] * 1e3:7.1f} ms ({len(worst[1])} chars: {worst[1][:40]!r})")
    print(f"total {total} inputs; slowest {slowest[0] * 1e3:.1f} ms ({len(slowest[1])} chars: {slowest[1][:40]!r})")


if __name__ == "__main__":
    main()
