"""Fuzzing the readers of every answer type (through the registry, as the grader reaches them) and of
answer files: each generated input ends in a verdict or a clear message, never an exception, and nothing
typed is ever evaluated. Together the tests below generate 10,200 inputs; `benchmarks/fuzz.py` runs the
same strategies and reports the slowest input."""
from __future__ import annotations

import os

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from exgen.answertypes import read, registry
from exgen.errors import FormatProblem, SubmissionError, WrongKind
from fuzz_inputs import answer_file, answer_text, long_text, quantity_text, shaped_text
from graders.answers import read_submission

MARKER = "/tmp/exgen-fuzz-was-evaluated"
FUZZ = dict(deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                  HealthCheck.large_base_example])
#: Generated inputs per test (the total is what CI runs).
COUNTS = {"any": 3000, "quantity": 3000, "shaped": 2000, "long": 200, "files": 2000}


def every_type():
    return [(kind, kind.sample_part()) for _, kind in sorted(registry().items())]


def judge(text: str) -> list[str]:
    """Read `text` as an answer of every registered type and judge it as the grader would: a verdict
    (right or wrong, with its feedback) or a clear message. Anything else raised fails the test."""
    outcomes = []
    for kind, part in every_type():
        try:
            given_ = read(text, part)
        except (FormatProblem, WrongKind) as exc:
            assert str(exc).strip(), f"{kind.name}: an empty message for {text[:80]!r}"
            outcomes.append("unreadable" if isinstance(exc, FormatProblem) else "wrong kind")
            continue
        expected = kind.example(part)
        right = kind.matches(given_.value, expected, part)
        assert isinstance(right, bool)
        if not right:
            kind.slip(given_, expected, part)
            assert kind.wrong_message(given_, part).strip()
        outcomes.append("right" if right else "wrong")
    assert not os.path.exists(MARKER)
    return outcomes


def test_every_registered_type_is_fuzzed():
    assert {k.name for k, _ in every_type()} >= {"number", "angle", "integer", "choice", "polar", "symbolic"}


@settings(max_examples=COUNTS["any"], **FUZZ)
@given(st.text(max_size=200))
def test_any_text_at_all(text):
    judge(text)


@settings(max_examples=COUNTS["quantity"], **FUZZ)
@given(quantity_text())
def test_quantities_with_unicode_digits_minus_signs_spaces_marks_and_huge_exponents(text):
    judge(text)


@settings(max_examples=COUNTS["shaped"], **FUZZ)
@given(shaped_text())
def test_sizes_at_angles_choices_and_formulas(text):
    judge(text)


@settings(max_examples=COUNTS["long"], **FUZZ)
@given(long_text())
def test_strings_up_to_a_megabyte(text):
    assert set(judge(text)) == {"unreadable"}  # refused before any reading: too long for every type


@settings(max_examples=COUNTS["files"], **FUZZ)
@given(answer_file())
def test_answer_files_of_every_format(tmp_path_factory, suffix_bytes):
    suffix, data = suffix_bytes
    path = tmp_path_factory.mktemp("fuzz", numbered=True) / f"s001{suffix}"
    path.write_bytes(data)
    try:
        submission = read_submission(path)
    except SubmissionError as exc:
        assert exc.detail.strip() and str(path) in str(exc)
        return
    for parts in submission.answers.values():
        for text in parts.values():
            judge(text)


def test_a_long_run_of_spaces_is_refused_before_any_pattern_reads_it(monkeypatch):
    """Found by the fuzzing above: `\\s*°` ran over 200,000 spaces in quadratic time (minutes per answer)."""
    from exgen.answertypes import quantity

    seen = []

    class Recording:
        def sub(self, replacement, text):
            seen.append(len(text))
            return text

    monkeypatch.setattr(quantity, "_DEGREE_SIGNS", Recording())
    for kind, part in every_type():
        for text in (" " * 200_000, "5" + " " * 200_000 + "N", "\t" * 200_000 + "°"):
            try:
                read(text, part)
            except (FormatProblem, WrongKind):
                pass
    assert max(seen, default=0) <= 200
