"""`exgen review` in a subprocess on a free port, for the tests that need a real server (a browser, raw
sockets): started as a lecturer starts it, its address read from what it prints, stopped after."""
from __future__ import annotations

import os
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

from practice_server import _address


@contextmanager
def running_review(graded: Path, *extra: str, cwd: Path | None = None):
    """The server's address; `cwd`: where the lecturer runs it (paths on the page are as given)."""
    env = {**os.environ, "PYTHONUNBUFFERED": "1", "PYTHONIOENCODING": "utf-8"}
    process = subprocess.Popen([sys.executable, "-m", "exgen.cli", "review", str(graded), "--port", "0", *extra],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, cwd=cwd)
    try:
        yield _address(process)
    finally:
        process.terminate()
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
        process.stdout.close()
