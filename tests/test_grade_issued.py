"""Grading against what was issued: the manifest's roster, secret and template versions are checked
before any mark; a mismatch names its cause, writes nothing and exits non-zero; --force grades with a
warning. Identity comes from where a file sits; every file is graded or listed with why not."""
import json
import re
from decimal import Decimal
from pathlib import Path

import pytest

from exgen.cli import main
from exgen.issue.assignment import Student, load_assignment
from exgen.issue.generate import generate
from exgen.issue.manifest import ManifestError, read_manifest
from exgen.issue.roster import load_roster
from exgen.load.bank import Bank, load_template
from graders.grade import grade_issued
from graders.results import GRADED, NO_SUBMISSION, PROBLEM_FILE

EXAMPLES = Path(__file__).parent.parent / "examples"
SECRET = "5b1f0e7c9a4d2e8f6a3c1b7d9e0f2a4c6b8d0e1f3a5c7e9b"
OTHER_SECRET = "e2c4a6f8b0d1e3f5a7c9b1d3f5e7a9c0b2d4f6e8a0c2e4f6"
STUDENTS = [Student("A21003", "Priya Ramasamy"), Student("A21005", "Chen Mei Ling"), Student("B30001", "Ana Silva")]


@pytest.fixture(scope="module")
def issued(tmp_path_factory, bank):
    """Tutorial 1 issued to three students (not the example roster), Markdown only."""
    root = tmp_path_factory.mktemp("issued")
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    generate(assignment, STUDENTS, bank, SECRET.encode(), root / "out", pdf=False, secret_source="$EXGEN_SECRET")
    return root / "out"


def keyed(issued: Path, student: str) -> str:
    """The student's answer form with every answer from their key typed in (the key grades 100 %)."""
    from exgen.issue.assignment import build_sheet
    from exgen.render.answer_form import answer_form

    bank = __import__("exgen.load.bank", fromlist=["load_bank"]).load_bank()
    manifest = read_manifest(issued)
    sheet = build_sheet(manifest.assignment, next(s for s in manifest.students if s.id == student), bank,
                        SECRET.encode())
    form = answer_form(sheet)
    for question in sheet.questions:
        for part_id, answer in question.variant.answers.items():
            form = form.replace(f'    {part_id}: ""', f'    {part_id}: "{answer.text}"', 1)
    return form


@pytest.fixture
def handed(issued, tmp_path):
    folder = tmp_path / "handed"
    folder.mkdir()
    for sid in ("A21003", "A21005"):
        (folder / f"{sid}.yaml").write_text(keyed(issued, sid), encoding="utf-8")
    return folder


def grade_cli(monkeypatch, *argv, secret=SECRET):
    if secret is None:
        monkeypatch.delenv("EXGEN_SECRET", raising=False)
    else:
        monkeypatch.setenv("EXGEN_SECRET", secret)
    return main(["grade", *map(str, argv)])


# ---- the secret ---------------------------------------------------------------------------------

def test_the_right_secret_grades_the_class_at_full_marks(issued, handed, tmp_path, monkeypatch, capsys):
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g") == 0
    assert "mean 100.0 %" in capsys.readouterr().out


def test_another_secret_stops_before_any_mark(issued, handed, tmp_path, monkeypatch, capsys):
    """Another secret marked a class that scored 100 % at a mean of 6 %, exit 0."""
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g", secret=OTHER_SECRET) == 1
    err = capsys.readouterr().err
    assert "not graded, nothing written" in err and "not the one these sheets were issued under" in err
    assert "$EXGEN_SECRET" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "g").exists()


def test_an_explicit_secret_file_beats_the_environment(issued, handed, tmp_path, monkeypatch, capsys):
    """With $EXGEN_SECRET set, --secret-file was silently ignored."""
    good, bad = tmp_path / "good.secret", tmp_path / "bad.secret"
    good.write_text(SECRET + "\n")
    bad.write_text(OTHER_SECRET + "\n")
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g", "--secret-file", good,
                     secret=OTHER_SECRET) == 0
    assert "--secret-file wins" in capsys.readouterr().err
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g2", "--secret-file", bad, secret=SECRET) == 1
    assert "bad.secret is not the one" in capsys.readouterr().err


