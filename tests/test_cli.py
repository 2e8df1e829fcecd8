"""The `exgen` command as a user types it: output, exit status, and errors without tracebacks."""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from exgen.cli import main

EXAMPLES = Path(__file__).parent.parent / "examples"
EXAMPLE_1_5 = ["--set", "d1=0.5m", "--set", "d2=1.2m", "--set", "X=3.6m", "--set", "N1=200rpm", "--set", "mu=0.3",
               "--set", "rho=2812.5kg/m^3", "--set", "A=320mm^2", "--set", "E=300MN/m^2", "--set", "sigma=6.25MPa"]


def test_list(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "belts.flat_belt_power" in out and "[Example 1.5]" in out


def test_show_is_reproducible_by_seed(capsys):
    assert main(["show", "belts.flat_belt_power", "--seed", "7"]) == 0
    first = capsys.readouterr().out
    assert main(["show", "belts.flat_belt_power", "--seed", "7"]) == 0
    assert capsys.readouterr().out == first and "(a)" in first


def test_show_writes_the_figures_to_look_at(tmp_path, capsys):
    """A template author had no way to see a figure short of issuing an assignment."""
    from exgen.figures import figure_svg, key_figure_svgs
    from exgen.load.bank import load_bank
    from exgen.solve.variant import make_variant

    assert main(["show", "balancing.static_balance", "--seed", "3", "--key", "--figures", str(tmp_path)]) == 0
    variant = make_variant(load_bank().get("balancing.static_balance"), 3)
    assert (tmp_path / "q1.svg").read_text(encoding="utf-8") == figure_svg(variant)
    ((name, key_svg),) = key_figure_svgs(variant)
    assert (tmp_path / f"q1-{name}.svg").read_text(encoding="utf-8") == key_svg
    assert f"figure: {tmp_path / 'q1.svg'}" in capsys.readouterr().err
    assert main(["show", "flywheels.punching_press", "--seed", "3", "--figures", str(tmp_path / "none")]) == 1
    assert capsys.readouterr().err.strip() == "exgen: flywheels.punching_press has no figure on its sheet"


def test_solve_prints_example_1_5(capsys):
    assert main(["solve", "belts.flat_belt_power", *EXAMPLE_1_5]) == 0
    out = capsys.readouterr().out
    for expected in ("168.8\u00b0", "5.236 m/s", "6.146 kW", "6.070 kW", "5.997 kW", "289.8 N\u00b7m", "695.6 N\u00b7m"):
        assert expected in out


def test_solve_json_has_every_part_value_and_unit(capsys):
    assert main(["solve", "belts.flat_belt_power", "--json", *EXAMPLE_1_5]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["parts"]["a"]["unit"] == "deg" and data["parts"]["a"]["value"] == pytest.approx(168.8415, rel=1e-6)
    assert data["parts"]["c"]["unit"] == "kW" and data["parts"]["c"]["value"] == pytest.approx(6.14594, rel=1e-5)
    density = next(q for q in data["derived"] if q["what"] == "belt density")
    assert density == {"what": "belt density", "value": pytest.approx(2812.5), "unit": "kg/m^3",
                       "plausible": [1000, 1500], "ok": False}


@pytest.mark.parametrize("argv, message", [
    (["show", "belts.nope"], "no template with id 'belts.nope'"),
    (["solve", "belts.flat_belt_power", "--set", "d1=0.5m"], "give a value for d2"),
    (["solve", "belts.flat_belt_power", *EXAMPLE_1_5, "--set", "d1=0.5kg"], "d1=0.5kg: 'kg' is a mass, but a length is asked"),
    (["generate", str(EXAMPLES / "missing.yaml"), "--out", "x"], "missing.yaml: no such file"),
])
def test_user_errors_are_one_line_without_traceback(capsys, argv, message):
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert err.startswith("exgen: ") and message in err and "Traceback" not in err


@pytest.mark.parametrize("argv, message", [
    (["show", "belts.flat_belt_power", "--seed", "-5"], "--seed: -5 is out of range"),
    (["show", "belts.flat_belt_power", "--seed", str(2**65)], "out of range"),
    (["show", "belts.flat_belt_power", "--seed", "seven"], "'seven' is not a whole number"),
    (["validate", "belts.drive_geometry", "--seeds", "0"], "--seeds: 0 is out of range"),
    (["generate", str(EXAMPLES / "tutorial1.yaml"), "--out", "x", "--jobs", "0"], "--jobs: 0 is out of range"),
])
def test_usage_mistakes_are_one_line_and_not_success(capsys, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)  # nothing may be written, but if it were, not into the repository
    with pytest.raises(SystemExit) as exited:
        main(argv)
    assert exited.value.code == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_a_bank_folder_that_does_not_exist_is_an_error(capsys, tmp_path, monkeypatch):
    monkeypatch.delenv("EXGEN_BANKS", raising=False)
    assert main(["--bank", str(tmp_path / "nonexistent"), "list"]) == 1
    assert "nonexistent (from --bank): no such folder of templates" in capsys.readouterr().err
    monkeypatch.setenv("EXGEN_BANKS", str(tmp_path / "gone"))
    assert main(["list"]) == 1
    assert "gone (from $EXGEN_BANKS)" in capsys.readouterr().err


def test_a_system_error_is_one_line_naming_the_path(capsys, tmp_path, monkeypatch):
    monkeypatch.setenv("EXGEN_SECRET", "3f9a1c7e52b8d04e6a1f9c3b7d2e8a45")
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    assert main(["generate", str(EXAMPLES / "tutorial1.yaml"), "--out", str(blocker / "out"), "--no-pdf"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("exgen: ") and "a-file" in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("where", ["secret folder", "out is a file", "out is not exgen's"])
def test_expected_failures_of_generate_are_one_line(capsys, tmp_path, monkeypatch, where):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    (tmp_path / "secrets").mkdir()
    (tmp_path / "a-file").write_text("x")
    (tmp_path / "thesis").mkdir()
    (tmp_path / "thesis" / "chapter1.tex").write_text("x")
    argv = {"secret folder": ["--out", str(tmp_path / "out"), "--secret-file", str(tmp_path / "secrets")],
            "out is a file": ["--out", str(tmp_path / "a-file")],
            "out is not exgen's": ["--out", str(tmp_path / "thesis")]}[where]
    monkeypatch.setenv("EXGEN_SECRET", "3f9a1c7e52b8d04e6a1f9c3b7d2e8a45") if where != "secret folder" else None
    assert main(["generate", str(EXAMPLES / "tutorial1.yaml"), "--no-pdf", *argv]) == 1
    err = capsys.readouterr().err
    assert err.startswith("exgen: ") and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert {"secret folder": "is a folder, not a secret file", "out is a file": "is not a folder",
            "out is not exgen's": "has files exgen did not write"}[where] in err
    assert (tmp_path / "thesis" / "chapter1.tex").read_text() == "x"


def test_generate_then_grade(tmp_path, capsys, monkeypatch):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    work = tmp_path / "course"
    shutil.copytree(EXAMPLES, work)
    assert main(["generate", str(work / "tutorial1.yaml"), "--out", str(tmp_path / "out"), "--no-pdf"]) == 0
    assert (work / "course.secret").is_file()  # created on first use
    submissions = tmp_path / "returned"
    submissions.mkdir()
    shutil.copy(tmp_path / "out" / "students" / "A21001" / "answers.yaml", submissions / "A21001.yaml")
    (submissions / "A21002.yaml").write_bytes(b"\x00\x01 not yaml")
    capsys.readouterr()
    assert main(["grade", str(tmp_path / "out"), str(submissions), "--out", str(tmp_path / "graded")]) == 0
    out = capsys.readouterr().out
    assert "1 unreadable file" in out and "no submission" in out
    gradebook = (tmp_path / "graded" / "gradebook.csv").read_text()
    assert "A21001" in gradebook and "A21006" in gradebook


def test_grade_without_the_secret_says_so(tmp_path, capsys, monkeypatch):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    work = tmp_path / "course"
    shutil.copytree(EXAMPLES, work)
    assert main(["generate", str(work / "tutorial1.yaml"), "--out", str(tmp_path / "out"), "--no-pdf"]) == 0
    (work / "course.secret").unlink()
    assert main(["grade", str(tmp_path / "out"), str(tmp_path), "--out", str(tmp_path / "g")]) == 1
    err = capsys.readouterr().err
    assert "no course secret" in err and "course.secret does not exist" in err


def test_validate_passes_on_the_bank(capsys):
    assert main(["validate", "belts.drive_geometry", "--seeds", "30"]) == 0
    assert "1 of 1 template(s) valid" in capsys.readouterr().out


@pytest.mark.parametrize("argv", [["list"], ["show", "gears.simple_train", "--seed", "3", "--key"]])
def test_a_reader_that_closes_early_ends_the_command_quietly(argv):
    """`exgen list | head`: the reader is gone before anything is written, so every write meets a closed pipe."""
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        done = subprocess.run([sys.executable, "-c", "import sys; from exgen.cli import main; sys.exit(main())", *argv],
                              stdout=write_end, stderr=subprocess.PIPE, text=True, timeout=120)
    finally:
        os.close(write_end)
    assert "Traceback" not in done.stderr and "Broken pipe" not in done.stderr and "Exception" not in done.stderr
    assert done.returncode == 141  # as a shell reports a process that SIGPIPE ended


def test_solve_says_what_a_mistake_close_to_the_answer_means(capsys):
    """'the mistake ... lands within 3 times 1 % of the answer' left a user of `exgen solve` guessing."""
    argv = ["solve", "belts.flat_belt_power"] + [a for s in (
        "d1=0.5m d2=1.2m X=3.6m N1=200rpm mu=0.3 rho=2812.5kg/m^3 A=320mm^2 E=300MN/m^2 sigma=6.25MPa").split()
        for a in ("--set", s)]
    assert main(argv) == 0
    err = capsys.readouterr().err.splitlines()
    close = [i for i, line in enumerate(err) if "lands within" in line]
    assert close and err[close[-1] + 1] == "  (a mistake that close is marked right: for these values the grader " \
        "cannot tell it from the answer; sheets never draw such values)"


@pytest.mark.parametrize("typed, meant", [("belts.flat_belt_powr", "belts.flat_belt_power"),
                                          ("gear.simple_trian", "gears.simple_train")])
def test_a_mistyped_template_id_is_answered_with_the_one_meant(typed, meant, capsys):
    """'belts.flat_belt_powr' got only 'Run `exgen list` to see them', though one letter was missing."""
    assert main(["show", typed]) == 1
    err = capsys.readouterr().err
    assert f"Did you mean: {meant}" in err and err.count("\n") == 1


@pytest.mark.parametrize("argv, message", [
    (["generate", "examples/no_such.yaml", "--out", "x"], "examples/no_such.yaml: no such file"),
    (["generate", "examples/tutorial1.yaml", "--roster", "no_such.csv", "--out", "x"], "no_such.csv: no such roster file"),
])
def test_a_file_that_is_not_there_is_said_plainly(argv, message, capsys, tmp_path, monkeypatch):
    """'cannot read: [Errno 2] No such file or directory: ...' told a newcomer what Python thought."""
    monkeypatch.chdir(Path(__file__).parent.parent)
    assert main([*argv[:-1], str(tmp_path / argv[-1])]) == 1
    err = capsys.readouterr().err
    assert message in err and "Errno" not in err and err.count("\n") == 1
