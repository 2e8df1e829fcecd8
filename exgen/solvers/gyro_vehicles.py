"""Worked derivations for vehicles on a curve: two-wheelers, cars and rail cars (course text §5.1).

The road wheels of any vehicle turning at Ω = v/R make a gyroscopic couple that tends to overturn
it outwards, like the centrifugal couple; an engine turning the same way as the wheels adds to
it, one turning the other way takes from it. A car's engine, spinning on the fore-and-aft axis,
instead loads one axle and relieves the other. Wheel speeds are ω = v / r with r the wheel's
effective (rolling) radius.
"""
from __future__ import annotations

import math

from ..mechanics import gyroscopes as gy
from .gyroscopes import KMH, directions, turn_note, word
from .slips import record



def _wheel_speed(p, d, radius_name: str, diameter: bool = False):
    """ω_w = v / r, from a radius or a diameter; records the diameter-for-radius slip."""
    if diameter:
        r = d.step("r_w", getattr(p, radius_name) / 2, "m", symbol="r_w", formula=rf"\frac{{@{radius_name}}}{{2}}")
        formula = r"\frac{@v}{@r_w}"
    else:
        r = getattr(p, radius_name)
        formula = rf"\frac{{@v}}{{@{radius_name}}}"
    omega = d.step("omega_w", p.v / r, "rad/s", symbol=r"\omega_w", formula=formula,
                   note="the wheels roll without slipping: v = ω r")
    d.mistake("omega_w", "diameter_for_radius", p.v / (2 * r))
    return omega


# ---- Example 5.2 and Problem 5.6: a motorcycle's angle of heel ------------------------------

def _heel(p, d, momentum_name: str):
    """The couples and the angle of heel from the total spin momentum step (Σ I ω)."""
    momentum = d.value_of(momentum_name)
    # The working adds C_g to the centrifugal couple as overturning outwards, and the part asks for it
    # with no sign: an engine turning against the wheels must not outweigh them.
    d.require(momentum > 0, "the engine's spin against the wheels outweighs theirs: the gyroscopic couple would "
                            "right the machine, not overturn it outwards")
    big_omega = d.step("Omega", gy.precession_rate(p.v, p.R), "rad/s", symbol=r"\Omega", formula=r"\frac{@v}{@R}",
                       note="the precession")
    gyro = d.step("C_g", momentum * big_omega, "N*m", symbol=r"C_g", formula=rf"@{momentum_name}\,@Omega",
                  note="the gyroscopic couple of wheels and engine with the machine upright; leaning at θ, "
                       "the spin axes tilt and it becomes $C_g \\cos\\theta$")
    fc = d.step("F_c", gy.centrifugal_force(p.m, p.v, p.R), "N", formula=r"\frac{@m\,@v^2}{@R}",
                note="the centrifugal force, acting at the centre of gravity")
    d.mistake("F_c", "kmh_not_converted", gy.centrifugal_force(p.m, p.v / KMH, p.R))
    cc = d.step("C_c", fc * p.h, "N*m", formula=r"@F_c\,@h", note="its overturning couple with the machine upright")
    d.mistake("C_c", "kmh_not_converted", gy.centrifugal_force(p.m, p.v / KMH, p.R) * p.h)
    d.constant("g", gy.G, "m/s^2", note="standard gravity")
    theta = d.step("theta", gy.heel_angle(gyro, cc, p.m, p.h), "rad",
                   formula=r"\tan^{-1}\frac{@C_g + @C_c}{@m\,@g\,@h}",
                   note="both couples overturn outwards and scale with cos θ; the weight rights the machine "
                        "with $m g h \\sin\\theta$: $(C_g + C_c)\\cos\\theta = m g h \\sin\\theta$")
    d.mistake("theta", "gyro_ignored", gy.heel_angle(0.0, cc, p.m, p.h))
    d.mistake("theta", "complement", math.pi / 2 - theta)
    return theta


def _engine_sign(p) -> float:
    return 1.0 if p.engine == "same" else -1.0


