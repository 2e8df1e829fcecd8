"""Example 6.2 and its companions: the natural frequency as a formula in K, M and m, from the bank's own
template, through exgen solve and through the whole sheet -> answer file -> grade path of the command line.

The text's answer: K' = K and m' = 3M/2 + 4m at the pulley's centre, so f = √(2K/(3M + 8m))/2π. Forms that
are the same function are right; ω_n (the 2π left out) is the named mistake omega_for_f.
"""
import csv
import json
import math
import re

import pytest
import yaml

from exgen.answertypes.symbolic import Expression
from exgen.check.given import solve
from exgen.cli import main
from exgen.solve.variant import make_variant
from exgen.solvers.vibration_formulas import SYMBOLS, SYSTEMS
from graders.grade import grade_variant

TEMPLATE = "vibration.natural_frequency_formula"
EQUIVALENT = ["sqrt(2*K/(3*M+8*m))/(2*pi)", "(2K/(3M+8m))^(1/2)/(2π)", "1/(2*pi)*sqrt(2*K/(3*M+8*m))",
              "1/(2π)√(2K/(3M+8m))", "sqrt(K/(1.5M + 4m))/(2pi)"]
#: each system's formula worked by hand (energy: ½ m' ẋ² and ½ K' x² at the reference point)
BY_HAND = {
    "floating pulley": lambda K, M, m: math.sqrt(K / (1.5 * M + 4 * m)) / (2 * math.pi),
    "fixed pulley": lambda K, M, m: math.sqrt(K / (0.5 * M + m)) / (2 * math.pi),
    "stepped pulley": lambda K, M, m: math.sqrt((K / 4) / (0.5 * M + m)) / (2 * math.pi),
    "lever": lambda K, M, m: math.sqrt(K / (M / 3 + m / 4)) / (2 * math.pi),
    "two springs": lambda K, M, m: math.sqrt(2 * K * (0.5 ** 2) / (M / 12 + m * 0.5 ** 2)) / (2 * math.pi),
}


def test_example_6_2_formula_and_value(bank):
    variant, warnings = solve(bank.get(TEMPLATE), {"system": "floating pulley", "K": "2000 N/m", "M": "4 kg",
                                                   "m": "2 kg"})
    formula = variant.answers["a"].value
    assert str(formula) == "sqrt(2*K/(3*M + 8*m))/(2*pi)" or all(
        formula(K=k, M=big, m=small) == pytest.approx(math.sqrt(2 * k / (3 * big + 8 * small)) / (2 * math.pi))
        for k, big, small in ((1000, 2, 1), (3000, 7, 0.5), (150, 0.6, 19)))
    assert variant.answers["b"].value == pytest.approx(math.sqrt(4000 / 28) / (2 * math.pi))   # 1.902 Hz
    assert str(variant.step("m_eq").value) in ("3*M/2 + 4*m", "3 * M / 2 + 4 * m") or \
        variant.step("m_eq").value(K=1, M=2, m=3) == pytest.approx(15)
    assert warnings == []


@pytest.mark.parametrize("system", sorted(SYSTEMS))
def test_every_system_s_formula_agrees_with_the_energy_method(bank, system):
    variant, _ = solve(bank.get(TEMPLATE), {"system": system, "K": "1500 N/m", "M": "3 kg", "m": "2.5 kg"})
    formula = variant.answers["a"].value
    for k, big, small in ((1000, 2, 1), (3000, 7, 0.5), (150, 0.6, 19), (9000, 15, 4)):
        assert formula(K=k, M=big, m=small) == pytest.approx(BY_HAND[system](k, big, small))
    assert variant.answers["b"].value == pytest.approx(BY_HAND[system](1500, 3, 2.5))


@pytest.mark.parametrize("text", EQUIVALENT)
def test_equivalent_forms_are_right(bank, text):
    variant, _ = solve(bank.get(TEMPLATE), {"system": "floating pulley", "K": "2 kN/m", "M": "4 kg", "m": "2 kg"})
    (part,) = [p for p in grade_variant(variant, {"a": text}).parts if p.part_id == "a"]
    assert part.points == part.max_points, (text, part.message)


