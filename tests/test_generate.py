"""Issuing an assignment: files per student, byte-identical on regeneration, a manifest without secrets."""
import json
from pathlib import Path

import pytest

from exgen.draw.seeds import derive_seed
from exgen.issue.assignment import load_assignment
from exgen.issue.generate import generate
from exgen.issue.roster import load_roster
from exgen.load.versions import template_version

EXAMPLES = Path(__file__).parent.parent / "examples"
SECRET = b"a course secret used only by these tests"


@pytest.fixture(scope="module")
def issued(tmp_path_factory, bank):
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    students = load_roster(EXAMPLES / "roster.csv")[:3]
    first = tmp_path_factory.mktemp("first")
    second = tmp_path_factory.mktemp("second")
    generate(assignment, students, bank, SECRET, first)
    generate(assignment, students, bank, SECRET, second, jobs=2)  # parallel PDFs, same bytes
    return first, second, students


def files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_each_student_gets_a_sheet_a_form_and_a_key(issued):
    first, _, students = issued
    for student in students:
        folder = first / "students" / student.id
        assert {"sheet.md", "sheet.pdf", "answers.yaml"} <= {p.name for p in folder.iterdir()}
        assert (folder / "sheet.pdf").read_bytes().startswith(b"%PDF")
        assert {"key.md", "key.pdf"} <= {p.name for p in (first / "keys" / student.id).iterdir()}
    # the student folder can be handed out as it is: no key material in it
    assert not any("key" in p.name for p in (first / "students").rglob("*"))


def test_regenerating_gives_byte_identical_files_in_one_process_or_several(issued):
    first, second, _ = issued
    assert files(first) == files(second)


def test_two_students_get_different_numbers(issued):
    first, _, students = issued
    sheets = [(first / "students" / s.id / "sheet.md").read_text() for s in students]
    statements = [s.split("## Question 1", 1)[1] if "## Question 1" in s else s for s in sheets]
    assert len(set(statements)) == len(students)


def test_manifest_records_what_was_issued_but_no_secret_or_seed(issued, bank):
    first, _, students = issued
    text = (first / "manifest.json").read_text()
    manifest = json.loads(text)
    assert manifest["assignment"]["id"] == "bmcm2723-tut1"
    recorded = manifest["templates"]["belts.flat_belt_power"]
    assert recorded["version"] == template_version(bank.get("belts.flat_belt_power")).digest
    assert "exgen/solvers/belts.py" in recorded["code"] and "exgen/solvers/belts.py" in manifest["files"]
    assert [s["id"] for s in manifest["students"]] == [s.id for s in students]
    assert manifest["students"][0]["questions"][0]["seed_input"] == f"bmcm2723-tut1/{students[0].id}/q1"
    assert SECRET.decode() not in text and SECRET.hex() not in text
    seed = derive_seed(SECRET, "bmcm2723-tut1", students[0].id, "q1")
    assert str(seed) not in text


def test_keys_grade_themselves_at_full_marks(issued, bank, tmp_path):
    from graders.grade import grade_batch

    first, _, students = issued
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    from exgen.issue.assignment import build_sheet
    from exgen.render.answer_form import answer_form

    for student in students:
        sheet = build_sheet(assignment, student, bank, SECRET)
        form = answer_form(sheet)
        for question in sheet.questions:
            for part_id, answer in question.variant.answers.items():
                form = form.replace(f'    {part_id}: ""', f'    {part_id}: "{answer.text}"', 1)
        (tmp_path / f"{student.id}.yaml").write_text(form, encoding="utf-8")
    batch = grade_batch(assignment, bank, SECRET, tmp_path, roster=students)
    assert [r.percent for r in batch.sheets] == [100.0] * len(students)


def _children() -> set[int]:
    """Processes whose parent is this one (from /proc)."""
    import os

    found = set()
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:  # it ended while we looked
            continue
        if int(fields[1]) == os.getpid() and fields[0] != "Z":
            found.add(int(stat.parent.name))
    return found


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads the process table from /proc")
def test_parallel_generate_leaves_no_process_behind(bank, tmp_path):
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    students = load_roster(EXAMPLES / "roster.csv")[:2]
    before = _children()
    generate(assignment, students, bank, SECRET, tmp_path / "out", jobs=2)
    assert (tmp_path / "out" / "keys" / students[1].id / "key.pdf").exists()
    assert _children() <= before  # no worker, no resource tracker


def test_markdown_only_starts_no_process_and_keys_can_skip_their_pdf(bank, tmp_path, monkeypatch):
    import exgen.runtime.parallel

    def refuse(*args, **kwargs):
        raise AssertionError("Markdown alone needs no worker process")

    monkeypatch.setattr(exgen.runtime.parallel, "pool", refuse)
    assignment = load_assignment(EXAMPLES / "tutorial1.yaml", bank)
    students = load_roster(EXAMPLES / "roster.csv")[:2]
    generate(assignment, students, bank, SECRET, tmp_path / "md", pdf=False, jobs=4)
    made = {p.name for p in (tmp_path / "md").rglob("*")}
    assert {"sheet.md", "key.md"} <= made and not any(name.endswith(".pdf") for name in made)

    generate(assignment, students, bank, SECRET, tmp_path / "sheets", key_pdf=False)
    for student in students:
        assert (tmp_path / "sheets" / "students" / student.id / "sheet.pdf").exists()
        key = tmp_path / "sheets" / "keys" / student.id
        assert (key / "key.md").exists() and not (key / "key.pdf").exists()
