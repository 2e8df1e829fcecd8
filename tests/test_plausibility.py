"""Machines that could exist: every drawn variant is a belt, gear train or engine someone could build.

The first half checks the `report:` mechanism (declared quantities, rejection at draw time, warnings in
`exgen solve`, the ranges `exgen validate` prints). The second half checks each rule over many seeds
from the drawn numbers themselves, independently of the templates' own `report:` expressions, so a
wrong expression or a missing constraint cannot hide.
"""
import itertools
import math
from decimal import Decimal
from pathlib import Path

import pytest

from exgen.check.given import solve
from exgen.check.validate import validate_template
from exgen.draw.plausibility import Implausible
from exgen.errors import BankError, ExgenError
from exgen.load.bank import load_template
from exgen.mechanics import engines as me
from exgen.solve.variant import build_variant, make_variant

SEEDS = range(150)
RPM = 2 * math.pi / 60


def variants(bank, template_id):
    template = bank.get(template_id)
    return [make_variant(template, seed) for seed in SEEDS]


def si(variant, name):
    return variant.si[name]


def step(variant, name):
    return variant.step(name).value


# ---- the report: mechanism ---------------------------------------------------------------------

TEMPLATE = """\
id: test.belt
title: A belt
solver: belts:max_power
params:
  d1:    {min: 200, max: 300, step: 100, unit: mm}
  d2:    {value: 900, unit: mm}
  X:     {value: 3, unit: m}
  mu:    {value: 0.3}
  A:     {min: 300, max: 1200, step: 900, unit: mm^2}
  rho:   {choices: [1000, 3000], unit: kg/m^3}
  sigma: {value: 2, unit: MPa}
report:
%s
statement: A belt.
parts:
  - {id: a, ask: the speed, answer: v_opt, unit: m/s}
"""


def write(tmp_path: Path, report: str) -> Path:
    path = tmp_path / "belt.yaml"
    path.write_text(TEMPLATE % report, encoding="utf-8")
    return path


DENSITY = "  - {what: belt density, value: m / A, unit: kg/m^3, range: [1000, 1500]}"
DRAWN_DENSE = {k: Decimal(v) for k, v in dict(d1="200", d2="900", X="3", mu="0.3", A="300", rho="3000", sigma="2").items()}


def test_a_reported_quantity_outside_its_range_rejects_the_draw(tmp_path):
    template = load_template(write(tmp_path, DENSITY))
    assert template.report[0].what == "belt density" and (template.report[0].low, template.report[0].high) == (1000, 1500)
    for seed in range(30):
        variant = make_variant(template, seed)
        assert variant.param("rho").text == "1000"
        assert variant.derived[0].value == pytest.approx(1000)
    with pytest.raises(Implausible, match="belt density 3000 kg/m³ is outside the plausible 1000-1500 kg/m³"):
        build_variant(template, DRAWN_DENSE)


def test_solve_keeps_an_implausible_machine_and_says_why(tmp_path):
    # (d2, X, mu and sigma are fixed in the template with `value:`: solve takes them as they stand)
    template = load_template(write(tmp_path, DENSITY))
    variant, warnings = solve(template, {"d1": "200 mm", "A": "300 mm^2", "rho": "3000 kg/m^3"})
    assert warnings == ["belt density 3000 kg/m³ is outside the plausible 1000-1500 kg/m³"]
    assert variant.answers["a"].value == pytest.approx(math.sqrt(2e6 / 3 / 3000))


def test_validate_prints_the_drawn_range_and_why_draws_were_rejected(tmp_path):
    report = validate_template(load_template(write(tmp_path, DENSITY)), seeds=40)
    assert report.ok and report.ranges[0][1:] == pytest.approx((1000, 1000))
    lines = report.details()
    assert lines[0] == "belt density: drawn 1000 to 1000 kg/m³ (plausible 1000 to 1500)"
    assert lines[1].startswith("rejected ") and lines[1].endswith("of draws: implausible belt density")


def test_a_quantity_of_parameters_alone_is_checked_before_the_solver_runs(tmp_path, monkeypatch):
    template = load_template(write(tmp_path, "  - {what: belt density, value: rho, unit: kg/m^3, range: [1000, 1500]}"))

    def no_solver(*args, **kwargs):
        raise AssertionError("the solver ran for a draw its parameters already rule out")

    monkeypatch.setattr("exgen.solve.variant.run_solver", no_solver)
    with pytest.raises(Implausible):
        build_variant(template, DRAWN_DENSE)


