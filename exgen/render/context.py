"""What a sheet or key layout sees: plain dicts of ready-written text for one output format.

Built once per sheet against a Target (targets.py), so a layout only arranges; it never
formats a number or escapes a character. Nothing here reads an answer unless `key` is set.
"""
from __future__ import annotations

import re

from .. import units
from .solution import solution
from .targets import PLAIN

ASK_UNITS = {"deg": "deg", "degree": "deg", "percent": "%"}
_SVG_TITLE = re.compile(r"<title>(.*?)</title>", re.DOTALL)


def marks(value: float) -> str:
    """3 -> '3', 1.5 -> '1.5', 0.333.. -> '0.33'."""
    return f"{value:.2f}".rstrip("0").rstrip(".")


def plural(value: float, word: str = "mark") -> str:
    return f"{marks(value)} {word}{'' if value == 1 else 's'}"


def asked_unit(part) -> str:
    """The unit an answer is asked in, as the sheet writes it ('deg', 'kW', 'N·m')."""
    return ASK_UNITS.get(part.unit, units.pretty_unit(part.unit)) if part.unit else ""


def ask_hint(part) -> str:
    """What the answer must look like: 'answer in kW', 'a whole number', 'one of: a, b'."""
    if part.type == "choice" and part.choices:
        return "one of: " + ", ".join(part.choices)
    if part.type == "integer":
        return "a whole number" + (f", in {asked_unit(part)}" if part.unit else "")
    if part.type == "polar":
        return f"{asked_unit(part) or 'magnitude'} at an angle in degrees"
    return f"answer in {asked_unit(part)}" if part.unit else "a pure number"


def tolerance_text(part) -> str:
    if part.type in ("integer", "choice"):
        return "exact"
    tol, pieces = part.tol, []
    if part.type == "polar":
        return f"±{tol.rel * 100:g} %, angle ±{PLAIN.quantity(tol.abs, 'deg')}"
    if tol.rel:
        pieces.append(f"±{tol.rel * 100:g} %")
    if tol.abs:
        pieces.append(f"±{PLAIN.quantity(tol.abs, part.unit)}")
    if tol.sig:
        pieces.append(f"{tol.sig} significant figures")
    return " or ".join(pieces) or "exact"


def figure_caption(number: int, svg: str | None) -> str:
    found = _SVG_TITLE.search(svg or "")
    return f"Figure {number}" + (f": {found.group(1).strip()}" if found else "")


def sheet_context(sheet, target, figures: dict[str, str], svgs: dict[str, str], key: bool = False) -> dict:
    """The whole sheet. `figures` maps a slot to what the layout embeds (a file path, or SVG
    source for Typst); `svgs` maps a slot to the figure's SVG text, read for its caption."""
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
        "questions": [question_context(q, target, figures.get(q.slot), svgs.get(q.slot), key)
                      for q in sheet.questions],
    }


def question_context(question, target, figure: str | None, svg: str | None, key: bool) -> dict:
    v = question.variant
    parts = []
    for part in v.template.parts:
        entry = {"id": part.id, "ask": target.text(v.asks[part.id]), "hint": target.prose(ask_hint(part)),
                 "marks": plural(part.points * question.scale)}
        if key:
            answer = v.answers[part.id]
            entry["answer"] = target.prose(answer.text)
            entry["tolerance"] = target.prose(tolerance_text(part))
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
