"""What a sheet or key layout sees: plain dicts of ready-written text for one output format.

Built once per sheet against a Target (targets.py), so a layout only arranges; it never
formats a number or escapes a character. Nothing here reads an answer unless `key` is set.
"""
from __future__ import annotations

import re

from .. import units
from ..answertypes import answer_type
from .equations import rows
from .solution import TableBlock, WorkLine, solution
from .targets import PLAIN

_SVG_TITLE = re.compile(r"<title>(.*?)</title>", re.DOTALL)
_SVG_BOX = re.compile(r'viewBox="[-\d.]+ [-\d.]+ ([\d.]+) ([\d.]+)"')
_SVG_WIDTH = re.compile(r'<svg\b[^>]*?\swidth="([\d.]+)pt"')
#: A4 less the margins, in mm: the text block a question must fit, and its width.
PAGE_HEIGHT, PAGE_WIDTH = 297 - 20 - 24, 210 - 44
#: The height a sheet's answer line adds to a part (a 16 pt line and the line break above it), in mm.
ANSWER_LINE = 7.5


def marks(value: float) -> str:
    """3 -> '3', 1.5 -> '1.5', 0.333.. -> '0.33'."""
    return f"{value:.2f}".rstrip("0").rstrip(".")


def plural(value: float, word: str = "mark") -> str:
    return f"{marks(value)} {word}{'' if value == 1 else 's'}"


def surely_fits(statement: str, svg: str | None, asks: list[str], answer_lines: bool = False) -> bool:
    """Whether a question's heading, statement, figure and parts (with a sheet's answer lines) surely fit
    on one page: a generous estimate, so that the layout measures only the questions that might not."""
    lines = sum(len(p) // 90 + 1 for p in statement.split("\n\n")) + sum(len(a) // 70 + 1 for a in asks)
    height = 14 + 5.2 * lines + (2.5 + (ANSWER_LINE if answer_lines else 0)) * len(asks)  # heading, text, parts
    box = _SVG_BOX.search(svg or "")
    if box:
        height += 0.88 * PAGE_WIDTH * float(box.group(2)) / float(box.group(1)) + 12  # figure and caption
    return height <= 0.8 * PAGE_HEIGHT


def wider_than_text(svg: str) -> bool:
    """Whether a figure, at the size its SVG states (pt), is wider than the text block (it is then shrunk to it)."""
    found = _SVG_WIDTH.search(svg)
    return bool(found) and float(found.group(1)) > PAGE_WIDTH * 72 / 25.4


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
        "fits": surely_fits(PLAIN.text(v.statement), svg if figure else None, [PLAIN.text(v.asks[p.id]) for p in v.template.parts],
                            answer_lines=not key),
    }
    if key:
        context.update(key_context(v, target, key_figures))
    return context


def key_context(variant, target, key_figures=(), worked=None) -> dict:
    """Template reference, given data and the worked solution (answers only ever reach a key).
    `key_figures` are the (embed, caption) of the figures only the key shows: the polygons and
    diagrams the text draws from its tables, placed after the last table of the working.
    `worked` is the variant's solution, if already made."""
    worked = worked or solution(variant)
    template = variant.template
    given = [{"symbol": target.math(g.symbol), "label": target.text(g.label),
              "printed": target.prose(g.printed), "si": target.prose(g.si_text or "")} for g in worked.given]
    blocks = [line_context(b, target) if isinstance(b, WorkLine) else table_context(b, target) for b in worked.blocks]
    tables = [i for i, b in enumerate(blocks) if b["kind"] == "table"]
    at = tables[-1] + 1 if tables else len(blocks)
    blocks[at:at] = [{"kind": "figure", "figure": embed, "caption": target.prose(caption)}
                     for embed, caption in key_figures]
    return {
        "template_id": target.prose(template.id),
        "template_title": target.prose(template.title),
        "source": target.text(template.source),
        "seed": variant.seed,
        "given": given,
        "given_si": any(g.si_text for g in worked.given),
        "blocks": blocks,
    }


def line_context(line: WorkLine, target) -> dict:
    """A worked line: its chain (one line) and its rows (for a layout that breaks long lines)."""
    return {"kind": "line", "equation": target.equation(rows(line, target)), "note": target.text(line.note),
            "parts": ", ".join(f"({p})" for p in line.parts)}


def table_context(table: TableBlock, target) -> dict:
    def cell(value) -> str:
        if value is None:
            return ""
        if isinstance(value, str):
            return target.text(value)
        return target.inline(target.number(value.value)) if not isinstance(value.value, str) else target.prose(value.value)

    head = []
    for column in table.columns:
        shown = "deg" if column.unit == "rad" else column.unit
        unit = units.pretty_unit(shown) if shown else ""
        head.append(target.text(column.head) + (f" ({target.prose(unit)})" if unit else ""))
    return {"kind": "table", "title": target.text(table.title), "head": head,
            "rows": [[cell(c) for c in row] for row in table.rows],
            "total": [cell(c) for c in table.total] if table.total else None}
