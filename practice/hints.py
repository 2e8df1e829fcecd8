"""The hints of a part, first to last: the part's own `hints:` if its template gives them, else the
worked solution's steps towards it. No hint hands over the answer to a part not yet answered right.

The default ladder is the lines of the working that come after the previous part's answer and
before this part's (only those the part is worked from: the steps its formula names, and theirs in
turn), then the line that answers the part as its formula with the numbers put in, without its
result. On every line a number is shown only if it gives away no answer still to be found
(`Withheld`): a value that is such an answer, in any unit of its kind, is left out, and a number in a
formula that is one stays its symbol. So "ωₙ = √(q/I_O)" is shown while (b) asks for q and (c) for
fₙ = ωₙ/2π; once (b) is answered right, the same hint shows q's number in the formula.
"""
from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass

from exgen.answertypes import answer_type
from exgen.render.solution import Filled, Number, WorkLine, solution
from exgen.render.targets import PLAIN, number_parts
from exgen.solve.derivation import PLACEHOLDER

#: A number as plain text writes it: "0.1991", "−3.5", "2.4×10⁻³".
_NUMBER = re.compile(r"([-\u2212]?\d+(?:\.\d+)?)(?:\s*\u00d7\s*10([\u207a\u207b]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+))?")
_POWER = str.maketrans("\u207a\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079", "+-0123456789")


@dataclass(frozen=True)
class Hint:
    """A template's hint text (with $LaTeX$), or a line of the worked solution as it may be shown."""

    text: str = ""
    line: WorkLine | None = None


class Withheld:
    """The answers of the parts not yet answered right, and whether a value shown would give one away."""

    def __init__(self, variant, answered: frozenset[str] = frozenset()):
        self.answers = tuple(variant.answers[p.id] for p in variant.template.parts if p.id not in answered)
        self.givens = frozenset(p.name for p in variant.params)
        self.symbols = {**{p.name: p.symbol for p in variant.params}, **{s.name: s.symbol for s in variant.steps}}

    def gives_away(self, value) -> bool:
        return any(answer_type(a.part).gives_away(value, a) for a in self.answers)

    def in_text(self, text: str) -> bool:
        """Whether a number written in a text gives an answer away."""
        if not any(c.isdigit() for c in text):
            return False
        return any(self.gives_away(n) for n in numbers_in(PLAIN.text(text)))


def numbers_in(text: str) -> list[float]:
    """The numbers a plain text writes."""
    return [float(m.replace("\u2212", "-")) * 10.0 ** int((p or "0").translate(_POWER)) for m, p in _NUMBER.findall(text)]


def hint_ladder(variant, part_id: str, worked=None, answered: frozenset[str] = frozenset()) -> tuple[Hint, ...]:
    """Every hint of the part, in the order they are given, as they may be shown while only the parts
    `answered` have been answered right; `worked` is the variant's solution if already made."""
    part = variant.template.part(part_id)
    if part.hints:  # a template's texts name given values only
        return tuple(Hint(text=variant.fill(h)) for h in part.hints)
    lines = (worked or solution(variant)).lines
    end = next((i for i, line in enumerate(lines) if part_id in line.parts), None)
    if end is None:
        return ()
    start = max((i + 1 for i, line in enumerate(lines[:end]) if line.parts), default=0)
    needed = _worked_from(variant.steps, lines[end].name)
    chosen = [(line, True) for line in lines[start:end] if not needed or line.name in needed] + [(lines[end], False)]
    # which lines make the ladder does not depend on what is answered, so a hint keeps its number
    everything = Withheld(variant)
    withheld = Withheld(variant, answered) if answered else everything
    ladder = []
    for line, result in chosen:
        hidden = shown(line, everything, result)
        if hidden is not None:
            ladder.append(Hint(line=hidden if withheld is everything else shown(line, withheld, result)))
    return tuple(ladder)


def shown(line: WorkLine, withheld: Withheld, result: bool = True) -> WorkLine | None:
    """The line with every number that would give an answer away taken out (and, without `result`,
    its value too); None when nothing of it is left to show."""
    values = line.values if result and not any(withheld.gives_away(_as_shown(q.value, q.sig)) for q in line.values) else ()
    substituted = _substituted(line, withheld)
    if line.formula is None and substituted is None:
        return None if not values else dataclasses.replace(line, note=_note(line, withheld), parts=())
    return dataclasses.replace(line, substituted=substituted, values=values, note=_note(line, withheld),
                               parts=line.parts if result and values else ())


def _substituted(line: WorkLine, withheld: Withheld) -> Filled | None:
    """The formula with numbers, those of steps that give an answer away left as their symbols; None
    when no number is left (the formula alone says it). A given's number is always shown: it is on the
    sheet."""
    filled = line.substituted
    if filled is None:
        return None
    fills, kept = [], 0
    for slot, fill in zip(filled.formula.slots, filled.fills):
        if isinstance(fill, Number) and slot.name not in withheld.givens and withheld.gives_away(displayed(fill)):
            fill = withheld.symbols[slot.name]
        kept += isinstance(fill, Number)
        fills.append(fill)
    return dataclasses.replace(filled, fills=tuple(fills)) if kept else None


def _note(line: WorkLine, withheld: Withheld) -> str:
    return "" if line.note and withheld.in_text(line.note) else line.note


def _as_shown(value, sig: int):
    """A value as a worked line writes it (to its `sig` figures), so that what is checked is what is read."""
    if isinstance(value, bool) or not isinstance(value, float):
        return value
    mantissa, exponent = number_parts(value, sig)
    return float(mantissa) * 10.0 ** int(exponent or 0)


def displayed(number: Number) -> float:
    """A number of a formula as it is written (rounded as shown, in the unit shown)."""
    if number.exact is not None:
        return float(number.exact)
    mantissa, exponent = number_parts(number.value, number.sig)
    return float(mantissa) * 10.0 ** int(exponent or 0)


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
