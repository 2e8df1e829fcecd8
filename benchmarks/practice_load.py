"""Load on `exgen serve`: simulated students practising at once on loopback, with latency percentiles.

    .venv/bin/python benchmarks/practice_load.py [--students 20] [--seconds 60] [--think 1-3] [--workers 1]

Starts `exgen serve` on a free port with a fresh progress file, lets it settle (it draws a problem per
template ahead), then runs the students for the given time; they arrive over their first pause, then
each runs a loop: "new variant" (POST /next and GET the problem page it redirects to: what a
student waits for), then for each part a pause (the think time, seconds, uniform in the range; 0 for
none: a stress test) and "check answer" (POST the part's answer, the JSON feedback back). Answers
are wrong numbers in the asked unit (the grader's slowest path: error carried forward and every named
mistake tried); one problem in ten also asks for a hint and one in ten for the worked solution. Prints
p50/p95/p99 per kind of request, the count, the errors, and the machine's load average before and after.
Asserts nothing: the figures depend on the machine and on what else runs on it.
"""
from __future__ import annotations

import argparse
import asyncio
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from practice_server import _address  # noqa: E402  the tests' way of starting a server and reading its address

PART = re.compile(rb'name="part" value="([^"]+)"')


class Client:
    """A minimal keep-alive HTTP/1.1 client on asyncio streams (one connection per student)."""

    def __init__(self, host: str, port: int):
        self.host, self.port, self.reader, self.writer = host, port, None, None

    async def request(self, method: str, path: str, body: bytes = b"", json: bool = False) -> tuple[int, dict, bytes]:
        if self.writer is None:
            self.reader, self.writer = await asyncio.open_connection(self.host, self.port)
        head = [f"{method} {path} HTTP/1.1", f"Host: {self.host}:{self.port}", "Connection: keep-alive"]
        if body or method == "POST":
            head += ["Content-Type: application/x-www-form-urlencoded", f"Content-Length: {len(body)}"]
        if json:
            head.append("Accept: application/json")
        self.writer.write(("\r\n".join(head) + "\r\n\r\n").encode() + body)
        await self.writer.drain()
        status_line = await self.reader.readline()
        status = int(status_line.split()[1])
        headers = {}
        while (line := await self.reader.readline()) not in (b"\r\n", b""):
            name, _, value = line.decode("latin-1").partition(":")
            headers[name.strip().lower()] = value.strip()
        payload = await self.reader.readexactly(int(headers.get("content-length", "0")))
        if headers.get("connection", "").lower() == "close":
            self.writer.close()
            self.writer = None
        return status, headers, payload

    def close(self):
        if self.writer is not None:
            self.writer.close()


async def student(number: int, host: str, port: int, until: float, think: tuple[float, float],
                  timings: dict[str, list[float]], errors: list[str]):
    rng = random.Random(number)
    client = Client(host, port)
    scopes = ["all", "chapter:1", "chapter:2", "chapter:3", "chapter:5", "chapter:6", "chapter:7", "topic:gears"]

    async def timed(kind, *args, **kwargs):
        start = time.perf_counter()
        result = await client.request(*args, **kwargs)
        timings.setdefault(kind, []).append(time.perf_counter() - start)
        if result[0] >= 400:
            errors.append(f"{kind}: {result[0]} {result[2][:120]!r}")
        return result

    async def pause():
        if think[1] > 0:
            await asyncio.sleep(rng.uniform(*think))

    try:
        await asyncio.sleep(rng.uniform(0, think[1]))  # students arrive over the first pause, not in one instant
        while time.perf_counter() < until:
            start = time.perf_counter()
            status, headers, _ = await client.request("POST", "/next", f"scope={rng.choice(scopes)}".encode())
            if status != 303:
                errors.append(f"new variant: {status}")
                await asyncio.sleep(0.5)
                continue
            path = headers["location"]
            status, _, page = await client.request("GET", path)
            timings.setdefault("new variant", []).append(time.perf_counter() - start)
            parts = [p.decode() for p in PART.findall(page)]
            if rng.random() < 0.1 and parts:
                await pause()
                await timed("hint", "POST", f"{path}/hint", f"part={parts[0]}".encode(), json=True)
            for part in parts:
                if time.perf_counter() >= until:
                    break
                await pause()
                answer = f"{rng.uniform(0.5, 900):.4g}"
                await timed("check answer", "POST", f"{path}/check", f"part={part}&answer={answer}".encode(), json=True)
            if rng.random() < 0.1:
                await timed("worked solution", "POST", f"{path}/solution", json=True)
            await pause()
    except (ConnectionError, asyncio.IncompleteReadError) as exc:
        errors.append(f"student {number}: {exc!r}")
    finally:
        client.close()


def percentiles(values: list[float]) -> str:
    if len(values) < 2:
        return "too few"
    q = statistics.quantiles(values, n=100, method="inclusive")
    return f"p50 {q[49] * 1e3:7.1f} ms   p95 {q[94] * 1e3:7.1f} ms   p99 {q[98] * 1e3:7.1f} ms"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--think", default="1-3", help="seconds between a student's requests, as LOW-HIGH (0: none)")
    parser.add_argument("--settle", type=float, default=10.0,
                        help="seconds to wait after the server starts (it draws a problem per template ahead)")
    args = parser.parse_args()
    low, _, high = args.think.partition("-")
    think = (float(low), float(high or low))

    db = Path(tempfile.mkdtemp(prefix="exgen-load-")) / "progress.sqlite3"
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    server = subprocess.Popen([sys.executable, "-m", "exgen.cli", "serve", "--port", "0", "--db", str(db)],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    try:
        url = _address(server)
        host, port = url.removeprefix("http://").split(":")
        time.sleep(args.settle)
        load_before = os.getloadavg()
        timings: dict[str, list[float]] = {}
        errors: list[str] = []

        async def run():
            until = time.perf_counter() + args.seconds
            await asyncio.gather(*(student(i, host, int(port), until, think, timings, errors)
                                   for i in range(args.students)))

        started = time.perf_counter()
        asyncio.run(run())
        elapsed = time.perf_counter() - started
        load_after = os.getloadavg()
    finally:
        server.terminate()
        server.wait(timeout=30)
    print(f"{args.students} students, {elapsed:.0f} s, think time {args.think} s, {os.cpu_count()} cores")
    print(f"load average before {load_before[0]:.2f}, after {load_after[0]:.2f} (1 min)")
    for kind in ("new variant", "check answer", "hint", "worked solution"):
        values = timings.get(kind, [])
        print(f"  {kind:<16} n={len(values):5d}  {percentiles(values)}")
    total = sum(len(v) for v in timings.values())
    print(f"  {total / elapsed:.1f} timed requests/s; errors: {len(errors)}")
    for error in errors[:5]:
        print(f"    {error}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