@pytest.mark.parametrize("system", sorted(SYSTEMS))
def test_the_missing_2pi_and_each_system_s_slips_are_named(bank, system):
    template = bank.get(TEMPLATE)
    variant = next(v for v in (make_variant(template, s) for s in range(80)) if v.param("system").exact == system)
    recorded = variant.mistakes["a"]
    assert "omega_for_f" in recorded and set(SYSTEMS[system].slips) <= set(recorded)
    for name, wrong in recorded.items():
        (part,) = [p for p in grade_variant(variant, {"a": str(wrong)}).parts if p.part_id == "a"]
        assert part.points == 0 and part.mistake == name, (system, name, part.mistake)
        say = next((m.say for m in template.part("a").mistakes if m.when == name), "")
        assert part.message == (say or part.message)


def test_sheet_answer_file_and_grade_on_the_command_line(tmp_path, capsys):
    """exgen generate -> the student's answers.yaml filled in -> exgen grade: equivalent forms full marks,
    ω for f named, and (b) worked from a student's own formula carried forward."""
    roster = tmp_path / "roster.csv"
    roster.write_text("id,name\n" + "".join(f"s{i},Student {i}\n" for i in range(1, 5)), encoding="utf-8")
    (tmp_path / "course.secret").write_text("a long and private course secret for this test only\n", encoding="utf-8")
    assignment = tmp_path / "hw.yaml"
    assignment.write_text(yaml.safe_dump({
        "assignment": "hw-formula", "title": "Formula answers", "secret_file": "course.secret",
        "roster": "roster.csv", "questions": [{"template": TEMPLATE}]}), encoding="utf-8")
    assert main(["generate", str(assignment), "--out", str(tmp_path / "out"), "--no-pdf"]) == 0
    # the three forms, written for whichever system each student drew
    typed = {"s1": "(({k})/({m}))^(1/2)/(2π)", "s2": "1/(2*pi)*sqrt(({k})/({m}))", "s3": "omega",
             "s4": "sqrt(({k})/({m}))/(2*pi)"}
    submissions = tmp_path / "returned"
    submissions.mkdir()
    for student, how in typed.items():
        folder = tmp_path / "out" / "students" / student
        form = (folder / "answers.yaml").read_text(encoding="utf-8")
        sheet = (folder / "sheet.md").read_text(encoding="utf-8")
        system = next(name for name in SYSTEMS if _describes(sheet, name))
        values = {name: float(re.search(rf"\${name}\$ = ([\d.]+)", sheet.replace("\\", "")).group(1))
                  for name in ("K", "M", "m")}
        right = BY_HAND[system]
        if how == "omega":
            formula = str(Expression.parse(_formula(system), SYMBOLS)).replace("/(2*pi)", "")
            value = right(**values) * 2 * math.pi
        else:
            formula = how.format(k=SYSTEMS[system].stiffness, m=SYSTEMS[system].mass)
            value = right(**values)
        form = form.replace('    a: ""', f"    a: {json.dumps(formula, ensure_ascii=False)}", 1)
        form = form.replace('    b: ""', f'    b: "{value:.5g} Hz"', 1)
        (submissions / f"{student}.yaml").write_text(form, encoding="utf-8")
    assert main(["grade", str(tmp_path / "out"), str(submissions), "--out", str(tmp_path / "graded")]) == 0
    with open(tmp_path / "graded" / "gradebook.csv", encoding="utf-8") as handle:
        rows = {row["id"] if "id" in row else row["student"]: row for row in csv.DictReader(handle)}
    totals = {student: float(next(v for k, v in rows[student].items() if k.lower() in ("total", "score", "points")))
              for student in typed}
    assert totals["s1"] == totals["s2"] == totals["s4"] == 4.0   # 3 for the formula, 1 for the value
    assert totals["s3"] == 1.0                                     # ω for f: (a) wrong, (b) carried forward
    feedback = next((tmp_path / "graded").rglob("s3.md")).read_text(encoding="utf-8")
    assert "circular frequency ω in rad/s" in feedback


def _formula(system: str) -> str:
    s = SYSTEMS[system]
    return f"sqrt(({s.stiffness})/({s.mass}))/(2*pi)"


def _describes(sheet: str, system: str) -> bool:
    words = {"floating pulley": "hangs in a loop", "fixed pulley": "turns on a fixed horizontal axle. A light cord",
             "stepped pulley": "light hub", "lever": "pivoted at one end", "two springs": "pivoted at its middle"}
    return words[system] in " ".join(sheet.split())