def test_a_name_neither_parameter_nor_step_is_the_templates_error(tmp_path):
    template = load_template(write(tmp_path, "  - {what: oops, value: m / area, unit: kg/m^3, range: [1, 2]}"))
    with pytest.raises(ExgenError, match=r"test.belt: report\[0\] \(oops\): unknown name 'area'"):
        make_variant(template, 0)


@pytest.mark.parametrize("entry, message", [
    ("  - {what: x, value: m / A, unit: kg/m^3, range: [1500, 1000]}", "report, entry 1, range: must be [low, high] with low < high"),
    ("  - {what: x, value: m / A, unit: kg/m^3, range: 1000}", "report, entry 1, range: must be [low, high]"),
    ("  - {what: x, value: m / A, unit: blorps/m^7, range: [1, 2]}", "report, entry 1, unit: unknown unit"),
    ("  - {what: x, value: 'm /', unit: kg/m^3, range: [1, 2]}", "report, entry 1, value: cannot read"),
    ("  - {value: m / A, unit: kg/m^3, range: [1, 2]}", "report, entry 1, what: is required"),
    ("  - {what: x, value: m / A, range: [1, 2], why: because}", "report, entry 1, why: unknown key"),
    ("  - belt density", "report, entry 1: must be a mapping"),
])
def test_a_malformed_report_names_the_file_key_and_line(tmp_path, entry, message):
    with pytest.raises(BankError) as caught:
        load_template(write(tmp_path, entry))
    assert message in str(caught.value) and "belt.yaml:" in str(caught.value)


# ---- belts --------------------------------------------------------------------------------------

BELT_POWER = ("belts.flat_belt_power", "belts.v_belt_power", "belts.max_power")


@pytest.mark.parametrize("template_id", BELT_POWER + ("belts.v_belt_count",))
def test_belts_are_leather_or_rubber_at_a_belts_stress_and_speed(bank, template_id):
    for v in variants(bank, template_id):
        mass = step(v, "m")
        assert 1000 * (1 - 1e-9) <= mass / si(v, "A") <= 1500 * (1 + 1e-9)     # kg/m³: leather to rubber-fabric
        tension = step(v, "T_max" if template_id == "belts.max_power" else "T1")
        assert 1.75e6 * (1 - 1e-9) <= tension / si(v, "A") <= 3.5e6 * (1 + 1e-9)  # Pa: real belting's working stress
        speed = step(v, "v_opt" if template_id == "belts.max_power" else "v")
        assert 5 <= speed <= 32


@pytest.mark.parametrize("template_id", ["belts.v_belt_power", "belts.v_belt_count"])
def test_v_grooves_are_standard(bank, template_id):
    assert {round(math.degrees(si(v, "groove"))) for v in variants(bank, template_id)} <= {34, 36, 38, 40}


# ---- gears --------------------------------------------------------------------------------------

GEAR_TEMPLATES = ("gears.compound_train", "gears.epicyclic", "gears.gear_pair_power", "gears.haulage_power",
                  "gears.hoist_torque", "gears.lift_counterweight", "gears.pitch_geometry", "gears.reverted_train",
                  "gears.simple_train", "gears.teeth_for_centre_distance")


def tooth_counts(v):
    """Every tooth count on the sheet or in the solution: parameters and steps named t<something>, and
    the compound train's gears given by diameter and diametral pitch."""
    counts = {n: x for n, x in v.si.items() if n.startswith("t") and isinstance(x, float) and n not in ("theta",)}
    counts.update({s.name: s.value for s in v.steps if s.name.startswith("t") and isinstance(s.value, int)})
    if v.template.id == "gears.compound_train":
        counts.update({"t3": si(v, "d3") * si(v, "P23"), "t5": si(v, "d5") * si(v, "P45"), "t6": si(v, "d6") * si(v, "P67")})
    return {n: x for n, x in counts.items() if not n.startswith(("tau", "theta", "t_"))}


