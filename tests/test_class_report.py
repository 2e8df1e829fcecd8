"""A simulated class (examples/simulate_class.py) graded end to end: the gradebooks import as they are,
the item analysis shows the mistakes planted, and the planted copies, and nothing else, are signs."""
import csv
import importlib.util
import json
from pathlib import Path

import pytest

from exgen.cli import main
from exgen.issue.assignment import load_assignment
from graders.analysis import analyse, point_biserial
from graders.record import read_record

SCRIPT = Path(__file__).parent.parent / "examples" / "simulate_class.py"
STUDENTS = 80


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    spec = importlib.util.spec_from_file_location("simulate_class", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = tmp_path_factory.mktemp("class")
    plan = module.simulate(out, STUDENTS, seed=11)
    return out / "graded", plan, module


def test_the_planted_mistake_is_counted_exactly_and_the_others_about_as_often_as_made(simulated):
    graded, plan, _ = simulated
    analysis = analyse(read_record(graded))
    found = {(p.slot, p.part, name): n for p in analysis.parts for name, n in p.mistakes}
    slot, part = plan["planted_part"]
    planted = [(s, p, n, c) for s, p, n, c in plan["mistakes"] if (s, p) == (slot, part)]
    assert len(planted) == 1 and found[planted[0][:3]] == planted[0][3] == plan["planted"]
    for s, p, name, count in plan["mistakes"]:
        # a random wrong answer may land on a mistake's value, or a mistake be read as carried forward
        assert abs(found.get((s, p, name), 0) - count) <= max(2, 0.1 * count), (s, p, name)


def test_the_planted_copies_and_only_they_are_signs(simulated):
    graded, plan, _ = simulated
    signs = read_record(graded)["signs"]
    assert {(s["kind"], tuple(s["students"])) for s in signs} == {(k, tuple(v)) for k, v in plan["copies"].items()}
    for sign in signs:
        assert sign["evidence"] and sign["summary"]
    html = (graded / "item-analysis.html").read_text(encoding="utf-8")
    markdown = (graded / "item-analysis.md").read_text(encoding="utf-8")
    for copier, source in plan["copies"].values():
        assert f"{copier} and {source}" in html and f"{copier} and {source}" in markdown


def test_signs_never_change_a_mark(simulated):
    graded, plan, _ = simulated
    copier, source = plan["copies"]["answers_match_another_sheet"]
    rows = {r["student"]: r for r in csv.DictReader((graded / "gradebook.csv").open(encoding="utf-8"))}
    assert rows[copier]["status"] == "graded" and rows[copier]["total"] != ""


def test_the_canvas_gradebook_has_canvas_headers_points_possible_and_the_graded_only(simulated):
    graded, plan, module = simulated
    possible = read_record(graded)["max_points"]      # the assignment's marks, every part counted
    rows = list(csv.reader((graded / "canvas_gradebook.csv").open(encoding="utf-8")))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Tutorial 1: Belt drives"]
    assert rows[1][0] == "Points Possible" and float(rows[1][5]) == possible
    by_id = {r[2]: r for r in rows[2:]}
    assert len(by_id) == STUDENTS - 1
    taker, _ = plan["copies"]["another_students_sheet_code"]
    assert taker not in by_id  # a refused file: no row, so the import keeps the grade the student has
    student = module.roster(STUDENTS)[0]
    assert by_id[student.id][:5] == [student.name, "", student.id, student.email, student.section]
    assert 0 <= float(by_id[student.id][5]) <= possible


def test_the_moodle_grades_match_by_id_number_or_email(simulated):
    graded, plan, module = simulated
    rows = list(csv.DictReader((graded / "moodle_grades.csv").open(encoding="utf-8")))
    assert list(rows[0]) == ["ID number", "Email address", "First name", "Last name", "Tutorial 1: Belt drives"]
    taker, _ = plan["copies"]["another_students_sheet_code"]
    assert taker not in {r["ID number"] for r in rows} and len(rows) == STUDENTS - 1
    gradebook = {r["student"]: r["total"] for r in csv.DictReader((graded / "gradebook.csv").open(encoding="utf-8"))}
    assert all(r["Tutorial 1: Belt drives"] == gradebook[r["ID number"]] for r in rows)


def test_the_parts_csv_has_a_column_per_part(simulated, bank):
    graded, _, _ = simulated
    header = next(csv.reader((graded / "parts.csv").open(encoding="utf-8")))
    possible = read_record(graded)["max_points"]
    parts = sum(len(bank.get(q.template).parts) for q in load_assignment(SCRIPT.parent / "tutorial1.yaml").questions)
    assert header[:3] == ["student", "name", "q1 (a) /1"] and header[-2:] == [f"total /{possible:g}", "status"]
    assert len(header) == 2 + parts + 2


def test_the_html_report_is_self_contained_with_pictures(simulated):
    graded, _, _ = simulated
    html = (graded / "item-analysis.html").read_text(encoding="utf-8")
    assert html.count("<svg") == 2 and "<style>" in html
    assert "src=" not in html and "<link" not in html and "<script" not in html  # nothing fetched
    assert "Distribution of marks" in html and "Signs of copying" in html


def test_exgen_report_writes_the_same_pages_again(simulated, tmp_path, capsys):
    graded, _, _ = simulated
    assert main(["report", str(graded), "--out", str(tmp_path)]) == 0
    for name in ("item-analysis.html", "item-analysis.md"):
        assert (tmp_path / name).read_text(encoding="utf-8") == (graded / name).read_text(encoding="utf-8")


def test_report_on_a_folder_without_results_is_one_line(tmp_path, capsys):
    assert main(["report", str(tmp_path)]) == 1
    assert "results.json" in capsys.readouterr().err


@pytest.mark.parametrize("item, rest, expected", [
    ([1, 1, 0, 0], [10, 8, 2, 0], 0.9701425),
    ([0, 0, 1, 1], [10, 8, 2, 0], -0.9701425),
    ([1, 1, 1, 1], [10, 8, 2, 0], None),
    ([1, 0], [3, 1], None),
])
def test_point_biserial(item, rest, expected):
    found = point_biserial(item, rest)
    assert found == pytest.approx(expected) if expected is not None else found is None


def test_a_part_nobody_got_right_is_flagged_first(simulated):
    graded, _, _ = simulated
    record = json.loads((graded / "results.json").read_text(encoding="utf-8"))
    for sheet in record["sheets"]:
        for part in sheet["parts"]:
            if (part["slot"], part["part"]) == ("q4", "b") and part["status"] in ("correct", "carried"):
                part["status"], part["points"] = "wrong", 0.0
    analysis = analyse(record)
    assert [p.label for p in analysis.nobody_right] == ["q4 (b)"]


def test_each_sign_names_the_parts_it_rests_on_and_whose_answers_they_are(simulated):
    """What `exgen review` lists as flagged: per sign, the parts of its evidence, for the student who handed in
    another's answers, or for both who gave the same wrong ones; each a wrong answer in the record."""
    graded, plan, _ = simulated
    record = read_record(graded)
    status = {(s["student"]["id"], p["slot"], p["part"]): p["status"] for s in record["sheets"] for p in s["parts"]}
    for sign in record["signs"]:
        flagged = {(p["student"], p["slot"], p["part"]) for p in sign["parts"]}
        told = {tuple(line.split(":", 1)[0].replace("(", "").replace(")", "").split()) for line in sign["evidence"]}
        whose = {"answers_match_another_sheet": sign["students"][:1], "identical_wrong_answers": sign["students"],
                 "another_students_sheet_code": []}[sign["kind"]]
        assert flagged == {(s, slot, part) for s in whose for slot, part in (told if whose else ())}
        assert all(status[key] == "wrong" for key in flagged)
    assert sum(len(s["parts"]) for s in record["signs"]) >= 2 * 2
