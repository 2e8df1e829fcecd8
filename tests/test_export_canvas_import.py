"""The Canvas zip of every template as Canvas imports it: through its QTI 1.2 converter
(tests/qti_migration.py, a port of instructure/QTIMigrationTool) and canvas-lms's reading of what that
writes (tests/canvas_rules.py). Every identifier survives every rewrite the converter makes, every choice
question keeps its one correct answer and each wrong choice its mistake's feedback, and every numerical
question its values and range. With $EXGEN_QTI_MIGRATION_TOOL naming a checkout of the converter, the
port is checked against the converter itself."""
import os
import subprocess
import sys
from functools import lru_cache
from pathlib import Path

import pytest
from lxml import etree

from exgen.export.canvas import canvas_files, groups

from canvas_rules import read_choice, read_numeric
from export_helpers import every_template_pool, written
from qti_migration import (FEEDBACK_PREFIX, OUTCOME_PREFIX, Q, RESPONSE_PREFIX, check_nmtoken, convert, d2l,
                           fix_identifier, html_text, item_identifier, read_identifier, strip_namespaces)

IDENT = "exgen-pool"


@lru_cache(maxsize=1)
def exported():
    pool = every_template_pool()
    files = canvas_files(pool)
    found, _ = groups(pool)
    return files, [q for g in found for q in g.questions]


@lru_cache(maxsize=1)
def imported():
    """(exported question, the QTI 2.1 item the converter writes for it)."""
    files, questions = exported()
    converted = {item.get("identifier"): item for item in convert(files[f"{IDENT}/{IDENT}.xml"])}
    return [(q, converted[item_identifier(q.ident)]) for q in questions]


def _rewrites(quiz):
    """(what, text as written, text after the converter's rewrite) for every identifier it rewrites."""
    for element in quiz.iter(f"{Q}assessment"):
        yield "assessment", element.get("ident"), fix_identifier("-".join(element.get("ident").split(":")))
    for element in quiz.iter(f"{Q}item"):
        yield "item", element.get("ident"), item_identifier(element.get("ident"))
    for tag in ("response_lid", "response_str", "response_label"):
        for element in quiz.iter(Q + tag):
            yield tag, element.get("ident"), read_identifier(d2l(element.get("ident")), RESPONSE_PREFIX)
    for tag in ("varequal", "vargte", "varlte"):
        for element in quiz.iter(Q + tag):
            yield f"{tag} respident", element.get("respident"), read_identifier(d2l(element.get("respident")), RESPONSE_PREFIX)
    for element in quiz.iter(f"{Q}response_lid"):
        for value in element.getparent().getparent().iter(f"{Q}varequal"):
            yield "varequal value", value.text, check_nmtoken(value.text, RESPONSE_PREFIX)
    for element in quiz.iter(f"{Q}itemfeedback"):
        yield "itemfeedback", element.get("ident"), read_identifier(element.get("ident"), FEEDBACK_PREFIX)
    for element in quiz.iter(f"{Q}displayfeedback"):
        yield "displayfeedback", element.get("linkrefid"), read_identifier(element.get("linkrefid"), FEEDBACK_PREFIX)
    for tag in ("decvar", "setvar"):
        for element in quiz.iter(Q + tag):
            yield tag, element.get("varname"), read_identifier(element.get("varname"), OUTCOME_PREFIX).upper()


def test_every_identifier_survives_every_rewrite_the_converter_makes():
    files, _ = exported()
    quiz = etree.fromstring(files[f"{IDENT}/{IDENT}.xml"])
    rewritten = [(what, before, after) for what, before, after in _rewrites(quiz) if before != after]
    counted = sum(1 for _ in _rewrites(quiz))
    assert counted > 5000
    assert not rewritten, f"{len(rewritten)} identifiers rewritten, such as {rewritten[:3]}"


def test_the_converters_rewrites_as_ported():
    assert read_identifier("q7-governors.spring_controlled-01-a-C2", RESPONSE_PREFIX) == "q7-governors_spring_controlled-01-a-C2"
    assert read_identifier("a:b c", RESPONSE_PREFIX) == "a_b-c" and read_identifier("1x", RESPONSE_PREFIX) == "RESPONSE_1x"
    assert d2l("choice_ANS") == "choice" and check_nmtoken("x.y", RESPONSE_PREFIX) == "x.y"
    assert item_identifier("q1:a.b c") == "q1-a.b_c"


def test_every_choice_question_keeps_its_correct_answer_and_each_wrong_choice_its_feedback():
    checked = with_feedback = 0
    for exported_question, item in imported():
        gap = exported_question.gap
        if gap.kind != "choice":
            continue
        question = read_choice(item)
        assert not question.import_error, (exported_question.ident, question.import_error)
        assert [a.text for a in question.answers] == list(gap.choices)
        assert [a.text for a in question.answers if a.weight == 100] == [gap.correct], exported_question.ident
        said = {w.value: html_text(w.message) for w in gap.wrong}
        assert {a.text: a.comments for a in question.answers if a.comments} == said, exported_question.ident
        # the worked solution is the question's general feedback, and no choice's feedback is taken for it
        assert set(question.comments) == {"neutral"} and "Worked solution" in question.comments["neutral"]
        checked += 1
        with_feedback += bool(gap.wrong)
    assert checked >= 40 and with_feedback >= 10


def test_every_numerical_question_keeps_its_values_and_their_range():
    checked = 0
    for exported_question, item in imported():
        gap = exported_question.gap
        if gap.kind != "numeric":
            continue
        question = read_numeric(item)
        assert [a.kind for a in question.answers] == ["exact_answer"] * len(gap.values)
        assert [a.exact for a in question.answers] == [written(v) for v in gap.values]
        for answer, value in zip(question.answers, gap.values):
            assert answer.margin == pytest.approx(gap.tolerance, rel=1e-9, abs=1e-11 * (abs(value) + gap.tolerance))
        checked += 1
    assert checked > 300


# ---- the port against the converter itself ---------------------------------------------------------

def _read(item):
    reader = read_choice if item.find(".//choiceInteraction") is not None else read_numeric
    question = reader(item)
    return question.import_error, [(a.migration_id, a.text, a.weight, a.comments, a.kind, a.exact, a.margin)
                                   for a in question.answers]


@pytest.mark.skipif(not os.environ.get("EXGEN_QTI_MIGRATION_TOOL"),
                    reason="set EXGEN_QTI_MIGRATION_TOOL to a checkout of instructure/QTIMigrationTool")
def test_the_port_reads_as_the_converter_writes(tmp_path):
    tool = Path(os.environ["EXGEN_QTI_MIGRATION_TOOL"])
    files, _ = exported()
    package = tmp_path / "in"
    for name, data in files.items():
        if not name.endswith("/"):
            (package / name).parent.mkdir(parents=True, exist_ok=True)
            (package / name).write_bytes(data)
    out = tmp_path / "out"
    run = subprocess.run([sys.executable, str(tool / "migrate.py"), "--ucvars", "--nogui", "--overwrite",
                          f"--cpout={out}", str(package)], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:]
    real = {}
    for path in (out / "assessmentItems").glob("*.xml"):
        item = strip_namespaces(etree.parse(str(path)).getroot())
        real[item.get("identifier")] = item
    ported = {item.get("identifier"): item for _, item in imported()}
    assert set(real) == set(ported)
    for ident, item in ported.items():
        assert _read(real[ident]) == _read(item), ident
