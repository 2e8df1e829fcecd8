"""Every worked example and tutorial problem of the course text solves with its template, and the
template's ranges either draw the text's own numbers or say in the YAML why they do not.

The cases are tests/textbook_cases.py: the givens the textbook tests use, in one list.
"""
from __future__ import annotations

import re
from decimal import Decimal

import pytest

from exgen.check.given import solve
from textbook_cases import CASES

#: "Example 1.5", "Problem 2.4(a)", "Problems 6.4 and 6.5", "Problems 7.2-7.3" in a template's `source:`.
NAMED = re.compile(r"(Examples?|Problems?) (\d\.\d+(?:\([ab]\))?)((?:(?:,| and|-) ?\d\.\d+(?:\([ab]\))?)*)")

#: Named by a template but not solvable with it yet, and why: each is a finding, not a pass (none now).
NOT_YET: dict[str, str] = {}


def named_cases(source: str) -> list[str]:
    """The examples and problems a template's source names, one label each."""
    out = []
    for kind, first, rest in NAMED.findall(source):
        singular = kind.rstrip("s")
        numbers = [first] + re.findall(r"\d\.\d+(?:\([ab]\))?", rest)
        if "-" in rest and len(numbers) == 2:       # a range, "Problems 7.2-7.3"
            chapter, low = numbers[0].split(".")
            numbers = [f"{chapter}.{k}" for k in range(int(low), int(numbers[1].split(".")[1]) + 1)]
        out += [f"{singular} {n}" for n in numbers]
    return out


def _case_id(case) -> str:
    return f"{case[0]}:{case[1]}"


@pytest.mark.parametrize("case", CASES, ids=_case_id)
def test_every_example_and_problem_solves_with_the_text_s_numbers(bank, case):
    label, template_id, given = case
    variant, _warnings = solve(bank.get(template_id), {k: str(v) for k, v in given.items()})  # a refusal raises
    assert set(variant.answers) == {part.id for part in bank.get(template_id).parts}, label


def test_every_example_and_problem_a_template_follows_has_a_case(bank):
    labels = {label for label, _, _ in CASES}
    missing = []
    for template in bank:
        for named in named_cases(template.source):
            if named in NOT_YET:
                continue
            if not any(label == named or label.startswith(named + " ") or label.startswith(named + "(")
                       for label in labels):
                missing.append(f"{template.id}: {named}")
    assert missing == []


def test_the_source_names_are_read_as_the_text_numbers_them():
    assert named_cases("Problems 6.4 and 6.5") == ["Problem 6.4", "Problem 6.5"]
    assert named_cases("Example 2.7, Problem 2.4(a)") == ["Example 2.7", "Problem 2.4(a)"]
    assert named_cases("Problems 7.2-7.3") == ["Problem 7.2", "Problem 7.3"]
    assert named_cases("Examples 1.10 and 1.11") == ["Example 1.10", "Example 1.11"]
    assert named_cases("Example 2.8, Problems 2.3 and 2.4(b)") == ["Example 2.8", "Problem 2.3", "Problem 2.4(b)"]


def _says_why(template, named: str) -> bool:
    """Whether a comment in the template's parameters names the case ("Problem 4.4: 1.2 kg, under ...")."""
    lines = template.path.read_text(encoding="utf-8").splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("params:"))
    end = next((i for i in range(start + 1, len(lines)) if lines[i][:1].isalpha()), len(lines))
    comments = [line.split("#", 1)[1] for line in lines[start:end] if "#" in line]
    return any(re.search(rf"{re.escape(named)}(?![\d.])", comment) for comment in comments)


def _own_cases():
    """The cases that are their template's own source, with the text's own numbers (not data of our own)."""
    for case in CASES:
        label, template_id, _ = case
        if "data of our own" in label:
            continue
        yield case


@pytest.mark.parametrize("case", list(_own_cases()), ids=_case_id)
def test_a_template_draws_its_own_source_s_numbers_or_says_why_not(bank, case):
    label, template_id, given = case
    template = bank.get(template_id)
    named = label.split(" (")[0]
    if named not in named_cases(template.source):
        pytest.skip(f"{label} is not {template_id}'s own source")
    variant, _ = solve(template, {k: str(v) for k, v in given.items()})
    outside = []
    for spec in template.params:
        if spec.name not in given or spec.derived or spec.given is False:
            continue
        value = variant.param(spec.name).exact
        if spec.is_range:
            inside = isinstance(value, Decimal) and spec.min <= value <= spec.max
        else:
            inside = value in spec.choices or str(variant.param(spec.name).text) in map(str, spec.choices)
        if not inside:
            outside.append(f"{spec.name} = {given[spec.name]}")
    assert outside == [] or _says_why(template, named), \
        f"{template_id} leaves out {label}'s numbers ({', '.join(outside)}) without a comment naming {named} in its params"
