"""Worked derivations for spring-loaded governors (course text §4.5, 4.8; Example 4.3, Problem 4.6).

Hartnell: moments about each bell crank's fulcrum, F·a = ½ (M g + S ± f)·b (eq 4.4), the moment
of the ball's weight and the change in the arms' lengths neglected, as the text does; friction
adds to the sleeve load while the sleeve rises. A spring-controlled governor's controlling force
is a straight line F = slope·r + intercept: stable if it cuts the force axis below the origin,
isochronous through it, unstable above it (§4.8).
"""
from __future__ import annotations

import math

from ..mechanics import governors as gv

G = gv.G
RPM = 2 * math.pi / 60


def hartnell_two_springs(p, d):
    """Example 4.3: the sleeve starts to rise at a speed; the force and stiffness of a second spring
    acting on the sleeve through a lever, the first spring's stiffness known."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    r0 = d.step("r_0", p.b + p.c, "m", formula=r"@b + @c", note="ball radius with the ball arm vertical")
    theta = d.step("theta_1", gv.bell_crank_angle(p.r1, r0, p.a), "rad", symbol=r"\theta_1",
                   formula=r"\sin^{-1}\frac{@r1 - @r_0}{@a}", note="the bell crank's turn")
    x1 = d.step("x_1", p.b * math.sin(theta), "m", formula=r"@b\sin @theta_1", note="the sleeve's rise: spring 1 compresses this much")
    p1 = d.step("P_1", p.K1 * x1, "N", formula=r"@K1\,@x_1")
    force = d.step("F_1", p.m * p.N ** 2 * p.r1, "N", formula=r"@m\,@N^2\,@r1")
    sleeve = d.step("P_2s", gv.hartnell_sleeve_force(force, p.a, p.b) - p.Ms * G - p1 - p.f, "N", symbol=r"P_2'",
                    formula=r"\frac{2\,@F_1\,@a\cos @theta_1}{@b\cos @theta_1} - @Ms\,@g - @P_1 - @f",
                    note=r"moments about the fulcrum: $\tfrac{1}{2}(m_s g + P_1 + P_2' + f)\,b\cos\theta = F a\cos\theta$; friction resists the rise")
    d.require(sleeve > 0, "no pull is left for the second spring")
    tension = d.step("P_2", sleeve * p.L1 / p.L2, "N", formula=r"@P_2s\,\frac{@L1}{@L2}",
                     note="moments about the lever's fulcrum")
    d.mistake("P_2", "friction_wrong_side", (sleeve + 2 * p.f) * p.L1 / p.L2, if_apart=True)
    d.mistake("P_2", "lever_inverted", sleeve * p.L2 / p.L1)
    d.mistake("P_2", "arms_inverted",
                  (gv.hartnell_sleeve_force(force, p.b, p.a) - p.Ms * G - p1 - p.f) * p.L1 / p.L2, if_apart=True)
    d.mistake("P_2", "rpm_as_rad_s",
              (gv.hartnell_sleeve_force(p.m * (p.N / RPM) ** 2 * p.r1, p.a, p.b) - p.Ms * G - p1 - p.f) * p.L1 / p.L2)
    x2 = d.step("x_2", x1 * p.L2 / p.L1, "m", formula=r"@x_1\,\frac{@L2}{@L1}", note="the lever moves spring 2 less")
    d.step("K2", tension / x2, "N/m", symbol=r"K_2", formula=r"\frac{@P_2}{@x_2}")
    d.mistake("K2", "lever_inverted", tension / (x1 * p.L1 / p.L2))
    d.mistake("K2", "sleeve_travel_for_spring", tension / x1)


def hartnell_spring(p, d):
    """A Hartnell governor between two radii and speeds: the spring force at each, and the spring's stiffness."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    forces = []
    for tag, r_name, w_name in (("1", "r1", "N1"), ("2", "r2", "N2")):
        r, w = getattr(p, r_name), getattr(p, w_name)
        force = d.step(f"F_{tag}", p.m * w ** 2 * r, "N", symbol=rf"F_{tag}", formula=rf"@m\,@{w_name}^2\,@{r_name}")
        spring = d.step(f"S_{tag}", gv.hartnell_sleeve_force(force, p.a, p.b) - p.M * G - p.f, "N", symbol=rf"S_{tag}",
                        formula=rf"\frac{{2\,@F_{tag}\,@a}}{{@b}} - @M\,@g - @f",
                        note=r"moments about the fulcrum: $F a = \tfrac{1}{2}(M g + S + f)\,b$; the sleeve is rising" if tag == "1" else "")
        d.mistake(f"S_{tag}", "friction_wrong_side", spring + 2 * p.f, if_apart=True)
        d.mistake(f"S_{tag}", "arms_inverted", gv.hartnell_sleeve_force(force, p.b, p.a) - p.M * G - p.f, if_apart=True)
        d.mistake(f"S_{tag}", "sleeve_weight_forgotten", spring + p.M * G)
        d.mistake(f"S_{tag}", "one_ball", force * p.a / p.b - p.M * G - p.f)
        d.mistake(f"S_{tag}", "rpm_as_rad_s", 2 * p.m * (w / RPM) ** 2 * r * p.a / p.b - p.M * G - p.f)
        forces.append(spring)
    lift = d.step("lift", gv.sleeve_lift(p.r1, p.r2, p.a, p.b), "m", symbol=r"x",
                  formula=r"(@r2 - @r1)\,\frac{@b}{@a}", note="the sleeve's rise, which compresses the spring")
    d.step("s", (forces[1] - forces[0]) / lift, "N/m", symbol=r"s", formula=r"\frac{@S_2 - @S_1}{@lift}")
    d.mistake("s", "lift_not_scaled", (forces[1] - forces[0]) / (p.r2 - p.r1), if_apart=True)
    d.mistake("s", "arms_inverted", (forces[1] - forces[0]) / ((p.r2 - p.r1) * p.a / p.b), if_apart=True)


