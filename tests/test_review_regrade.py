"""Review and regrade: a class graded with planted format problems ("raises" for "raises the bow", a speed
written "348.3 rpm clockwise", an unknown unit); accepting one spelling for everyone and one answer for one
student, then grading again, changes exactly those marks, and every output of a second regrade is the same,
byte for byte. A decision on an answer that has changed since is listed and not applied; a broken decisions
file stops grading in one line and loses nothing."""
import csv
import re
import io
import json
from pathlib import Path

import pytest
import yaml

from exgen.cli import main
from exgen.issue.assignment import Student, build_sheet, load_assignment
from exgen.issue.generate import generate
from exgen.issue.manifest import read_manifest

SECRET = "5b1f0e7c9a4d2e8f6a3c1b7d9e0f2a4c6b8d0e1f3a5c7e9b"
ASSIGNMENT = """\
assignment: review-demo
title: Review demo
questions:
  - template: belts.driven_speed_slip
  - template: gyroscopes.ship_turbine
"""
CLASS = [Student(f"S{n:03d}", f"Student {n}") for n in range(1, 25)]
SPEED, TURN = (1, "a"), (2, "b")  # (question, part): a speed in rpm; "raises the bow" or "lowers the bow"


@pytest.fixture(scope="module")
def course(tmp_path_factory, bank):
    """The class issued, and the planted answers: the key everywhere else."""
    root = tmp_path_factory.mktemp("review")
    (root / "review.yaml").write_text(ASSIGNMENT, encoding="utf-8")
    assignment = load_assignment(root / "review.yaml", bank)
    generate(assignment, CLASS, bank, SECRET.encode(), root / "issued", pdf=False, secret_source="$EXGEN_SECRET")
    manifest = read_manifest(root / "issued")
    sheets = {s.id: build_sheet(manifest.assignment, s, bank, SECRET.encode()) for s in manifest.students}
    keys = {sid: {q.number: {p: a for p, a in q.variant.answers.items()} for q in sheet.questions}
            for sid, sheet in sheets.items()}
    raises = [sid for sid in keys if keys[sid][2]["b"].value == "raises the bow"]
    lowers = [sid for sid in keys if keys[sid][2]["b"].value == "lowers the bow"]
    assert len(raises) >= 2 and len(lowers) >= 2, "the class must hold both keys of (b)"
    planted = {
        "alias_right": (raises[0], TURN, "raises"),
        "alias_right_too": (raises[1], TURN, "  Raises "),
        "alias_wrong": (lowers[0], TURN, "raises"),
        "direction": (lowers[1], SPEED, f"{keys[lowers[1]][1]['a'].text} clockwise"),
        "unknown_unit": (next(s for s in keys if s not in raises[:2] + lowers[:2]), SPEED, "348.3 blorps"),
    }
    return {"root": root, "sheets": sheets, "keys": keys, "planted": planted}


def hand_in(course, folder: Path, changes: dict | None = None) -> Path:
    """Every student's answer file: the key, with the planted answers (and `changes`: student -> (q, p, text))."""
    folder.mkdir(parents=True, exist_ok=True)
    typed = {sid: {n: {p: a.text for p, a in parts.items()} for n, parts in q.items()}
             for sid, q in course["keys"].items()}
    for student, (question, part), text in list(course["planted"].values()) + list((changes or {}).values()):
        typed[student][question][part] = text
    for sid, sheet in course["sheets"].items():
        data = {"student": sid, "code": sheet.code,
                "answers": {q.slot: typed[sid][q.number] for q in sheet.questions}}
        (folder / f"{sid}.yaml").write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return folder


def grade(course, handed: Path, out: Path, monkeypatch, capsys, *extra) -> tuple[int, str, str]:
    monkeypatch.setenv("EXGEN_SECRET", SECRET)
    status = main(["grade", str(course["root"] / "issued"), str(handed), "--out", str(out), *map(str, extra)])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def decide(*argv) -> int:
    return main(["decide", *map(str, argv), "--reviewer", "A. Lecturer", "--reason", "reviewed by hand"])


