"""Worked derivations for balancing rotating masses (course text §2.1-2.2, Examples 2.1-2.5).

The method is the text's: a table of planes (m, r, m·r, l, m·r·l, θ), the moment polygon about
a reference plane (which removes that plane's unknown), then the force polygon. Distances l
are signed: a plane on the far side of the reference is negative, and losing that sign is the
commonest slip, so every solver records it where the data can show it.
"""
from __future__ import annotations

import math

from ..mechanics import balancing as mb
from .polygons import closing_angle, components, magnitude_formula

PI = math.pi
#: The course text's balancing table: a row per plane.
PLANE = [("Plane",), ("$m$", "kg"), ("$r$", "m"), ("$l$", "m"), (r"$\theta$", "rad"), ("$m r$", "kg*m"),
         ("$m r l$", "kg*m^2")]
FORCE = [("Plane",), ("$m r$", "kg*m"), (r"$\theta$", "rad")]


def _planes(tags, masses, radii, angles) -> list[list]:
    """Rows of the plane table: tag, m, r, l, θ (a number for a plane on the 0° line), m r, m r l."""
    return [[tag, f"@{m}", f"@{r}", f"@l{tag}", f"@{a}" if a else 0.0, f"@mr{tag}", f"@mrl{tag}"]
            for tag, m, r, a in zip(tags, masses, radii, angles)]


def _forces(tags, angles) -> list[list]:
    return [[tag, f"@mr{tag}", f"@{a}" if a else 0.0] for tag, a in zip(tags, angles)]


def static_balance(p, d):
    """Example 2.1: one plane, three masses; the balancing m·r and where it goes."""
    masses = [(p.m1, p.r1, 0.0), (p.m2, p.r2, p.theta2), (p.m3, p.r3, p.theta3)]
    for i, (m, r, _) in enumerate(masses, start=1):
        d.step(f"mr{i}", m * r, "kg*m", symbol=rf"m_{i} r_{i}", formula=rf"@m{i}\,@r{i}")
    rows = [[str(i), f"@m{i}", f"@r{i}", f"@theta{i}" if i > 1 else 0.0, f"@mr{i}"] for i in (1, 2, 3)]
    x, y = components(d, "F", "R", [("mr1", None), ("mr2", "theta2"), ("mr3", "theta3")],
                      "kg*m", "the resultant m·r",
                      table=("The masses, resolved", [("Mass",)] + PLANE[1:3] + [PLANE[4], PLANE[5]], rows, "m r"))
    size = d.step("Bb", math.hypot(x, y), "kg*m", symbol=r"B\,b", formula=magnitude_formula("F_0", "F_90"),
                  note="the balancing m·r closes the force polygon")
    angle = closing_angle(d, "theta_b", r"\theta_b", "F_0", "F_90")
    _removal(d, "theta_b", r"\theta_b")
    d.mistake("Bb", "scalar_sum", sum(m * r for m, r, _ in masses))
    d.step("B", size / p.b, "kg", formula=r"\frac{@Bb}{@b}", note="the balancing mass at the radius given")
    d.mistake("B", "scalar_sum", sum(m * r for m, r, _ in masses) / p.b)
    # the masses balanced as though all at one radius: the polygon of m, not of m·r
    d.mistake("B", "eccentricity_ignored", abs(sum(m * complex(math.cos(a), math.sin(a)) for m, _, a in masses)))
    d.mistake("theta_b", "resultant_not_balance", angle + PI)


def _removal(d, name: str, symbol: str) -> None:
    """Where the same m·r may be taken off instead of added: half a turn from the balancing mass."""
    angle = d.value_of(name)
    sign, value = ("-", angle - PI) if angle >= PI else ("+", angle + PI)
    d.step(f"{name}_remove", value, "rad", symbol=symbol + r"^{\mathrm{rem}}",
           formula=rf"@{name} {sign} 180^\circ", note="or remove the same m·r half a turn round")


def _plane(d, tag: str, m_name: str, r_name: str, l_value: float, l_formula: str, l_note: str = "",
           moment: bool = True):
    """Steps l, m·r and m·r·l of one plane of the table; returns (m·r, l)."""
    l = d.step(f"l{tag}", l_value, "m", symbol=f"l_{tag}", formula=l_formula, note=l_note)
    mr = d.step(f"mr{tag}", d.value_of(m_name) * d.value_of(r_name), "kg*m", symbol=f"m_{tag} r_{tag}",
                formula=rf"@{m_name}\,@{r_name}")
    if moment:
        d.step(f"mrl{tag}", mr * l, "kg*m^2", symbol=f"m_{tag} r_{tag} l_{tag}",
               formula=rf"@mr{tag}\,@l{tag}")
    return mr, l


