"""A variant as plain Unicode text for the terminal (`exgen show`, `exgen solve --steps`)."""
from __future__ import annotations

import textwrap

from ..answertypes import answer_type
from .solution import solution
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
           "", _wrap(PLAIN.text(variant.statement)), ""]
    for part in template.parts:
        ask = f"{PLAIN.text(variant.asks[part.id])} [{answer_type(part).hint(part)}]"
        out.append(_wrap(ask, "    ", f"({part.id}) "))
    if not key:
        return "\n".join(out)
    worked = solution(variant)
    out += ["", "Given"]
    for g in worked.given:
        si = f" = {g.si_text}" if g.si_text else ""
        label = f"  ({PLAIN.text(g.label)})" if g.label else ""
        out.append(f"  {PLAIN.math(g.symbol)} = {g.printed}{si}{label}")
    out += ["", "Worked solution"]
    for line in worked.lines:
        marker = "  " + " ".join(f"({p})" for p in line.parts) if line.parts else ""
        out.append("  " + " = ".join(line.chain(PLAIN)) + marker)
        if line.note:
            out.append(f"      {PLAIN.text(line.note)}")
    out += ["", "Answers"]
    for part in template.parts:
        out.append(f"  ({part.id}) {answer_type(part).key_text(variant.answers[part.id], PLAIN)}")
    return "\n".join(out)
