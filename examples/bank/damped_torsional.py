"""The course's own solver and figure for a flywheel on a shaft with a torsional damper (course text §6.6.2).

The text's equation of motion, θ̈ + (C/I) θ̇ + (q/I) θ = 0 (eq. 6.43), with C/I = 2ζω_n and q/I = ω_n²:
critical damping is C_c = 2 I ω_n, ζ = C/C_c, and the damped frequency ω_d = ω_n √(1 − ζ²) (eq. 6.44).
The physics is exgen's own (exgen.mechanics.vibration); this file only orders it into the steps a key shows.
"""
from __future__ import annotations

import math

from exgen.figures.svg import LINE, THIN, Drawing
from exgen.figures.symbols import dashpot, dimension, ground
from exgen.figures.values import shown
from exgen.mechanics import vibration as vb

#: Damping ratios a torsional damper on a flywheel gives: light enough to oscillate, heavy enough to show.
ZETA = (0.1, 0.6)


def damped_torsional(p, d):
    """I = m k², J, q = G J / l, ω_n and f_n, C_c = 2 I ω_n, ζ = C / C_c and f_d = f_n √(1 − ζ²)."""
    inertia = d.step("I", p.m * p.k ** 2, "kg*m^2", formula=r"@m\,@k^2", note="the flywheel, from its radius of gyration")
    j = d.step("J", vb.polar_second_moment(p.d), "m^4", formula=r"\frac{\pi\,@d^4}{32}",
               note="the shaft's polar second moment of area")
    q = d.step("q", vb.torsional_stiffness(p.G, p.d, p.l), "N*m", symbol="q", formula=r"\frac{@G\,@J}{@l}",
               note="torque per radian of twist")
    d.mistake("q", "bending_for_polar", p.G * vb.second_moment(p.d) / p.l)
    omega = d.step("omega_n", vb.natural_speed(q, inertia), "rad/s", symbol=r"\omega_n",
                   formula=r"\sqrt{\frac{@q}{@I}}", note=r"from $I\ddot\theta + q\theta = 0$, the damper left out")
    f_n = d.step("f_n", vb.frequency(omega), "Hz", symbol="f_n", formula=r"\frac{@omega_n}{2\pi}")
    d.mistake("f_n", "omega_for_f", omega)
    d.mistake("f_n", "sqrt_missing", q / inertia / (2 * math.pi))
    # what follows is worked from f_n, the step (b) answers, so a student's own (b) carries forward
    cc = d.step("C_c", vb.critical_damping(inertia, 2 * math.pi * f_n), "N*m*s", symbol="C_c",
                formula=r"2\,@I \times 2\pi\,@f_n", note=r"critical damping: $C/I = 2\zeta\omega_n$ with $\zeta = 1$")
    d.mistake("C_c", "factor_two_missing", inertia * 2 * math.pi * f_n)
    zeta = d.step("zeta", vb.damping_ratio(p.C, cc), "", symbol=r"\zeta", formula=r"\frac{@C}{@C_c}")
    d.require(ZETA[0] <= zeta <= ZETA[1], "a damping ratio outside 0.1-0.6: hardly damped, or hardly oscillating")
    f_d = d.step("f_d", vb.damped_speed(f_n, zeta), "Hz", symbol="f_d", formula=r"@f_n\,\sqrt{1 - @zeta^2}",
                 note=r"$\omega_d = \omega_n\sqrt{1 - \zeta^2}$ (eq. 6.44), in cycles per second")
    d.mistake("f_d", "omega_for_f", 2 * math.pi * f_d)
    d.mistake("f_d", "damping_ignored", f_n)
    return f_d


def flywheel_damper(variant) -> str:
    """The shaft held at its left end, the flywheel on its right end, and the damper acting on the wheel."""
    length_px = 120 + 160 * min(1.0, shown(variant, "l").si / 1.5)
    wheel = 70 + 90 * min(1.0, shown(variant, "k").si / 0.8)
    shaft = 6 + 10 * min(1.0, shown(variant, "d").si / 0.08)
    drawing = Drawing()
    ground(drawing, (0, 0), (0, 1), wheel * 0.8, side=1)
    drawing.polygon([(0, -shaft / 2), (length_px, -shaft / 2), (length_px, shaft / 2), (0, shaft / 2)],
                    fill="#ececec", width=LINE)
    drawing.polygon([(length_px, -wheel / 2), (length_px + 20, -wheel / 2), (length_px + 20, wheel / 2),
                     (length_px, wheel / 2)], fill="#d8d8d8", width=LINE)
    drawing.line((-6, 0), (length_px + 34, 0), THIN, dash="10 3 2 3", cls="axis")
    dashpot(drawing, (length_px + 10, wheel / 2), (length_px + 10, wheel / 2 + 70))
    ground(drawing, (length_px - 20, wheel / 2 + 70), (1, 0), 60, side=-1)
    dimension(drawing, (0, -shaft / 2), (length_px, -shaft / 2), shown(variant, "l").label("l"), side=1,
              offset=wheel / 2 - shaft / 2 + 14)
    drawing.place([((length_px * 0.45, shaft / 2 + 18), "middle")], shown(variant, "d").label("d"))
    drawing.place([((length_px + 40, -wheel / 2 + 10), "start")], shown(variant, "m").label("m"))
    drawing.place([((length_px + 40, -wheel / 2 + 30), "start")], shown(variant, "k").label("k"))
    drawing.place([((length_px + 30, wheel / 2 + 40), "start")], shown(variant, "C").label("C"))
    return drawing.svg("Flywheel on a shaft fixed at its far end, with a torsional damper")