def marks(out: Path) -> dict[tuple[str, str, str], tuple[str, float]]:
    record = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return {(s["student"]["id"], p["slot"], p["part"]): (p["status"], p["points"]) for s in record["sheets"]
            for p in s["parts"]}


def files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def rows(path: Path) -> dict[str, list[str]]:
    """A gradebook's rows by their first cell that names a student."""
    return {r[0]: r for r in csv.reader(io.StringIO(path.read_text(encoding="utf-8"))) if r}


@pytest.fixture
def reviewed(course, tmp_path, monkeypatch, capsys):
    """Graded once, one spelling accepted for everyone and one answer for one student, graded again."""
    handed = hand_in(course, tmp_path / "handed")
    out = tmp_path / "graded" / "review-demo"
    assert grade(course, handed, out, monkeypatch, capsys)[0] == 0
    before = {name: data for name, data in files(out).items()}
    first = marks(out)
    planted = course["planted"]
    assert decide(out, "--accept-spelling", "raises", "--question", 2, "--part", "b", "--means", "Raises the bow") == 0
    student = planted["direction"][0]
    assert decide(out, "--accept", student, "--question", 1, "--part", "a", "--comment",
                  "the direction is not asked, but the speed is right") == 0
    capsys.readouterr()
    status, said, err = grade(course, handed, out, monkeypatch, capsys)
    assert status == 0
    return {"handed": handed, "out": out, "first": first, "before": before, "said": said, "err": err}


def test_the_planted_answers_are_format_problems_before_review(course, tmp_path, monkeypatch, capsys):
    out = tmp_path / "g"
    assert grade(course, hand_in(course, tmp_path / "handed"), out, monkeypatch, capsys)[0] == 0
    graded = marks(out)
    for student, (question, part), _ in course["planted"].values():
        assert graded[(student, f"q{question}", part)] == ("unreadable", 0.0)


def test_review_changes_exactly_the_reviewed_marks(course, reviewed):
    planted, first, after = course["planted"], reviewed["first"], marks(reviewed["out"])
    changed = {key for key in first if first[key] != after[key]}
    right = {(planted[k][0], f"q{planted[k][1][0]}", planted[k][1][1]) for k in ("alias_right", "alias_right_too",
                                                                                     "direction")}
    wrong = (planted["alias_wrong"][0], "q2", "b")
    assert changed == right | {wrong}
    assert all(after[key][0] == "correct" and after[key][1] > 0 for key in right)
    assert after[wrong] == ("wrong", 0.0)  # "raises" read as "raises the bow", graded against "lowers the bow"
    unknown = planted["unknown_unit"]
    assert after[(unknown[0], "q1", "a")] == ("unreadable", 0.0)  # not reviewed: as it was


def test_gradebooks_carry_the_reviewed_marks_and_nothing_else_changes(course, reviewed):
    planted = course["planted"]
    students = {planted[k][0] for k in ("alias_right", "alias_right_too", "direction")}
    for name in ("gradebook.csv", "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"):
        old = rows_of(reviewed["before"][name])
        new = rows(reviewed["out"] / name)
        differ = {key for key in new if new[key] != old.get(key)}
        column = 2 if name == "canvas_gradebook.csv" else 0
        ids = {new[key][column] for key in differ}
        assert ids == students, name
    gradebook = rows(reviewed["out"] / "gradebook.csv")
    for student in students:
        old = rows_of(reviewed["before"]["gradebook.csv"])[student]
        assert float(gradebook[student][-4]) > float(old[-4])


def rows_of(data: bytes) -> dict[str, list[str]]:
    return {r[0]: r for r in csv.reader(io.StringIO(data.decode("utf-8"))) if r}


def test_feedback_says_marked_by_hand_and_read_as(course, reviewed):
    planted = course["planted"]
    page = (reviewed["out"] / "feedback" / f"{planted['direction'][0]}.md").read_text(encoding="utf-8")
    assert "Marked by hand: the direction is not asked, but the speed is right." in page
    alias = (reviewed["out"] / "feedback" / f"{planted['alias_right'][0]}.md").read_text(encoding="utf-8")
    assert "read as 'raises the bow', a spelling accepted in review" in alias
    assert "Your answer: `raises`" in alias


