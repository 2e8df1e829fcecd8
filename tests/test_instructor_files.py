"""An instructor's YAML files (assignments, templates in a --bank folder) are read with the caps answer
files are read with, and every mistake is one line at file:line:column, in plain words, with what to do."""
import subprocess
import sys
from pathlib import Path

import pytest

from exgen.errors import AssignmentError, BankError
from exgen.issue.assignment import load_assignment
from exgen.load.bank import _load_bank, load_template

BILLION_LAUGHS = "".join(f"{a}: &{a} [{', '.join(['*' + p] * 9 if p else ['lol'] * 9)}]\n"
                         for a, p in zip("abcdefghi", ["", *"abcdefgh"]))
HANG_GUARD = 120  # seconds: only a stall reaches it (it takes milliseconds)
GOOD = """\
assignment: tut1
title: Tutorial 1
questions:
  - template: belts.drive_geometry
  - template: belts.v_belt_count
    points: 4
"""


def write(tmp_path: Path, text: str, name="hw.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def refusal(bank, path: Path) -> str:
    with pytest.raises(AssignmentError) as caught:
        load_assignment(path, bank)
    return str(caught.value)


def test_the_billion_laughs_fails_fast_naming_the_file(bank, tmp_path):
    """A 372-byte YAML in a --bank folder stalled every command (7 levels: 7 s and 400 MB; 9 levels still
    running at 60 s, 2.7 GB)."""
    assert len(BILLION_LAUGHS) < 500
    path = write(tmp_path, "id: demo.bomb\n" + BILLION_LAUGHS, "bomb.yaml")
    done = subprocess.run([sys.executable, "-m", "exgen.cli", "--bank", str(tmp_path), "list"], capture_output=True,
                          text=True, timeout=HANG_GUARD)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert f"{path}:5:4: more than 2,000 entries from here down (aliases counted" in done.stderr
    with pytest.raises(BankError, match="bomb.yaml:5:4: more than 2,000 entries"):
        _load_bank((tmp_path,))
    with pytest.raises(AssignmentError, match=r"hw\.yaml:4:4: more than 2,000 entries"):
        load_assignment(write(tmp_path, BILLION_LAUGHS), bank)


@pytest.mark.parametrize("text, expected", [
    ("a: &a [1, *a]\n", "2:4: an alias (*name) refers to the value it is inside: a loop"),
    ("a: " + "[" * 40 + "]" * 40 + "\n", "2:19: nested more than 16 levels deep"),
    ("a:\n" + "".join(f"  k{i}: {i}\n" for i in range(2100)), "more than 2,000 entries"),
])
def test_instructor_files_have_the_caps_of_answer_files(tmp_path, text, expected):
    with pytest.raises(BankError, match=expected.replace("(", r"\(").replace(")", r"\)").replace("*", r"\*")):
        load_template(write(tmp_path, "id: demo.x\n" + text if not text.startswith("a:\n") else text, "t.yaml"))


def test_a_huge_template_file_is_refused_before_it_is_read(tmp_path):
    path = tmp_path / "t.yaml"
    with path.open("wb") as handle:
        handle.write(b"id: x\n")
        handle.truncate(64 * 1024 * 1024)
    with pytest.raises(BankError, match="more than the 256 KiB allowed"):
        load_template(path)


@pytest.mark.parametrize("text, place, words", [
    ('assignment: t1\ntitle: "Tutorial 1\ncourse: X\nquestions:\n  - template: a\n', "2:8", "a quote opened here is never closed"),
    ('assignment: "t1\ntitle: x\nquestions:\n  - template: "belts.x"\n', "1:13", "a quote opened here is not closed on its line"),
    ("assignment: t1\nquestions:\n\t- template: a\n", "3:1", "a tab character: YAML indents with spaces only"),
    ("assignment: t1\nquestions:\n  - template: a\n   points: 3\n", "4:4", "indented differently from the lines above it"),
    ("assignment: t1\ntitle: Tutorial 1: Belts\n", "2:18", 'a value holding a colon must be in quotes (title: "Tutorial 1: Belts")'),
    ("assignment: t1\ntitle\nquestions: []\n", "2:1", "this line is not `key: value` (a colon missing after the key?)"),
    ("assignment: t1\nquestions: [a, b\ntitle: x\n", "2:12", "a list opened with [ here is not closed with ]"),
    ("assignment: *t1\n", "1:13", "a value starting with * is read as a reference"),
    ("assignment: @t1\n", "1:13", "a value cannot start with @: put the value in quotes"),
    ('title: "a\\qb"\n', "1:11", "a backslash inside \"double quotes\" starts an escape"),
    ("assignment: a\n---\nassignment: b\n", "2:1", "a second document starts here (---): an assignment file holds one"),
    ("assignment: !!python/object/apply:os.system [ls]\n", "1:13", "a tag (!name) that an assignment file cannot have"),
])
def test_yaml_syntax_errors_are_said_in_plain_words_with_their_place(bank, tmp_path, text, place, words):
    """YAML syntax errors quoted `in "<unicode string>", line 5` with no word on what to fix."""
    path = write(tmp_path, text)
    message = refusal(bank, path)
    assert message.startswith(f"{path}:{place}: not valid YAML: ") and words in message, message
    assert "<unicode string>" not in message and "\n" not in message


def test_a_duplicate_key_is_an_error_not_the_last_value(bank, tmp_path):
    """A duplicate key silently took the last value."""
    path = write(tmp_path, GOOD + "title: Tutorial 2\n")
    assert refusal(bank, path) == (f"{path}:7:1: `title:` appears twice in one place (first on line 2): YAML would "
                                   "keep only the last; keep one")
    path = write(tmp_path, GOOD.replace("    points: 4\n", "    points: 4\n    points: 5\n"))
    assert refusal(bank, path).startswith(f"{path}:7:5: `points:` appears twice in one place (first on line 6)")


def test_a_template_with_a_duplicate_key_is_refused(tmp_path):
    text = (Path(__file__).parent.parent / "banks" / "ch1_belts" / "flat_belt_power.yaml").read_text(encoding="utf-8")
    with pytest.raises(BankError, match=r"t\.yaml:\d+:1: `title:` appears twice in one place"):
        load_template(write(tmp_path, text + "title: Another title\n", "t.yaml"))


def test_a_missing_assignment_id_says_what_to_write(bank, tmp_path):
    """A missing `assignment:` read "must be an id of letters...", as if one had been given."""
    path = write(tmp_path, GOOD.replace("assignment: tut1\n", ""))
    assert refusal(bank, path).startswith(f"{path}: no `assignment:` line: give the assignment an id, such as "
                                          "`assignment: tut1-belts`")
    path = write(tmp_path, GOOD.replace("assignment: tut1", "assignment: tut 1"))
    assert refusal(bank, path).startswith(f"{path}:1:1: `assignment: tut 1` is not an id")


def test_questions_are_counted_from_one_with_their_lines(bank, tmp_path):
    """Assignment errors said `questions[3]` with no line, and read as counted from 0."""
    path = write(tmp_path, "assignment: tut1\nquestions:\n  - template: belts.drive_geometry\n"
                           "  - template: belts.no_such\n  - {template: belts.drive_geometry, pionts: 3}\n"
                           "  - slot: q1\n    template: belts.v_belt_count\n  - points: 2\n")
    lines = refusal(bank, path).splitlines()
    assert lines[0] == f"4 problems in {path}:"
    assert lines[1].startswith(f"  {path}:4:5: question 2 (line 4): no template with id 'belts.no_such'.")
    assert lines[2] == (f"  {path}:5:38: question 3 (line 5): unknown key `pionts` (did you mean `points`?); a "
                        "question has points, slot, template")
    assert lines[3] == f"  {path}:6:5: question 4 (line 6): slot 'q1' is already question 1's; give each question its own"
    assert lines[4].startswith(f"  {path}:8:5: question 5 (line 8): no `template:`; give the template's id")


@pytest.mark.parametrize("text, expected", [
    ("questionz: []\n", "1:1: unknown key `questionz` (did you mean `questions`?)"),
    ("questions: belts.drive_geometry\n", "2:1: `questions:` must be a list"),
    ("questions: []\n", "2:1: no questions: list the templates under `questions:`"),
    ("roster: [a.csv]\nquestions: [belts.drive_geometry]\n", "2:1: `roster:` must be a file name"),
])
def test_other_assignment_mistakes_have_a_place_and_a_hint(bank, tmp_path, text, expected):
    path = write(tmp_path, "assignment: tut1\n" + text if not text.startswith("questionz") else
                 "assignment: tut1\nquestions: [belts.drive_geometry]\n" + text)
    message = refusal(bank, path)
    assert expected.split(": ", 1)[1] in message, message
    assert f"{path}:" in message


def test_a_good_assignment_still_loads(bank, tmp_path):
    assignment = load_assignment(write(tmp_path, GOOD), bank)
    assert [(q.slot, q.template, q.points) for q in assignment.questions] == [
        ("q1", "belts.drive_geometry", None), ("q2", "belts.v_belt_count", 4.0)]


def test_every_packaged_template_and_example_passes_the_caps(bank):
    examples = Path(__file__).parent.parent / "examples"
    assert len(bank) >= 77
    for path in sorted(examples.glob("*.yaml")):
        assert load_assignment(path, bank).questions
