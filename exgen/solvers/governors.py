"""Worked derivations for Watt, Porter and Proell governors (course text §4.2-4.4, 4.7; Examples 4.1-4.2,
Problems 4.1-4.5).

The text's method: moments about I, the instantaneous centre of the lower arm, where the upper
arm's line meets the horizontal through the sleeve pivot Y. For each ball X, with Z below it on
that horizontal,

    F·XZ = m g·IZ + (M g ± f)/2 · IY,    F = m ω² r,

the friction f adding to the sleeve load while the sleeve rises and relieving it while it falls
(eq 4.6). The sensitivity is the text's, ω/(ω₁ − ω₂) (eq 4.5). g = 9.81 m/s².
"""
from __future__ import annotations

import dataclasses
import math

from ..mechanics import governors as gv

#: The points the moments are taken about, which the figure does not mark: said where the key first names them.
POINTS = ("X is the ball's centre; I, the lower arm's instantaneous centre, where the upper arm's line meets "
          "the horizontal through the sleeve pivot Y; Z, the point of that horizontal below X")

PROELL_POINTS = ("I is the lower arm's instantaneous centre, where the upper arm's line meets the horizontal "
                 "through the sleeve pivot C; Z, the point of that horizontal below the joint B")


def _with_points(d, note: str) -> str:
    """`note`, with the points X, I, Z and Y said in words the first time a step names them."""
    if any(s.note and POINTS in s.note for s in d.steps):
        return note
    return f"{note}. {POINTS}" if note else POINTS

G = gv.G
RPM = 2 * math.pi / 60


