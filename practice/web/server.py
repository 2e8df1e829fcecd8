"""`exgen serve`: the practice app on this computer, with uvicorn, until Ctrl+C.

The socket is bound and listening before the address is printed or the browser opened, so neither
can race the server. What the first problems would otherwise wait for (imports, compiled texts, figures
drawn ahead) is done meanwhile, in a thread and another process. On loopback (the default) only this
computer can reach the app, and it answers only to its own address.
"""
from __future__ import annotations

import socket
import sys
import threading
import webbrowser

from exgen.errors import ExgenError
from exgen.render.mathml import latex_to_mathml
from ..ahead import Ahead
from .app import create_app, loopback_hosts

PORT_IN_USE = "port {port} on {host} is in use (another exgen serve?); give another with --port, or --port 0 for any free one"
CANNOT_BIND = "cannot listen on {host}:{port}: {reason}"


def listen(host: str, port: int) -> socket.socket:
    """A listening TCP socket on host:port (port 0: a free one)."""
    try:
        family, kind, proto, _, address = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0]
    except socket.gaierror as exc:
        raise ExgenError(CANNOT_BIND.format(host=host, port=port, reason=exc.strerror)) from None
    sock = socket.socket(family, kind, proto)
    try:
        if sys.platform != "win32":
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(address)
        sock.listen(128)
    except OSError as exc:
        sock.close()
        if exc.errno in (48, 98, 10048):  # EADDRINUSE on macOS, Linux, Windows
            raise ExgenError(PORT_IN_USE.format(port=port, host=host)) from None
        raise ExgenError(CANNOT_BIND.format(host=host, port=port, reason=exc.strerror or exc)) from None
    sock.set_inheritable(True)
    return sock


def url_of(sock: socket.socket) -> str:
    host, port = sock.getsockname()[:2]
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/"


def _warm(practice) -> None:
    practice.warm()
    latex_to_mathml(r"\frac{a}{b}")  # the converter's import, before the first worked solution


def serve(practice, host: str = "127.0.0.1", port: int = 8000, open_browser: bool = False,
          announce=print) -> int:
    import uvicorn

    sock = listen(host, port)
    bound = sock.getsockname()[1]
    # the first problem of each template should not wait for imports and compiled texts: done meanwhile
    threading.Thread(target=_warm, args=(practice,), name="exgen-warm", daemon=True).start()
    practice.ahead = Ahead()
    practice.ahead.fill(practice.catalogue.templates)
    loopback = host in ("127.0.0.1", "localhost", "::1")
    app = create_app(practice, loopback_hosts(bound) if loopback else None)
    url = url_of(sock)
    announce(f"exgen practice is at {url}  (progress: {practice.store.path}; Ctrl+C stops it)", flush=True)
    if not loopback:
        announce(f"Listening on {host}: other computers can reach this app.", flush=True)
    if open_browser:
        webbrowser.open(url)
    config = uvicorn.Config(app, log_level="warning", access_log=False, server_header=False, date_header=False,
                            timeout_keep_alive=30, h11_max_incomplete_event_size=16 * 1024)
    try:
        uvicorn.Server(config).run(sockets=[sock])
    finally:
        practice.ahead.close()
    return 0
