"""The words of the messages a student and an instructor read: what was typed is not said twice, a list of
choices is quoted, a unit is written as the question writes it, a tolerance is named only where there is
one, and values that cannot make a problem are refused in plain words."""
import io
import re
import sys

from exgen.answertypes import answer_type
from exgen.cli import main
from exgen.export.pool import solution_html
from exgen.render.targets import MARKDOWN
from exgen.solve import variant as variant_module
from exgen.solve.variant import make_variant, mistakes_apart
from graders.grade import grade_variant
from graders.results import UNREADABLE


def _result(variant, part, text):
    return next(p for p in grade_variant(variant, {part.id: text}).parts if p.part_id == part.id)


def test_a_choice_list_is_quoted_in_every_format_message(bank):
    """'write one of raises the bow, lowers the bow' ran the choices into the sentence."""
    found = []
    for template in bank:
        for part in (p for p in template.parts if p.type == "choice"):
            result = _result(make_variant(template, 1), part, "zzz")
            choices = part.options["choices"]
            if result.status != UNREADABLE or not all(f'"{c}"' in result.message for c in choices) \
                    or "one of " + choices[0] in result.message:
                found.append((template.id, part.id, result.message))
    assert not found, found[:3]


def test_every_bracketed_hint_writes_the_unit_as_the_question_does(bank):
    """'[N*m]' beside 'N·m': the prompt and the answer file print the unit as the question does."""
    found = [(t.id, p.id, answer_type(p).form_hint(p)) for t in bank for p in t.parts
             if p.unit and re.search(r"[*^]", answer_type(p).form_hint(p).split("e.g.")[0])]
    assert not found, found[:5]


def test_practice_says_once_that_it_cannot_read_an_answer(monkeypatch, capsys, tmp_path):
    """'Cannot read that: cannot read 'abc' as a number' said it twice."""
    monkeypatch.setattr(sys, "stdin", io.StringIO("abc\nq\n"))
    assert main(["practice", "--topic", "belts.compound_drive", "--db", str(tmp_path / "p.sqlite3")]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "Cannot read 'abc' as a number" in out
    assert not re.search(r"cannot read that: cannot read", out, re.IGNORECASE)


def test_a_mistake_that_is_the_answer_is_said_so_where_the_tolerance_is_exact(bank, monkeypatch):
    """'lands within 3 times exact of the answer' for a whole number or a choice: it is the answer itself."""
    seen = 0
    for template in bank:
        for part in (p for p in template.parts if answer_type(p).tolerance_text(p) == "exact" and p.mistakes):
            variant = make_variant(template, 1)
            derivation = variant_module.rerun(variant, {})
            kind = answer_type(part)
            monkeypatch.setattr(type(kind), "apart", lambda self, *a: False)
            mistakes_apart(part, variant.answers[part.id].value, derivation, check=False)
            monkeypatch.undo()
            for warning in derivation.warnings:
                seen += 1
                assert "times exact" not in warning and "gives the answer itself" in warning, warning
    assert seen


def test_solution_lists_name_no_tolerance_for_exact_answers(bank):
    """'(within exact)' beside a choice or a whole number in the learning systems' worked solutions."""
    found = []
    for template in bank:
        variant = make_variant(template, 1)
        html = str(solution_html(variant, MARKDOWN, []))
        if "within exact" in html:
            found.append(template.id)
        for part in template.parts:
            if answer_type(part).tolerance_text(part) != "exact":
                assert f"(within {answer_type(part).tolerance_text(part)})" in html.replace("&amp;", "&"), \
                    (template.id, part.id)
    assert not found, found[:5]


def test_values_that_cannot_make_a_belt_drive_are_refused_in_plain_words(capsys):
    """A centre distance shorter than the radii's difference: 'math domain error' said nothing."""
    values = ["d1=300mm", "d2=2000mm", "X=0.5m", "N1=500rpm", "mu=0.3", "A=800mm^2", "rho=1000kg/m^3",
              "E=100MN/m^2", "sigma=2MPa"]
    code = main(["solve", "belts.flat_belt_power", *[a for v in values for a in ("--set", v)]])
    err = capsys.readouterr().err
    assert code != 0 and "math domain" not in err and "Traceback" not in err
    assert "the difference of their radii is more than the centre distance" in err
    assert "X > d1 + d2" in err


def test_a_unit_of_inches_is_named_in_words(bank):
    """"a length is asked (in in)": the inch is spelt out where a sentence names it."""
    found = [(t, p) for t in bank for p in t.parts if p.unit == "in"]
    assert found
    for template, part in found:
        message = _result(make_variant(template, 1), part, "5 kg").message
        assert "(in inches)" in message and "in in)" not in message, message
