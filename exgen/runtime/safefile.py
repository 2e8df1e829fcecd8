"""Reading a file that may be hostile, or not a file at all: only a regular file is read, the open never
blocks, and the size and time limits cover the open itself.

A named pipe blocks an ordinary open until someone writes to it, and a device may never end; a path
checked first and opened after may have been swapped meanwhile. So the file is opened without blocking,
what was opened is checked (fstat) before a byte is read, its size is the opened file's, and the deadline
starts before the open.
"""
from __future__ import annotations

import codecs
import os
import stat
import time
from pathlib import Path

#: Flags of every open here: never block (a pipe with no writer), never become the terminal's owner.
_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_BINARY", 0)
_CHUNK = 64 * 1024


class UnsafeFile(Exception):
    """A path that is not read: not a regular file, too large, or too slow. `reason` says why in words;
    `kind` is "special", "link", "large" or "slow", and `size` the size found for a large one."""

    def __init__(self, path, reason: str, kind: str = "special", size: int = 0):
        super().__init__(reason)
        self.path, self.reason, self.kind, self.size = Path(path), reason, kind, size


def kind_of(mode: int) -> str:
    """What a file that is not a regular one is, in words."""
    for test, name in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a named pipe"), (stat.S_ISSOCK, "a socket"),
                       (stat.S_ISCHR, "a device"), (stat.S_ISBLK, "a device"), (stat.S_ISLNK, "a symbolic link")):
        if test(mode):
            return name
    return "a special file"


def read_bytes(path: Path, limit: int, deadline: float | None = None, *, follow_links: bool = True) -> bytes:
    """At most `limit` bytes of a regular file, by `deadline` (time.perf_counter()), else UnsafeFile.
    A file larger than `limit` is refused, not cut. OSError for a file that cannot be opened."""
    flags = _FLAGS | (0 if follow_links else getattr(os, "O_NOFOLLOW", 0))
    try:
        fd = os.open(path, flags)
    except OSError as exc:
        if not follow_links and os.path.islink(path):  # O_NOFOLLOW's ELOOP
            raise UnsafeFile(path, "a symbolic link; not followed", "link") from None
        raise
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise UnsafeFile(path, f"{kind_of(info.st_mode)}, not a regular file; not read")
        if info.st_size > limit:
            raise UnsafeFile(path, f"the file is {info.st_size:,} bytes, more than the {_size(limit)} allowed", "large",
                             info.st_size)
        chunks, total = [], 0
        while True:
            _in_time(path, deadline)
            chunk = os.read(fd, min(_CHUNK, limit + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > limit:  # grew since the fstat
                raise UnsafeFile(path, f"the file is larger than the {_size(limit)} allowed", "large", total)
        return b"".join(chunks)
    finally:
        os.close(fd)


def _in_time(path: Path, deadline: float | None) -> None:
    if deadline is not None and time.perf_counter() > deadline:
        raise UnsafeFile(path, "the file took too long to read (opening it included)", "slow")


def _size(limit: int) -> str:
    return f"{limit // (1024 * 1024)} MiB" if limit % (1024 * 1024) == 0 else f"{limit // 1024} KiB"


class Unreadable(Exception):
    """A file whose text cannot be had: missing, not a regular file, too large or slow, not readable, or not
    text. `reason` says why in words; `line` and `column`, where known, the place of the first bad byte."""

    def __init__(self, reason: str, line: int | None = None, column: int | None = None, missing: bool = False):
        super().__init__(reason)
        self.reason, self.line, self.column, self.missing = reason, line, column, missing


class NotText(Unreadable):
    """Bytes that are no text exgen reads (`raw`, bad from `offset`)."""

    def __init__(self, reason: str, raw: bytes, offset: int):
        line = raw[:offset].count(b"\n") + 1
        super().__init__(reason, line, offset - (raw.rfind(b"\n", 0, offset) + 1) + 1)
        self.raw, self.offset = raw, offset


def read_text(path: Path, limit: int, seconds: float) -> str:
    """The text of a regular file of at most `limit` bytes, read within `seconds` (see read_bytes and
    decoded); Unreadable says why not."""
    try:
        raw = read_bytes(path, limit, time.perf_counter() + seconds)
    except FileNotFoundError:
        raise Unreadable("no such file", missing=True) from None
    except UnsafeFile as exc:
        raise Unreadable(exc.reason) from None
    except OSError as exc:
        raise Unreadable(exc.strerror or str(exc)) from None
    return decoded(raw)


def decoded(raw: bytes) -> str:
    """Text from a file's bytes: UTF-8 (its byte-order mark dropped), or UTF-16 with its byte-order mark;
    NotText for anything else (a NUL byte: UTF-16 without its mark, or no text at all)."""
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return raw.decode("utf-16")
        except UnicodeDecodeError as exc:
            raise NotText("not valid UTF-16 text", raw, exc.start) from None
    if b"\x00" in raw:
        raise NotText("holds NUL bytes: UTF-16 text without its byte-order mark, or not text at all", raw,
                      raw.index(b"\x00"))
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise NotText(f"not UTF-8 text (the byte 0x{raw[exc.start]:02x})", raw, exc.start) from None
