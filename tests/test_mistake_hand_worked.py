"""Named mistakes worked by hand from the course text's own data, one or more of each kind of slip: a unit
left unconverted, a diameter for a radius, a ratio upside down or not squared, a term left out, a sign or
side reversed, the wrong formula or member, a factor of two or 2π, a count rounded the wrong way, a formula
with a slip in it. Each value is the one the key records for that slip, to the figures shown."""
import math

import pytest

from textbook_helpers import solved

EXAMPLE_1_5 = dict(d1="0.5 m", d2="1.2 m", X="3.6 m", rho="2812.5 kg/m^3", A="320 mm^2", E="300 MN/m^2",
                   sigma="6.25 MPa", N1="200 rpm", mu="0.3")
PROBLEM_1_2 = dict(tau_M="1000 N*m", eta="90 %", ml="2000 kg", a="0.5 m/s^2", R="500 N", dD="1 m", t1=80, t2=100,
                   t3=20, t4=40, I_M="2 kg*m^2", I_T="20 kg*m^2", I_D="50 kg*m^2")
EXAMPLE_3_1 = dict(a1="295 mm^2", a2="685 mm^2", a3="40 mm^2", a4="340 mm^2", a5="960 mm^2", first="above",
                   Ts="5 N*m", As="1 deg", N="1800 rpm", m="36 kg", k="150 mm")

