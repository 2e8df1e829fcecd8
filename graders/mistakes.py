"""Name the mistake behind a wrong answer, so feedback says what went wrong and not only that it did.

Two sources, tried in order: (1) the template's mistakes, whose values the solver records
(`d.mistake(step, name, value)`) and which match with the part's own tolerance; the template's
`say:` wins over the default message (exgen/data/mistakes.yaml); (2) the generic slips of the
part's answer type (units confused, a wrong prefix, the sign, an angle half a turn out, rounding).
"""
from __future__ import annotations

from typing import Any, Callable, Iterable, Mapping

from exgen.answertypes import answer_type
from exgen.answertypes.base import Given, Mistake
from exgen.errors import ExgenError
from exgen.load.mistake_messages import message_for
from exgen.load.template import PartSpec

#: (given, expected, widen) -> whether given is expected within the part's tolerance times widen.
Matcher = Callable[..., bool]
#: The tolerances, as fractions of the part's, that tell apart slips whose values are close together.
NARROWING = (0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625)


def template_mistake(part: PartSpec, value: Any, recorded: Iterable[Mapping[str, Any]],
                     matches: Matcher, write: Callable[[str], str] = str) -> Mistake | None:
    """The recorded mistake the answer matches: those the template lists, in its order, then any others
    the solver records. Where the values of several lie within the tolerance of the answer (two slips that
    land 0.5 % apart), the one the answer stays close to as the tolerance narrows is named, so that a
    student who typed one slip's value to four figures is not told of the other; equal values name the
    first listed. `write` writes the message with the variant the answer belongs to (Variant.fill), so what
    it says of the draw is the student's own sheet's."""
    recorded = [r for r in recorded if r]
    says = {m.when: m.say for m in part.mistakes}
    names = list(says) + [n for r in recorded for n in r if n not in says]
    candidates = [(name, values[name]) for name in dict.fromkeys(names) for values in recorded
                  if name in values and _safe_match(matches, value, values[name])]
    for widen in NARROWING:
        if len(candidates) < 2:
            break
        closer = [(name, v) for name, v in candidates if _safe_match(matches, value, v, widen)]
        if not closer:
            break
        candidates = closer
    if not candidates:
        return None
    name = candidates[0][0]
    return Mistake(name, write(message_for(name, says.get(name, ""))))


def generic_mistake(part: PartSpec, given: Given, expected: Any) -> Mistake | None:
    """The first generic slip of the part's type that explains a wrong answer."""
    try:
        return answer_type(part).slip(given, expected, part)
    except (ExgenError, TypeError, ValueError, ArithmeticError):
        return None


def _safe_match(matches: Matcher, given, expected, widen: float = 1.0) -> bool:
    """An overflow or a value outside a number's domain is no match; any other error is a defect, raised."""
    try:
        return bool(matches(given, expected, widen))
    except (ValueError, ArithmeticError):
        return False