@pytest.mark.parametrize("template_id", GEAR_TEMPLATES)
def test_no_gear_has_fewer_than_twelve_teeth(bank, template_id):
    for v in variants(bank, template_id):
        found = tooth_counts(v)
        assert found and min(found.values()) >= 12 - 1e-9, (v.seed, found)


def test_epicyclic_planets_assemble_equally_spaced_and_clear_each_other(bank):
    for v in variants(bank, "gears.epicyclic"):
        sun, planet, ring, n = si(v, "ts"), si(v, "tp"), step(v, "tR"), int(si(v, "planets"))
        assert (sun + ring) % n == 0
        assert 2 * (sun + planet) / 2 * math.sin(math.pi / n) > planet + 2   # centres apart > tip diameter


@pytest.mark.parametrize("template_id", ["gears.gear_pair_power", "gears.hoist_torque", "gears.haulage_power",
                                         "gears.lift_counterweight", "gears.robot_arm"])
def test_a_spur_mesh_is_95_to_99_percent_efficient(bank, template_id):
    assert all(0.95 <= si(v, "eta") <= 0.99 for v in variants(bank, template_id))


def test_tooth_load_fits_the_module(bank):
    for v in variants(bank, "gears.gear_pair_power"):
        module, teeth = si(v, "m"), si(v, "t1")
        tangential = 2 * si(v, "tau1") / (module * teeth)
        lewis = tangential / (10 * module * module * 0.32)        # face width 10 m, form factor 0.32
        assert 20e6 <= lewis <= 200e6 + 1


def test_bigger_gears_have_bigger_inertias(bank):
    for v in variants(bank, "gears.robot_arm"):
        for small, big, k in (("I_G1", "I_G2", "k12"), ("I_G3", "I_G4", "k34")):
            ratio, k = si(v, big) / si(v, small), si(v, k)
            assert k ** 2 - 1e-9 <= ratio <= 1.5 * k ** 4 + 1e-9


# ---- engines ------------------------------------------------------------------------------------

REAL_FIRING = {"1-3-4-2", "1-2-4-3", "1-3-2", "1-2-3", "1-5-3-6-2-4", "1-4-2-6-3-5", "1-3-5-6-4-2"}


def test_in_line_engines_fire_in_real_orders(bank):
    for v in variants(bank, "balancing.inline_engine_firing"):
        assert v.param("firing").text in REAL_FIRING
        order = me.parse_firing_order(v.param("firing").text)
        if len(order) == 4 and int(v.param("strokes").text) == 4:
            angles = me.crank_angles(order, 4)
            assert math.isclose(angles[1], angles[4]) and math.isclose(angles[2], angles[3])  # flat-plane 1-4 / 2-3


def test_a_four_with_cranks_given_has_them_a_quarter_turn_apart(bank):
    for v in variants(bank, "balancing.inline_engine_unbalance"):
        angles = sorted(round(math.degrees(si(v, f"theta{i}"))) for i in range(1, 5))
        assert angles == [0, 90, 180, 270]


ENGINES = {  # template id -> (stroke, rod, reciprocating mass, speed) read from a variant, SI
    "balancing.inline_engine_firing": lambda v: (2 * si(v, "r"), si(v, "l"), si(v, "m"), si(v, "N")),
    "balancing.inline_engine_unbalance": lambda v: (2 * si(v, "r"), si(v, "l"), si(v, "m"), si(v, "N")),
    "balancing.inline_primary_balance": lambda v: (2 * si(v, "r"), si(v, "l"), si(v, "m_out"), si(v, "N")),
    "balancing.radial_engine": lambda v: (si(v, "S"), si(v, "l"), si(v, "m"), si(v, "N")),
    "balancing.v_engine": lambda v: (si(v, "S"), si(v, "l"), si(v, "m"), si(v, "N")),
}


@pytest.mark.parametrize("template_id", sorted(ENGINES))
def test_engines_have_real_piston_speeds_masses_and_rods(bank, template_id):
    for v in variants(bank, template_id):
        stroke, rod, mass, omega = ENGINES[template_id](v)
        assert 4 - 1e-9 <= 2 * stroke * omega / (2 * math.pi) <= 20 + 1e-9   # mean piston speed, m/s
        assert 400 - 1e-6 <= mass / stroke ** 3 <= 2500 + 1e-6                 # kg per stroke cubed
        assert 3 - 1e-9 <= rod / (stroke / 2) <= 5 + 1e-9


