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
from exgen.mistake_messages import message_for
from exgen.template import PartSpec

Matcher = Callable[[Any, Any], bool]


def template_mistake(part: PartSpec, value: Any, recorded: Iterable[Mapping[str, Any]],
                     matches: Matcher) -> Mistake | None:
    """The first recorded mistake value the answer matches: those the template lists, in its order,
    then any others the solver records."""
    recorded = [r for r in recorded if r]
    says = {m.when: m.say for m in part.mistakes}
    names = list(says) + [n for r in recorded for n in r if n not in says]
    for name in dict.fromkeys(names):
        for values in recorded:
            if name in values and _safe_match(matches, value, values[name]):
                return Mistake(name, message_for(name, says.get(name, "")))
    return None


def generic_mistake(part: PartSpec, given: Given, expected: Any) -> Mistake | None:
    """The first generic slip of the part's type that explains a wrong answer."""
    try:
        return answer_type(part).slip(given, expected, part)
    except (ExgenError, TypeError, ValueError, ArithmeticError):
        return None


def _safe_match(matches: Matcher, given, expected) -> bool:
    try:
        return bool(matches(given, expected))
    except (TypeError, ValueError, ArithmeticError):
        return False
