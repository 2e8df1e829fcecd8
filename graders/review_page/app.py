"""The review app (Starlette) over a graded folder: GET / lists what needs a human, POST /decide writes a
decision to the decisions file. Guarded as every local page of exgen is (exgen.runtime.localweb: this
computer's address only, forms from this site only, within limits); each form also carries a token made
when the server started, so a page from before a restart, or from anywhere else, cannot write.

Nothing is written but the decisions file, through graders.decisions, whole or not at all; results.json
is read again whenever it changes (a regrade while the page is open), the decisions file on every request.
Without JavaScript: every form is an ordinary POST answered with a redirect to the list.
"""
from __future__ import annotations

import hmac
import logging
import secrets
import threading
from pathlib import Path

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import HTMLResponse, RedirectResponse, Response
from starlette.routing import Route

from exgen.echo import shown
from exgen.errors import ExgenError
from exgen.runtime.localweb import BadRequest, Disconnected, Guard, asset_response, load_assets, read_form

from ..decisions import Decisions, default_path, load_decisions, save_decisions
from ..record import RESULTS, read_record
from . import pages
from .decide import Invalid, decide
from .queue import Queue, build_queue

MAX_BODY = 16 * 1024  # a decision: a few names, a comment and a reason
MAX_FIELDS = 16
log = logging.getLogger("review")


class Review:
    """The graded folder and its decisions file, read fresh when they change."""

    def __init__(self, graded: Path, decisions_path: Path, reviewer: str = "", bank=None):
        """`bank`: the templates, or a function that loads them (called once, when a spelling is first
        accepted for a part that is not a choice), to check what it is accepted as."""
        self.graded, self.decisions_path, self.reviewer = Path(graded), Path(decisions_path), reviewer
        self._bank = bank
        self._record, self._stamp = None, None
        self.said: tuple[str, str] = ("", "")  # (group, what was decided for it), shown once after the redirect
        self.lock = threading.Lock()  # one decision written at a time

    def record(self) -> dict:
        path = self.graded / RESULTS
        try:
            stat = path.stat()
            stamp = (stat.st_mtime_ns, stat.st_size)
        except OSError:
            stamp = None
        if self._record is None or stamp != self._stamp:
            self._record, self._stamp = read_record(self.graded), stamp
        return self._record

    def decisions(self) -> Decisions:
        return load_decisions(self.decisions_path, self.record()["assignment"]["id"])

    def queue(self) -> Queue:
        return build_queue(self.record(), self.decisions())

    def spec(self, template: str, part: str):
        """The part's PartSpec from the bank, None without a bank or if the bank no longer has it."""
        if callable(self._bank):
            self._bank = self._bank()
        if self._bank is None:
            return None
        try:
            return self._bank.get(template).part(part)
        except (ExgenError, KeyError, LookupError):
            return None


def view_of(query) -> dict:
    """The filters of a request (question, part, everything) from its query, anything odd ignored."""
    question = query.get("question", "")
    return {"question": int(question) if question.isdigit() and len(question) < 5 else None,
            "part": query.get("part", "")[:20], "everything": query.get("show", "") == "all"}


def create_app(review: Review, allowed_hosts: tuple[str, ...] | None):
    token = secrets.token_urlsafe(24)
    assets = load_assets("graders.review_page")

    def failure(status: int, message: str) -> Response:
        titles = {400: "Cannot do that", 403: "Refused", 404: "Not found", 408: "Too slow", 413: "Too large",
                  415: "Cannot read that"}
        return HTMLResponse(pages.error_page(status, titles.get(status, "Something went wrong"), message),
                            status_code=status)

    def guarded(handler):
        async def endpoint(request: Request) -> Response:
            try:
                form = await read_form(request, MAX_BODY, MAX_FIELDS) if request.method == "POST" else {}
                return await run_in_threadpool(handler, request, form)
            except Disconnected:
                return Response(status_code=400, headers={"connection": "close"})
            except BadRequest as exc:
                response = failure(exc.status, exc.message)
                if exc.status == 408:
                    response.headers["connection"] = "close"
                return response
            except ExgenError as exc:  # results.json or the decisions file cannot be used: say which and why
                return failure(400, str(exc))
        return endpoint

    def page(view: dict, saved=None, invalid=None, status: int = 200) -> HTMLResponse:
        return HTMLResponse(pages.review_page(review.queue(), view, token=token, reviewer=review.reviewer,
                                              decisions_path=str(review.decisions_path), graded=str(review.graded),
                                              beside=review.decisions_path == default_path(review.graded), saved=saved, invalid=invalid), status_code=status)

    def home(request, form):
        view = view_of(request.query_params)
        saved = request.query_params.get("saved", "")
        group = review.queue().group(saved) if saved else None
        said = review.said[1] if group is not None and review.said[0] == saved else ""
        return page(view, saved={"group": group, "said": said} if group else None)

    def decide_one(request, form):
        if not hmac.compare_digest(form.get("token", ""), token):
            raise BadRequest(403, "this form is from an earlier run of exgen review: reload the page and decide again")
        view = view_of(form)
        with review.lock:
            queue = review.queue()
            group = queue.group(form.get("group", ""))
            if group is None:
                raise BadRequest(404, "that answer is no longer listed (graded again since?): reload the page")
            try:
                spec = review.spec(group.template, group.part) if form.get("decision") == "alias" else None
                decisions, said = decide(review.decisions(), group, form, spec)
            except Invalid as exc:
                return page(view, invalid={"group": group.id, "field": exc.name, "message": exc.message,
                                           "values": form}, status=400)
            save_decisions(decisions, review.decisions_path)
            review.said = (group.id, said)
        review.reviewer = shown(form.get("reviewer", ""), 200) or review.reviewer  # the next form is filled in with it
        log.info("review: %s", said)
        return RedirectResponse("/?" + pages.view_query(view, saved=group.id) + "#saved", status_code=303)

    async def static(request: Request) -> Response:
        asset = assets.get(request.path_params["name"])
        if asset is None:
            return failure(404, "there is no such file")
        return asset_response(asset, request)

    async def not_found(request: Request, exc) -> Response:
        return failure(getattr(exc, "status_code", 404), "there is no such page")

    async def server_error(request: Request, exc: Exception) -> Response:
        log.exception("review: an unexpected error in %s %s", request.method, request.url.path)
        return failure(500, "something went wrong on the server; the decisions saved so far are kept")

    routes = [Route("/", guarded(home)), Route("/decide", guarded(decide_one), methods=["POST"]),
              Route("/static/{name}", static)]
    app = Starlette(routes=routes, exception_handlers={404: not_found, 405: not_found, Exception: server_error})
    return Guard(app, allowed_hosts, MAX_BODY)
