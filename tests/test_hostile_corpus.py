"""The hostile corpus (tests/hostile/): every answer ends in a verdict or a clear message under every
answer type, every file is read or refused with its reason, and a batch of all of them grades the one
good file in it, lists the rest, and writes small, clean pages."""
import json

import pytest

import hostile
from exgen.errors import SubmissionError
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from graders.answers import read_submission
from graders.grade import grade_batch
from graders.report import write_results
from graders.results import GRADED
from test_fuzz import MARKER, judge

SECRET = b"hostile corpus: b7e1c93f04a28d56"
ASSIGNMENT = Assignment("hw-hostile", "Hostile", (QuestionSpec("q1", "belts.flat_belt_power"),
                                                  QuestionSpec("q2", "balancing.static_balance")))
HIDDEN = ("\u202e", "\u2066", "\u200b", "\x00", "\x1b", "\u2028")


@pytest.mark.parametrize("text", hostile.strings(), ids=lambda t: repr(t[:24]) + f"({len(t)})")
def test_every_hostile_answer_gets_a_verdict_or_a_message(text):
    assert len(judge(text)) >= 6


@pytest.mark.parametrize("name", sorted(hostile.files()))
def test_every_hostile_file_is_read_or_refused_with_its_reason(tmp_path, name):
    path = tmp_path / name
    path.write_bytes(hostile.files()[name])
    try:
        submission = read_submission(path)
    except SubmissionError as exc:
        assert exc.detail.strip() and str(path) in str(exc) and len(exc.detail) < 300
        return
    assert isinstance(submission.answers, dict) and len(submission.warnings) <= 11


def test_a_batch_of_the_whole_corpus_grades_the_good_file_and_lists_the_rest(bank, tmp_path):
    corpus = hostile.files()
    roster = [Student("good")] + [Student(f"h{i:03d}") for i in range(len(corpus))]
    folder = tmp_path / "handed"
    folder.mkdir()
    sheet = build_sheet(ASSIGNMENT, roster[0], bank, SECRET)
    answers = {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}
    (folder / "good.json").write_text(json.dumps({"student": "good", "code": sheet.code, "answers": answers}),
                                      encoding="utf-8")
    for student, (name, data) in zip(roster[1:], sorted(corpus.items())):
        (folder / student.id).mkdir()
        (folder / student.id / name).write_bytes(data)
    batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=roster)
    by_id = {s.student.id: s for s in batch.sheets}
    assert by_id["good"].status == GRADED and by_id["good"].percent == pytest.approx(100)
    assert all(s.status for s in batch.sheets) and len(batch.sheets) == len(roster)
    paths = write_results(batch, tmp_path / "out")
    pages = [p.read_text(encoding="utf-8") for p in paths["feedback"].glob("*.md")] + [paths["report"].read_text()]
    assert max(len(page.encode()) for page in pages[:-1]) < 20_000
    assert not any(mark in page for page in pages for mark in HIDDEN)
    import os
    assert not os.path.exists(MARKER)


def test_hostile_answers_inside_a_well_formed_file_are_graded_one_by_one(bank, tmp_path):
    student = Student("s001")
    sheet = build_sheet(ASSIGNMENT, student, bank, SECRET)
    texts = [t for t in hostile.strings() if len(t) < 5000]
    folder = tmp_path / "handed"
    folder.mkdir()
    for start in range(0, len(texts), 20):
        chunk = texts[start:start + 20]
        answers = {q.slot: {p.id: chunk[i % len(chunk)] for i, p in enumerate(q.variant.template.parts)}
                   for q in sheet.questions}
        (folder / "s001.json").write_text(json.dumps({"student": "s001", "code": sheet.code, "answers": answers}),
                                          encoding="utf-8")
        batch = grade_batch(ASSIGNMENT, bank, SECRET, folder, roster=[student])
        assert batch.sheets[0].status == GRADED
        page = write_results(batch, tmp_path / "out")["feedback"].joinpath("s001.md").read_text(encoding="utf-8")
        assert len(page.encode()) < 20_000 and not any(mark in page for mark in HIDDEN)
