"""Collection finds every student's file whatever else the submissions folder holds, never opens what is not
a regular file, never loses a file silently (each is graded or listed by name), and says when a limit was
reached instead of grading as if nothing had been missed."""
import json
import os
import threading
import time
from pathlib import Path

import pytest

import graders.walk
from exgen.errors import SubmissionError
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from graders.answers import read_submission
from graders.grade import grade_batch
from graders.report import write_results
from graders.results import GRADED, NO_SUBMISSION
from graders.walk import LimitsReached

SECRET = b"collection tests: 4f1c9e27b8a3d605"
ASSIGNMENT = Assignment("hw3", "Belts", (QuestionSpec("q1", "belts.drive_geometry"),))
HANG_GUARD = 120  # seconds: only a hang reaches it, however busy the machine


def roster(count: int) -> list[Student]:
    return [Student(f"B{22000 + i}", f"Student Number {i}") for i in range(count)]


def answers_of(bank, student: Student) -> str:
    """The student's sheet answered right, as JSON (the YAML form's keys)."""
    sheet = build_sheet(ASSIGNMENT, student, bank, SECRET)
    return json.dumps({"student": student.id, "code": sheet.code,
                       "answers": {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}})


def graded_in_time(*args, **kwargs):
    """grade_batch in a thread: a hang fails the test (at HANG_GUARD) instead of stopping the suite."""
    done = {}

    def run():
        try:
            done["batch"] = grade_batch(*args, **kwargs)
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            done["error"] = exc

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(HANG_GUARD)
    assert not worker.is_alive(), "grading hung"
    if "error" in done:
        raise done["error"]
    return done["batch"]


def listed(batch) -> dict[str, str]:
    return {str(p.path.relative_to(batch.submissions)): p.reason for p in batch.problems}


def test_photos_beside_every_answer_file_never_hide_a_submission(bank, tmp_path):
    """250 learning-system folders, each with answers.yaml and 20 photos (5,250 files): 11 students were
    "no submission" once the walk stopped at 5,000 files."""
    students = roster(250)
    for s in students:
        folder = tmp_path / f"{s.name}_{s.id[1:]}_assignsubmission_file_"
        folder.mkdir()
        (folder / "answers.json").write_text(json.dumps({"student": s.id, "answers": {"q1": {"a": "1 m"}}}))
        for i in range(20):
            (folder / f"working_{i:02d}.jpg").write_bytes(b"\xff\xd8")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert batch.by_status() == {GRADED: 250} and not batch.limits
    assert len(batch.problems) == 250 * 20 and all("not an answer file (.jpg)" in r for r in listed(batch).values())


def test_a_junk_folder_before_the_students_hides_none_of_them(bank, tmp_path):
    """A folder AAA_junk/ of 10,000 tiny files, walked first: all 60 students were "no submission"."""
    students = roster(60)
    (tmp_path / "AAA_junk").mkdir()
    for i in range(10_000):
        (tmp_path / "AAA_junk" / f"f{i:05d}{('.txt', '.yaml', '.png')[i % 3]}").write_text("x: 1\n")
    for s in students:
        (tmp_path / f"{s.id}.json").write_text(answers_of(bank, s), encoding="utf-8")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert batch.by_status() == {GRADED: 60} and not batch.limits
    assert all(s.percent == pytest.approx(100) for s in batch.sheets)
    assert len(batch.problems) == 10_000 and all(p.path.parent.name == "AAA_junk" for p in batch.problems)


@pytest.mark.parametrize("name", ["notes.yaml", "B22001_late.yaml", "B22001.json"])
def test_a_named_pipe_named_like_an_answer_file_is_listed_never_opened(bank, tmp_path, name):
    """`mkfifo subs/notes.yaml` hung grading for ever: the file was opened before any check."""
    students = roster(2)
    (tmp_path / "B22000.json").write_text(answers_of(bank, students[0]), encoding="utf-8")
    os.mkfifo(tmp_path / name)
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert [s.status for s in batch.sheets] == [GRADED, NO_SUBMISSION]
    assert listed(batch) == {name: "a named pipe, not a regular file; not opened"}
    assert [p.student for p in batch.problems] == ["B22001" if name.startswith("B22001") else ""]


def in_time(function, *args):
    """function(*args) in a thread; a hang fails the test at HANG_GUARD."""
    done = {}
    worker = threading.Thread(target=lambda: done.setdefault("value", function(*args)), daemon=True)
    worker.start()
    worker.join(HANG_GUARD)
    assert not worker.is_alive(), f"{function.__name__}{args} hung"
    return done["value"]


def test_reading_a_pipe_or_a_device_directly_is_refused_at_once(tmp_path):
    """Whatever hands over a path, it is opened without blocking and read only if it is a regular file."""
    os.mkfifo(tmp_path / "pipe.yaml")
    assert in_time(_refusal, tmp_path / "pipe.yaml") == "a named pipe, not a regular file; not read"
    for device in ("/dev/zero", "/dev/null", "/dev/tty"):
        if os.path.exists(device):
            assert in_time(_unsafe, Path(device)) == "a device, not a regular file; not read"
    (tmp_path / "zero.yaml").symlink_to("/dev/zero")
    assert in_time(_refusal, tmp_path / "zero.yaml") == "a symbolic link; not followed"


