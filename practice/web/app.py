"""The practice web app (Starlette): the topic map, a problem page, checks, hints, the worked solution
and progress, over the same practice core as the terminal.

Requests are hostile data like answer files, guarded as every local page of exgen is
(exgen.runtime.localweb): bodies over MAX_BODY bytes are refused before they are read, forms are parsed
from urlencoded text only, a request from another site or, on loopback, for a host name that is not
this computer's is refused, only the files packaged beside this module are served, and pages forbid
scripts and styles from anywhere but this server. Anything not understood is a 400 with a message,
and an unexpected failure is a 500 page while the server goes on.
"""
from __future__ import annotations

import logging

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.routing import Route

from exgen.errors import ExgenError
from exgen.runtime.localweb import (BODY_SECONDS, BadRequest, Disconnected, Guard, asset_response, field,
                                    load_assets as _load_assets, loopback_hosts, read_form as _read_form)
from ..scope import Scope, topic_of
from ..session import NoProblem, Practice
from ..store import ProgressError
from . import pages

__all__ = ["BODY_SECONDS", "MAX_BODY", "create_app", "loopback_hosts"]
MAX_BODY = 8 * 1024   # a form holds a part id and one answer: a few hundred bytes
MAX_FIELDS = 8
log = logging.getLogger("practice")


async def read_form(request: Request) -> dict[str, str]:
    return await _read_form(request, MAX_BODY, MAX_FIELDS)


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
        return asset_response(asset, request)

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
    return Guard(app, allowed_hosts, MAX_BODY)


def _standing_text(problem, standing: dict | None) -> str:
    name = pages.topic_name(topic_of(problem.template))
    if not standing or not standing["started"]:
        return f"{name}: not started"
    return f"{name}: {standing['text']} ({standing['level']})"


def load_assets() -> dict[str, tuple[bytes, str, str]]:
    """Every packaged static file of the practice app by name (exgen.runtime.localweb)."""
    return _load_assets("practice.web")
