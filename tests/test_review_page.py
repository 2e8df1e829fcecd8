"""The review page over HTTP: it lists exactly what needs a human in a graded class (format problems, blanks
beside answered parts, the parts signs of copying rest on), groups the same text typed by many, filters by
question and part, and writes each decision through graders.decisions to the decisions file, nothing else;
a form it cannot use is said beside its field; requests from elsewhere, for another host, with a stale
token, or a listening address another computer could reach are refused."""
import hashlib
import html
import socket

import pytest
from starlette.testclient import TestClient

import review_class as rc
from exgen.cli import main
from exgen.errors import ExgenError
from exgen.runtime.localweb import loopback_hosts
from graders.decisions import load_decisions
from graders.record import read_record
from graders.review_page.app import MAX_BODY, Review, create_app
from graders.review_page.queue import BLANK_AMONG, COPYING, FORMAT, build_queue
from graders.review_page.server import review
from review_server import running_review

HOST = "http://127.0.0.1:8001"


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    return rc.graded_class(tmp_path_factory.mktemp("review"))


@pytest.fixture
def state(graded, tmp_path):
    return Review(graded.graded, tmp_path / "decisions.yaml", reviewer="A. Lecturer")


@pytest.fixture
def client(state):
    with TestClient(create_app(state, loopback_hosts(8001)), base_url=HOST, raise_server_exceptions=False) as client:
        yield client


def token_of(page: str) -> str:
    return page.split('name="token" value="', 1)[1].split('"', 1)[0]


def group_of(state, slot: str, part: str, given: str):
    return next(g for g in state.queue().groups if (g.slot, g.part, g.given) == (slot, part, given))


def post(client, group, **fields):
    form = {"token": token_of(client.get("/").text), "group": group.id, "reviewer": "A. Lecturer",
            "reason": "the sense is clear", **fields}
    return client.post("/decide", data=form, follow_redirects=False)


def folder_hash(folder) -> str:
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


# ---- what is listed ----------------------------------------------------------------------------------

def test_exactly_what_needs_a_human_is_listed(graded, state):
    """The rule, read from results.json on its own: unreadable parts, blanks on sheets with any other part
    answered, and each part a sign of copying names for its student."""
    record = read_record(graded.graded)
    expected = set()
    for sheet in record["sheets"]:
        answered = [p for p in sheet["parts"] if p["given"].strip()]
        for p in sheet["parts"]:
            if p["status"] == "unreadable" or (p["status"] == "blank" and answered):
                expected.add((sheet["student"]["id"], p["slot"], p["part"]))
    expected |= {(p["student"], p["slot"], p["part"]) for s in record["signs"] for p in s["parts"]}
    listed = {(a.student, g.slot, g.part) for g in state.queue().groups for a in g.answers}
    assert listed == expected
    planted = ({(s, "q2", "b") for s in rc.SPELLERS} | {(rc.WORDY, "q1", "a"), (rc.BLANKER, "q1", "b"),
                                                        (rc.HOSTILE, "q1", "c")}
               | {(rc.COPIER, slot, part) for slot, part in rc.COPIED})
    assert listed == planted


def test_each_answer_stands_under_its_reason_with_its_text_key_and_the_graders_words(graded, state, client):
    queue = state.queue()
    kinds = {(a.student, g.slot, g.part): g.kind for g in queue.groups for a in g.answers}
    assert kinds[(rc.WORDY, "q1", "a")] == FORMAT and kinds[(rc.BLANKER, "q1", "b")] == BLANK_AMONG
    assert all(kinds[(rc.COPIER, slot, part)] == COPYING for slot, part in rc.COPIED)
    wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
    assert wordy.keys == (graded.keys[rc.WORDY]["q1"]["a"],) and "rpm clockwise" in wordy.message
    page = client.get("/").text
    article = page.split(f'id="g-{wordy.id}"', 1)[1].split("</article>", 1)[0]
    assert f"“{rc.UNIT_WORD}”" in article and graded.keys[rc.WORDY]["q1"]["a"] in article
    assert "Grader said" in article and "unknown unit" in article
    copied = group_of(state, "q1", "a", graded.keys[rc.SOURCE]["q1"]["a"])
    article = page.split(f'id="g-{copied.id}"', 1)[1].split("</article>", 1)[0]
    assert f"is {rc.SOURCE}'s answer" in html.unescape(article)  # the evidence, beside the answer it is about
    assert page.index("Format problem") < page.index("Blank where other parts were answered") \
        < page.index("Flagged by signs of copying")


