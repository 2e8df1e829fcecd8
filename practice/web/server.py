"""`exgen serve`: the practice app on this computer, with uvicorn, until Ctrl+C.

The socket is bound and listening before the address is printed or the browser opened, so neither
can race the server. What the first problems would otherwise wait for (imports, compiled texts, figures
drawn ahead) is done meanwhile, in a thread and another process. On loopback (the default) only this
computer can reach the app, and it answers only to its own address.
"""
from __future__ import annotations

import threading
import webbrowser

from exgen.render.mathml import latex_to_mathml
from exgen.runtime.localweb import is_loopback, listen, loopback_hosts, run, url_of
from ..ahead import Ahead
from .app import create_app

__all__ = ["listen", "serve", "url_of"]


def _warm(practice) -> None:
    practice.warm()
    latex_to_mathml(r"\frac{a}{b}")  # the converter's import, before the first worked solution


def serve(practice, host: str = "127.0.0.1", port: int = 8000, open_browser: bool = False,
          announce=print) -> int:
    sock = listen(host, port)
    bound = sock.getsockname()[1]
    # the first problem of each template should not wait for imports and compiled texts: done meanwhile
    threading.Thread(target=_warm, args=(practice,), name="exgen-warm", daemon=True).start()
    practice.ahead = Ahead()
    practice.ahead.fill(practice.catalogue.templates)
    loopback = is_loopback(host)
    app = create_app(practice, loopback_hosts(bound) if loopback else None)
    url = url_of(sock)
    announce(f"exgen practice is at {url}  (progress: {practice.store.path}; Ctrl+C stops it)", flush=True)
    if not loopback:
        announce(f"Listening on {host}: other computers can reach this app.", flush=True)
    if open_browser:
        webbrowser.open(url)
    try:
        run(app, sock)
    finally:
        practice.ahead.close()
    return 0
