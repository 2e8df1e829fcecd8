"""What the feedback, the hints, the key's notes and the figures' captions say of a draw is true of the sheet
they are shown beside.

Every text of every template is written for many seeds: the feedback of each mistake a variant records,
as a student typing its value (or a wrong choice) receives it; each hint; each note of the worked solution;
each figure's caption, the alt text of the exports. Two rules hold in each:
- a text of the template file (a `say:`, a hint, a default text) names no value the draw decides in words
  it prints whatever the draw (exgen.check.draw_words.misstatements, which `exgen validate` runs too);
- in any text, a word for a value of a word choice (clockwise, left, port, the bow) or for an option of a
  choice part that this draw did not decide is written from the variant: it changes when that choice
  is drawn the other way. A fixed "a left turn is anticlockwise, so Ω points up" beside a right turn
  fails; "a turn to the right is clockwise seen from above" written from the turn passes, whatever
  sense the rotor has.
"""
import difflib
import os

import pytest

from exgen.answertypes import answer_type
from exgen.check.draw_words import described, disagreeing, draw_words, misstatements, spans, tokens
from exgen.errors import ExgenError
from exgen.figures import Drawn, figure_svg, key_figure_svgs
from exgen.load.bank import load_bank
from exgen.solve.variant import build_variant, make_variant
from graders.grade import grade_variant

SEEDS = range(int(os.environ.get("EXGEN_TEXT_SEEDS", "50")))


def word_params(template):
    return [p for p in template.params if p.given and len(p.choices) > 1 and all(isinstance(c, str) for c in p.choices)]


def texts(variant, graded: bool = True) -> dict[tuple, str]:
    """Every text a student or an instructor reads beside the variant, by where it stands."""
    out = {}
    for step in variant.steps:
        if step.note:
            out.setdefault(("note", step.name), step.note)
    svg = figure_svg(variant)
    if svg:
        out[("caption", "sheet")] = Drawn("", svg).title
    for name, key_svg in key_figure_svgs(variant):
        out[("caption", name)] = Drawn("", key_svg).title
    for part in variant.template.parts:
        for i, hint in enumerate(part.hints, 1):
            out[("hint", part.id, i)] = variant.fill(hint)
        for name in variant.mistakes[part.id]:
            out[("feedback", part.id, name)] = variant.mistake_message(part.id, name)
        if graded:
            out.update(_graded(variant, part))
    return out


def _graded(variant, part) -> dict[tuple, str]:
    """The message a student receives for each wrong answer a template's mistake names: each value the
    variant records typed back, and each wrong choice. What the grader says is the mistake's text written
    with this variant (the grader's own sentences for an answer nothing names are exgen's, the same for
    every template)."""
    kind, answer = answer_type(part), variant.answers[part.id]
    tried = [kind.text(value, part) for value in variant.mistakes[part.id].values()]
    if part.type == "choice":
        tried += [c for c in part.options["choices"] if c != answer.value]
    out = {}
    for typed in tried:
        result = next(r for r in grade_variant(variant, {part.id: typed}).parts if r.part_id == part.id)
        if result.status == "wrong" and result.mistake in variant.mistakes[part.id]:
            assert result.message.startswith(variant.mistake_message(part.id, result.mistake).rstrip(".")), typed
            out[("feedback", part.id, result.mistake)] = result.message
    return out


def flipped(variant):
    """The variant with each word choice drawn each other way in turn (the rest of its data kept), where
    the solver works with it."""
    printed = {p.name: p.exact for p in variant.params}
    for spec in word_params(variant.template):
        for other in dict.fromkeys(spec.choices):
            if other == printed[spec.name]:
                continue
            try:
                yield build_variant(variant.template, {**printed, spec.name: other}, seed=variant.seed, check=False)
            except ExgenError:
                continue


def unmoved_misstatements(variant) -> list[str]:
    """Runs of the draw's words that disagree with the variant and stay where they are when any word choice
    is drawn otherwise: fixed words stating what this draw did not decide. Options of choice parts are
    the feedback's business (misstatements); the key's notes and the captions name the vehicle's parts
    ("the front left wheel") in the words the options use."""
    words = tuple(w for w in draw_words(variant.template) if w.param)
    if not words:
        return []
    own = texts(variant)
    others = [texts(v, graded=False) for v in flipped(variant)]
    problems = []
    for key, text in own.items():
        mine = tokens(text)
        found = spans(mine, words)
        if not found:
            continue
        moved = [False] * len(mine)
        for other in others:
            if key not in other:
                continue
            ops = difflib.SequenceMatcher(None, mine, tokens(other[key]), autojunk=False).get_opcodes()
            for op, i1, i2, _, _ in ops:
                if op != "equal":
                    moved[max(i1 - (i1 == i2), 0):max(i2, i1 + 1)] = [True] * (max(i2, i1 + 1) - max(i1 - (i1 == i2), 0))
        wrong = disagreeing([owners for start, end, owners in found if not any(moved[start:end])], variant)
        if wrong:
            problems.append(f"{' '.join(map(str, key))}: says {described(wrong, variant)}: {text!r}")
    return problems


