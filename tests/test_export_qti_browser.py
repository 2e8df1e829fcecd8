"""A QTI 2.1 item's formulas as a browser lays them out: the item body and worked solution, with QTI's
XHTML-named elements put in the XHTML namespace as a delivery engine does and everything else kept as
written, loaded as XHTML (namespaces count there) in headless Chromium. Every <math> must be a MathML
element the browser knows, and a fraction must stand over its denominator.

Skipped, saying why, only where no Chromium is installed (.ci/run installs it). With EXGEN_SCREENSHOTS
set to a folder, the screenshot docs/lms.md shows is written there.
"""
from pathlib import Path

import pytest
from lxml import etree

from exgen.export.qti import qti_files

from chromium import CHROMIUM, SHOTS, needs_chromium
from export_helpers import SECRET

playwright_api = pytest.importorskip("playwright.sync_api", reason="Playwright is not installed")
pytestmark = needs_chromium

QTI = "http://www.imsglobal.org/xsd/imsqti_v2p1"
XHTML = "http://www.w3.org/1999/xhtml"
STYLE = """body { font: 16px/1.5 "DejaVu Sans", sans-serif; max-width: 46em; margin: 1.5em auto; }
math { font-family: "DejaVu Math TeX Gyre", math; } textEntryInteraction { display: inline-block;
width: 8em; height: 1.4em; border: 1px solid #888; vertical-align: middle; } table { border-collapse: collapse; }
td, th { padding: 0.1em 0.6em; } .exgen-solution { border-top: 2px solid #ccc; margin-top: 1.5em; }"""


def _as_xhtml(item_xml: bytes) -> bytes:
    """The item body and the worked solution as one XHTML page."""
    item = etree.fromstring(item_xml)
    for element in item.iter(f"{{{QTI}}}*"):
        element.tag = f"{{{XHTML}}}{etree.QName(element).localname}"
    html = etree.Element(f"{{{XHTML}}}html", nsmap={None: XHTML})
    head = etree.SubElement(html, f"{{{XHTML}}}head")
    etree.SubElement(head, f"{{{XHTML}}}style").text = STYLE
    body = etree.SubElement(html, f"{{{XHTML}}}body")
    body.extend(list(item.find(f"{{{XHTML}}}itemBody")))
    body.extend(list(item.find(f"{{{XHTML}}}modalFeedback[@identifier='SOLUTION']")))
    return etree.tostring(html, xml_declaration=True, encoding="utf-8")


def test_an_items_formulas_are_laid_out_as_mathml(tmp_path):
    from exgen.export.pool import build_pool
    from exgen.load.bank import load_bank

    template = load_bank().get("belts.flat_belt_power")
    files = qti_files(build_pool("Belts", "pool", [("q1", template, template.points)], SECRET, 1))
    name = next(n for n in files if n.startswith("items/") and n.endswith(".xml"))
    page_path = tmp_path / "items" / "item.xhtml"
    page_path.parent.mkdir()
    page_path.write_bytes(_as_xhtml(files[name]))
    for path, data in files.items():
        if path.startswith("items/images/"):
            (tmp_path / path).parent.mkdir(parents=True, exist_ok=True)
            (tmp_path / path).write_bytes(data)
    with playwright_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM)
        try:
            page = browser.new_page(viewport={"width": 900, "height": 1200})
            page.goto(page_path.as_uri())
            found = page.evaluate("""() => {
                const all = [...document.getElementsByTagNameNS('http://www.w3.org/1998/Math/MathML', 'math')];
                const fractions = [...document.getElementsByTagNameNS('http://www.w3.org/1998/Math/MathML', 'mfrac')];
                const stacked = fractions.filter(f => f.children.length === 2 &&
                    f.children[0].getBoundingClientRect().bottom <= f.children[1].getBoundingClientRect().top + 1);
                return {math: all.length, known: all.filter(m => m instanceof MathMLElement).length,
                        fractions: fractions.length, stacked: stacked.length,
                        blocks: all.filter(m => getComputedStyle(m).display.startsWith('block')).length};
            }""")
            assert found["math"] > 10 and found["known"] == found["math"]
            assert found["fractions"] > 0 and found["stacked"] == found["fractions"]
            assert found["blocks"] > 0  # worked lines are display math
            if SHOTS:
                top = page.evaluate("document.querySelector('.exgen-solution').getBoundingClientRect().top")
                page.screenshot(path=str(Path(SHOTS) / "qti-item-mathml.png"), full_page=True,
                                clip={"x": 60, "y": top + 250, "width": 780, "height": 560})
        finally:
            browser.close()
