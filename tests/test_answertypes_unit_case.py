"""A unit typed in the wrong case is read as the one unit of the asked kind it can only mean ("1.2 KN",
"12.8 kw", "62 NM", "5.2 M/S"), never as milli for mega or mega for milli; a unit that measures nothing
nameable says the asked kind and that capitals matter, not pint's dimension."""
import pytest

from exgen.answertypes import answer_type
from exgen.errors import FormatProblem, WrongKind
from exgen.load.template import PartSpec


def part(unit: str) -> PartSpec:
    return PartSpec("a", "x", "v", unit)


def read(text: str, unit: str) -> float:
    spec = part(unit)
    return answer_type(spec).read(text, spec).value


@pytest.mark.parametrize("text, unit, value", [
    ("1.2 KN", "N", 1200.0), ("1.2kn", "N", 1200.0), ("1200 n", "N", 1200.0), ("1.2 Kn", "kN", 1.2),
    ("12.84 kw", "kW", 12.84), ("12.84 KW", "kW", 12.84), ("12840 w", "kW", 12.84),
    ("3.2 hz", "Hz", 3.2), ("3.2 HZ", "Hz", 3.2), ("3.2 S", "s", 3.2),
    ("5.24 M/S", "m/s", 5.24), ("18.9 KM/H", "m/s", 5.25),
    ("62 NM", "N*m", 62.0), ("62 nm", "N*m", 62.0), ("62 N.M", "N*m", 62.0), ("0.062 KNM", "N*m", 62.0),
    ("2 KG M^2", "kg*m^2", 2.0), ("13 KN/M", "kN/m", 13.0), ("3 KG", "kg", 3.0),
    # the right case is read as before, whatever else is nearby
    ("1.2 kN", "N", 1200.0), ("2.546 Mm", "mm", 2.546e9),
])
def test_a_unit_in_the_wrong_case_is_read_as_the_one_it_can_only_mean(text, unit, value):
    assert read(text, unit) == pytest.approx(value)


@pytest.mark.parametrize("text, unit", [("12.84 mw", "kW"), ("2.546 MM", "mm"), ("3.2 MS", "s"), ("5 mn", "N")])
def test_milli_and_mega_are_never_guessed(text, unit):
    with pytest.raises((FormatProblem, WrongKind)):
        read(text, unit)


def test_a_unit_of_no_nameable_kind_says_what_is_asked_and_that_capitals_matter():
    with pytest.raises(WrongKind) as info:
        read("2.546 MM", "mm")
    message = str(info.value)
    assert "length is asked (in mm)" in message and "capitals" in message and "dimension" not in message
