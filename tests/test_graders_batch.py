"""Grading a directory of answer files, and the gradebook, feedback and report written from it."""
import csv
import json
import os

import pytest

from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.answer_form import answer_form
from graders.grade import grade_batch
from graders.report import write_results
from graders.results import GRADED, NO_SUBMISSION, PROBLEM_FILE, UNREADABLE_FILE

SECRET = b"s" * 32
ASSIGNMENT = Assignment("hw2", "Belts <b>&</b> friends", (
    QuestionSpec("q1", "belts.flat_belt_power"), QuestionSpec("q2", "belts.v_belt_count", 6.0)))
ROSTER = [Student(f"s{i:03d}", f"Student {i}", f"s{i}@uni.example") for i in range(6)] + [
    Student("s900", "=HYPERLINK(\"http://x\")", "x@y")]


def key_form(bank, student, right=("q1", "q2")):
    sheet = build_sheet(ASSIGNMENT, student, bank, SECRET)
    data = {"student": student.id, "assignment": ASSIGNMENT.id, "code": sheet.code, "answers": {}}
    for q in sheet.questions:
        data["answers"][q.slot] = {p: (a.text if q.slot in right else "") for p, a in q.variant.answers.items()}
    return sheet, data


@pytest.fixture
def handed_in(bank, tmp_path):
    """s000 all right (YAML form), s001 q1 only (JSON, named as a learning system names downloads), s002
    broken, s003 two files, s004 in a folder, s005 and s900 nothing; plus a stranger, a bomb, a text file
    and a hidden one."""
    folder = tmp_path / "in"
    folder.mkdir()
    sheet, data = key_form(bank, ROSTER[0])
    form = answer_form(sheet)
    for slot, parts in data["answers"].items():
        for pid, text in parts.items():
            form = form.replace(f'  {slot}:', f'  {slot}:', 1)
    (folder / "s000.yaml").write_text(_filled(form, data["answers"]), encoding="utf-8")
    _, data = key_form(bank, ROSTER[1], right=("q1",))
    (folder / "hw2_s001_attempt_1.json").write_text(json.dumps(data), encoding="utf-8")
    (folder / "s002.yaml").write_text("answers: !!python/object/apply:os.system ['echo hi']\n", encoding="utf-8")
    _, data = key_form(bank, ROSTER[3])
    old = folder / "s003.json"
    old.write_text(json.dumps(data), encoding="utf-8")
    os.utime(old, (1_000_000_000, 1_000_000_000))
    (folder / "s003_resubmitted.csv").write_text("student,s003\nq1,a,1 m\n", encoding="utf-8")
    (folder / "s004").mkdir()
    _, data = key_form(bank, ROSTER[4], right=("q2",))
    del data["student"]
    (folder / "s004" / "answers.yaml").write_text(json.dumps(data), encoding="utf-8")
    (folder / "stranger.yaml").write_text("student: zz999\nanswers: {}\n", encoding="utf-8")
    (folder / "bomb.yaml").write_text("a: &a [x, x]\nb: [*a, *a]\n", encoding="utf-8")
    (folder / "notes.txt").write_text("not an answer file", encoding="utf-8")
    (folder / ".hidden.yaml").write_text("{", encoding="utf-8")
    return folder


def _filled(form, answers):
    out, slot = [], None
    for line in form.splitlines():
        if line.startswith("  ") and not line.startswith("    ") and ":" in line:
            slot = line.split(":")[0].strip()
        elif line.startswith("    ") and slot:
            pid = line.split(":")[0].strip()
            line = line.replace('""', json.dumps(answers[slot][pid], ensure_ascii=False), 1)
        out.append(line)
    return "\n".join(out) + "\n"


