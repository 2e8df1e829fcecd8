"""What the chapter 3-4 sheets and keys say, read as a student and a lecturer would: the reasons a key
gives match its numbers, the wording reads for every draw, the machines drawn could be built."""
import math

from textbook_helpers import answers


def _note(variant, step):
    return next(s.note for s in variant.steps if s.name == step)


def test_the_stability_reason_follows_the_sign_of_the_intercept(bank):
    # Problem 4.6's line cuts the force axis below the origin: stable.
    _, stable, _ = answers(bank, "governors.spring_controlled", m="30 kg", r1="190 mm", F1="4250 N",
                           r2="300 mm", F2="7500 N", N="250 rpm")
    assert stable.answers["a"].value == "stable"
    assert _note(stable, "kind").startswith("b < 0") and "below the origin" in _note(stable, "kind")
    # The sheet drawn as Question 18 of a review: b = +737.5 N, above the origin: unstable.
    _, unstable, _ = answers(bank, "governors.spring_controlled", m="18 kg", r1="150 mm", F1="2500 N",
                             r2="350 mm", F2="4850 N", N="300 rpm")
    assert unstable.answers["a"].value == "unstable"
    assert _note(unstable, "kind").startswith("b > 0") and "above the origin" in _note(unstable, "kind")
    assert "falls" in _note(unstable, "kind")


def test_the_wrong_way_for_the_spring_load_is_explained(bank):
    from graders.grade import grade_variant

    _, variant, _ = answers(bank, "governors.spring_controlled", m="30 kg", r1="190 mm", F1="4250 N",
                            r2="300 mm", F2="7500 N", N="250 rpm")
    given = {part: a.text for part, a in variant.answers.items()} | {"d": "decrease"}
    result = next(p for p in grade_variant(variant, given).parts if p.part_id == "d")
    assert result.status == "wrong" and "through the origin" in result.message and "rises by |b|" in result.message


def test_a_flywheel_rim_is_thin_beside_its_radius(bank):
    """I = m R² takes the rim's mass at its mean radius: a section as thick as the radius is a disc, not a rim
    (Problem 3.1's is 67 mm thick on a 325 mm radius)."""
    from exgen.solve.variant import make_variant

    template = bank.get("flywheels.flywheel_rim")
    for seed in range(120):
        variant = make_variant(template, seed)
        radius_mm = variant.param("D").si * 1000 / 2
        assert variant.answers["c"].value <= 0.35 * radius_mm, seed


def _number(text: str) -> float:
    return float(text.split()[0].replace("\u2212", "-"))


#: Parts worked as a difference of two earlier answers: (template, part, the part from the earlier answers as printed).
DIFFERENCES = [
    ("governors.porter_dead_load", "d", lambda v, a: v.param("N").si / (a["b"] - a["c"])),
    ("governors.porter_friction", "d", lambda v, a: a["b"] - a["c"]),
    ("governors.porter_speed_range", "c", lambda v, a: a["b"] - a["a"]),
]


def test_a_difference_worked_from_answers_kept_to_four_figures_is_right(bank):
    """The sheet asks for four significant figures; a student who works a sensitivity or a range of speed from
    the speeds as they wrote them down (as the text's Example 4.1 does) has worked it right."""
    from exgen.solve.variant import make_variant
    from graders.grade import grade_variant

    for template_id, part, worked in DIFFERENCES:
        template = bank.get(template_id)
        for seed in range(250):
            variant = make_variant(template, seed)
            given = {p: a.text for p, a in variant.answers.items()}
            numbers = {p: _number(t) for p, t in given.items() if variant.template.part(p).type == "number"}
            given[part] = f"{worked(variant, numbers):.6g}"
            result = next(r for r in grade_variant(variant, given).parts if r.part_id == part)
            assert result.status == "correct", (template_id, seed, given[part], variant.answers[part].text)


def test_statements_read_right_for_every_draw(bank):
    from exgen.solve.variant import make_variant

    for seed in range(60):
        engine = make_variant(bank.get("flywheels.energy_coefficient"), seed).statement
        assert "every one revolution" not in engine
        machine = make_variant(bank.get("flywheels.torque_time"), seed)
        base = machine.param("T").si - (machine.param("t4").si - machine.param("t1").si)
        if base < 0.5 * machine.param("T").si:   # the pulse takes most of the cycle
            assert "most of its cycle" not in machine.statement
        if machine.param("dwell").text == "0":   # the torque falls as soon as it peaks
            assert "stays at" not in machine.statement and "then at once falls" in machine.statement


