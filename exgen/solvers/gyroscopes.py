"""Worked derivations for gyroscopic couples on vehicles, ships and aircraft (course text §5.1).

Every template finds the couple I ω Ω and then its direction by the right-hand rule, recorded as
steps that name the spin vector, the precession vector and the reactive couple H × Ω in words,
so the key explains the effect the way the text does. A reversed precession (or spin) gives the
opposite effect: it is recorded as the mistake of each direction part.
"""
from __future__ import annotations

import math

from ..mechanics import gyroscopes as gy
KMH = 1 / 3.6

#: How a direction in the vehicle's axes (x forward, y left, z up) is said on a road vehicle and on a ship.
WORDS = {
    "vehicle": {(1, 0, 0): "forward", (-1, 0, 0): "backward", (0, 1, 0): "to the left",
                (0, -1, 0): "to the right", (0, 0, 1): "up", (0, 0, -1): "down"},
    "ship": {(1, 0, 0): "towards the bow", (-1, 0, 0): "towards the stern", (0, 1, 0): "to port",
             (0, -1, 0): "to starboard", (0, 0, 1): "up", (0, 0, -1): "down"},
    "aircraft": {(1, 0, 0): "towards the nose", (-1, 0, 0): "towards the tail", (0, 1, 0): "to the left wing",
                 (0, -1, 0): "to the right wing", (0, 0, 1): "up", (0, 0, -1): "down"},
}


def word(vector, frame: str) -> str:
    """A unit axis vector as words in the frame's vocabulary ('to starboard')."""
    key = tuple(int(round(c)) for c in vector)
    return WORDS[frame][key]


def spin_speed(p, d, name: str = "N"):
    """ω from the rotor speed in rpm, with the rpm-as-rad/s slip."""
    return d.step("omega", getattr(p, name), "rad/s", symbol=r"\omega", formula=rf"\frac{{2\pi\,@{name}}}{{60}}",
                  shown="rad/s", note="the rotor's spin, N in rpm")


def precession(p, d, speed: str = "v", radius: str = "R"):
    """Ω = v / R, and Ω with the speed left in km/h."""
    big_omega = d.step("Omega", gy.precession_rate(getattr(p, speed), getattr(p, radius)), "rad/s",
                       symbol=r"\Omega", formula=rf"\frac{{@{speed}}}{{@{radius}}}",
                       note="the precession: the vehicle turns about the vertical axis once per circuit")
    d.mistake("Omega", "kmh_not_converted", getattr(p, speed) / KMH / getattr(p, radius))
    return big_omega


def axial_spin_note(sense: str, viewed_from: str, looking: str) -> str:
    """Why a rotor seen turning one way has its spin vector pointing where it does."""
    away = "away from" if sense == "clockwise" else "towards"
    return (f"{sense} seen from the {looking}: curl the right-hand fingers the way the rotor turns and the "
            f"thumb points {away} the viewer")


def turn_note(turn: str) -> str:
    seen = "anticlockwise" if turn == "left" else "clockwise"
    return f"a turn to the {turn} is {seen} seen from above: the right-hand thumb points {'up' if turn == 'left' else 'down'}"


def directions(d, spin, spin_note: str, prec, prec_note: str, frame: str, prec_symbol: str = r"\vec{\Omega}"):
    """Steps naming ω, Ω and the reactive couple H × Ω as directions; returns the couple's unit vector."""
    d.step("spin_vector", word(spin, frame), "", symbol=r"\vec{\omega}", note=spin_note)
    d.step("precession_vector", word(prec, frame), "", symbol=prec_symbol, note=prec_note)
    couple = gy.reactive_couple(spin, prec)
    d.step("couple_vector", word(couple, frame), "", symbol=r"\vec{C}",
           formula=r"I\,\vec{\omega} \times \vec{\Omega}",
           note="the reactive (gyroscopic) couple on the vehicle: turn ω towards Ω and the right-hand thumb "
                "gives C; the active couple on the rotor is the reverse, Ω × ω")
    return couple


