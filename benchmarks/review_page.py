"""The review page over a simulated class (examples/simulate_class.py: realistic mistakes, blanks and planted
copies): what it lists, how long the list takes to build and to serve, and a decision to write.

    python benchmarks/review_page.py [N]

N students (default 600). Times, as the page's server does them for each request: build_queue over
results.json and the decisions file; GET / (the whole list, every group with its form) and GET / filtered to
one question; POST /decide for the largest group (each of its students' decisions written whole through
graders.decisions), then GET / again with that decision in the file. Wall and CPU, with the load average.
"""
from __future__ import annotations

import importlib.util
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import Clock, load  # noqa: E402
from contextlib import contextmanager  # noqa: E402

from starlette.testclient import TestClient  # noqa: E402

from exgen.runtime.localweb import loopback_hosts  # noqa: E402
from graders.review_page.app import Review, create_app  # noqa: E402

SCRIPT = Path(__file__).parent.parent / "examples" / "simulate_class.py"


@contextmanager
def timed(what: str):
    with Clock() as clock:
        yield
    print(f"{what}: {clock}")


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 600
    spec = importlib.util.spec_from_file_location("simulate_class", SCRIPT)
    simulate = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(simulate)
    print(f"load before: {load()}")
    with tempfile.TemporaryDirectory() as tmp:
        with timed(f"a class of {n} simulated and graded"):
            simulate.simulate(Path(tmp), n, seed=7)
        graded = Path(tmp) / "graded"
        state = Review(graded, Path(tmp) / "decisions.yaml", "A. Lecturer")
        with timed("build_queue (results.json read)"):
            queue = state.queue()
        with timed("build_queue again (results.json cached)"):
            queue = state.queue()
        kinds = {}
        for group in queue.groups:
            kinds[group.kind] = kinds.get(group.kind, 0) + len(group.answers)
        largest = max(queue.groups, key=lambda g: len(g.answers))
        print(f"{queue.answers} answers need a human in {len(queue.groups)} rows ({kinds}); the largest row: "
              f"{len(largest.answers)} students, Q{largest.question} ({largest.part}) {largest.given!r}")
        with TestClient(create_app(state, loopback_hosts(8001)), base_url="http://127.0.0.1:8001") as client:
            with timed("GET / (every row)"):
                page = client.get("/").text
            print(f"the page: {len(page) / 1024:.0f} KiB")
            with timed(f"GET /?question={largest.question}"):
                client.get(f"/?question={largest.question}")
            token = page.split('name="token" value="', 1)[1].split('"', 1)[0]
            form = {"token": token, "group": largest.id, "decision": "reject", "comment": "see me",
                    "reviewer": "A. Lecturer", "reason": "benchmark"}
            with timed(f"POST /decide ({len(largest.answers)} decisions written)"):
                assert client.post("/decide", data=form, follow_redirects=False).status_code == 303
            with timed("GET / with the decisions file"):
                client.get("/")
    print(f"load after: {load()}")


if __name__ == "__main__":
    main()
