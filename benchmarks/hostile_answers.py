"""How long each answer type takes to refuse hostile text: code, a power tower, 100,000 brackets, a megabyte.

Every registered type reads every case through the one reader a grader uses (exgen.answertypes.read);
the median and the slowest of 20 runs are printed per case, with what the reader said. Nothing here
asserts a time (the slowest run includes whatever else the machine was doing).
"""
import statistics
import sys
import time

from exgen.answertypes import answer_type, names, read
from exgen.errors import FormatProblem, WrongKind

CASES = {
    "code": "__import__('os').system('rm -rf /')",
    "code, no quotes": "__import__(os).system(ls)",
    "lambda": "(lambda: 0)()",
    "power tower": "9^9^9^9",
    "100,000 brackets": "(" * 100_000 + "1" + ")" * 100_000,
    "1 MB": "K*" * 500_000 + "K",
    "long digits": "9" * 10_000,
    "control characters": "1\x00\x1b[2J",
    "deep within limits": "(" * 12 + "1" + ")" * 12,
}
RUNS = 20


def timed(text: str, part) -> tuple[list[float], str]:
    """Each run's time, and what the reader said."""
    times, said = [], ""
    for _ in range(RUNS):
        start = time.perf_counter()
        try:
            read(text, part)
            said = "read"
        except (FormatProblem, WrongKind) as exc:
            said = str(exc)
        times.append(time.perf_counter() - start)
    return times, said


def main() -> int:
    kinds = sys.argv[1:] or list(names())
    overall = (0.0, "")
    print(f"{'':22}{'median':>9} {'slowest':>9}   (ms, {RUNS} runs each)")
    for kind in kinds:
        part = answer_type(kind).sample_part()
        timed("1 kN", part)  # warm up: imports, the unit registry
        print(kind)
        for name, text in CASES.items():
            times, said = timed(text, part)
            overall = max(overall, (max(times), f"{kind}, {name}"))
            print(f"  {name:<20}{statistics.median(times) * 1000:9.3f} {max(times) * 1000:9.3f}   {said[:60]}")
    print(f"slowest of all: {overall[0] * 1000:.3f} ms ({overall[1]})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
