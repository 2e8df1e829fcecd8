"""What every local web page of exgen stands on (`exgen serve`, `exgen review`): a socket listening on this
computer, an ASGI guard, forms read as hostile data, and the packaged files served by name.

Requests are hostile data like answer files. The guard refuses a Host header that is not this
computer's address (DNS rebinding) and a declared body over the app's limit before the app sees the
request, and adds to every response headers that forbid scripts, styles and frames from anywhere but
the server. A POST from another site (Origin, Sec-Fetch-Site), or from an opaque origin, is refused
when its form is read; a body is read within a byte limit and a time limit. Only files packaged beside
an app are served, looked up by name in a table made at start-up: no path is ever built from a URL.

Starlette and uvicorn are imported by the functions that need them, not by importing this module.
"""
from __future__ import annotations

import asyncio
import hashlib
import json
import mimetypes
import socket
import sys
from importlib import resources
from urllib.parse import parse_qs, urlsplit

from ..errors import ExgenError

LOOPBACK_NAMES = ("127.0.0.1", "localhost", "[::1]")
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")
#: A body that has not arrived whole by then is refused (a client that stalls holds no connection for long).
BODY_SECONDS = 5.0
SECURITY_HEADERS = [
    (b"content-security-policy", b"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
                                 b"font-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; "
                                 b"frame-ancestors 'none'"),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"same-origin"),  # other sites learn nothing; this one's forms send their origin
]
NO_STORE = (b"cache-control", b"no-store")  # pages change with every request; assets revalidate by ETag

PORT_IN_USE = "port {port} on {host} is in use (another exgen {command}?); give another with --port, or --port 0 for any free one"
CANNOT_BIND = "cannot listen on {host}:{port}: {reason}"
OTHER_SITE = "requests from other sites are refused"


class BadRequest(Exception):
    """A request refused with a status and a message for the page (or the JSON) that answers it."""

    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status, self.message = status, message


class Disconnected(Exception):
    """The client went away before its request was read: there is no one to answer."""


# ---- the socket -------------------------------------------------------------------------------------------

def is_loopback(host: str) -> bool:
    return host in LOOPBACK_HOSTS


def listen(host: str, port: int, command: str = "serve") -> socket.socket:
    """A listening TCP socket on host:port (port 0: a free one), bound before any address is printed."""
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
            raise ExgenError(PORT_IN_USE.format(port=port, host=host, command=command)) from None
        raise ExgenError(CANNOT_BIND.format(host=host, port=port, reason=exc.strerror or exc)) from None
    sock.set_inheritable(True)
    return sock


def url_of(sock: socket.socket) -> str:
    host, port = sock.getsockname()[:2]
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/"


def loopback_hosts(port: int) -> tuple[str, ...]:
    """The Host headers a browser on this computer sends to a loopback server on `port`."""
    return tuple(f"{name}:{port}" for name in LOOPBACK_NAMES)


def run(app, sock: socket.socket) -> None:
    """Serve `app` on the listening socket with uvicorn until Ctrl+C: no access log, no server or date
    header, a request's head capped at 16 KiB."""
    import uvicorn

    config = uvicorn.Config(app, log_level="warning", access_log=False, server_header=False, date_header=False,
                            timeout_keep_alive=30, h11_max_incomplete_event_size=16 * 1024)
    uvicorn.Server(config).run(sockets=[sock])


# ---- reading a request ------------------------------------------------------------------------------------

def refuse_other_sites(request) -> None:
    """A request from another site is refused, and so is one from an opaque origin (`Origin: null`: a
    sandboxed frame, a file on disk): an app's own pages send their origin (their referrer policy is
    same-origin)."""
    if request.headers.get("sec-fetch-site", "same-origin") not in ("same-origin", "none"):
        raise BadRequest(403, OTHER_SITE)
    origin = request.headers.get("origin")
    if origin and (origin == "null" or urlsplit(origin).netloc != request.headers.get("host", "")):
        raise BadRequest(403, OTHER_SITE)


