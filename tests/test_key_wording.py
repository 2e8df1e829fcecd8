"""A key's working says each thing once: no line restates its own value, no note repeats its comparison."""
import pytest

from exgen.render.solution import solution
from exgen.solve.variant import make_variant

SEEDS = range(12)


def _all_ids(bank):
    return [t.id for t in bank]


def test_no_worked_line_substitutes_a_lone_signed_value(bank):
    """'φ₃ = −θ₃ = −14.56° = −14.56°': a formula that is one value with a sign is written once with its
    number ('φ₃ = −θ₃ = −14.56°'), as a formula that is one value alone already was; only a negative value
    keeps the step that shows its sign turned ('ΔF = −b = −(−3050) = 3050 N')."""
    found = []
    for template in bank:
        for seed in SEEDS:
            for line in solution(make_variant(template, seed)).lines:
                if line.substituted is None:
                    continue
                formula = line.substituted.formula
                if len(formula.slots) == 1 and formula.latex.replace(" ", "").lstrip("+-") == "@" + formula.slots[0].name:
                    number = line.substituted.fills[0]
                    if not (formula.latex.strip().startswith("-") and number.value < 0):
                        found.append((template.id, seed, line.name))
    assert not found, found[:5]


@pytest.mark.parametrize("seed", range(60))
def test_the_grashof_class_states_its_comparison_once(bank, seed):
    """'S + L > P + Q with BC grounded: S + L > P + Q: no link can make a full turn' said it twice."""
    variant = make_variant(bank.get("linkages.grashof"), seed)
    note = variant.step("kind").note
    assert note.count("P + Q") == 1, note


def test_g_is_written_as_its_symbol_in_every_formula(bank):
    """'m (9.81) L n / η²' wrote g's value into a formula; a formula names g, and g = 9.81 m/s² is a line."""
    found = []
    for template in bank:
        for seed in range(3):
            for step in make_variant(template, seed).steps:
                if "9.81" in (step.formula or ""):
                    found.append((template.id, step.name, step.formula))
    assert not found, found


@pytest.mark.parametrize("template_id", ["balancing.inline_engine_unbalance", "balancing.inline_engine_firing"])
def test_a_resultant_that_vanishes_is_given_no_direction(bank, template_id):
    """'F_p = 0 N' followed by 'θ_Fp = 180°: opposite the resultant': a zero force has no direction to balance."""
    for seed in range(40):
        variant = make_variant(bank.get(template_id), seed)
        names = {step.name for step in variant.steps}
        for tag in ("Fp", "Cp", "Fs", "Cs"):
            if variant.step(tag).value == 0:
                assert f"theta_{tag}" not in names, (seed, tag)
            elif template_id == "balancing.inline_engine_unbalance":
                assert f"theta_{tag}" in names, (seed, tag)


def test_a_direction_on_an_axis_names_no_quadrant(bank):
    """'θ = 0°: opposite the resultant, in the quadrant +x, −y': an angle of 0° or 180° is in no quadrant."""
    import math

    found = []
    for template in bank:
        if not template.id.startswith("balancing."):
            continue
        for seed in range(40):
            for step in make_variant(template, seed).steps:
                if "in the quadrant" in step.note and isinstance(step.value, float):
                    quarter = math.degrees(step.value) / 90
                    if abs(quarter - round(quarter)) < 1e-9:
                        found.append((template.id, seed, step.name, step.note))
    assert not found, found[:3]


def test_the_formula_question_s_figure_says_what_it_shows(bank):
    """The caption read 'The system: two springs', a catalogue entry; it names the rod or pulley drawn."""
    from exgen.figures.formula_systems import formula_system

    captions = {}
    for seed in range(40):
        variant = make_variant(bank.get("vibration.natural_frequency_formula"), seed)
        svg = formula_system(variant)
        captions[variant.param("system").text] = svg
    assert len(captions) == 5
    for system, svg in captions.items():
        assert "The system:" not in svg, system
        assert ("rod" if system in ("lever", "two springs") else "pulley") in svg, system


def test_a_period_taken_as_one_over_omega_is_named_as_that(bank):
    """A periodic time worked as 1/ω was told 'That is the circular frequency ω in rad/s': the answer is in
    seconds, and the slip is the 2π of a cycle left out of T = 2π/ω."""
    from exgen.load.mistake_messages import default_messages

    for template in bank:
        for part in template.parts:
            for spec in part.mistakes:
                if spec.when == "omega_for_f" and part.unit == "s":
                    message = spec.say or default_messages()[spec.when]
                    assert "1/ω" in message and "circular frequency" not in message, (template.id, part.id, message)


