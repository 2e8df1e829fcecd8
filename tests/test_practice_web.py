"""The practice web app over HTTP: pages, checks without a reload, and hostile requests (oversized or
malformed bodies, other sites, other host names, paths outside the assets, a script in an answer)."""
import html
import random
import re
import socket
import sqlite3

import pytest
from starlette.testclient import TestClient

from exgen.answertypes import registry
from practice.scope import Scope
from practice.session import Practice
from practice.store import Store
from practice.web.app import MAX_BODY, create_app, loopback_hosts
from practice_server import running_server

JSON = {"accept": "application/json"}
SCRIPT = "<script>alert('x')</script>"
BREAKOUT = '"><img src=x onerror=alert(1)>'


@pytest.fixture
def practice(bank, tmp_path):
    return Practice(bank, Store(tmp_path / "progress.sqlite3"), rng=random.Random(4))


@pytest.fixture
def client(practice):
    app = create_app(practice, loopback_hosts(8000))
    with TestClient(app, base_url="http://127.0.0.1:8000", raise_server_exceptions=False) as client:
        yield client


def new_problem(client, scope="template:belts.compound_drive") -> int:
    response = client.post("/next", data={"scope": scope}, follow_redirects=False)
    assert response.status_code == 303, response.text
    return int(response.headers["location"].rsplit("/", 1)[1])


def test_the_map_shows_all_seven_chapters_and_their_topics(client):
    page = client.get("/").text
    for title in ("Power transmission", "Dynamic balancing", "Flywheels", "Governors", "Gyroscopes",
                  "Free vibration", "Linkage kinematics"):
        assert title in page
    assert 'value="topic:belts"' in page and "not started" in page


def test_the_problem_page_has_the_statement_figure_and_a_labelled_input_per_part(client, practice):
    problem_id = new_problem(client)
    page = client.get(f"/problem/{problem_id}").text
    problem = practice.problem(problem_id)
    assert "<svg" in page and "<figcaption>" in page
    for part in problem.template.parts:
        assert f'<label for="answer-{part.id}">' in page and f'id="answer-{part.id}"' in page
    assert problem.variant.param("N1").text in page


def test_a_check_answers_with_the_feedback_alone(client, practice):
    problem_id = new_problem(client)
    variant = practice.problem(problem_id).variant
    right = client.post(f"/problem/{problem_id}/check", data={"part": "a", "answer": variant.answers["a"].text},
                        headers=JSON).json()
    assert right["correct"] and "Right." in right["html"] and right["standing"].startswith("Belts: ")
    slip = variant.mistakes["b"]["slip_not_applied"]
    wrong = client.post(f"/problem/{problem_id}/check", data={"part": "b", "answer": f"{slip:.6g} rpm"},
                        headers=JSON).json()
    assert not wrong["correct"] and wrong["status"] == "wrong" and "Not right:" in wrong["html"]


def test_without_script_a_check_returns_to_the_page_which_shows_the_answer_and_feedback(client):
    problem_id = new_problem(client)
    response = client.post(f"/problem/{problem_id}/check", data={"part": "a", "answer": "12 rpm"},
                           follow_redirects=False)
    assert response.status_code == 303 and response.headers["location"] == f"/problem/{problem_id}#part-a"
    page = client.get(f"/problem/{problem_id}").text
    assert 'value="12 rpm"' in page and "Not right:" in page


def test_hints_then_the_worked_solution_as_mathml(client):
    problem_id = new_problem(client, "template:belts.flat_belt_power")
    hint = client.post(f"/problem/{problem_id}/hint", data={"part": "a"}, headers=JSON).json()
    assert "Hint 1" in hint["html"] and "<math" in hint["html"] and hint["more"]
    solution = client.post(f"/problem/{problem_id}/solution", data={}, headers=JSON).json()["html"]
    assert "Worked solution" in solution and solution.count("<math") > 10 and "<mfrac>" in solution
    assert "\\frac" not in solution.replace('alttext="', "") and "$" not in solution
    page = client.get(f"/problem/{problem_id}").text
    assert "Worked solution" in page and "Hint 1" in page


@pytest.mark.parametrize("answer", [SCRIPT, BREAKOUT])
def test_a_students_text_is_escaped_wherever_it_is_shown(client, answer):
    problem_id = new_problem(client)
    html = client.post(f"/problem/{problem_id}/check", data={"part": "a", "answer": answer}, headers=JSON).json()["html"]
    page = client.get(f"/problem/{problem_id}").text
    for shown in (html, page):
        assert "<script>alert" not in shown and "<img src=x" not in shown
    assert 'value="&#34;&gt;&lt;img src=x onerror=alert(1)&gt;"' in page or "&lt;script&gt;" in page


