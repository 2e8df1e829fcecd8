"""examples/bank/, the folder of templates an instructor copies: a template with its solver and figure in a file
beside it (a flywheel on a shaft with a torsional damper, course text §6.6.2), loaded, validated, checked
against the text's numbers and against answers worked out again from the printed givens, drawn, issued to a
class from the command line and graded, as any folder of an instructor's own would be.

Copy this file beside a folder of your own and change the names: it is what the test suite does for every
template of exgen's own bank."""
import csv
import math
import os
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from exgen.check.given import solve
from exgen.check.validate import check_variant, validate_template
from exgen.cli import main
from exgen.figures import figure_svg
from exgen.figures.checks import collisions, texts
from exgen.figures.svg import MAX_WIDTH
from exgen.load.bank import load_bank
from exgen.render.solution import line_value, reproduces, solution
from exgen.solve.variant import make_variant
from sheet_values import check_answers, check_mistakes, printed

FOLDER = Path(__file__).parent.parent / "examples" / "bank"
TEMPLATE = "examples.damped_torsional"
SECRET = b"a course secret used only by these tests"


@pytest.fixture(scope="module")
def folder_bank():
    return load_bank([FOLDER])


def test_the_folder_adds_its_template_to_the_bank_and_brings_its_code(folder_bank):
    template = folder_bank.get(TEMPLATE)
    assert len(folder_bank) == len(load_bank()) + 1
    assert template.solver == f"{(FOLDER / 'damped_torsional.py').resolve().as_posix()}:damped_torsional"
    assert not (Path(__file__).parent.parent / "exgen" / "solvers" / "damped_torsional.py").exists()


def test_it_validates_cleanly(folder_bank):
    report = validate_template(folder_bank.get(TEMPLATE), seeds=150)
    assert report.problems == [] and report.warnings == []
    assert report.distinct > 0.95


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(min_value=0, max_value=2**65 - 1))
def test_any_seed_gives_a_valid_problem_whose_key_scores_full_marks(folder_bank, seed):
    assert check_variant(make_variant(folder_bank.get(TEMPLATE), seed)) == []


# ---- the text's numbers ------------------------------------------------------------------------------

def test_example_6_3s_flywheel_on_its_equivalent_shaft_has_the_texts_10_hz(folder_bank):
    """Example 6.3: a 60 kg flywheel of radius of gyration 0.6 m (I = 21.6 kg·m²) on shafts equivalent to one
    50 mm in diameter and 0.576 m long (G = 80 GN/m²) vibrates at the 10 Hz the example asks for. The damper
    is this problem's own: 800 N·m·s, worked by hand below."""
    variant, warnings = solve(folder_bank.get(TEMPLATE),
                              {"m": "60kg", "k": "0.6m", "d": "50mm", "l": "0.576m", "C": "800N*m*s"})
    answers = {part: answer.value for part, answer in variant.answers.items()}
    assert variant.step("I").value == pytest.approx(21.6)          # the text's I = m k²
    assert answers["b"] == pytest.approx(10.0, rel=5e-4)            # the text's f_n (l' rounded to 0.576 m)
    # by hand: J = π 0.05⁴/32 = 6.1359e-7 m⁴, q = 80e9 J / 0.576, ω_n = √(q/21.6) = 62.813 rad/s
    assert answers["a"] == pytest.approx(85221, rel=1e-4)
    assert answers["b"] == pytest.approx(9.9970, rel=1e-4)
    assert answers["c"] == pytest.approx(2713.5, rel=1e-4)          # 2 × 21.6 × 62.813
    assert answers["d"] == pytest.approx(0.29482, rel=1e-4)         # 800 / 2713.5
    assert answers["e"] == pytest.approx(9.5527, rel=1e-4)          # 9.9970 √(1 − 0.29482²)
    assert warnings == []


# ---- answers and named mistakes worked out again, from the printed givens ----------------------------

def worked(variant):
    """Every answer and named mistake from what the sheet prints, by the text's formulas, with no exgen code."""
    g = printed(variant, "m", "k", "d", "l", "G", "C")
    inertia = g.m * g.k ** 2
    q = g.G * math.pi * g.d ** 4 / 32 / g.l
    f_n = math.sqrt(q / inertia) / (2 * math.pi)
    c_c = 2 * inertia * 2 * math.pi * f_n
    zeta = g.C / c_c
    f_d = f_n * math.sqrt(1 - zeta ** 2)
    answers = {"a": q, "b": f_n, "c": c_c, "d": zeta, "e": f_d}
    mistakes = {"a": {"bending_for_polar": g.G * math.pi * g.d ** 4 / 64 / g.l},
                "b": {"omega_for_f": 2 * math.pi * f_n, "sqrt_missing": q / inertia / (2 * math.pi)},
                "c": {"factor_two_missing": c_c / 2},
                "e": {"omega_for_f": 2 * math.pi * f_d, "damping_ignored": f_n}}
    return answers, mistakes