def test_feedback_on_a_percentage_change_speaks_of_the_change(bank):
    """The idler's change in power per belt, worked upside down, was told about pulleys' speeds
    ('For pulleys N₂/N₁ = d₁/d₂'): a percentage part names the ratio it is about."""
    from exgen.load.mistake_messages import default_messages

    for template in bank:
        for part in template.parts:
            if part.unit != "percent":
                continue
            for spec in part.mistakes:
                message = spec.say or default_messages()[spec.when]
                assert "pulleys N₂/N₁" not in message, (template.id, part.id, spec.when)


def test_a_statement_points_to_its_figure_in_words(bank):
    """'... falls back to 14 N·m at 1.35 s (the figure).' reads as a stray note; a sheet says what the figure does."""
    found = [(t.id, seed) for t in bank for seed in range(5)
             if "(the figure)" in make_variant(t, seed).statement]
    assert not found, found[:5]


def test_a_bearing_reaction_is_worked_before_its_row_in_the_force_table(bank):
    """The force table's row for Y (R_Y = 0.1275 kg·m at 162.3°) appeared with no line working it out
    from the moment polygon: R_Y = l_Y R_Y / l_Y and its closing angle are lines of the working."""
    for seed in range(30):
        variant = make_variant(bank.get("balancing.bearing_reactions"), seed)
        shown = [line.name for line in solution(variant).lines]
        assert "RY" in shown and "theta_RY" in shown, seed
        assert shown.index("theta_RY") < shown.index("RX"), seed


def test_a_balancing_direction_in_the_working_is_within_one_turn(bank):
    """'θ_FX = 198.9° + 180° = 378.9°' with 18.88° in the answers: a direction is written within 0-360°,
    the turn it drops written in the line ('+ 180° − 360°'). Crank angles of a firing order stay as the text
    counts them (480°, 600°: Example 2.7)."""
    import math

    found = []
    for template in bank:
        if template.chapter != 2:
            continue
        for seed in range(40):
            for step in make_variant(template, seed).steps:
                if step.name.startswith("theta_") and step.unit == "rad" and isinstance(step.value, float):
                    if not 0 <= step.value < 2 * math.pi:
                        found.append((template.id, seed, step.name, round(math.degrees(step.value), 2)))
    assert not found, found[:5]


def test_a_table_hides_no_line_whose_working_it_lacks(bank):
    """A table that lists a step's value spares the step its own line only where the table shows how it is
    made (m·r beside m and r): a car wheel's share of the weight, W(b − a)/2b, appeared only as a number in
    the reactions table, worked nowhere."""
    from exgen.solve.derivation import Table

    needs_its_line = {"gyroscopes.car_wheel_reactions": ("W_f", "W_r"),
                      "balancing.bearing_reactions": ("RY", "theta_RY")}
    for template_id, names in needs_its_line.items():
        for seed in range(10):
            variant = make_variant(bank.get(template_id), seed)
            assert any(isinstance(i, Table) and set(names) & i.names for i in variant.inserts)
            shown = {line.name for line in solution(variant).lines}
            assert set(names) <= shown, (template_id, seed)


def test_a_rim_note_names_the_rim_s_own_material(bank):
    """A cast-steel rim's key said 'a cast-iron rim is kept below about 35 m/s'."""
    template = bank.get("flywheels.flywheel_rim")
    said = {}
    for seed in range(60):
        variant = make_variant(template, seed)
        note = next(line.note for line in solution(variant).lines if line.name == "v")
        said.setdefault(variant.param("rho").si >= 7500, set()).add("cast-steel rim" in note)
    assert said == {True: {True}, False: {False}}


def test_a_rotor_s_spin_is_worked_with_its_speed_in_rpm(bank):
    """Every gyroscope key wrote 'ω = 2πN/60 = 288 rad/s' with no numbers: now '2π × 2750/60'."""
    from exgen.render.targets import PLAIN

    checked = 0
    for template in (t for t in bank if t.id.startswith("gyroscopes.")):
        for seed in range(3):
            variant = make_variant(template, seed)
            for line in solution(variant).lines:
                if line.name == "omega" and line.formula and "{60}" in line.formula.formula.latex:
                    rpm = next(p for p in variant.params if p.unit == "rpm")
                    assert f"2π × {rpm.text}" in " = ".join(line.chain(PLAIN)), (template.id, seed)
                    checked += 1
    assert checked >= 12
