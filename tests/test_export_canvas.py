"""The Canvas zip for every template: the layout Canvas's importer looks for (a manifest resource of
type imsqti_xmlv1p2 with its settings file), a question group per gap drawing one variant, numerical
questions whose range is the part's tolerance, choices with the named mistakes' feedback, and images."""
import re
from functools import lru_cache
from urllib.parse import unquote

from lxml import etree

from exgen.export.canvas import canvas_files, groups

from export_helpers import every_template_pool, written

Q = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
CC = "{http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1}"
IDENT = "exgen-pool"


@lru_cache(maxsize=1)
def package():
    pool = every_template_pool()
    return canvas_files(pool), groups(pool)[0]


def _field(item, label):
    for field in item.iter(f"{Q}qtimetadatafield"):
        if field.findtext(f"{Q}fieldlabel") == label:
            return field.findtext(f"{Q}fieldentry")
    return None


def test_the_zip_has_the_layout_canvas_imports():
    files, _ = package()
    assert {"imsmanifest.xml", "non_cc_assessments/", f"{IDENT}/{IDENT}.xml", f"{IDENT}/assessment_meta.xml"} <= set(files)
    manifest = etree.fromstring(files["imsmanifest.xml"])
    resources = {r.get("identifier"): r for r in manifest.iter(f"{CC}resource")}
    quiz = resources[IDENT]
    assert quiz.get("type") == "imsqti_xmlv1p2"
    assert quiz.find(f"{CC}file").get("href") == f"{IDENT}/{IDENT}.xml"
    meta = resources[quiz.find(f"{CC}dependency").get("identifierref")]
    assert meta.get("type") == "associatedcontent/imscc_xmlv1p1/learning-application-resource"
    for resource in resources.values():
        for f in resource.iter(f"{CC}file"):
            assert f.get("href") in files
    settings = etree.fromstring(files[f"{IDENT}/assessment_meta.xml"])
    assert settings.tag == "{http://canvas.instructure.com/xsd/cccv1p0}quiz"


def test_a_group_per_gap_draws_one_variant_and_the_points_add_up():
    files, found = package()
    root = etree.fromstring(files[f"{IDENT}/{IDENT}.xml"])
    assert root.tag == f"{Q}questestinterop"
    sections = root.findall(f"{Q}assessment/{Q}section/{Q}section")
    assert len(sections) == len(found)
    pool = every_template_pool()
    for section, group in zip(sections, found):
        assert section.findtext(f".//{Q}selection_number") == "1"
        assert float(section.findtext(f".//{Q}points_per_item")) == group.points
        assert len(section.findall(f"{Q}item")) == len(pool.questions[0].variants)
    by_question = {}
    for group in found:
        slot = group.title.split(" ")[0]
        by_question[slot] = by_question.get(slot, 0) + group.points
    for question in pool.questions:
        exported = sum(p.points for p in question.template.parts if p.type != "symbolic")
        assert abs(by_question[question.slot] - exported * question.points / question.template.points) < 1e-9


def test_numerical_ranges_and_choices_round_trip():
    files, found = package()
    root = etree.fromstring(files[f"{IDENT}/{IDENT}.xml"])
    items = {i.get("ident"): i for i in root.iter(f"{Q}item")}
    numeric = choice = 0
    for group in found:
        for question in group.questions:
            item = items[question.ident]
            gap = question.gap
            if gap.kind == "numeric":
                assert _field(item, "question_type") == "numerical_question"
                conditions = [c for c in item.iter(f"{Q}respcondition") if c.find(f".//{Q}setvar") is not None]
                assert len(conditions) == len(gap.values)
                for condition, value in zip(conditions, gap.values):
                    assert float(condition.findtext(f".//{Q}varequal")) == written(value)
                    low, high = float(condition.findtext(f".//{Q}vargte")), float(condition.findtext(f".//{Q}varlte"))
                    assert low == written(value - gap.tolerance) and high == written(value + gap.tolerance)
                    assert condition.findtext(f".//{Q}setvar") == "100"
                numeric += 1
            else:
                assert _field(item, "question_type") == "multiple_choice_question"
                labels = item.findall(f".//{Q}response_label")
                assert [lab.findtext(f".//{Q}mattext") for lab in labels] == list(gap.choices)
                right = [c for c in item.iter(f"{Q}respcondition") if c.find(f".//{Q}setvar") is not None]
                assert [c.findtext(f".//{Q}varequal") for c in right] == [question.choice_ids[gap.correct]]
                feedback = {f.get("ident"): f.findtext(f".//{Q}mattext") for f in item.findall(f"{Q}itemfeedback")}
                for wrong in gap.wrong:
                    assert feedback[question.choice_ids[wrong.value] + "_fb"] == str(wrong.message)
                choice += 1
            assert _field(item, "points_possible") == _n(group.points)
            assert "Worked solution" in {f.get("ident"): f.findtext(f".//{Q}mattext")
                                         for f in item.findall(f"{Q}itemfeedback")}["general_fb"]
    assert numeric and choice


def test_every_image_a_question_shows_is_in_the_zip():
    files, _ = package()
    text = files[f"{IDENT}/{IDENT}.xml"].decode("utf-8")
    for src in re.findall(r'src=&#34;([^&]+)&#34;|src="([^"]+)"', text):
        path = unquote((src[0] or src[1])).replace("$IMS-CC-FILEBASE$/", "")
        assert path in files, path


def _n(value):
    from exgen.export.filters import number

    return number(value)


def test_math_is_latex_canvas_finds_and_display_lines_come_with_inline_math():
    """Canvas loads MathJax for text holding \\( or $$, not \\[ alone: display lines go as
    \\(\\displaystyle ...\\), so every text with math holds \\( (a key with no givens too), and every
    delimiter is closed."""
    files, found = package()
    document = etree.fromstring(files[f"{IDENT}/{IDENT}.xml"])
    texts = [m.text or "" for m in document.iter(f"{Q}mattext")]
    with_math = [t for t in texts if "\\(" in t or "\\[" in t]
    assert len(with_math) > 100
    assert not any("\\[" in t for t in texts) and any("\\(\\displaystyle" in t for t in texts)
    assert all(t.count("\\(") == t.count("\\)") and t.count("\\[") == t.count("\\]") for t in texts)
    for group in found:
        for question in group.questions:
            assert "\\(" in str(question.solution)
