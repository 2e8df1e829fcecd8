"""Ctrl+C and SIGTERM while a command runs: raised where the program is (KeyboardInterrupt, and
Terminated for SIGTERM, so that both unwind alike and remove what was being written), except inside a
`held()` block, where the first waits until the block ends (a second is raised at once).

A pool starting or stopping its workers holds them: an exception raised in the middle of starting a
process leaves a worker the pool does not know of, which nobody ever stops (and whose parent then waits
for it for ever).
"""
from __future__ import annotations

import signal
from contextlib import contextmanager
from typing import Iterator


class Terminated(KeyboardInterrupt):
    """SIGTERM (a `timeout`, a cancelled CI job), taken like Ctrl+C."""


_held = 0
_pending: type[KeyboardInterrupt] | None = None


@contextmanager
def held() -> Iterator[None]:
    """Ctrl+C and SIGTERM arriving inside the block are raised when it ends."""
    global _held, _pending
    _held += 1
    try:
        yield
    finally:
        _held -= 1
        pending, _pending = (_pending, None) if _held == 0 else (None, _pending)
        if pending is not None:
            raise pending()


def _raise(signum, frame) -> None:
    """Raise the interrupt, or keep it for the end of the held block; a second one while held is raised at
    once (a pool that never finishes stopping can still be interrupted)."""
    global _pending
    interrupt = Terminated if signum == signal.SIGTERM else KeyboardInterrupt
    if _held and _pending is None:
        _pending = interrupt
        return
    _pending = None
    raise interrupt()


@contextmanager
def handled() -> Iterator[None]:
    """For the duration of the block (in the main thread; elsewhere nothing changes): SIGINT and SIGTERM
    raise KeyboardInterrupt and Terminated, or wait while held."""
    previous = {}
    try:
        for signum in (signal.SIGINT, signal.SIGTERM):
            previous[signum] = signal.signal(signum, _raise)
    except (ValueError, OSError):  # not the main thread
        pass
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