def test_report_and_item_analysis_count_the_marks_review_changed_per_part(reviewed):
    report = (reviewed["out"] / "report.md").read_text(encoding="utf-8")
    assert "## Review" in report and "1 decision(s), 1 alias(es)" in report
    assert "| q1 | a | 1 | +" in report and "| q2 | b | 2 | +" in report  # the wrong one changed no mark
    analysis = (reviewed["out"] / "item-analysis.md").read_text(encoding="utf-8")
    assert "## Changed by review" in analysis and "q2 (b)" in analysis.split("## Changed by review")[1]
    assert "Changed by review" in (reviewed["out"] / "item-analysis.html").read_text(encoding="utf-8")
    assert ": 1 decision(s) and 1 alias(es), which marked 4 answer(s)" in reviewed["said"]
    assert "which marked 4 answer(s)" in report


def test_results_json_records_what_review_did_for_the_review_page(course, reviewed):
    record = json.loads((reviewed["out"] / "results.json").read_text(encoding="utf-8"))
    parts = {(s["student"]["id"], p["slot"], p["part"]): p for s in record["sheets"] for p in s["parts"]}
    direction = parts[(course["planted"]["direction"][0], "q1", "a")]
    assert direction["review"]["by"] == "decision" and direction["review"]["decision"] == "accept"
    assert direction["review"]["status_before"] == "unreadable" and direction["review"]["points_before"] == 0
    assert direction["given"].endswith(" clockwise") and direction["review"]["reviewer"] == "A. Lecturer"
    alias = parts[(course["planted"]["alias_right_too"][0], "q2", "b")]
    assert alias["review"]["by"] == "alias" and alias["review"]["means"] == "raises the bow"
    assert alias["given"] == "Raises"
    assert record["review"]["decisions"] == 1 and record["review"]["not_applied"] == []
    turn = next(p for c in record["columns"] if c["number"] == 2 for p in c["parts"] if p["id"] == "b")
    assert turn["type"] == "choice" and turn["choices"] == ["raises the bow", "lowers the bow"]
    assert all(p["review"] is None for key, p in parts.items() if key[0] not in
               {v[0] for v in course["planted"].values()})


def test_a_second_regrade_is_byte_identical(course, reviewed, monkeypatch, capsys):
    once = files(reviewed["out"])
    assert grade(course, reviewed["handed"], reviewed["out"], monkeypatch, capsys)[0] == 0
    assert files(reviewed["out"]) == once


def test_a_decision_whose_answer_changed_is_listed_and_not_applied(course, reviewed, monkeypatch, capsys):
    student = course["planted"]["direction"][0]
    key = course["keys"][student][1]["a"].text
    handed = hand_in(course, reviewed["handed"], {"resubmitted": (student, SPEED, f"{key} cw")})
    status, said, err = grade(course, handed, reviewed["out"], monkeypatch, capsys)
    assert status == 0
    assert marks(reviewed["out"])[(student, "q1", "a")] == ("unreadable", 0.0)
    decisions = reviewed["out"].with_name("review-demo.decisions.yaml")
    line = next(n for n, text in enumerate(decisions.read_text(encoding="utf-8").splitlines(), 1) if student in text)
    expected = f"{decisions}:{line}: accept {student}, question 1 (a): the answer is now '{key} cw'"
    assert expected in err and "1 not applied" in said
    report = (reviewed["out"] / "report.md").read_text(encoding="utf-8")
    assert "### Not applied" in report and f"accept {student}, question 1 (a): the answer is now" in report
    feedback = (reviewed["out"] / "feedback" / f"{student}.md").read_text(encoding="utf-8")
    assert "Marked by hand" not in feedback