def test_force_grades_with_a_warning_at_the_top_of_the_report(issued, handed, tmp_path, monkeypatch, capsys):
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g", "--force", secret=OTHER_SECRET) == 0
    captured = capsys.readouterr()
    assert "graded with --force" in captured.out and "WARNING" in captured.err
    report = (tmp_path / "g" / "report.md").read_text(encoding="utf-8")
    assert report.split("\n")[2].startswith("> **WARNING:** Graded with --force although the course secret")


# ---- the templates and the code they run ---------------------------------------------------------

def edited_bank(bank, template_id: str, edit) -> Bank:
    """The bank with one template's file edited (a copy: the bank itself is untouched)."""
    template = bank.get(template_id)
    copy = Path(__import__("tempfile").mkdtemp()) / template.path.name
    copy.write_text(edit(template.path.read_text(encoding="utf-8")), encoding="utf-8")
    return Bank({**bank.templates, template_id: load_template(copy)})


def one_more_step(text: str) -> str:
    """The first stepped range widened by one step (always a valid template)."""
    def widen(match):
        low, high, step = (Decimal(g) for g in match.groups())
        return f"{{min: {low}, max: {high + step}, step: {step}"

    return re.sub(r"\{min: ([\d.]+), max: ([\d.]+), step: ([\d.]+)", widen, text, count=1)


def test_an_edited_range_stops_grading_naming_the_template_and_file(issued, handed, bank):
    changed = edited_bank(bank, "belts.flat_belt_power", one_more_step)
    assert changed.get("belts.flat_belt_power").digest != bank.get("belts.flat_belt_power").digest
    with pytest.raises(ManifestError) as caught:
        grade_issued(read_manifest(issued), changed, SECRET.encode(), handed)
    assert "belts.flat_belt_power: its template file" in str(caught.value)
    assert "flat_belt_power.yaml changed" in str(caught.value)


def test_an_edited_answer_stops_grading(issued, handed, bank):
    changed = edited_bank(bank, "belts.drive_geometry", lambda t: t.replace("answer: L", "answer: L_crossed", 1))
    with pytest.raises(ManifestError, match="belts.drive_geometry: its template file"):
        grade_issued(read_manifest(issued), changed, SECRET.encode(), handed)


def test_comments_and_layout_of_a_template_change_nothing(issued, handed, bank):
    """A comment-only edit changed every student's sheet code."""
    changed = edited_bank(bank, "belts.flat_belt_power",
                          lambda t: "# an instructor's note\n" + t.replace(": ", ":    ", 3) + "\n# the end\n")
    assert changed.get("belts.flat_belt_power").digest == bank.get("belts.flat_belt_power").digest
    batch = grade_issued(read_manifest(issued), changed, SECRET.encode(), handed)
    assert [s.percent for s in batch.sheets if s.status == GRADED] == [100.0, 100.0]
    assert not batch.warnings and not any(s.code_mismatch for s in batch.sheets)


def test_a_changed_solver_file_stops_grading_naming_the_file(issued, handed, bank, tmp_path):
    """Editing a coefficient in exgen/solvers/belts.py marked right answers wrong without a warning. Here the
    manifest records another hash for it: as if the file had changed since the sheets were issued."""
    data = json.loads((issued / "manifest.json").read_text(encoding="utf-8"))
    data["files"]["exgen/solvers/belts.py"] = "0" * 64
    for record in data["templates"].values():
        record["version"] = "1" * 64
    edited = tmp_path / "manifest.json"
    edited.write_text(json.dumps(data), encoding="utf-8")
    with pytest.raises(ManifestError) as caught:
        grade_issued(read_manifest(edited), bank, SECRET.encode(), handed)
    message = str(caught.value)
    assert "exgen/solvers/belts.py changed" in message
    # the templates a changed file touches share one line, not one each (a whole tutorial's worth)
    line = next(p for p in message.split("; ") if "belts.flat_belt_power" in p)
    assert "belts.v_belt_count" in line and message.count("exgen/solvers/belts.py changed") == 1