def couple_step(d, inertia: str, unit: str = "N*m"):
    """C = I ω Ω from the steps omega and Omega, with the rpm and km/h slips."""
    value = d.step("C", gy.couple(d.value_of(inertia), d.value_of("omega"), d.value_of("Omega")), unit,
                   formula=rf"@{inertia}\,@omega\,@Omega", note="the gyroscopic couple (eq. 5.2)")
    return value


def couple_slips(p, d, inertia: float, rpm: float, big_omega_kmh: float | None = None):
    """What the couple comes out as with rpm used as rad/s, or the speed left in km/h."""
    right = d.value_of("C")
    d.mistake("C", "rpm_as_rad_s", inertia * rpm * d.value_of("Omega"))
    if big_omega_kmh is not None:
        d.mistake("C", "kmh_not_converted", inertia * d.value_of("omega") * big_omega_kmh)
    return right


def _rpm(p, name: str = "N") -> float:
    return getattr(p, name) * 60 / (2 * math.pi)


# ---- Example 5.1: a flywheel on springs in a turning vehicle ---------------------------------

def vehicle_rotor_springs(p, d):
    """Example 5.1: the couple of a transverse flywheel on a turning vehicle, the spring forces and
    deflections, and which spring it stretches."""
    spin_speed(p, d)
    precession(p, d)
    couple_step(d, "I")
    c = couple_slips(p, d, p.I, _rpm(p), p.v / KMH / p.R)
    force = d.step("F", gy.couple_force(c, p.l), "N", formula=r"\frac{@C}{@l}",
                   note="the two springs push and pull with equal forces l apart: F l = C")
    d.mistake("F", "half_spacing", 2 * c / p.l)
    d.mistake("F", "couple_shared", c / (2 * p.l))
    x = d.step("x", force / p.K, "m", formula=r"\frac{@F}{@K}", note="each spring, one stretched and one compressed")
    d.require(0.002 <= x <= 0.06, "a spring deflection outside 2-60 mm: not a practical mounting")
    same = p.spin == "same"
    couple = directions(
        d, gy.wheel_spin(same),
        ("the road wheels rolling forward spin about the axis pointing to the vehicle's left-hand side (their tops "
         "move forward); the flywheel turns " + ("the same way" if same else "the opposite way")),
        gy.turning(p.turn), turn_note(p.turn), "vehicle")
    pressed = gy.roll_effect(couple)
    lifted = "left" if pressed == "right" else "right"
    d.step("tension", lifted, "", symbol=r"\text{spring in tension}",
           note=f"about the fore-and-aft axis, a couple pointing {word(couple, 'vehicle')} lifts the {lifted} "
                f"bearing (its spring stretches) and presses the {pressed} one down (its spring is compressed)")
    d.mistake("tension", "precession_reversed", pressed)


# ---- Problem 5.1: an engine rotor in a ship's bearings -------------------------------------

