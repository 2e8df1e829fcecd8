"""Cold start of the commands that should stay light: `exgen --version`, `exgen list`, `exgen show`.

    python benchmarks/cold_start.py [RUNS] [EXGEN]

Each command runs RUNS times (default 9) as a new process, after one run that is not timed; prints the
median wall time and the median CPU time (user + system) of the process. EXGEN is the command to time
(default: the exgen beside the Python running this script), so an older checkout's venv can be measured
the same way. The commands may write Python's bytecode cache, as they do for a user: with
PYTHONDONTWRITEBYTECODE set, every run would compile exgen's modules from source again.
"""
from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import load  # noqa: E402

COMMANDS = (["--version"], ["list"], ["show", "belts.flat_belt_power", "--seed", "1"])


ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def timed(command: list[str]) -> tuple[float, float]:
    before = os.times()
    start = time.perf_counter()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, env=ENV)
    wall = time.perf_counter() - start
    after = os.times()
    return wall, (after.children_user - before.children_user) + (after.children_system - before.children_system)


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 9
    exgen = sys.argv[2] if len(sys.argv) > 2 else str(Path(sys.executable).parent / "exgen")
    print(f"{exgen}, median of {runs} runs; {load()}")
    for args in COMMANDS:
        timed([exgen, *args])  # caches written (bytecode), not timed
        walls, cpus = zip(*(timed([exgen, *args]) for _ in range(runs)))
        print(f"exgen {' '.join(args):36s} {statistics.median(walls) * 1e3:6.0f} ms wall, "
              f"{statistics.median(cpus) * 1e3:6.0f} ms CPU")


if __name__ == "__main__":
    main()
