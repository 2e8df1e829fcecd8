"""Every export of every template, answered with probe answers and marked by each consumer's own rules:
QTI 2.1 by pyslet's item session (response processing run as written), Moodle XML by ports of Moodle's
importer and marking (tests/moodle_rules.py), Canvas by ports of its converter and canvas-lms
(tests/qti_migration.py, tests/canvas_rules.py). For each probe the consumer's verdict, right or wrong,
and the named mistake its feedback gives, equal exgen's own grader's.

The probes of a number: the key, the key to 4 significant figures, just inside and just outside the
tolerance each way (0.999 and 1.001 of it), every mistake the solver records for the part, and the same
direction a turn either way for an angle; of a choice, every choice. exgen compares angles modulo any
number of turns, a learning system only a turn either way (docs/lms.md); no probe goes further.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import pytest
from lxml import etree

from exgen.answertypes.polar import Polar
from exgen.export.canvas import canvas_files, groups
from exgen.export.filters import number
from exgen.export.html import LATEX_HTML, MATHML_XHTML
from exgen.export.moodle import PLUGINFILE, moodle_xml
from exgen.export.pool import make_item
from exgen.export.qti import IMAGES, gap_refs, qti_files
from exgen.issue.assignment import Question
from graders.marking import QuestionMarker
from graders.results import CORRECT

from canvas_rules import mark_choice, mark_numeric, read_choice, read_numeric
from export_helpers import every_template_pool
from moodle_rules import import_question
from qti_migration import convert, html_text, item_identifier

INSIDE, OUTSIDE = 0.999, 1.001
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # pyslet 0.7 calls its own old names


@dataclass(frozen=True)
class Probe:
    typed: str       # what goes in the gap
    answer: str      # the same answer as exgen's answer file holds it (a polar answer whole)
    why: str
    whole: str = ""  # a polar mistake whole, whose half the gap holds: the answer exgen names a mistake of


@dataclass(frozen=True)
class Case:
    ident: str       # the item's
    part: object
    gap: object
    probe: Probe
    right: bool      # exgen's verdict
    named: str | None  # the feedback of the exported mistake exgen names, as text, if any


def _numbers(value: float, tolerance: float, also, recorded) -> list[tuple[float, str, str]]:
    out = [(value, "the key", ""), (float(f"{value:.4g}"), "the key to 4 figures", "")]
    step = tolerance or 1.0
    out += [(value + INSIDE * tolerance, "inside", ""), (value - INSIDE * tolerance, "inside", "")] if tolerance else []
    out += [(value + OUTSIDE * step, "outside", ""), (value - OUTSIDE * step, "outside", "")]
    out += [(v, "a turn on", "") for v in also]
    out += [(v, f"mistake {name}", name) for name, v in recorded]
    return out


def probes(variant, part, gap) -> list[Probe]:
    key = variant.answers[part.id].value
    recorded = variant.mistakes.get(part.id, {})
    if gap.kind == "choice":
        return [Probe(c, c, "a choice") for c in gap.choices]
    if isinstance(key, Polar):
        def whole(size, angle):
            return f"{number(size)} {part.unit} at {number(angle)} deg"

        def mistake(name):
            return whole(recorded[name].magnitude, recorded[name].angle_deg) if name else ""

        if gap.key == "size":
            values = _numbers(gap.value, gap.tolerance, gap.also, [(n, m.magnitude) for n, m in recorded.items()])
            return [Probe(number(v), whole(v, key.angle_deg), why, mistake(name)) for v, why, name in values]
        values = _numbers(gap.value, gap.tolerance, gap.also, [(n, m.angle_deg) for n, m in recorded.items()])
        return [Probe(number(v), whole(key.magnitude, v), why, mistake(name)) for v, why, name in values]
    numeric = [(n, float(v)) for n, v in recorded.items() if isinstance(v, (int, float)) and not isinstance(v, bool)]
    return [Probe(number(v), number(v), why) for v, why, _ in _numbers(gap.value, gap.tolerance, gap.also, numeric)]


@lru_cache(maxsize=1)
def cases() -> list[Case]:
    """Every probe of every gap of every variant as the exports hold it, with exgen's own verdict."""
    out = []
    for question in every_template_pool().questions:
        for index, variant in enumerate(question.variants, 1):
            item = make_item(question, index, variant, LATEX_HTML, PLUGINFILE)
            asked = Question(question.number, question.slot, variant, question.points)
            for item_part in item.exported_parts:
                part = variant.template.part(item_part.id)
                for gap in item_part.gaps:
                    said = {w.name: html_text(w.message) for w in gap.wrong}
                    for probe in probes(variant, part, gap):
                        # each probe alone, as a learning system marks it: no earlier answer to carry forward
                        result = QuestionMarker(asked).part(part, probe.answer)
                        named = QuestionMarker(asked).part(part, probe.whole).mistake if probe.whole else result.mistake
                        out.append(Case(item.ident, part, gap, probe, result.status == CORRECT, said.get(named)))
    return out


def _named(gap, feedback: str, html: bool = True) -> str | None:
    """The feedback a consumer shows, as text, when it is a named mistake's (`html`: given as HTML)."""
    shown = html_text(feedback) if html else feedback
    return shown if any(html_text(w.message) == shown for w in gap.wrong) and feedback else None


