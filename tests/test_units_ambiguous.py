"""A unit of the asked dimension but another kind is neither right nor wrong: it is a format problem that
names the two readings. A torque written in J (an energy unit), an energy written in N·m (a torque's), an
angular speed written in bare 1/s (radians or revolutions per second?). No false conversion is printed
("1 rad/s = 0.1592 1/s"). Checked over every part of every template of the bank, at several seeds, and so
for practice too, which marks with the same code."""
import re

import pytest

from exgen import units
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from graders.results import CORRECT, UNREADABLE

SEEDS = (1, 2, 3)
NUMERIC = ("number", "integer")


def _parts(bank, pick):
    for template in bank:
        for part in template.parts:
            if part.type in NUMERIC and part.unit and pick(part.unit):
                yield template, part


def _torque_or_energy(unit: str) -> bool:
    return units.unit_info(unit).kind == "torque or energy"


def _angular_rate(unit: str) -> bool:
    info = units.unit_info(unit)
    return info.angle == 1 and info.dims == "[time]^-1"


def _message(variant, part, text):
    return next(p for p in grade_variant(variant, {part.id: text}).parts if p.part_id == part.id)


def test_the_bank_asks_for_torques_energies_and_angular_speeds():
    """The checks below run over something: the bank has parts of each kind."""
    from exgen.load.bank import load_bank

    bank = load_bank()
    energies = [p for _, p in _parts(bank, _torque_or_energy) if units.si_unit(p.unit) == "J"]
    torques = [p for _, p in _parts(bank, _torque_or_energy) if units.si_unit(p.unit) != "J"]
    rates = list(_parts(bank, _angular_rate))
    assert energies and torques and rates


def test_an_energy_unit_for_a_torque_and_a_torque_unit_for_an_energy_are_format_problems(bank):
    found = []
    for template, part in _parts(bank, _torque_or_energy):
        energy_asked = units.si_unit(part.unit) == "J"
        for seed in SEEDS:
            variant = make_variant(template, seed)
            value = units.convert(variant.answers[part.id].value, part.unit, "J")
            number = f"{value:.6g}"
            for other in (("N*m", "N m", "kN*m") if energy_asked else ("J", "kJ")):
                shown = number if other != "kN*m" and other != "kJ" else f"{value / 1000:.6g}"
                result = _message(variant, part, f"{shown} {other}")
                meant = units.pretty_unit(part.unit)
                ok = (result.status == UNREADABLE and result.points == 0
                      and ("is a torque unit" if energy_asked else "is an energy unit") in result.message
                      and re.search(rf"write [\d.e+-]+ {re.escape(meant)} if you mean", result.message)
                      and " = " not in result.message)
                if not ok:
                    found.append((template.id, part.id, seed, f"{shown} {other}", result.status, result.message))
            right = _message(variant, part, f"{variant.answers[part.id].value:.6g} {part.unit}")
            if right.status != CORRECT:
                found.append((template.id, part.id, seed, "in the asked unit", right.status, right.message))
    assert not found, found[:5]


def test_a_bare_reciprocal_second_for_an_angular_speed_is_a_format_problem(bank):
    found = []
    for template, part in _parts(bank, _angular_rate):
        for seed in SEEDS:
            variant = make_variant(template, seed)
            value = units.convert(variant.answers[part.id].value, part.unit, "rad/s")
            for written in ("1/s", "s^-1", "s\u207b\u00b9"):
                text = f"{value:.6g} {written}"
                result = _message(variant, part, text)
                ok = (result.status == UNREADABLE and result.points == 0
                      and "rad/s" in result.message and "rev/s" in result.message
                      and f"write {value:.6g} rad/s if you mean" in result.message
                      and " = " not in result.message)
                if not ok:
                    found.append((template.id, part.id, seed, text, result.status, result.message))
    assert not found, found[:5]


def test_units_that_say_which_they_are_still_convert(bank):
    """Hz counts cycles, rad/s radians: an angular speed in rev/s or Hz converts, and a frequency in 1/s is in Hz."""
    template, part = next(_parts(bank, _angular_rate))
    variant = make_variant(template, 1)
    rev_per_s = units.convert(variant.answers[part.id].value, part.unit, "rev/s")
    for written in ("rev/s", "Hz"):
        assert _message(variant, part, f"{rev_per_s:.6g} {written}").status == CORRECT
    frequency = next((t, p) for t in bank for p in t.parts
                     if p.type == "number" and p.unit == "Hz")
    variant = make_variant(frequency[0], 1)
    value = variant.answers[frequency[1].id].value
    assert _message(variant, frequency[1], f"{value:.6g} 1/s").status == CORRECT
    assert _message(variant, frequency[1], f"{value:.6g} s^-1").status == CORRECT


@pytest.mark.parametrize("text, asked, words", [
    ("140.4 J", "N*m", ("J is an energy unit; a torque is in N·m: write 140.4 N·m if you mean the torque",)),
    ("482.6 N*m", "J", ("N·m is a torque unit; an energy is in J: write 482.6 J if you mean the energy",)),
    ("31.416 1/s", "rad/s", ("1/s could be rad/s or rev/s", "write 31.416 rad/s if you mean radians per second")),
])
def test_the_message_names_the_two_readings(text, asked, words):
    from exgen.answertypes.quantity import in_unit
    from exgen.errors import QuantityError

    with pytest.raises(QuantityError) as info:
        in_unit(text, asked)
    assert all(w in str(info.value) for w in words), str(info.value)
