"""The practice web app (Starlette): the topic map, a problem page, checks, hints, the worked solution
and progress, over the same practice core as the terminal.

Requests are hostile data like answer files: bodies over MAX_BODY bytes are refused before they are
read, forms are parsed here from urlencoded text only, anything not understood is a 400 with a
message, and an unexpected failure is a 500 page while the server goes on. Only the files packaged
beside this module are served, looked up by name in a table made at start-up (no path is ever built
from a URL). A request from another site (Origin, Sec-Fetch-Site), or, on loopback, for a host name
that is not this computer's (DNS rebinding), is refused. Pages forbid scripts and styles from
anywhere but this server.
"""
from __future__ import annotations

import asyncio
import hashlib
import json
import logging
import mimetypes
from importlib import resources
from urllib.parse import parse_qs, urlsplit

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import ClientDisconnect, Request
from starlette.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.routing import Route

from exgen.errors import ExgenError
from ..scope import Scope, topic_of
from ..session import NoProblem, Practice
from ..store import ProgressError
from . import pages

MAX_BODY = 8 * 1024   # a form holds a part id and one answer: a few hundred bytes
#: A body that has not arrived whole by then is refused (a client that stalls holds no connection for long).
BODY_SECONDS = 5.0
MAX_FIELDS = 8
LOOPBACK_NAMES = ("127.0.0.1", "localhost", "[::1]")
SECURITY_HEADERS = [
    (b"content-security-policy", b"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
                                 b"font-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; "
                                 b"frame-ancestors 'none'"),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"same-origin"),  # other sites learn nothing; this one's forms send their origin
]
NO_STORE = (b"cache-control", b"no-store")  # pages change with every answer; assets revalidate by ETag
log = logging.getLogger("practice")


class BadRequest(Exception):
    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status, self.message = status, message


# ---- reading a request ----------------------------------------------------------------------

class Disconnected(Exception):
    """The client went away before its request was read: there is no one to answer."""


async def read_form(request: Request) -> dict[str, str]:
    """The urlencoded fields of a POST, within MAX_BODY bytes and BODY_SECONDS, as text (one value per name).
    A POST from another site is refused, and so is one from an opaque origin (`Origin: null`: a sandboxed
    frame, a file on disk): this app's own pages send their origin (their referrer policy is same-origin)."""
    if request.headers.get("sec-fetch-site", "same-origin") not in ("same-origin", "none"):
        raise BadRequest(403, "requests from other sites are refused")
    origin = request.headers.get("origin")
    if origin and (origin == "null" or urlsplit(origin).netloc != request.headers.get("host", "")):
        raise BadRequest(403, "requests from other sites are refused")
    try:
        body = await asyncio.wait_for(_body(request), BODY_SECONDS)
    except asyncio.TimeoutError:
        raise BadRequest(408, f"the request's body did not arrive within {BODY_SECONDS:g} seconds") from None
    except ClientDisconnect:
        raise Disconnected() from None
    kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if body and kind != "application/x-www-form-urlencoded":
        raise BadRequest(415, "send the form as application/x-www-form-urlencoded")
    try:
        fields = parse_qs(body.decode("utf-8"), keep_blank_values=True, strict_parsing=False,
                          max_num_fields=MAX_FIELDS, errors="strict")
    except (UnicodeDecodeError, ValueError):
        raise BadRequest(400, "the form could not be read (not UTF-8 text, or too many fields)") from None
    return {name: values[0] for name, values in fields.items()}


async def _body(request: Request) -> bytes:
    body = b""
    async for chunk in request.stream():
        body += chunk
        if len(body) > MAX_BODY:
            raise BadRequest(413, f"the request is larger than {MAX_BODY} bytes")
    return body


def field(form: dict[str, str], name: str) -> str:
    if name not in form:
        raise BadRequest(400, f"the form has no {name!r}")
    return form[name]


def wants_json(request: Request) -> bool:
    return "application/json" in request.headers.get("accept", "")


# ---- the application ------------------------------------------------------------------------

