import math

import pytest

from exgen.errors import DimensionError, QuantityError
from exgen.units import convert, format_number, format_quantity, parse_quantity, pretty_unit, unit_info


@pytest.mark.parametrize("text, value, unit", [
    ("12.5", 12.5, None),
    ("  -3.5e2 ", -350.0, None),
    ("\u22125.2 kN", -5.2, "kN"),            # Unicode minus
    ("\u20135.2", -5.2, None),               # en dash typed as minus
    ("1.2 \u00d7 10^3 N", 1200.0, "N"),
    ("1.2x10^-3 m", 1.2e-3, "m"),
    ("2.4 * 10**2 W", 240.0, "W"),
    ("1.2\u00d710\u207b\u00b3 m", 1.2e-3, "m"),  # superscript exponent
    ("168.8\u00b0", 168.8, "\u00b0"),
    ("\u03b8 = 168.8 deg", 168.8, "deg"),
    ("v = 5.24 m/s", 5.24, "m/s"),
    ("= 1200 N", 1200.0, "N"),               # an equals sign, an "about" before the number
    ("\u2248 5.24 m/s", 5.24, "m/s"),
    ("~5.24 m/s", 5.24, "m/s"),
    ("F \u2248 1.2 kN", 1.2, "kN"),
    ("5 %", 5.0, "%"),
    ("3,5", 3.5, None),                      # decimal comma
    ("12 893 W", 12893.0, "W"),              # digit groups
    ("289.8 Nm", 289.8, "Nm"),
    ("5.2 kN\u00b7m", 5.2, "kN*m"),
    ("644.6 rev/min", 644.6, "rev/min"),
    ("309.2 N-m", 309.2, "N-m"),
    (".5 m", 0.5, "m"),
])
def test_parse_quantity_reads(text, value, unit):
    reading = parse_quantity(text)
    assert reading.value == pytest.approx(value)
    assert reading.unit == unit


@pytest.mark.parametrize("text", [
    "", "abc", "1,500", "__import__('os').system('x')", "9**9**9", "1e999999", "nan", "inf",
    "x" * 10_000, "1\x00", "5 \U0001f600", "5 parsecs of joy", "1 2 3", "--5", "5 m; import os",
    "5 __import__", "5 m**99999999",
])
def test_parse_quantity_refuses_without_evaluating(text):
    with pytest.raises(QuantityError):
        parse_quantity(text)


def test_a_strange_but_harmless_unit_is_read_as_what_it_is():
    reading = parse_quantity("5 m/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s")
    assert unit_info(reading.unit).kind.startswith("quantity of dimension")


@pytest.mark.parametrize("value, src, dst, expected", [
    (1.0, "kN", "N", 1000.0),
    (200.0, "rpm", "rad/s", 200 * 2 * math.pi / 60),
    (1.0, "Hz", "rad/s", 2 * math.pi),       # a frequency counts cycles: never 1 Hz = 1 rad/s
    (2 * math.pi, "rad/s", "Hz", 1.0),
    (60.0, "rpm", "Hz", 1.0),
    (math.pi, "rad", "deg", 180.0),
    (300.0, "MN/m^2", "MPa", 300.0),
    (1.0, "N*m", "J", 1.0),
    (5.0, "percent", "", 0.05),
    (1.0, "m/min", "m/s", 1 / 60),
    (289.8, "Nm", "N*m", 289.8),
    (289.8, "N-m", "N*m", 289.8),            # the hyphen some students (and US texts) write
    (1.5, "kN-m", "N*m", 1500.0),
    (250.0, "N-mm", "N*m", 0.25),
    (2.0, "kg-m^2", "kg*m^2", 2.0),          # a hyphen between any unit symbols multiplies
    (1.0, "lbf-ft", "N*m", 1.3558179483314),
])
def test_convert(value, src, dst, expected):
    assert convert(value, src, dst) == pytest.approx(expected)


@pytest.mark.parametrize("src, dst, message", [
    ("m", "N", "'m' is a length, but a force is asked (in N)"),
    ("kg", "kW", "'kg' is a mass, but a power is asked (in kW)"),
    ("deg", "percent", "'deg' is an angle, but a pure number is asked"),
])
def test_convert_refuses_the_wrong_kind(src, dst, message):
    with pytest.raises(DimensionError) as info:
        convert(1.0, src, dst)
    assert str(info.value).startswith(message)


def test_angular_speed_and_frequency_are_named():
    assert unit_info("rpm").kind == "angular speed"
    assert unit_info("Hz").kind == "frequency"
    assert unit_info("deg").kind == "angle"


@pytest.mark.parametrize("value, text", [
    (168.84152806470766, "168.8"), (5.235987755982988, "5.236"), (0.3220796, "0.3221"),
    (6145.94, "6146"), (12893.2, "12890"), (0, "0"), (-2.5, "-2.500"), (1.5e-6, "1.500e-6"), (3.2e8, "3.200e8"),
])
def test_format_number(value, text):
    assert format_number(value) == text


def test_display():
    assert pretty_unit("N*m") == "N\u00b7m" and pretty_unit("m/s^2") == "m/s\u00b2"
    assert format_quantity(168.84, "deg") == "168.8\u00b0"
    assert format_quantity(6.146, "kW") == "6.146 kW"


@pytest.mark.parametrize("text", ["5 km**99", "5 km^999999", "5 m^(12)"])
def test_absurd_unit_powers_are_refused(text):
    with pytest.raises(QuantityError):
        parse_quantity(text)


@pytest.mark.parametrize("text", ["1 m^9^9^9", "1 m**9**9**9", "1 m^(9^(9^9))", "1.2 x 10^999 N", "5\x07 N"])
def test_towers_overflows_and_control_characters_are_refused(text):
    with pytest.raises(QuantityError):
        parse_quantity(text)


@pytest.mark.parametrize("value, src, dst, expected", [
    (1.0, "lbf", "N", 4.4482216), (1.0, "kgf", "N", 9.80665), (1.0, "hp", "W", 745.69987),
])
def test_one_dimension_in_any_spelling(value, src, dst, expected):
    assert convert(value, src, dst) == pytest.approx(expected)
    assert unit_info(src).kind == unit_info(dst).kind


def test_the_stored_unit_table_is_what_pint_says_for_every_unit_the_bank_uses(bank):
    """Drawing reads units from data/unit_table.tsv instead of building pint's registry: each row must be
    pint's own answer, and every unit a template writes must be there (else: python -m exgen.check.unit_table)."""
    from exgen import units
    from exgen.check import unit_table

    stored = units._unit_table()
    assert all(units._ask_pint(name) == info for name, info in stored.items())
    assert all(units._spell_with_pint(name) == spelled for name, (_, spelled) in units._unit_table_rows().items())
    missing = unit_table.bank_units(bank) - set(stored) - {"", "1", "dimensionless"}
    assert not missing, f"units missing from {units.UNIT_TABLE}: {sorted(missing)}; run python -m exgen.check.unit_table"