def _check(verdicts, consumer: str):
    wrong = [(c.ident, c.part.id, c.gap.key, c.probe.why, c.probe.typed, (c.right, c.named), got)
             for c, got in verdicts if got != (c.right, c.named)]
    assert len(verdicts) > 2000
    assert not wrong, f"{consumer} differs from exgen in {len(wrong)} of {len(verdicts)} probes, such as {wrong[:4]}"


def test_the_probes_cover_every_kind_of_answer():
    whys = {c.probe.why.split(" ")[0] for c in cases()}
    assert {"the", "inside", "outside", "a", "mistake"} <= whys
    assert sum(c.right for c in cases()) and sum(not c.right for c in cases()) and sum(bool(c.named) for c in cases())
    assert any(c.probe.why == "a turn on" for c in cases()) and any(c.gap.kind == "choice" for c in cases())


# ---- QTI 2.1: pyslet runs each item's response processing ------------------------------------------

@pytest.fixture(scope="module")
def pyslet():
    """pyslet 0.7's item session. Its `equal` declares `tolerance` as a plain string, though the schema
    makes it a list, and then takes the string's first characters for the two tolerances; declared as a
    list, as every list attribute of pyslet's is, it reads the tolerance the schema describes."""
    from pyslet.qtiv2 import expressions, variables
    from pyslet.qtiv2 import xml as qtixml

    expressions.Equal.XMLATTR_tolerance = ("tolerance", None, None, list)
    return qtixml, variables


def test_qti_2_1_items_mark_every_probe_as_exgen_does(pyslet):
    qtixml, variables = pyslet
    pool = every_template_pool()
    files = qti_files(pool)
    refs, documents = {}, {}
    for question in pool.questions:
        for index, variant in enumerate(question.variants, 1):
            item = make_item(question, index, variant, MATHML_XHTML, IMAGES)
            if item.gaps:
                refs[item.ident] = {(r.part.id, r.gap.key): r for r in gap_refs(item)}
    verdicts = []
    for case in cases():
        if case.ident not in documents:
            document = qtixml.QTIDocument()
            document.read(src=files[f"items/{case.ident}.xml"])
            documents[case.ident] = document.root
        item, ref = documents[case.ident], refs[case.ident][(case.part.id, case.gap.key)]
        state = variables.ItemSessionState(item)
        state.begin_session()
        state.map["numAttempts"].set_value(1)
        for declaration in item.ResponseDeclaration:  # begin_attempt, without laying out the item
            state.map[declaration.identifier] = variables.Value.copy_value(state.map[declaration.identifier + ".DEFAULT"])
        typed = ref.choice_ids[case.probe.typed] if case.gap.kind == "choice" else float(case.probe.typed)
        state.map[ref.rid].set_value(typed)
        state.end_attempt()
        score, shown = state.map["SCORE"].value, state.map["FEEDBACK"].value or {}
        named = next((html_text(w.wrong.message) for w in ref.wrong if w.fid in shown), None)
        verdicts.append((case, (abs(score - ref.points) < 1e-9, named)))
    _check(verdicts, "QTI 2.1 (pyslet)")


# ---- Moodle XML ------------------------------------------------------------------------------------

def test_moodle_marks_every_probe_as_exgen_does():
    pool = every_template_pool()
    root = etree.fromstring(moodle_xml(pool).encode("utf-8"))
    written = [q for q in root.findall("question") if q.get("type") != "category"]
    items = [make_item(q, i, v, LATEX_HTML, PLUGINFILE) for q in pool.questions for i, v in enumerate(q.variants, 1)]
    items = [item for item in items if item.gaps]
    parts = {}
    for item, element in zip(items, written):
        imported = import_question(element)
        gaps = [(p, g) for p, g, _ in item.weights()] if imported.qtype == "multianswer" else \
            [(item.exported_parts[0], item.gaps[0])]
        assert len(gaps) == len(imported.parts), item.ident
        for (part, gap), question in zip(gaps, imported.parts):
            parts[(item.ident, part.id, gap.key)] = question
    verdicts = []
    for case in cases():
        fraction, feedback = parts[(case.ident, case.part.id, case.gap.key)].grade(case.probe.typed)
        verdicts.append((case, (fraction == 1.0, _named(case.gap, feedback))))
    _check(verdicts, "Moodle")


# ---- Canvas ----------------------------------------------------------------------------------------

def test_canvas_marks_every_probe_as_exgen_does():
    """Canvas numerical questions carry no named mistakes (all their answers are right answers)."""
    pool = every_template_pool()
    files = canvas_files(pool)
    converted = {i.get("identifier"): i for i in convert(files["exgen-pool/exgen-pool.xml"])}
    read = {}
    for group in groups(pool)[0]:
        for question in group.questions:
            doc = converted[item_identifier(question.ident)]
            read[question.ident] = read_choice(doc) if question.gap.kind == "choice" else read_numeric(doc)
    verdicts = []
    for case in cases():
        suffix = case.part.id + (f"-{case.gap.key}" if case.gap.key else "")
        question = read[f"{case.ident}-{suffix}"]
        if case.gap.kind == "choice":
            right, comments = mark_choice(question, case.probe.typed)
            verdicts.append((case, (right, _named(case.gap, comments, html=False))))  # canvas-lms's text
        else:
            verdicts.append((replace(case, named=None), (mark_numeric(question, case.probe.typed), None)))
    _check(verdicts, "Canvas")


def test_the_export_narrows_through_the_tolerances_the_grader_does():
    from graders.mistakes import NARROWING

    from exgen.export import mistakes

    assert mistakes.NARROWING == NARROWING
