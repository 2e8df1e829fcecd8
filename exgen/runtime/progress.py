"""Progress of long runs: a bar on a terminal, and periodic lines when the output is a log or a pipe
(a four-minute `generate` under a scheduler or CI says how far it is, not nothing until the end)."""
from __future__ import annotations

import sys
import time
from typing import Callable, Iterable, Iterator, TextIO

#: What a long run reports its work through: (items, total, label) -> the items, as they are worked.
Progress = Callable[[Iterable, int, str], Iterable]

#: Without a terminal: a line each time another tenth is done, and at least every so many seconds,
#: once a run has lasted QUIET_SECONDS (a quick run prints nothing).
STEPS = 10
EVERY_SECONDS = 15.0
QUIET_SECONDS = 2.0


def silent(items: Iterable, total: int, label: str = "") -> Iterable:
    """No report: the library's default (the command line passes `progress`)."""
    return items


def progress(items: Iterable, total: int, label: str = "working", stream: TextIO | None = None) -> Iterable:
    """`items`, reporting progress on `stream` (stderr): tqdm's bar on a terminal, lines otherwise."""
    stream = stream or sys.stderr
    if _is_terminal(stream):
        from tqdm import tqdm

        return tqdm(items, total=total, desc=label, unit="item", leave=False, file=stream)
    return _lines(items, total, label, stream)


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False


def _lines(items: Iterable, total: int, label: str, stream: TextIO, clock=time.monotonic) -> Iterator:
    """Yield the items; once QUIET_SECONDS have passed, print "label: done/total (p %)" at each tenth
    and every EVERY_SECONDS, and at the end a line with the time taken."""
    start = last = clock()
    next_step = 1
    done, spoke = 0, False
    for item in items:
        yield item
        done += 1
        now = clock()
        due = done * STEPS >= next_step * total or now - last >= EVERY_SECONDS
        if due and done < total and now - start >= QUIET_SECONDS:
            print(f"{label}: {done}/{total} ({100 * done // total} %)", file=stream, flush=True)
            last, spoke = now, True
        while next_step * total <= done * STEPS:
            next_step += 1
    if spoke:
        print(f"{label}: {done}/{total} done in {clock() - start:.1f} s", file=stream, flush=True)
