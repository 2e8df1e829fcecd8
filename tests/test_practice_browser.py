"""The practice app in a real headless Chromium (Debian's, driven by Playwright): a student practises
with the mouse and with the keyboard alone, on a desktop and a phone-width screen; math is MathML the
browser lays out; nothing is fetched from anywhere but the app.

Skipped, saying why, only where no Chromium is installed (.ci/run installs it). With EXGEN_SCREENSHOTS
set to a folder, the screenshots docs/practice.md shows are written there.
"""
from pathlib import Path

import pytest

from exgen.answertypes import answer_type
from exgen.bank import load_bank
from practice.session import Practice
from practice.store import Store
from chromium import CHROMIUM, SHOTS, needs_chromium
from practice_server import running_server

playwright_api = pytest.importorskip("playwright.sync_api", reason="Playwright is not installed")
pytestmark = needs_chromium


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    db = tmp_path_factory.mktemp("practice") / "progress.sqlite3"
    with running_server(db) as url:
        yield url, db


@pytest.fixture(scope="module")
def browser():
    with playwright_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM)
        yield browser
        browser.close()


@pytest.fixture
def page(browser, server):
    context = browser.new_context(viewport={"width": 1000, "height": 900})
    page = context.new_page()
    outside = []
    page.on("request", lambda r: None if r.url.startswith((server[0], "data:")) else outside.append(r.url))
    page.on("dialog", lambda d: outside.append(f"dialog: {d.message}") or d.dismiss())
    yield page
    context.close()
    assert outside == [], f"requests outside the app, or a script ran: {outside}"


def key(server, page):
    """The problem the page shows, as the server built it (the test reads the key; the student cannot)."""
    problem_id = int(page.url.rstrip("/").split("#")[0].rsplit("/", 1)[1])
    return Practice(load_bank(), Store(server[1])).problem(problem_id)


def answer(problem, part_id, value=None) -> str:
    part = problem.template.part(part_id)
    return answer_type(part).text(problem.variant.answers[part_id].value if value is None else value, part)


def shot(page, name, tmp_path, full=True):
    page.screenshot(path=str(tmp_path / name), full_page=full)
    if SHOTS:
        Path(SHOTS).mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(Path(SHOTS) / name), full_page=full)


def wait_focus(page, element_id: str, seconds: float = 10.0) -> None:
    """Polled from here: a predicate run in the page would be eval, which the app's CSP forbids."""
    for _ in range(int(seconds / 0.05)):
        if page.evaluate("document.activeElement && document.activeElement.id") == element_id:
            return
        page.wait_for_timeout(50)
    raise AssertionError(f"focus never reached #{element_id}")


def mathml_renders(page, selector) -> dict:
    return page.evaluate("""(selector) => {
        const root = document.querySelector(selector);
        const maths = root.querySelectorAll('math');
        const frac = root.querySelector('mfrac');
        const [top, bottom] = frac ? [...frac.children].map(e => e.getBoundingClientRect()) : [null, null];
        return {count: maths.length, mathml: maths.length > 0 && maths[0] instanceof MathMLElement,
                stacked: frac ? top.bottom <= bottom.top + 1 : false,
                raw: /\\\\(frac|text|mathrm|sqrt|omega)/.test(root.textContent)};
    }""", selector)


def practise_elsewhere(db):
    """Some progress in other topics, for a map worth a screenshot: right, half right, wrong."""
    from practice.scope import Scope

    practice = Practice(load_bank(), Store(db))
    for topic, right in (("gears", 1.0), ("gears", 1.0), ("gears", 1.0), ("gears", 1.0), ("gears", 1.0),
                         ("balancing", 0.5), ("balancing", 1.0), ("vibration", 0.0), ("flywheels", 1.0)):
        problem = practice.next_problem(Scope("topic", topic))
        parts = problem.template.parts
        for i, part in enumerate(parts):
            good = i < round(right * len(parts))
            practice.check(problem, part.id, problem.variant.answers[part.id].text if good else "1e9")


def test_a_student_practises_a_topic_with_the_mouse(page, server, tmp_path):
    url, _ = server
    page.goto(url + "/")
    assert page.locator("h2", has_text="Chapter 4: Governors").is_visible()
    page.get_by_role("button", name="Practise Belts").click()
    page.wait_for_url("**/problem/*")
    problem = key(server, page)
    if problem.template.id != "belts.compound_drive":  # a problem whose (b) has a named slip and a figure
        page.goto(url + "/")
        page.locator("summary", has_text="problem types").first.click()
        page.get_by_role("button", name="Speed of a countershaft driven through a compound belt drive").click()
        page.wait_for_url("**/problem/*")
        problem = key(server, page)
    assert page.locator("figure svg").count() == 1 and page.get_by_label("(a)").is_visible()
    page.evaluate("window.notReloaded = true")

    page.get_by_label("(a)").fill(answer(problem, "a"))
    page.locator("#part-a").get_by_role("button", name="Check").click()
    page.locator("#feedback-a .verdict-correct").wait_for()
    slip = problem.variant.mistakes["b"]["slip_once"]
    page.get_by_label("(b)").fill(answer(problem, "b", slip))
    page.locator("#part-b").get_by_role("button", name="Check").click()
    page.locator("#feedback-b .verdict-wrong").wait_for()
    assert "Each of the two drives slips" in page.locator("#feedback-b").inner_text()
    assert page.evaluate("window.notReloaded === true")  # checked without a page load

    page.get_by_role("button", name="Hint for (b)").click()
    page.locator("#hints-b .hint").first.wait_for()
    page.get_by_role("button", name="Show the worked solution").click()
    page.locator("#solution-heading").wait_for()
    rendered = mathml_renders(page, "#solution")
    assert rendered["count"] > 5 and rendered["mathml"] and rendered["stacked"] and not rendered["raw"]
    assert page.evaluate("window.notReloaded === true")
    shot(page, "practice-problem.png", tmp_path)

    first = page.url
    page.get_by_role("button", name="Another one").click()
    page.wait_for_url(lambda u: u != first and "/problem/" in u)
    if SHOTS:
        practise_elsewhere(server[1])
    page.goto(url + "/")
    belts = page.locator("li.topic", has=page.locator(".topic-name", has_text="Belts"))
    assert "not started" not in belts.locator(".level").first.inner_text()
    shot(page, "practice-map.png", tmp_path)
    page.goto(url + "/progress")
    assert page.locator("svg.chart rect").count() > 7 and "Belts" in page.locator("table.progress").inner_text()


