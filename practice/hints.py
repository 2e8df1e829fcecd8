"""The hints of a part, first to last: the part's own `hints:` if its template gives them, else the
worked solution's first steps towards it.

The default ladder is the lines of the working that come after the previous part's answer and
before this part's, each in full (they are steps on the way, not the answer), then the line that
answers the part as a formula only, without its numbers: the method, never the value asked for.
Of those lines, only the ones the part is worked from count (the steps its formula names, and
theirs in turn): the slip worked out first is no hint for the speed asked without slip.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from exgen.derivation import PLACEHOLDER
from exgen.render.solution import WorkLine, solution


@dataclass(frozen=True)
class Hint:
    """A template's hint text (with $LaTeX$), or a line of the worked solution."""

    text: str = ""
    line: WorkLine | None = None


def hint_ladder(variant, part_id: str, worked=None) -> tuple[Hint, ...]:
    """Every hint of the part, in the order they are given; `worked` is the variant's solution if
    already made."""
    part = variant.template.part(part_id)
    if part.hints:
        return tuple(Hint(text=variant.fill(h)) for h in part.hints)
    lines = (worked or solution(variant)).lines
    end = next((i for i, line in enumerate(lines) if part_id in line.parts), None)
    if end is None:
        return ()
    start = max((i + 1 for i, line in enumerate(lines[:end]) if line.parts), default=0)
    needed = _worked_from(variant.steps, lines[end].name)
    ladder = [Hint(line=line) for line in lines[start:end] if not needed or line.name in needed]
    if lines[end].formula is not None:
        ladder.append(Hint(line=dataclasses.replace(lines[end], substituted=None, values=(), parts=())))
    return tuple(ladder)


def _worked_from(steps, name: str) -> set[str]:
    """The names a step's formula uses, and theirs in turn; empty when its formula names none."""
    formulas = {step.name: step.formula or "" for step in steps}
    found: set[str] = set()
    todo = [name]
    while todo:
        for used in PLACEHOLDER.findall(formulas.get(todo.pop(), "")):
            if used not in found:
                found.add(used)
                todo.append(used)
    return found