def test_the_same_text_from_many_students_is_one_row_with_its_count_and_the_students(graded, state, client):
    spelled = [g for g in state.queue().groups if g.given == rc.SPELLING]
    assert len(spelled) == 1 and set(spelled[0].students) == set(rc.SPELLERS)
    group = spelled[0]
    assert set(group.keys) == {graded.keys[s]["q2"]["b"] for s in rc.SPELLERS}
    article = client.get("/").text.split(f'id="g-{group.id}"', 1)[1].split("</article>", 1)[0]
    assert f"{len(rc.SPELLERS)} students" in article and all(s in article for s in rc.SPELLERS)
    assert f'<option value="*">all {len(rc.SPELLERS)} students</option>' in article
    assert "Accept this spelling for everyone" in article
    for choice in ("raises the bow", "lowers the bow"):  # what it may mean: the part's own choices
        assert f'<option value="{choice}">{choice}</option>' in article


def test_only_text_that_could_not_be_read_can_be_accepted_as_a_spelling_for_everyone(state, client):
    page = client.get("/").text
    for group in state.queue().groups:
        article = page.split(f'id="g-{group.id}"', 1)[1].split("</article>", 1)[0]
        assert ('value="alias"' in article) is (group.kind == FORMAT)


@pytest.mark.parametrize("query, shown", [
    ("question=2", {("q2", "a"), ("q2", "b"), ("q2", "c"), ("q2", "d")}),
    ("question=2&part=b", {("q2", "b")}),
    ("part=a", {("q1", "a"), ("q2", "a")}),
    ("question=1&part=c", {("q1", "c")}),
    ("question=9", set()),
])
def test_filters_by_question_and_part(state, client, query, shown):
    page = client.get("/?" + query).text
    listed = {(g.slot, g.part) for g in state.queue().groups if f'id="g-{g.id}"' in page}
    assert listed == shown


def test_a_students_text_is_cleaned_and_escaped(state, client):
    page = client.get("/").text
    assert "<img src=x" not in page and "\u202e" not in page
    assert "&lt;img src=x onerror=alert(1)&gt;" in page


# ---- deciding ----------------------------------------------------------------------------------------

def test_decisions_go_through_the_decisions_module_to_the_file_and_nowhere_else(graded, state, client):
    before = (folder_hash(graded.submissions), folder_hash(graded.graded))
    spelled = group_of(state, "q2", "b", rc.SPELLING)
    response = post(client, spelled, decision="alias", means="raises the bow")
    assert response.status_code == 303 and response.headers["location"].endswith("#saved")
    wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
    assert post(client, wordy, decision="accept", points="0.5").status_code == 303
    blank = group_of(state, "q1", "b", "")
    assert post(client, blank, decision="reject", comment="no working shown").status_code == 303
    decisions = load_decisions(state.decisions_path, "review-demo", missing_ok=False)
    assert [(a.question, a.part, a.spelling, a.means, a.template) for a in decisions.aliases] == \
        [(2, "b", rc.SPELLING, "raises the bow", "gyroscopes.ship_turbine")]
    assert {(d.student, d.question, d.part, d.answer, d.decision, d.points, d.comment) for d in decisions.decisions} \
        == {(rc.WORDY, 1, "a", rc.UNIT_WORD, "accept", 0.5, ""), (rc.BLANKER, 1, "b", "", "reject", None,
                                                                  "no working shown")}
    assert all(d.reviewer == "A. Lecturer" and d.reason for d in decisions.decisions + decisions.aliases)
    assert (folder_hash(graded.submissions), folder_hash(graded.graded)) == before
    page = client.get(response.headers["location"]).text
    assert 'id="saved"' in page and "run again" in page and "exgen grade" in page


