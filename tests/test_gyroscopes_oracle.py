"""Every direction a chapter 5 key prints, checked over many drawn variants by an oracle of its own.

The oracle reads only what the sheet prints (the sense of rotation and the side it is seen from, the
turn, the pitch) and works each direction by an explicit cross product in the vehicle's axes
(x forward, y to the left, z up): the reactive couple on the vehicle is spin × precession, and a
couple about +x lifts the left side, about +y dips the nose, about +z turns the nose to the left. It
then reads the physical answer (which spring stretches, which bearing is relieved, which axle is
loaded, which way the bow turns) from that couple, with no code from exgen's mechanics or solvers.
"""
from __future__ import annotations

import math

import pytest

from exgen.solve.variant import make_variant

SEEDS = range(150)
X, Y, Z = (1, 0, 0), (0, 1, 0), (0, 0, 1)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def neg(a):
    return tuple(-c for c in a)


def fore_and_aft_spin(sense: str, seen_from: str):
    """A rotor on the fore-and-aft axis: seen turning clockwise, its vector points away from the viewer."""
    looking = X if seen_from in ("rear", "stern") else neg(X)     # from behind one looks forward
    return looking if sense == "clockwise" else neg(looking)


def turning(turn: str):
    return Z if turn == "left" else neg(Z)                          # a left turn is anticlockwise from above


def nose(couple) -> str:
    assert couple[0] == 0 and couple[2] == 0
    return "down" if couple[1] > 0 else "up"                        # about +y, x turns towards -z


def given(variant, name: str) -> str:
    return variant.param(name).text


def variants(bank, template_id):
    template = bank.get(template_id)
    return [make_variant(template, seed) for seed in SEEDS]


def test_flywheel_on_springs_stretches_the_spring_on_the_side_the_couple_lifts(bank):
    for v in variants(bank, "gyroscopes.vehicle_rotor_springs"):
        spin = Y if given(v, "spin") == "same" else neg(Y)           # road wheels rolling forward spin about +y
        couple = cross(spin, turning(given(v, "turn")))
        lifted = "left" if couple[0] > 0 else "right"                 # about +x the left side rises
        assert v.answers["f"].value == lifted, v.seed


def test_ship_engine_bearings_follow_the_bow(bank):
    for v in variants(bank, "gyroscopes.rotor_bearing_reactions"):
        couple = cross(fore_and_aft_spin(given(v, "sense"), "stern"), turning(given(v, "turn")))
        up = nose(couple) == "up"
        assert v.answers["b"].value == ("raises the bow" if up else "lowers the bow"), v.seed
        # the rotor pushes the forward bearing A up when the bow rises: A's upward reaction on it falls
        m, l, a = (v.param(n).si for n in ("m", "l", "a"))
        share_a, share_b = m * 9.81 * (l - a) / l, m * 9.81 * a / l
        force = v.answers["a"].si / l
        expect_a, expect_b = (share_a - force, share_b + force) if up else (share_a + force, share_b - force)
        assert v.answers["c"].si == pytest.approx(expect_a, rel=1e-9), v.seed
        assert v.answers["d"].si == pytest.approx(expect_b, rel=1e-9), v.seed


def test_aircraft_nose_seen_from_either_end(bank):
    for v in variants(bank, "gyroscopes.aircraft_turning"):
        couple = cross(fore_and_aft_spin(given(v, "sense"), given(v, "view")), turning(given(v, "turn")))
        assert v.answers["c"].value == ("raises the nose" if nose(couple) == "up" else "lowers the nose"), v.seed


def test_ship_turbine_steering_pitching_and_rolling(bank):
    for v in variants(bank, "gyroscopes.ship_turbine"):
        spin = fore_and_aft_spin(given(v, "sense"), given(v, "view"))
        steer = cross(spin, turning(given(v, "turn")))
        assert v.answers["b"].value == ("raises the bow" if nose(steer) == "up" else "lowers the bow"), v.seed
        pitch = neg(Y) if given(v, "pitch") == "rising" else Y       # the bow rising turns the ship about -y
        yaw = cross(spin, pitch)
        assert yaw[0] == 0 and yaw[1] == 0
        assert v.answers["e"].value == ("port" if yaw[2] > 0 else "starboard"), v.seed   # about +z the bow goes left
        assert cross(spin, X if spin[0] > 0 else neg(X)) == (0, 0, 0) and v.answers["f"].value == "no effect"


def test_car_engine_loads_the_axle_its_couple_presses_down(bank):
    for v in variants(bank, "gyroscopes.car_wheel_reactions"):
        turn = given(v, "turn")
        engine = cross(fore_and_aft_spin(given(v, "sense"), "front"), turning(turn))
        loaded = "rear" if nose(engine) == "up" else "front"
        assert v.answers["c"].value == loaded, v.seed
        wheels = cross(Y, turning(turn))
        pressed = "right" if wheels[0] > 0 else "left"                # about +x the right side goes down
        assert pressed == ("left" if turn == "right" else "right")    # the wheels' couple loads the outer side
        reactions = {k: v.answers[p].si for k, p in (("fl", "e"), ("fr", "f"), ("rl", "g"), ("rr", "h"))}
        outer, inner = pressed[0], "r" if pressed == "left" else "l"
        assert reactions["f" + outer] > reactions["f" + inner] and reactions["r" + outer] > reactions["r" + inner]
        up, down = ("r", "f") if loaded == "rear" else ("f", "r")
        # the engine's share alone: the loaded axle's pair gains what the other pair loses
        gain = (reactions[up + "l"] + reactions[up + "r"]) - (reactions[down + "l"] + reactions[down + "r"])
        m, a, b = (v.param(n).si for n in ("m", "a", "b"))
        weights = {"f": m * 9.81 * (b - a) / b, "r": m * 9.81 * a / b}
        assert gain == pytest.approx(weights[up] - weights[down] + 4 * v.answers["b"].si, rel=1e-9), v.seed


def test_rail_car_motors_against_their_axles_relieve_only_when_they_outweigh_them(bank):
    for v in variants(bank, "gyroscopes.rail_car_limiting_speed"):
        I_a, I_m, G = (v.param(n).si for n in ("I_a", "I_m", "G"))
        motors = G * I_m if given(v, "motor") == "same" else -G * I_m
        assert v.answers["c"].value == ("adds" if I_a + motors > 0 else "relieves"), v.seed


@pytest.mark.parametrize("template_id", ["gyroscopes.motorcycle_heel", "gyroscopes.motorcycle_banking"])
def test_two_wheeler_couple_overturns_outwards_as_the_working_says(bank, template_id):
    """The heel's working adds the gyroscopic couple to the centrifugal one, both overturning outwards, and
    the part asks for it with no sign convention: an engine that outweighs the wheels is never drawn."""
    for v in variants(bank, template_id):
        assert v.answers["b"].value > 0, v.seed
        assert math.isfinite(v.answers["d"].value)


def test_a_heel_given_with_the_engine_outweighing_the_wheels_is_flagged(bank):
    from exgen.check.given import solve

    variant, warnings = solve(bank.get("gyroscopes.motorcycle_heel"), {
        "I_w": "0.5 kg*m^2", "I_e": "0.39 kg*m^2", "G": "6", "engine": "opposite", "d_w": "0.69 m",
        "m": "150 kg", "h": "0.6 m", "v": "45 km/h", "R": "50 m"})
    assert variant.answers["b"].value < 0
    assert any("outweighs" in w for w in warnings)
