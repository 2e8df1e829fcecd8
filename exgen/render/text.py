"""A variant as plain Unicode text for the terminal (`exgen show`, `exgen solve --steps`)."""
from __future__ import annotations

import textwrap

from .. import units
from ..answertypes import answer_type
from .solution import TableBlock, solution
from .targets import PLAIN

WIDTH = 88


def _wrap(text: str, indent: str = "", first: str | None = None) -> str:
    """Re-flow prose (the statement keeps its paragraphs) to the terminal width."""
    paragraphs = [" ".join(p.split()) for p in text.split("\n\n")]
    lead = indent if first is None else first
    return "\n\n".join(textwrap.fill(p, WIDTH, initial_indent=lead if i == 0 else indent,
                                     subsequent_indent=indent) for i, p in enumerate(paragraphs))


def variant_text(variant, key: bool = False) -> str:
    """Statement and parts (with the unit asked); with `key`, the given data, worked steps and answers."""
    template = variant.template
    out = [f"{template.title}  [{template.id}" + (f", seed {variant.seed}]" if variant.seed is not None else "]"),
           "", statement_text(variant), ""]
    out += [ask_text(variant, part) for part in template.parts]
    if key:
        out += [""] + key_lines(variant)
    return "\n".join(out)


def statement_text(variant) -> str:
    return _wrap(PLAIN.text(variant.statement))


def ask_text(variant, part, indent: str = "") -> str:
    """'(a) the power transmitted [answer in kW]', wrapped."""
    ask = f"{PLAIN.text(variant.asks[part.id])} [{answer_type(part).hint(part)}]"
    return _wrap(ask, indent + "    ", f"{indent}({part.id}) ")


def key_lines(variant, worked=None) -> list[str]:
    """The given data, the worked solution (`worked`, if already made) and the answers."""
    worked = worked or solution(variant)
    out = ["Given"] if worked.given else []
    for g in worked.given:
        si = f" = {g.si_text}" if g.si_text else ""
        label = f"  ({PLAIN.text(g.label)})" if g.label else ""
        out.append(f"  {PLAIN.math(g.symbol)} = {PLAIN.prose(g.printed)}{si}{label}")
    out += ["", "Worked solution"] if out else ["Worked solution"]
    for block in worked.blocks:
        if isinstance(block, TableBlock):
            out += table_text(block)
        else:
            out += line_text(block)
    out += ["", "Answers"]
    for part in variant.template.parts:
        out.append(f"  ({part.id}) {answer_type(part).key_text(variant.answers[part.id], PLAIN)}")
    return out


def line_text(line, indent: str = "  ") -> list[str]:
    """A worked line as 'symbol = formula = numbers = value  (a)', and its note under it."""
    marker = "  " + " ".join(f"({p})" for p in line.parts) if line.parts else ""
    out = [indent + " = ".join(line.chain(PLAIN)) + marker]
    if line.note:
        out.append(f"{indent}    {PLAIN.text(line.note)}")
    return out


def table_text(table: TableBlock) -> list[str]:
    """A table in fixed-width columns, numbers right-aligned."""
    def cell(value) -> str:
        if value is None:
            return ""
        if isinstance(value, str):
            return PLAIN.text(value)
        return PLAIN.number(value.value) if not isinstance(value.value, str) else value.value

    head = []
    for column in table.columns:
        unit = units.pretty_unit("deg" if column.unit == "rad" else column.unit)
        head.append(PLAIN.text(column.head) + (f" ({unit})" if unit else ""))
    body = [[cell(c) for c in row] for row in table.rows]
    if table.total:
        body.append([cell(c) for c in table.total])
    widths = [max(len(r[i]) for r in [head] + body) for i in range(len(head))]
    rows = [head] + body
    lines = [f"  {PLAIN.text(table.title)}"]
    for k, row in enumerate(rows):
        lines.append("    " + "  ".join(c.ljust(w) if i == 0 else c.rjust(w) for i, (c, w) in
                                         enumerate(zip(row, widths))))
        if k == 0 or (table.total and k == len(rows) - 2):
            lines.append("    " + "  ".join("-" * w for w in widths))
    return lines
