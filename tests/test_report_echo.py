"""What a student typed is echoed in feedback and reports only short, on one line, without characters
that hide or reorder text; a page stays small whatever a file holds."""
import json

import pytest

from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from graders.grade import grade_batch
from graders.report import write_results

SECRET = b"echo tests: a course secret of no value"
ASSIGNMENT = Assignment("hw9", "Balancing", (QuestionSpec("q1", "balancing.static_balance"),))
STUDENT = Student("s001")


def feedback_for(bank, tmp_path, answers: dict, name="s001.json") -> tuple[str, str]:
    sheet = build_sheet(ASSIGNMENT, STUDENT, bank, SECRET)
    folder = tmp_path / "in"
    folder.mkdir()
    data = {"student": "s001", "assignment": "hw9", "code": sheet.code, "answers": answers}
    (folder / name).write_text(json.dumps(data), encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=[STUDENT])
    paths = write_results(batch, tmp_path / "out")
    return (paths["feedback"] / "s001.md").read_text(encoding="utf-8"), paths["report"].read_text(encoding="utf-8")


def test_many_unknown_parts_make_one_short_note(bank, tmp_path):
    """Every unknown part was a note of its own: a 1 MB feedback page from one file."""
    answers = {"q1": {f"part{i}" + "x" * 60: "1" for i in range(1500)}}
    page, _ = feedback_for(bank, tmp_path, answers)
    assert len(page.encode()) < 8_000
    assert "and 1495 more" in page


def test_many_unknown_questions_make_one_short_note(bank, tmp_path):
    answers = {f"question{i}": {"a": "1"} for i in range(900)}
    page, _ = feedback_for(bank, tmp_path, answers)
    assert len(page.encode()) < 8_000 and "and 895 more" in page


def test_a_huge_polar_answer_is_not_echoed_whole(bank, tmp_path):
    """The polar reader's message quoted the whole answer (1,000,000 characters); others cut at 80."""
    page, _ = feedback_for(bank, tmp_path, {"q1": {"a": "9" * 200_000}})
    assert len(page.encode()) < 8_000 and "format problem" in page


@pytest.mark.parametrize("hidden", ["\u202e", "\u2066", "\u200f", "\u200b", "\x1b", "\u2028", "\ufeff"])
def test_bidi_and_control_characters_never_reach_a_page(bank, tmp_path, hidden):
    text = f"5{hidden}72.9 kg mm at 48 deg"
    page, report = feedback_for(bank, tmp_path, {"q1": {"a": text, f"x{hidden}y": "1"}, f"q{hidden}9": {"a": "1"}},
                                name=f"s001{hidden}.json")
    assert hidden not in page and hidden not in report


def test_a_file_name_in_the_report_is_shown_safely(bank, tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / "s\u202egpj.exe.yaml").write_text("{", encoding="utf-8")
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=[STUDENT])
    report = write_results(batch, tmp_path / "out")["report"].read_text(encoding="utf-8")
    assert "\u202e" not in report and "gpj.exe.yaml" in report
