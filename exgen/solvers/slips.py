"""Recording a known slip only where a student's answer could show it."""
from __future__ import annotations

import math

def record(d, step: str, mistake: str, value: float) -> None:
    """Record `mistake` on `step`, named only in draws where it lands apart from the answer (where the
    grader would otherwise accept it as right, or could not tell it from rounding)."""
    if math.isfinite(value):
        d.mistake(step, mistake, value, if_apart=True)
