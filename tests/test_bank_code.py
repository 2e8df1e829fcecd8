"""A folder of templates brings its own code: a solver or figure in a file beside the template (`solver:
./speeds.py:driven_speed`), found from the template file, kept inside the folder, imported only when the
template is loaded in full or drawn, and covered by the template's version like a packaged solver. Grading
never takes a bank from the folder of answers handed in."""
import re
import shutil
from pathlib import Path

import pytest

from exgen.check.validate import validate_template
from exgen.cli import main
from exgen.errors import BankError, ExgenError
from exgen.figures import figure_svg
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.issue.manifest import read_manifest, template_mismatches
from exgen.load.bank import load_bank, load_template, refuse_code_in
from exgen.load.versions import template_version
from exgen.solve.variant import make_variant

SECRET = b"a course secret used only by these tests"

TEMPLATE = """\
id: course.driven_speed
title: Speed of a driven pulley
chapter: 1
topic: course
solver: {solver}
figure: ./speeds.py:pulleys
params:
  N1: {{min: 720, max: 1800, step: 20, unit: rpm, label: motor speed}}
  d1: {{min: 20, max: 50, step: 1, unit: cm, label: motor pulley diameter}}
  d2: {{min: 60, max: 120, step: 5, unit: cm, label: driven pulley diameter}}
statement: A motor at {{{{ N1 }}}} drives a pulley of {{{{ d2 }}}} from one of {{{{ d1 }}}}.
parts:
  - id: a
    ask: the speed of the driven pulley
    answer: N2
    unit: rpm
    mistakes:
      - {{when: ratio_inverted, say: "That is the speed ratio turned upside down."}}
"""

SOLVER = '''\
"""The course's own solver: the speed of a driven pulley, by the physics exgen already has."""
from exgen.mechanics import belts


def driven_speed(p, d):
    ratio = d.step("n", belts.speed_ratio(p.d1, p.d2), "", formula=r"\\frac{@d1}{@d2}", symbol="n")
    d.step("N2", p.N1 * ratio, "rad/s", shown="rpm", formula=r"@N1\\,@n", symbol=r"\\omega_2")
    d.mistake("N2", "ratio_inverted", p.N1 / ratio)


def pulleys(variant):
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20"><title>The two pulleys</title>'
            '<circle cx="10" cy="10" r="5"/><circle cx="30" cy="10" r="9"/></svg>')
'''


def course(folder: Path, solver: str = "./speeds.py:driven_speed", code: str = SOLVER, where: str = "") -> Path:
    """A folder of templates with one template and its code beside it (in the subfolder `where`)."""
    home = folder / where if where else folder
    home.mkdir(parents=True, exist_ok=True)
    (home / "speeds.py").write_text(code, encoding="utf-8")
    path = home / "driven_speed.yaml"
    path.write_text(TEMPLATE.format(solver=solver), encoding="utf-8")
    return path


def problems(path: Path, **kwargs) -> list[str]:
    with pytest.raises(BankError) as info:
        load_template(path, **kwargs)
    return [str(e) for e in info.value.errors]


def test_a_solver_and_a_figure_beside_the_template_draw_validate_and_issue(tmp_path):
    course(tmp_path)
    bank = load_bank([tmp_path])
    template = bank.get("course.driven_speed")
    variant = make_variant(template, 3)
    n1, d1, d2 = (variant.param(name).si for name in ("N1", "d1", "d2"))
    assert variant.answers["a"].si == pytest.approx(n1 * d1 / d2)
    assert "<title>The two pulleys</title>" in figure_svg(variant)
    report = validate_template(template, seeds=30)
    assert report.problems == [] and report.warnings == []
    sheet = build_sheet(Assignment("hw1", "Homework 1", (QuestionSpec("q1", template.id),)), Student("s1"), bank, SECRET)
    assert sheet.questions[0].variant.answers["a"].si > 0


def test_the_code_may_sit_anywhere_in_the_folder_of_templates(tmp_path):
    path = course(tmp_path, solver="../speeds.py:driven_speed", where="ch1")
    shutil.move(tmp_path / "ch1" / "speeds.py", tmp_path / "speeds.py")
    (tmp_path / "ch1" / "driven_speed.yaml").write_text(
        path.read_text(encoding="utf-8").replace("./speeds.py:pulleys", "../speeds.py:pulleys"), encoding="utf-8")
    template = load_bank([tmp_path]).get("course.driven_speed")
    assert make_variant(template, 1).answers["a"].si > 0


@pytest.mark.parametrize("solver, message", [
    ("./nowhere.py:driven_speed", "solver: no file ./nowhere.py beside driven_speed.yaml"),
    ("./speeds.py:no_such", "solver: ./speeds.py has no function 'no_such'"),
    ("speeds.py:driven_speed", "solver: 'speeds.py': write a file of the bank as a path from the template "
                               "file, starting ./ (./speeds.py)"),
    ("../outside.py:driven_speed", "solver: ../outside.py lies outside the folder of templates"),
    ("./speeds.py", "solver: must be 'module:function' naming a function in exgen.solvers, or "
                    "'./file.py:function' naming one in a file beside the template"),
])
def test_a_wrong_reference_is_named_with_file_and_line(tmp_path, solver, message):
    (tmp_path / "outside.py").write_text(SOLVER, encoding="utf-8")
    path = course(tmp_path / "bank", solver=solver)
    found = problems(path, bank_dir=tmp_path / "bank")
    assert any(re.search(rf"driven_speed\.yaml:5:(\d+:)? {re.escape(message)}", p) for p in found), found


