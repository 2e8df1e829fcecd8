"""Hostile submissions folders (tests/hostile_folders.py), drawn from seeds: every real file among the junk,
pipes, devices, deep folders, links and loops is graded, and every other entry is listed by name, without a
hang. EXGEN_HOSTILE_FOLDERS=N draws N folders (default 3, to keep the suite quick)."""
import os

import pytest

from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from graders.results import GRADED
from hostile_folders import hostile_folder
from test_collect import graded_in_time

SECRET = b"hostile folders: 8d0e4b71c3a9f256"
ASSIGNMENT = Assignment("hw4", "Belts", (QuestionSpec("q1", "belts.drive_geometry"),
                                          QuestionSpec("q2", "belts.flat_belt_power")))
ROSTER = [Student(f"K{31000 + i}", f"Student {chr(65 + i)} Lee") for i in range(8)]
FOLDERS = int(os.environ.get("EXGEN_HOSTILE_FOLDERS", "3"))


def key_answers(bank, student: Student) -> dict:
    sheet = build_sheet(ASSIGNMENT, student, bank, SECRET)
    return {"student": student.id, "code": sheet.code,
            "answers": {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}}


@pytest.mark.parametrize("seed", range(FOLDERS))
def test_every_real_file_is_graded_and_every_other_entry_listed(bank, tmp_path, seed):
    forms = {s.id: key_answers(bank, s) for s in ROSTER}
    expected = hostile_folder(tmp_path / "handed", seed, forms, {s.id: s.name for s in ROSTER})
    batch = graded_in_time(ASSIGNMENT, bank, SECRET, tmp_path / "handed", roster=ROSTER)
    for sheet in batch.sheets:
        assert (sheet.status, sheet.path) == (GRADED, expected.real[sheet.student.id]), sheet.warnings
        assert sheet.percent == pytest.approx(100)
    listed = {p.path for p in batch.problems}
    missing = [p for p in expected.others if p not in listed and expected.through.get(p) not in listed]
    assert not missing, f"not listed: {missing[:5]}"
    assert not listed & set(expected.real.values())
    assert not batch.limits