# ---- corrections of a sensible size ---------------------------------------------------------------

CORRECTIONS = {  # template id -> (corrections found, masses they balance)
    "balancing.static_balance": (("B",), ("m1", "m2", "m3")),
    "balancing.two_plane_balance": (("mP", "mQ"), ("m1", "m2", "m3")),
    "balancing.correction_plane_position": (("mX",), ("m1", "m2", "m3")),
    "balancing.complete_balance_masses": (("mA", "mD"), ("mB", "mC")),
    "balancing.complete_balance_position": (("mB",), ("mA", "mC", "mD")),
}


@pytest.mark.parametrize("template_id", sorted(CORRECTIONS))
def test_corrections_are_of_the_order_of_the_masses_they_balance(bank, template_id):
    found, given = CORRECTIONS[template_id]
    for v in variants(bank, template_id):
        heaviest = max(si(v, name) for name in given)
        for name in found:
            assert 0.1 - 1e-9 <= step(v, name) / heaviest <= 2 + 1e-9, (v.seed, name)


def test_inner_cranks_carry_masses_like_the_outer_ones(bank):
    for v in variants(bank, "balancing.inline_primary_balance"):
        assert all(0.5 <= step(v, name) / si(v, "m_out") <= 3 + 1e-9 for name in ("mB", "mC"))


def test_every_engine_and_belt_template_reports_what_makes_it_real(bank):
    for template_id in itertools.chain(ENGINES, BELT_POWER, CORRECTIONS, ["gears.gear_pair_power"]):
        assert bank.get(template_id).report, template_id


@pytest.mark.parametrize("template_id", ["belts.driven_speed_slip", "belts.compound_drive", "belts.driven_pulley_diameter"])
def test_every_flat_belt_runs_at_a_flat_belts_speed(bank, template_id):
    """The speed-ratio drives run their belts at up to 30 m/s, as the power drives do: a 50 cm motor pulley at
    1800 rpm (47 m/s) was drawn."""
    for v in variants(bank, template_id):
        belts = [si(v, "N1") * si(v, "d1") / 2]
        if template_id == "belts.compound_drive":
            belts.append(step(v, "N2") * si(v, "d3") / 2)
        assert max(belts) <= 30 * (1 + 1e-9), (v.seed, belts)


@pytest.mark.parametrize("template_id", ["gears.teeth_for_centre_distance", "gears.pitch_geometry", "gears.gear_pair_power"])
def test_spur_gears_run_at_a_spur_gears_pitch_line_velocity(bank, template_id):
    """Spur gears run at up to about 25 m/s at the pitch line: a 480 mm pinion at 1800 rpm (45 m/s) was drawn."""
    for v in variants(bank, template_id):
        m = si(v, "m")
        pinion = step(v, "t1") if template_id == "gears.teeth_for_centre_distance" else si(v, "t1")
        assert si(v, "N1") * m * pinion / 2 <= 25 * (1 + 1e-9), v.seed


def test_every_templates_ranges_give_their_reasons():
    """Each template says in YAML comments why its parameters range as they do (a real machine's sizes,
    speeds and masses, the textbook's own values): twelve chapter 1-2 templates said nothing."""
    import re

    silent = []
    for path in sorted(Path(__file__).resolve().parents[1].joinpath("banks").glob("*/*.yaml")):
        text = path.read_text(encoding="utf-8")
        block = re.search(r"^params:\n(.*?)^(?:require|report|statement):", text, re.S | re.M)
        if block and "#" not in block.group(1):
            silent.append(path.name)
    assert not silent, silent


@pytest.mark.parametrize("template_id", ["gears.hoist_torque", "gears.haulage_power", "gears.gear_pair_power"])
def test_a_single_spur_pair_reduces_by_ten_to_one_at_most(bank, template_id):
    """Example 1.12's 200/20 is about the most one spur pair is made to give: 240 teeth driven by 15 (16 : 1)
    was drawn for a hoist."""
    for v in variants(bank, template_id):
        assert si(v, "t2") <= 10 * si(v, "t1"), (v.seed, si(v, "t1"), si(v, "t2"))
