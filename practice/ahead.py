"""Figures drawn ahead: for each template a fresh seed and the figure of its variant, made in another
process while students read and think, so that "another one" waits only for the (quick) solver.

The other process has its own interpreter, so its drawing never holds up a request, and on a machine
with two cores it runs on the other one. It reads each template from its file (the same file the server
loaded); the server rebuilds the variant from the seed, which gives the same numbers, so the figure
fits. Only a cache: what is taken is checked against what the student has met like any other draw.
"""
from __future__ import annotations

import multiprocessing
import os
import threading
from functools import lru_cache
from pathlib import Path

from exgen.draw.seeds import practice_seed
from exgen.load.template import Template
from exgen.runtime.interrupts import held
from exgen.runtime.parallel import watch_parent


@lru_cache(maxsize=512)
def _template(path: str) -> Template:
    from exgen.load.bank import load_template

    return load_template(Path(path))


def draw_figure(path: str, seed: int) -> str | None:
    """In the other process: the figure of the template's variant for this seed."""
    from exgen.figures import figure_svg
    from exgen.solve.variant import make_variant

    return figure_svg(make_variant(_template(path), seed))


class Ahead:
    def __init__(self):
        self._ready: dict[str, tuple[int, dict]] = {}
        self._pending: set[str] = set()
        self._lock = threading.Lock()
        # a spawned daemon: a fresh interpreter (no copy of the server's threads), ended with the server
        with held():  # a worker half started would be one nobody stops
            self._worker = multiprocessing.get_context("spawn").Pool(1, initializer=watch_parent,
                                                                     initargs=(os.getpid(),))
        self._closed = False

    def fill(self, templates) -> None:
        """Draw ahead for each template not yet drawn or being drawn."""
        for template in templates:
            self._schedule(template)

    def take(self, template: Template) -> tuple[int, dict] | None:
        """(seed, what was made for it) drawn ahead for the template, if ready; the next is started."""
        with self._lock:
            ready = self._ready.pop(template.id, None)
        self._schedule(template)
        return ready

    def _schedule(self, template: Template) -> None:
        if template.path is None or not template.figure:
            return  # nothing slow to draw, or no file for the other process to read
        with self._lock:
            if template.id in self._ready or template.id in self._pending:
                return
            self._pending.add(template.id)
        seed = practice_seed()
        try:
            self._worker.apply_async(draw_figure, (str(template.path), seed),
                                     callback=lambda svg: self._done(template.id, seed, svg),
                                     error_callback=lambda _: self._done(template.id, seed, None, failed=True))
        except ValueError:  # closed
            return

    def _done(self, template_id: str, seed: int, svg: str | None, failed: bool = False) -> None:
        with self._lock:
            self._pending.discard(template_id)
            if not failed:  # a draw that failed there fails again, visibly, when drawn for a student
                self._ready[template_id] = (seed, {"figure": svg})

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            self._worker.terminate()
            self._worker.join()
