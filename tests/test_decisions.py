"""The review decisions file: read with the capped YAML reader, every mistake one line at file:line, written
back in a stable order that reads back to the same decisions (whatever text a student typed), and a
decision holds for the answer text it was made on only."""
import json
import time
from pathlib import Path

import pytest

from graders.decisions import (ACCEPT, REJECT, Alias, Decision, Decisions, DecisionsError, cleaned, default_path,
                               dump, load_decisions, save_decisions, spelling_key)

HOSTILE = json.loads((Path(__file__).parent / "hostile" / "strings.json").read_text(encoding="utf-8"))
BILLION_LAUGHS = "".join(f"{a}: &{a} [{', '.join(['*' + p] * 9 if p else ['lol'] * 9)}]\n"
                         for a, p in zip("abcdefghi", ["", *"abcdefgh"]))
GOOD = """\
# Review decisions for tutorial1: exgen grade applies them on every run.
assignment: tutorial1
decisions:
  - student: A21001
    question: 3
    part: b
    answer: "348.3 rpm clockwise"
    decision: accept
    points: 2.0
    comment: "the direction word is fine"
    reviewer: "A. Lecturer"
    reason: "the sense was asked in (c)"
aliases:
  - question: 3
    part: c
    template: gyroscopes.ship_turbine
    spelling: "raises"
    means: "raises the bow"
    reviewer: "A. Lecturer"
    reason: "the sheet's wording invites it"
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "graded.decisions.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def refusal(path: Path, assignment: str | None = None) -> str:
    with pytest.raises(DecisionsError) as caught:
        load_decisions(path, assignment)
    message = str(caught.value)
    assert "\n" not in message and message.startswith(str(path))
    return message


def test_the_agreed_shape_reads_as_decisions_and_aliases(tmp_path):
    found = load_decisions(write(tmp_path, GOOD), "tutorial1")
    assert found.assignment == "tutorial1"
    (decision,) = found.decisions
    assert (decision.student, decision.question, decision.part, decision.decision, decision.points) == \
        ("A21001", 3, "b", ACCEPT, 2.0)
    assert decision.line == 4 and found.decision_for("A21001", 3, "b") is decision
    (alias,) = found.aliases_for(3, "c")
    assert alias.means == "raises the bow" and alias.matches("  Raises ") and not alias.matches("raises the bow")
    assert alias.line == 14


def test_the_default_file_sits_beside_the_graded_folder_not_in_it(tmp_path):
    out = tmp_path / "graded" / "tutorial1"
    assert default_path(out) == tmp_path / "graded" / "tutorial1.decisions.yaml"
    assert out not in default_path(out).parents


def test_a_missing_default_file_is_no_decisions_and_a_missing_named_one_is_an_error(tmp_path):
    assert not load_decisions(tmp_path / "none.yaml", "t1")
    with pytest.raises(DecisionsError, match="none.yaml: no such file"):
        load_decisions(tmp_path / "none.yaml", "t1", missing_ok=False)


def test_a_decision_holds_for_its_own_text_only():
    decision = Decision("A1", 1, "a", cleaned("348.3 rpm\tclockwise"), ACCEPT, "me", "why")
    assert decision.answer == "348.3 rpm clockwise"
    assert decision.matches("t.x", "348.3  rpm\nclockwise")  # the same text, as results.json cleans it
    assert not decision.matches("t.x", "348.3 rpm")
    assert not decision.matches("t.x", "348.3 RPM clockwise")
    pinned = Decision("A1", 1, "a", "5", REJECT, "me", "why", template="t.x")
    assert pinned.matches("t.x", "5") and not pinned.matches("t.y", "5")
    assert pinned.points_for(3.0) == 0.0 and decision.points_for(3.0) == 3.0
    assert Decision("A1", 1, "a", "5", ACCEPT, "me", "why", points=1.5).points_for(3.0) == 1.5


def test_adding_replaces_the_same_part_and_keeps_a_stable_order():
    base = Decisions("t1")
    d1 = Decision("B2", 2, "a", "x", ACCEPT, "me", "r1")
    d2 = Decision("A1", 2, "a", "y", REJECT, "me", "r2")
    d3 = Decision("A1", 1, "b", "z", ACCEPT, "me", "r3")
    one = base.with_decision(d1).with_decision(d2).with_decision(d3)
    other = base.with_decision(d3).with_decision(d1).with_decision(d2)
    assert one == other and [d.key for d in one.decisions] == [("A1", 1, "b"), ("A1", 2, "a"), ("B2", 2, "a")]
    again = one.with_decision(Decision("A1", 2, "a", "y", ACCEPT, "you", "r4"))
    assert len(again.decisions) == 3 and again.decision_for("A1", 2, "a").reviewer == "you"
    a1 = Alias(1, "a", "t.x", "Raises", "raises the bow", "me", "r")
    assert len(Decisions("t1").with_alias(a1).with_alias(Alias(1, "a", "t.x", "raises ", "lowers the bow", "me", "r"))
               .aliases) == 1
    assert dump(one) == dump(other)


def test_what_is_saved_reads_back_the_same_whatever_was_typed(tmp_path):
    """Every hostile string of the corpus as an answer, a spelling, a comment and a reason."""
    decisions = Decisions("tutorial1", path=tmp_path / "d.yaml")
    for i, text in enumerate(HOSTILE):
        decisions = decisions.with_decision(Decision(f"S{i:03d}", 1 + i % 5, "abc"[i % 3], cleaned(text),
                                                     (ACCEPT, REJECT)[i % 2], cleaned(text) or "me",
                                                     cleaned(text) or "why", points=None if i % 4 else 0.5 * (i % 2 == 0),
                                                     comment=cleaned(text)[:400]))
        if spelling_key(text) and spelling_key(text) != "x":
            decisions = decisions.with_alias(Alias(1 + i % 5, "b", "t.x", cleaned(text), "x", "me", "why"))
    path = save_decisions(decisions)
    again = load_decisions(path, "tutorial1")
    assert again.decisions == decisions.decisions and again.aliases == decisions.aliases
    assert dump(again) == path.read_text(encoding="utf-8")
    assert [p.name for p in tmp_path.iterdir()] == ["d.yaml"]  # no temporary file left


def test_the_saved_file_is_plain_block_yaml_a_line_a_field(tmp_path):
    path = save_decisions(load_decisions(write(tmp_path, GOOD)), tmp_path / "out.yaml")
    text = path.read_text(encoding="utf-8")
    assert text.startswith("# Review decisions for tutorial1: exgen grade applies them on every run.\n")
    assert "  - student: A21001\n    question: 3\n    part: b\n    answer: 348.3 rpm clockwise\n" in text
    assert "{" not in text and "&" not in text


@pytest.mark.parametrize("text, where, words", [
    (GOOD.replace("question: 3\n    part: b", "question: three\n    part: b"), ":5:5:", "the question's number"),
    (GOOD.replace("student: A21001", "student: 21001"), ":4:5:", "write it as text in quotes"),
    (GOOD.replace("decision: accept", "decision: maybe"), ":8:5:", "accept or reject"),
    (GOOD.replace("points: 2.0", "points: -1"), ":9:5:", "0 or more"),
    (GOOD.replace("points: 2.0", "points: .nan"), ":9:5:", "0 or more"),
    (GOOD.replace("decision: accept", "decision: reject"), ":9:5:", "a rejected answer scores 0"),
    (GOOD.replace('    reviewer: "A. Lecturer"\n    reason: "the sense', '    reason: "the sense'), ":4:5:",
     "`reviewer:` is missing"),
    (GOOD.replace("    comment:", "    coment:"), ":10:5:", "`coment:` is not a field of a decision"),
    (GOOD.replace("aliases:", "alias:"), ":13:1:", "`alias:` is not a key"),
    (GOOD.replace("part: c", "part: 3"), ":15:5:", "named by its letter"),
    (GOOD.replace('spelling: "raises"', 'spelling: "raises the bow"'), ":18:5:", "the spelling itself"),
    ("assignment: t\ndecisions: 5\n", ":2:1:", "must be a list"),
    (GOOD + GOOD.split("aliases:\n")[1], ":21:5:", "is here twice (first on line 14)"),
    (GOOD.replace("  - student", "\t- student"), ":4:", "a tab character"),
    (GOOD.replace('answer: "348.3 rpm clockwise"', 'answer: "348.3 rpm'), ":", "quote"),
    ("- a\n- b\n", ":1:1:", "holds a list"),
    ("assignment: t\ndecisions: [1]\n", ":2:13:", "a decision holds a number"),
    ("assignment: t\naliases:\n  - [a, b]\n", ":3:5:", "an alias holds a list"),
    (GOOD.replace('answer: "348.3 rpm clockwise"', "answer: [348.3]"), ":7:5:", "`answer:` is a list"),
    (GOOD.replace('comment: "the direction word is fine"', "comment: {a: 1}"), ":10:5:", "`comment:` is a mapping"),
    (GOOD.replace("points: 2.0", 'points: "2"'), ":9:5:", "it is a number of points"),
    (GOOD.replace("points: 2.0", "points: true"), ":9:5:", "it is a number of points"),
    (GOOD.replace('answer: "348.3 rpm clockwise"', 'answer: "348.3  rpm"'), ":7:5:", "copy it from there"),
    (GOOD.replace('comment: "the direction word is fine"', "comment: " + "x" * 401), ":10:5:", "at most 400"),
    ("assignment: 5\n", ":1:1:", "`assignment:` is a number"),
    (BILLION_LAUGHS, ":", "entries from here down (aliases counted"),
    ("a: &a [1, *a]\n", ":1:4:", "a loop"),
    ("assignment: " + "[" * 40 + "]" * 40 + "\n", ":1:", "nested more than 16 levels"),
    ("assignment: !!python/object:os.system x\n", ":1:", "a tag"),
    (GOOD.replace("assignment: tutorial1", "assignment: tutorial1\nassignment: other"), ":3:1:", "appears twice"),
])
def test_a_hostile_or_mistaken_file_is_one_line_with_its_place(tmp_path, text, where, words):
    message = refusal(write(tmp_path, text))
    assert where in message and words in message, message


def test_decisions_for_another_assignment_are_refused(tmp_path):
    assert "decisions for the assignment 'tutorial1', not 'tutorial2'" in refusal(write(tmp_path, GOOD), "tutorial2")


def test_a_huge_file_is_refused_before_it_is_read(tmp_path):
    path = tmp_path / "d.yaml"
    with path.open("wb") as handle:
        handle.write(b"assignment: t\n")
        handle.truncate(1024 * 1024 * 1024)
    started = time.perf_counter()
    message = refusal(path)
    assert "MiB allowed" in message or "allowed" in message
    assert time.perf_counter() - started < 60  # a hang guard only: it takes milliseconds


def test_a_file_of_a_large_class_reads(tmp_path):
    """A thousand students with ten parts each reviewed: 10,000 decisions."""
    decisions = Decisions("t1")
    items = [Decision(f"S{s:04d}", 1 + p // 3, "abc"[p % 3], f"{s}.{p} rpm cw", ACCEPT, "A. Lecturer",
                      "units written out") for s in range(1000) for p in range(10)]
    decisions = Decisions("t1", tuple(items))
    path = save_decisions(decisions, tmp_path / "big.yaml")
    assert load_decisions(path, "t1").decisions == decisions.with_decision(items[0]).decisions
