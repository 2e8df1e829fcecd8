"""`exgen serve` in a subprocess on a free port, for the tests that need a real server (a browser, raw
sockets): started as a user starts it, its address read from what it prints, stopped after."""
from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

START_SECONDS = 120  # a loaded machine takes a while to import and load the bank


@contextmanager
def running_server(db: Path, *extra: str, output: list | None = None):
    """The server's address; `output`, if given, receives what the server printed, once it has stopped."""
    env = {**os.environ, "PYTHONUNBUFFERED": "1", "PYTHONIOENCODING": "utf-8"}
    process = subprocess.Popen([sys.executable, "-m", "exgen.cli", "serve", "--port", "0", "--db", str(db), *extra],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    try:
        url = _address(process)
        yield url
    finally:
        process.terminate()
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
        rest = process.stdout.read()
        if output is not None:
            output.append(rest)


def _address(process) -> str:
    deadline = time.monotonic() + START_SECONDS
    seen = []
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        if not line:
            if process.poll() is not None:
                raise RuntimeError("exgen serve stopped: " + "".join(seen))
            continue
        seen.append(line)
        found = re.search(r"(http://127\.0\.0\.1:\d+)/", line)
        if found:
            return found.group(1)
    raise RuntimeError("exgen serve did not print its address: " + "".join(seen))
