"""Work spread over processes, and nothing left running afterwards.

Processes are spawned, not forked: a forked child can inherit the lock of a thread Typst was running
in the parent, and hang. The shared inputs (bank, assignment, secret) reach each worker once, through
its initializer, not with every task. A spawned pool starts multiprocessing's resource tracker, a
process that outlives the pool; it is stopped here too when this pool was what started it, so a
caller that lives on (a test run, a server) keeps no stray process. Workers that typeset can start
with a faster allocator preloaded (exgen.allocator).
"""
from __future__ import annotations

import gc
from contextlib import contextmanager

_shared: tuple = ()


def shared() -> tuple:
    """In a worker: the arguments its pool was started with."""
    return _shared


def _set_shared(*args) -> None:
    global _shared
    _shared = args


@contextmanager
def pool(jobs: int, args: tuple = (), preload: str | None = None):
    """A pool of `jobs` spawned workers whose tasks read `shared()` for `args`, started with the library
    `preload` preloaded if one is given; every worker (and the resource tracker, if this pool started it) has
    ended when the block ends."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from multiprocessing import resource_tracker

    from .allocator import preloaded

    tracker = resource_tracker._resource_tracker
    tracker_was_running = getattr(tracker, "_fd", None) is not None
    executor = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn"),
                                   initializer=_set_shared, initargs=args)
    try:
        with preloaded(preload):  # workers are spawned as tasks arrive: any time inside the block
            yield executor
    finally:
        executor.shutdown(wait=True, cancel_futures=True)
        del executor
        gc.collect()  # the pool's queues release their semaphores (a release would restart the tracker)
        if not tracker_was_running and hasattr(tracker, "_stop"):
            tracker._stop()