def _refusal(path: Path) -> str:
    try:
        read_submission(path)
    except SubmissionError as exc:
        return exc.detail
    return "read"


def _unsafe(path: Path) -> str:
    from exgen.runtime.safefile import UnsafeFile, read_bytes

    try:
        read_bytes(path, 1024)
    except UnsafeFile as exc:
        return exc.reason
    except OSError as exc:  # /dev/tty without a terminal
        return "a device, not a regular file; not read" if path.name == "tty" else str(exc)
    return "read"


def test_a_device_node_is_listed_never_opened(bank, tmp_path):
    try:
        os.mknod(tmp_path / "B22001.yaml", 0o600 | 0o020000, os.makedev(1, 5))  # a character device: /dev/zero's
    except (PermissionError, AttributeError, OSError):
        pytest.skip("device nodes cannot be made here (not root)")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=roster(2))
    assert listed(batch) == {"B22001.yaml": "a device, not a regular file; not opened"}


def test_files_deep_down_are_found_when_a_student_is_named_and_listed_when_not(bank, tmp_path):
    """Files six or more folders down vanished: "no submission", and in no list."""
    students = roster(3)
    six = tmp_path / "a" / "b" / "c" / "d" / "e" / "f"
    six.mkdir(parents=True)
    (six / f"{students[0].id}.json").write_text(answers_of(bank, students[0]), encoding="utf-8")
    (six / "answers.yaml").write_text("answers: {}\n")
    hundred = tmp_path / students[1].id
    for level in range(100):
        hundred = hundred / f"level{level}"
    hundred.mkdir(parents=True)
    (hundred / "answers.json").write_text(answers_of(bank, students[1]), encoding="utf-8")
    (hundred / "stray.yaml").write_text("answers: {}\n")
    nowhere = tmp_path / "misc"
    for level in range(100):
        nowhere = nowhere / f"level{level}"
    nowhere.mkdir(parents=True)
    (nowhere / "deep.yaml").write_text("answers: {}\n")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert [s.status for s in batch.sheets] == [GRADED, GRADED, NO_SUBMISSION]
    assert all(s.percent == pytest.approx(100) for s in batch.sheets[:2])
    reasons = listed(batch)
    assert "more than 4 folders down" in reasons["a/b/c/d/e/f/answers.yaml"]
    assert "more than 4 folders down" in reasons[str(nowhere.relative_to(tmp_path) / "deep.yaml")]
    assert reasons[str(hundred.relative_to(tmp_path) / "stray.yaml")].startswith("holds no answers")
    assert not batch.limits


def test_links_and_loops_are_listed_and_never_followed(bank, tmp_path):
    students = roster(1)
    (tmp_path / f"{students[0].id}.json").write_text(answers_of(bank, students[0]), encoding="utf-8")
    (tmp_path / "loop").symlink_to(".")
    (tmp_path / "B22000_again.json").symlink_to(tmp_path / f"{students[0].id}.json")
    (tmp_path / "up").mkdir()
    (tmp_path / "up" / "back").symlink_to("..")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert batch.by_status() == {GRADED: 1}
    assert listed(batch) == {"loop": "a symbolic link; not followed", "B22000_again.json": "a symbolic link; not followed",
                             "up/back": "a symbolic link; not followed"}


def test_every_file_is_graded_or_listed_and_a_hidden_folder_is_listed_once(bank, tmp_path):
    students = roster(2)
    (tmp_path / ".git" / "objects").mkdir(parents=True)
    for i in range(50):
        (tmp_path / ".git" / "objects" / f"{i:02x}").write_text("x")
    (tmp_path / "__MACOSX").mkdir()
    (tmp_path / "__MACOSX" / "._B22000.json").write_text("x")
    (tmp_path / f"{students[0].id}.json").write_text(answers_of(bank, students[0]), encoding="utf-8")
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    assert listed(batch) == {".git": "a hidden folder; skipped with everything in it",
                             "__MACOSX": "a hidden folder; skipped with everything in it"}


def test_a_newer_file_holding_no_answers_never_replaces_one_that_has_them(bank, tmp_path):
    """A newer file holding only `student:` was graded 0 in place of the same student's older file."""
    students = roster(2)
    old = tmp_path / f"{students[0].id}.json"
    old.write_text(answers_of(bank, students[0]), encoding="utf-8")
    os.utime(old, (1_000_000_000, 1_000_000_000))
    for name, text in (("B22000_resubmitted.yaml", "student: B22000\n"),
                       ("B22000_blank.yaml", "student: B22000\nanswers:\n  q1:\n    a: \"\"\n    b: ''\n")):
        (tmp_path / name).write_text(text, encoding="utf-8")
    only_empty = [tmp_path / "B22001.yaml", tmp_path / "B22001_v2.yaml"]
    for i, path in enumerate(only_empty):
        path.write_text("student: B22001\n", encoding="utf-8")
        os.utime(path, (1_000_000_000 + i, 1_000_000_000 + i))
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    first, second = batch.sheets
    assert first.status == GRADED and first.path == old and first.percent == pytest.approx(100)
    assert any("3 files" in w and "holding answers" in w for w in first.warnings)
    reasons = listed(batch)
    for name in ("B22000_resubmitted.yaml", "B22000_blank.yaml"):
        assert reasons[name].startswith("holds no answers") and f"{old.name}, which has answers" in reasons[name]
    assert second.status == GRADED and second.path.name == "B22001_v2.yaml"  # all empty: the newest, as before
    assert "older file" in reasons["B22001.yaml"]