def watt_height(p, d):
    """Problem 4.1: the height of a Watt governor at a speed, how far it falls when the speed rises,
    and the angle of its arms."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    h1 = d.step("h_1", gv.watt_height(p.N1), "m", formula=r"\frac{@g}{@N1^2}", note="eq 4.1 with the arms pivoted on the axis")
    d.mistake("h_1", "rpm_as_rad_s", G / (p.N1 / RPM) ** 2)
    h2 = d.step("h_2", gv.watt_height(p.N2), "m", formula=r"\frac{@g}{@N2^2}")
    d.step("dh", h1 - h2, "m", symbol=r"h_1 - h_2", formula=r"@h_1 - @h_2", note="the balls rise as the speed rises")
    d.mistake("dh", "rpm_as_rad_s", G / (p.N1 / RPM) ** 2 - G / (p.N2 / RPM) ** 2)
    d.mistake("dh", "height_not_change", h2)
    d.require(h1 <= 0.9 * p.l, "arms too short for the height")
    alpha = d.step("alpha", math.acos(h1 / p.l), "rad", symbol=r"\alpha", formula=r"\cos^{-1}\frac{@h_1}{@l}",
                   note="the arm is the hypotenuse, h the height below its pivot")
    d.mistake("alpha", "sine_for_cosine", math.asin(h1 / p.l))


def _position(p, d, linkage: gv.Linkage, tag: str, r_name: str, r: float, sleeve_force: float,
              sleeve_formula: str, extension: float = 0.0, tilt: float = 0.0, note: str = "") -> tuple[float, gv.LeverArms]:
    """One position of a Porter (or Proell) governor, worked by moments about I: ω there, and the lever arms."""
    at = gv.pose(linkage, r)
    d.step(f"alpha_{tag}", at.alpha, "rad", symbol=rf"\alpha_{tag}",
           formula=rf"\sin^{{-1}}\frac{{@{r_name} - @e_u}}{{@l}}", note=note)
    d.step(f"beta_{tag}", at.beta, "rad", symbol=rf"\beta_{tag}", formula=rf"\sin^{{-1}}\frac{{@{r_name} - @e_l}}{{@l}}")
    arms = gv.lever_arms(linkage, at, extension, tilt)
    if extension and not tilt:
        d.step(f"XZ_{tag}", arms.XZ, "m", symbol=rf"XZ_{tag}", formula=rf"@l\cos @beta_{tag} + @e",
               note=_with_points(d, "height of the ball above the sleeve pivots: the extension is upright"))
        d.step(f"x_{tag}", arms.ball_radius, "m", symbol=rf"r_{{b{tag}}}", formula=f"@{r_name}",
               note="the ball turns at the joint's radius")
    elif extension:
        d.step(f"XZ_{tag}", arms.XZ, "m", symbol=rf"XZ_{tag}",
               formula=rf"@l\cos @beta_{tag} + @e\cos(@beta_{tag} - @beta_1)",
               note=_with_points(d, "height of the ball above the sleeve pivots"))
        d.step(f"x_{tag}", arms.ball_radius, "m", symbol=rf"r_{{b{tag}}}", formula=rf"@{r_name} + @e\sin(@beta_{tag} - @beta_1)",
               note="radius of the ball's path: the extension turns with the lower arm")
    if extension:
        d.step(f"IZ_{tag}", arms.IZ, "m", symbol=rf"IZ_{tag}",
               formula=rf"@l\cos @beta_{tag}\tan @alpha_{tag}" + (rf" + @{r_name} - @x_{tag}" if tilt else ""))
    else:
        d.step(f"XZ_{tag}", arms.XZ, "m", symbol=rf"XZ_{tag}", formula=rf"@l\cos @beta_{tag}",
               note=_with_points(d, "height of the ball above the sleeve pivots"))
        d.step(f"IZ_{tag}", arms.IZ, "m", symbol=rf"IZ_{tag}", formula=rf"@XZ_{tag}\tan @alpha_{tag}")
    ball = "x_" + tag if extension else r_name
    d.step(f"IY_{tag}", arms.IY, "m", symbol=rf"IY_{tag}", formula=rf"@IZ_{tag} + @{ball} - @e_l",
           note="I to the sleeve pivot")
    d.step(f"F_{tag}", gv.centrifugal_force(p.m, sleeve_force, arms), "N", symbol=rf"F_{tag}",
           formula=rf"\frac{{@m\,@g\,@IZ_{tag} + \tfrac{{1}}{{2}}({sleeve_formula})\,@IY_{tag}}}{{@XZ_{tag}}}",
           note="moments about I: F·XZ = m g·IZ + ½(sleeve force)·IY")
    w = d.step(f"omega_{tag}", gv.equilibrium_speed(p.m, sleeve_force, arms), "rad/s", symbol=rf"\omega_{tag}",
               formula=rf"\sqrt{{\frac{{@F_{tag}}}{{@m\,@{ball}}}}}", note="F = m ω² r")
    return w, arms


def _linkage(p) -> gv.Linkage:
    """Equal upper and lower arms of length l, pivoted e_u and e_l off the axis."""
    return gv.Linkage(p.l, p.l, p.e_u, p.e_l)


def _within(d, linkage: gv.Linkage, *radii: float) -> None:
    """Geometry that closes: every radius reachable with the arms between 12° and 60° from the vertical."""
    for r in radii:
        ok = linkage.radius_range[0] < r < linkage.radius_range[1]
        d.require(ok, "the arms cannot reach that radius")
        if ok:
            at = gv.pose(linkage, r)
            d.require(math.radians(12) <= min(at.alpha, at.beta) and max(at.alpha, at.beta) <= math.radians(60),
                      "arms too near the vertical or the horizontal")


def porter_speed_range(p, d):
    """Problem 4.2: the range of speed between the extreme radii of a Porter governor, and its sleeve travel."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = _linkage(p)
    _within(d, linkage, p.r1, p.r2)
    load = d.step("W_s", p.M * G, "N", symbol=r"M g", formula=r"@M\,@g", note="the sleeve load")
    w1, _ = _position(p, d, linkage, "1", "r1", p.r1, load, "@W_s", note="at the least radius")
    w2, _ = _position(p, d, linkage, "2", "r2", p.r2, load, "@W_s", note="at the greatest radius")
    d.step("range", w2 - w1, "rad/s", symbol=r"\omega_2 - \omega_1", formula=r"@omega_2 - @omega_1")
    for tag, r in (("1", p.r1), ("2", p.r2)):
        same = gv.Linkage(p.l, p.l, p.e_u, p.e_u)
        d.mistake(f"omega_{tag}", "offset_ignored",
                  gv.equilibrium_speed(p.m, load, gv.lever_arms(same, gv.pose(same, r))), if_apart=True)
        arms = gv.lever_arms(linkage, gv.pose(linkage, r))
        d.mistake(f"omega_{tag}", "sleeve_moment_arm",
                  math.sqrt((p.m * G * arms.IZ + load / 2 * arms.IZ) / arms.XZ / (p.m * r)))
    lift = d.step("lift", gv.pose(linkage, p.r1).depth - gv.pose(linkage, p.r2).depth, "m", symbol=r"x",
                  formula=r"(@l\cos @alpha_1 + @l\cos @beta_1) - (@l\cos @alpha_2 + @l\cos @beta_2)",
                  note="how far the sleeve rises")
    d.mistake("lift", "one_arm_only", p.l * (math.cos(d.value_of("alpha_1")) - math.cos(d.value_of("alpha_2"))))
    _controlling_curve(p, d)


