"""`exgen export` from an assignment file or template ids: the file written, what is left out said once,
and the pool keyed by the course secret (another secret, other numbers; the same, the same bytes)."""
import zipfile

import pytest

from exgen.cli import main

SECRET = "5f0c2d9a8b7e6f1a3c4d5e6f708192a3b4c5d6e7f8091a2b"


@pytest.fixture(autouse=True)
def secret(monkeypatch):
    monkeypatch.setenv("EXGEN_SECRET", SECRET)


def test_export_moodle_from_an_assignment(tmp_path, capsys):
    out = tmp_path / "t1.xml"
    assert main(["export", "moodle", "examples/tutorial1.yaml", "--variants", "3", "--out", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert text.startswith("<?xml") and text.count('<question type="category">') == 4
    assert text.count("<idnumber>") == 4 * 3
    assert "4 question(s) x 3 variant(s) as moodle" in capsys.readouterr().out


def test_the_pool_is_the_same_for_the_same_secret_and_different_for_another(tmp_path, monkeypatch):
    args = ["export", "qti", "belts.flat_belt_power", "--variants", "2"]
    assert main(args + ["--out", str(tmp_path / "a.zip")]) == 0
    assert main(args + ["--out", str(tmp_path / "b.zip")]) == 0
    assert (tmp_path / "a.zip").read_bytes() == (tmp_path / "b.zip").read_bytes()
    monkeypatch.setenv("EXGEN_SECRET", SECRET[::-1] + "x9")
    assert main(args + ["--out", str(tmp_path / "c.zip")]) == 0
    assert (tmp_path / "a.zip").read_bytes() != (tmp_path / "c.zip").read_bytes()


def test_export_canvas_says_what_it_leaves_out(tmp_path, capsys):
    out = tmp_path / "c.zip"
    assert main(["export", "canvas", "vibration.natural_frequency_formula", "--variants", "2", "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert err.count("part (a) is left out") == 1 and "equivalent forms" in err
    assert "imsmanifest.xml" in zipfile.ZipFile(out).namelist()


@pytest.mark.parametrize("argv, message", [
    (["export", "moodle", "examples/tutorial1.yaml", "belts.flat_belt_power", "--out", "x.xml"], "not both"),
    (["export", "moodle", "no.such_template", "--out", "x.xml"], "no.such_template"),
    # a Moodle XML pool written as tutorial1-moodle.zip, without a word, would fail only at Moodle's import
    (["export", "moodle", "examples/tutorial1.yaml", "--out", "tutorial1-moodle.zip"], "moodle writes a .xml file"),
    (["export", "canvas", "examples/tutorial1.yaml", "--out", "tutorial1.xml"], "canvas writes a .zip file"),
])
def test_mistakes_are_one_line(argv, message, capsys):
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and err.count("\n") == 1


def test_a_count_of_variants_out_of_range_is_a_usage_error(capsys):
    with pytest.raises(SystemExit):
        main(["export", "qti", "belts.flat_belt_power", "--variants", "0", "--out", "x.zip"])
    assert "out of range" in capsys.readouterr().err