def test_a_body_over_the_limit_is_refused_before_it_is_read(client):
    problem_id = new_problem(client)
    big = {"part": "a", "answer": "9" * (MAX_BODY + 10)}
    assert client.post(f"/problem/{problem_id}/check", data=big).status_code == 413

    def chunks():  # no Content-Length: counted as it arrives
        for _ in range(MAX_BODY // 1000 + 2):
            yield b"answer=" + b"9" * 1000 + b"&"
    response = client.post(f"/problem/{problem_id}/check", content=chunks(),
                           headers={"content-type": "application/x-www-form-urlencoded", **JSON})
    assert response.status_code == 413 and "larger than" in response.json()["error"]


@pytest.mark.parametrize("body, kind, status", [
    (b'{"part": "a"}', "application/json", 415),
    (b"part=a&answer=%ff%fe", "application/x-www-form-urlencoded", 400),
    (b"part=a", "application/x-www-form-urlencoded", 400),
    (b"&".join(b"f%d=1" % i for i in range(50)), "application/x-www-form-urlencoded", 400),
    (b"part=zz&answer=1", "application/x-www-form-urlencoded", 400),
])
def test_malformed_forms_are_400s_with_a_reason(client, body, kind, status):
    problem_id = new_problem(client)
    response = client.post(f"/problem/{problem_id}/check", content=body, headers={"content-type": kind, **JSON})
    assert response.status_code == status and response.json()["error"]


@pytest.mark.parametrize("path", ["/problem/999999", "/problem/abc", "/problem/99999999999999999999999",
                                  "/nowhere", "/static/../app.py", "/static/%2e%2e%2fapp.py", "/static/app.py",
                                  "/static/practice.css%00", "/static/"])
def test_unknown_pages_and_files_outside_the_assets_are_404(client, path):
    assert client.get(path).status_code == 404


def test_assets_are_served_from_the_package_with_etags(client):
    css = client.get("/static/practice.css")
    assert css.status_code == 200 and css.headers["content-type"].startswith("text/css")
    assert client.get("/static/practice.css", headers={"if-none-match": css.headers["etag"]}).status_code == 304
    fonts = re.findall(r'url\("(/static/[^"]+\.woff2)"\)', css.text)
    assert len(fonts) == 5  # New Computer Modern's four text faces and its math face
    for path in fonts:
        font = client.get(path)
        assert font.headers["content-type"] == "font/woff2" and font.content[:4] == b"wOF2"
    assert "GUST Font License" in client.get("/static/NewCM-README.txt").text


def test_every_page_forbids_outside_scripts_and_styles(client):
    headers = client.get("/").headers
    assert "script-src 'self'" in headers["content-security-policy"] and headers["x-content-type-options"] == "nosniff"


def test_other_host_names_and_other_sites_are_refused(client):
    assert client.get("/", headers={"host": "attacker.example"}).status_code == 421
    other = client.post("/next", data={"scope": "all"}, headers={"origin": "http://attacker.example"})
    assert other.status_code == 403
    sneaky = client.post("/next", data={"scope": "all"}, headers={"sec-fetch-site": "cross-site"})
    assert sneaky.status_code == 403


def test_a_scope_that_does_not_exist_is_a_400(client):
    assert client.post("/next", data={"scope": "topic:nonsense"}).status_code == 400
    assert client.post("/next", data={"scope": "../../etc"}).status_code == 400


def test_a_locked_progress_file_is_a_503_and_loses_nothing(client, practice):
    problem_id = new_problem(client)
    practice.store.busy_seconds = 0.2
    practice.store.close()
    other = sqlite3.connect(practice.store.path, isolation_level=None)
    other.execute("BEGIN EXCLUSIVE")
    try:
        response = client.post("/next", data={"scope": "all"}, headers=JSON)
        assert response.status_code == 503 and "busy" in response.json()["error"]
    finally:
        other.execute("ROLLBACK")
        other.close()
    assert client.get(f"/problem/{problem_id}").status_code == 200
    assert new_problem(client) > problem_id


def test_an_unexpected_failure_is_a_500_page_and_the_server_goes_on(client, practice, monkeypatch):
    monkeypatch.setattr(practice, "next_problem", lambda scope: 1 / 0)
    response = client.post("/next", data={"scope": "all"})
    assert response.status_code == 500 and "your progress so far is kept" in response.text
    monkeypatch.undo()
    assert client.get("/").status_code == 200


def test_a_real_server_survives_malformed_requests(tmp_path):
    with running_server(tmp_path / "p.sqlite3") as url:
        host, port = url.removeprefix("http://").split(":")
        garbage = [b"GARBAGE\r\n\r\n", b"GET / HTTP/1.1\r\nHost: \xff\xfe\r\n\r\n",
                   b"POST /next HTTP/1.1\r\nHost: x\r\nContent-Length: -5\r\n\r\n",
                   b"GET /" + b"a" * 70000 + b" HTTP/1.1\r\n\r\n", b"\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03"]
        for request in garbage:
            with socket.create_connection((host, int(port)), timeout=10) as sock:
                sock.sendall(request)
                try:
                    reply = sock.recv(200)
                except (ConnectionResetError, socket.timeout):
                    reply = b""
                assert reply == b"" or reply.startswith(b"HTTP/1.1 4"), reply
        with socket.create_connection((host, int(port)), timeout=10) as sock:
            sock.sendall(f"GET / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n".encode())
            assert sock.recv(100).startswith(b"HTTP/1.1 200")


def test_scope_keys_round_trip():
    for scope in (Scope(), Scope("chapter", "3"), Scope("topic", "belts"), Scope("template", "belts.max_power")):
        assert Scope.parse(scope.key) == scope


def test_an_assignments_practice_set_keeps_to_its_templates(bank, tmp_path):
    from pathlib import Path

    from exgen.issue.assignment import load_assignment

    assignment = load_assignment(Path(__file__).resolve().parents[1] / "examples" / "tutorial1.yaml", bank)
    practice = Practice(bank, Store(tmp_path / "p.sqlite3"), assignment, rng=random.Random(9))
    with TestClient(create_app(practice, loopback_hosts(8000)), base_url="http://127.0.0.1:8000") as client:
        page = client.get("/").text
        assert "Tutorial 1" in page and "Not in Tutorial 1" in page
        allowed = {q.template for q in assignment.questions}
        for _ in range(4):
            assert practice.problem(new_problem(client, "all")).template.id in allowed
        assert client.post("/next", data={"scope": "topic:gyroscopes"}).status_code == 400


def test_a_post_from_an_opaque_origin_is_refused(client):
    """`Origin: null` (a sandboxed frame, a file on disk) was accepted when Sec-Fetch-Site was absent."""
    for headers in ({"origin": "null"}, {"origin": "null", "sec-fetch-site": "same-origin"}):
        assert client.post("/next", data={"scope": "all"}, headers=headers).status_code == 403
    assert client.post("/next", data={"scope": "all"}, headers={"origin": "http://127.0.0.1:8000"},
                       follow_redirects=False).status_code == 303
    # this app's own forms send their real origin: its pages' referrer policy is not no-referrer
    assert client.get("/").headers["referrer-policy"] == "same-origin"


HIDDEN = ["\u202e", "\u2066", "\u200f", "\u200b", "\x1b", "\u2028", "\ufeff", "\x00"]


@pytest.mark.parametrize("kind", sorted(registry()))
def test_control_and_bidi_characters_in_an_answer_never_reach_a_page(bank, client, practice, kind):
    """A choice answer's message quoted the answer as typed, bidi overrides and all: every answer type's
    messages, on a template that asks for one."""
    template = next((t for t in bank if any(p.type == kind for p in t.parts)), None)
    if template is None:
        pytest.skip(f"no template of the bank has a {kind} answer")
    problem_id = new_problem(client, f"template:{template.id}")
    for part in practice.problem(problem_id).template.parts:
        for hidden in HIDDEN:
            for answer in (f"{hidden}left", f"12{hidden}5 rpm", f"clock{hidden}wise", f"{hidden * 3}x{hidden}"):
                html = client.post(f"/problem/{problem_id}/check", data={"part": part.id, "answer": answer},
                                   headers=JSON).json()["html"]
                assert hidden not in html, (part.id, answer, html)
    page = client.get(f"/problem/{problem_id}").text
    assert not any(hidden in page for hidden in HIDDEN)


def test_a_client_gone_mid_body_or_a_body_that_stalls_costs_no_traceback_and_no_long_wait(tmp_path):
    """A client that disconnected mid-body printed two tracebacks; a body that stopped arriving held its
    connection 70 s or more."""
    from practice.web.app import BODY_SECONDS

    output = []
    with running_server(tmp_path / "p.sqlite3", output=output) as url:
        host, port = url.removeprefix("http://").split(":")
        head = (f"POST /next HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/x-www-form-urlencoded\r\n"
                f"Content-Length: 100\r\n\r\nscope=al").encode()
        with socket.create_connection((host, int(port)), timeout=60) as sock:
            sock.sendall(head)  # and goes away
        with socket.create_connection((host, int(port)), timeout=10 * BODY_SECONDS + 60) as sock:
            sock.sendall(head)  # and stalls: the answer comes, the connection is closed
            reply = sock.recv(300)
            assert reply.startswith(b"HTTP/1.1 408"), reply
            assert b"connection: close" in reply.lower()
        with socket.create_connection((host, int(port)), timeout=60) as sock:
            sock.sendall(f"GET / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n".encode())
            assert sock.recv(100).startswith(b"HTTP/1.1 200")
    assert "Traceback" not in output[0] and "ClientDisconnect" not in output[0], output[0]


def test_every_figure_shown_has_the_level_the_progress_page_states_for_it(practice, monkeypatch):
    """"Belts: 80 % (learning)", then "79 % (learning)", then "80 % (mastered)": the figure was rounded to
    the nearest percent and the level read from the unrounded estimate."""
    import math

    from practice.mastery import Mastery
    from practice.progress import Row
    from practice.terminal import stats_text
    from practice.web import pages

    topics = [t for chapter in practice.catalogue.chapters() for t in chapter.topics]
    means = [0.795, 0.7996, 0.8, 0.8004, 0.4996, 0.5, 0.5004, 0.123]
    rows = {t: Row(t, 1, Mastery(math.log(m / (1 - m)), 2), 2, 3, 60.0) for t, m in zip(topics, means)}
    monkeypatch.setattr(practice, "table", lambda by="topic": rows)
    page = pages.progress_page(practice)
    mastered, weak = map(int, re.search(r"mastered from (\d+) % and weak below\s+(\d+) %", page).groups())

    def level(percent: int) -> str:
        return "mastered" if percent >= mastered else "weak" if percent < weak else "learning"

    table = re.findall(r"<td>(\d+) %</td><td>(\w+)</td>", page)
    chart = re.findall(r"(\d+) % · (\w+)</text>", page)
    shown = pages.map_page(practice)
    listed = re.findall(r'<span class="level">(\d+) % · (\w+)</span>', shown)
    stats = re.findall(r"(\d+) %\s+(mastered|learning|weak)\b", stats_text(practice))
    for found in (table, chart, listed, stats):
        assert len(found) >= len(rows) == len(means)
        assert all(level(int(percent)) == said for percent, said in found), found
    assert ("79", "learning") in table and ("80", "mastered") in table and ("49", "weak") in table


def test_what_help_costs_is_on_the_page_before_it_is_asked_for_and_follows_the_answers(client, practice):
    problem_id = new_problem(client, "template:vibration.beam_two_springs")
    page = " ".join(html.unescape(client.get(f"/problem/{problem_id}").text).split())
    assert "each hint costs a quarter of its part's credit" in page
    assert 'data-cost="a">costs a quarter of (a)\'s credit</span>' in page
    assert "costs half of the credit of every part not answered yet" in page
    variant = practice.problem(problem_id).variant
    checked = client.post(f"/problem/{problem_id}/check", data={"part": "a", "answer": variant.answers["a"].text},
                          headers=JSON).json()
    assert checked["costs"]["a"] == "free: (a) has been answered" and checked["costs"]["b"].startswith("costs a quarter")
    hinted = client.post(f"/problem/{problem_id}/hint", data={"part": "c"}, headers=JSON).json()
    assert hinted["more"] and hinted["costs"]["c"].startswith("costs a quarter") and hinted["costs"]["a"].startswith("free")
    last = client.post(f"/problem/{problem_id}/hint", data={"part": "c"}, headers=JSON).json()
    assert not last["more"] and last["costs"]["c"] == ""  # no hint left to cost anything
    for part in ("b", "c"):
        client.post(f"/problem/{problem_id}/check", data={"part": part, "answer": "1"}, headers=JSON)
    assert "free: every part has been answered" in client.get(f"/problem/{problem_id}").text