def test_a_group_decision_covers_each_student_or_the_one_chosen(state, client):
    spelled = group_of(state, "q2", "b", rc.SPELLING)
    assert post(client, spelled, decision="accept", student=rc.SPELLERS[1]).status_code == 303
    decisions = load_decisions(state.decisions_path)
    assert [d.student for d in decisions.decisions] == [rc.SPELLERS[1]]
    assert post(client, spelled, decision="reject", comment="not a choice").status_code == 303
    decisions = load_decisions(state.decisions_path)
    assert sorted(d.student for d in decisions.decisions) == sorted(rc.SPELLERS)
    assert {d.decision for d in decisions.decisions} == {"reject"}  # the earlier one replaced


def test_decided_answers_leave_the_list_and_are_shown_on_asking(state, client):
    wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
    assert post(client, wordy, decision="accept").status_code == 303
    assert f'id="g-{wordy.id}"' not in client.get("/").text
    shown = client.get("/?show=all").text
    article = shown.split(f'id="g-{wordy.id}"', 1)[1].split("</article>", 1)[0]
    assert "accepted (1 / 1) by A. Lecturer" in article and "applied when exgen grade runs again" in article


@pytest.mark.parametrize("fields, field, says", [
    ({"decision": "accept", "reviewer": ""}, "reviewer", "reviewer"),
    ({"decision": "accept", "reason": "  "}, "reason", "reason"),
    ({"decision": "reject"}, "comment", "comment"),
    ({"decision": "accept", "points": "3"}, "points", "at most 1"),
    ({"decision": "accept", "points": "abc"}, "points", "number"),
    ({"decision": "accept", "points": "0"}, "points", "more than 0"),
    ({"decision": "accept", "points": "nan"}, "points", "more than 0"),
    ({"decision": "maybe"}, "decision", "choose"),
    ({"decision": "alias", "means": ""}, "means", "means"),
    ({"decision": "alias", "means": "sideways"}, "means", "choices"),
    ({"decision": "accept", "student": "Z99999"}, "student", "students"),
])
def test_a_form_that_cannot_be_used_is_said_beside_its_field_and_nothing_is_written(state, client, fields, field,
                                                                                   says):
    group = group_of(state, "q2", "b", rc.SPELLING)
    response = post(client, group, **fields)
    assert response.status_code == 400 and not state.decisions_path.exists()
    article = response.text.split(f'id="g-{group.id}"', 1)[1].split("</article>", 1)[0]
    error = article.split(f'id="error-{group.id}" role="alert">', 1)[1].split("</p>", 1)[0]
    assert says in error
    described = f'aria-invalid="true" aria-describedby="error-{group.id}" autofocus'
    assert article.count(described) == 1  # the field at fault, and it alone, takes the focus
    element = article.split(described)[0].rsplit("<", 1)[1]
    assert element.startswith('fieldset class="choices"') if field == "decision" else f'name="{field}"' in element


def test_what_a_spelling_is_accepted_as_must_read_as_an_answer_of_the_part(graded, bank, tmp_path):
    state = Review(graded.graded, tmp_path / "decisions.yaml", bank=lambda: bank)
    with TestClient(create_app(state, loopback_hosts(8001)), base_url=HOST) as client:
        wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
        refused = post(client, wordy, decision="alias", means="fast")
        assert refused.status_code == 400 and "not an answer the part reads" in html.unescape(refused.text)
        assert not state.decisions_path.exists()
        assert post(client, wordy, decision="alias", means="348.3 rpm").status_code == 303
        assert [a.means for a in load_decisions(state.decisions_path).aliases] == ["348.3 rpm"]


def test_a_blank_cannot_be_accepted_as_a_spelling(state, client):
    blank = group_of(state, "q1", "b", "")
    assert post(client, blank, decision="alias", means="1 rpm").status_code == 400
    assert not state.decisions_path.exists()


# ---- guards ------------------------------------------------------------------------------------------

