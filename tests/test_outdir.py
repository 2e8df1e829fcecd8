"""Never half-write: generate and grade build their output beside the target and swap it in when
complete; an error or interruption leaves the previous output whole; only exgen's own outputs are replaced."""
from pathlib import Path

import pytest

import exgen.generate as generate_module
from exgen.assignment import Student, load_assignment
from exgen.generate import generate
from exgen.outdir import MARKER, OutputError
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
