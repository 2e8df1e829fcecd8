"""A faster memory allocator for the processes that typeset PDFs, where the system has one.

Typst is linked against the C library's malloc. Under glibc's, a key spends about a tenth of its time
allocating and freeing, and a process that has typeset a hundred documents typesets a fifth slower than a
fresh one (its heap fragments). With jemalloc the same worker typesets a key about 12 % faster and keeps
its pace: a class set of 500 takes about a sixth less time (benchmarks/README.md). A running process
keeps its allocator, but exgen starts its PDF workers itself: where jemalloc is installed (Debian and
Ubuntu: the libjemalloc2 package) they start with it preloaded. The PDFs are the same bytes either way.

    EXGEN_ALLOCATOR=system          keep the system's allocator
    EXGEN_ALLOCATOR=/path/to/lib.so preload that library instead
"""
from __future__ import annotations

import os
import subprocess
import sys
from contextlib import contextmanager
from functools import lru_cache
from typing import Iterator

SETTING = "EXGEN_ALLOCATOR"
PRELOAD = "LD_PRELOAD"


@lru_cache(maxsize=None)
def faster_allocator() -> str | None:
    """The library to preload into PDF workers, or None: on Linux, jemalloc found on the library path (or
    the library the setting names), used only once a Python has started with it preloaded and said nothing
    (a library built for another page size aborts; one that cannot be found only makes the loader warn)."""
    choice = os.environ.get(SETTING, "").strip()
    if choice == "system" or not sys.platform.startswith("linux"):
        return None
    if not choice:
        from ctypes.util import find_library

        choice = find_library("jemalloc") or ""
    return choice if choice and _starts_with(choice) else None


def _starts_with(library: str) -> bool:
    env = dict(os.environ, **{PRELOAD: _joined(library, os.environ.get(PRELOAD))})
    try:
        done = subprocess.run([sys.executable, "-S", "-c", ""], env=env, capture_output=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return False
    return done.returncode == 0 and not done.stderr


def _joined(library: str, already: str | None) -> str:
    return f"{library}:{already}" if already else library


@contextmanager
def preloaded(library: str | None) -> Iterator[None]:
    """Processes started inside the block start with `library` preloaded; this process's environment is
    as it was afterwards. (A running process is not affected: the loader reads the setting at start.)"""
    if not library:
        yield
        return
    before = os.environ.get(PRELOAD)
    os.environ[PRELOAD] = _joined(library, before)
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(PRELOAD, None)
        else:
            os.environ[PRELOAD] = before
