"""Balancing answers that are wrong in a known way are named: each template's own mistakes (a lost
distance sign, rpm for rad/s, the secondary angle not doubled, ...) and the generic angle slips
(measured the other way round, from the wrong axis, half a turn out)."""
import pytest

from exgen.answertypes import answer_type
from exgen.answertypes.polar import Polar
from exgen.load.bank import load_bank
from exgen.solve.variant import make_variant
from graders.grade import grade_variant

TEMPLATES = ("balancing.static_balance", "balancing.two_plane_balance", "balancing.complete_balance_position",
             "balancing.complete_balance_masses", "balancing.bearing_reactions", "balancing.inline_engine_unbalance",
             "balancing.inline_engine_firing", "balancing.inline_primary_balance", "balancing.radial_engine",
             "balancing.v_engine")


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


def _close(a, b, part):
    return answer_type(part).matches(a, b, part)


POLAR_PARTS = [(t, p.id) for t in TEMPLATES for p in load_bank().get(t).parts if p.type == "polar"]


@pytest.mark.parametrize("template_id, part_id", POLAR_PARTS)
@pytest.mark.parametrize("slip, expected", [("mirrored", "mirrored_angle"), ("from_other_axis", "wrong_axis"),
                                            ("quarter_turn", "wrong_axis"), ("magnitude_only", "magnitude_wrong")])
def test_generic_slips_of_a_polar_answer_are_named(bank, template_id, part_id, slip, expected):
    template = bank.get(template_id)
    part = template.part(part_id)
    for seed in range(40):
        variant = make_variant(template, seed)
        right = variant.answers[part_id].value
        slips = {"mirrored": -right.angle_deg, "from_other_axis": 90 - right.angle_deg,
                 "quarter_turn": right.angle_deg + 90, "magnitude_only": right.angle_deg}
        size = right.magnitude * (1.2 if slip == "magnitude_only" else 1.0)
        given = Polar.of(size, slips[slip])
        recorded = variant.mistakes[part_id].values()
        # at 45° the mirror image is also a quarter turn: such a draw cannot tell the two slips apart
        others = [Polar.of(right.magnitude, a) for name, a in slips.items() if name not in (slip, "magnitude_only")]
        degenerate = _close(given, right, part) or any(_close(given, m, part) for m in [*recorded, *others])
        if not degenerate:
            break
    else:
        pytest.skip("every drawn variant makes this slip coincide with a named mistake")
    result = grade(variant, part_id, given.text(part.unit))
    assert result.status == "wrong" and result.mistake == expected, (seed, result.message)


@pytest.mark.parametrize("template_id, part_id", [("balancing.complete_balance_position", "b"),
                                                  ("balancing.complete_balance_position", "c"),
                                                  ("balancing.complete_balance_masses", "a")])
@pytest.mark.parametrize("shift, expected", [(lambda a: -a, "mirrored_angle"), (lambda a: 90 - a, "wrong_axis")])
def test_generic_slips_of_an_angle_answer_are_named(bank, template_id, part_id, shift, expected):
    template = bank.get(template_id)
    variant = next(v for v in (make_variant(template, s) for s in range(40))
                   if all(abs((shift(v.answers[part_id].value) - m) % 360) > 2 and
                          abs((shift(v.answers[part_id].value) - m) % 360) < 358
                          for m in v.mistakes[part_id].values()))
    result = grade(variant, part_id, f"{shift(variant.answers[part_id].value):.2f} deg")
    assert result.status == "wrong" and result.mistake == expected


def test_rpm_for_rad_s_in_a_bearing_force_is_named(bank):
    variant = make_variant(bank.get("balancing.bearing_reactions"), 3)
    right = variant.answers["a"].value
    rpm = variant.param("N").si * 60 / (2 * 3.141592653589793)
    wrong = Polar.of(right.magnitude * (rpm / variant.param("N").si) ** 2, right.angle_deg)
    result = grade(variant, "a", wrong.text("N"))
    assert result.mistake == "rpm_as_rad_s" and "2πN/60" in result.message


def test_half_a_turn_out_on_a_bearing_is_the_balancing_direction(bank):
    variant = make_variant(bank.get("balancing.bearing_reactions"), 3)
    right = variant.answers["b"].value
    result = grade(variant, "b", Polar.of(right.magnitude, right.angle_deg + 180).text("N"))
    assert result.mistake == "balance_direction" and "opposite" in result.message


@pytest.fixture(scope="module")
def flat_four(bank):
    from exgen.check.given import solve

    variant, _ = solve(bank.get("balancing.inline_engine_firing"),
                       {"firing": "1-3-4-2", "strokes": "4", "m": "1 kg", "r": "60 mm", "l": "240 mm",
                        "a": "100 mm", "N": "2000 rpm"})
    return variant


def test_a_balanced_engine_called_balanced_when_only_the_primary_is(flat_four):
    assert flat_four.answers["d"].value == "not balanced"  # four-stroke flat four: secondary forces remain
    result = grade(flat_four, "d", "balanced")
    assert result.mistake == "secondary_ignored"
    assert grade(flat_four, "d", "Not balanced").status == "correct"


def test_a_shared_alias_of_a_choice_is_accepted(flat_four):
    assert grade(flat_four, "d", "unbalanced").status == "correct"


def test_a_wrong_angle_of_d_carries_forward_to_b(bank):
    import math

    from exgen.solve.variant import answer_for, rerun

    variant = make_variant(bank.get("balancing.complete_balance_position"), 5)
    wrong = (variant.answers["b"].value + 25) % 360
    again = rerun(variant, {"theta_D": math.radians(wrong)})
    theta_b, mass_b = (answer_for(variant.template.part(k), again).value for k in "cd")
    result = grade_variant(variant, {"b": f"{wrong} deg", "c": f"{theta_b:.3f} deg", "d": f"{mass_b:.4f} kg"})
    assert [r.status for r in result.parts] == ["blank", "wrong", "carried", "carried"]


def test_a_crank_angle_misread_off_the_end_view_is_named_and_carried_into_the_polygons(bank):
    import math

    from exgen.solve.variant import answer_for, rerun

    variant = make_variant(bank.get("balancing.inline_engine_angles_read"), 3)
    theta3 = variant.answers["b"].value
    against = grade(variant, "b", f"{360 - theta3:g} deg")
    assert against.status == "wrong" and against.mistake == "against_rotation"
    misread = (theta3 + 10) % 360                         # a division out: wrong, but the polygons follow it
    again = rerun(variant, {"read3": math.radians(misread)})
    polygons = {k: answer_for(variant.template.part(k), again).value for k in "defg"}
    units = {"d": "N", "e": "N m", "f": "N", "g": "N m"}
    result = grade_variant(variant, {"b": f"{misread:g} deg",
                                     **{k: f"{polar.magnitude:.6g} {units[k]} at {polar.angle_deg:.4f} deg"
                                        for k, polar in polygons.items()}})
    assert [r.status for r in result.parts] == ["blank", "wrong", "blank", "carried", "carried", "carried", "carried"]
