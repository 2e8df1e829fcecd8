"""The review page in a real headless Chromium (Debian's, driven by Playwright), as the practice pages are
tested: a lecturer decides with the mouse and with the keyboard alone (every control reached by Tab in
reading order, its focus visible, its label read), on a desktop and a phone-width screen; nothing is
fetched from anywhere but the page's own server, and no script runs, not even a student's.

Skipped, saying why, only where no Chromium is installed. With EXGEN_SCREENSHOTS set to a folder, the
screenshots docs/grading.md shows are written there: the page with a grouped answer, and a feedback page
marked by hand after `exgen grade` has applied a decision made on it.
"""
import html
from pathlib import Path

import pytest

import review_class as rc
from chromium import CHROMIUM, SHOTS, needs_chromium
from graders.decisions import load_decisions
from review_server import running_review

playwright_api = pytest.importorskip("playwright.sync_api", reason="Playwright is not installed")
pytestmark = needs_chromium


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    return rc.graded_class(tmp_path_factory.mktemp("review"))


@pytest.fixture(scope="module")
def browser():
    with playwright_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM)
        yield browser
        browser.close()


@pytest.fixture
def decisions(tmp_path):
    return tmp_path / "decisions.yaml"


@pytest.fixture
def server(graded, decisions):
    with running_review(graded.graded, "--decisions", str(decisions), "--reviewer", "A. Lecturer") as url:
        yield url


def open_page(browser, server, width=1000, **options):
    context = browser.new_context(viewport={"width": width, "height": 900}, **options)
    page = context.new_page()
    outside = []
    page.on("request", lambda r: None if r.url.startswith((server, "data:")) else outside.append(r.url))
    page.on("dialog", lambda d: outside.append(f"dialog: {d.message}") or d.dismiss())
    return context, page, outside


@pytest.fixture
def page(browser, server):
    context, page, outside = open_page(browser, server)
    yield page
    context.close()
    assert outside == [], f"requests outside the page's server, or a script ran: {outside}"


def shot(target, name, tmp_path):
    target.screenshot(path=str(tmp_path / name))
    if SHOTS:
        Path(SHOTS).mkdir(parents=True, exist_ok=True)
        target.screenshot(path=str(Path(SHOTS) / name))


FOCUSED = """() => {
    const e = document.activeElement;
    if (!e || e === document.body) return null;
    const style = getComputedStyle(e), box = e.getBoundingClientRect();
    return {tag: e.tagName, id: e.id, type: e.type || '', value: e.value || '', name: e.name || '',
            text: (e.innerText || '').trim().slice(0, 60), top: box.top + window.scrollY,
            outline: style.outlineStyle !== 'none' ? parseFloat(style.outlineWidth) : 0,
            labelled: e.labels ? e.labels.length > 0 : true};
}"""


def test_a_lecturer_accepts_a_spelling_for_everyone_with_the_mouse(browser, graded, tmp_path):
    """Run as a lecturer runs it, in the course folder with the graded folder's own decisions file."""
    decisions = graded.decisions
    with running_review(graded.graded.relative_to(graded.root), "--reviewer", "A. Lecturer", cwd=graded.root) as url:
        context, page, outside = open_page(browser, url)
        try:
            accept_a_spelling(page, url, decisions, tmp_path)
        finally:
            context.close()
            decisions.unlink(missing_ok=True)
    assert outside == [], f"requests outside the page's server, or a script ran: {outside}"