@pytest.mark.parametrize("text, words", [
    ("assignment: review-demo\ndecisions:\n  - student: S001\n    question: [1\n", "not valid YAML"),
    ("assignment: review-demo\n" + "".join(f"{a}: &{a} [{', '.join(['*' + p] * 9 if p else ['lol'] * 9)}]\n"
                                           for a, p in zip("abcdefghi", ["", *"abcdefgh"])), "aliases counted"),
    ("assignment: review-demo\ndecisions:\n  - {student: S001, question: 1, part: a, answer: x, decision: 3,"
     " reviewer: me, reason: r}\n", "`decision:` is a number"),
    ("assignment: another\n", "not 'review-demo'"),
])
def test_a_broken_decisions_file_stops_grading_in_one_line_and_loses_nothing(course, reviewed, monkeypatch, capsys,
                                                                             text, words):
    decisions = reviewed["out"].with_name("review-demo.decisions.yaml")
    decisions.write_text(text, encoding="utf-8")
    once = files(reviewed["out"])
    status, said, err = grade(course, reviewed["handed"], reviewed["out"], monkeypatch, capsys)
    assert status == 1 and len(err.strip().splitlines()) == 1 and str(decisions) in err and words in err, err
    assert "Traceback" not in err and files(reviewed["out"]) == once
    assert decisions.read_text(encoding="utf-8") == text
    assert decide(reviewed["out"], "--reject", "S001", "--question", 1, "--part", "a") == 1
    assert decisions.read_text(encoding="utf-8") == text


def test_a_decisions_file_among_the_submissions_or_inside_the_output_is_refused(course, reviewed, monkeypatch,
                                                                                capsys):
    planted = reviewed["out"].with_name("review-demo.decisions.yaml").read_text(encoding="utf-8")
    for inside in (reviewed["handed"] / "mine.decisions.yaml", reviewed["out"] / "d.yaml"):
        inside.write_text(planted, encoding="utf-8")
        status, _, err = grade(course, reviewed["handed"], reviewed["out"], monkeypatch, capsys, "--decisions", inside)
        assert status == 1 and "keep it beside the output folder" in err
        inside.unlink()


def test_a_huge_decisions_file_is_refused(course, reviewed, monkeypatch, capsys):
    decisions = reviewed["out"].with_name("review-demo.decisions.yaml")
    with decisions.open("wb") as handle:
        handle.write(b"assignment: review-demo\n")
        handle.truncate(64 * 1024 * 1024)
    status, _, err = grade(course, reviewed["handed"], reviewed["out"], monkeypatch, capsys)
    assert status == 1 and str(decisions) in err and "allowed" in err and len(err.strip().splitlines()) == 1


# ---- exgen decide: checked against the graded run before the file is touched ---------------------------------

@pytest.fixture
def graded(course, tmp_path, monkeypatch, capsys):
    out = tmp_path / "graded" / "review-demo"
    assert grade(course, hand_in(course, tmp_path / "handed"), out, monkeypatch, capsys)[0] == 0
    return out


@pytest.mark.parametrize("argv, words", [
    (["--accept-spelling", "raises", "--question", 2, "--part", "z", "--means", "raises the bow"],
     "question 2 (gyroscopes.ship_turbine) has no part (z): its parts are a, b, c, d, e, f"),
    (["--accept-spelling", "raises", "--question", 9, "--part", "b", "--means", "raises the bow"],
     "there is no question 9: the assignment has questions 1 to 2"),
    (["--accept-spelling", "raises", "--question", 2, "--part", "b", "--means", "raises the stern"],
     "--means 'raises the stern' is not one of the part's choices (raises the bow, lowers the bow)"),
    (["--accept-spelling", "fast", "--question", 1, "--part", "a", "--means", "very fast"],
     "--means 'very fast' is not an answer the part reads"),
    (["--accept", "Z999", "--question", 1, "--part", "a"], "no student Z999 in this class"),
    (["--accept", "S001", "--question", 1, "--part", "a", "--points", 99], "--points 99 is outside 0 to"),
    (["--reject", "S001", "--question", 1, "--part", "a", "--points", 1], "--points is for --accept"),
    (["--accept-spelling", "raises", "--question", 2, "--part", "b"], "--accept-spelling needs --means"),
    (["--accept", "S001", "--question", 1, "--part", "a", "--means", "x"], "--means is for --accept-spelling"),
])
def test_decide_refuses_what_the_graded_run_does_not_hold_in_one_line(graded, capsys, argv, words):
    assert decide(graded, *argv) == 1
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert not graded.with_name("review-demo.decisions.yaml").exists()


