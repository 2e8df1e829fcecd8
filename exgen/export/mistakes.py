"""A gap's named mistakes in the order a learning system must test them to name the mistake exgen's grader
names.

A learning system gives an answer the feedback of the first wrong answer whose range holds it. exgen's
grader, where several mistakes' values lie within the tolerance of an answer (two slips 0.15 % apart),
names the one the answer stays close to as the tolerance narrows (graders.mistakes.template_mistake),
the first listed of those left. So where ranges overlap, each mistake is listed again at each narrower
tolerance, narrowest first: the first range holding an answer is then the narrowest any holds it in,
and of those the first listed, as the grader decides. Mistakes whose ranges touch no other's are listed
once.
"""
from __future__ import annotations

from dataclasses import replace

from ..answertypes.lms import Wrong

#: The fractions of a mistake's tolerance the grader narrows through (graders.mistakes.NARROWING; a
#: test keeps the two equal).
NARROWING = (0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625)


def ordered_wrongs(wrongs: list[Wrong]) -> tuple[Wrong, ...]:
    """`wrongs` (in the order the grader tries them, each with its full tolerance) as a learning system
    must test them."""
    overlapping = [w for w in wrongs if any(o is not w and _overlap(w, o) for o in wrongs)]
    if not overlapping:
        return tuple(wrongs)
    narrowed = [replace(w, tolerance=w.tolerance * widen) for widen in reversed(NARROWING) for w in overlapping]
    return tuple(narrowed + list(wrongs))


def _overlap(a: Wrong, b: Wrong) -> bool:
    return abs(a.value - b.value) <= a.tolerance + b.tolerance
