"""Work spread over processes, and nothing left running afterwards, however the parent ends.

Processes are spawned, not forked: a forked child can inherit the lock of a thread Typst was running
in the parent, and hang. The shared inputs (bank, assignment, secret) reach each worker once, through
its initializer, not with every task. A spawned pool starts multiprocessing's resource tracker, a
process that outlives the pool; it is stopped here too when this pool was what started it, so a
caller that lives on (a test run, a server) keeps no stray process. Workers that typeset can start
with a faster allocator preloaded (exgen.runtime.allocator).

A worker ends with its parent even when the parent is killed outright (kill -9, which runs no cleanup):
on Linux the kernel kills it at once (PR_SET_PDEATHSIG), and everywhere a thread of the worker's own
sees its parent gone within WATCH_SECONDS and ends it. The resource tracker then ends by itself, its
pipe closed by the last process that held it.
"""
from __future__ import annotations

import gc
import os
import signal
import sys
import threading
import time
from contextlib import contextmanager

from .interrupts import held

_shared: tuple = ()


def shared() -> tuple:
    """In a worker: the arguments its pool was started with."""
    return _shared


#: How often a worker looks whether its parent still runs (where the kernel cannot be asked to tell it).
WATCH_SECONDS = 0.2
_PR_SET_PDEATHSIG = 1


def _set_shared(parent: int, *args) -> None:
    global _shared
    watch_parent(parent)
    _shared = args


def watch_parent(parent: int) -> None:
    """In a worker: end this process as soon as `parent` (the pid that started it) is gone."""
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        except (ImportError, OSError, AttributeError):
            pass
    if os.getppid() != parent:  # gone already, before the watch was set
        os._exit(1)
    threading.Thread(target=_end_with, args=(parent,), name="exgen-parent-watch", daemon=True).start()


def _end_with(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(WATCH_SECONDS)
    os._exit(1)


class _Pool:
    """The executor's map and submit, with Ctrl+C and SIGTERM held while they submit (and so start workers)."""

    def __init__(self, executor):
        self.executor = executor

    def map(self, function, iterable, chunksize: int = 1):
        with held():
            return self.executor.map(function, iterable, chunksize=chunksize)

    def submit(self, function, *args, **kwargs):
        with held():
            return self.executor.submit(function, *args, **kwargs)


@contextmanager
def pool(jobs: int, args: tuple = (), preload: str | None = None):
    """A pool of `jobs` spawned workers whose tasks read `shared()` for `args`, started with the library
    `preload` preloaded if one is given; every worker (and the resource tracker, if this pool started it) has
    ended when the block ends, however it ends."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from multiprocessing import resource_tracker

    from .allocator import preloaded

    tracker = resource_tracker._resource_tracker
    tracker_was_running = getattr(tracker, "_fd", None) is not None
    executor = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn"),
                                   initializer=_set_shared, initargs=(os.getpid(), *args))
    try:
        with preloaded(preload):  # workers are spawned as tasks arrive: any time inside the block
            yield _Pool(executor)
    finally:
        with held():  # a worker half stopped is as lost as one half started
            executor.shutdown(wait=True, cancel_futures=True)
            del executor
            gc.collect()  # the pool's queues release their semaphores (a release would restart the tracker)
            if not tracker_was_running and hasattr(tracker, "_stop"):
                tracker._stop()