def test_every_answer_is_what_the_printed_givens_give(folder_bank):
    check_answers(folder_bank, TEMPLATE, worked)


def test_every_named_mistake_is_what_its_slip_gives(folder_bank):
    check_mistakes(folder_bank, TEMPLATE, lambda v: worked(v)[1])


# ---- the key and the figure ---------------------------------------------------------------------------

def test_every_worked_line_reproduces_its_value(folder_bank):
    for seed in range(20):
        variant = make_variant(folder_bank.get(TEMPLATE), seed)
        for line in solution(variant).lines:
            if line.substituted is not None and isinstance(line.value, float):
                assert reproduces(line_value(line.substituted), line.values[0].value), (seed, line.name)


def test_the_figure_is_drawn_to_the_data_with_its_labels_clear(folder_bank):
    for seed in range(40):
        variant = make_variant(folder_bank.get(TEMPLATE), seed)
        svg = figure_svg(variant)
        assert collisions(svg) == [], seed
        width = float(svg.split('viewBox="')[1].split()[2])
        assert width <= MAX_WIDTH
        labels = texts(svg)
        for name in ("m", "k", "d", "l", "C"):
            assert any(t.startswith(f"{name} = {variant.param(name).text} ") for t in labels), (seed, name, labels)


# ---- issued to a class and graded, as an instructor does it --------------------------------------------

def test_a_class_is_issued_from_the_folder_and_graded(tmp_path, folder_bank, capsys):
    """Two students, PDFs made by two processes (each imports the folder's solver file itself); one hands back
    the key's answers, the other the undamped frequency for (e): full marks, and the slip named."""
    from exgen.issue.assignment import Student, build_sheet, load_assignment
    from exgen.render.answer_form import answer_form

    (tmp_path / "hw6.yaml").write_text("assignment: hw6-damping\ntitle: Damped torsional vibration\n"
                                       "questions:\n  - template: examples.damped_torsional\n", encoding="utf-8")
    (tmp_path / "roster.csv").write_text("id,name\nS1,Ann\nS2,Ben\n", encoding="utf-8")
    secret = tmp_path / "course.secret"
    secret.write_bytes(SECRET)
    os.chmod(secret, 0o600)
    bank_args = ["--bank", str(FOLDER)]
    assert main([*bank_args, "generate", str(tmp_path / "hw6.yaml"), "--roster", str(tmp_path / "roster.csv"),
                 "--out", str(tmp_path / "issued"), "--secret-file", str(secret), "--jobs", "2"]) == 0
    assert (tmp_path / "issued" / "students" / "S1" / "sheet.pdf").read_bytes().startswith(b"%PDF")
    assert (tmp_path / "issued" / "students" / "S2" / "q1.svg").is_file()

    handed = tmp_path / "handed"
    handed.mkdir()
    assignment = load_assignment(tmp_path / "hw6.yaml", folder_bank)
    for student, slip in ((Student("S1", "Ann"), None), (Student("S2", "Ben"), "damping_ignored")):
        sheet = build_sheet(assignment, student, folder_bank, SECRET)
        variant = sheet.questions[0].variant
        form = answer_form(sheet)
        for part_id, answer in variant.answers.items():
            text = answer.text
            if slip and part_id == "e":
                text = f"{variant.mistakes['e'][slip]:.4g} Hz"
            form = form.replace(f'    {part_id}: ""', f'    {part_id}: "{text}"', 1)
        (handed / f"{student.id}.yaml").write_text(form, encoding="utf-8")

    assert main([*bank_args, "grade", str(tmp_path / "issued"), str(handed), "--out", str(tmp_path / "graded"),
                 "--secret-file", str(secret)]) == 0
    with open(tmp_path / "graded" / "gradebook.csv", encoding="utf-8") as f:
        rows = {row["student"]: row for row in csv.DictReader(f)}
    total = next(k for k in rows["S1"] if k.lower().startswith("total"))
    assert float(rows["S1"][total]) == 5.0 and float(rows["S2"][total]) == 4.0
    feedback = (tmp_path / "graded" / "feedback" / "S2.md").read_text(encoding="utf-8")
    assert "That is the undamped natural frequency; damping slows the oscillation" in feedback
    shutil.rmtree(tmp_path / "issued")