def create_app(practice: Practice, allowed_hosts: tuple[str, ...] | None = None):
    """The ASGI app. `allowed_hosts`: the Host headers accepted (host:port), None for any."""
    assets = load_assets()

    def page(status: int, title: str, message: str) -> HTMLResponse:
        return HTMLResponse(pages.error_page(status, title, message), status_code=status)

    def failure(request: Request, status: int, message: str) -> Response:
        if wants_json(request):
            return JSONResponse({"error": message}, status_code=status)
        titles = {400: "Cannot do that", 403: "Refused", 404: "Not found", 408: "Too slow", 413: "Too large",
                  415: "Cannot read that", 503: "Progress unavailable"}
        return page(status, titles.get(status, "Something went wrong"), message)

    def guarded(handler):
        """Run a handler's work off the event loop, turning expected failures into pages or JSON."""
        async def endpoint(request: Request) -> Response:
            try:
                form = await read_form(request) if request.method == "POST" else {}
                return await run_in_threadpool(handler, request, form)
            except Disconnected:  # nothing to say, and nothing worth a line on the terminal
                return Response(status_code=400, headers={"connection": "close"})
            except BadRequest as exc:
                response = failure(request, exc.status, exc.message)
                if exc.status == 408:  # the rest of the body may still come: not on this connection
                    response.headers["connection"] = "close"
                return response
            except ProgressError as exc:
                return failure(request, 503, str(exc))
            except NoProblem as exc:
                return failure(request, 404, str(exc))
            except ExgenError as exc:
                return failure(request, 400, str(exc))
        return endpoint

    def problem_of(request: Request):
        try:
            problem_id = int(request.path_params["problem"])
        except (ValueError, OverflowError):
            raise BadRequest(404, "there is no such problem") from None
        return practice.problem(problem_id)

    def home(request, form):
        return HTMLResponse(pages.map_page(practice))

    def progress(request, form):
        return HTMLResponse(pages.progress_page(practice))

    def next_problem(request, form):
        scope = Scope.parse(field(form, "scope"))
        problem = practice.next_problem(scope)
        return RedirectResponse(f"/problem/{problem.id}", status_code=303)

    def show(request, form):
        return HTMLResponse(pages.problem_page(practice, problem_of(request)))

    def check(request, form):
        problem = problem_of(request)
        part_id, answer = field(form, "part"), field(form, "answer")
        result = practice.check(problem, part_id, answer)
        if not wants_json(request):
            return RedirectResponse(f"/problem/{problem.id}#part-{part_id}", status_code=303)
        row = practice.table("topic").get(topic_of(problem.template))
        standing = pages.standing(row.mastery) if row else None
        html = pages.fragment("parts.html", "feedback", None, pages.feedback(result.status, result.message)
                              if result.status != "blank" else None)
        return JSONResponse({"html": html, "status": result.status, "correct": result.correct,
                             "standing": _standing_text(problem, standing),
                             "costs": pages.costs_now(practice, problem, practice.state(problem))})

    def hint(request, form):
        problem = problem_of(request)
        part_id = field(form, "part")
        practice.next_hint(problem, part_id)
        if not wants_json(request):
            return RedirectResponse(f"/problem/{problem.id}#part-{part_id}", status_code=303)
        state = practice.state(problem)
        part = pages.part_context(practice, problem, problem.template.part(part_id), state, asked=True)
        return JSONResponse({"html": pages.fragment("parts.html", "hints", part), "more": part["more_hints"],
                             "costs": pages.costs_now(practice, problem, state)})

    def solution(request, form):
        problem = problem_of(request)
        practice.show_solution(problem)
        if not wants_json(request):
            return RedirectResponse(f"/problem/{problem.id}#solution", status_code=303)
        return JSONResponse({"html": pages.fragment("parts.html", "solution",
                                                    pages.solution_context(practice, problem)),
                             "costs": pages.costs_now(practice, problem, practice.state(problem))})

    async def static(request: Request) -> Response:
        asset = assets.get(request.path_params["name"])
        if asset is None:
            return failure(request, 404, "there is no such file")
        body, kind, etag = asset
        if request.headers.get("if-none-match") == etag:
            return Response(status_code=304, headers={"etag": etag})
        return Response(body, media_type=kind, headers={"etag": etag, "cache-control": "no-cache"})

    async def not_found(request: Request, exc) -> Response:
        return failure(request, getattr(exc, "status_code", 404), "there is no such page")

    async def server_error(request: Request, exc: Exception) -> Response:
        log.exception("practice: an unexpected error in %s %s", request.method, request.url.path)
        return failure(request, 500, "something went wrong on the server; your progress so far is kept")

    routes = [
        Route("/", guarded(home)),
        Route("/progress", guarded(progress)),
        Route("/next", guarded(next_problem), methods=["POST"]),
        Route("/problem/{problem}", guarded(show)),
        Route("/problem/{problem}/check", guarded(check), methods=["POST"]),
        Route("/problem/{problem}/hint", guarded(hint), methods=["POST"]),
        Route("/problem/{problem}/solution", guarded(solution), methods=["POST"]),
        Route("/static/{name}", static),
    ]
    app = Starlette(routes=routes, exception_handlers={404: not_found, 405: not_found, Exception: server_error})
    return Guard(app, allowed_hosts)


def _standing_text(problem, standing: dict | None) -> str:
    name = pages.topic_name(topic_of(problem.template))
    if not standing or not standing["started"]:
        return f"{name}: not started"
    return f"{name}: {standing['text']} ({standing['level']})"


def load_assets() -> dict[str, tuple[bytes, str, str]]:
    """Every packaged static file by name: (content, media type, ETag). Nothing else is ever served."""
    folder = resources.files("practice.web").joinpath("static")
    assets = {}
    for entry in folder.iterdir():
        if entry.is_file():
            body = entry.read_bytes()
            kind = {".woff2": "font/woff2", ".js": "text/javascript", ".svg": "image/svg+xml"}.get(
                entry.name[entry.name.rfind("."):], mimetypes.guess_type(entry.name)[0] or "application/octet-stream")
            if kind.startswith("text/") or kind == "image/svg+xml":
                kind += "; charset=utf-8"
            assets[entry.name] = (body, kind, '"' + hashlib.sha256(body).hexdigest()[:16] + '"')
    return assets


class Guard:
    """ASGI wrapper: refuses a Host not allowed and a declared body over MAX_BODY before the app
    sees the request, and adds the security headers to every response."""

    def __init__(self, app, allowed_hosts: tuple[str, ...] | None):
        self.app, self.allowed = app, allowed_hosts

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        headers = dict(scope.get("headers") or [])
        refusal = None
        if self.allowed is not None and headers.get(b"host", b"").decode("latin-1").lower() not in self.allowed:
            refusal = (421, "this server answers only to its own address")
        length = headers.get(b"content-length", b"0")
        if not length.isdigit() or int(length) > MAX_BODY:
            refusal = refusal or (413, f"the request is larger than {MAX_BODY} bytes")
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


def loopback_hosts(port: int) -> tuple[str, ...]:
    return tuple(f"{name}:{port}" for name in LOOPBACK_NAMES)