# ---- the roster ---------------------------------------------------------------------------------

def test_the_roster_is_the_one_the_sheets_were_issued_to(issued, handed, tmp_path, monkeypatch):
    """Without --roster, grading fell back to the example roster: real students 'not on the roster'."""
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g") == 0
    rows = (tmp_path / "g" / "gradebook.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert [r.split(",")[0] for r in rows] == ["A21003", "A21005", "B30001"]
    assert rows[-1].endswith(NO_SUBMISSION)


def test_a_foreign_roster_stops_grading_naming_who_was_not_issued(issued, handed, tmp_path, monkeypatch, capsys):
    assert grade_cli(monkeypatch, issued, handed, "--out", tmp_path / "g", "--roster", EXAMPLES / "roster.csv") == 1
    err = capsys.readouterr().err
    assert "A21001 was not issued a sheet" in err and not (tmp_path / "g").exists()


def test_a_part_of_the_roster_grades_those_students(issued, handed, bank):
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), handed, roster=[Student("A21005")])
    assert [(s.student.id, s.student.name, s.status) for s in batch.sheets] == [("A21005", "Chen Mei Ling", GRADED)]


def test_the_assignment_file_is_not_what_grade_takes(tmp_path, monkeypatch, capsys):
    assert grade_cli(monkeypatch, EXAMPLES / "tutorial1.yaml", tmp_path, "--out", tmp_path / "g") == 1
    assert "give the folder `exgen generate` wrote" in capsys.readouterr().err


# ---- identity from where a file sits ------------------------------------------------------------

def test_a_file_naming_another_student_never_replaces_their_submission(issued, tmp_path, bank):
    """'H11.yaml' or 'A21005/...' saying `student: A21003` replaced A21003's own file; A21005 had none."""
    folder = tmp_path / "handed"
    (folder / "A21005").mkdir(parents=True)
    own = keyed(issued, "A21003")
    (folder / "A21003.yaml").write_text(own.replace('"168', '"1', 1), encoding="utf-8")  # graded, own file
    (folder / "A21005" / "answers.yaml").write_text(own, encoding="utf-8")               # A21003's, in A21005's place
    (folder / "H11.yaml").write_text(own, encoding="utf-8")                               # whose?
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), folder)
    by_id = {s.student.id: s for s in batch.sheets}
    assert by_id["A21003"].path.name == "A21003.yaml" and by_id["A21003"].status == GRADED
    assert by_id["A21005"].status == PROBLEM_FILE and by_id["A21005"].points == 0
    reasons = {p.path.name: p.reason for p in batch.problems}
    assert "sits in A21005's place" in reasons["answers.yaml"] and "student: A21003" in reasons["answers.yaml"]
    assert "cannot tell whose file" in reasons["H11.yaml"] and "student: A21003" in reasons["H11.yaml"]


def test_another_sheets_code_is_a_problem_file_naming_whose_it_is(issued, tmp_path, bank):
    folder = tmp_path / "handed"
    folder.mkdir()
    theirs = keyed(issued, "A21003").replace("student: \"A21003\"", "student: \"A21005\"")
    (folder / "A21005.yaml").write_text(theirs, encoding="utf-8")
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), folder)
    assert {s.student.id: s.status for s in batch.sheets}["A21005"] == PROBLEM_FILE
    assert "A21003's sheet has" in batch.problems[0].reason


def test_an_answer_file_for_another_assignment_is_reported_not_graded(issued, tmp_path, bank):
    """It was graded 0 as if it were this assignment's."""
    folder = tmp_path / "handed"
    folder.mkdir()
    other = keyed(issued, "A21003").replace('assignment: "bmcm2723-tut1"', 'assignment: "bmcm2723-tut2"')
    (folder / "A21003.yaml").write_text(other, encoding="utf-8")
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), folder)
    assert batch.sheets[0].status == PROBLEM_FILE
    assert "is for the assignment 'bmcm2723-tut2', not 'bmcm2723-tut1'" in batch.problems[0].reason


