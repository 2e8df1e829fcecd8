"""The IMS QTI 2.1 package for every template: every item and the test valid against imsqti_v2p1.xsd
(vendored, read with no network, MathML 2 included), the manifest checked for the structure of IMS CP
1.1 and for files that exist, every value and tolerance as the pool has them, and every formula of the
statement, asks and worked solution set as MathML."""
import io
import zipfile
from functools import lru_cache
from pathlib import PurePosixPath

from lxml import etree

from exgen.export.html import MATHML_XHTML
from exgen.render.unicode_math import latex_to_unicode, split_math
from exgen.export.pool import make_item
from exgen.export.qti import IMAGES, gap_refs, qti_files

from export_helpers import every_template_pool, qti_schema, written

QTI = "{http://www.imsglobal.org/xsd/imsqti_v2p1}"
CP = "{http://www.imsglobal.org/xsd/imscp_v1p1}"
MATHML = "{http://www.w3.org/1998/Math/MathML}"


@lru_cache(maxsize=1)
def package():
    pool = every_template_pool()
    files = qti_files(pool)
    items = [make_item(q, i, v, MATHML_XHTML, IMAGES) for q in pool.questions for i, v in enumerate(q.variants, 1)]
    return files, {item.ident: item for item in items if item.gaps}


def test_every_item_and_the_test_are_valid_qti_2_1():
    files, items = package()
    schema = qti_schema()
    xml = [name for name in files if name.endswith(".xml") and name != "imsmanifest.xml"]
    assert len(xml) == len(items) + 1
    for name in xml:
        document = etree.fromstring(files[name])
        assert schema.validate(document), f"{name}: {schema.error_log.last_error}"


def test_the_schema_rejects_what_is_not_qti():
    files, _ = package()
    name = next(n for n in files if n.startswith("items/") and n.endswith(".xml"))
    broken = files[name].replace(b'toleranceMode="absolute"', b'toleranceMode="roughly"', 1)
    assert not qti_schema().validate(etree.fromstring(broken))


def test_the_manifest_lists_the_test_and_every_item_with_files_that_exist():
    files, items = package()
    manifest = etree.fromstring(files["imsmanifest.xml"])
    assert manifest.tag == f"{CP}manifest" and manifest.get("identifier")
    assert manifest.findtext(f"{CP}metadata/{CP}schema") == "QTIv2.1 Package"
    assert manifest.find(f"{CP}organizations") is not None
    resources = manifest.findall(f"{CP}resources/{CP}resource")
    identifiers = [r.get("identifier") for r in resources]
    assert len(identifiers) == len(set(identifiers))
    kinds = [r.get("type") for r in resources]
    assert kinds.count("imsqti_test_xmlv2p1") == 1 and kinds.count("imsqti_item_xmlv2p1") == len(items)
    listed = set()
    for resource in resources:
        hrefs = [f.get("href") for f in resource.findall(f"{CP}file")]
        assert resource.get("href") in hrefs
        for href in hrefs:
            assert href in files, href
            listed.add(href)
        for dependency in resource.findall(f"{CP}dependency"):
            assert dependency.get("identifierref") in identifiers
    assert listed == set(files) - {"imsmanifest.xml"}  # nothing in the zip the manifest does not name


def test_the_test_draws_one_variant_per_question_from_items_in_the_package():
    files, items = package()
    test = etree.fromstring(files["test.xml"])
    sections = test.findall(f".//{QTI}assessmentSection")
    assert len(sections) == len({item.question.number for item in items.values()})
    for section in sections:
        assert section.find(f"{QTI}selection").get("select") == "1"
        for ref in section.findall(f"{QTI}assessmentItemRef"):
            assert ref.get("href") in files and ref.get("identifier") in items