def _controlling_curve(p, d) -> None:
    """§4.8: the controlling force F = m ω² r at each extreme radius, and whether F/r rises with r (stable):
    the chord of the curve through the two points cuts the force axis below the origin."""
    forces = {}
    for tag, r in (("1", "r1"), ("2", "r2")):
        omega = d.value_of(f"omega_{tag}")
        # a step of its own (Fc): F_1 and F_2 are the moments' results, and one name is one step
        forces[tag] = d.step(f"Fc_{tag}", p.m * omega ** 2 * getattr(p, r), "N", symbol=f"F_{tag}",
                             formula=rf"@m\,@omega_{tag}^2\,@{r}", note="the controlling force on each ball (eq 4.7)")
        d.mistake(f"Fc_{tag}", "rpm_as_rad_s", p.m * (omega * 60 / (2 * math.pi)) ** 2 * getattr(p, r))
        d.mistake(f"Fc_{tag}", "speed_not_squared", p.m * omega * getattr(p, r))
    slope, intercept = gv.controlling_line(forces["1"], p.r1, forces["2"], p.r2)
    d.step("F_axis", intercept, "N", symbol="b", formula=r"@Fc_1 - \frac{@Fc_2 - @Fc_1}{@r2 - @r1}\,@r1",
           note="where the line through the two points cuts the force axis, r = 0")
    kind = gv.stability(intercept, forces["2"])
    reason = {gv.STABLE: "below the origin: F/r rises with r, one radius for each speed",
              gv.ISOCHRONOUS: "through the origin: F/r is the same at every radius",
              gv.UNSTABLE: "above the origin: F/r falls as r rises"}[kind]
    d.step("stability", kind, "", symbol=r"\text{governor}", note=reason)
    d.mistake("stability", "stability_inverted", {gv.STABLE: gv.UNSTABLE, gv.UNSTABLE: gv.STABLE}.get(kind, gv.STABLE))


