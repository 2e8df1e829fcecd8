"""What a sheet or key layout sees: plain dicts of ready-written text for one output format.

Built once per sheet against a Target (targets.py), so a layout only arranges; it never
formats a number or escapes a character. Nothing here reads an answer unless `key` is set.
"""
from __future__ import annotations

import re

from ..answertypes import answer_type
from .solution import solution

_SVG_TITLE = re.compile(r"<title>(.*?)</title>", re.DOTALL)


def marks(value: float) -> str:
    """3 -> '3', 1.5 -> '1.5', 0.333.. -> '0.33'."""
    return f"{value:.2f}".rstrip("0").rstrip(".")


def plural(value: float, word: str = "mark") -> str:
    return f"{marks(value)} {word}{'' if value == 1 else 's'}"


def figure_caption(number: int, svg: str | None) -> str:
    found = _SVG_TITLE.search(svg or "")
    return f"Figure {number}" + (f": {found.group(1).strip()}" if found else "")


def sheet_context(sheet, target, figures: dict[str, str], svgs: dict[str, str], key: bool = False,
                  key_figures: dict[str, list[tuple[str, str]]] | None = None) -> dict:
    """The whole sheet. `figures` maps a slot to what the layout embeds (a file path, or SVG
    source for Typst); `svgs` maps a slot to the figure's SVG text, read for its caption;
    `key_figures` maps a slot to the (embed, caption) of each figure only the key shows."""
    a, s = sheet.assignment, sheet.student
    return {
        "key": key,
        "course": target.prose(a.course),
        "title": target.prose(a.title),
        "assignment_id": target.prose(a.id),
        "student_name": target.prose(s.name or s.id),
        "student_id": target.prose(s.id),
        "section": target.prose(s.section),
        "code": target.prose(sheet.code),
        "due": target.prose(a.due),
        "total": plural(sheet.points),
        "instructions": target.text(a.instructions) if a.instructions else "",
        "questions": [question_context(q, target, figures.get(q.slot), svgs.get(q.slot), key,
                                       (key_figures or {}).get(q.slot, ()))
                      for q in sheet.questions],
    }


def question_context(question, target, figure: str | None, svg: str | None, key: bool, key_figures=()) -> dict:
    v = question.variant
    parts = []
    for part in v.template.parts:
        kind = answer_type(part)
        entry = {"id": part.id, "ask": target.text(v.asks[part.id]), "hint": target.prose(kind.hint(part)),
                 "marks": plural(part.points * question.scale)}
        if key:
            entry["answer"] = kind.key_text(v.answers[part.id], target)
            entry["tolerance"] = target.prose(kind.tolerance_text(part))
        parts.append(entry)
    context = {
        "number": question.number,
        "slot": target.prose(question.slot),
        "marks": plural(question.points),
        "statement": target.text(v.statement),
        "figure": figure,
        "caption": target.prose(figure_caption(question.number, svg)),
        "parts": parts,
    }
    if key:
        context.update(key_context(v, target))
        # beside the working: the polygons and diagrams the textbook draws (never on a sheet)
        context["key_figures"] = [{"figure": embed, "caption": target.prose(caption)} for embed, caption in key_figures]
    return context


def key_context(variant, target) -> dict:
    """Template reference, given data and worked lines (answers only ever reach a key)."""
    worked = solution(variant)
    template = variant.template
    return {
        "template_id": target.prose(template.id),
        "template_title": target.prose(template.title),
        "source": target.prose(template.source),
        "seed": variant.seed,
        "given": [{"symbol": target.math(g.symbol), "label": target.text(g.label),
                   "printed": target.prose(g.printed), "si": target.prose(g.si_text or "")}
                  for g in worked.given],
        "lines": [{"symbol": target.math(line.symbol), "chain": line.chain(target)[1:],
                   "note": target.text(line.note), "parts": ", ".join(f"({p})" for p in line.parts)}
                  for line in worked.lines],
    }