async def read_form(request, max_body: int, max_fields: int, seconds: float = BODY_SECONDS) -> dict[str, str]:
    """The urlencoded fields of a POST from this site, within `max_body` bytes and `seconds`, as text (one
    value per name)."""
    from starlette.requests import ClientDisconnect

    refuse_other_sites(request)
    try:
        body = await asyncio.wait_for(_body(request, max_body), seconds)
    except asyncio.TimeoutError:
        raise BadRequest(408, f"the request's body did not arrive within {seconds:g} seconds") from None
    except ClientDisconnect:
        raise Disconnected() from None
    kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if body and kind != "application/x-www-form-urlencoded":
        raise BadRequest(415, "send the form as application/x-www-form-urlencoded")
    try:
        fields = parse_qs(body.decode("utf-8"), keep_blank_values=True, strict_parsing=False,
                          max_num_fields=max_fields, errors="strict")
    except (UnicodeDecodeError, ValueError):
        raise BadRequest(400, "the form could not be read (not UTF-8 text, or too many fields)") from None
    return {name: values[0] for name, values in fields.items()}


async def _body(request, max_body: int) -> bytes:
    body = b""
    async for chunk in request.stream():
        body += chunk
        if len(body) > max_body:
            raise BadRequest(413, f"the request is larger than {max_body} bytes")
    return body


def field(form: dict[str, str], name: str) -> str:
    if name not in form:
        raise BadRequest(400, f"the form has no {name!r}")
    return form[name]


# ---- what is served ---------------------------------------------------------------------------------------

def load_assets(package: str, folder: str = "static") -> dict[str, tuple[bytes, str, str]]:
    """Every file of a package's folder by name: (content, media type, ETag). Nothing else is ever served."""
    assets = {}
    for entry in resources.files(package).joinpath(folder).iterdir():
        if entry.is_file():
            body = entry.read_bytes()
            kind = {".woff2": "font/woff2", ".js": "text/javascript", ".svg": "image/svg+xml"}.get(
                entry.name[entry.name.rfind("."):], mimetypes.guess_type(entry.name)[0] or "application/octet-stream")
            if kind.startswith("text/") or kind == "image/svg+xml":
                kind += "; charset=utf-8"
            assets[entry.name] = (body, kind, '"' + hashlib.sha256(body).hexdigest()[:16] + '"')
    return assets


class Guard:
    """ASGI wrapper: refuses a Host not allowed and a declared body over `max_body` before the app sees
    the request, and adds the security headers to every response. `allowed_hosts`: the Host headers
    accepted (host:port), None for any."""

    def __init__(self, app, allowed_hosts: tuple[str, ...] | None, max_body: int):
        self.app, self.allowed, self.max_body = app, allowed_hosts, max_body

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        headers = dict(scope.get("headers") or [])
        refusal = None
        if self.allowed is not None and headers.get(b"host", b"").decode("latin-1").lower() not in self.allowed:
            refusal = (421, "this server answers only to its own address")
        length = headers.get(b"content-length", b"0")
        if not length.isdigit() or int(length) > self.max_body:
            refusal = refusal or (413, f"the request is larger than {self.max_body} bytes")
        if refusal:
            body = json.dumps({"error": refusal[1]}).encode()
            await send({"type": "http.response.start", "status": refusal[0],
                        "headers": [(b"content-type", b"application/json"), (b"connection", b"close")]
                        + SECURITY_HEADERS})
            await send({"type": "http.response.body", "body": body})
            return

        async def send_with_headers(message):
            if message["type"] == "http.response.start":
                headers = list(message.get("headers", [])) + SECURITY_HEADERS
                if not any(name.lower() == b"cache-control" for name, _ in headers):
                    headers.append(NO_STORE)
                message = {**message, "headers": headers}
            await send(message)

        await self.app(scope, receive, send_with_headers)


def asset_response(asset: tuple[bytes, str, str], request):
    """One packaged file, or 304 when the browser holds it already (by its ETag)."""
    from starlette.responses import Response

    body, kind, etag = asset
    if request.headers.get("if-none-match") == etag:
        return Response(status_code=304, headers={"etag": etag})
    return Response(body, media_type=kind, headers={"etag": etag, "cache-control": "no-cache"})
