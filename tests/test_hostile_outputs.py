"""What a student typed, and what they named their files, reaches every output of grading and practice
only as `graders.echo.shown` leaves it (one line, capped, no control or bidi characters) and escaped for
the format: results.json, the item analysis in HTML and Markdown, the report, feedback, the gradebooks,
the practice progress file and its pages."""
import json
import unicodedata
from pathlib import Path

import pytest

from exgen.cli import main
from exgen.issue.assignment import Student, load_assignment
from exgen.issue.generate import generate

EXAMPLES = Path(__file__).parent.parent / "examples"
SECRET = "9c2e4a6f8b0d1e3f5a7c9b1d3f5e7a9c0b2d4f6e8a0c2e4f"
STUDENTS = [Student("A21003", "Priya Ramasamy"), Student("A21005", "Chen Mei Ling"), Student("A21006", "Arjun Nair")]
#: Markup, a bidi override (it shows 'evil' as 'live'), a zero-width space, a bell, an escape sequence,
#: a spreadsheet formula and an HTML entity, then a long tail.
HOSTILE = "<script>alert(1)</script>\u202eevil\u200b|`**x**`[a](javascript:x)\x07\x1b[31m=1+2&amp;" + "9" * 5000
HIDDEN = {"Cc", "Cf"}


def hidden_characters(text: str) -> list[str]:
    return [f"U+{ord(c):04X}" for c in text if unicodedata.category(c) in HIDDEN and c not in "\n\t"]


@pytest.fixture(scope="module")
def graded(tmp_path_factory, bank):
    root = tmp_path_factory.mktemp("hostile")
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    generate(assignment, STUDENTS, bank, SECRET.encode(), root / "issued", pdf=False, secret_source="$EXGEN_SECRET")
    handed = root / "handed"
    handed.mkdir()
    # graded: hostile answers in a folder whose name is hostile too
    folder = handed / "A21003 <b>\u202efdp.exe\x1b[0m`"
    folder.mkdir()
    (folder / "answers.json").write_text(json.dumps(
        {"student": "A21003", "answers": {"q1": {"a": HOSTILE, "b": "12 " + HOSTILE}, "q2": {"a": HOSTILE[:40]}}}))
    # refused: a sheet code that is no one's, and one that names another student hostilely
    (handed / "A21005.json").write_text(json.dumps({"student": "A21005", "code": HOSTILE[:120], "answers": {}}))
    (handed / "A21006.json").write_text(json.dumps({"student": HOSTILE, "answers": {}}))
    # no one's: its name is hostile
    (handed / "<img src=x onerror=alert(1)>\u202e.yaml").write_text("student: A21099\n")
    out = root / "graded"
    import os
    os.environ["EXGEN_SECRET"] = SECRET
    try:
        assert main(["grade", str(root / "issued"), str(handed), "--out", str(out)]) == 0
    finally:
        del os.environ["EXGEN_SECRET"]
    return out


def test_no_output_of_grading_carries_a_hidden_character(graded):
    files = [p for p in graded.rglob("*") if p.is_file() and p.name != ".exgen-output"]
    assert {p.name for p in files} >= {"results.json", "item-analysis.html", "item-analysis.md", "report.md",
                                      "gradebook.csv", "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"}
    found = {p.name: hidden_characters(p.read_text(encoding="utf-8")) for p in files}
    assert {name: chars for name, chars in found.items() if chars} == {}


def test_results_json_keeps_what_students_typed_short(graded):
    record = json.loads((graded / "results.json").read_text(encoding="utf-8"))
    typed = [p["given"] for s in record["sheets"] for p in s["parts"] if p["given"]]
    assert typed and all(len(t) <= 200 for t in typed)
    texts = [s["file"] for s in record["sheets"]] + [p["path"] for p in record["problems"]] + \
        [line for sign in record["signs"] for line in [sign["summary"], *sign["evidence"]]]
    assert any("fdp.exe" in t for t in texts) and any("onerror" in t for t in texts)
    assert all(len(t) <= 400 and not hidden_characters(t) for t in texts)
    assert any("alert" in line for sign in record["signs"] for line in sign["evidence"])  # the code is quoted


def test_the_html_item_analysis_escapes_every_tag(graded):
    html = (graded / "item-analysis.html").read_text(encoding="utf-8")
    assert "<script>alert" not in html and "<img src=x" not in html and "<b>" not in html
    assert "&lt;img src=x onerror=alert(1)&gt;" in html  # shown, as text
    assert "<code>student: A21099</code>" in html  # what a file says, quoted as code, not between backticks


def test_the_markdown_item_analysis_keeps_hostile_names_inside_their_code_spans(graded):
    markdown = (graded / "item-analysis.md").read_text(encoding="utf-8")
    lines = [line for line in markdown.splitlines() if "onerror" in line or "fdp.exe" in line]
    assert lines and all("<img" not in line for line in lines)
    for line in lines:
        if line.startswith("- `"):
            span = line[3:line.index("`", 3)]
            assert "onerror" in span or "fdp.exe" in span  # the name closes no span early


def test_exgen_report_cleans_a_results_file_written_elsewhere(graded, tmp_path, capsys):
    """results.json may come from an older exgen or an edit by hand: its text is cleaned on reading too."""
    record = json.loads((graded / "results.json").read_text(encoding="utf-8"))
    record["problems"].append({"path": "x\u202e\x1b[2J.yaml", "reason": "a \u2066reason\u2069", "student": ""})
    folder = tmp_path / "edited"
    folder.mkdir()
    (folder / "results.json").write_text(json.dumps(record, ensure_ascii=False), encoding="utf-8")
    assert main(["report", str(folder)]) == 0
    for name in ("item-analysis.html", "item-analysis.md"):
        assert hidden_characters((folder / name).read_text(encoding="utf-8")) == []


def test_the_practice_progress_file_and_its_page_keep_an_answer_clean(tmp_path, bank):
    from practice.web.pages import problem_page
    from practice.session import Practice
    from practice.store import Store

    practice = Practice(bank, Store(tmp_path / "progress.sqlite3"))
    problem = practice.next_problem(practice.catalogue.choose(None, "belts.drive_geometry"))
    practice.check(problem, "a", HOSTILE)
    stored = practice.store.checks(problem.id)[-1].answer
    assert len(stored) <= 200 and hidden_characters(stored) == [] and stored.startswith("<script>")
    page = problem_page(practice, problem)
    assert hidden_characters(page) == [] and "<script>alert" not in page and "&lt;script&gt;alert" in page
