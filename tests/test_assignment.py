"""Assignment files are checked when loaded: every name that becomes a path, and every number."""
from pathlib import Path

import pytest

from exgen.errors import AssignmentError
from exgen.issue.assignment import load_assignment


def write(tmp_path: Path, questions: str) -> Path:
    path = tmp_path / "hw.yaml"
    path.write_text(f"assignment: hw1\ntitle: Homework\nquestions:\n{questions}", encoding="utf-8")
    return path


@pytest.mark.parametrize("slot", ["../../../../x", "/tmp/x", "a/b", "a\\\\b", "..", ".hidden", "", "q1\\n",
                                  "x" * 65, "q 1", "q1.svg/..", "\\u202eq1"])
def test_a_slot_that_is_not_a_plain_name_is_refused(tmp_path, bank, slot):
    path = write(tmp_path, f'  - {{template: belts.drive_geometry, slot: "{slot}"}}\n')
    with pytest.raises(AssignmentError, match="slot") as caught:
        load_assignment(path, bank)
    assert str(path) in str(caught.value) and "question 1 (line 4)" in str(caught.value)


@pytest.mark.parametrize("points", [".nan", ".inf", "-.inf", "0", "-2", "true", "'5'", "[5]"])
def test_points_must_be_a_positive_finite_number(tmp_path, bank, points):
    path = write(tmp_path, f"  - {{template: belts.drive_geometry, points: {points}}}\n")
    with pytest.raises(AssignmentError, match="points must be a positive, finite number"):
        load_assignment(path, bank)


def test_good_slots_and_points_load(tmp_path, bank):
    path = write(tmp_path, "  - {template: belts.drive_geometry, slot: Q1-a.2, points: 2.5}\n"
                           "  - belts.v_belt_count\n")
    assignment = load_assignment(path, bank)
    assert [(q.slot, q.points) for q in assignment.questions] == [("Q1-a.2", 2.5), ("q2", None)]