def porter_friction(p, d):
    """Problem 4.5: the equilibrium speed of a Porter governor at a radius, and the range friction at the sleeve allows."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = _linkage(p)
    _within(d, linkage, p.r)
    load = d.step("W_s", p.M * G, "N", symbol=r"M g", formula=r"@M\,@g", note="the sleeve load")
    w, arms = _position(p, d, linkage, "0", "r", p.r, load, "@W_s", note="without friction")
    same = gv.Linkage(p.l, p.l, p.e_u, p.e_u)
    d.mistake("omega_0", "offset_ignored", gv.equilibrium_speed(p.m, load, gv.lever_arms(same, gv.pose(same, p.r))),
              if_apart=True)
    d.mistake("omega_0", "sleeve_moment_arm", math.sqrt((p.m * G * arms.IZ + load / 2 * arms.IZ) / arms.XZ / (p.m * p.r)))
    rising = d.step("omega_up", gv.equilibrium_speed(p.m, load + p.f, arms), "rad/s", symbol=r"\omega_{\max}",
                    formula=r"\sqrt{\frac{@m\,@g\,@IZ_0 + \tfrac{1}{2}(@W_s + @f)\,@IY_0}{@m\,@r\,@XZ_0}}",
                    note="about to rise: friction adds to the sleeve load")
    falling = d.step("omega_down", gv.equilibrium_speed(p.m, load - p.f, arms), "rad/s", symbol=r"\omega_{\min}",
                     formula=r"\sqrt{\frac{@m\,@g\,@IZ_0 + \tfrac{1}{2}(@W_s - @f)\,@IY_0}{@m\,@r\,@XZ_0}}",
                     note="about to fall: friction relieves it")
    d.step("range", rising - falling, "rad/s", symbol=r"\omega_{\max} - \omega_{\min}", formula=r"@omega_up - @omega_down")
    d.mistake("omega_up", "friction_wrong_side", falling)
    d.mistake("omega_down", "friction_wrong_side", rising)
    d.mistake("omega_up", "friction_doubled", gv.equilibrium_speed(p.m, load + 2 * p.f, arms))
    d.mistake("omega_down", "friction_doubled", gv.equilibrium_speed(p.m, load - 2 * p.f, arms))
    return w


def porter_sleeve_friction(p, d):
    """Problem 4.4: friction from the speed at which the sleeve starts to rise; the speeds at another angle."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = gv.Linkage(p.l, p.l, p.e, p.e)
    start = gv.pose_at_angle(linkage, p.alpha0)
    arms0 = gv.lever_arms(linkage, start)
    r0 = d.step("r_0", start.r, "m", formula=r"@e + @l\sin @alpha0")
    d.step("h_0", arms0.XZ, "m", formula=r"@l\cos @alpha0", note=_with_points(d, "XZ = h"))
    iz0 = d.step("IZ_0", arms0.IZ, "m", symbol=r"IZ_0", formula=r"@l\sin @alpha0", note="IY = 2 IZ: equal arms and offsets")
    force0 = d.step("F_0", p.m * p.N0 ** 2 * r0, "N", symbol=r"F_0", formula=r"@m\,@N0^2\,@r_0")
    friction = d.step("f", gv.sleeve_friction(force0, p.m, p.M, arms0), "N", symbol=r"f",
                      formula=r"\frac{@F_0\,@h_0 - @m\,@g\,@IZ_0}{@IZ_0} - @M\,@g",
                      note="the sleeve begins to rise: F₀h = m g·IZ + (M g + f)·IZ")
    d.mistake("f", "friction_wrong_side", -friction)
    d.mistake("f", "rpm_as_rad_s", gv.sleeve_friction(p.m * (p.N0 / RPM) ** 2 * r0, p.m, p.M, arms0))
    top = gv.pose_at_angle(linkage, p.alpha1)
    arms1 = gv.lever_arms(linkage, top)
    d.step("r_1", top.r, "m", formula=r"@e + @l\sin @alpha1")
    d.step("h_1", arms1.XZ, "m", formula=r"@l\cos @alpha1")
    d.step("IZ_1", arms1.IZ, "m", symbol=r"IZ_1", formula=r"@l\sin @alpha1")
    d.require(gv.centrifugal_force(p.m, p.M * G - friction, arms1) > 0,
              "no speed holds the top pose while the sleeve falls: friction outweighs the central load")
    up = d.step("omega_up", gv.equilibrium_speed(p.m, p.M * G + friction, arms1), "rad/s", symbol=r"\omega_{\max}",
                formula=r"\sqrt{\frac{(@m\,@g + @M\,@g + @f)\,@IZ_1}{@m\,@r_1\,@h_1}}",
                note="rising: friction adds to the sleeve load")
    down = d.step("omega_down", gv.equilibrium_speed(p.m, p.M * G - friction, arms1), "rad/s", symbol=r"\omega_{\min}",
                  formula=r"\sqrt{\frac{(@m\,@g + @M\,@g - @f)\,@IZ_1}{@m\,@r_1\,@h_1}}",
                  note="falling: friction relieves it")
    d.mistake("omega_up", "friction_wrong_side", down)
    d.mistake("omega_down", "friction_wrong_side", up)
    d.mistake("omega_up", "friction_ignored", gv.equilibrium_speed(p.m, p.M * G, arms1), if_apart=True)
    d.mistake("omega_down", "friction_ignored", gv.equilibrium_speed(p.m, p.M * G, arms1), if_apart=True)