FAR_SIDE = "negative: on the far side of the reference plane"


def two_plane_balance(p, d):
    """Examples 2.2 and 2.5: three masses balanced by corrections in planes P (the reference) and Q."""
    rows = []
    for i in (1, 2, 3):
        z = getattr(p, f"z{i}")
        mr, l = _plane(d, str(i), f"m{i}", f"r{i}", z - p.zP, rf"@z{i} - @zP", FAR_SIDE if z < p.zP else "")
        rows.append((mr, l, getattr(p, f"theta{i}")))
    l_q = d.step("lQ", p.zQ - p.zP, "m", symbol=r"l_Q", formula=r"@zQ - @zP")
    mx, my = components(d, "M", "M", [(f"mrl{i}", f"theta{i}") for i in (1, 2, 3)], "kg*m^2",
                        "moments about P", table=("Planes, with P as the reference: moments", PLANE,
                                                  _planes("123", ("m1", "m2", "m3"), ("r1", "r2", "r3"),
                                                          ("theta1", "theta2", "theta3")), "m r l"))
    m_q = d.step("mQ", math.hypot(mx, my) / (p.rQ * l_q), "kg", symbol=r"m_Q",
                 formula=rf"\frac{{{magnitude_formula('M_0', 'M_90')}}}{{@rQ\,@lQ}}",
                 note="Q's correction closes the moment polygon about P")
    closing_angle(d, "theta_Q", r"\theta_Q", "M_0", "M_90")
    d.step("mrQ", m_q * p.rQ, "kg*m", symbol=r"m_Q r_Q", formula=r"@mQ\,@rQ")
    fx, fy = components(d, "F", "F", [(f"mr{i}", f"theta{i}") for i in (1, 2, 3)] + [("mrQ", "theta_Q")],
                        "kg*m", "forces, with Q's correction",
                        table=("Forces, with Q's correction", FORCE,
                               _forces(["1", "2", "3", "Q"], ["theta1", "theta2", "theta3", "theta_Q"]), "m r"))
    d.step("mP", math.hypot(fx, fy) / p.rP, "kg", symbol=r"m_P",
           formula=rf"\frac{{{magnitude_formula('F_0', 'F_90')}}}{{@rP}}", note="P's correction closes the force polygon")
    closing_angle(d, "theta_P", r"\theta_P", "F_0", "F_90")
    _removal(d, "theta_Q", r"\theta_Q")
    _removal(d, "theta_P", r"\theta_P")
    _two_plane_mistakes(p, d, rows, l_q)


def _two_plane_mistakes(p, d, rows, l_q):
    (q2, qa2), (p2, pa2) = mb.two_plane_correction([(mr, abs(l), a) for mr, l, a in rows], l_q)
    wrong_q, wrong_p = (q2 / p.rQ, qa2), (p2 / p.rP, pa2)
    for part, (size, angle) in (("Q", wrong_q), ("P", wrong_p)):
        d.mistake(f"m{part}", "sign_lost", size)
        d.mistake(f"theta_{part}", "sign_lost", angle)
    left_out = mb.balancing_vector([(mr, a) for mr, _, a in rows])
    d.mistake("mP", "q_correction_left_out", left_out[0] / p.rP)
    d.mistake("theta_P", "q_correction_left_out", left_out[1])
    d.mistake("theta_Q", "resultant_not_balance", d.value_of("theta_Q") + PI)
    d.mistake("theta_P", "resultant_not_balance", d.value_of("theta_P") + PI)


