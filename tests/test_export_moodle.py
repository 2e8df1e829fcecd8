"""Moodle XML for every template, read back as Moodle's importer (question/format/xml/format.php) reads
it: the structure it expects, files it can store, cloze text it can split, and every value and
tolerance as the pool has them, with tolerances that accept what exgen accepts and no more."""
import base64
import re
from functools import lru_cache

import pytest
from lxml import etree

from exgen.answertypes import answer_type
from exgen.export.filters import moodle_units
from exgen.export.html import LATEX_HTML
from exgen.export.moodle import PLUGINFILE, moodle_xml
from exgen.export.pool import make_item

from export_helpers import cloze_subquestions, every_template_pool, written

#: The grades Moodle's import accepts as they are (question/engine/bank.php), in percent.
MOODLE_FRACTIONS = {100, 90, 83.33333, 80, 75, 70, 66.66667, 60, 50, 40, 33.33333, 30, 25, 20, 16.66667, 14.28571,
                    12.5, 11.11111, 10, 5, 0}


@lru_cache(maxsize=1)
def exported():
    pool = every_template_pool()
    text = moodle_xml(pool)
    items = [make_item(q, i, v, LATEX_HTML, PLUGINFILE) for q in pool.questions for i, v in enumerate(q.variants, 1)]
    return text, etree.fromstring(text.encode("utf-8")), [item for item in items if item.gaps]


def questions():
    return [q for q in exported()[1].findall("question") if q.get("type") != "category"]


def test_the_file_is_utf8_with_the_declaration_on_its_first_line_and_a_quiz_root():
    text, root, _ = exported()
    assert text.startswith('<?xml version="1.0" encoding="UTF-8"?>\n<quiz>')
    assert root.tag == "quiz"


def test_a_category_per_question_of_the_pool_holds_its_variants():
    _, root, items = exported()
    categories = [q for q in root.findall("question") if q.get("type") == "category"]
    assert len(categories) == len({item.question.number for item in items})
    for category in categories:
        assert category.findtext("category/text").startswith("$course$/top/Every template/")
    # each category is followed by its own variants only: "$course$/top/Every template/q7 Title" by q7-...
    current = None
    for element in root.findall("question"):
        if element.get("type") == "category":
            current = element.findtext("category/text").split("/")[3].split(" ")[0]
        else:
            assert element.findtext("idnumber").startswith(current + "-")


def test_every_item_is_written_in_pool_order_with_its_type_and_idnumber():
    _, _, items = exported()
    written = questions()
    assert [q.findtext("idnumber") for q in written] == [item.ident for item in items]
    for element, item in zip(written, items):
        gaps = item.gaps
        expected = "cloze" if len(gaps) > 1 else ("numerical" if gaps[0].kind == "numeric" else "multichoice")
        assert element.get("type") == expected
        assert element.findtext("name/text").strip()
        assert element.find("questiontext").get("format") == "html"
        assert element.find("generalfeedback").get("format") == "html"
        assert "Worked solution" in element.findtext("generalfeedback/text")


def test_every_file_a_text_refers_to_is_embedded_beside_it_as_base64():
    for element in questions():
        for area in ("questiontext", "generalfeedback"):
            node = element.find(area)
            files = {f.get("name"): f for f in node.findall("file")}
            for f in files.values():
                assert f.get("path") == "/" and f.get("encoding") == "base64"
                assert base64.b64decode(f.text).startswith(b"<svg")
            referred = set(re.findall(r'@@PLUGINFILE@@/([^"]+)"', node.findtext("text")))
            assert referred == set(files), (element.findtext("idnumber"), area)


def _in_tolerance_like_exgen(item, gap, part_id, value, tolerance):
    """The tolerance Moodle applies accepts what exgen's grader accepts, and not much more."""
    part = item.variant.template.part(part_id)
    kind = answer_type(part)
    expected = item.variant.answers[part_id].value
    if gap.kind != "numeric" or gap.key:  # a polar answer's halves are checked through the gap values
        return
    assert kind.matches(value + 0.999 * tolerance, expected, part)
    if tolerance:
        assert not kind.matches(value + 1.01 * tolerance, expected, part)


