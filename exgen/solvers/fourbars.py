"""Worked derivations for four-bar linkages (course text §7.5-7.6 and the four-bar example, §7.9).

Angles are measured from +x counter-clockwise (chapter 7's convention) and kept in radians in
the steps. The position follows the text's analytical method: the diagonal BD (eq 7.3), the
transmission angle γ (eq 7.4), then θ3 and θ4 by the half-angle forms of eqs 7.5-7.8, whose
sign of sin γ picks the circuit. Every later step is computed from the returned values of the
earlier ones, so a student's wrong BD or γ carries forward.
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from .angles import difference, direction, wrapped
from .polygons import angle_gap_deg

#: The transmission angle is kept in this window: nearer a dead point the answers turn on the
#: last figure of BD, and a real linkage there would jam.
GAMMA_RANGE_DEG = (25.0, 155.0)
#: The half-angle fractions of eqs 7.5-7.8 stay this far from 0/0 (a fraction of the longest link): nearer,
#: the worked line divides differences of printed values that nearly cancel (at 0/0 it cannot be followed
#: at all), and γ rounded to four figures moves θ3 or θ4 by more than half a degree. About 1 draw in 20.
HALF_ANGLE_MIN = 0.1

BD_FORMULA = r"\sqrt{@L1^2 + @L2^2 - 2\,@L1\,@L2\cos @phi2}"
GAMMA_FORMULA = r"\cos^{-1}\frac{@L3^2 + @L4^2 - @BD^2}{2\,@L3\,@L4}"
THETA3_FORMULA = (r"2\tan^{{-1}}\frac{{-@L2\sin @phi2 {sign} @L4\sin @gamma}}"
                  r"{{@L1 + @L3 - @L2\cos @phi2 - @L4\cos @gamma}}")
THETA4_FORMULA = (r"2\tan^{{-1}}\frac{{@L2\sin @phi2 {sign} @L3\sin @gamma}}"
                  r"{{@L4 - @L1 + @L2\cos @phi2 - @L3\cos @gamma}}")
CIRCUIT_NOTE = {1: "circuit 1 (eq {eq}): +L₄ sin γ, C on the left of BD seen from B",
                2: "circuit 2 (eq {eq}): −L₄ sin γ, C on the right of BD seen from B"}


def circuit_of(p) -> int:
    return int(str(p.circuit))


def position_steps(d, lengths, phi2_name: str, circuit: int, suffix: str = "") -> tuple[float, float, float, float]:
    """Steps BD, γ, θ3, θ4 (eqs 7.3-7.8) for the crank at the angle step/param `phi2_name` from AD.

    The formulas name the crank angle @phi2; `phi2_name` is what it stands for here.
    """
    l1, l2, l3, l4 = lengths
    phi2 = d.value_of(phi2_name)

    def formula(text: str) -> str:
        return text.replace("@phi2", f"@{phi2_name}")

    bd = d.step("BD", lk.diagonal(l1, l2, phi2), "m", symbol="BD", formula=formula(BD_FORMULA),
                note="the diagonal from the crank pin to the rocker pivot (eq 7.3)")
    d.mistake("BD", "degrees_as_radians", lk.diagonal(l1, l2, math.degrees(phi2)))
    gamma = d.step("gamma", lk.transmission_angle(l3, l4, bd), "rad", symbol=r"\gamma",
                   formula=GAMMA_FORMULA, note="the transmission angle between coupler and rocker (eq 7.4)")
    sign = "+" if circuit == 1 else "-"
    other = 3 - circuit
    theta3 = d.step(f"theta3{suffix}", lk.coupler_angle(l1, l2, l3, l4, phi2, gamma, circuit), "rad",
                    symbol=r"\theta_3" + ("'" if suffix else ""), formula=formula(THETA3_FORMULA.format(sign=sign)),
                    note=CIRCUIT_NOTE[circuit].format(eq="7.5" if circuit == 1 else "7.7"))
    theta4 = d.step(f"theta4{suffix}", lk.rocker_angle(l1, l2, l3, l4, phi2, gamma, circuit), "rad",
                    symbol=r"\theta_4" + ("'" if suffix else ""),
                    formula=formula(THETA4_FORMULA.format(sign="-" if circuit == 1 else "+")),
                    note=f"eq {'7.6' if circuit == 1 else '7.8'}; check: θ4 − θ3 = {'+' if circuit == 1 else '−'}γ")
    d.mistake(f"theta3{suffix}", "wrong_circuit", lk.coupler_angle(l1, l2, l3, l4, phi2, gamma, other))
    d.mistake(f"theta4{suffix}", "wrong_circuit", lk.rocker_angle(l1, l2, l3, l4, phi2, gamma, other))
    return bd, gamma, theta3, theta4


def require_well_conditioned(d, gamma: float, circuit_gap: float) -> None:
    low, high = GAMMA_RANGE_DEG
    d.require(low <= math.degrees(gamma) <= high, "the linkage is near a dead point")
    d.require(circuit_gap >= math.radians(6.0), "the two circuits nearly coincide")


def fourbar_position(p, d):
    """The four-bar example, analytical method: BD, γ, θ3, θ4 at the crank angle θ2 in a given circuit."""
    circuit = circuit_of(p)
    d.require(lk.can_assemble(p.L1, p.L2, p.L3, p.L4, p.theta2), "the linkage cannot be assembled at θ2")
    bd, gamma, theta3, theta4 = position_steps(d, (p.L1, p.L2, p.L3, p.L4), "theta2", circuit)
    other3 = lk.coupler_angle(p.L1, p.L2, p.L3, p.L4, p.theta2, gamma, 3 - circuit)
    require_well_conditioned(d, gamma, math.radians(angle_gap_deg(theta3, other3)))
    conditioning = lk.half_angle_conditioning(p.L1, p.L2, p.L3, p.L4, p.theta2, gamma, circuit)
    d.require(conditioning >= HALF_ANGLE_MIN, "the half-angle form of θ3 or θ4 is near 0/0 at this crank angle")
    d.mistake("gamma", "theta4_for_gamma", theta4)
    d.mistake("gamma", "supplement", math.pi - gamma)
    d.mistake("theta4", "gamma_for_theta4", gamma)
    for name, value in (("theta3", theta3), ("theta4", theta4)):
        d.mistake(name, "radians_for_degrees", math.radians(value))


def coupler_point(p, d):
    """The four-bar example by its vector method: D at the origin, A anywhere; θ4, θ3 and the point P.

    R_H = R_1 + R_2 runs from D to the crank pin B; the cosine law in triangle DBC gives the angle
    φ at D between DB and DC, on the side of DB that the circuit names (the example's θ4 = θ_H + φ
    is circuit 2). The coupler triangle's angle α at C (cosine law again) turns C → B onto C → P.
    """
    circuit = circuit_of(p)
    pin = lk.polar((p.xA, p.yA), p.L2, p.theta2)
    xb = d.step("xB", pin[0], "m", symbol="x_B", formula=r"@xA + @L2\cos @theta2",
                note="$R_H = R_1 + R_2$, from D to the crank pin B")
    yb = d.step("yB", pin[1], "m", symbol="y_B", formula=r"@yA + @L2\sin @theta2")
    theta_h = direction(d, "theta_H", r"\theta_H", "@yB", "@xB", yb, xb, "the direction D → B")
    r_h = d.step("r_H", math.hypot(xb, yb), "m", symbol="r_H", formula=r"\sqrt{@xB^2 + @yB^2}")
    phi = d.step("phi", lk.cosine_law_angle(r_h, p.L4, p.L3), "rad", symbol=r"\varphi",
                 formula=r"\cos^{-1}\frac{@r_H^2 + @L4^2 - @L3^2}{2\,@L4\,@r_H}",
                 note="the angle BDC in triangle DBC (cosine law)")
    turn = 1.0 if circuit == 2 else -1.0
    theta4 = wrapped(d, "theta4", r"\theta_4", rf"@theta_H {'+' if turn > 0 else '-'} @phi", theta_h + turn * phi,
                     note=f"circuit {circuit}: C on the {'right' if circuit == 2 else 'left'} of B → D, "
                          f"{'counter-' if turn > 0 else ''}clockwise from D → B")
    rocker_pin = lk.polar((0.0, 0.0), p.L4, theta4)
    xc = d.step("xC", rocker_pin[0], "m", symbol="x_C", formula=r"@L4\cos @theta4")
    yc = d.step("yC", rocker_pin[1], "m", symbol="y_C", formula=r"@L4\sin @theta4")
    theta3 = direction(d, "theta3", r"\theta_3", "@yC - @yB", "@xC - @xB", yc - yb, xc - xb,
                       "the coupler B → C from the loop $R_4 = R_H + R_3$ (the text's loop takes $R_3$ from C to B, "
                       "180° round)")
    alpha = d.step("alpha", lk.cosine_law_angle(p.CP, p.L3, p.BP), "rad", symbol=r"\alpha",
                   formula=r"\cos^{-1}\frac{@CP^2 + @L3^2 - @BP^2}{2\,@CP\,@L3}",
                   note="the angle BCP of the coupler triangle (cosine law)")
    # the cosine law with the sides about B taken for those about C: the triangle's angle at B
    d.mistake("alpha", "wrong_vertex", lk.cosine_law_angle(p.BP, p.L3, p.CP), if_apart=True)
    right = str(p.side) == "right"
    theta6 = wrapped(d, "theta6", r"\theta_6", rf"@theta3 + 180^\circ {'+' if right else '-'} @alpha",
                     theta3 + math.pi + (alpha if right else -alpha),
                     note="the line C → P: from C the coupler points back along θ3 + 180°, turned through α "
                         + ("counter-clockwise (P on the right of B → C)" if right else "clockwise (P on the left of B → C)"))
    point = lk.polar((xc, yc), p.CP, theta6)
    xp = d.step("xP", point[0], "m", symbol="x_P", formula=r"@xC + @CP\cos @theta6", note="$R_P = R_4 + R_6$")
    yp = d.step("yP", point[1], "m", symbol="y_P", formula=r"@yC + @CP\sin @theta6")
    gamma = lk.cosine_law_angle(p.L3, p.L4, r_h)
    require_well_conditioned(d, gamma, 2 * phi)
    _coupler_point_mistakes(p, d, (theta_h, phi, turn, alpha, right), (theta3, theta4), (xp, yp))


def _coupler_point_mistakes(p, d, geometry, angles, answer) -> None:
    """The other circuit, the coupler taken from C to B, the other side of the coupler, and the
    turned frame of eqs 7.5-7.8 with its angles left measured from AD."""
    theta_h, phi, turn, alpha, right = geometry
    theta3, theta4 = angles
    b = lk.polar((p.xA, p.yA), p.L2, p.theta2)

    def place(t4: float, right_used: bool):
        """θ3 and P for the rocker at t4, with P on the given side of B -> C."""
        c = lk.polar((0.0, 0.0), p.L4, t4)
        t3 = math.atan2(c[1] - b[1], c[0] - b[0])
        return t3, lk.coupler_point(c, t3, p.CP, alpha, left_of_bc=not right_used)

    other4 = lk.wrap(theta_h - turn * phi)
    other3, other_point = place(other4, right)
    theta1 = math.atan2(-p.yA, -p.xA)
    wrongs = {"wrong_circuit": other_point, "other_side": place(theta4, not right)[1]}
    d.mistake("theta4", "wrong_circuit", other4)
    d.mistake("theta3", "wrong_circuit", other3)
    d.mistake("theta3", "coupler_reversed", lk.wrap(theta3 + math.pi))
    for name, value in (("theta3", theta3), ("theta4", theta4)):
        relative = lk.wrap(value - theta1)
        d.mistake(name, "relative_to_ground_line", relative, if_apart=True)
    scale = max(p.L2, p.L3, p.L4, p.CP)
    for name, point in wrongs.items():
        d.require(not d.strict or math.dist(point, answer) >= 0.1 * scale, f"{name.replace('_', ' ')} barely moves P")
        for step, wrong, right in zip(("xP", "yP"), point, answer):
            d.mistake(step, name, wrong, if_apart=True)


GRASHOF_REASON = {
    "crank-rocker": "the shortest link is beside the ground link, so it turns fully and the other rocks",
    "double-crank": "the shortest link is the ground link, so both links pivoted on it turn fully",
    "double-rocker": "the shortest link is the coupler, opposite the ground: it turns fully, both side links rock",
    "change-point": "the links can all line up, and the linkage may change circuit there",
    "triple-rocker": "no link can make a full turn, whichever is grounded",
}
NAMES = ("AB", "BC", "CD", "DA")


def grashof(p, d):
    """Grashof's criterion (eq 7.2, Table 7.1): S + L against P + Q, and where the shortest link is."""
    lengths = {name: getattr(p, name) for name in NAMES}
    ground = str(p.ground)
    at = NAMES.index(ground)
    roles = dict(zip(("ground", "crank", "coupler", "rocker"), (NAMES[(at + k) % 4] for k in range(4))))
    result = lk.grashof(*(lengths[roles[r]] for r in ("ground", "crank", "coupler", "rocker")))
    ordered = sorted(NAMES, key=lambda n: (lengths[n], NAMES.index(n)))
    s_name, p_name, q_name, l_name = ordered
    d.require(len(set(lengths.values())) == 4 or result.kind in ("change-point",),
              "two links of one length make the shortest or longest ambiguous")
    s_l = d.step("S_plus_L", lengths[s_name] + lengths[l_name], "m", symbol="S + L",
                 formula=rf"@{s_name} + @{l_name}", note=f"shortest {s_name} and longest {l_name}")
    p_q = d.step("P_plus_Q", lengths[p_name] + lengths[q_name], "m", symbol="P + Q",
                 formula=rf"@{p_name} + @{q_name}", note="the other two links")
    kind = lk.grashof_kind(s_l, p_q, result.shortest)
    compare = "=" if kind == "change-point" else ("<" if s_l < p_q else ">")
    kind = d.step("kind", kind, "", symbol=r"\text{class}",
                  note=f"S + L {compare} P + Q with {ground} grounded: {GRASHOF_REASON[kind]} (Table 7.1)")
    _actuator(d, kind, result.shortest)
    d.mistake("S_plus_L", "wrong_pair", lengths[s_name] + lengths[p_name])
    d.mistake("P_plus_Q", "wrong_pair", lengths[l_name] + lengths[q_name])
    by_position = [(lengths[roles["ground"]] + lengths[roles["crank"]], lengths[roles["coupler"]] + lengths[roles["rocker"]]),
                   (lengths[roles["ground"]] + lengths[roles["coupler"]], lengths[roles["crank"]] + lengths[roles["rocker"]])]
    wrong = [lk.grashof_kind(a, b, result.shortest) for pair in by_position for a, b in (pair, pair[::-1])]
    wrong += [lk.grashof_kind(lengths[s_name] + lengths[p_name], lengths[l_name] + lengths[q_name], result.shortest)]
    mistaken = next((w for w in wrong if w != kind), None)
    if mistaken:
        d.mistake("kind", "wrong_pair", mistaken)
    if kind in ("double-crank", "double-rocker"):
        d.mistake("kind", "ground_ignored", "crank-rocker")
    elif kind == "crank-rocker":
        d.mistake("kind", "ground_ignored", "double-crank")


