"""The practice app in a real headless Chromium (Debian's, driven by Playwright): a student practises
with the mouse and with the keyboard alone, on a desktop and a phone-width screen; math is MathML the
browser lays out; nothing is fetched from anywhere but the app.

Skipped, saying why, only where no Chromium is installed (.ci/run installs it). With EXGEN_SCREENSHOTS
set to a folder, the screenshots docs/practice.md shows are written there.
"""
from pathlib import Path

import pytest

from chromium import CHROMIUM, SHOTS, needs_chromium
from exgen.answertypes import answer_type
from exgen.load.bank import load_bank
from practice.session import Practice
from practice.store import Store
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
    # the new problem's first box has the focus: after "Another one" it took six Tabs to reach (a)
    wait_focus(page, f"answer-{key(server, page).template.parts[0].id}")
    page.keyboard.type("1")
    assert page.evaluate("document.activeElement.value") == "1"


SCROLLERS = ".figure, .math-line, .table-wrap, .chart-figure, .hint"


def sideways(page) -> list[dict]:
    """Every box that can scroll sideways: how far, and how much of each edge fades (the sign it scrolls)."""
    return page.evaluate("""(selector) => [...document.querySelectorAll(selector)].map(e => {
        const style = getComputedStyle(e);
        return {what: e.className + ' ' + (e.id || ''), over: e.scrollWidth - e.clientWidth,
                left: parseFloat(style.getPropertyValue('--more-left')) || 0,
                right: parseFloat(style.getPropertyValue('--more-right')) || 0, mask: style.maskImage};
    })""", SCROLLERS)


def scroll_all(page, where: str) -> None:
    page.evaluate("""([selector, where]) => document.querySelectorAll(selector).forEach(
        e => e.scrollLeft = where === 'end' ? e.scrollWidth : 0)""", [SCROLLERS, where])
    page.wait_for_timeout(150)  # the scroll timeline updates at the next frames


def small_text(page) -> list[str]:
    """Text drawn smaller than 0.8 of the body's: HTML text by its computed size, an SVG's labels by their size
    times the figure's scale on screen. Subscripts, superscripts and math are not labels."""
    return page.evaluate("""() => {
        const body = parseFloat(getComputedStyle(document.body).fontSize), out = [];
        const walker = document.createTreeWalker(document.querySelector('main'), NodeFilter.SHOW_TEXT);
        for (let node = walker.nextNode(); node; node = walker.nextNode()) {
            const e = node.parentElement;
            if (!node.textContent.trim() || e.closest('math, sub, sup, tspan, title, desc, .skip')) continue;
            let size = parseFloat(getComputedStyle(e).fontSize);
            const svg = e.closest('svg');
            if (svg) size *= svg.getScreenCTM().a;
            const box = e.getBoundingClientRect();
            if (box.width === 0 && box.height === 0) continue;  // not shown (a closed <details>)
            if (size < 0.8 * body - 0.01) out.push(`${node.textContent.trim().slice(0, 30)}: ${size.toFixed(1)}px`);
        }
        return out;
    }""")


@pytest.mark.parametrize("width", [390, 1280])
def test_at_phone_and_desktop_width_labels_read_and_what_scrolls_shows_it(browser, server, width):
    """At 390 px worked lines and the progress table were cut with no sign that they scroll, and chart and
    figure labels shrank to about 6 px."""
    url, _ = server
    context = browser.new_context(viewport={"width": width, "height": 800}, is_mobile=width < 500, has_touch=width < 500)
    page = context.new_page()
    page.goto(url + "/")
    page.get_by_role("button", name="Practise Balancing").click()
    page.wait_for_url("**/problem/*")
    problem = key(server, page)
    for part in problem.template.parts:
        page.locator(f"#part-{part.id}").get_by_role("button", name=f"Hint for ({part.id})").click()
        page.locator(f"#hints-{part.id} .hint").first.wait_for()
    page.get_by_role("button", name="Show the worked solution").click()
    page.locator("#solution-heading").wait_for()
    page.evaluate("document.fonts.ready.then(() => true)")
    for where in ("/problem", "/progress"):
        if where == "/progress":
            page.goto(url + "/progress")
        width_now = page.evaluate("document.documentElement.scrollWidth")
        assert width_now <= width + 1, f"the page is {width_now}px wide on a {width}px screen"
        boxes = sideways(page)
        assert page.locator("figure svg").count() >= 1
        for box in boxes:
            if box["over"] > 1:   # it scrolls: at the start its right edge fades, the left does not
                assert box["right"] > 0 and box["left"] == 0 and box["mask"] != "none", box
            else:
                assert box["right"] == box["left"] == 0, box
        scroll_all(page, "end")
        for box in sideways(page):
            if box["over"] > 1:   # at the end, the other way round
                assert box["left"] > 0 and box["right"] == 0, box
        if width < 500 and where == "/problem":
            assert any(b["over"] > 1 for b in boxes), "nothing scrolls on a phone: the test shows nothing"
        assert small_text(page) == []
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