def test_batch_grades_everyone_and_reports_every_problem(bank, handed_in):
    seen = []

    def progress(items, total):
        seen.append(total)
        return items

    batch = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER, progress=progress)
    by_id = {s.student.id: s for s in batch.sheets}
    assert [s.student.id for s in batch.sheets] == [s.id for s in ROSTER]
    assert seen == [len(ROSTER)]
    assert by_id["s000"].status == GRADED and by_id["s000"].percent == pytest.approx(100)
    assert by_id["s001"].points == pytest.approx(7) and by_id["s001"].max_points == pytest.approx(13)
    assert by_id["s002"].status == UNREADABLE_FILE and "tag" in by_id["s002"].warnings[-1]
    assert by_id["s003"].path.name == "s003_resubmitted.csv" and by_id["s003"].points == 0
    assert any("2 files" in w for w in by_id["s003"].warnings)
    assert by_id["s004"].question("q2").points == pytest.approx(6) and by_id["s004"].question("q1").points == 0
    assert by_id["s005"].status == NO_SUBMISSION and by_id["s005"].points == 0
    reasons = {p.path.name: p.reason for p in batch.problems}
    assert set(reasons) == {"s002.yaml", "s003.json", "stranger.yaml", "bomb.yaml", "notes.txt", ".hidden.yaml"}
    assert "cannot tell whose file" in reasons["stranger.yaml"] and "student: zz999" in reasons["stranger.yaml"]
    assert "aliases" in reasons["bomb.yaml"] and "not an answer file (.txt)" in reasons["notes.txt"]
    assert "hidden" in reasons[".hidden.yaml"]
    assert "s003_resubmitted.csv was graded" in reasons["s003.json"]
    assert batch.by_status() == {GRADED: 4, UNREADABLE_FILE: 1, NO_SUBMISSION: 2}
    assert "7 student(s)" in batch.summary()


def test_without_a_roster_a_file_name_or_first_folder_is_the_student(bank, handed_in):
    batch = grade_batch(ASSIGNMENT, bank, SECRET, handed_in)
    ids = [s.student.id for s in batch.sheets]
    assert ids == sorted(ids) and {"s000", "s004", "stranger"} <= set(ids) and "s005" not in ids
    assert "zz999" not in ids  # what a file says inside never decides whose it is
    assert {p.path.name for p in batch.problems} >= {"s002.yaml", "bomb.yaml", "stranger.yaml"}


def test_progress_wrapper_with_a_label_is_given_one(bank, handed_in):
    labels = []

    def progress(items, total, label):
        labels.append(label)
        return items

    grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER, progress=progress)
    assert labels == ["grading"]


def test_results_written(bank, handed_in, tmp_path):
    batch = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER)
    paths = write_results(batch, tmp_path / "out")
    rows = list(csv.DictReader(paths["gradebook"].open(encoding="utf-8")))
    assert list(rows[0]) == ["student", "name", "email", "q1 (/7)", "q2 (/6)", "total", "max", "percent", "status"]
    assert rows[0]["percent"] == "100.0" and rows[0]["total"] == "13"
    assert rows[-1]["name"].startswith("'=")  # a spreadsheet will not run it
    assert {r["status"] for r in rows} == {GRADED, UNREADABLE_FILE, NO_SUBMISSION}
    feedback = {p.stem: p.read_text(encoding="utf-8") for p in paths["feedback"].glob("*.md")}
    assert set(feedback) == {s.id for s in ROSTER}
    assert "\u2713" in feedback["s000"] and "<b>" not in feedback["s000"] and "\u2039b\u203a" in feedback["s000"]
    assert "'m' is a length, but an angle is asked" in feedback["s003"]
    assert "No answer file" in feedback["s005"]
    report = paths["report"].read_text(encoding="utf-8")
    assert "4 graded" in report and "| q1 | a |" in report and "stranger.yaml" in report
    assert "wrong_kind (1)" in report


