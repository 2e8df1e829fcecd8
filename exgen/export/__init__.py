"""Exports to learning systems: a pool of variants per question, written as Moodle XML, an IMS QTI 2.1
package or a Canvas (QTI 1.2) zip. Each answer type says which gaps its part becomes
(exgen.answertypes.lms); each format writes gaps from data layouts in export/templates/."""
from __future__ import annotations

from pathlib import Path
from typing import Callable

from .pool import Pool

FORMATS = ("moodle", "qti", "canvas")


def writer(name: str) -> Callable[[Pool, Path], Path]:
    """The function that writes a pool in format `name` to a file."""
    if name == "moodle":
        from .moodle import write_moodle

        return write_moodle
    if name == "qti":
        from .qti import write_qti

        return write_qti
    from .canvas import write_canvas

    return write_canvas