def test_decide_refuses_a_student_who_handed_nothing_in(course, tmp_path, monkeypatch, capsys):
    handed = hand_in(course, tmp_path / "handed")
    (handed / "S001.yaml").unlink()
    out = tmp_path / "graded"
    assert grade(course, handed, out, monkeypatch, capsys)[0] == 0
    assert decide(out, "--accept", "S001", "--question", 1, "--part", "a") == 1
    assert "S001's answers were not graded (no submission)" in capsys.readouterr().err


def test_decide_replaces_the_decision_on_the_same_part_and_says_so(graded, capsys):
    assert decide(graded, "--accept", "s001", "--question", 1, "--part", "(A)", "--points", 1) == 0
    assert decide(graded, "--reject", "S001", "--question", 1, "--part", "a", "--comment", "no  unit") == 0
    said = capsys.readouterr().out
    assert "rejected S001's answer" in said and "(replacing the earlier decision)" in said
    from graders.decisions import load_decisions

    (decision,) = load_decisions(graded.with_name("review-demo.decisions.yaml"), "review-demo").decisions
    assert (decision.decision, decision.points, decision.comment, decision.template) == \
        ("reject", None, "no unit", "belts.driven_speed_slip")


def test_grading_in_worker_processes_applies_the_same_decisions(course, reviewed, bank, monkeypatch):
    """A large class is graded in worker processes: the decisions reach them, and the marks are the same."""
    import graders.grade as grading
    from graders.decisions import load_decisions
    from graders.record import batch_record

    manifest = read_manifest(course["root"] / "issued")
    decisions = load_decisions(reviewed["out"].with_name("review-demo.decisions.yaml"), "review-demo")
    alone = grading.grade_issued(manifest, bank, SECRET.encode(), reviewed["handed"], decisions=decisions)
    monkeypatch.setattr(grading, "PARALLEL_FROM", 2)
    shared = grading.grade_issued(manifest, bank, SECRET.encode(), reviewed["handed"], decisions=decisions, jobs=2)
    assert batch_record(shared) == batch_record(alone)
    assert sum(p.review is not None for s in shared.sheets for q in s.questions for p in q.parts) == 4


def test_every_decision_that_matches_nothing_is_listed_with_why_and_changes_no_mark(course, graded, monkeypatch,
                                                                                    capsys):
    """Written by hand: a question, part, template, student, choice or number of points the run does not have."""
    handed = graded.parent.parent / "handed"
    first, first_marks = files(graded), marks(graded)
    student = course["planted"]["direction"][0]
    given = json.loads((graded / "results.json").read_text())["sheets"]
    text = next(p["given"] for s in given if s["student"]["id"] == student for p in s["parts"]
                if (p["slot"], p["part"]) == ("q1", "a"))

    def decision(**fields):
        base = {"student": student, "question": 1, "part": "a", "answer": text, "decision": "accept",
                "reviewer": "me", "reason": "why"}
        return {**base, **fields}

    def alias(**fields):
        base = {"question": 2, "part": "b", "template": "gyroscopes.ship_turbine", "spelling": "raises",
                "means": "raises the bow", "reviewer": "me", "reason": "why"}
        return {**base, **fields}

    wrong = {"decisions": [decision(question=7), decision(part="z"), decision(student="Z999"),
                           decision(template="belts.flat_belt_power", student=course["planted"]["alias_wrong"][0]),
                           decision(points=99)],
             "aliases": [alias(template="belts.flat_belt_power"), alias(part="z"), alias(means="sideways", spelling="up"),
                         alias(question=5)]}
    path = graded.with_name("review-demo.decisions.yaml")
    path.write_text(yaml.safe_dump({"assignment": "review-demo", **wrong}, sort_keys=False), encoding="utf-8")
    status, said, err = grade(course, handed, graded, monkeypatch, capsys)
    assert status == 0 and "9 not applied" in said, err
    for why in ("the assignment has no question 7 (it has 2)", "question 1 (belts.driven_speed_slip) has no part (z)",
                "no student Z999 in this class", "the question is now belts.driven_speed_slip, not belts.flat_belt_power",
                "it gives 99 points, more than the part's", "question 2 is now gyroscopes.ship_turbine, not "
                "belts.flat_belt_power", "question 2 (gyroscopes.ship_turbine) has no part (z)",
                "'sideways' is not one of the part's choices (raises the bow, lowers the bow)",
                "the assignment has no question 5 (it has 2)"):
        assert why in err, why
    assert all(re.search(rf"{re.escape(str(path))}:\d+: ", line) for line in err.splitlines() if "not applied" in line)
    after = files(graded)
    for name in ("gradebook.csv", "canvas_gradebook.csv", "moodle_grades.csv", "parts.csv"):
        assert after[name] == first[name], name
    assert marks(graded) == first_marks
    record = json.loads((graded / "results.json").read_text())
    assert all(p["review"] is None for s in record["sheets"] for p in s["parts"])
    assert len(record["review"]["not_applied"]) == 9


