"""exgen run as a user runs it, in a process of its own, killed at a chosen moment; and the processes it
leaves behind, found by a mark in their environment (every process exgen starts inherits it).

A test may patch the library in the process before the command runs (`patches`: Python lines), to
lower a threshold or to die at a chosen instant (os.kill(os.getpid(), signal.SIGKILL)).
"""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

MARK = "EXGEN_TEST_PROCESS"
#: Only a hang reaches these, however busy the machine.
RUN_GUARD, GONE_GUARD = 300, 60
DRIVER = "import sys\n{patches}\nfrom exgen.cli import main\nsys.exit(main(sys.argv[1:]))\n"
CAN_LOOK = Path("/proc/self/environ").exists()


@dataclass
class Run:
    process: subprocess.Popen
    mark: str
    log: Path
    started: float

    def kill_at(self, seconds: float, signum: int) -> int | None:
        """Send `signum` `seconds` after the start, if the run still runs; its exit status either way."""
        remaining = seconds - (time.monotonic() - self.started)
        try:
            return self.process.wait(timeout=max(0.0, remaining))
        except subprocess.TimeoutExpired:
            self.process.send_signal(signum)
        return self.process.wait(timeout=RUN_GUARD)

    def finish(self) -> int:
        return self.process.wait(timeout=RUN_GUARD)

    def output(self) -> str:
        return self.log.read_text(encoding="utf-8", errors="replace")


def start(args: list[str], log: Path, patches: str = "", env: dict | None = None) -> Run:
    """`exgen ARGS` in a new process (its stdout and stderr in `log`), marked to be found later."""
    mark = uuid.uuid4().hex
    environment = {**os.environ, **(env or {}), MARK: mark, "PYTHONUNBUFFERED": "1"}
    handle = log.open("wb")
    process = subprocess.Popen([sys.executable, "-c", DRIVER.format(patches=patches), *args], stdout=handle,
                               stderr=subprocess.STDOUT, env=environment, stdin=subprocess.DEVNULL)
    handle.close()
    return Run(process, mark, log, time.monotonic())


def survivors(mark: str) -> list[str]:
    """The command lines of live processes carrying the mark."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            if f"{MARK}={mark}".encode() in (entry / "environ").read_bytes().split(b"\0"):
                state = (entry / "stat").read_text().rsplit(")", 1)[1].split()[0]
                if state != "Z":  # a zombie has ended; only its parent's wait is missing
                    found.append((entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace"))
        except OSError:
            continue
    return found


def left_running(mark: str) -> list[str]:
    """The processes carrying the mark still running once they have had GONE_GUARD seconds to end."""
    deadline = time.monotonic() + GONE_GUARD
    while True:
        alive = survivors(mark)
        if not alive or time.monotonic() > deadline:
            return alive
        time.sleep(0.1)


def snapshot(root: Path) -> dict[str, bytes]:
    """Every file under `root` by its relative path, with its bytes."""
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def beside(folder: Path) -> list[str]:
    """What else lies beside a folder named like it (staging folders of runs)."""
    return sorted(p.name for p in folder.parent.iterdir() if p.name.startswith(f".{folder.name}."))


SIGNALS = {"SIGKILL": signal.SIGKILL, "SIGTERM": signal.SIGTERM}