def test_values_tolerances_points_and_feedback_round_trip():
    files, items = package()
    for ident, item in items.items():
        document = etree.fromstring(files[f"items/{ident}.xml"])
        declared = {d.get("identifier"): d for d in document.findall(f"{QTI}responseDeclaration")}
        assert float(document.find(f"{QTI}outcomeDeclaration[@identifier='MAXSCORE']").findtext(f".//{QTI}value")) \
            == item.points
        conditions = document.findall(f"{QTI}responseProcessing/{QTI}responseCondition")
        for ref, condition in zip(gap_refs(item), conditions):
            value = declared[ref.rid].findtext(f"{QTI}correctResponse/{QTI}value")
            branches = condition.findall(f"{QTI}responseElseIf")
            added = float(branches[0].find(f".//{QTI}sum/{QTI}baseValue").text)
            assert added == ref.points
            if ref.gap.kind == "numeric":
                assert float(value) == written(ref.gap.value)
                right = branches[0].findall(f"{QTI}or/{QTI}equal")
                assert [float(e.findtext(f"{QTI}baseValue")) for e in right] == [written(v) for v in ref.gap.values]
                assert {e.get("tolerance") for e in right} == {f"{_n(ref.gap.tolerance)} {_n(ref.gap.tolerance)}"}
                named = [float(b.findtext(f"{QTI}equal/{QTI}baseValue")) for b in branches[1:]]
                assert named == [written(w.value) for w in ref.gap.wrong]
            else:
                assert value == ref.choice_ids[ref.gap.correct]
        feedback = {f.get("identifier"): f for f in document.findall(f"{QTI}modalFeedback")}
        assert "SOLUTION" in feedback
        for ref in gap_refs(item):
            for wrong in ref.wrong:
                assert "".join(feedback[wrong.fid].itertext()) == wrong.wrong.message.unescape()
        for img in document.iter(f"{QTI}img"):
            assert str(PurePosixPath("items") / img.get("src")) in files


def _math_spans(text: str) -> list[str]:
    return [chunk for is_math, chunk in split_math(text) if is_math]


def _text_outside_math(element) -> str:
    """The element's text with every <math> left out (its tail kept)."""
    out = [element.text or ""] if element.tag != f"{MATHML}math" else []
    for child in element:
        out.append(_text_outside_math(child))
        out.append(child.tail or "")
    return "".join(out)


def test_formulas_are_mathml_in_the_namespace_the_schema_checks():
    files, items = package()
    checked = 0
    for ident, item in items.items():
        document = etree.fromstring(files[f"items/{ident}.xml"])
        body = document.find(f"{QTI}itemBody")
        statement = body.find(f"{QTI}div")
        spans = _math_spans(item.variant.statement)
        formulas = statement.findall(f".//{MATHML}math")
        # each $...$ of the statement is one <math>, whose alternative text is that formula
        assert [m.get("alttext") for m in formulas] == [latex_to_unicode(s) for s in spans], ident
        asks = [p for p in body.findall(f"{QTI}p") if (p.text or "").startswith("(")]
        for part, ask in zip(item.exported_parts, asks):
            assert len(ask.findall(f".//{MATHML}math")) == len(_math_spans(item.variant.asks[part.id])), ident
        solution = document.find(f"{QTI}modalFeedback[@identifier='SOLUTION']")
        display = [m for m in solution.iter(f"{MATHML}math") if m.get("display") == "block"]
        assert display, f"{ident}: the worked solution has no display formula"
        for element in (body, solution):
            text = _text_outside_math(element)
            assert "\\" not in text and "$" not in text, f"{ident}: LaTeX outside MathML: {text[:200]}"
        assert not document.findall(f".//{QTI}math") and not document.findall(".//math")
        checked += len(formulas) + len(display)
    assert checked > 1000


def test_math_that_is_not_mathml_2_is_rejected():
    files, _ = package()
    name = next(n for n in files if n.startswith("items/") and b'display="block"' in files[n])
    assert qti_schema().validate(etree.fromstring(files[name]))
    for broken in (files[name].replace(b'display="block"', b'display="wide"', 1),
                   files[name].replace(b"<mrow>", b"<mrow><mfoo/>", 1),
                   files[name].replace(b'xmlns="http://www.w3.org/1998/Math/MathML"', b"", 1)):
        assert not qti_schema().validate(etree.fromstring(broken))


def test_the_package_is_a_zip_with_the_manifest_at_its_root(tmp_path):
    from exgen.export.qti import write_qti

    path = write_qti(every_template_pool(), tmp_path / "pool.zip")
    with zipfile.ZipFile(io.BytesIO(path.read_bytes())) as archive:
        assert "imsmanifest.xml" in archive.namelist()
        assert archive.testzip() is None


def _n(value):
    from exgen.export.filters import number

    return number(value)