def test_a_broken_solver_file_is_named_with_its_own_line_not_a_traceback(tmp_path):
    path = course(tmp_path, code=SOLVER.replace("    ratio = d.step(", "    ratio = = d.step(", 1))
    (found,) = [p for p in problems(path) if "solver:" in p]
    assert "speeds.py cannot be imported: SyntaxError: invalid syntax" in found and "line 6" in found
    assert main(["--bank", str(tmp_path), "validate", "course.driven_speed", "--seeds", "2"]) == 1


def test_a_light_load_runs_none_of_the_banks_code(tmp_path):
    marker = tmp_path / "ran"
    path = course(tmp_path, code=SOLVER + f"\nopen({str(marker)!r}, 'w').close()\n")
    template = load_template(path, full=False)
    assert not marker.exists()  # `exgen list` reads titles: nothing of the bank's runs
    make_variant(template, 1)
    assert marker.exists()


def test_the_version_covers_the_banks_solver_and_what_it_imports(tmp_path):
    template = load_template(course(tmp_path / "course"))
    version = template_version(template)
    assert "bank:course/speeds.py" in version.code
    assert {"exgen/mechanics/belts.py", "exgen/solve/variant.py", "graders/marking.py"} <= set(version.code)
    # a comment or a docstring changes nothing; a number does
    source = tmp_path / "course" / "speeds.py"
    source.write_text(SOLVER.replace('"""The course', '# reviewed\n"""The course'), encoding="utf-8")
    assert template_version(load_template(source.with_name("driven_speed.yaml"))).digest == version.digest
    source.write_text(SOLVER.replace("p.N1 * ratio", "p.N1 * ratio * 1.01"), encoding="utf-8")
    assert template_version(load_template(source.with_name("driven_speed.yaml"))).digest != version.digest


def test_the_version_does_not_depend_on_where_the_folder_lies(tmp_path):
    first = template_version(load_template(course(tmp_path / "a" / "course"))).digest
    assert template_version(load_template(course(tmp_path / "b" / "course"))).digest == first


def issue(tmp_path: Path, bank_dir: Path) -> Path:
    """One sheet of the bank's template issued to one student, by the command an instructor types."""
    assignment = tmp_path / "hw1.yaml"
    assignment.write_text("assignment: hw1\ntitle: Homework 1\nquestions:\n  - template: course.driven_speed\n",
                          encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("id,name\ns1,Ann\n", encoding="utf-8")
    secret = tmp_path / "course.secret"
    secret.write_bytes(SECRET)
    issued = tmp_path / "issued"
    assert main(["--bank", str(bank_dir), "generate", str(assignment), "--roster", str(roster), "--out",
                 str(issued), "--secret-file", str(secret), "--no-pdf"]) == 0
    return issued


def test_grading_names_the_banks_solver_when_it_changed_since_issue(tmp_path):
    bank_dir = tmp_path / "course"
    course(bank_dir)
    manifest = read_manifest(issue(tmp_path, bank_dir))
    assert manifest.templates["course.driven_speed"]["code"][0] == "bank:course/speeds.py"
    assert template_mismatches(manifest, load_bank([bank_dir])) == []
    (bank_dir / "speeds.py").write_text(SOLVER.replace("p.N1 * ratio", "p.N1 * ratio * 1.01"), encoding="utf-8")
    assert template_mismatches(manifest, load_bank([bank_dir])) == ["course.driven_speed: bank:course/speeds.py changed"]


@pytest.mark.parametrize("bank_in", ["same", "inside", "around"])
def test_grading_takes_no_bank_from_the_answers_handed_in(tmp_path, bank_in):
    handed = tmp_path / "submissions"
    bank = {"same": handed, "inside": handed / "s1", "around": tmp_path}[bank_in]
    for folder in (handed, bank, tmp_path / "elsewhere"):
        folder.mkdir(parents=True, exist_ok=True)
    with pytest.raises(ExgenError, match="a folder of templates cannot be, hold or lie in the folder of answers"):
        refuse_code_in(handed, [bank])
    refuse_code_in(handed, [tmp_path / "elsewhere"])  # beside it: nothing to refuse


def test_the_grade_command_stops_before_loading_a_bank_among_the_answers(tmp_path, capsys):
    issued = issue(tmp_path, course(tmp_path / "course").parent)
    handed = tmp_path / "submissions"
    marker = tmp_path / "ran"
    course(handed, code=SOLVER + f"\nopen({str(marker)!r}, 'w').close()\n")
    capsys.readouterr()
    assert main(["--bank", str(handed), "grade", str(issued), str(handed), "--out", str(tmp_path / "graded"),
                 "--secret-file", str(tmp_path / "course.secret")]) == 1
    err = capsys.readouterr().err
    assert "a folder of templates cannot be, hold or lie in the folder of answers handed in" in err
    assert err.count("\n") == 1 and not marker.exists()
