"""`exgen practice` driven through stdin as a student would type, plain text only; `--stats`; errors
in one line."""
import io
import itertools
import re
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from exgen.answertypes import answer_type
from exgen.cli import main
from exgen.load.mistake_messages import message_for
from exgen.solve.variant import make_variant
from practice import session
from practice.store import default_path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SEEDS = [2**64 + 11, 2**64 + 12, 2**64 + 13]


@pytest.fixture
def seeds(monkeypatch):
    """Practice seeds known in advance, so that a test knows the answers."""
    counter = itertools.cycle(SEEDS)
    monkeypatch.setattr(session, "practice_seed", lambda: next(counter))
    return SEEDS


def run(monkeypatch, capsys, lines, *argv, db=None):
    monkeypatch.setattr(sys, "stdin", io.StringIO("".join(f"{line}\n" for line in lines)))
    code = main(["practice", *argv, "--db", str(db)])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_a_sitting_right_wrong_hint_solution_next_quit(monkeypatch, capsys, tmp_path, bank, seeds):
    template = bank.get("belts.compound_drive")
    variant = make_variant(template, seeds[0])
    a, b = template.part("a"), template.part("b")
    slip = variant.mistakes["b"]["slip_not_applied"]
    lines = [variant.answers["a"].text, answer_type(b).text(slip, b), "h", "s", "", "n", "q"]
    code, out, err = run(monkeypatch, capsys, lines, "--topic", "belts.compound_drive", db=tmp_path / "p.sqlite3")
    assert code == 0, err
    assert "Problem 1  ·  Speed of a countershaft driven through a compound belt drive" in out
    assert "Figure: " in out and ".svg" in out
    assert f"(a) [{answer_type(a).form_hint(a)}] > {variant.answers['a'].text}\n  Right." in out
    assert f"Not right: {message_for('slip_not_applied')}" in out or "Not right: " in out
    assert "Hint 1:" in out and "Worked solution" in out and "Answers" in out
    assert "count for nothing in your progress" in out
    assert "Problem 2" in out
    assert ("This sitting: 2 problem(s), 4 part(s): 1 right at the first try, 0 right after a hint, 1 wrong at "
            "the first try, 2 left blank; 1 hint(s) and 1 worked solution(s) seen.") in " ".join(out.split())
    assert "belts: not started → " in out
    assert "\x1b[" not in out  # no colour, no cursor control


@pytest.mark.parametrize("c, counted", [
    (["h", "{c}"], "1 right at the first try, 1 right after a hint, 0 wrong at the first try, 1 left blank"),
    (["1 Hz", "h", "{c}"], "1 right at the first try, 0 right after a hint, 1 wrong at the first try, 1 left blank"),
])
def test_the_summary_counts_each_part_as_mastery_does(monkeypatch, capsys, tmp_path, bank, seeds, c, counted):
    """A 3-part problem with (b) blank and (c) right only after a hint was summed up as "2 of 2 part(s)
    right at the first try; 1 hint(s)"."""
    variant = make_variant(bank.get("vibration.beam_two_springs"), seeds[0])
    lines = [variant.answers["a"].text, ""] + [line.format(c=variant.answers["c"].text) for line in c] + ["q"]
    code, out, err = run(monkeypatch, capsys, lines, "--topic", variant.template.id, db=tmp_path / "p.sqlite3")
    assert code == 0, err
    assert f"This sitting: 1 problem(s), 3 part(s): {counted}; 1 hint(s) and 0 worked solution(s) seen." \
        in " ".join(out.split())


def test_what_help_costs_is_said_before_it_is_asked_for(monkeypatch, capsys, tmp_path, seeds):
    code, out, _ = run(monkeypatch, capsys, ["q"], "--topic", "vibration", db=tmp_path / "p.sqlite3")
    said = " ".join(out.split())
    assert "each hint costs a quarter of its part's credit" in said
    assert said.index("the worked solution costs half") < said.index("Problem 1")


def test_the_named_mistake_is_said(monkeypatch, capsys, tmp_path, bank, seeds):
    template = bank.get("belts.driven_speed_slip")
    variant = make_variant(template, seeds[0])
    part = template.parts[0]
    name, value = next(iter(variant.mistakes[part.id].items()))
    code, out, _ = run(monkeypatch, capsys, [answer_type(part).text(value, part), "q"],
                       "--topic", template.id, db=tmp_path / "p.sqlite3")
    says = {m.when: m.say for m in part.mistakes}
    assert code == 0 and "Not right: " in out
    assert message_for(name, says.get(name, "")).split(":")[0][:30] in out


def test_end_of_input_ends_the_sitting_with_its_summary(monkeypatch, capsys, tmp_path, seeds):
    code, out, _ = run(monkeypatch, capsys, [], "--chapter", "2", db=tmp_path / "p.sqlite3")
    assert code == 0 and "This sitting: 1 problem(s)" in out and " 0 right at the first try" in " ".join(out.split())


def test_stats_lists_every_chapter_and_topic(monkeypatch, capsys, tmp_path, seeds, bank):
    db = tmp_path / "p.sqlite3"
    variant = make_variant(bank.get("gears.simple_train"), seeds[0])
    run(monkeypatch, capsys, [variant.answers[variant.template.parts[0].id].text, "q"], "--topic", "gears.simple_train",
        db=db)
    code, out, _ = run(monkeypatch, capsys, [], "--stats", db=db)
    assert code == 0
    for chapter in ("Chapter 1: Power transmission", "Chapter 4: Governors", "Chapter 7: Linkage kinematics"):
        assert chapter in out
    gears = next(line for line in out.splitlines() if line.strip().startswith("gears"))
    assert "%" in gears and gears.split()[-4:-2] == ["1", "1"]  # one problem, one answer checked
    assert "not started" in next(line for line in out.splitlines() if line.strip().startswith("belts"))
    assert f"Progress file: {db}" in out