ACTUATORS = ("motor", "cylinder")
#: The classes in which a link pivoted on the frame turns fully (the change-point too, when the shortest link is
#: the ground or beside it): a motor can drive it round; in the others both such links rock.
TURNING = ("crank-rocker", "double-crank")


def _actuator(d, kind: str, shortest: str) -> None:
    """§7.5: a motor for a link that turns fully, a hydraulic or pneumatic cylinder for one that rocks."""
    turns = kind in TURNING or (kind == "change-point" and shortest != "coupler")
    which = ("a link pivoted on the frame turns fully: a motor drives it round" if turns else
             "both links pivoted on the frame only rock: a cylinder swings one of them")
    d.step("actuator", ACTUATORS[0 if turns else 1], "", symbol=r"\text{actuator}", note=f"{kind}: {which}")
    if kind == "double-rocker":
        d.mistake("actuator", "grashof_only", "motor")


def rocker_swing(p, d):
    """Limit positions of a crank-rocker (Problems 7.2-7.3): crank and coupler in line, AC = L3 ± L2."""
    result = lk.grashof(p.L1, p.L2, p.L3, p.L4)
    d.require(result.kind == "crank-rocker" and result.shortest == "crank", "not a crank-rocker driven by its crank")
    ext = d.step("AC_ext", p.L3 + p.L2, "m", symbol=r"AC_{\mathrm{ext}}", formula=r"@L3 + @L2",
                 note="crank and coupler stretched out in one line")
    fold = d.step("AC_fold", p.L3 - p.L2, "m", symbol=r"AC_{\mathrm{fold}}", formula=r"@L3 - @L2",
                  note="the crank folded back along the coupler")
    out = {}
    for tag, reach, name in (("ext", ext, "AC_ext"), ("fold", fold, "AC_fold")):
        delta = d.step(f"delta_{tag}", lk.cosine_law_angle(p.L1, p.L4, reach), "rad",
                       symbol=rf"\delta_{{\mathrm{{{tag}}}}}",
                       formula=rf"\cos^{{-1}}\frac{{@L1^2 + @L4^2 - @{name}^2}}{{2\,@L1\,@L4}}",
                       note="the angle ADC in triangle ACD (cosine law)")
        out[tag] = d.step(f"theta4_{tag}", math.pi - delta, "rad", symbol=rf"\theta_{{4,\mathrm{{{tag}}}}}",
                          formula=rf"180^\circ - @delta_{tag}", note="C above the ground line, measured from +x")
        d.mistake(f"theta4_{tag}", "interior_angle", delta)
    swing = difference(d, "swing", r"\psi", "theta4_ext", "theta4_fold",
                       note="the rocker's swing between its limit positions")
    limits = lk.rocker_limits(p.L1, p.L2, p.L3, p.L4)
    d.mistake("theta4_ext", "sum_and_difference_swapped", limits.theta4_folded)
    d.mistake("theta4_fold", "sum_and_difference_swapped", limits.theta4_extended)
    d.mistake("swing", "radians_for_degrees", math.radians(swing))
    d.require(math.radians(15) <= swing <= math.radians(120), "a swing no real rocker would be built for")
