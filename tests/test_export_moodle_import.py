"""The Moodle XML of every template as Moodle imports and marks it (tests/moodle_rules.py, ports of
format.php, qtype_multianswer's parser and qtype_numerical's unit handling): every unit a numerical
question lists is one a typed answer can reach, and every question's identity reaches Moodle 4.x, whose
importer reads no ID number for a cloze question."""
import dataclasses
from functools import lru_cache

from lxml import etree
from markupsafe import Markup

from exgen.export.filters import number
from exgen.export.html import LATEX_HTML, render
from exgen.export.moodle import PLUGINFILE, Category, moodle_xml
from exgen.export.pool import make_item

from export_helpers import every_template_pool
from moodle_rules import import_question


@lru_cache(maxsize=1)
def written():
    pool = every_template_pool()
    root = etree.fromstring(moodle_xml(pool).encode("utf-8"))
    return [q for q in root.findall("question") if q.get("type") != "category"]


def single_numeric_questions():
    """Every numeric gap of every template as the numerical question Moodle gets for a one-gap item."""
    for question in every_template_pool().questions:
        for index, variant in enumerate(question.variants, 1):
            item = make_item(question, index, variant, LATEX_HTML, PLUGINFILE)
            for part in item.exported_parts:
                if len(part.gaps) == 1 and part.gaps[0].kind == "numeric":
                    alone = dataclasses.replace(item, parts=(part,))
                    text = render("moodle.xml.j2", title="t", questions=[Category("h", Markup(""), (alone,))])
                    element = etree.fromstring(text.lstrip().encode("utf-8")).findall("question")[1]
                    yield part.gaps[0], element


def test_every_unit_a_numerical_question_accepts_is_one_a_typed_answer_reaches():
    checked = 0
    for gap, element in single_numeric_questions():
        names = [u.findtext("unit_name") for u in element.iter("unit")]
        assert all(name == "".join(name.split()) for name in names), names
        question = import_question(element).parts[0]
        for name, multiplier in gap.units:  # as a student types it, spaces and all
            typed = f"{number(gap.value * multiplier)} {name}"
            assert question.grade(typed)[0] == 1.0, (typed, names)
            checked += 1
        assert question.grade(number(gap.value))[0] == 1.0  # a bare number, in the unit asked
    assert checked > 1000


def test_every_questions_identity_reaches_moodle_4_in_its_name_and_5_in_its_id_number_too():
    pool = every_template_pool()
    items = [make_item(q, i, v, LATEX_HTML, PLUGINFILE) for q in pool.questions for i, v in enumerate(q.variants, 1)]
    idents = [item.ident for item in items if item.gaps]
    seen = set()
    for element, ident in zip(written(), idents):
        old, new = import_question(element, version="4"), import_question(element, version="5")
        assert new.idnumber == ident
        assert len(old.name) <= 255 and old.name.split(": ", 1)[0] == ident, (old.name, ident)
        seen.add(old.name)
    assert len(seen) == len(idents) and sum(e.get("type") == "cloze" for e in written()) > 50
