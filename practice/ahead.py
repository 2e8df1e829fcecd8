"""Problems drawn ahead: one fresh variant per template, with its figure, made in a background thread
while students read and think, so that "another one" waits for neither the draw nor the drawing.

Only a cache: a variant is taken once, checked against what the student has met like any other, and
its template's next one is drawn at once. The web server uses it; the terminal does not need it.
"""
from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor

from exgen.figures import figure_svg
from exgen.seeds import practice_seed
from exgen.template import Template
from exgen.variant import Variant, make_variant


class Ahead:
    def __init__(self):
        self._ready: dict[str, tuple[int, Variant, dict]] = {}
        self._pending: set[str] = set()
        self._lock = threading.Lock()
        self._worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="exgen-ahead")

    def fill(self, templates) -> None:
        """Draw one ahead for each template not yet drawn or being drawn."""
        for template in templates:
            self._schedule(template)

    def take(self, template: Template) -> tuple[int, Variant, dict] | None:
        """The variant drawn ahead for the template, if ready (seed, variant, what was made with it);
        its replacement is drawn in the background."""
        with self._lock:
            ready = self._ready.pop(template.id, None)
        self._schedule(template)
        return ready

    def _schedule(self, template: Template) -> None:
        with self._lock:
            if template.id in self._ready or template.id in self._pending:
                return
            self._pending.add(template.id)
        self._worker.submit(self._draw, template)

    def _draw(self, template: Template) -> None:
        try:
            seed = practice_seed()
            variant = make_variant(template, seed)
            made = {"figure": figure_svg(variant)}
            with self._lock:
                self._ready[template.id] = (seed, variant, made)
        except Exception:  # a draw that fails here fails again, visibly, when drawn for a student
            pass
        finally:
            with self._lock:
                self._pending.discard(template.id)

    def close(self) -> None:
        self._worker.shutdown(wait=False, cancel_futures=True)
