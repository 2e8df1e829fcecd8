"""Recording a known slip only where a student's answer could show it."""
from __future__ import annotations

import math

#: Keep a known slip this far from the right answer (parts are graded at 1 %).
APART = 0.03


def record(d, step: str, mistake: str, value: float, apart: float = APART) -> None:
    """Record `mistake` on `step` unless its value lies within `apart` of the step's own value
    (where the grader would accept it as right, or could not tell it from rounding)."""
    right = d.value_of(step)
    if math.isfinite(value) and abs(value - right) > apart * abs(right):
        d.mistake(step, mistake, value)