def test_a_hostile_comment_reaches_the_feedback_harmless(course, graded, monkeypatch, capsys):
    student = course["planted"]["direction"][0]
    comment = "<script>alert(1)</script> `code` [link](http://x) \u202eevil &lt;"
    assert decide(graded, "--accept", student, "--question", 1, "--part", "a", "--comment", comment) == 0
    assert grade(course, graded.parent.parent / "handed", graded, monkeypatch, capsys)[0] == 0
    page = (graded / "feedback" / f"{student}.md").read_text(encoding="utf-8")
    line = next(text for text in page.splitlines() if "Marked by hand" in text)
    assert "<" not in line and "\u202e" not in line and "`" not in line and "&lt;" not in line


def test_a_decision_and_an_alias_can_be_withdrawn(course, graded, monkeypatch, capsys):
    first = marks(graded)
    handed = graded.parent.parent / "handed"
    student = course["planted"]["direction"][0]
    assert decide(graded, "--accept", student, "--question", 1, "--part", "a") == 0
    assert decide(graded, "--accept-spelling", "raises", "--question", 2, "--part", "b", "--means", "raises the bow") == 0
    assert grade(course, handed, graded, monkeypatch, capsys)[0] == 0
    assert marks(graded) != first
    assert main(["decide", str(graded), "--withdraw", student, "--question", "1", "--part", "a"]) == 0
    assert main(["decide", str(graded), "--withdraw-spelling", " RAISES", "--question", "2", "--part", "b"]) == 0
    assert "withdrew the spelling 'RAISES' on question 2 (b)" in capsys.readouterr().out
    assert main(["decide", str(graded), "--withdraw", student, "--question", "1", "--part", "a"]) == 1
    assert f"there is no decision on {student}'s question 1 (a)" in capsys.readouterr().err
    assert main(["decide", str(graded), "--accept", student, "--question", "1", "--part", "a"]) == 1
    assert "--reviewer is required" in capsys.readouterr().err
    assert grade(course, handed, graded, monkeypatch, capsys)[0] == 0
    assert marks(graded) == first


@pytest.mark.parametrize("edit", [
    lambda r: r.pop("columns"),
    lambda r: r.update(assignment=["x"]),
    lambda r: r["columns"][0].update(parts="abc"),
    lambda r: r["sheets"][0].update(student=None),
    lambda r: r["sheets"][0]["parts"][0].update(max_points="2"),
])
def test_decide_on_results_edited_by_hand_is_one_line(graded, capsys, edit):
    record = json.loads((graded / "results.json").read_text(encoding="utf-8"))
    edit(record)
    (graded / "results.json").write_text(json.dumps(record), encoding="utf-8")
    for argv in (["--accept", "S001"], ["--accept-spelling", "up", "--means", "raises the bow"], ["--withdraw", "S001"]):
        argv += ["--question", 2, "--part", "b"]
        status = main(["decide", str(graded), *map(str, argv)] + ([] if "--withdraw" in argv else
                                                                  ["--reviewer", "me", "--reason", "why"]))
        err = capsys.readouterr().err
        assert status == 1 and "not grading results as exgen grade writes them" in err and len(err.splitlines()) == 1
