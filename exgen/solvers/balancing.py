"""Worked derivations for the balancing templates (course text chapter 2)."""
from __future__ import annotations

import math

from ..mechanics import balancing as mb


def static_balance(p, d):
    """Example 2.1: one plane, three masses; the balancing m·r and where it goes."""
    masses = [(p.m1, p.r1, 0.0), (p.m2, p.r2, p.theta2), (p.m3, p.r3, p.theta3)]
    for i, (m, r, _) in enumerate(masses, start=1):
        d.step(f"mr{i}", m * r, "kg*m", symbol=rf"m_{i} r_{i}", formula=rf"@m{i}\,@r{i}")
    x = d.step("sum_x", sum(m * r * math.cos(a) for m, r, a in masses), "kg*m", symbol=r"R_x",
               formula=r"@mr1 + @mr2 \cos @theta2 + @mr3 \cos @theta3", note=r"resultant of $m r \cos\theta$")
    y = d.step("sum_y", sum(m * r * math.sin(a) for m, r, a in masses), "kg*m", symbol=r"R_y",
               formula=r"@mr2 \sin @theta2 + @mr3 \sin @theta3", note=r"resultant of $m r \sin\theta$")
    size, angle = mb.polar(-x, -y)
    size = d.step("Bb", size, "kg*m", symbol=r"B\,b", formula=r"\sqrt{@sum_x^2 + @sum_y^2}",
                  note="the balancing m·r closes the force polygon")
    angle = d.step("theta_b", angle, "rad", symbol=r"\theta_b", formula=r"\tan^{-1}\frac{-@sum_y}{-@sum_x}",
                   note="opposite the resultant: in the quadrant of $(-R_x, -R_y)$")
    d.mistake("Bb", "scalar_sum", sum(m * r for m, r, _ in masses))
    d.step("B", size / p.b, "kg", formula=r"\frac{@Bb}{@b}", note="the balancing mass at the radius given")
    d.mistake("B", "scalar_sum", sum(m * r for m, r, _ in masses) / p.b)
    d.mistake("theta_b", "resultant_not_balance", angle + math.pi)
