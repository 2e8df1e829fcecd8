"""The rules of review, over every template of the bank and many draws: an alias reads a spelling as what it
means and the part is then graded against the student's own key (the key's text is right, another choice is
wrong); a decision sets exactly its part's points and says "marked by hand"; every listed choice is something
a spelling may be accepted as, and what a part cannot read is refused."""
import pytest

from exgen.answertypes import answer_type
from exgen.issue.assignment import Question
from graders.decisions import ACCEPT, REJECT, Alias, Decision, Decisions, cleaned
from graders.marking import QuestionMarker
from graders.results import ALIAS, BLANK, CORRECT, DECISION, WRONG
from graders.review import ReviewPlan, reading_problem

SPELLING = "see my working"
SEEDS = range(12)


def question(variant) -> Question:
    return Question(1, "q1", variant, variant.template.points)


def aliases(variant, means: dict[str, str]) -> dict:
    return {part_id: {SPELLING: Alias(1, part_id, variant.template.id, SPELLING, text, "me", "why")}
            for part_id, text in means.items()}


@pytest.mark.parametrize("seed", SEEDS)
def test_an_alias_to_the_key_is_right_and_to_another_choice_is_wrong(bank, seed):
    from exgen.solve.variant import make_variant

    for template in bank:
        variant = make_variant(template, seed)
        keys = {pid: a.text for pid, a in variant.answers.items()}
        typed = {pid: SPELLING for pid in keys}
        result = QuestionMarker(question(variant), aliases(variant, keys)).mark(typed)
        for part in result.parts:
            assert part.status == CORRECT and part.points == part.max_points, (template.id, part.part_id)
            assert part.given == SPELLING and part.review.by == ALIAS and part.review.means == keys[part.part_id]
            assert part.review.status_before != CORRECT and part.review.points_before == 0
        others = {}
        for part in template.parts:
            choices = answer_type(part).form_choices(part) or ()
            other = next((c for c in choices if not answer_type(part).matches(c, variant.answers[part.id].value, part)),
                         None)
            if other is not None:
                others[part.id] = other
        for part_id, other in others.items():
            # every other part answered right: a choice that follows from an earlier part (an actuator from a
            # Grashof class) would otherwise be carried forward from that part's wrong answer, rightly
            typed = {**keys, part_id: SPELLING}
            result = QuestionMarker(question(variant), aliases(variant, {part_id: other})).mark(typed)
            part = next(p for p in result.parts if p.part_id == part_id)
            assert part.status == WRONG and part.points == 0, (template.id, part_id)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_decision_sets_exactly_its_parts_points(bank, seed):
    from exgen.solve.variant import make_variant

    for template in bank:
        variant = make_variant(template, seed)
        keys = {pid: a.text for pid, a in variant.answers.items()}
        marked = QuestionMarker(question(variant)).mark(keys)
        first, *rest = [p.part_id for p in marked.parts]
        half = 0.5 * min(p.max_points for p in marked.parts)
        decisions = Decisions("t", (Decision("S1", 1, first, cleaned(keys[first]), REJECT, "me", "copied",
                                             comment="see me"),))
        for part_id in rest:
            decisions = decisions.with_decision(Decision("S1", 1, part_id, cleaned(keys[part_id]), ACCEPT, "me", "ok",
                                                         points=half))
        applied = ReviewPlan(decisions).apply("S1", marked)
        assert applied.parts[0].points == 0 and applied.parts[0].status == WRONG
        assert applied.parts[0].message == "marked by hand: see me"
        assert applied.parts[0].review.by == DECISION and applied.parts[0].review.status_before == CORRECT
        for part in applied.parts[1:]:
            assert part.points == half and part.status == WRONG and part.review.points_before == part.max_points, \
                (template.id, part.part_id)
        assert ReviewPlan(decisions).apply("S2", marked) is marked  # another student's decisions: nothing
        blank = QuestionMarker(question(variant)).mark({})
        accepted = ReviewPlan(Decisions("t", tuple(Decision("S1", 1, p.part_id, "", ACCEPT, "me", "lost file")
                                                   for p in blank.parts))).apply("S1", blank)
        assert all(p.status == CORRECT and p.points == p.max_points and p.review.status_before == BLANK
                   for p in accepted.parts), template.id


def test_every_listed_choice_may_be_meant_and_nonsense_may_not(bank):
    for template in bank:
        for part in template.parts:
            for choice in answer_type(part).form_choices(part) or ():
                assert reading_problem(choice, part) is None, (template.id, part.id, choice)
            assert reading_problem("\u2603 nothing at all \u2603", part) is not None, (template.id, part.id)
