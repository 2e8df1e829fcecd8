"""Every template's answers that are wrong in a known way are named in feedback with the template's words
(or the shared default for the slip): whatever a variant records as a mistake's value, typed as a student
would type it, is marked wrong and named, and every mistake a template lists is met over the seeds drawn."""
import pytest

from exgen.answertypes import answer_type
from exgen.load.bank import load_bank
from exgen.load.mistake_messages import default_messages
from exgen.solve.variant import make_variant
from graders.grade import grade_variant

SEEDS = range(30)


def typed(value, part) -> str:
    """What a student would type for a recorded value: the answer type's text, as the key prints answers."""
    return answer_type(part).text(value, part)


def grade(variant, part_id, text):
    return next(r for r in grade_variant(variant, {part_id: text}).parts if r.part_id == part_id)


@pytest.mark.parametrize("template_id", sorted(load_bank().templates))
def test_every_named_mistake_is_recognised_with_its_own_words(bank, template_id):
    template = bank.get(template_id)
    seen = set()
    for seed in SEEDS:
        variant = make_variant(template, seed)
        for part in template.parts:
            recorded, same_value = variant.mistakes[part.id], answer_type(part).matches
            for spec in part.mistakes:
                if spec.when not in recorded:
                    continue
                result = grade(variant, part.id, typed(recorded[spec.when], part))
                assert result.status == "wrong", (seed, part.id, spec.when, recorded[spec.when])
                # another listed mistake may give the same value: the first listed of them is named
                same = [m.when for m in part.mistakes if m.when in recorded
                        and same_value(recorded[m.when], recorded[spec.when], part)]
                assert result.mistake in same, (seed, part.id, spec.when, result.mistake)
                if result.mistake == spec.when:
                    assert result.message == variant.mistake_message(part.id, spec.when), (seed, part.id)
                seen.add((part.id, spec.when))
    named = {(p.id, m.when) for p in template.parts for m in p.mistakes}
    assert named <= seen, f"listed but never met over {len(SEEDS)} seeds: {sorted(named - seen)}"


def test_every_mistake_named_has_words(bank):
    """No part falls back on the general "a known slip" line."""
    missing = {(t.id, p.id, m.when) for t in bank for p in t.parts for m in p.mistakes
               if not m.say and m.when not in default_messages()}
    assert not missing


def test_of_two_slips_close_together_the_one_typed_is_named(bank):
    """A rail car's speed with the gyroscopic couple left out and with it subtracted can lie 0.5 % apart,
    both within the tolerance of either: an answer names the slip it is nearer."""
    template = bank.get("gyroscopes.rail_car_limiting_speed")
    part = template.part("a")
    kind = answer_type(part)
    pair = ("gyro_ignored", "gyro_subtracted_where_it_adds")
    close = [v for v in (make_variant(template, s) for s in range(200)) if set(pair) <= set(v.mistakes["a"])
             and kind.matches(v.mistakes["a"][pair[0]], v.mistakes["a"][pair[1]], part)]
    assert close
    for variant in close:
        recorded = variant.mistakes["a"]
        for name in pair:
            text = typed(recorded[name], part)
            read = kind.read(text, part).value  # to four figures: the nearer of the two is meant
            listed = [m.when for m in part.mistakes]  # equal values name the first listed
            nearer = min(pair, key=lambda n: (abs(recorded[n] - read), listed.index(n)))
            assert grade(variant, "a", text).mistake == nearer


@pytest.mark.parametrize("template_id", sorted(load_bank().templates))
def test_every_mistake_a_solver_records_for_a_part_has_words(bank, template_id):
    """Feedback names any recorded mistake a wrong answer matches, listed or not: each has the part's `say:`
    or a shared default, never the general "a known slip"."""
    template = bank.get(template_id)
    silent = set()
    for seed in range(15):
        variant = make_variant(template, seed)
        for part in template.parts:
            says = {m.when for m in part.mistakes if m.say}
            silent |= {(part.id, name) for name in variant.mistakes[part.id]
                       if name not in says and name not in default_messages()}
    assert not silent


def test_shared_default_words_fit_every_part_that_uses_them(bank):
    """A default is read wherever its slip is recorded: diameters for radii in a belt length or a speed, the
    crossed-belt angle given for an open drive's larger pulley. Its words name no one formula's piece."""
    words = default_messages()
    assert "sin" not in words["diameters_for_radii"]
    assert "θ = π − 2α" not in words["crossed_formula"] and "π + 2α on the larger" in words["crossed_formula"]
    assert "pulley" not in words["ratio_inverted"].split(":")[0]
    uses = {(t.id, p.id) for t in bank for p in t.parts for m in p.mistakes if m.when == "diameters_for_radii"}
    kinds = {bank.get(t).part(p).unit for t, p in uses}
    assert {"deg", "m"} <= kinds  # an angle and a length: one text serves both


def test_every_template_s_named_mistakes_have_values_worked_out_on_their_own(bank):
    """The oracles of chapters 1, 2 and 6 and the mistake checks of chapters 3-5 and 7 between them work out
    every template's named mistakes independently of its solver (each checks its chapter's are all there)."""
    from test_mistake_values_ch3_ch4 import MISTAKES as ch34
    from test_mistake_values_ch5_ch7 import MISTAKES as ch57
    from test_oracle_ch1 import ORACLES as ch1
    from test_oracle_ch2 import ORACLES as ch2
    from test_oracle_ch6 import ORACLES as ch6

    worked = set(ch1) | set(ch2) | set(ch6) | set(ch34) | set(ch57)
    assert worked == set(bank.templates)