#: Why the governor is what it is, by the sign of the controlling-force line's intercept b (§4.8).
_STABILITY_REASON = {
    gv.STABLE: "b < 0: the line cuts the force axis below the origin, so F/r rises with r",
    gv.ISOCHRONOUS: "b = 0: the line passes through the origin, so F/r is the same at every radius",
    gv.UNSTABLE: "b > 0: the line cuts the force axis above the origin, so F/r falls as r rises",
}


def spring_controlled(p, d):
    """Problem 4.6: a straight controlling-force line through two measured points: the radius at a speed,
    the change of spring load that makes it isochronous, and the speed it would then run at."""
    line = gv.controlling_line(p.F1, p.r1, p.F2, p.r2)
    slope = d.step("k_F", line[0], "N/m", symbol=r"a", formula=r"\frac{@F2 - @F1}{@r2 - @r1}",
                   note="F = a r + b, a straight controlling-force line")
    intercept = d.step("b_F", line[1], "N", symbol=r"b", formula=r"@F1 - @k_F\,@r1")
    kind = gv.stability(intercept, p.F2)
    d.step("kind", kind, "", symbol=r"\text{governor}", note=_STABILITY_REASON[kind])
    d.mistake("kind", "stability_inverted", {gv.STABLE: gv.UNSTABLE, gv.UNSTABLE: gv.STABLE}.get(kind, gv.STABLE))
    d.require(abs(intercept) >= 0.05 * p.F1, "a line too near the origin to tell stable from isochronous")
    radius = d.step("r", gv.radius_at_speed(p.m, p.N, slope, intercept), "m",
                    formula=r"\frac{@b_F}{@m\,@N^2 - @k_F}", note=r"where $m\omega^2 r = a r + b$")
    d.mistake("r", "rpm_as_rad_s", gv.radius_at_speed(p.m, p.N / RPM, slope, intercept))
    d.step("change", abs(intercept), "N", symbol=r"\Delta F", formula=r"-@b_F" if intercept < 0 else r"@b_F",
           note="shift the line through the origin: the spring load changes by |b| at every radius")
    d.step("way", "increase" if intercept < 0 else "decrease", "", symbol=r"\text{spring load}",
           note="b < 0: add |b| to every force" if intercept < 0 else "b > 0: take b off every force")
    d.mistake("way", "opposite", "decrease" if intercept < 0 else "increase")
    d.step("omega_iso", gv.isochronous_speed(p.m, slope), "rad/s", symbol=r"\omega_{\mathrm{iso}}",
           formula=r"\sqrt{\frac{@k_F}{@m}}", note="F = a r: m ω² r = a r at every radius")
    d.mistake("omega_iso", "mass_not_divided", math.sqrt(slope))