def accept_a_spelling(page, server, decisions, tmp_path):
    page.goto(server + "/?question=2&part=b")
    group = page.locator("article", has=page.locator("h3", has_text=f"“{rc.SPELLING}”"))
    assert page.locator("article").count() == 1  # the filter leaves that part's alone
    assert group.count() == 1 and f"{len(rc.SPELLERS)} students" in group.locator("h3").inner_text()
    for student in rc.SPELLERS:
        assert group.get_by_text(student, exact=False).first.is_visible()
    assert page.locator("main script").count() == 0 and page.locator("img[src=x]").count() == 0
    page.set_viewport_size({"width": 900, "height": 900})
    shot(page.locator("main"), "review-grouped-answer.png", tmp_path)
    group.get_by_label("Accept this spelling for everyone").check()
    group.get_by_label("The spelling means").select_option("raises the bow")
    group.get_by_label("Reason").fill("the sheet's wording invites the short form")
    group.get_by_role("button", name="Save the decision").click()
    page.wait_for_url("**saved=*")
    notice = page.locator("#saved")
    assert notice.is_visible() and "exgen grade" in notice.inner_text()
    assert f"“{rc.SPELLING}” is read as “raises the bow”" in notice.inner_text()
    aliases = load_decisions(decisions).aliases
    assert [(a.spelling, a.means, a.reviewer) for a in aliases] == [(rc.SPELLING, "raises the bow", "A. Lecturer")]
    assert page.locator("article", has=page.locator("h3", has_text=f"“{rc.SPELLING}”")).count() == 0  # decided
    page.get_by_role("link", name="show them").click()
    assert page.locator("article.decided", has=page.locator("h3", has_text=f"“{rc.SPELLING}”")).count() == 1


def test_the_same_with_the_keyboard_alone_every_control_in_order_its_focus_visible(page, server, decisions):
    page.goto(server + "/?question=1&part=a")
    seen = []

    def tab_to(predicate, limit=80):
        for _ in range(limit):
            page.keyboard.press("Tab")
            focused = page.evaluate(FOCUSED)
            assert focused is not None, "Tab left the page"
            seen.append(focused)
            if predicate(focused):
                return focused
        raise AssertionError(f"not reached with Tab; reached {[f['id'] or f['text'] for f in seen]}")

    wordy = page.locator("article", has=page.locator("h3", has_text=f"“{rc.UNIT_WORD}”"))
    group_id = wordy.get_attribute("id").removeprefix("g-")
    tab_to(lambda f: f["type"] == "radio" and f["value"] == "accept" and f["id"] == "" and f["name"] == "decision"
           and page.evaluate("document.activeElement.closest('article').id") == f"g-{group_id}")
    page.keyboard.press("Space")
    tab_to(lambda f: f["id"] == f"points-{group_id}")
    page.keyboard.type("0.5")
    tab_to(lambda f: f["id"] == f"comment-{group_id}")
    page.keyboard.type("the number is right; the direction is not a unit")
    reviewer = tab_to(lambda f: f["id"] == f"reviewer-{group_id}")
    assert reviewer["value"] == "A. Lecturer"  # signed as the server was started
    tab_to(lambda f: f["id"] == f"reason-{group_id}")
    page.keyboard.type("right value, wrong form")
    page.keyboard.press("Enter")
    page.wait_for_url("**saved=*")
    assert page.locator("#saved").is_visible()
    (decision,) = load_decisions(decisions).decisions
    assert (decision.student, decision.answer, decision.points, decision.decision) == (rc.WORDY, rc.UNIT_WORD, 0.5,
                                                                                       "accept")
    assert all(f["outline"] >= 2 for f in seen), [f for f in seen if f["outline"] < 2]
    assert all(f["labelled"] for f in seen if f["tag"] in ("INPUT", "SELECT")), seen
    controls = [f for f in seen if f["tag"] != "A"]
    assert [f["top"] for f in controls] == sorted(f["top"] for f in controls)  # Tab follows the page down


