"""Whether a shaft is balanced statically, dynamically, or not at all (course text §2.1).

Static balance is Σ m r = 0 (eq 2.1), the force polygon closed; dynamic balance needs the couple
polygon, Σ m r l = 0 about any plane, closed as well. A shaft balanced dynamically is balanced
statically too; one balanced statically may not be balanced dynamically.
"""
from __future__ import annotations

import math

from .polygons import components, magnitude_formula

PLANES = "ABCD"
VERDICTS = ("both", "static only", "neither")
#: A sum below this share of its terms is a closed polygon (float noise).
CLOSED = 1e-9


def angles_of(arrangement: str) -> list[float]:
    """'0, 180, 180, 0' -> the four masses' angles in radians."""
    return [math.radians(float(a)) for a in str(arrangement).split(",")]


def balance_kind(p, d):
    """Σ m r and Σ m r l about plane A, then which polygons close."""
    masses = {"A": p.m, "B": p.m, "C": p.m, "D": p.mD}
    for k, (tag, angle) in enumerate(zip(PLANES, angles_of(p.arrangement))):
        d.step(f"theta{tag}", angle, "rad", symbol=rf"\theta_{tag}", note=f"mass {tag}'s angle, as given")
        d.step(f"l{tag}", k * p.a, "m", symbol=f"l_{tag}", formula=rf"{k}\,@a" if k > 1 else ("@a" if k else ""),
               note="from plane A" if k else "plane A is the reference")
        mass = "m" if tag != "D" else "mD"
        d.step(f"mr{tag}", masses[tag] * p.r, "kg*m", symbol=f"m_{tag} r", formula=rf"@{mass}\,@r")
        d.step(f"mrl{tag}", d.value_of(f"mr{tag}") * d.value_of(f"l{tag}"), "kg*m^2", symbol=f"m_{tag} r\\,l_{tag}",
               formula=rf"@mr{tag}\,@l{tag}")
    rows = [[tag, f"@m" if tag != "D" else "@mD", "@r", f"@l{tag}", f"@theta{tag}", f"@mr{tag}", f"@mrl{tag}"]
            for tag in PLANES]
    head = [("Plane",), ("$m$", "kg"), ("$r$", "m"), ("$l$", "m"), (r"$\theta$", "rad"), ("$m r$", "kg*m"),
            ("$m r l$", "kg*m^2")]
    fx, fy = components(d, "F", r"\Sigma m r", [(f"mr{t}", f"theta{t}") for t in PLANES], "kg*m",
                        "the force polygon", table=("Forces: the masses resolved", head, rows, "m r"))
    mx, my = components(d, "M", r"\Sigma m r l", [(f"mrl{t}", f"theta{t}") for t in PLANES], "kg*m^2",
                        "the couple polygon about plane A",
                        table=("Couples about plane A", [head[0], head[6], head[4]],
                               [[t, f"@mrl{t}", f"@theta{t}"] for t in PLANES], "m r l"))
    force = d.step("F", math.hypot(fx, fy), "kg*m", symbol=r"\left|\Sigma m r\right|", formula=magnitude_formula("F_0", "F_90"),
                   note="zero if the force polygon closes (eq 2.1)")
    couple = d.step("C", math.hypot(mx, my), "kg*m^2", symbol=r"\left|\Sigma m r l\right|",
                    formula=magnitude_formula("M_0", "M_90"), note="zero if the couple polygon closes too")
    static = force <= CLOSED * sum(d.value_of(f"mr{t}") for t in PLANES)
    dynamic = static and couple <= CLOSED * sum(abs(d.value_of(f"mrl{t}")) for t in PLANES)
    verdict = VERDICTS[0 if dynamic else 1 if static else 2]
    reason = ("both polygons close" if dynamic else "the force polygon closes, the couple polygon does not" if static
              else "the force polygon does not close: not even statically balanced")
    d.step("verdict", verdict, "", symbol=r"\text{balance}", note=reason)
    d.mistake("F", "scalar_sum", sum(d.value_of(f"mr{t}") for t in PLANES))
    d.mistake("C", "scalar_sum", sum(d.value_of(f"mrl{t}") for t in PLANES))
    if verdict == "static only":
        d.mistake("verdict", "static_is_enough", "both")
