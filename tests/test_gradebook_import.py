"""The Canvas and Moodle gradebooks exgen writes, imported by the systems' own rules (tests/gradebook_rules.py,
ports of canvas-lms's GradebookImporter and Moodle's grade/import/csv): a graded student's mark arrives, and
a student with nothing graded (no file, an unreadable one) keeps the grade they already had."""
import csv
import json

import pytest

from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.load.bank import load_bank
from graders.grade import grade_batch
from graders.report import write_results
from graders.results import GRADED

from gradebook_rules import CanvasCourse, CanvasStudent, MoodleUser, canvas_import, moodle_import

SECRET = b"g" * 32
ASSIGNMENT = Assignment("hw9", "Belt drives", (QuestionSpec("q1", "belts.flat_belt_power"),))
ROSTER = [Student("s001", "Ada Lovelace", "Ada@Uni.example"), Student("s002", "Ben Okri", "ben@uni.example"),
          Student("s003", "Cy Twombly", "cy@uni.example"), Student("s004", "Di Ng", "di@uni.example"),
          Student("s005", "Ed Kahn", "ed@uni.example")]
EXISTING = 3.5  # what every student has in the learning system before the import


@pytest.fixture(scope="module")
def graded(tmp_path_factory, bank):
    """s001 and s002 hand in their keys, s003 a file that cannot be read, s004 and s005 nothing."""
    folder = tmp_path_factory.mktemp("in")
    for student in ROSTER[:2]:
        sheet = build_sheet(ASSIGNMENT, student, bank, SECRET)
        answers = {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}
        data = {"student": student.id, "assignment": ASSIGNMENT.id, "code": sheet.code, "answers": answers}
        (folder / f"{student.id}.json").write_text(json.dumps(data), encoding="utf-8")
    (folder / "s003.yaml").write_text("answers: [unclosed\n", encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=ROSTER)
    paths = write_results(batch, tmp_path_factory.mktemp("out") / "graded", canvas_id="77")
    return batch, paths


@pytest.fixture(scope="module")
def bank():
    return load_bank()


def test_a_canvas_import_gives_the_graded_their_marks_and_keeps_everyone_elses_grade(graded):
    batch, paths = graded
    students = [CanvasStudent(100 + n, s.name, s.id, s.email) for n, s in enumerate(ROSTER)]
    course = CanvasCourse(students, 77, ASSIGNMENT.title, {s.id: str(EXISTING) for s in students})
    after = canvas_import(paths["canvas gradebook"].read_text(encoding="utf-8"), course)
    for sheet, student in zip(batch.sheets, students):
        if sheet.status == GRADED:
            assert float(after[student.id]) == pytest.approx(sheet.points)
        else:
            assert after[student.id] == str(EXISTING), sheet.student.id
    assert sum(s.status == GRADED for s in batch.sheets) == 2


def test_a_moodle_import_by_id_number_or_email_gives_the_graded_their_marks_and_keeps_everyone_elses(graded):
    batch, paths = graded
    # Moodle holds the emails in its own case: check_user_exists compares them case-insensitively
    users = [MoodleUser(200 + n, s.id, s.email.lower()) for n, s in enumerate(ROSTER)]
    before = {u.id: EXISTING for u in users}
    text = paths["moodle grades"].read_text(encoding="utf-8")
    for column, field in (("ID number", "useridnumber"), ("Email address", "useremail")):
        result = moodle_import(text, users, before, column, field, ASSIGNMENT.title)
        assert result.ok, result.error
        for sheet, user in zip(batch.sheets, users):
            expected = sheet.points if sheet.status == GRADED else EXISTING
            assert result.grades[user.id] == pytest.approx(expected), (field, sheet.student.id)


def test_exgens_own_gradebooks_still_list_everyone_blank_where_nothing_was_graded(graded):
    _, paths = graded
    for name in ("gradebook", "parts"):
        rows = {r["student"]: r for r in csv.DictReader(paths[name].open(encoding="utf-8"))}
        total = next(column for column in rows["s004"] if column.startswith("total"))
        assert set(rows) == {s.id for s in ROSTER} and rows["s004"][total] == ""


def test_the_report_names_who_is_left_out_of_the_learning_systems_gradebooks(graded):
    _, paths = graded
    report = paths["report"].read_text(encoding="utf-8")
    section = report.split("## Not in the Canvas and Moodle gradebooks", 1)[1].split("##", 1)[0]
    assert [line[2:6] for line in section.splitlines() if line.startswith("- ")] == ["s003", "s004", "s005"]


def test_a_blank_cell_would_clear_a_grade_in_both_systems_which_is_why_the_row_is_left_out():
    students = [CanvasStudent(1, "Ada", "s001", "ada@x")]
    course = CanvasCourse(students, 5, "T", {1: "4"})
    blank = "Student,ID,SIS User ID,SIS Login ID,Section,T (5)\nAda,,s001,ada@x,,\n"
    assert canvas_import(blank, course) == {1: ""}
    assert canvas_import("Student,ID,SIS User ID,SIS Login ID,Section,T (5)\n", course) == {1: "4"}
    users = [MoodleUser(1, "s001", "ada@x")]
    result = moodle_import("ID number,Email address,T\ns001,ada@x,\n", users, {1: 4.0}, "ID number", "useridnumber", "T")
    assert result.ok and result.grades == {1: None}


def test_one_row_moodle_cannot_match_aborts_its_whole_import():
    users = [MoodleUser(1, "s001", "ada@x"), MoodleUser(2, "s002", "ben@x")]
    text = "ID number,Email address,T\ns001,ada@x,5\ns999,zed@x,6\ns002,ben@x,7\n"
    result = moodle_import(text, users, {1: 1.0, 2: 2.0}, "ID number", "useridnumber", "T")
    assert not result.ok and result.grades == {1: 1.0, 2: 2.0} and "s999" in result.error
    by_email = moodle_import(text.replace("ada@x", "ADA@X"), users[:1], {1: 1.0}, "Email address", "useremail", "T")
    assert not by_email.ok  # ADA@X matches ada@x; zed@x matches no one and stops the import
    # a row with its mapped column empty goes to the user of the row above (studentid is kept across rows)
    kept = moodle_import("ID number,Email address,T\ns001,ada@x,5\ns002,,6\n", users, {1: 1.0, 2: 2.0},
                         "Email address", "useremail", "T")
    assert kept.ok and kept.grades == {1: 6.0, 2: 2.0}