def test_a_decision_the_server_cannot_use_comes_back_with_the_focus_on_the_field_at_fault(page, server, decisions):
    page.goto(server + "/")
    blank = page.locator("article", has=page.locator("h3", has_text="(blank)"))
    group_id = blank.get_attribute("id").removeprefix("g-")
    blank.get_by_label("Reject", exact=True).check()
    blank.get_by_label("Reason").fill("nothing to mark")
    blank.get_by_role("button", name="Save the decision").click()
    page.locator(f"#error-{group_id}").wait_for()
    assert "needs a comment" in page.locator(f"#error-{group_id}").inner_text()
    assert page.evaluate("document.activeElement.id") == f"comment-{group_id}"
    assert page.locator(f"#reason-{group_id}").input_value() == "nothing to mark"  # nothing typed is lost
    page.keyboard.type("no working shown")
    page.keyboard.press("Enter")
    page.wait_for_url("**saved=*")
    assert [d.comment for d in load_decisions(decisions).decisions] == ["no working shown"]


@pytest.mark.parametrize("width", [390, 1280])
def test_at_phone_and_desktop_width_nothing_is_cut_and_every_control_is_labelled(browser, server, width):
    context, page, outside = open_page(browser, server, width, is_mobile=width < 500, has_touch=width < 500)
    page.goto(server + "/?show=all")
    assert page.evaluate("document.documentElement.scrollWidth") <= width + 1
    unlabelled = page.evaluate("""() => [...document.querySelectorAll('input:not([type=hidden]), select')]
        .filter(e => !e.labels || e.labels.length === 0).map(e => e.name)""")
    assert unlabelled == []
    small = page.evaluate("""() => {
        const body = parseFloat(getComputedStyle(document.body).fontSize), out = [];
        for (const e of document.querySelectorAll('main *')) {
            if (!e.childNodes.length || ![...e.childNodes].some(n => n.nodeType === 3 && n.textContent.trim())) continue;
            if (parseFloat(getComputedStyle(e).fontSize) < 0.8 * body - 0.01) out.push(e.textContent.trim().slice(0, 30));
        }
        return out; }""")
    assert small == []
    buttons = page.evaluate("() => [...document.querySelectorAll('button')].map(b => b.getBoundingClientRect().height)")
    assert buttons and min(buttons) >= 40  # a finger can press them
    context.close()
    assert outside == []


def test_a_feedback_page_marked_by_hand_after_grading_again(browser, tmp_path):
    """The page's decision, applied by `exgen grade`, on the feedback the student gets (feedback/<id>.md)."""
    graded = rc.graded_class(tmp_path / "class")
    with running_review(graded.graded, "--reviewer", "A. Lecturer") as url:
        context, page, outside = open_page(browser, url)
        page.goto(url + "/")
        wordy = page.locator("article", has=page.locator("h3", has_text=f"“{rc.UNIT_WORD}”"))
        wordy.get_by_label("Accept", exact=True).check()
        wordy.get_by_label("Points, if accepted").fill("0.5")
        wordy.get_by_label("Comment for the student's feedback").fill("the number is right; the direction is not a unit")
        wordy.get_by_label("Reason").fill("right value, wrong form")
        wordy.get_by_role("button", name="Save the decision").click()
        page.wait_for_url("**saved=*")
        assert graded.grade() == 0
        page.goto(url + "/?show=all")
        assert "applied: now 0.5 / 1 (was 0)" in page.locator(f"#{wordy.get_attribute('id')}").inner_text()
        context.close()
    feedback = (graded.graded / "feedback" / f"{rc.WORDY}.md").read_text(encoding="utf-8")
    assert "Marked by hand: the number is right; the direction is not a unit." in feedback
    first = feedback.split("\n## Q2.", 1)[0]  # the student's page as they get it: Markdown text, the first question
    context = browser.new_context(viewport={"width": 900, "height": 600})
    page = context.new_page()
    page.set_content(f'<pre style="white-space: pre-wrap; font: 15px/1.5 monospace; margin: 0; padding: 16px; '
                     f'width: 900px; background: #fff">{html.escape(first)}</pre>')
    assert page.locator("pre").inner_text().count("Marked by hand") == 1
    shot(page.locator("pre"), "feedback-marked-by-hand.png", tmp_path)
    context.close()
