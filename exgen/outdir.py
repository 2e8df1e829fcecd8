"""Output folders that are never half-written: built beside the target, swapped in when complete.

A run writes into a fresh hidden folder next to the target and, only when everything is written,
renames the old folder away, the new one into place, and removes the old. An interrupted run leaves
the old output as it was (and a hidden temporary folder to delete). A folder exgen did not make is
never replaced: it must be empty, or carry the marker file exgen leaves in its outputs.
"""
from __future__ import annotations

import json
import os
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from . import __version__
from .errors import ExgenError

MARKER = ".exgen-output"


class OutputError(ExgenError, OSError):
    """An output folder exgen must not, or cannot, write."""


def is_output(folder: Path) -> bool:
    return (Path(folder) / MARKER).is_file()


def output_kind(folder: Path) -> str | None:
    """What made an exgen output folder ("generate", "grade"), or None if exgen did not."""
    try:
        return json.loads((Path(folder) / MARKER).read_text(encoding="utf-8")).get("kind")
    except (OSError, ValueError, AttributeError):
        return None


def check_target(target: Path, kind: str) -> None:
    """Refuse a target that is a file, a folder exgen did not make, or the output of another command."""
    target = Path(target)
    if target.is_symlink() or (target.exists() and not target.is_dir()):
        raise OutputError(f"{target}: exists and is not a folder; give --out a folder to create or replace")
    if target.is_dir() and any(target.iterdir()):
        made_by = output_kind(target)
        if made_by is None:
            raise OutputError(f"{target}: the folder has files exgen did not write; give --out a new or empty "
                              f"folder (exgen replaces only its own outputs, marked by {MARKER})")
        if made_by != kind:
            raise OutputError(f"{target}: holds the output of `exgen {made_by}`; give `exgen {kind}` another --out")


@contextmanager
def replacing(target: Path, kind: str) -> Iterator[Path]:
    """Yield a fresh folder to write into; on success it becomes `target` (marked as exgen's `kind` output)."""
    target = Path(target)
    check_target(target, kind)
    target.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=f".{target.name}.writing-", dir=target.parent))
    try:
        yield work
        (work / MARKER).write_text(json.dumps({"kind": kind, "exgen": __version__}) + "\n", encoding="utf-8")
        _swap_in(work, target)
    except BaseException:
        shutil.rmtree(work, ignore_errors=True)
        raise


def _swap_in(work: Path, target: Path) -> None:
    """Put `work` where `target` is: two renames on one file system, then the old output is removed."""
    os.chmod(work, 0o755 & ~_umask())
    if not target.exists():
        work.rename(target)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=target.parent))
    old.rmdir()
    target.rename(old)
    try:
        work.rename(target)
    except OSError:
        old.rename(target)  # put the previous output back as it was
        raise
    shutil.rmtree(old, ignore_errors=True)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
