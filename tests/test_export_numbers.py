"""Every value and tolerance an export writes, over every template: at most 12 significant figures, so
no binary noise of arithmetic reaches a learning system (675.0000000000002, 0.34500000000000003), and
each within a thousandth of its tolerance of the value exgen grades with (exactly it, where the
tolerance is 0)."""
import re
from functools import lru_cache

import pytest
from lxml import etree

from exgen.answertypes import answer_type
from exgen.export.canvas import canvas_files
from exgen.export.filters import SIGNIFICANT, number
from exgen.export.moodle import moodle_xml
from exgen.export.qti import qti_files

from export_helpers import cloze_subquestions, every_template_pool

QTI = "{http://www.imsglobal.org/xsd/imsqti_v2p1}"
CANVAS = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
_MANTISSA = re.compile(r"-?([0-9]*)\.?([0-9]*)(?:[eE][-+]?[0-9]+)?")


def figures(text: str) -> int:
    """Significant figures of a number as written ("675" 3, "0.00125" 3, "1.5e-07" 2)."""
    match = _MANTISSA.fullmatch(text.strip())
    assert match, f"not a number: {text!r}"
    digits = (match.group(1) + match.group(2)).lstrip("0")
    if not match.group(2):  # a whole number: its trailing zeros may be places, not figures
        digits = digits.rstrip("0")
    return len(digits)


@lru_cache(maxsize=1)
def written_numbers() -> dict[str, list[str]]:
    """Every value and tolerance each export writes, as text."""
    pool = every_template_pool()
    moodle = etree.fromstring(moodle_xml(pool).encode("utf-8"))
    found = {"moodle": [], "qti": [], "canvas": []}
    for question in moodle.findall("question"):
        for answer in question.findall("answer"):
            if answer.findtext("text") != "*":
                found["moodle"].append(answer.findtext("text"))
            found["moodle"].append(answer.findtext("tolerance") or "0")
        found["moodle"] += [u.findtext("multiplier") for u in question.iter("unit")]
        if question.get("type") == "cloze":
            for sub in cloze_subquestions(question.findtext("questiontext/text")):
                for alternative in sub.alternatives:
                    if sub.qtype == "numerical" and alternative.answer != "*":
                        found["moodle"] += [alternative.answer, repr(alternative.tolerance)]
    for name, data in qti_files(pool).items():
        if name.startswith("items/") and name.endswith(".xml"):
            item = etree.fromstring(data)
            found["qti"] += [v.text for v in item.iter(f"{QTI}baseValue") if v.get("baseType") == "float"]
            found["qti"] += [t for e in item.iter(f"{QTI}equal") for t in e.get("tolerance").split()]
            found["qti"] += [d.findtext(f"{QTI}correctResponse/{QTI}value") for d in item.iter(f"{QTI}responseDeclaration")
                             if d.get("baseType") == "float"]
    for name, data in canvas_files(pool).items():
        if name.endswith(".xml") and b"questestinterop" in data[:400]:
            for item in etree.fromstring(data).iter(CANVAS + "item"):
                if item.find(f".//{CANVAS}response_str") is not None:  # a numerical question
                    found["canvas"] += [v.text for tag in ("varequal", "vargte", "varlte") for v in item.iter(CANVAS + tag)]
    return found


@pytest.mark.parametrize("export", ["moodle", "qti", "canvas"])
def test_no_number_an_export_writes_carries_binary_noise(export):
    numbers = written_numbers()[export]
    assert len(numbers) > 500
    noisy = [text for text in numbers if figures(text) > SIGNIFICANT]
    assert not noisy, f"{len(noisy)} of {len(numbers)} numbers carry more than {SIGNIFICANT} figures: {noisy[:5]}"


def test_a_written_value_is_within_a_thousandth_of_its_tolerance_of_the_graded_one():
    checked = 0
    for question in every_template_pool().questions:
        for variant in question.variants:
            for part in variant.template.parts:
                try:
                    gaps = answer_type(part).lms_gaps(part, variant.answers[part.id].value, {})
                except ValueError:
                    continue
                for gap in gaps:
                    if gap.kind != "numeric":
                        continue
                    for value in gap.values:
                        error = abs(float(number(value)) - value)
                        assert error <= 1e-3 * gap.tolerance if gap.tolerance else error == 0, (variant.template.id, value)
                        checked += 1
    assert checked > 200


def test_figures_counts_as_a_reader_would():
    assert [figures(t) for t in ("675", "0.00125", "1.5e-07", "0.34500000000000003", "145.00000000000003", "1200")] \
        == [3, 3, 2, 17, 17, 2]
    assert number(675.0000000000002) == "675" and number(0.34500000000000003) == "0.345" and number(1e-05) == "1e-05"