def test_an_assignments_practice_set_shows_the_chapters_it_leaves_out(monkeypatch, capsys, tmp_path):
    code, out, _ = run(monkeypatch, capsys, [], "--stats", "--assignment", str(EXAMPLES / "tutorial1.yaml"),
                       db=tmp_path / "p.sqlite3")
    assert code == 0 and "Chapter 5: Gyroscopes  (not in Tutorial 1" in out


@pytest.mark.parametrize("argv, message", [
    (["--topic", "no_such_topic"], "'no_such_topic' is neither a topic nor a template; the topics are belts, gears"),
    (["--chapter", "9"], "chapter 9 has no templates"),
])
def test_a_scope_with_nothing_in_it_is_one_line(monkeypatch, capsys, tmp_path, argv, message):
    code, out, err = run(monkeypatch, capsys, [], *argv, db=tmp_path / "p.sqlite3")
    assert code == 1 and message in err and len(err.strip().splitlines()) == 1


def test_a_damaged_progress_file_is_one_line_and_untouched(monkeypatch, capsys, tmp_path):
    db = tmp_path / "p.sqlite3"
    db.write_bytes(b"\x00garbage" * 500)
    code, _, err = run(monkeypatch, capsys, ["q"], db=db)
    assert code == 1 and err.startswith(f"exgen: {db} is not a readable practice file") and "Traceback" not in err
    assert db.read_bytes() == b"\x00garbage" * 500


def test_over_a_real_pipe_with_help_showing_the_progress_file(tmp_path):
    env = {**os.environ, "EXGEN_PRACTICE_DB": str(tmp_path / "piped.sqlite3"), "PYTHONIOENCODING": "utf-8"}
    shown = subprocess.run([sys.executable, "-m", "exgen.cli", "practice", "--help"], capture_output=True,
                           text=True, env=env, timeout=120)
    assert str(tmp_path / "piped.sqlite3") in " ".join(shown.stdout.split())
    done = subprocess.run([sys.executable, "-m", "exgen.cli", "practice", "--topic", "vibration"],
                          input="1 Hz\nh\nn\nq\n", capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "Practising Vibration." in done.stdout and "Problem 2" in done.stdout and "\x1b[" not in done.stdout
    assert (tmp_path / "piped.sqlite3").exists()


def test_the_default_progress_file_is_in_the_help(capsys, monkeypatch):
    monkeypatch.delenv("EXGEN_PRACTICE_DB", raising=False)
    with pytest.raises(SystemExit):
        main(["serve", "--help"])
    assert str(default_path()) in " ".join(capsys.readouterr().out.split())


def test_feedback_fits_the_page_and_the_summary_names_the_progress_file_given(monkeypatch, capsys, tmp_path, bank,
                                                                               seeds):
    """A long message ran off an 80-column terminal mid-word, an answer typed once the problem was done
    vanished without a word, and the summary offered `exgen practice --stats`, which shows another file's
    progress when --db was given."""
    from exgen.render.text import WIDTH

    template = bank.get("belts.compound_drive")
    variant = make_variant(template, seeds[0])
    b = template.part("b")
    slip = answer_type(b).text(variant.mistakes["b"]["slip_not_applied"], b)
    in_rad_s = f"{variant.answers['a'].value * math.pi / 30:.4g}"  # rpm asked: its message is long
    lines = [in_rad_s, variant.answers["a"].text, slip] + [variant.answers[p.id].text for p in template.parts[1:]]
    lines += ["12 rpm", "q"]
    db = tmp_path / "my progress.sqlite3"
    code, out, err = run(monkeypatch, capsys, lines, "--topic", "belts.compound_drive", db=db)
    assert code == 0, err
    feedback = [line for line in out.splitlines() if line.startswith("  ") and not line.startswith("  (")]
    assert any("Not right" in line for line in feedback) and all(len(line) <= WIDTH for line in feedback)
    assert "that was not read as an answer" in out
    assert f"`exgen practice --stats --db '{db}'` shows all of it" in out


def test_a_figure_that_is_the_given_stays_beside_the_progress_file_after_the_sitting(monkeypatch, capsys, tmp_path,
                                                                                      seeds):
    """For linkages.mobility the figure is the problem; the terminal printed a temporary path deleted on quit."""
    from practice import terminal

    monkeypatch.setattr(terminal, "can_open", lambda: True)
    db = tmp_path / "mine.sqlite3"
    code, out, err = run(monkeypatch, capsys, ["q"], "--topic", "linkages.mobility", db=db)
    assert code == 0, err
    shown = re.search(r"The figure is the problem's data; open it to answer: (\S+\.svg)", out)
    assert shown, out
    path = Path(shown.group(1))
    assert path.parent == tmp_path / "mine-figures" and path.is_file() and path.read_text().startswith("<svg")
    assert "`exgen practice --open` opens each in your viewer" in " ".join(out.split())


def test_a_figure_that_cannot_be_written_is_one_line_and_the_sitting_goes_on(monkeypatch, capsys, tmp_path, seeds):
    blocker = tmp_path / "p-figures"
    blocker.write_text("a file where the folder would go")
    code, out, err = run(monkeypatch, capsys, ["q"], "--topic", "linkages.mobility", db=tmp_path / "p.sqlite3")
    assert code == 0 and "The figure could not be written to" in out and "Traceback" not in out + err