def test_learning_system_layouts_are_read(issued, tmp_path, bank):
    folder = tmp_path / "handed"
    (folder / "Chen Mei Ling_4711_assignsubmission_file_").mkdir(parents=True)
    (folder / "Chen Mei Ling_4711_assignsubmission_file_" / "answers.yaml").write_text(
        keyed(issued, "A21005"), encoding="utf-8")
    (folder / "Tutorial1_A21003_attempt_2026-12-04.yaml").write_text(keyed(issued, "A21003"), encoding="utf-8")
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), folder)
    assert [(s.student.id, s.status, s.percent) for s in batch.sheets[:2]] == [
        ("A21003", GRADED, 100.0), ("A21005", GRADED, 100.0)]


def test_every_file_is_graded_or_listed_with_why(issued, tmp_path, bank):
    """answers.yaml.txt, answers.pdf and a CSV named gradebook.csv were skipped without a word."""
    folder = tmp_path / "handed"
    (folder / "A21003").mkdir(parents=True)
    (folder / "A21003" / "answers.yaml.txt").write_text(keyed(issued, "A21003"), encoding="utf-8")
    (folder / "A21003" / "answers.pdf").write_bytes(b"%PDF-1.7\n")
    (folder / "gradebook.csv").write_text("student,total\n", encoding="utf-8")
    (folder / ".DS_Store").write_bytes(b"\0\0")
    (folder / "README").write_text("hello", encoding="utf-8")
    batch = grade_issued(read_manifest(issued), bank, SECRET.encode(), folder)
    assert batch.sheets[0].status == GRADED and batch.sheets[0].percent == 100.0  # the .yaml.txt
    reasons = {p.path.name: p.reason for p in batch.problems}
    assert set(reasons) == {"answers.pdf", "gradebook.csv", ".DS_Store", "README"}
    assert "not a readable PDF" in reasons["answers.pdf"] and "gradebook" in reasons["gradebook.csv"]
    assert "hidden" in reasons[".DS_Store"] and "no extension" in reasons["README"]


def test_a_misnamed_file_is_told_to_the_student_it_names(issued, tmp_path, monkeypatch, capsys):
    """A file named with a typo in the id ('A2103_tut1.csv', saying `student: A21003` inside) was listed in
    the report, but A21003's own feedback said 'No answer file was handed in'."""
    folder = tmp_path / "handed"
    folder.mkdir()
    (folder / "A2103_tut1.yaml").write_text(keyed(issued, "A21003"), encoding="utf-8")
    assert grade_cli(monkeypatch, issued, folder, "--out", tmp_path / "g") == 0
    feedback = (tmp_path / "g" / "feedback" / "A21003.md").read_text(encoding="utf-8")
    assert "An answer file that names you inside, A2103_tut1.yaml, was not graded" in feedback
    assert "name it A21003.yaml" in feedback and "No answer file was handed in" not in feedback
    assert "No answer file was handed in" in (tmp_path / "g" / "feedback" / "A21005.md").read_text(encoding="utf-8")
    gradebook = (tmp_path / "g" / "gradebook.csv").read_text(encoding="utf-8")
    assert next(line for line in gradebook.splitlines() if line.startswith("A21003")).endswith(",no submission")


def test_a_submissions_folder_that_is_not_there_is_said_plainly(issued, tmp_path, monkeypatch, capsys):
    assert grade_cli(monkeypatch, issued, tmp_path / "handed_in", "--out", tmp_path / "g") == 1
    assert capsys.readouterr().err.strip().endswith("handed_in: no such folder")
    (tmp_path / "answers.yaml").write_text("answers: {}\n")
    assert grade_cli(monkeypatch, issued, tmp_path / "answers.yaml", "--out", tmp_path / "g") == 1
    assert "answers.yaml: not a folder: give the folder holding the answer files" in capsys.readouterr().err