def rotor_bearing_reactions(p, d):
    """Problem 5.1: couple of a ship's engine on a turn, its effect, and the bearing reactions
    with the rotor's weight (eqs. 5.4-5.7). Bearing A is forward."""
    inertia = d.step("I", gy.moment_of_inertia(p.m, p.k), "kg*m^2", formula=r"@m\,@k^2")
    spin_speed(p, d)
    big_omega = d.step("Omega", gy.precession_rate(p.v, p.R), "rad/s", symbol=r"\Omega", formula=r"\frac{@v}{@R}",
                       note="the ship turns about the vertical axis")
    c = couple_step(d, "I")
    d.mistake("C", "rpm_as_rad_s", inertia * _rpm(p) * big_omega)
    d.mistake("C", "radius_for_k", p.m * p.k ** 2 / 2 * d.value_of("omega") * big_omega)
    couple = directions(d, gy.axial_spin(p.sense, "rear"), axial_spin_note(p.sense, "rear", "stern"),
                        gy.turning(p.turn), turn_note(p.turn), "ship")
    effect = "raises the bow" if gy.pitch_effect(couple) == "nose up" else "lowers the bow"
    other = "lowers the bow" if effect == "raises the bow" else "raises the bow"
    d.step("effect", effect, "", symbol=r"\text{effect}",
           note=f"a couple pointing {word(couple, 'ship')} turns the ship about its athwartships axis: it "
                f"{effect}{' and lowers the stern' if effect == 'raises the bow' else ' and raises the stern'}")
    d.mistake("effect", "precession_reversed", other)

    d.constant("g", gy.G, "m/s^2", note="standard gravity")
    weight = d.step("W", p.m * gy.G, "N", formula=r"@m\,@g")
    wa, wb = gy.weight_shares(weight, p.a, p.l)
    d.step("W_A", wa, "N", formula=r"\frac{@W\,(@l - @a)}{@l}", note="the weight's share at A (eq. 5.4)")
    d.step("W_B", wb, "N", formula=r"\frac{@W\,@a}{@l}", note="and at B (eq. 5.5)")
    force = d.step("F_C", gy.couple_force(c, p.l), "N", formula=r"\frac{@C}{@l}",
                   note="the couple is carried by equal and opposite forces at the two bearings")
    # The rotor pushes the forward bearing up when the bow rises: the support's upward reaction falls there.
    s = -1.0 if effect == "raises the bow" else 1.0
    ra = d.step("R_A", wa + s * force, "N", formula=rf"@W_A {'-' if s < 0 else '+'} @F_C",
                note="upward on the rotor at A, the forward bearing: " + (
                    "the rotor lifts on it, relieving it" if s < 0 else "the rotor presses down on it"))
    rb = d.step("R_B", wb - s * force, "N", formula=rf"@W_B {'+' if s < 0 else '-'} @F_C",
                note="upward on the rotor at B, the aft bearing")
    d.require(min(ra, rb) > 0.1 * weight, "a bearing nearly or fully unloaded: the rotor would lift off it")
    relieved, loaded = ("R_A", "R_B") if s < 0 else ("R_B", "R_A")
    d.mistake(relieved, "gyro_added_where_it_relieves", d.value_of(relieved) + 2 * force)
    d.mistake(loaded, "gyro_subtracted_where_it_adds", d.value_of(loaded) - 2 * force)
    for name, share in (("R_A", wa), ("R_B", wb)):
        # the static reaction, the couple left out; a slow rotor's couple may be too small to tell apart
        d.mistake(name, "gyro_ignored", share, if_apart=True)
        d.mistake(name, "weight_ignored", abs(d.value_of(name) - share))
        if abs(p.a - p.l / 2) > 0.05 * p.l:
            d.mistake(name, "weight_halved", weight / 2 + (d.value_of(name) - share))


# ---- Problem 5.2: an aircraft turning -----------------------------------------------------

def aircraft_turning(p, d):
    """Problem 5.2: the couple of an aircraft's engine and propeller in a level turn, and its effect."""
    inertia = d.step("I", gy.moment_of_inertia(p.m, p.k), "kg*m^2", formula=r"@m\,@k^2")
    spin_speed(p, d)
    precession(p, d)
    couple_step(d, "I")
    couple_slips(p, d, inertia, _rpm(p), p.v / KMH / p.R)
    d.mistake("C", "radius_for_k", p.m * p.k ** 2 / 2 * d.value_of("omega") * d.value_of("Omega"))
    view = "rear" if p.view == "rear" else "front"
    couple = directions(d, gy.axial_spin(p.sense, view), axial_spin_note(p.sense, view, view),
                        gy.turning(p.turn), turn_note(p.turn), "aircraft")
    effect = "raises the nose" if gy.pitch_effect(couple) == "nose up" else "lowers the nose"
    d.step("effect", effect, "", symbol=r"\text{effect}",
           note=f"a couple pointing {word(couple, 'aircraft')} pitches the aircraft: it {effect} and "
                f"{'dips' if effect == 'raises the nose' else 'raises'} the tail")
    d.mistake("effect", "precession_reversed", "lowers the nose" if effect == "raises the nose" else "raises the nose")