def test_other_hosts_other_sites_and_stale_tokens_are_refused(state, client):
    group = group_of(state, "q1", "a", rc.UNIT_WORD)
    good = {"token": token_of(client.get("/").text), "group": group.id, "decision": "accept",
            "reviewer": "x", "reason": "y"}
    assert client.get("/", headers={"host": "attacker.example"}).status_code == 421
    assert client.post("/decide", data=good, headers={"host": "attacker.example:8001"}).status_code == 421
    assert client.post("/decide", data=good, headers={"origin": "http://attacker.example"}).status_code == 403
    assert client.post("/decide", data=good, headers={"origin": "null"}).status_code == 403
    assert client.post("/decide", data=good, headers={"sec-fetch-site": "cross-site"}).status_code == 403
    assert client.post("/decide", data={**good, "token": "guessed"}).status_code == 403
    assert client.post("/decide", data={k: v for k, v in good.items() if k != "token"}).status_code == 403
    assert client.post("/decide", data={**good, "reason": "9" * (MAX_BODY + 10)}).status_code == 413
    assert not state.decisions_path.exists()
    own = client.post("/decide", data=good, headers={"origin": HOST}, follow_redirects=False)
    assert own.status_code == 303  # from its own page


def test_every_page_forbids_scripts_from_anywhere_and_serves_only_its_own_files(client):
    headers = client.get("/").headers
    assert "script-src 'self'" in headers["content-security-policy"] and headers["cache-control"] == "no-store"
    assert "<script" not in client.get("/").text  # nothing on the page needs JavaScript
    css = client.get("/static/review.css")
    assert css.status_code == 200 and css.headers["content-type"].startswith("text/css")
    assert client.get("/static/review.css", headers={"if-none-match": css.headers["etag"]}).status_code == 304
    for path in ("/static/../app.py", "/static/%2e%2e%2fapp.py", "/static/app.py", "/nowhere"):
        assert client.get(path).status_code == 404
    assert client.get("/decide").status_code == 405


