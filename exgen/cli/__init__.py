"""The `exgen` command: parses arguments, calls the library, prints. Errors meant for the user
are printed as one message (no traceback) with exit status 1. SIGTERM (a `timeout`, a CI job cancelled)
is taken like Ctrl+C: what was being written is removed, the workers end, and the status is 143."""
from __future__ import annotations

import os
import signal
import sys

from ..errors import ExgenError
from ..runtime.interrupts import Terminated, handled
from .commands import solution_json
from .parser import build_parser

__all__ = ["build_parser", "main", "solution_json"]


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        with handled():
            status = args.func(args)
        sys.stdout.flush()  # a reader that went away (`exgen list | head`) shows here, not at exit
        return status
    except Terminated:
        print("exgen: terminated", file=sys.stderr)
        return 128 + signal.SIGTERM
    except BrokenPipeError:
        return _reader_gone()
    except ExgenError as exc:
        print(f"exgen: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:  # a folder or file the system refuses: say which, and why
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"exgen: {where}{exc.strerror or exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("exgen: interrupted", file=sys.stderr)
        return 130


def _reader_gone() -> int:
    """The program reading our output closed it: stop quietly, as `yes | head` does, with the status a
    shell gives a process that SIGPIPE ended. Output still buffered goes nowhere instead of raising again
    when the interpreter flushes it at exit."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError):  # stdout is no file (captured, replaced): nothing is flushed to it at exit
        pass
    return 128 + 13  # 128 + SIGPIPE