# ---- Problem 5.4: a ship's turbine when steering, pitching and rolling --------------------------

def ship_turbine(p, d):
    """Problem 5.4 and its companions: steering (couple and effect), pitching (greatest couple and
    effect) and rolling (no effect: the roll axis is the spin axis)."""
    inertia = d.step("I", gy.moment_of_inertia(p.m, p.k), "kg*m^2", formula=r"@m\,@k^2")
    spin_speed(p, d)
    precession(p, d)
    c = couple_step(d, "I")
    couple_slips(p, d, inertia, _rpm(p), p.v / KMH / p.R)
    view = "rear" if p.view == "stern" else "front"
    spin = gy.axial_spin(p.sense, view)
    couple = directions(d, spin, axial_spin_note(p.sense, view, p.view), gy.turning(p.turn), turn_note(p.turn), "ship")
    steer = "raises the bow" if gy.pitch_effect(couple) == "nose up" else "lowers the bow"
    d.step("steer_effect", steer, "", symbol=r"\text{steering}",
           note=f"a couple pointing {word(couple, 'ship')} turns the ship about its athwartships axis: it {steer}")
    d.mistake("steer_effect", "precession_reversed", "lowers the bow" if steer == "raises the bow" else "raises the bow")

    rate = d.step("omega_p", gy.pitching_rate(p.phi, p.T), "rad/s", symbol=r"\omega_{p,\max}",
                  formula=r"@phi\,\frac{2\pi}{@T}",
                  note="the pitch is simple harmonic, φ = φ₀ sin(2πt/T): its angular speed peaks at φ₀ 2π/T, "
                       "with φ₀ in radians")
    d.mistake("omega_p", "degrees_not_converted", math.degrees(p.phi) * 2 * math.pi / p.T)
    d.mistake("omega_p", "missing_2pi", p.phi / p.T)
    d.step("C_p", gy.couple(inertia, d.value_of("omega"), rate), "N*m", symbol=r"C_{\max}",
           formula=r"@I\,@omega\,@omega_p", note="the greatest couple while pitching")
    d.mistake("C_p", "rpm_as_rad_s", inertia * _rpm(p) * rate)
    rising = p.pitch == "rising"
    pitch_vector = gy.pitching(rising)
    pitch_couple = gy.reactive_couple(spin, pitch_vector)
    d.step("pitch_vector", word(pitch_vector, "ship"), "", symbol=r"\vec{\omega}_p",
           note=f"the bow {'rising' if rising else 'falling'}: curl the fingers with the pitch and the thumb points "
                f"{word(pitch_vector, 'ship')}")
    side = "port" if gy.yaw_effect(pitch_couple) == "left" else "starboard"
    d.step("pitch_effect", side, "", symbol=r"\text{pitching}",
           formula=r"I\,\vec{\omega} \times \vec{\omega}_p",
           note=f"the couple points {word(pitch_couple, 'ship')}: about the vertical axis it turns the bow to {side}")
    d.mistake("pitch_effect", "precession_reversed", "starboard" if side == "port" else "port")
    rolled = gy.reactive_couple(spin, gy.rolling(to_right=True))  # either way: Ω along the rotor's own axis
    d.require(not any(rolled), "the rotor does not spin about the roll axis")
    d.step("roll_effect", "no effect", "", symbol=r"\text{rolling}",
           note="rolling turns the ship about its fore-and-aft axis, the rotor's own axis: Ω is parallel to ω, "
                "ω × Ω = 0, so there is no gyroscopic couple")
    d.mistake("roll_effect", "rolling_like_steering", steer)
    d.mistake("roll_effect", "rolling_like_pitching", side)
    d.require(c > 0, "no couple")
