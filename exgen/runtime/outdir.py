"""Output folders that are never half-written: built beside the target, swapped in when complete.

A run writes into a fresh hidden folder next to the target, `.NAME.writing-PID-XXXX`, and only when
everything is written swaps it in. Where the system can exchange two folders in one step (Linux's
renameat2, macOS's renamex_np) it does, so at every instant the target is the old output or the new
one; elsewhere the old output is first renamed `.NAME.old-PID-XXXX`, and a run killed between the two
renames is recovered by the next run, or by a reader (`recover`), which puts the old output back. The
process id in both names tells a folder of a run still going from one an interrupted run left:
`tidy` removes those, and names those it cannot tell. A folder exgen did not make is never replaced: it
must be empty, or carry the marker file exgen leaves in its outputs.
"""
from __future__ import annotations

import errno
import json
import os
import re
import shutil
import socket
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from .. import __version__
from ..errors import ExgenError

MARKER = ".exgen-output"
#: In a folder being written: which process on which host writes it.
WRITER = ".exgen-writer"
WRITING, OLD = "writing", "old"

REMOVED = "removed {folder}, left by an interrupted run (process {pid}, no longer running)"
RESTORED = "put {target} back from {folder}: an interrupted run had moved it aside to swap in its output"
RUNNING = "{folder} is being written by process {pid}, still running (another exgen?); left as it is"
ELSEWHERE = "{folder} is being written, or was left, by exgen on {host}; delete it if no exgen runs there"
EARLIER = "{folder} was left by an interrupted run of an earlier exgen; delete it if no exgen is running"


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
    tidy(target)
    check_target(target, kind)
    target.parent.mkdir(parents=True, exist_ok=True)
    work = _staging(target, WRITING)
    try:
        (work / WRITER).write_text(json.dumps({"pid": os.getpid(), "host": _host()}) + "\n", encoding="utf-8")
        yield work
        (work / WRITER).unlink()
        (work / MARKER).write_text(json.dumps({"kind": kind, "exgen": __version__}) + "\n", encoding="utf-8")
        _swap_in(work, target)
    except BaseException:
        shutil.rmtree(work, ignore_errors=True)
        raise


def _staging(target: Path, role: str) -> Path:
    """A new hidden folder beside `target` whose name carries this process's id."""
    return Path(tempfile.mkdtemp(prefix=f".{target.name}.{role}-{os.getpid()}-", dir=target.parent))


def _swap_in(work: Path, target: Path) -> None:
    """Put `work` where `target` is, the old output then removed: in one exchange where the system has
    one, else in two renames that `recover` can undo if the run dies between them."""
    os.chmod(work, 0o755 & ~_umask())
    if not target.exists():
        work.rename(target)
        return
    if _exchange(work, target):
        shutil.rmtree(work, ignore_errors=True)  # the old output, now under the staging name
        return
    old = _staging(target, OLD)
    old.rmdir()
    _set_aside(target, old)
    try:
        _put_in_place(work, target)
    except OSError:
        old.rename(target)  # put the previous output back as it was
        raise
    shutil.rmtree(old, ignore_errors=True)


def _set_aside(target: Path, old: Path) -> None:
    target.rename(old)


def _put_in_place(work: Path, target: Path) -> None:
    work.rename(target)


def _exchange(a: Path, b: Path) -> bool:
    """Swap two folders in one step; False where the system or the file system cannot."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
    except (ImportError, OSError):
        return False
    if sys.platform.startswith("linux") and hasattr(libc, "renameat2"):
        at_cwd, rename_exchange = -100, 2
        done = libc.renameat2(at_cwd, os.fsencode(a), at_cwd, os.fsencode(b), rename_exchange)
    elif sys.platform == "darwin" and hasattr(libc, "renamex_np"):
        rename_swap = 2
        done = libc.renamex_np(os.fsencode(a), os.fsencode(b), rename_swap)
    else:
        return False
    if done == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.EINVAL, errno.ENOSYS, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EXDEV):
        return False
    raise OSError(code, os.strerror(code), str(b))


def recover(target: Path) -> Path | None:
    """Put back an output an interrupted swap had moved aside (`target` missing, its `.old-` folder left by
    a process no longer running); the folder it came from, if it did. Readers of an output call this
    before giving up on it."""
    target = Path(target)
    if target.exists() or not target.parent.is_dir():
        return None
    aside = [p for p in _leftovers(target, OLD) if _state(p, target, OLD)[0] == "gone" and is_output(p)]
    if not aside:
        return None
    newest = max(aside, key=lambda p: (p / MARKER).stat().st_mtime)
    try:
        newest.rename(target)
    except OSError:
        return None
    return newest


def tidy(target: Path) -> list[str]:
    """Recover an output an interrupted swap left aside, remove the folders interrupted runs left beside
    `target`, and say (one sentence each) what was done and which folders are left, and why."""
    target = Path(target)
    notes = []
    restored = recover(target)
    if restored is not None:
        notes.append(RESTORED.format(target=target, folder=restored))
    for role in (WRITING, OLD):
        for folder in _leftovers(target, role):
            notes += _tidied(folder, *_state(folder, target, role))
    return notes


def _tidied(folder: Path, state: str, detail: str) -> list[str]:
    """Remove a folder an interrupted run left; say what was done with it, or why it is left."""
    if state == "gone":
        shutil.rmtree(folder, ignore_errors=True)
        return [REMOVED.format(folder=folder, pid=detail)]
    if state == "running":
        return [RUNNING.format(folder=folder, pid=detail)]
    if state == "elsewhere":
        return [ELSEWHERE.format(folder=folder, host=detail)]
    return [EARLIER.format(folder=folder)]


def _leftovers(target: Path, role: str) -> list[Path]:
    prefix = f".{target.name}.{role}-"
    try:
        return sorted(p for p in target.parent.iterdir() if p.name.startswith(prefix) and p.is_dir()
                      and not p.is_symlink())
    except OSError:
        return []


_PID = re.compile(r"(\d+)-[A-Za-z0-9_]+\Z")


def _state(folder: Path, target: Path, role: str) -> tuple[str, str]:
    """("gone", pid) for a folder whose writer no longer runs on this host; ("running", pid),
    ("elsewhere", host) or ("earlier", "") for one this cannot tell is abandoned."""
    found = _PID.fullmatch(folder.name[len(f".{target.name}.{role}-"):])
    if not found:
        return "earlier", ""
    pid = int(found.group(1))
    try:
        host = json.loads((folder / WRITER).read_text(encoding="utf-8")).get("host", _host())
    except (OSError, ValueError, AttributeError):
        host = _host()  # finished writing, or killed before its first file: this host's, by its name
    if host != _host():
        return "elsewhere", str(host)
    return ("running" if _alive(pid) else "gone"), str(pid)


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    if os.name == "nt":  # os.kill would end the process: a folder on Windows is never taken as abandoned
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process: alive
        return True
    return True


def _host() -> str:
    return socket.gethostname()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
