"""Wall and CPU time of a piece of work, this process's and its finished children's (worker pools).

On a shared machine the wall time depends on what else runs; the CPU time (user + system) much less,
so every benchmark prints both, with the load average it ran under.
"""
from __future__ import annotations

import os
import statistics
import time


class Clock:
    """with Clock() as c: ...  then c.wall, c.cpu (seconds)."""

    def __enter__(self):
        self._wall, self._times = time.perf_counter(), os.times()
        return self

    def __exit__(self, *exc):
        self.wall = time.perf_counter() - self._wall
        now = os.times()
        self.cpu = sum(getattr(now, f) - getattr(self._times, f)
                       for f in ("user", "system", "children_user", "children_system"))
        return False

    def __str__(self) -> str:
        return f"{self.wall:.2f} s wall, {self.cpu:.2f} s CPU"


def median_ms(fn, items, warm: bool = True) -> tuple[float, float]:
    """(median wall, median CPU) of fn(item) over items, in ms; the first item warms caches and is not timed
    again (a PDF typeset a second time in one process is nearly free: Typst keeps what it laid out)."""
    if warm:
        fn(items[0])
        items = items[1:] or items
    walls, cpus = [], []
    for item in items:
        wall, cpu = time.perf_counter(), time.process_time()
        fn(item)
        cpus.append((time.process_time() - cpu) * 1e3)
        walls.append((time.perf_counter() - wall) * 1e3)
    return statistics.median(walls), statistics.median(cpus)


def load() -> str:
    one, five, _ = os.getloadavg()
    return f"load average {one:.2f} (5 min: {five:.2f}) on {os.cpu_count()} cores"


def allocator() -> str:
    """Which malloc this process typesets with: Typst's time depends on it (exgen/runtime/allocator.py)."""
    preloaded = os.environ.get("LD_PRELOAD", "")
    return "jemalloc preloaded" if "jemalloc" in preloaded else "the system's malloc"
