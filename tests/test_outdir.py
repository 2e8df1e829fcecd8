"""Never half-write: generate and grade build their output beside the target and swap it in when
complete; an error or interruption leaves the previous output whole; only exgen's own outputs are replaced."""
import os
from pathlib import Path

import pytest

import exgen.issue.generate as generate_module
from exgen.issue.assignment import Student, load_assignment
from exgen.issue.generate import generate
from exgen.runtime.outdir import MARKER, OutputError
from graders import report
from graders.grade import grade_batch
from graders.report import write_results

EXAMPLES = Path(__file__).parent.parent / "examples"
SECRET = b"outdir tests: 7c2e9a41f0b3d5e8"
ROSTER_A = [Student("A1"), Student("A2")]
ROSTER_B = [Student("B1")]


def snapshot(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture
def tutorial(bank):
    return load_assignment(EXAMPLES / "tutorial1.yaml", bank)


def test_a_rerun_for_another_roster_leaves_no_stale_students(tutorial, bank, tmp_path):
    out = tmp_path / "out"
    generate(tutorial, ROSTER_A, bank, SECRET, out, pdf=False)
    (out / "students" / "A1" / "sheet.pdf").write_bytes(b"%PDF stale")  # as a PDF run would have left
    generate(tutorial, ROSTER_B, bank, SECRET, out, pdf=False)
    assert sorted(p.name for p in (out / "students").iterdir()) == ["B1"]
    assert sorted(p.name for p in (out / "keys").iterdir()) == ["B1"]
    assert not list(out.rglob("sheet.pdf")) and (out / MARKER).is_file()
    assert [p.name for p in tmp_path.iterdir()] == ["out"]  # no temporary folder left behind


def test_an_interrupted_run_leaves_the_previous_output_whole(tutorial, bank, tmp_path, monkeypatch):
    out = tmp_path / "out"
    generate(tutorial, ROSTER_A, bank, SECRET, out, pdf=False)
    before = snapshot(out)
    real = generate_module.write_student
    calls = []

    def dies_on_the_second(sheet, folder, *options):
        calls.append(sheet.student.id)
        if len(calls) == 2:
            raise KeyboardInterrupt
        real(sheet, folder, *options)

    monkeypatch.setattr(generate_module, "write_student", dies_on_the_second)
    with pytest.raises(KeyboardInterrupt):
        generate(tutorial, [Student("C1"), Student("C2")], bank, b"another secret: 91be4c07d2f5a3e6", out, pdf=False)
    assert snapshot(out) == before
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


@pytest.mark.parametrize("make", ["file", "foreign folder", "grade output"])
def test_a_folder_exgen_did_not_make_for_this_is_never_replaced(tutorial, bank, tmp_path, make):
    out = tmp_path / "out"
    if make == "file":
        out.write_text("precious")
    else:
        out.mkdir()
        (out / "thesis.tex").write_text("precious")
        if make == "grade output":
            (out / MARKER).write_text('{"kind": "grade"}')
    with pytest.raises(OutputError) as caught:
        generate(tutorial, ROSTER_A, bank, SECRET, out, pdf=False)
    assert str(out) in str(caught.value)
    assert (out.read_text() if make == "file" else (out / "thesis.tex").read_text()) == "precious"


def test_an_empty_folder_may_be_the_output(tutorial, bank, tmp_path):
    (tmp_path / "out").mkdir()
    generate(tutorial, ROSTER_B, bank, SECRET, tmp_path / "out", pdf=False)
    assert (tmp_path / "out" / "manifest.json").is_file()


def test_an_interrupted_grade_leaves_the_previous_results_whole(tutorial, bank, tmp_path, monkeypatch):
    """An interrupted grade left a new gradebook beside old feedback."""
    handed = tmp_path / "handed"
    handed.mkdir()
    batch = grade_batch(tutorial, bank, SECRET, handed, roster=ROSTER_A)
    out = tmp_path / "graded"
    write_results(batch, out)
    before = snapshot(out)

    def dies(*args):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(report, "write_gradebook", dies)
    with pytest.raises(OSError):
        write_results(grade_batch(tutorial, bank, SECRET, handed, roster=ROSTER_B), out)
    assert snapshot(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["graded", "handed"]


def test_grading_results_replace_only_grading_results(tutorial, bank, tmp_path):
    handed = tmp_path / "handed"
    handed.mkdir()
    batch = grade_batch(tutorial, bank, SECRET, handed, roster=ROSTER_A)
    generate(tutorial, ROSTER_B, bank, SECRET, tmp_path / "issued", pdf=False)
    with pytest.raises(OutputError, match="holds the output of `exgen generate`"):
        write_results(batch, tmp_path / "issued")


def test_staging_folders_of_earlier_runs_are_removed_or_named(tmp_path):
    """Folders of interrupted runs stayed for ever (up to 21 MB, one with a complete-looking gradebook),
    and nothing cleaned or mentioned them."""
    import json
    import subprocess
    import sys

    from exgen.runtime.outdir import WRITER, tidy

    target = tmp_path / "out"
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    dead = int(ended.stdout)
    folders = {
        "dead": tmp_path / f".out.writing-{dead}-abc123",
        "dead, aside": tmp_path / f".out.old-{dead}-def456",
        "running": tmp_path / f".out.writing-{os.getppid()}-ghi789",
        "elsewhere": tmp_path / f".out.writing-{dead}-jkl012",
        "earlier": tmp_path / ".out.writing-mno345",
    }
    for folder in folders.values():
        folder.mkdir()
        (folder / "gradebook.csv").write_text("student,total\n")
    (folders["elsewhere"] / WRITER).write_text(json.dumps({"pid": dead, "host": "another-computer.example"}))
    target.mkdir()
    notes = tidy(target)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["out", folders["running"].name, folders["elsewhere"].name, folders["earlier"].name])
    assert f"removed {folders['dead']}, left by an interrupted run (process {dead}, no longer running)" in notes
    assert any(str(folders["dead, aside"]) in n and "removed" in n for n in notes)
    assert any(str(folders["running"]) in n and "still running" in n for n in notes)
    assert any(str(folders["elsewhere"]) in n and "another-computer.example" in n for n in notes)
    assert any(str(folders["earlier"]) in n and "earlier exgen" in n for n in notes)
    assert len(notes) == 5


def test_the_output_is_swapped_in_one_step_where_the_system_can(tmp_path):
    from exgen.runtime.outdir import _exchange

    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "old").write_text("old")
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "new").write_text("new")
    if not _exchange(tmp_path / "a", tmp_path / "b"):
        pytest.skip("this system or file system cannot exchange two folders in one step")
    assert [p.name for p in (tmp_path / "a").iterdir()] == ["new"] and [p.name for p in (tmp_path / "b").iterdir()] == ["old"]
