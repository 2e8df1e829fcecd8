"""How long figures take to draw: every template's sheet figure and key figures, per variant.

    python benchmarks/figures.py [SEEDS]

Prints the median and slowest per template and the mean over all; each figure is drawn once per
student (generate shares it between the folders, the Markdown and the PDFs).
"""
from __future__ import annotations

import statistics
import sys
import time

from exgen.figures import question_figures
from exgen.load.bank import load_bank
from exgen.solve.variant import make_variant


def main(seeds: int = 20) -> None:
    bank = load_bank()
    everything = []
    for template in bank:
        if not (template.figure or template.key_figures):
            continue
        variants = [make_variant(template, seed) for seed in range(seeds)]
        question_figures("q1", variants[0])  # imports and caches out of the timing
        times = []
        for variant in variants:
            start = time.perf_counter()
            question_figures("q1", variant)
            times.append((time.perf_counter() - start) * 1e3)
        everything += times
        print(f"{template.id:42s} median {statistics.median(times):6.2f} ms, max {max(times):6.2f} ms")
    print(f"all {len(everything)} variants: mean {statistics.mean(everything):.2f} ms per question's figures")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 20)