def test_student_text_in_feedback_is_escaped(bank, tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    _, data = key_form(bank, ROSTER[0])
    data["answers"]["q1"]["a"] = "<img src=x onerror=alert(1)>`code`\n# heading"
    data["code"] = "<script>"
    (folder / "s000.json").write_text(json.dumps(data), encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=ROSTER[:1])
    page = (write_results(batch, tmp_path / "out")["feedback"] / "s000.md").read_text(encoding="utf-8")
    assert "<img" not in page and "<script>" not in page and "\n# heading" not in page
    assert batch.sheets[0].code_mismatch


def test_a_path_in_the_student_field_cannot_escape_the_feedback_folder(bank, tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / "s001.yaml").write_text("student: ../../evil\nanswers: {}\n", encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder)
    assert [(s.student.id, s.status) for s in batch.sheets] == [("s001", PROBLEM_FILE)]
    assert "says `student: ../../evil` inside" in batch.sheets[0].warnings[0]
    write_results(batch, tmp_path / "out")
    assert not (tmp_path / "evil.md").exists()


@pytest.mark.parametrize("name, payload", [
    ("s001.yaml", b"a: &a [x, x, x]\nb: &b [*a, *a, *a]\nc: [*b, *b, *b]\n"),
    ("s001.yaml", b"answers: !!python/object/apply:os.system ['echo pwned']\n"),
    ("s001.yaml", b"answers:\n  q1:\n    a: \"" + b"9" * (10 * 1024 * 1024) + b"\"\n"),
    ("s001.json", bytes(range(256)) * 64),
    ("s001.yaml", b"- just\n- a list\n"),
    ("s001.json", b"[" * 100_000 + b"]" * 100_000),
    ("s001.csv", b"q1,a," + b"9" * 200_000 + b"\n"),
    ("s001.yaml", b"answers:\n  q1:\n    a: \xff\xfe 5 N\n"),
])
def test_one_hostile_file_never_stops_the_batch(bank, tmp_path, name, payload):
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / name).write_bytes(payload)
    _, data = key_form(bank, ROSTER[0])
    (folder / "s000.json").write_text(json.dumps(data), encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=ROSTER[:2])
    assert [(s.student.id, s.status) for s in batch.sheets] == [("s000", GRADED), ("s001", UNREADABLE_FILE)]
    assert batch.sheets[0].percent == pytest.approx(100)
    assert [p.path.name for p in batch.problems] == [name] and batch.problems[0].reason


def test_a_large_class_graded_in_worker_processes_gets_the_same_results(bank, handed_in, monkeypatch):
    """Every kind of file of the fixture (right, partly right, broken, duplicated, foldered, a stranger's),
    read and graded by two workers, gives what one process gives, in the same order."""
    import graders.grade

    alone = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER)
    monkeypatch.setattr(graders.grade, "PARALLEL_FROM", 2)  # this small class counts as large
    shared = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER, jobs=2)
    assert shared == alone
    assert [s.status for s in shared.sheets].count(GRADED) >= 3


def test_a_class_graded_in_worker_processes_writes_the_same_files(bank, handed_in, monkeypatch, tmp_path):
    """The workers write each feedback page where the sheet was graded; every file written (pages,
    gradebooks, report, results.json) is byte for byte what one process writes."""
    import graders.grade

    write_results(grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER), tmp_path / "alone")
    monkeypatch.setattr(graders.grade, "PARALLEL_FROM", 2)
    shared = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER, jobs=2)
    assert set(shared.pages) == {s.student.id for s in shared.sheets}
    write_results(shared, tmp_path / "shared")
    alone = {p.relative_to(tmp_path / "alone"): p.read_bytes() for p in (tmp_path / "alone").rglob("*") if p.is_file()}
    both = {p.relative_to(tmp_path / "shared"): p.read_bytes() for p in (tmp_path / "shared").rglob("*") if p.is_file()}
    assert both == alone and len(alone) > len(ROSTER)


def test_a_sheet_replaced_after_grading_gets_a_page_of_its_own(bank, handed_in, tmp_path):
    """A page written where a sheet was graded is used only for that very sheet."""
    import dataclasses

    batch = grade_batch(ASSIGNMENT, bank, SECRET, handed_in, roster=ROSTER)
    first = batch.sheets[0]
    renamed = dataclasses.replace(first, student=dataclasses.replace(first.student, name="Another Name"))
    batch = dataclasses.replace(batch, sheets=(renamed, *batch.sheets[1:]),
                                pages={first.student.id: (first, "a page of the sheet as first graded\n")})
    page = (write_results(batch, tmp_path / "out")["feedback"] / f"{first.student.id}.md").read_text(encoding="utf-8")
    assert "Another Name" in page and "as first graded" not in page
