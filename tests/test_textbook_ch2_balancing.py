"""Chapter 2 balancing templates against the course text's worked examples.

Angles: each sheet states its convention; the text measures Example 2.1's angles from mass 1
towards mass 2 (counter-clockwise here), and the answer is compared modulo 360 degrees.
"""
import pytest

from exgen.solve import solve


def answers(bank, template_id, **given):
    variant, warnings = solve(bank.get(template_id), {k: str(v) for k, v in given.items()})
    return {part: answer.value for part, answer in variant.answers.items()}, warnings


def test_example_2_1_static_balance(bank):
    # Example 2.1: 3 kg at 1 mm (0 deg) and 2 kg at 2 mm (90 deg); Bb = 5 kg mm at 233.13 deg.
    # The template has a third mass; with m3 = 0 it is the example exactly.
    got, _ = answers(bank, "balancing.static_balance", m1="3 kg", r1="1 mm", m2="2 kg", r2="2 mm", theta2="90 deg",
                     m3="0 kg", r3="1 mm", theta3="180 deg", b="1 mm")
    assert got["a"].magnitude == pytest.approx(5.0)
    assert got["a"].angle_deg == pytest.approx(270 - 36.8699, abs=1e-4)  # printed: 233.13 deg
    assert got["b"] == pytest.approx(5.0)  # "Assuming B = 5 kg; then b = 1 mm"