CASES = [
    # ---- units left unconverted
    # v = ω r with ω = 200 (the rpm figure) and r = 0.25 m: 50.00 m/s (right: 2π·200/60 × 0.25 = 5.236 m/s)
    ("belts.flat_belt_power", EXAMPLE_1_5, "b", "rpm_as_rad_s", 50.00),
    # P₁ = τ₁ N₁ = 80 N·m × 300 = 24 000 W = 24.00 kW (right: 80 × 31.42 rad/s = 2.513 kW)
    ("gears.gear_pair_power", dict(m="10 mm", t1=20, t2=60, tau1="80 N*m", N1="300 rpm", eta="85 %"), "e",
     "rpm_as_rad_s", 24.00),
    # h = g/ω² with ω = 50: 9.81/2500 = 0.003924 m = 3.924 mm (right: 9.81/5.236² = 357.8 mm)
    ("governors.watt_height", dict(N1="50 rpm", dN="1 rpm", l="500 mm"), "a", "rpm_as_rad_s", 3.924),
    # Ω = v/R with v = 200 (km/h) and R = 50 m: 4.000 rad/s (right: 55.56/50 = 1.111 rad/s)
    ("gyroscopes.aircraft_turning", dict(m="400 kg", k="0.3 m", N="2400 rpm", sense="clockwise", view="rear",
                                         v="200 km/h", R="50 m", turn="left"), "a", "kmh_not_converted", 4.000),
    # ---- a diameter for a radius
    # v = ω d = (2π·200/60)(0.5 m) = 20.944 × 0.5 = 10.47 m/s, twice the belt speed
    ("belts.flat_belt_power", EXAMPLE_1_5, "b", "diameter_for_radius", 10.47),
    # each crank's force (m/2) r ω² with the stroke for r: 3 × 1 kg × 0.12 m × 209.44² = 15 791 N (right: 7896 N)
    ("balancing.radial_engine", dict(ncyl="3", S="120 mm", l="180 mm", m="2 kg", N="2000 rpm"), "a",
     "stroke_for_radius", 15791),
    # ---- a ratio not squared, or upside down
    # I_EQ = I_M + I_T n₁/η + I_D n/η² = 2 + 20 × 0.8/0.9 + 50 × 0.4/0.81 = 2 + 17.78 + 24.69 = 44.47 kg·m²
    # (right: 2 + 20 × 0.64/0.9 + 50 × 0.16/0.81 = 26.10)
    ("gears.lift_counterweight", PROBLEM_1_2, "b", "ratio_not_squared", 44.47),
    # d₂ = d₁ N₂/N₁ = 600 × 400/300 = 800 mm (right: 600 × 300/400 = 450 mm)
    ("belts.driven_pulley_diameter", dict(N1="300 rpm", N2="400 rpm", d1="60 cm", t="8 mm", G="5 %"), "a",
     "ratio_inverted", 800.0),
    # the secondary direct force times n² instead of over it: 2 cos 30° × 884.3 N × 3² = 13 785 N (right: 1532 N)
    ("balancing.v_engine", dict(V="60 deg", S="140 mm", l="210 mm", m="1.2 kg", N="2400 rpm"), "c", "n_inverted", 13785),
    # ---- a term left out
    # Example 1.12 without the inertias: only the load's torque at the motor, M(g + a) r n/η =
    # 250 × 11.01 × 0.6 × 0.1/0.9 = 183.5 N·m (right: 183.5 + I_EQ α_M = 183.5 + 5.556 × 20 = 294.6 N·m)
    ("gears.hoist_torque", dict(M="250 kg", a="1.2 m/s^2", dD="1.2 m", t1=20, t2=200, eta="90 %", mM="250 kg",
                                kM="100 mm", mD="1100 kg", kD="500 mm", slope="10 deg", f="1000 N", tau_fM="10 N*m",
                                tau_fD="200 N*m"), "c", "inertia_forgotten", 183.5),
    # one ball's force only: F a/b − M g − f with F = 4 × (2π·280/60)² × 0.14 = 481.5 N:
    # 481.5 × 1.5 − 147.15 − 12 = 563.0 N (right, both balls: 1285 N)
    ("governors.hartnell_spring", dict(m="4 kg", a="120 mm", b="80 mm", M="15 kg", r1="140 mm", dr="25 mm",
                                       N1="280 rpm", dN="20 rpm", f="12 N"), "a", "one_ball", 563.0),
    # N₂ = N₁ d₁/d₂ = 1200 × 40/70 = 685.7 rpm, the 6 % slip left out (right: 644.6 rpm)
    ("belts.driven_speed_slip", dict(N1="1200 rpm", d1="40 cm", d2="70 cm", G1="3%", G2="3%", t="0 mm"), "b",
     "slip_not_applied", 685.7),
    # ---- a sign or side reversed
    # creep added: T₁ − T₂ = 2000 − 840.7 = 1159.3 N at 5.236 m/s is 6070 W; the strain difference
    # 1159.3/(320 mm² × 300 MN/m²) = 0.012076 added: 6070 × 1.012076 = 6143 W = 6.143 kW (right: 5.997 kW)
    ("belts.flat_belt_power", EXAMPLE_1_5, "e", "creep_added", 6.143),
    # A's moment 7.5 × 30 × 0.4 = 90 kg·mm·m taken at +0.4 m: with C's 97.5 the polygon is (97.5, −90),
    # closed by D at 180° − tan⁻¹(90/97.5) = 180° − 42.71° = 137.29° (right: 222.71°)
    ("balancing.complete_balance_position", dict(mA="7.5 kg", rA="30 mm", thetaA="270 deg", rB="36 mm", mC="5 kg",
                                                 rC="39 mm", mD="4 kg", rD="33 mm", lAB="0.4 m", lBC="0.5 m"), "b",
     "sign_lost", 137.29),
    # the balancing mass put where the resultant points: 233.13° − 180° = 53.13°
    ("balancing.static_balance", dict(m1="3 kg", r1="1 mm", m2="2 kg", r2="2 mm", theta2="90 deg", m3="0 kg",
                                      r3="1 mm", theta3="180 deg", b="1 mm"), "a", "resultant_not_balance", (5.0, 53.13)),
    # Problem 4.4: friction on the wrong side while the sleeve falls gives the rising speed,
    # √((21.2 g + 39.75)/(1.2 × 0.1673)) = 35.13 rad/s = 335.5 rpm (right: 276.4 rpm)
    ("governors.porter_sleeve_friction", dict(l="180 mm", e="40 mm", m="1.2 kg", M="20 kg", N0="275 rpm",
                                              alpha0="25 deg", alpha1="45 deg"), "b", "friction_wrong_side", 335.5),
    # Example 5.1: the right spring stretches; the precession reversed stretches the left
    ("gyroscopes.vehicle_rotor_springs", dict(I="4 kg*m^2", N="1500 rpm", spin="same", K="20 kN/m", l="30 cm",
                                              v="60 km/h", R="30 m", turn="right"), "f", "precession_reversed", "left"),
    # ---- the wrong formula or member
    # the four-bar example in circuit 2: θ₃ = 2 tan⁻¹((−8 sin 75° − 10 sin 61.24°)/(14 + 16 − 8 cos 75° − 10 cos 61.24°))
    # = 2 tan⁻¹(−16.494/23.118) = −71.01° (right, circuit 1: 5.146°)
    ("linkages.fourbar_position", dict(L1="14 inch", L2="8 inch", L3="16 inch", L4="10 inch", theta2="75 deg",
                                       circuit="1"), "c", "wrong_circuit", -71.01),
    # I_G = m k_G² = 5 × 0.1² = 0.05 kg·m², about the centre of gravity (right, about the knife edge: 0.25)
    ("vibration.compound_pendulum", dict(m="5 kg", h="200 mm", k_G="100 mm"), "a", "wrong_axis", 0.05),
    # ---- a factor of two or 2π
    # ω_n = √(9.81/1) = 3.132 rad/s given for f_n (right: 3.132/2π = 0.4985 Hz)
    ("vibration.simple_pendulum", dict(l="1 m", m="1 kg", T="2 s"), "b", "omega_for_f", 3.132),
    # ±0.5 % read as C_s = 0.5 %: I = ΔE/(ω² C_s) = 2983/(15.708² × 0.005) = 2418 kg·m² (right: 1209)
    ("flywheels.turning_moment_equation", dict(T0="14500 N*m", b="2300 N*m", c="-1900 N*m", n=2, N="150 rpm",
                                               band="0.5 %", theta="30 deg"), "b", "plus_minus_read_as_total", 2418),
    # C_s = 0.2987 % halved: 0.1493 %
    ("flywheels.speed_fluctuation", EXAMPLE_3_1, "d", "half_band", 0.1493),
    # ΔE/(m k N²) = 85.96/(36 × 0.15 × 188.50²) = 4.480e-4 = 0.04480 %: k not squared
    ("flywheels.speed_fluctuation", EXAMPLE_3_1, "d", "k_not_squared", 0.04480),
    # η multiplied in: I_M + I_T n₁² η + I_D n² η² = 2 + 20 × 0.64 × 0.9 + 50 × 0.16 × 0.81 = 2 + 11.52 + 6.48 = 20.00
    ("gears.lift_counterweight", PROBLEM_1_2, "b", "efficiency_multiplied", 20.00),
    # ---- cycles counted wrong, a count rounded the wrong way
    # δ = ln(a₁/a_r)/(n + 1) = ln 4/6 = 0.2310 (right: ln 4/5 = 0.2773)
    ("vibration.log_decrement", dict(m="3 kg", n_s=1, K="4 N/mm", a1="40 mm", a_r="10 mm", n=5), "a",
     "cycles_plus_one", 0.2310),
    # 100 kW over 12.89 kW a belt is 7.757 belts: rounded down, 7 (right: 8)
    ("belts.v_belt_count", dict(P="100 kW", N2="250 rpm", N1="1250 rpm", d2_max="1 m", X="1.75 m", v_max="1800 m/min",
                                A="400 mm^2", rho="1000 kg/m^3", sigma="3.25 MPa", groove="60 deg", mu="0.3",
                                idler="10 %"), "a", "rounded_down", 7),
    # S with P, 20 + 50 = 70 mm, for S + L
    ("linkages.grashof", dict(AB="20 mm", BC="70 mm", CD="50 mm", DA="80 mm", ground="DA"), "a", "wrong_pair", 70.0),
    # ---- a formula with a slip in it: the 2π left out of Example 6.2's pulley, at K = 1000 N/m, M = 2 kg, m = 1 kg:
    # √(K/(3M/2 + 4m)) = √(1000/7) = 11.95 (right: 11.95/2π = 1.902 Hz)
    ("vibration.natural_frequency_formula", dict(system="floating pulley", K="1000 N/m", M="2 kg", m="1 kg"), "b",
     "omega_for_f", 11.95),
]