@pytest.mark.parametrize("template_id", sorted(load_bank().templates))
def test_every_text_agrees_with_the_variant_it_is_shown_with(bank, template_id):
    template = bank.get(template_id)
    problems: dict[str, int] = {}
    for seed in SEEDS:
        variant = make_variant(template, seed)
        for problem in misstatements(variant) + unmoved_misstatements(variant):
            problems.setdefault(problem, seed)
    assert not problems, "\n".join(f"seed {seed}: {p}" for p, seed in list(problems.items())[:12])


# ---- the check itself, on the sentence that was fixed for every draw --------------------------------------

FIXED = ("That is the opposite effect. Clockwise seen from the stern, the spin vector points to the bow; a left "
         "turn is anticlockwise seen from above, so Ω points up. The reactive couple on the ship is ω × Ω.")


def with_say(template, part_id, name, say):
    import dataclasses

    from exgen.load.template import MistakeSpec

    parts = tuple(dataclasses.replace(p, mistakes=tuple(MistakeSpec(m.when, say if m.when == name else m.say)
                                                           for m in p.mistakes)) if p.id == part_id else p
                  for p in template.parts)
    return dataclasses.replace(template, parts=parts)


def test_a_fixed_sentence_naming_the_drawn_sense_and_turn_is_a_problem_for_validate(bank):
    from exgen.check.validate import validate_template

    template = with_say(bank.get("gyroscopes.rotor_bearing_reactions"), "b", "precession_reversed", FIXED)
    other = next(v for v in (make_variant(template, s) for s in range(40))
                 if v.param("sense").text == "counter-clockwise" and v.param("turn").text == "right")
    problems = " ".join(misstatements(other))
    assert "'clockwise' (a value of sense, counter-clockwise here)" in problems
    assert "'left' (a value of turn, right here)" in problems
    report = validate_template(template, seeds=12)
    assert any("precession_reversed" in p and "whatever the draw" in p for p in report.problems)


def test_the_feedback_on_a_counter_clockwise_rotor_turning_right_says_so(bank):
    """The finding: a student whose sheet says counter-clockwise and a right turn was told the opposite."""
    template = bank.get("gyroscopes.rotor_bearing_reactions")
    for seed in range(40):
        variant = make_variant(template, seed)
        wrong = variant.mistakes["b"]["precession_reversed"]
        message = next(r for r in grade_variant(variant, {"b": wrong}).parts if r.part_id == "b").message
        sense, turn = variant.param("sense").text, variant.param("turn").text
        assert message.startswith(f"That is the opposite effect. {sense.capitalize()} seen from the stern")
        assert f"a turn to the {turn} is {'anticlockwise' if turn == 'left' else 'clockwise'} seen from above" in message
        assert f"Ω points {variant.step('precession_vector').value}" in message
        assert "Clockwise" not in message or sense == "clockwise"


def test_a_text_naming_a_step_the_solver_does_not_record_in_words_cannot_be_written(bank):
    template = with_say(bank.get("gyroscopes.rotor_bearing_reactions"), "b", "precession_reversed",
                        "The couple points {{ steps.C }}.")  # C is a number, not words
    assert any("cannot be written" in p for p in misstatements(make_variant(template, 0)))


def test_a_rule_naming_two_cases_of_a_choice_is_not_a_fact_of_the_draw(bank):
    """"The shortest link grounded gives a double-crank, beside the ground a crank-rocker, opposite it a
    double-rocker" tells the classes apart: it passes beside any of them."""
    template = bank.get("linkages.grashof")
    shown = [v for v in (make_variant(template, s) for s in range(40)) if "ground_ignored" in v.mistakes["c"]]
    assert {v.answers["c"].value for v in shown} >= {"crank-rocker", "double-crank"}
    assert not [p for v in shown for p in misstatements(v)]