def motorcycle_banking(p, d):
    """Example 5.2: wheel and engine inertias from masses and radii of gyration, then the bank angle
    at which the rider stays normal to the track."""
    iw = d.step("I_w", 2 * gy.moment_of_inertia(p.m_w, p.k_w), "kg*m^2", symbol="I_w", formula=r"2\,@m_w\,@k_w^2",
                note="both wheels")
    ie = d.step("I_e", gy.moment_of_inertia(p.m_e, p.k_e), "kg*m^2", symbol="I_e", formula=r"@m_e\,@k_e^2")
    omega_w = _wheel_speed(p, d, "r_w")
    omega_e = d.step("omega_e", p.G * omega_w, "rad/s", symbol=r"\omega_e", formula=r"@G\,@omega_w",
                     note="the engine turns G times as fast as the back wheel")
    s = _engine_sign(p)
    d.step("H", iw * omega_w + s * ie * omega_e, "kg*m^2/s", symbol=r"\Sigma I\omega",
           formula=r"@I_w\,@omega_w " + ("+" if s > 0 else "-") + r" @I_e\,@omega_e",
           note="the engine " + ("turns the same way as the wheels: its couple adds" if s > 0
                                  else "turns against the wheels: its couple takes away"))
    _heel(p, d, "H")
    big_omega = p.v / p.R
    record(d, "C_g", "engine_sense_reversed", (iw * omega_w - s * ie * omega_e) * big_omega)
    d.mistake("C_g", "radius_for_k", (2 * p.m_w * p.r_w ** 2 * omega_w + s * ie * omega_e) * big_omega)
    d.mistake("C_g", "one_wheel", (iw / 2 * omega_w + s * ie * omega_e) * big_omega)
    d.mistake("C_g", "ratio_inverted", (iw * omega_w + s * ie * omega_w / p.G) * big_omega)


def motorcycle_heel(p, d):
    """Problem 5.6: the angle of heel with wheel and engine inertias given."""
    omega_w = _wheel_speed(p, d, "d_w", diameter=True)
    s = _engine_sign(p)
    d.step("H", (2 * p.I_w + s * p.G * p.I_e) * omega_w, "kg*m^2/s", symbol=r"\Sigma I\omega",
           formula=r"(2\,@I_w " + ("+" if s > 0 else "-") + r" @G\,@I_e)\,@omega_w",
           note="two wheels, and the engine at G times their speed, "
                + ("the same way: its couple adds" if s > 0 else "the other way: its couple takes away"))
    _heel(p, d, "H")
    big_omega = p.v / p.R
    record(d, "C_g", "engine_sense_reversed", (2 * p.I_w - s * p.G * p.I_e) * omega_w * big_omega)
    d.mistake("C_g", "diameter_for_radius", (2 * p.I_w + s * p.G * p.I_e) * p.v / p.d_w * big_omega)
    d.mistake("C_g", "one_wheel", (p.I_w + s * p.G * p.I_e) * omega_w * big_omega)
    record(d, "theta", "engine_sense_reversed", gy.heel_angle(
        (2 * p.I_w - s * p.G * p.I_e) * omega_w * big_omega, d.value_of("C_c"), p.m, p.h))


# ---- Problem 5.3: reactions at the wheels of a car on a curve --------------------------------