def complete_balance_position(p, d):
    """Example 2.3: A, B, C, D in that order, reference plane B; find D's plane and angle, then B."""
    mr_a, _ = _plane(d, "A", "mA", "rA", -p.lAB, r"-@lAB", FAR_SIDE)
    _plane(d, "C", "mC", "rC", p.lBC, r"@lBC")
    mx, my = components(d, "M", "M", [("mrlA", "thetaA"), ("mrlC", None)], "kg*m^2",
                        "moments about B (angles from C)",
                        table=("Planes, with B as the reference: moments", PLANE,
                               _planes("AC", ("mA", "mC"), ("rA", "rC"), ("thetaA", None)), "m r l"))
    mrl_d = d.step("mrlD", math.hypot(mx, my), "kg*m^2", symbol=r"m_D r_D l_D",
                   formula=magnitude_formula("M_0", "M_90"), note="D closes the moment polygon")
    mr_d = d.step("mrD", p.mD * p.rD, "kg*m", symbol=r"m_D r_D", formula=r"@mD\,@rD")
    l_d = d.step("lD", mrl_d / mr_d, "m", symbol=r"l_D", formula=r"\frac{@mrlD}{@mrD}", note="D's distance from B")
    x = d.step("x", l_d - p.lBC, "m", formula=r"@lD - @lBC", note="from C to D")
    d.require(0.1 <= x <= 2.0, "plane D too close to C or too far away")
    theta_d = closing_angle(d, "theta_D", r"\theta_D", "M_0", "M_90")
    fx, fy = components(d, "F", "F", [("mrA", "thetaA"), ("mrC", None), ("mrD", "theta_D")], "kg*m", "forces",
                        table=("Forces, with D", FORCE, _forces("ACD", ("thetaA", None, "theta_D")), "m r"))
    mr_b = d.step("mrB", math.hypot(fx, fy), "kg*m", symbol=r"m_B r_B", formula=magnitude_formula("F_0", "F_90"),
                  note="B closes the force polygon")
    theta_b = closing_angle(d, "theta_B", r"\theta_B", "F_0", "F_90")
    d.step("mB", mr_b / p.rB, "kg", symbol=r"m_B", formula=r"\frac{@mrB}{@rB}")

    # A's distance taken as positive: the moment polygon, and all that follows, changes
    signless = mb.balancing_vector([(mr_a * p.lAB, p.thetaA), (p.mC * p.rC * p.lBC, 0.0)])
    x_signless = signless[0] / mr_d - p.lBC
    b_signless = mb.balancing_vector([(mr_a, p.thetaA), (p.mC * p.rC, 0.0), (mr_d, signless[1])])
    d.mistake("x", "sign_lost", x_signless)
    d.mistake("mB", "sign_lost", b_signless[0] / p.rB)
    for step, value in (("theta_D", signless[1]), ("theta_B", b_signless[1])):
        d.mistake(step, "sign_lost", value, if_apart=True)  # the sign may leave an angle where it was
    d.mistake("x", "distance_from_reference", l_d)
    without_d = mb.balancing_vector([(mr_a, p.thetaA), (p.mC * p.rC, 0.0)])
    d.mistake("mB", "d_left_out", without_d[0] / p.rB)
    d.mistake("theta_B", "d_left_out", without_d[1])
    d.mistake("theta_D", "resultant_not_balance", theta_d + PI)
    d.mistake("theta_B", "resultant_not_balance", theta_b + PI)


def complete_balance_masses(p, d):
    """Problem 2.2: A, B, C, D; A and D have unknown masses, D an unknown plane and angle; reference A."""
    _plane(d, "B", "mB", "rBC", p.lAB, r"@lAB")
    _plane(d, "C", "mC", "rBC", p.lAB + p.lBC, r"@lAB + @lBC")
    mx, my = components(d, "M", "M", [("mrlB", None), ("mrlC", "thetaC")], "kg*m^2",
                        "moments about A (angles from B)",
                        table=("Planes, with A as the reference: moments", PLANE,
                               _planes("BC", ("mB", "mC"), ("rBC", "rBC"), (None, "thetaC")), "m r l"))
    mrl_d = d.step("mrlD", math.hypot(mx, my), "kg*m^2", symbol=r"m_D r_D l_D",
                   formula=magnitude_formula("M_0", "M_90"), note="D closes the moment polygon")
    theta_d = closing_angle(d, "theta_D", r"\theta_D", "M_0", "M_90")
    fx, fy = components(d, "F", "F", [("mrB", None), ("mrC", "thetaC")], "kg*m", "forces of B and C",
                        table=("Forces of B and C", FORCE, _forces("BC", (None, "thetaC")), "m r"))
    # A at θ_A and D at θ_D close the force polygon: resolve across each direction (Cramer's rule)
    d.require(abs(math.sin(theta_d - p.thetaA)) > 0.2, "A and D nearly in line: their masses are ill-determined")
    sizes = mb.two_directions((-fx, -fy), p.thetaA, theta_d)
    mr_a = d.step("mrA", sizes[0], "kg*m", symbol=r"m_A r_A",
                  formula=r"\frac{@F_90 \cos @theta_D - @F_0 \sin @theta_D}{\sin(@theta_D - @thetaA)}",
                  note=r"resolving at right angles to D removes D's unknown")
    mr_d = d.step("mrD", sizes[1], "kg*m", symbol=r"m_D r_D",
                  formula=r"\frac{@F_0 \sin @thetaA - @F_90 \cos @thetaA}{\sin(@theta_D - @thetaA)}",
                  note=r"resolving at right angles to A removes A's unknown")
    d.require(mr_a > 0 and mr_d > 0, "a negative mass: A or D would sit half a turn from the stated angle")
    m_a = d.step("mA", mr_a / p.rAD, "kg", symbol=r"m_A", formula=r"\frac{@mrA}{@rAD}")
    m_d = d.step("mD", mr_d / p.rAD, "kg", symbol=r"m_D", formula=r"\frac{@mrD}{@rAD}")
    l_d = d.step("lD", mrl_d / (m_d * p.rAD), "m", symbol=r"l_D", formula=r"\frac{@mrlD}{@mD\,@rAD}",
                 note="the distance from A to D")
    d.require(p.lAB + p.lBC + 0.05 <= l_d <= 2.0, "plane D does not lie beyond C, as the order A, B, C, D needs")

    # every eccentricity taken as equal (masses used for m·r): θ_D is unchanged, the masses are not; D's
    # moment divided by B and C's eccentricity instead of its own
    ratio = p.rBC / p.rAD
    for step, value in (("mA", m_a / ratio), ("mD", m_d / ratio), ("lD", mrl_d / (m_d * p.rBC))):
        d.mistake(step, "eccentricity_ignored", value)
    flipped = theta_d + PI
    d.mistake("theta_D", "resultant_not_balance", flipped)