def value_figures(expected) -> float:
    """Half a unit in the last figure written: the tolerance of a number worked to the figures shown."""
    text = f"{expected:.6g}"
    places = len(text.split(".")[1]) if "." in text else 0
    return 0.5 * 10 ** -places if places else 0.5


@pytest.mark.parametrize("template_id, given, part, mistake, expected", CASES,
                         ids=[f"{c[0]}-{c[2]}-{c[3]}" for c in CASES])
def test_the_slip_gives_the_value_worked_by_hand(bank, template_id, given, part, mistake, expected):
    variant, _, _ = solved(bank, template_id, **given)
    recorded = variant.mistakes[part][mistake]
    if isinstance(expected, str):
        assert recorded == expected
    elif isinstance(expected, tuple):
        assert recorded.magnitude == pytest.approx(expected[0], abs=value_figures(expected[0]))
        assert recorded.angle_deg == pytest.approx(expected[1], abs=value_figures(expected[1]))
    elif variant.template.part(part).type == "angle":
        assert abs((recorded - expected + 180) % 360 - 180) <= value_figures(expected)
    else:
        assert recorded == pytest.approx(expected, abs=value_figures(expected))


def test_every_kind_of_slip_is_worked_by_hand():
    """The kinds above, each met at least once, and the three slips that once passed every test unchecked."""
    named = {(c[0], c[3]) for c in CASES}
    assert {("belts.flat_belt_power", "diameter_for_radius"), ("belts.flat_belt_power", "creep_added"),
            ("gears.lift_counterweight", "ratio_not_squared")} <= named
    assert len({c[3] for c in CASES}) >= 25