@pytest.mark.parametrize("host", ["0.0.0.0", "::", "192.168.1.10", "example.org"])
def test_a_listening_address_another_computer_could_reach_is_refused(graded, host, capsys):
    with pytest.raises(ExgenError, match="this computer only"):
        review(graded.graded, host=host, port=0)
    assert main(["review", str(graded.graded), "--host", host, "--port", "0"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "loopback" in err


def test_a_folder_without_results_is_one_line(tmp_path, capsys):
    assert main(["review", str(tmp_path), "--port", "0"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "results.json" in err


def test_the_real_server_answers_only_to_its_own_address(graded):
    with running_review(graded.graded) as url:
        host, port = url.removeprefix("http://").split(":")
        for name, status in ((f"127.0.0.1:{port}", b"200"), ("attacker.example", b"421"), (f"localhost:{port}", b"200")):
            with socket.create_connection((host, int(port)), timeout=20) as sock:
                sock.sendall(f"GET / HTTP/1.1\r\nHost: {name}\r\nConnection: close\r\n\r\n".encode())
                assert sock.recv(100).startswith(b"HTTP/1.1 " + status)
    assert url.startswith("http://127.0.0.1:")  # the default: loopback, where only this computer reaches it


def test_a_sheet_left_blank_throughout_is_not_listed(graded):
    """A blank on a sheet with nothing else answered is no one's business but the student's."""
    record = read_record(graded.graded)
    listed = build_queue(record, load_decisions(graded.decisions))
    assert rc.BLANKER in {a.student for g in listed.groups for a in g.answers}  # one blank beside answers
    sheet = next(s for s in record["sheets"] if s["student"]["id"] == rc.BLANKER)
    for part in sheet["parts"]:
        part.update(given="", status="blank")
    queue = build_queue(record, load_decisions(graded.decisions))
    assert rc.BLANKER not in {a.student for g in queue.groups for a in g.answers}


def test_decided_on_the_page_then_graded_again_the_marks_change_and_the_page_says_so(tmp_path):
    """The page writes; `exgen grade` run again applies: the feedback says marked by hand, and the page shows
    each decided answer as applied, still listed for what the grader gave before."""
    graded = rc.graded_class(tmp_path)
    state = Review(graded.graded, graded.decisions, reviewer="A. Lecturer")
    with TestClient(create_app(state, loopback_hosts(8001)), base_url=HOST) as client:
        wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
        assert post(client, wordy, decision="accept", points="0.5", comment="the number is right").status_code == 303
        spelled = group_of(state, "q2", "b", rc.SPELLING)
        assert post(client, spelled, decision="alias", means="raises the bow").status_code == 303
        assert graded.grade() == 0
        feedback = (graded.graded / "feedback" / f"{rc.WORDY}.md").read_text(encoding="utf-8")
        assert "Marked by hand: the number is right." in feedback
        page = html.unescape(client.get("/?show=all").text)
        queue = state.queue()
        planted = len(rc.SPELLERS) + 3 + len(rc.COPIED)  # and the wordy, the blank, the hostile
        assert (queue.answers, queue.open_answers) == (planted, planted - len(rc.SPELLERS) - 1)
        said = " ".join(page.replace("<strong>", "").replace("</strong>", "").split())
        assert f"{planted} answers in this grading run need a human; {planted - len(rc.SPELLERS) - 1} are still to " \
               "decide" in said and "--decisions" not in said  # the default file: exgen grade finds it itself
        article = page.split(f'id="g-{wordy.id}"', 1)[1].split("</article>", 1)[0]
        assert "applied: now 0.5 / 1 (was 0)" in article and "Change the decision" in article
        article = page.split(f'id="g-{spelled.id}"', 1)[1].split("</article>", 1)[0]
        right = [s for s in rc.SPELLERS if graded.keys[s]["q2"]["b"] == "raises the bow"]
        assert article.count("read as “raises the bow”: now 1 / 1 (was 0)") == len(right)
        assert article.count("read as “raises the bow”: now 0 / 1 (was 0)") == len(rc.SPELLERS) - len(right)


def test_a_decision_made_on_other_text_is_shown_as_not_matching_and_the_answer_stays_open(graded, state, client):
    from graders.decisions import Decision, Decisions, save_decisions

    earlier = Decision(rc.WORDY, 1, "a", "348.3", "accept", "A. Lecturer", "an earlier hand-in",
                       template="belts.driven_speed_slip")
    save_decisions(Decisions("review-demo").with_decision(earlier), state.decisions_path)
    wordy = group_of(state, "q1", "a", rc.UNIT_WORD)
    assert not wordy.decided and wordy.stale[0].stale == earlier
    article = html.unescape(client.get("/").text).split(f'id="g-{wordy.id}"', 1)[1].split("</article>", 1)[0]
    assert "a decision made on “348.3” no longer matches: not applied" in article


def test_a_run_with_nothing_to_review_says_so(graded):
    from graders.review_page import pages
    from graders.decisions import Decisions

    record = read_record(graded.graded)
    for sheet in record["sheets"]:
        for part in sheet["parts"]:
            part["status"] = "correct"
    record["signs"] = []
    queue = build_queue(record, Decisions("review-demo"))
    page = pages.review_page(queue, {"question": None, "part": "", "everything": False}, token="t", reviewer="",
                             decisions_path="d.yaml", graded="g")
    assert queue.groups == () and "Nothing in this grading run needs a human" in page and "<form class=\"decide\"" not in page


def test_the_decisions_on_a_row_can_be_taken_back(state, client):
    spelled = group_of(state, "q2", "b", rc.SPELLING)
    assert post(client, spelled, decision="alias", means="raises the bow").status_code == 303
    assert post(client, spelled, decision="accept", student=rc.SPELLERS[0]).status_code == 303
    article = client.get("/?show=all").text.split(f'id="g-{spelled.id}"', 1)[1].split("</article>", 1)[0]
    assert "Take back the decisions on these answers" in article
    assert post(client, spelled, decision="withdraw").status_code == 303
    assert not load_decisions(state.decisions_path)  # neither the alias nor the student's decision is left
    assert f'id="g-{spelled.id}"' in client.get("/").text  # open again
    assert post(client, spelled, decision="withdraw").status_code == 400  # nothing left to take back