def bearing_reactions(p, d):
    """Example 2.4: dynamic forces on bearings X and Y of a shaft with three masses, reference X."""
    _plane(d, "A", "mA", "rA", -p.a, r"-@a", FAR_SIDE)
    _plane(d, "B", "mB", "rB", p.b, r"@b")
    _plane(d, "C", "mC", "rC", p.b + p.c + p.e, r"@b + @c + @e")
    l_y = d.step("lY", p.b + p.c, "m", symbol=r"l_Y", formula=r"@b + @c")
    mx, my = components(d, "M", "M", [("mrlA", None), ("mrlB", "thetaB"), ("mrlC", "thetaC")], "kg*m^2",
                        "moments about X (angles from A)",
                        table=("Planes, with bearing X as the reference: moments", PLANE,
                               _planes("ABC", ("mA", "mB", "mC"), ("rA", "rB", "rC"), (None, "thetaB", "thetaC")),
                               "m r l"))
    d.step("MY", math.hypot(mx, my), "kg*m^2", symbol=r"l_Y R_Y", formula=magnitude_formula("M_0", "M_90"),
           note="the moment about X that Y's reaction balances")
    r_y = d.step("RY", d.value_of("MY") / l_y, "kg*m", symbol=r"R_Y", formula=r"\frac{@MY}{@lY}",
                 note="the m·r that would balance the moments, in plane Y")
    closing_angle(d, "theta_RY", r"\theta_{R_Y}", "M_0", "M_90")
    fx, fy = components(d, "F", "F", [("mrA", None), ("mrB", "thetaB"), ("mrC", "thetaC"), ("RY", "theta_RY")],
                        "kg*m", "forces, with Y's",
                        table=("Forces, with Y's", FORCE, _forces("ABC", (None, "thetaB", "thetaC")) +
                               [["Y", "@RY", "@theta_RY"]], "m r"), shown=("RY", "theta_RY"))
    r_x = d.step("RX", math.hypot(fx, fy), "kg*m", symbol=r"R_X", formula=magnitude_formula("F_0", "F_90"),
                 note="the m·r that would close the force polygon, in plane X")
    closing_angle(d, "theta_RX", r"\theta_{R_X}", "F_0", "F_90")
    forces = {}
    for tag, size in (("Y", r_y), ("X", r_x)):
        force = d.step(f"F{tag}", mb.rotating_force(size, p.N), "N", symbol=f"F_{tag}", formula=rf"@R{tag}\,@N^2",
                       note=f"the dynamic force at {tag}")
        opposite = d.value_of(f"theta_R{tag}") + PI
        turn = r" - 360^\circ" if opposite >= 2 * PI else ""   # kept within a turn, as the answer is given
        angle = d.step(f"theta_F{tag}", opposite - 2 * PI if turn else opposite, "rad", symbol=rf"\theta_{{F_{tag}}}",
                       formula=rf"@theta_R{tag} + 180^\circ{turn}", note="on the bearing: opposite the balancing direction")
        forces[tag] = (force, angle)
    _bearing_mistakes(p, d, forces)