def platform_fonts(page, selector) -> list[dict]:
    """The fonts Chromium drew a node's text with (DevTools' CSS.getPlatformFontsForNode)."""
    cdp = page.context.new_cdp_session(page)
    cdp.send("DOM.enable")
    cdp.send("CSS.enable")
    root = cdp.send("DOM.getDocument", {"depth": -1})["root"]["nodeId"]
    node = cdp.send("DOM.querySelector", {"nodeId": root, "selector": selector})["nodeId"]
    assert node, f"nothing matches {selector}"
    return cdp.send("CSS.getPlatformFontsForNode", {"nodeId": node})["fonts"]


def test_figures_and_problem_text_are_set_in_the_sheets_font(page, server):
    """New Computer Modern from the app's own files: the figure's labels (placed by that font's metrics),
    the statement and the formulas, as in the PDFs; never a fallback serif."""
    url, _ = server
    page.goto(url + "/")
    page.locator("summary", has_text="problem types").first.click()
    page.get_by_role("button", name="Speed of a countershaft driven through a compound belt drive").click()
    page.wait_for_url("**/problem/*")
    page.get_by_role("button", name="Show the worked solution").click()
    page.locator("#solution-heading").wait_for()
    page.evaluate("document.fonts.ready.then(() => true)")
    for selector, face in (("figure svg text", "NewCMexgen-Regular"), (".statement", "NewCMexgen-Regular"),
                           ("#solution math mi", "NewCMexgen-Math")):
        fonts = platform_fonts(page, selector)
        assert fonts and all(f["isCustomFont"] and f["familyName"] == "NewCM exgen" for f in fonts), (selector, fonts)
        assert face in {f["postScriptName"] for f in fonts}, (selector, fonts)


def test_the_same_with_the_keyboard_alone(page, server):
    url, _ = server
    page.goto(url + "/")

    def tab_to(text, limit=200):
        for _ in range(limit):
            page.keyboard.press("Tab")
            focused = page.evaluate("""() => {
                const e = document.activeElement;
                if (!e || !['A', 'BUTTON', 'INPUT', 'SUMMARY'].includes(e.tagName)) return '';
                return e.getAttribute('aria-label') || e.innerText || e.id; }""")
            if text in focused:
                return
        raise AssertionError(f"{text!r} cannot be reached with Tab")

    tab_to("Practise Vibration")
    page.keyboard.press("Enter")
    page.wait_for_url("**/problem/*")
    problem = key(server, page)
    parts = [p.id for p in problem.template.parts]
    tab_to(f"answer-{parts[0]}")
    page.keyboard.type(answer(problem, parts[0]))
    page.keyboard.press("Enter")
    page.locator(f"#feedback-{parts[0]} .verdict-correct").wait_for()
    if len(parts) > 1:  # a right answer moves on to the next part's box
        wait_focus(page, f"answer-{parts[1]}")
        page.keyboard.type("123456 zz")
        page.keyboard.press("Enter")
        page.locator(f"#feedback-{parts[1]} .verdict").wait_for()
        tab_to(f"Hint for ({parts[1]})")
        page.keyboard.press("Enter")
        page.locator(f"#hints-{parts[1]} .hint").first.wait_for()
    tab_to("Show the worked solution")
    page.keyboard.press("Enter")
    wait_focus(page, "solution-heading")
    tab_to("Another one")
    first = page.url
    page.keyboard.press("Enter")
    page.wait_for_url(lambda u: u != first and "/problem/" in u)


def test_a_phone_width_screen_needs_no_sideways_scrolling(browser, server):
    url, _ = server
    context = browser.new_context(viewport={"width": 375, "height": 740}, is_mobile=True, has_touch=True)
    page = context.new_page()
    page.goto(url + "/")
    page.get_by_role("button", name="Practise Balancing").click()
    page.wait_for_url("**/problem/*")
    page.get_by_role("button", name="Show the worked solution").click()
    page.locator("#solution-heading").wait_for()
    width = page.evaluate("document.documentElement.scrollWidth")
    assert width <= 376, f"the page is {width}px wide on a 375px screen"
    context.close()


@pytest.mark.parametrize("typed", ["<script>alert('x')</script>", '"><img src=x onerror=alert(1)>'])
def test_a_script_typed_as_an_answer_stays_text(page, server, typed):
    url, _ = server
    page.goto(url + "/")
    page.get_by_role("button", name="Practise Gears").click()
    page.wait_for_url("**/problem/*")
    box = page.locator("input[name=answer]").first
    box.fill(typed)
    box.press("Enter")
    page.locator(".feedback .verdict").first.wait_for()
    page.reload()  # and when the page shows it again from the server
    assert page.locator("input[name=answer]").first.input_value() == typed
    assert page.locator("img[src=x]").count() == 0 and page.locator("main script").count() == 0
