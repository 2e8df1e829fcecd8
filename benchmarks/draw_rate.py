"""Variants drawn and solved per second per core, over every template of the bank.

    python benchmarks/draw_rate.py [SEEDS]

Each template is drawn for SEEDS seeds (default 200) in this one process (make_variant: drawing with
rejection, the solver, the answers and mistake values); the rate is variants per CPU second, so it
is the rate of one core whatever else the machine runs. The templates' own rates, slowest first, follow.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import load  # noqa: E402

from exgen.load.bank import load_bank  # noqa: E402
from exgen.solve.variant import make_variant  # noqa: E402


def main() -> None:
    seeds = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    bank = load_bank()
    rates, total_cpu, total = [], 0.0, 0
    for template in bank:
        make_variant(template, 10**9)  # imports and caches out of the timing
        start = time.process_time()
        for seed in range(seeds):
            make_variant(template, seed)
        cpu = time.process_time() - start
        rates.append((seeds / cpu, template.id))
        total_cpu += cpu
        total += seeds
    print(f"{total} variants of {len(bank)} templates: {total / total_cpu:.0f} variants per CPU second; {load()}")
    for rate, template_id in sorted(rates)[:8]:
        print(f"  {template_id:42s} {rate:8.0f} /s")


if __name__ == "__main__":
    main()
