"""The practice pages: what each one shows, built from the practice core and rendered with Jinja2.

Autoescape is on: text exgen writes reaches a page through the HTML target (render.html), already
escaped, with its math as MathML; everything else, a student's answer and any message quoting it
included, is a plain string the layout escapes. Figures are the variant's own SVG, inline.
"""
from __future__ import annotations

from functools import lru_cache

import jinja2
from markupsafe import Markup

from exgen.answertypes import answer_type
from exgen.echo import shown
from exgen.figures import Drawn
from exgen.render.context import figure_caption, key_context, line_context
from exgen.render.html import HTML
from ..mastery import MASTERED, SOLUTION_COST, WEAK, Mastery, costs, share_words
from ..progress import Row
from ..scope import Scope, topic_of
from ..session import Practice, Problem, State
from .chart import mastery_chart
from .legible import legible

@lru_cache(maxsize=1)
def environment() -> jinja2.Environment:
    env = jinja2.Environment(loader=jinja2.PackageLoader("practice.web", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined, trim_blocks=True,
                             lstrip_blocks=True)
    env.filters["math"] = HTML.inline
    env.globals.update(mastered=MASTERED, weak=WEAK, costs=costs())
    return env


def render(name: str, **context) -> str:
    return environment().get_template(name).render(**context)


def fragment(name: str, macro: str, *args) -> str:
    """One macro of a template, for a part of a page sent on its own (a check's feedback, a hint)."""
    return str(getattr(environment().get_template(name).module, macro)(*args))


def standing(estimate: Mastery) -> dict:
    """How a topic stands, as every page shows it: the percentage (rounded down) and the level read from it."""
    return {"percent": estimate.percent if estimate.problems else 0, "text": estimate.text,
            "level": estimate.level, "started": bool(estimate.problems)}


def topic_name(topic: str) -> str:
    return topic.replace("_", " ").capitalize()


# ---- the map of chapters and topics ---------------------------------------------------------

def map_page(practice: Practice) -> str:
    topics, templates = practice.table("topic"), practice.table("template")
    chapters = []
    for chapter in practice.catalogue.chapters():
        entries = []
        for topic, members in chapter.topics.items():
            row = topics.get(topic)
            entries.append({
                "name": topic_name(topic), "scope": Scope("topic", topic).key,
                "standing": standing(row.mastery if row else Mastery()),
                "problems": row.problems if row else 0,
                "templates": [{"title": HTML.text(t.title), "scope": Scope("template", t.id).key,
                               "source": t.source,
                               "standing": standing(templates[t.id].mastery if t.id in templates else Mastery())}
                              for t in members],
            })
        chapters.append({"number": chapter.number, "title": chapter.title, "topics": entries,
                         "scope": Scope("chapter", str(chapter.number)).key})
    catalogue = practice.catalogue
    return render("map.html", chapters=chapters, assignment=catalogue.assignment.title if catalogue.assignment else "",
                  count=len(catalogue.templates), absent=catalogue.absent)


# ---- a problem --------------------------------------------------------------------------

def problem_page(practice: Practice, problem: Problem) -> str:
    state = practice.state(problem)
    variant = problem.variant
    topic = topic_of(problem.template)
    row = practice.table("topic").get(topic)
    parts = [part_context(practice, problem, part, state) for part in problem.template.parts]
    fresh = not (state.checks or state.hints or state.solution)  # just served: the first box takes the focus
    return render("problem.html", problem=problem_context(practice, problem), parts=parts,
                  solution_cost=solution_cost_text(problem, state), fresh=fresh,
                  statement=HTML.text(variant.statement), figure=_figure(practice, problem),
                  standing=standing(row.mastery if row else Mastery()), topic=topic_name(topic),
                  solution=solution_context(practice, problem) if state.solution else None)


def problem_context(practice: Practice, problem: Problem) -> dict:
    template = problem.template
    return {"id": problem.id, "title": HTML.text(template.title), "template": template.id,
            "seed": problem.variant.seed, "source": template.source, "chapter": template.chapter,
            "scope": problem.scope.key, "scope_label": practice.catalogue.label(problem.scope)}


def _figure(practice: Practice, problem: Problem) -> dict | None:
    svg = practice.figure(problem)
    if not svg:
        return None
    return {"svg": Markup(legible(svg)), "caption": figure_caption(1, svg).partition(": ")[2] or "Figure"}


def part_context(practice: Practice, problem: Problem, part, state: State, asked: bool = False) -> dict:
    """A part's box; `asked`: a hint was just asked for, so whether there are more is worth knowing."""
    kind = answer_type(part)
    check = state.checks.get(part.id)
    hinted = state.hints.get(part.id, 0)
    # the ladder (made from the worked solution) only once a hint is asked for: until then there may be more
    known = bool(hinted or asked)
    ladder = practice.hints(problem, part.id, state) if known else ()
    return {
        "id": part.id, "ask": HTML.text(problem.variant.asks[part.id]), "unit": kind.hint(part),
        "example": kind.format_hint(part), "answer": check.answer if check else "",
        "feedback": feedback(check.status, check.message) if check else None,
        "hints": [hint_context(i + 1, h) for i, h in enumerate(ladder[:hinted])],
        "more_hints": hinted < len(ladder) if known else True, "problem": problem.id,
        "cost": hint_cost_text(part.id, state, hinted < len(ladder) if known else True),
    }


def hint_cost_text(part_id: str, state: State, more: bool = True) -> str:
    """What the part's next hint costs, said beside its button before it is pressed (nothing once there
    is no next hint)."""
    if not more:
        return ""
    cost = state.hint_cost(part_id)
    if cost:
        return f"costs {share_words(cost)} of ({part_id})'s credit"
    if part_id in state.answered:
        return f"free: ({part_id}) has been answered"
    return "free: the worked solution is shown" if state.solution else "free: its hints have cost all they can"


def solution_cost_text(problem: Problem, state: State) -> str:
    if state.solution_cost(problem.template.parts):
        return f"costs {share_words(SOLUTION_COST)} of the credit of every part not answered yet"
    return "free: every part has been answered" if not state.solution else "shown below"


def costs_now(practice: Practice, problem: Problem, state: State) -> dict[str, str]:
    """Every cost the page shows, as it stands (sent with each check, hint and solution)."""
    def more(part_id: str) -> bool:
        hinted = state.hints.get(part_id, 0)
        return not hinted or hinted < len(practice.hints(problem, part_id, state))

    return {**{p.id: hint_cost_text(p.id, state, more(p.id)) for p in problem.template.parts},
            "solution": solution_cost_text(problem, state)}


#: A message on a page: long enough for every message exgen writes; what a student typed in it is short.
MESSAGE_LENGTH = 400


def feedback(status: str, message: str) -> dict:
    """A check's status and message for a page: the message cleaned as every echo of student text is
    (one line, no control or bidi characters; the page escapes it as HTML)."""
    return {"status": status, "message": shown(message, MESSAGE_LENGTH, word=48)}


def hint_context(level: int, hint) -> dict:
    if hint.line is not None:
        return {"level": level, "math": line_context(hint.line, HTML)["equation"],
                "note": HTML.text(hint.line.note), "text": ""}
    return {"level": level, "math": "", "note": "", "text": HTML.text(hint.text)}


def solution_context(practice: Practice, problem: Problem) -> dict:
    figures = [(Markup(legible(svg)), Drawn(name, svg).title or name.replace("_", " "))
               for name, svg in practice.key_figures(problem)]
    context = key_context(problem.variant, HTML, figures, practice.worked(problem))
    context["answers"] = [{"id": p.id, "text": answer_type(p).key_text(problem.variant.answers[p.id], HTML)}
                          for p in problem.template.parts]
    return context


# ---- progress -----------------------------------------------------------------------------

def progress_page(practice: Practice) -> str:
    rows: dict[str, Row] = practice.table("topic")
    entries = []
    for chapter in practice.catalogue.chapters():
        for topic in chapter.topics:
            row = rows.get(topic) or Row(topic, chapter.number, Mastery(), 0, 0, 0.0)
            entries.append({"name": topic_name(topic), "chapter": chapter.number, "mastery": row.mastery,
                            "standing": standing(row.mastery), "problems": row.problems, "checks": row.checks,
                            "minutes": round(row.seconds / 60)})
    return render("progress.html", chart=Markup(mastery_chart(entries)), rows=entries,
                  db=str(practice.store.path))


def error_page(status: int, title: str, message: str) -> str:
    return render("error.html", status=status, title=title, message=message)
