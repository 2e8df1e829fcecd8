"""Hostile answer text: nothing crashes, hangs or is evaluated; a format problem is told apart from wrong."""
import time

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exgen.answertypes.quantity import read_quantity
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from graders.results import BLANK, CARRIED, CORRECT, UNREADABLE, WRONG

MARKER = "/tmp/exgen-grader-was-evaluated"

HOSTILE = [
    f"__import__('os').system('touch {MARKER}')",
    f"eval(\"open('{MARKER}', 'w')\")",
    "1e999999", "-1e999999", "1e-999999", "9**9**9", "9^9^9^9", "10**10**10 N", "1 m**9**9**9", "1 m^(9^(9^9))",
    "1 kN^99999999999", "2 ** 1000000", "1.2 x 10^999 N", "1.2 × 10^-999 N",
    "1,500", "1,500,000 N", "−5.2 kN", "\u22125.2", "5.2 kN·m", "5.2 kN⋅m", "1.2 × 10^3 N", "1.2×10³ N",
    "θ = 168.8°", "θ=168.8 °", "168.8º", "x" * 10_000, "9" * 10_000, "1" + "0" * 400, "0." + "0" * 400 + "1",
    "5\x00", "\x00" * 50, "5 N\x00; rm -rf /", "\x1b[31m5\x1b[0m", "5\u200b", "\ufeff5", "5\u2028N",
    "\U0001f4a5", "5 \U0001f4a9", "💯 kW", "nan", "NaN kW", "inf", "-inf", "Infinity", "1/0", "0/0",
    "5 m/s/s/s/s/s/s/s/s/s/s/s/s/s/s/s", "5 " + "/s" * 39, "5 " + "(" * 40, "5 " + ")" * 40, "5 " + "m*" * 20,
    "{{ 7*7 }}", "${7*7}", "<script>alert(1)</script>", "'; DROP TABLE answers; --", "%s%s%s%n", "../../etc/passwd",
    "5 N; import os", "lambda: 0", "[1, 2]", "{'a': 1}", "True", "None", "0x10", "0o17", "0b101", "1_000",
    "1e3", "1.0e+3", "  5  ", "+5", "--5", "5-", ".5", "5.", "..5", "5..", "1 2 3", "1e", "e5", "∞", "½", "٥",
    "５ｋＮ", "5 newton", "5 kilonewtons", "5 N m s kg A K mol cd", "5 degC", "5 °C", "5 %%", "5 percent",
    "5 rad/s", "5 Hz", "5 rpm", "5 1/s", "5 s^-1", "5 m^-0.5", "5 m^(1/2)", "5 m**0.5", "5 [length]", "5 UnitRegistry",
    "5 _", "5 __class__", "5 m.__class__", "5 m;N", "5 m\nN", "5\r\n", "\t5\t",
]


@pytest.fixture(scope="module")
def variants(bank):
    return [make_variant(bank.get("belts.flat_belt_power"), 5), make_variant(bank.get("belts.v_belt_count"), 5),
            make_variant(bank.get("belts.driven_speed_slip"), 5)]


@pytest.mark.parametrize("text", HOSTILE)
def test_hostile_text_is_graded_without_crash_hang_or_evaluation(variants, text):
    start = time.perf_counter()
    for variant in variants:
        result = grade_variant(variant, {p.id: text for p in variant.template.parts})
        for part in result.parts:
            assert part.status in (CORRECT, CARRIED, WRONG, BLANK, UNREADABLE)
            assert part.points in (0, part.max_points)
            assert part.message
            if part.status == UNREADABLE:
                assert "format problem" in part.message
    assert time.perf_counter() - start < 2
    import os
    assert not os.path.exists(MARKER)


@pytest.mark.parametrize("text, value, unit", [
    ("−5.2 kN", -5.2, "kN"), ("1.2 × 10^3 N", 1200.0, "N"), ("θ = 168.8°", 168.8, "deg"), ("168.8°", 168.8, "deg"),
    ("5.2 kN·m", 5.2, "kN*m"), ("1e3", 1000.0, None), ("1.0e+3", 1000.0, None),
])
def test_friendly_spellings_are_read(text, value, unit):
    reading = read_quantity(text)
    assert reading.value == pytest.approx(value)
    assert (reading.unit is None) == (unit is None)


@pytest.mark.parametrize("text, reason", [
    ("1,500", "ambiguous"), ("9**9**9", "exponents"), ("1 m^9^9^9", "exponents"), ("1e999999", "finite"),
    ("x" * 10_000, "longer"), ("5\x00", "control"), ("nan", "cannot read"), ("💥", "cannot read"),
])
def test_unreadable_text_says_why(variants, text, reason):
    part = grade_variant(variants[0], {"b": text}).parts[1]
    assert part.status == UNREADABLE and reason in part.message and "format problem" in part.message


def test_a_long_unit_chain_is_a_wrong_kind_not_a_crash(variants):
    part = grade_variant(variants[0], {"b": "5 m/s/s/s/s"}).parts[1]
    assert part.status == WRONG and part.mistake == "wrong_kind"


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=90))
def test_any_text_at_all(variants, text):
    for variant in variants[:2]:
        result = grade_variant(variant, {p.id: text for p in variant.template.parts})
        assert all(p.status in (CORRECT, CARRIED, WRONG, BLANK, UNREADABLE) for p in result.parts)


@settings(max_examples=200, deadline=None)
@given(st.from_regex(r"[-+]?[0-9.]{1,8}([eE][-+]?[0-9]{1,3})? ?[a-zA-Z/*^()0-9 .°%-]{0,20}", fullmatch=True))
def test_number_like_text(variants, text):
    result = grade_variant(variants[0], {p.id: text for p in variants[0].template.parts})
    assert all(p.status in (CORRECT, CARRIED, WRONG, BLANK, UNREADABLE) for p in result.parts)