def car_wheel_reactions(p, d):
    """Problem 5.3: each wheel's reaction from the weight, the wheels' and engine's gyroscopic couples
    and the centrifugal couple; the overturning couples are shared equally by the two axles."""
    d.constant("g", gy.G, "m/s^2", note="standard gravity")
    weight = d.step("W", p.m * gy.G, "N", formula=r"@m\,@g")
    front = d.step("W_f", weight * (p.b - p.a) / (2 * p.b), "N", symbol=r"W_{\mathrm{front}}",
                   formula=r"\frac{@W\,(@b - @a)}{2\,@b}", note="each front wheel's share of the weight")
    rear = d.step("W_r", weight * p.a / (2 * p.b), "N", symbol=r"W_{\mathrm{rear}}",
                  formula=r"\frac{@W\,@a}{2\,@b}", note="each rear wheel's share")
    omega_w = _wheel_speed(p, d, "d_w", diameter=True)
    big_omega = d.step("Omega", gy.precession_rate(p.v, p.R), "rad/s", symbol=r"\Omega", formula=r"\frac{@v}{@R}")
    cw = d.step("C_w", gy.couple(4 * p.I_w, omega_w, big_omega), "N*m", symbol=r"C_w",
                formula=r"4\,@I_w\,@omega_w\,@Omega", note="the four road wheels' couple: it overturns outwards")
    pw = d.step("P_w", cw / (2 * p.x), "N", symbol=r"P_w", formula=r"\frac{@C_w}{2\,@x}",
                note="more on each outer wheel, less on each inner wheel")
    d.mistake("P_w", "wheelbase_for_track", cw / (2 * p.b))
    d.mistake("P_w", "diameter_for_radius", pw / 2)
    ie = d.step("I_e", gy.moment_of_inertia(p.m_e, p.k_e), "kg*m^2", symbol="I_e", formula=r"@m_e\,@k_e^2")
    omega_e = d.step("omega_e", p.G * omega_w, "rad/s", symbol=r"\omega_e", formula=r"@G\,@omega_w")
    ce = d.step("C_e", gy.couple(ie, omega_e, big_omega), "N*m", symbol=r"C_e", formula=r"@I_e\,@omega_e\,@Omega",
                note="the engine's couple, about the axis across the car")
    pe = d.step("P_e", ce / (2 * p.b), "N", symbol=r"P_e", formula=r"\frac{@C_e}{2\,@b}",
                note="shared by the two wheels of each axle, the wheelbase apart")
    d.mistake("P_e", "track_for_wheelbase", ce / (2 * p.x))
    d.mistake("P_e", "not_shared", ce / p.b)
    spin = gy.axial_spin(p.sense, "front")
    couple = directions(d, spin, f"{p.sense} seen from the front: curl the right-hand fingers the way it "
                                 f"turns and the thumb points {'away from' if p.sense == 'clockwise' else 'towards'} "
                                 "the viewer", gy.turning(p.turn), turn_note(p.turn), "vehicle")
    loaded = "rear" if gy.pitch_effect(couple) == "nose up" else "front"
    other = "front" if loaded == "rear" else "rear"
    loaded = d.step("engine_loads", loaded, "", symbol=r"\text{axle loaded}",  # a student's choice carries forward
                     note=f"a couple pointing {word(couple, 'vehicle')} pitches the car {gy.pitch_effect(couple)}: "
                          f"it presses the {loaded} wheels down and lifts the {other} ones")
    d.mistake("engine_loads", "precession_reversed", "front" if loaded == "rear" else "rear")
    fc = d.step("F_c", gy.centrifugal_force(p.m, p.v, p.R), "N", formula=r"\frac{@m\,@v^2}{@R}")
    pc = d.step("P_c", fc * p.h / (2 * p.x), "N", symbol=r"P_c", formula=r"\frac{@F_c\,@h}{2\,@x}",
                note="the centrifugal couple $F_c h$, outwards: more on each outer wheel, less on each inner")
    d.mistake("P_c", "not_shared", fc * p.h / p.x)
    outer = gy.outer_side(p.turn)
    e_front = -1.0 if loaded == "rear" else 1.0
    rows = []
    for axle, share, sign_e in (("f", "W_f", e_front), ("r", "W_r", -e_front)):
        for side in ("left", "right"):
            out = 1.0 if side == outer else -1.0
            rows.append([f"{'front' if axle == 'f' else 'rear'} {side} ({'outer' if out > 0 else 'inner'})",
                         f"@{share}", out * pw, sign_e * pe, out * pc, f"@R_{axle}{side[0]}"])
            name = f"R_{axle}{side[0]}"
            value = d.value_of(share) + out * (pw + pc) + sign_e * pe
            words = f"{'front' if axle == 'f' else 'rear'} {side}, {'outer' if out > 0 else 'inner'}"
            d.step(name, value, "N", symbol=rf"R_{{\mathrm{{{axle}{side[0]}}}}}",
                   formula=rf"@{share} {'+' if out > 0 else '-'} @P_w {'+' if out > 0 else '-'} @P_c "
                           rf"{'+' if sign_e > 0 else '-'} @P_e", note=words)
            d.mistake(name, "sides_swapped", d.value_of(share) - out * (pw + pc) + sign_e * pe)
            d.mistake(name, "weight_split_reversed",
                      d.value_of("W_r" if axle == "f" else "W_f") + out * (pw + pc) + sign_e * pe)
            d.mistake(name, "centrifugal_ignored", d.value_of(share) + out * pw + sign_e * pe)
    d.table("Each wheel's reaction: its share of the weight, then the changes (+ more load, − less)",
            [("Wheel",), ("$W$", "N"), ("$P_w$", "N"), ("$P_e$", "N"), ("$P_c$", "N"), ("$R$", "N")], rows,
            shown=("W_f", "W_r"))   # each wheel's share of the weight is worked nowhere else
    d.require(min(d.value_of(n) for n in ("R_fl", "R_fr", "R_rl", "R_rr")) > 0.15 * weight / 4,
              "an inner wheel nearly lifts: the car would be at the limit of overturning")