def test_a_limit_reached_stops_grading_unless_accepted_and_is_said(bank, tmp_path, monkeypatch):
    """Past a cap, grading said nothing but one line deep in report.md, and exited 0."""
    monkeypatch.setattr(graders.walk, "MAX_LISTED", 30)
    students = roster(3)
    for s in students:
        (tmp_path / f"{s.id}.json").write_text(answers_of(bank, s), encoding="utf-8")
    (tmp_path / "junk").mkdir()
    for i in range(100):
        (tmp_path / "junk" / f"{i}.txt").write_text("x")
    with pytest.raises(LimitsReached) as caught:
        graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    message = str(caught.value)
    assert "nothing written" in message and "--accept-limits" in message and "junk" in message
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students, accept_limits=True)
    assert batch.by_status() == {GRADED: 3}  # the students' own files are never capped
    assert len(batch.limits) == 1 and "limits reached" in batch.summary()
    # the folder and 29 files looked at one by one (the cap counts folders too), the other 71 counted
    assert sum(1 for p in batch.problems if p.path.parent.name == "junk") == 29
    assert [p.reason for p in batch.problems if p.path.name == "junk"] == [
        "71 more entries in no student's place here were not listed one by one"]
    report = write_results(batch, tmp_path.parent / "graded")["report"].read_text(encoding="utf-8")
    assert "--accept-limits although a limit was reached" in report


def test_files_that_are_no_answer_files_are_never_opened(bank, tmp_path):
    """The walk tells files apart by name and type: a folder of photos costs no open at all."""
    (tmp_path / "photos").mkdir()
    for i in range(2000):
        (tmp_path / "photos" / f"{i}.jpg").write_bytes(b"\xff")
    opened = []
    real = os.open

    def counting(path, *args, **kwargs):
        opened.append(str(path))
        return real(path, *args, **kwargs)

    os.open = counting
    try:
        graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=roster(1))
    finally:
        os.open = real
    assert not [p for p in opened if p.endswith(".jpg")]


def test_the_command_says_a_limit_and_exits_1_unless_told_to_go_on(bank, tmp_path, monkeypatch, capsys):
    from exgen.cli import main

    monkeypatch.setattr(graders.walk, "MAX_LISTED", 5)
    monkeypatch.setenv("EXGEN_SECRET", SECRET.decode())
    issued = tmp_path / "issued"
    assert main(["generate", str(Path(__file__).parent.parent / "examples" / "tutorial1.yaml"), "--out", str(issued),
                 "--no-pdf"]) == 0
    handed = tmp_path / "handed"
    (handed / "scans").mkdir(parents=True)
    for i in range(20):
        (handed / "scans" / f"page{i}.png").write_bytes(b"\x89PNG")
    (handed / "A21001.yaml").write_bytes((issued / "students" / "A21001" / "answers.yaml").read_bytes())
    capsys.readouterr()
    assert main(["grade", str(issued), str(handed), "--out", str(tmp_path / "graded")]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--accept-limits" in err and "scans" in err
    assert not (tmp_path / "graded").exists()
    assert main(["grade", str(issued), str(handed), "--out", str(tmp_path / "graded"), "--accept-limits"]) == 0
    captured = capsys.readouterr()
    assert "WARNING: graded with --accept-limits" in captured.err and "limits reached: 1" in captured.out
    assert "1 graded" in captured.out


def test_past_the_names_limit_the_walk_stops_and_says_where(bank, tmp_path, monkeypatch):
    monkeypatch.setattr(graders.walk, "MAX_NAMES", 50)
    students = roster(2)
    (tmp_path / f"{students[0].id}.json").write_text(answers_of(bank, students[0]), encoding="utf-8")
    for folder in ("many", "more", "most"):
        (tmp_path / folder).mkdir()
        for i in range(40):
            (tmp_path / folder / f"{i}.txt").write_text("x")
    with pytest.raises(LimitsReached, match="more than 50 names in all: the walk stopped, and 2 folder"):
        graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students)
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path, roster=students, accept_limits=True)
    assert batch.sheets[0].status == GRADED and len(batch.limits) == 1
    reasons = listed(batch)
    assert "looked into only in part" in reasons["more"] and reasons["most"].startswith("a folder not looked into")
    assert sum(1 for p in batch.problems if p.path.parent.name == "many") == 40
