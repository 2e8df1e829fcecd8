"""A parameter's physical domain: `exgen solve` refuses values outside it and warns about values outside
the drawing range; templates may declare a domain, and never draw outside it."""
import math

import pytest

from exgen.cli import main
from exgen.errors import BankError
from exgen.load.bank import load_template
from exgen.load.domains import ANY, NOT_NEGATIVE, PERCENTAGE, POSITIVE, Domain, domain_of, parse_domain

GEAR_PAIR = ["solve", "gears.gear_pair_power", "--set", "m=4mm", "--set", "t1=20", "--set", "t2=60",
             "--set", "tau1=100N*m", "--set", "N1=1000rpm"]


def test_a_fraction_typed_for_a_percentage_is_warned_about(capsys):
    """`eta=0.9` was taken as 0.9 % without a word."""
    assert main([*GEAR_PAIR, "--set", "eta=0.9"]) == 0
    err = capsys.readouterr().err
    assert "eta=0.9 is read as 0.9 %" in err and "draws 95 to 98 %" in err  # a spur pair, 95-98 %
    assert "for the fraction write 90%" in err


@pytest.mark.parametrize("setting, message", [
    ("m=-4mm", "m (module) must not be negative"),
    ("eta=120", "eta (efficiency of the pair) must lie in (0, 100] %"),
    ("eta=0", "must lie in (0, 100] %"),
    ("eta=-5%", "must lie in (0, 100] %"),
    ("N1=-1000rpm", "N1 (input speed) must not be negative"),
    ("tau1=-0.1kN*m", "tau1 (input torque) must not be negative"),
])
def test_a_value_outside_the_physical_domain_is_refused(capsys, setting, message):
    """Negative diameters were accepted without a word."""
    argv = [*GEAR_PAIR, "--set", "eta=90"]
    name = setting.split("=")[0]
    argv = [a for i, a in enumerate(argv) if not (a.startswith(name + "=") or
                                                  (a == "--set" and argv[i + 1].startswith(name + "=")))]
    assert main([*argv, "--set", setting]) == 1
    err = capsys.readouterr().err
    assert err.startswith("exgen: ") and message in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("eta", ["90", "0.9%", "1%", "75"])
def test_a_percentage_written_as_one_is_not_questioned(capsys, eta):
    assert main([*GEAR_PAIR, "--set", f"eta={eta}"]) == 0
    assert "warning" not in capsys.readouterr().err


@pytest.mark.parametrize("text, domain", [
    ("(0, 100]", PERCENTAGE), ("(0, inf)", POSITIVE), ("any", ANY), ("(-inf, inf)", ANY),
    ("[0, 1)", Domain(0.0, 1.0, True, False)), (" [ -1.5 , 2e3 ] ", Domain(-1.5, 2000.0, True, True)),
])
def test_domains_are_written_as_intervals(text, domain):
    assert parse_domain(text) == domain


@pytest.mark.parametrize("text", ["0..100", "(1, 0)", "[0, 1", "positive", "(nan, 1)"])
def test_a_malformed_domain_is_refused(text):
    with pytest.raises(ValueError):
        parse_domain(text)


def test_interval_ends():
    assert 0 not in POSITIVE and 1e-9 in POSITIVE and 100 in PERCENTAGE and 100.01 not in PERCENTAGE
    assert 0 in NOT_NEGATIVE and -1e-12 not in NOT_NEGATIVE
    assert -math.inf < 0 and -1e300 in ANY and 0 in parse_domain("[0, 1)") and 1 not in parse_domain("[0, 1)")


def test_defaults_follow_the_unit_and_what_is_drawn(bank):
    params = {p.name: p for p in bank.get("gears.gear_pair_power").params}
    assert domain_of(params["eta"]) == PERCENTAGE and domain_of(params["m"]) == NOT_NEGATIVE
    assert domain_of(params["t1"]) == NOT_NEGATIVE  # a count
    angles = [p for t in bank for p in t.params if p.unit == "deg"]
    assert angles and all(domain_of(p) == ANY for p in angles)


TEMPLATE = """\
id: demo.restitution
title: Demo
solver: belts:drive_geometry
statement: "{{{{ e }}}}"
params:
  e: {{min: 0.2, max: 0.8, step: 0.1, domain: "{domain}"}}
parts:
  - {{id: a, ask: x, answer: L, unit: m}}
"""


def test_a_template_declares_a_domain(tmp_path):
    path = tmp_path / "t.yaml"
    path.write_text(TEMPLATE.format(domain="[0, 1)"), encoding="utf-8")
    template = load_template(path)
    assert domain_of(template.param("e")) == Domain(0.0, 1.0, True, False)


@pytest.mark.parametrize("domain, message", [("0 to 1", "not an interval"), ("(0, 0.5]", "draws 0.8, outside its domain (0, 0.5]")])
def test_a_bad_domain_names_the_file_and_line(tmp_path, domain, message):
    path = tmp_path / "t.yaml"
    path.write_text(TEMPLATE.format(domain=domain), encoding="utf-8")
    with pytest.raises(BankError) as caught:
        load_template(path)
    assert message in str(caught.value) and f"{path}:6" in str(caught.value)


def _solve_json(capsys, template, settings):
    argv = ["solve", template, "--json"] + [a for s in settings.split() for a in ("--set", s)]
    assert main(argv) == 0, capsys.readouterr().err
    import json
    return json.loads(capsys.readouterr().out)


SHAFT = "m1=2kg r1=40mm theta1=90deg m2=1kg r2=50mm theta2=0deg m3=1kg r3=50mm theta3=180deg rP=30mm rQ=20mm"


def test_positions_along_a_shaft_may_lie_either_side_of_the_reference(capsys):
    """A plane on the other side of the reference was refused ('z1 must not be negative'), so a problem given
    from plane P, as the textbook's tables give it, could not be solved as printed."""
    from_p = _solve_json(capsys, "balancing.two_plane_balance", SHAFT + " z1=-1.2m zP=0m z2=1.2m z3=2m zQ=2.4m")
    from_end = _solve_json(capsys, "balancing.two_plane_balance", SHAFT + " z1=0m zP=1.2m z2=2.4m z3=3.2m zQ=3.6m")
    assert [p["text"] for p in from_p["parts"].values()] == [p["text"] for p in from_end["parts"].values()] \
        == ["2.167 kg at 67.38°", "4.038 kg at 262.1°"]
    masses = ("m1=3kg r1=50mm theta1=0deg m2=2kg r2=60mm theta2=120deg m3=2kg r3=40mm theta3=240deg "
              "B1=3kg b1=150mm bX=150mm")
    assert _solve_json(capsys, "balancing.correction_plane_position", masses + " z1=-0.3m z2=1.2m z3=2m")["parts"]

