"""The review page, rendered with Jinja2 (autoescape on: a student's text, a comment, a reason are plain
strings the layout escapes)."""
from __future__ import annotations

from functools import lru_cache
from urllib.parse import urlencode

import jinja2

from .queue import KINDS, Queue


@lru_cache(maxsize=1)
def environment() -> jinja2.Environment:
    return jinja2.Environment(loader=jinja2.PackageLoader("graders.review_page", "templates"), autoescape=True,
                              undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)


def render(name: str, **context) -> str:
    return environment().get_template(name).render(**context)


def points(value: float | None) -> str:
    if value is None:
        return "full marks"
    return f"{value:.2f}".rstrip("0").rstrip(".") if value else "0"


def review_page(queue: Queue, view: dict, *, token: str, reviewer: str, decisions_path: str, graded: str,
                beside: bool = True, saved: dict | None = None, invalid: dict | None = None) -> str:
    """The list of what needs a human under the filters of `view` (question, part, everything), with a form
    per group. `beside`: the decisions file is the default one, which `exgen grade` finds itself. `saved`: the
    group just decided and what was said of it. `invalid`: a form sent back with what is wrong in it (group,
    field, message, values)."""
    question = view.get("question")
    groups = queue.shown(question, view.get("part", ""), view.get("everything", False))
    sections = []
    for kind, heading in KINDS.items():
        members = [g for g in groups if g.kind == kind]
        if members:
            sections.append({"kind": kind, "heading": heading, "groups": members,
                             "answers": sum(len(g.answers) for g in members)})
    open_by_question: dict[int, int] = {}
    for g in queue.groups:
        if not g.decided:
            open_by_question[g.question] = open_by_question.get(g.question, 0) + len(g.answers)
    parts = [(q.number, p) for q in queue.questions for p in q.parts if question is None or q.number == question]
    return render("review.html", queue=queue, sections=sections, view=view, token=token, reviewer=reviewer,
                  decisions_path=decisions_path, graded=graded, beside=beside, saved=saved, invalid=invalid or {},
                  parts=parts, points=points, shown=len(groups), kinds=KINDS,
                  open_by_question=open_by_question, show_all="/?" + view_query({**view, "everything": True}))


def view_query(view: dict, **extra) -> str:
    """The query string of a view (its filters), with `extra` fields."""
    fields = {"question": view["question"] if view["question"] is not None else "", "part": view["part"],
              "show": "all" if view["everything"] else "", **extra}
    return urlencode({k: v for k, v in fields.items() if v != ""})


def error_page(status: int, title: str, message: str) -> str:
    return render("error.html", status=status, title=title, message=message)