def porter_dead_load(p, d):
    """Example 4.1: the central load for a speed at a given arm angle, and the sensitivity for a sleeve travel ±x."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = gv.Linkage(p.l, p.l, p.e, p.e)
    mid = gv.pose_at_angle(linkage, p.alpha)
    arms = gv.lever_arms(linkage, mid)
    h = d.step("h", arms.XZ, "m", formula=r"@l\cos @alpha", note=_with_points(d, "XZ = h"))
    iz = d.step("IZ", arms.IZ, "m", symbol=r"IZ", formula=r"@l\sin @alpha", note="ZY = IZ; IY = 2 IZ")
    r = d.step("r", iz + p.e, "m", formula=r"@IZ + @e")
    force = d.step("F", p.m * p.N ** 2 * r, "N", formula=r"@m\,@N^2\,@r")
    load = d.step("M", gv.sleeve_mass(force, p.m, arms), "kg", symbol=r"M",
                  formula=r"\frac{@F\,@h - @m\,@g\,@IZ}{@g\,@IZ}",
                  note=r"moments about I: $F\cdot XZ = m g\cdot IZ + \tfrac{1}{2} M g\cdot IY$")
    d.mistake("M", "rpm_as_rad_s", gv.sleeve_mass(p.m * (p.N / RPM) ** 2 * r, p.m, arms))
    d.mistake("M", "sleeve_moment_arm", gv.sleeve_mass(force, p.m, dataclasses.replace(arms, IY=arms.IZ)))
    if p.e > 0:
        d.mistake("M", "offset_ignored", gv.sleeve_mass(p.m * p.N ** 2 * iz, p.m, arms))
    speeds = []
    for tag, sign, word in (("1", -1, "rises"), ("2", 1, "falls")):
        hk = d.step(f"h_{tag}", h + sign * p.x / 2, "m", formula=rf"@h {'-' if sign < 0 else '+'} \frac{{@x}}{{2}}",
                    note=f"the sleeve {word} by x: each arm's height changes by half of it")
        d.require(0.25 * p.l < hk < 0.98 * p.l, "the sleeve's travel takes the arms past their working range")
        at = gv.pose_at_depth(linkage, 2 * hk)   # equal arms: the sleeve pivots lie 2h below the upper ones
        arms_k = gv.lever_arms(linkage, at)
        d.step(f"IZ_{tag}", arms_k.IZ, "m", symbol=rf"IZ_{tag}", formula=rf"\sqrt{{@l^2 - @h_{tag}^2}}")
        d.step(f"r_{tag}", at.r, "m", formula=rf"@IZ_{tag} + @e")
        w = d.step(f"omega_{tag}", gv.equilibrium_speed(p.m, load * G, arms_k), "rad/s", symbol=rf"\omega_{tag}",
                   formula=rf"\sqrt{{\frac{{(@m + @M)\,@g\,@IZ_{tag}}}{{@m\,@r_{tag}\,@h_{tag}}}}}",
                   note=rf"$F_{tag}\,h_{tag} = (m + M) g\,IZ_{tag}$")
        wrong_h = h + sign * p.x
        if 0 < wrong_h < p.l:
            wrong = gv.lever_arms(linkage, gv.pose_at_depth(linkage, 2 * wrong_h))
            d.mistake(f"omega_{tag}", "full_sleeve_travel", gv.equilibrium_speed(p.m, load * G, wrong), if_apart=True)
        speeds.append(w)
    sensitivity = d.step("S", gv.sensitivity(p.N, *speeds), "", symbol=r"S",
                         formula=r"\frac{@N}{@omega_1 - @omega_2}", note="eq 4.5, with ω the mean speed")
    d.mistake("S", "sensitivity_inverted", 1 / sensitivity)
    d.mistake("S", "rpm_as_rad_s", (p.N / RPM) / (speeds[0] - speeds[1]))


def proell_extension(p, d):
    """Example 4.2: the length of a Proell governor's vertical extension for a speed, and the upper-arm tension."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = gv.Linkage(p.l, p.l, p.e, p.e)
    d.require(linkage.radius_range[0] < p.r < linkage.radius_range[1], "the arms cannot reach that radius")
    mid = gv.pose(linkage, p.r)
    d.require(math.radians(15) <= mid.alpha <= math.radians(55), "arms too near the vertical or the horizontal")
    arms = gv.lever_arms(linkage, mid)
    iz = d.step("IZ", arms.IZ, "m", symbol=r"IZ", formula=r"@r - @e", note=f"IZ = ZC; IC = 2 IZ; the extension is vertical. {PROELL_POINTS}")
    bz = d.step("BZ", mid.h_lower, "m", symbol=r"BZ", formula=r"\sqrt{@l^2 - @IZ^2}")
    force = d.step("F", p.m * p.N ** 2 * p.r, "N", formula=r"@m\,@N^2\,@r")
    ext = d.step("AB", (p.m + p.M) * G * iz / force - bz, "m", symbol=r"AB",
                 formula=r"\frac{(@m + @M)\,@g\,@IZ}{@F} - @BZ",
                 note=r"moments about I: $F\,(AB + BZ) = m g\cdot IZ + \tfrac{1}{2} M g\cdot IC$")
    d.mistake("AB", "rpm_as_rad_s", (p.m + p.M) * G * iz / (p.m * (p.N / RPM) ** 2 * p.r) - bz)
    d.mistake("AB", "sleeve_moment_arm", (p.m + p.M / 2) * G * iz / force - bz)
    d.step("T", gv.upper_arm_tension(p.m, p.M * G, mid.alpha), "N", symbol=r"T_{BD}",
                     formula=r"\frac{@m\,@g + \tfrac{1}{2}\,@M\,@g}{@BZ / @l}",
                     note="the arm's vertical pull carries the ball and half the sleeve: T cos θ = m g + M g/2")
    d.mistake("T", "whole_sleeve_load", (p.m * G + p.M * G) / math.cos(mid.alpha))
    d.mistake("T", "sine_for_cosine", (p.m * G + p.M * G / 2) / math.sin(mid.alpha))