def test_unequal_offsets_are_explained_whichever_pivots_are_farther_out(bank):
    """Upper pivots 30 mm out and lower 20 mm: the lower arms lean more than the upper, not less."""
    from graders.grade import grade_variant

    _, variant, _ = answers(bank, "governors.porter_speed_range", l="280 mm", e_u="30 mm", e_l="20 mm", m="2 kg",
                            M="20 kg", r1="100 mm", r2="145 mm")
    slip = variant.mistakes["a"]["offset_ignored"]
    given = {part: a.text for part, a in variant.answers.items()} | {"a": f"{slip:.5g} rpm"}
    result = next(p for p in grade_variant(variant, given).parts if p.part_id == "a")
    assert result.mistake == "offset_ignored" and "lean less" not in result.message
    assert "different distances from the axis" in result.message


def test_a_proell_key_writes_the_upright_extension_plainly(bank):
    """At the lowest position the extension is upright: XZ = l cos β₁ + e and the ball turns at r₁, not
    e cos(β₁ − β₁) and r₁ + e sin(β₁ − β₁)."""
    _, variant, _ = answers(bank, "governors.proell_speeds", l="300 mm", e_u="0 mm", e_l="40 mm", e="100 mm",
                            m="5 kg", M="40 kg", r1="170 mm", r2="215 mm")
    formulas = " ".join(s.formula for s in variant.steps)
    assert r"@beta_1 - @beta_1" not in formulas
    assert variant.step("XZ_1").formula == r"@l\cos @beta_1 + @e"
    assert variant.step("x_1").formula == "@r1"


def test_the_crossings_of_greatest_and_least_speed_read_as_a_sentence(bank):
    from exgen.render.unicode_math import latex_to_unicode

    _, variant, _ = answers(bank, "flywheels.speed_fluctuation", a1="295 mm^2", a2="685 mm^2", a3="40 mm^2",
                            a4="340 mm^2", a5="960 mm^2", first="above", Ts="5 N*m", As="1 deg", N="1800 rpm",
                            m="36 kg", k="150 mm")
    lines = [f"{latex_to_unicode(variant.step(n).symbol)} = {variant.step(n).value}" for n in ("fastest", "slowest")]
    assert lines == ["crossing of ωₘₐₓ = B", "crossing of ωₘᵢₙ = E"]   # Example 3.1: B and E


def test_the_proell_figure_names_the_points_the_statement_names(bank):
    """The statement speaks of the extension AB, the cranked lever ABC and the upper arm BD: the figure marks them."""
    from exgen.figures import figure_svg
    from exgen.solve.variant import make_variant
    from svg_helpers import texts

    for seed in range(5):
        variant = make_variant(bank.get("governors.proell_extension"), seed)
        assert all(word in variant.statement for word in ("AB", "ABC", "BD"))
        assert {"A", "B", "C", "D"} <= set(texts(figure_svg(variant)))


def test_a_negative_acceleration_is_said_to_slow_the_flywheel(bank):
    _, variant, _ = answers(bank, "flywheels.turning_moment_equation", T0="12500 N*m", b="2500 N*m", c="1900 N*m",
                            n=4, N="110 rpm", band="0.5 %", theta="135 deg")
    assert variant.answers["c"].value < 0 and "slowing" in _note(variant, "alpha")
    _, variant, _ = answers(bank, "flywheels.turning_moment_equation", T0="14500 N*m", b="2300 N*m", c="-1900 N*m",
                            n=2, N="150 rpm", band="0.5 %", theta="30 deg")    # Problem 3.2
    assert variant.answers["c"].value > 0 and "speeding up" in _note(variant, "alpha")


def test_the_change_of_spring_load_is_asked_as_a_size(bank):
    """Part (d) asks which way: part (c) asks the size, so that a signed −737.5 N is a sign slip, said as one."""
    from exgen.solve.variant import make_variant

    assert "size" in make_variant(bank.get("governors.spring_controlled"), 0).asks["c"]


def test_a_second_hartnell_spring_is_a_spring(bank):
    """Example 4.3's spring 2 is 1158 kN/m, stiff because the sleeve's first few millimetres stretch it; the
    drawn ones stay within about three times that, not a solid bar of 16 MN/m."""
    from exgen.solve.variant import make_variant

    template = bank.get("governors.hartnell_two_springs")
    for seed in range(150):
        variant = make_variant(template, seed)
        assert 100 <= variant.answers["b"].value <= 3000, seed          # kN/m
        assert variant.answers["a"].value <= 5000, seed                  # N