# ---- Problem 5.5: a rail car's limiting speed on a curve ------------------------------------

def rail_car_limiting_speed(p, d):
    """Problem 5.5: the speed at which the inner wheels leave the rail, with the centrifugal couple and
    the gyroscopic couples of both axles and their motors."""
    s = 1.0 if p.motor == "same" else -1.0
    sigma = d.step("S", 2 * p.I_a + s * 2 * p.G * p.I_m, "kg*m^2", symbol=r"\Sigma I G",
                   formula=r"2\,@I_a " + ("+" if s > 0 else "-") + r" 2\,@G\,@I_m",
                   note="two axles at ω = v/r and two motors at Gω, "
                        + ("the same way as their axles" if s > 0 else "against their axles"))
    per_v2 = d.step("k_c", gy.centrifugal_couple_per_v2(p.m, p.h, p.R), "kg", symbol=r"\frac{C_c}{v^2}",
                    formula=r"\frac{@m\,@h}{@R}", note="the centrifugal couple m v²h/R, per v²")
    per_v2_g = d.step("k_g", gy.gyroscopic_couple_per_v2(sigma, p.r, p.R), "kg", symbol=r"\frac{C_g}{v^2}",
                      formula=r"\frac{@S}{@r\,@R}", note="the gyroscopic couple Σ(I G)(v/r)(v/R), per v²; "
                      + ("positive: it overturns outwards like the wheels" if sigma > 0
                         else "negative: it tilts the car inwards, against the centrifugal couple"))
    d.constant("g", gy.G, "m/s^2", note="standard gravity")
    d.step("W_i", p.m * gy.G / 4, "N", symbol=r"\frac{m g}{4}", formula=r"\frac{@m\,@g}{4}",
           note="each inner wheel's share of the weight")
    v = d.step("v_max", gy.rail_limiting_speed(p.m, p.x, per_v2 + per_v2_g), "m/s", symbol=r"v_{\max}",
               formula=r"\sqrt{\frac{2\,@x\,@W_i}{@k_c + @k_g}}",
               note="each inner wheel loses $(C_c + C_g)/(2x)$: it leaves the rail when that equals its share")
    kmh = v / KMH
    d.require(40 <= kmh <= 200, "a limiting speed outside 40-200 km/h: not a practical rail car")
    wrong = per_v2 + gy.gyroscopic_couple_per_v2(2 * p.I_a - s * 2 * p.G * p.I_m, p.r, p.R)
    if wrong > 0:  # else the wrong sign leaves the car on the rail at any speed
        d.mistake("v_max", "gyro_added_where_it_relieves" if s < 0 else "gyro_subtracted_where_it_adds",
                  gy.rail_limiting_speed(p.m, p.x, wrong))
    d.mistake("v_max", "gyro_ignored", gy.rail_limiting_speed(p.m, p.x, per_v2))
    d.mistake("v_max", "motors_ignored",
              gy.rail_limiting_speed(p.m, p.x, per_v2 + gy.gyroscopic_couple_per_v2(2 * p.I_a, p.r, p.R)))
    d.step("C_g", abs(per_v2_g) * v ** 2, "N*m", symbol=r"C_g", formula=r"\left|@k_g\right|\,@v_max^2",
           note="the size of the gyroscopic couple at the limiting speed")
    d.mistake("C_g", "motors_ignored", abs(gy.gyroscopic_couple_per_v2(2 * p.I_a, p.r, p.R)) * v ** 2)
    d.mistake("C_g", "gyro_added_where_it_relieves" if s < 0 else "gyro_subtracted_where_it_adds",
              abs(gy.gyroscopic_couple_per_v2(2 * p.I_a - s * 2 * p.G * p.I_m, p.r, p.R)) * v ** 2)
    effect = "adds" if per_v2_g > 0 else "relieves"
    d.step("gyro_effect", effect, "", symbol=r"\text{gyroscopic couple}",
           note="it " + ("overturns outwards with the centrifugal couple" if per_v2_g > 0
                         else "tilts the car inwards and relieves the centrifugal couple"))
    d.mistake("gyro_effect", "precession_reversed", "relieves" if effect == "adds" else "adds")
    d.step("C_c", per_v2 * v ** 2, "N*m", symbol=r"C_c", formula=r"@k_c\,@v_max^2",
           note="the centrifugal couple at the limiting speed")