def proell_speeds(p, d):
    """Problem 4.3: a Proell governor's speeds at its least and greatest radii, the extensions vertical at the least."""
    d.constant("g", G, "m/s^2", note="standard gravity")
    linkage = _linkage(p)
    _within(d, linkage, p.r1, p.r2)
    load = d.step("W_s", p.M * G, "N", symbol=r"M g", formula=r"@M\,@g", note="the sleeve load")
    w1, _ = _position(p, d, linkage, "1", "r1", p.r1, load, "@W_s", extension=p.e,
                      note="least radius: the extension is vertical")
    tilt = gv.pose(linkage, p.r2).beta - gv.pose(linkage, p.r1).beta
    w2, arms2 = _position(p, d, linkage, "2", "r2", p.r2, load, "@W_s", extension=p.e, tilt=tilt,
                          note="greatest radius: the extension has turned with the lower arm")
    upright = gv.lever_arms(linkage, gv.pose(linkage, p.r2), p.e, 0.0)
    d.mistake("omega_2", "extension_kept_vertical", gv.equilibrium_speed(p.m, load, upright))
    d.mistake("x_2", "extension_kept_vertical", p.r2)
    for tag, r in (("1", p.r1), ("2", p.r2)):
        porter = gv.lever_arms(linkage, gv.pose(linkage, r))
        d.mistake(f"omega_{tag}", "porter_formula", gv.equilibrium_speed(p.m, load, porter))
    _joint_for_ball(p, d, linkage)


def _joint_for_ball(p, d, linkage: gv.Linkage) -> None:
    """The other reading of "the governor's radius": the ball, not the joint, at r₂; the joint then lies
    nearer the axis by e sin(β − β₁), β the lower arm's angle there, found by trial."""
    joint = gv.joint_radius_for_ball(linkage, p.e, p.r1, p.r2)
    d.require(gv.pose(linkage, joint).beta - gv.pose(linkage, p.r1).beta >= math.radians(4),
              "the joint hardly moves from where the ball is")
    d.step("r_j", joint, "m", symbol=r"r_2'",
           note=r"the joint's radius when the ball is at $r_2$, found by trial: the radius $r$ for which "
                r"$r + e \sin(\beta - \beta_1) = r_2$, with $\sin\beta = (r - e_l)/l$")
    d.step("beta_j", gv.pose(linkage, joint).beta, "rad", symbol=r"\beta_2'", formula=r"\sin^{-1}\frac{@r_j - @e_l}{@l}")
    d.step("x_j", joint + p.e * math.sin(d.value_of("beta_j") - d.value_of("beta_1")), "m", symbol=r"r_b'",
           formula=r"@r_j + @e\sin(@beta_j - @beta_1)", note=r"the check: the ball is at $r_2$")
    d.mistake("r_j", "extension_kept_vertical", p.r2)

