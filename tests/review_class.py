"""A small class graded with what needs a human planted in it, for the review page's tests: four students
typing the same spelling a choice part cannot read, one a unit with a word after it, one a blank beside
answered parts, one handing in another's numbers, one markup with a bidi override, the rest right. Issued and graded as a lecturer does,
with `exgen generate` and `exgen grade`."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import yaml

from exgen.cli import main
from exgen.issue.assignment import build_sheet
from exgen.issue.manifest import read_manifest
from exgen.load.bank import load_bank

SECRET = "9c2e4a6f8b0d1e3f5a7c9b1d3f5e7a9c0b2d4f6e8a0c2e4f"
ASSIGNMENT = """assignment: review-demo
title: "Tutorial 5: Belts and gyroscopes"
course: BMCM 2723 Mechanics of Machines
secret_file: course.secret
roster: roster.csv
questions:
  - template: belts.driven_speed_slip
  - template: gyroscopes.ship_turbine
"""
NAMES = ["Aisyah Rahman", "Daniel Lim", "Priya Ramasamy", "Haziq Azmi", "Chen Mei Ling", "Arjun Nair",
         "Farah Ismail", "Tan Wei Jie", "Kavitha Pillai", "Amir Yusof"]
STUDENTS = [f"A2100{i}" if i < 10 else f"A210{i}" for i in range(1, len(NAMES) + 1)]
SPELLING = "raises"              # typed for q2 (b) by the first four: not one of the choices
SPELLERS = STUDENTS[:4]
UNIT_WORD = "348.3 rpm clockwise"  # typed for q1 (a) by the fifth: a unit exgen does not know
WORDY = STUDENTS[4]
BLANKER = STUDENTS[5]            # leaves q1 (b) blank, answers the rest
COPIER, SOURCE = STUDENTS[6], STUDENTS[7]  # the copier hands in the source's numbers for q1 and q2 (a), (c), (d)
COPIED = (("q1", "a"), ("q1", "b"), ("q1", "c"), ("q2", "a"), ("q2", "c"), ("q2", "d"))
HOSTILE = STUDENTS[8]            # types markup and a bidi override for q1 (c)
HOSTILE_TEXT = "<img src=x onerror=alert(1)>\u202e 12 rpm"


@dataclass(frozen=True)
class Graded:
    root: Path
    issued: Path
    submissions: Path
    graded: Path
    keys: dict  # student -> slot -> part -> the key's text

    @property
    def decisions(self) -> Path:
        return self.graded.with_name(self.graded.name + ".decisions.yaml")

    def grade(self, *extra: str) -> int:
        """`exgen grade` as the lecturer runs it again (after deciding)."""
        return main(["grade", str(self.issued), str(self.submissions), "--out", str(self.graded),
                     "--secret-file", str(self.root / "course.secret"), "--jobs", "1", *extra])


def graded_class(root: Path) -> Graded:
    root = Path(root)
    root.mkdir(parents=True, exist_ok=True)
    (root / "course.secret").write_text(SECRET + "\n", encoding="utf-8")
    (root / "course.secret").chmod(0o600)
    (root / "roster.csv").write_text("id,name\n" + "".join(f"{s},{n}\n" for s, n in zip(STUDENTS, NAMES)),
                                     encoding="utf-8")
    (root / "review-demo.yaml").write_text(ASSIGNMENT, encoding="utf-8")
    issued = root / "issued"
    assert main(["generate", str(root / "review-demo.yaml"), "--out", str(issued), "--no-pdf"]) == 0
    manifest = read_manifest(issued)
    bank = load_bank()
    keys = {}
    for student in manifest.students:
        sheet = build_sheet(manifest.assignment, student, bank, SECRET.encode())
        keys[student.id] = {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}
    submissions = root / "submissions"
    submissions.mkdir()
    for student in STUDENTS:
        answers = {slot: dict(parts) for slot, parts in keys[student].items()}
        if student in SPELLERS:
            answers["q2"]["b"] = SPELLING
        if student == WORDY:
            answers["q1"]["a"] = UNIT_WORD
        if student == BLANKER:
            answers["q1"]["b"] = ""
        if student == HOSTILE:
            answers["q1"]["c"] = HOSTILE_TEXT
        if student == COPIER:
            for slot, part in COPIED:
                answers[slot][part] = keys[SOURCE][slot][part]
        form = {"assignment": manifest.assignment.id, "student": student, "code": manifest.codes[student],
                "answers": answers}
        (submissions / f"{student}.yaml").write_text(yaml.safe_dump(form, allow_unicode=True, sort_keys=False),
                                                     encoding="utf-8")
    graded = Graded(root, issued, submissions, root / "graded" / "review-demo", keys)
    assert graded.grade() == 0
    return graded
