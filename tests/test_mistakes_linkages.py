"""Chapter 7 names the slips its topics are known for: the other circuit or branch, γ for θ4, radians for
degrees, the wrong pair in Grashof's sum, the ground or a shared pin miscounted (that every named mistake
is recognised with its own words is tests/test_named_mistakes.py's, for every template)."""

TEMPLATES = ("linkages.mobility", "linkages.grashof", "linkages.fourbar_position", "linkages.coupler_point",
             "linkages.slider_crank", "linkages.rocker_swing", "linkages.actuator_swing",
             "linkages.two_position_synthesis")


def test_chapter_7_names_its_known_slips(bank):
    names = {m.when for t in TEMPLATES for p in bank.get(t).parts for m in p.mistakes}
    assert {"wrong_circuit", "gamma_for_theta4", "theta4_for_gamma", "degrees_as_radians", "radians_for_degrees",
            "wrong_pair", "ground_not_counted", "shared_joint_counted_once"} <= names
