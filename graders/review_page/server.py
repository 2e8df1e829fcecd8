"""`exgen review`: the review page on this computer, with uvicorn, until Ctrl+C. It lists students' work
and writes the decisions file, so it listens on a loopback address only and answers only to that
address: another computer can neither reach it nor, through a web page, make a browser here write."""
from __future__ import annotations

import webbrowser
from pathlib import Path

from exgen.errors import ExgenError
from exgen.runtime.localweb import LOOPBACK_HOSTS, is_loopback, listen, loopback_hosts, run, url_of

from ..decisions import default_path
from .app import Review, create_app

NOT_LOCAL = ("exgen review listens on this computer only (--host {allowed}): the page shows students' answers "
             "and writes the decisions file; {host} is not a loopback address")


def review(graded: Path, decisions: Path | None = None, host: str = "127.0.0.1", port: int = 8001,
           open_browser: bool = False, reviewer: str = "", bank=None, announce=print) -> int:
    """Serve the review page of `graded` until Ctrl+C; `bank` (or a function loading it) checks what a
    spelling is accepted as."""
    if not is_loopback(host):
        raise ExgenError(NOT_LOCAL.format(allowed=", ".join(LOOPBACK_HOSTS), host=host))
    graded = Path(graded)
    state = Review(graded, Path(decisions) if decisions else default_path(graded), reviewer, bank)
    queue = state.queue()  # results.json and the decisions file are read now: a problem is one line, before listening
    sock = listen(host, port, command="review")
    app = create_app(state, loopback_hosts(sock.getsockname()[1]))
    url = url_of(sock)
    announce(f"exgen review is at {url}  ({queue.open_answers} of {queue.answers} answer(s) to decide; decisions: "
             f"{state.decisions_path}; Ctrl+C stops it)", flush=True)
    if open_browser:
        webbrowser.open(url)
    run(app, sock)
    return 0