def _bearing_mistakes(p, d, forces):
    rpm = p.N * 60 / (2 * PI)
    for tag, (force, angle) in forces.items():
        d.mistake(f"F{tag}", "rpm_as_rad_s", force / p.N ** 2 * rpm ** 2)
        d.mistake(f"F{tag}", "mm_for_m", force * 1000)
        d.mistake(f"theta_F{tag}", "balance_direction", angle - PI)
    for tag, other in (("Y", "X"), ("X", "Y")):
        d.mistake(f"F{tag}", "bearings_swapped", forces[other][0])
        d.mistake(f"theta_F{tag}", "bearings_swapped", forces[other][1])
    # A's distance taken as positive
    l_y = p.b + p.c
    rows = [(p.mA * p.rA, p.a, 0.0), (p.mB * p.rB, p.b, p.thetaB), (p.mC * p.rC, p.b + p.c + p.e, p.thetaC)]
    r_y = mb.balancing_vector((mr * l, a) for mr, l, a in rows)
    r_y = (r_y[0] / l_y, r_y[1])
    r_x = mb.balancing_vector([(mr, a) for mr, _, a in rows] + [r_y])
    for tag, (size, angle) in (("Y", r_y), ("X", r_x)):
        wrong = (mb.rotating_force(size, p.N), angle + PI)
        d.mistake(f"F{tag}", "sign_lost", wrong[0])
        d.mistake(f"theta_F{tag}", "sign_lost", wrong[1])
    without_y = mb.balancing_vector([(mr, a) for mr, _, a in rows])
    wrong = (mb.rotating_force(without_y[0], p.N), without_y[1] + PI)
    d.mistake("FX", "reaction_left_out", wrong[0])
    d.mistake("theta_FX", "reaction_left_out", wrong[1])


def correction_plane_position(p, d):
    """Example 2.2: a correction of given mass and radius balances the moments about plane X; its angle,
    then the position of its plane follow, and the force polygon gives the correction in X itself."""
    rows = []
    for i in (1, 2, 3):
        mr, l = _plane(d, str(i), f"m{i}", f"r{i}", getattr(p, f"z{i}"), rf"@z{i}")
        rows.append((mr, l, getattr(p, f"theta{i}")))
    mx, my = components(d, "M", "M", [(f"mrl{i}", f"theta{i}") for i in (1, 2, 3)], "kg*m^2", "moments about X",
                        table=("Planes, with X as the reference: moments", PLANE,
                               _planes("123", ("m1", "m2", "m3"), ("r1", "r2", "r3"), ("theta1", "theta2", "theta3")),
                               "m r l"))
    moment = d.step("MQ", math.hypot(mx, my), "kg*m^2", symbol=r"B_1 b_1 x", formula=magnitude_formula("M_0", "M_90"),
                    note="the moment the correction must supply about X")
    theta_q = closing_angle(d, "theta_Q", r"\theta_{B_1}", "M_0", "M_90")
    mr_q = d.step("mrQ", p.B1 * p.b1, "kg*m", symbol=r"B_1 b_1", formula=r"@B1\,@b1")
    x = d.step("x", moment / mr_q, "m", formula=r"\frac{@MQ}{@mrQ}", note="the correction's plane, from X")
    d.require(0.1 <= x <= 1.2 * max(p.z1, p.z2, p.z3), "the correction's plane would lie off the shaft")
    d.require(min(abs(x - getattr(p, f"z{i}")) for i in (1, 2, 3)) >= 0.05, "the correction's plane meets a mass's")
    fx, fy = components(d, "F", "F", [(f"mr{i}", f"theta{i}") for i in (1, 2, 3)] + [("mrQ", "theta_Q")],
                        "kg*m", "forces, with the correction's",
                        table=("Forces, with the correction B₁", FORCE,
                               _forces("123", ("theta1", "theta2", "theta3")) + [["B₁", "@mrQ", "@theta_Q"]], "m r"))
    d.step("mX", math.hypot(fx, fy) / p.bX, "kg", symbol=r"B_X", formula=rf"\frac{{{magnitude_formula('F_0', 'F_90')}}}{{@bX}}",
           note="the correction in X closes the force polygon")
    theta_x = closing_angle(d, "theta_X", r"\theta_X", "F_0", "F_90")
    d.mistake("theta_Q", "resultant_not_balance", theta_q + PI)
    d.mistake("theta_X", "resultant_not_balance", theta_x + PI)
    d.mistake("x", "radius_forgotten", moment / p.B1)
    left_out = mb.balancing_vector([(mr, a) for mr, _, a in rows])
    d.mistake("mX", "q_correction_left_out", left_out[0] / p.bX)
    d.mistake("theta_X", "q_correction_left_out", left_out[1])