def test_numerical_questions_round_trip_values_tolerances_units_and_mistakes():
    checked = 0
    for element, item in zip(questions(), exported()[2]):
        if element.get("type") != "numerical":
            continue
        gap, part = item.gaps[0], item.exported_parts[0]
        answers = element.findall("answer")
        right = [a for a in answers if a.get("fraction") == "100"]
        assert [float(a.findtext("text")) for a in right] == [written(v) for v in gap.values]
        assert all(float(a.findtext("tolerance")) == written(gap.tolerance) for a in right)
        wrong = [a for a in answers if a.get("fraction") == "0" and a.findtext("text") != "*"]
        assert [float(a.findtext("text")) for a in wrong] == [written(w.value) for w in gap.wrong]
        assert [a.findtext("feedback/text") for a in wrong] == [str(w.message) for w in gap.wrong]
        assert answers[-1].findtext("text") == "*"
        assert all(float(a.get("fraction")) in MOODLE_FRACTIONS for a in answers)
        _in_tolerance_like_exgen(item, gap, part.id, gap.value, gap.tolerance)
        units = element.findall("units/unit")
        if gap.units:
            assert [(u.findtext("unit_name"), float(u.findtext("multiplier"))) for u in units] \
                == [(name, written(m)) for name, m in moodle_units(gap.units)]
            assert float(units[0].findtext("multiplier")) == 1.0
            assert element.findtext("unitgradingtype") == "0" and element.findtext("showunits") == "0"
        assert float(element.findtext("defaultgrade")) == pytest.approx(item.points)
        checked += 1
    assert checked > 0


def test_cloze_questions_split_into_one_subquestion_per_gap_with_every_value_and_tolerance():
    checked = 0
    for element, item in zip(questions(), exported()[2]):
        if element.get("type") != "cloze":
            continue
        subquestions = cloze_subquestions(element.findtext("questiontext/text"))
        weights = item.weights()
        assert len(subquestions) == len(weights)
        for sub, (part, gap, weight) in zip(subquestions, weights):
            assert sub.weight == weight >= 1
            assert any(a.fraction == 1 for a in sub.alternatives)  # Moodle refuses a gap with no right answer
            assert all(100 * a.fraction in MOODLE_FRACTIONS for a in sub.alternatives)
            if gap.kind == "numeric":
                assert sub.qtype == "numerical"
                right = [a for a in sub.alternatives if a.fraction == 1]
                assert [float(a.answer) for a in right] == [written(v) for v in gap.values]
                assert all(a.tolerance == written(gap.tolerance) for a in right)
                named = [a for a in sub.alternatives if a.fraction == 0 and a.answer != "*"]
                assert [(float(a.answer), a.tolerance) for a in named] == [(written(w.value), written(w.tolerance)) for w in gap.wrong]
                assert [a.feedback for a in named] == [str(w.message) for w in gap.wrong]
                assert sub.alternatives[-1].answer == "*"
                _in_tolerance_like_exgen(item, gap, part.id, gap.value, gap.tolerance)
            else:
                assert sub.qtype == "multichoice" and len(sub.alternatives) >= 2
                assert [a.answer for a in sub.alternatives] == list(gap.choices)
                assert [a.answer for a in sub.alternatives if a.fraction == 1] == [gap.correct]
        # the weights keep the parts' marks in proportion
        total = sum(w for _, _, w in weights)
        for part in item.exported_parts:
            share = sum(w for p, _, w in weights if p is part) / total
            assert share == pytest.approx(part.points / item.points)
        checked += 1
    assert checked > 0


def test_every_template_is_exported_and_only_formulas_are_left_out():
    pool = every_template_pool()
    _, _, items = exported()
    exported_templates = {item.variant.template.id for item in items}
    assert exported_templates == {q.template.id for q in pool.questions}
    for item in items:
        for part in item.parts:
            assert part.exported == (part.id and item.variant.template.part(part.id).type != "symbolic")


def test_text_from_a_template_cannot_break_the_cloze_syntax():
    from markupsafe import escape

    from exgen.export.filters import cloze

    written = str(cloze(escape("a } b { c ~ d # e < f & g")))
    subs = cloze_subquestions("{1:MULTICHOICE:=x#" + written + "~y}")
    assert subs[0].alternatives[0].feedback == "a } b { c ~ d # e &lt; f &amp; g"  # escaped HTML, as stored
