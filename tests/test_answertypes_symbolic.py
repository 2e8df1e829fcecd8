"""Formula answers: the grammar, equivalence at sampled points, named mistakes and generic slips, format
problems (hostile text among them), and one fixture template from sheet to key, answer file, grade, feedback
and error carried forward."""
import csv
import io
import json
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from exgen.answertypes import answer_type, read
from exgen.answertypes.expressions import MAX_LENGTH, Expression, ExpressionError
from exgen.check.validate import validate_template
from exgen.errors import BankError, FormatProblem
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.load.bank import load_bank, load_template
from exgen.render.answer_form import answer_form
from exgen.render.markdown import key_markdown, sheet_markdown
from exgen.render.pdf import key_pdf
from exgen.render.text import variant_text
from exgen.solve.variant import make_variant
from graders.answers import read_submission
from graders.grade import grade_batch, grade_variant
from graders.report import write_results
from graders.results import CARRIED, CORRECT, UNREADABLE, WRONG

FIXTURES = Path(__file__).parent / "fixtures" / "symbolic"
SECRET = b"a course secret used only by these tests"
SYMBOLS = ("K", "M", "m")
PART = answer_type("symbolic").sample_part()
RIGHT = Expression.parse("sqrt(2*K/(3*M + 8*m))/(2*pi)", SYMBOLS)


@pytest.fixture(scope="module")
def fixture_bank():
    return load_bank([FIXTURES])  # its solver is the file beside its template


@pytest.fixture(scope="module")
def variant(fixture_bank):
    return make_variant(fixture_bank.get("fixture.pulley_frequency"), 3)


def matches(text: str, expected: Expression = RIGHT) -> bool:
    return answer_type(PART).matches(read(text, PART).value, expected, PART)


# ---- equivalence -------------------------------------------------------------------------------------

@pytest.mark.parametrize("text", [
    "sqrt(2*K/(3*M+8*m))/(2*pi)", "(2K/(3M+8m))^(1/2)/(2π)", "1/(2*pi)*sqrt(2*K/(3*M+8*m))",
    "1/(2π)√(2K/(3M+8m))", "sqrt(2K/(3M+8m))/2/pi", "((2K)/(3M + 8m))**0.5/(2*pi)", "sqrt(K/(1.5M+4m))/(2pi)",
    "0.1592*sqrt(2K/(3M+8m))", "sqrt(2)*sqrt(K)/(2*pi*sqrt(3*M+8*m))", "(1/(2π))·√(2K ÷ (3M + 8m))",
    "exp(0.5*ln(2K/(3M+8m)))/(2pi)", "1/(2pi sqrt((3M+8m)/(2K)))", "  sqrt( 2 K / ( 3 M + 8 m ) ) / ( 2 pi ) ",
    # as copied from working: a name before, a frequency's unit after, square or curly brackets
    "f = sqrt(2K/(3M+8m))/(2pi)", "f_n=sqrt(2K/(3M+8m))/(2pi)", "fₙ = √(2K/(3M + 8m))/(2π)",
    "sqrt(2K/(3M+8m))/(2pi) Hz", "[sqrt(2K/(3M+8m))]/(2π)", "{2K/(3M+8m)}^(1/2)/(2π) hz.",
])
def test_equivalent_forms_are_right(text):
    assert matches(text)


@pytest.mark.parametrize("text", [
    "sqrt(2*K/(3*M+8*m))", "sqrt(K/(M+4m))/(2pi)", "sqrt(2K/(3M+7m))/(2pi)", "sqrt(2K/(3M+8m))/(2*3.1)",
    "2K/(3M+8m)/(2pi)", "sqrt(2K/(3M))/(2pi)", "K", "0.5", "sqrt(2K/(3M+8m))/(2pi) + 0.01",
    "ω = sqrt(2K/(3M+8m))", "sqrt(2K/(3M+8m)) rad/s",
])
def test_different_forms_are_wrong(text):
    assert not matches(text)


def test_comparison_points_are_the_same_in_every_process():
    from exgen.answertypes.symbolic import POINTS, _points

    ranges = (("K", 1000.0, 5000.0), ("M", 2.0, 10.0))
    code = f"from exgen.answertypes.symbolic import _points; print(repr(_points({ranges!r})))"
    other = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
    assert other == repr(_points(ranges))
    assert len({p["K"] for p in _points(ranges)}) == POINTS
    assert all(1000 <= p["K"] <= 5000 and 2 <= p["M"] <= 10 for p in _points(ranges))


@pytest.mark.parametrize("text, name, words", [
    ("sqrt(2K/(3M+8m))", "factor_2pi", "2π times"),
    ("sqrt(2K/(3M+8m))/(4pi^2)", "factor_2pi", "1/(2π) of"),
    ("3*sqrt(2K/(3M+8m))/(2pi)", "constant_factor", "3 times"),
    ("-sqrt(2K/(3M+8m))/(2pi)", "wrong_sign", "wrong sign"),
    ("2pi*sqrt((3M+8m)/(2K))", "reciprocal", "upside down"),
    ("2K/(3M+8m)/(4pi^2)", "missing_root", "square root is missing"),
])
def test_generic_slips_are_named(text, name, words):
    found = answer_type(PART).slip(read(text, PART), RIGHT, PART)
    assert found is not None and found.name == name and words in found.message


# ---- reading: format problems ---------------------------------------------------------------------------

@pytest.mark.parametrize("text, words", [
    ("sqrt(2k/(3M+8m))/(2pi)", "unknown symbol 'k': the symbols are K, M and m (did you mean K?)"),
    ("sqrt(2K/(3M+8m)/(2pi)", "unbalanced brackets"),
    ("sqrt(2K/(3M+8m)))/(2pi)", "unbalanced brackets"),
    ("2 3K", "missing operator before '3'"),
    ("K2", "missing operator between 'K' and '2'"),
    ("1/2piK", "after '/', put a product in brackets"),
    ("log(K)", "ln(...)"),
    ("sqrt K", "sqrt needs brackets"),
    ("K^", "something is missing"),
    ("2,5K", "decimals with a point"),
    ("__import__('os').system('ls')", "cannot be part of an expression"),
    ("__import__(os)", "unknown symbol '__import__'"),
    ("9^9^9^9", "exponents of exponents"),
    ("K^99", "exponents larger than 10"),
    ("(" * 100_000 + ")" * 100_000, f"longer than {MAX_LENGTH}"),
    ("K+" * 500_000, f"longer than {MAX_LENGTH}"),
    ("(" * 20 + "K" + ")" * 20, "nested more than"),
    ("1e999*K", "too large a number"),
    ("lambda: 0", "cannot be part of an expression"),
    ("", "no expression given"),
])
def test_format_problems_say_what_to_fix(text, words):
    with pytest.raises(ExpressionError) as info:
        read(text, PART)
    assert words in str(info.value)
    assert isinstance(info.value, FormatProblem)


def test_nothing_is_evaluated_or_imported_while_reading(monkeypatch):
    import builtins

    monkeypatch.setattr(builtins, "eval", None)
    monkeypatch.setattr(builtins, "exec", None)
    monkeypatch.setattr(builtins, "__import__", None)
    assert isinstance(read("sqrt(2K/(3M+8m))/(2π)", PART).value, Expression)


@pytest.mark.parametrize("text", [
    "sqrt(2*K/(3*M + 8*m))/(2*pi)", "-K^2", "(-K)^2", "K^(-1)", "K - (M - m)", "K/(M*m)", "K*m/M", "(K + m)^(1/3)",
    "abs(sin(K) - cos(M))", "exp(-K/M)*tan(m)", "ln(K)/log10(M)", "2.5e-3*K", "K/-m",
])
def test_printed_text_reads_back_as_the_same_expression(text):
    first = Expression.parse(text, SYMBOLS)
    again = Expression.parse(str(first), SYMBOLS)
    assert again == first
    values = {"K": 1.3, "M": 2.1, "m": 0.7}
    assert math.isclose(again(**values), first(**values))


@pytest.mark.parametrize("text, latex", [
    ("sqrt(2*K/(3*M+8*m))/(2*pi)", r"\frac{1}{2\pi}\sqrt{\frac{2K}{3M + 8m}}"),
    ("(K + m)/2", r"\frac{K + m}{2}"),
    ("2/(3*K)", r"\frac{2}{3K}"),
    ("(2K)^(1/2)", r"\sqrt{2K}"),
    ("K*m^2", r"K\,m^{2}"),
    ("-(K + m)", r"-\left(K + m\right)"),
    ("2*3", r"2 \cdot 3"),
    ("abs(K)", r"\left|K\right|"),
])
def test_latex(text, latex):
    assert Expression.parse(text, SYMBOLS).latex() == latex


# ---- the part's YAML ---------------------------------------------------------------------------------

@pytest.mark.parametrize("symbols, message", [
    ("", "a symbolic answer needs `symbols:`"),
    ("symbols: [K, pi]", "symbols.pi: a symbol is a plain name"),
    ("symbols: {K: [0, 10]}", "symbols.K: a range is [low, high] with 0 < low < high"),
    ("symbols: [K, M, m]\n    tol: {abs: 1}", "tol.abs: not a tolerance of a symbolic answer; expected one of rel"),
])
def test_the_part_is_checked_at_load(tmp_path, symbols, message):
    text = (FIXTURES / "pulley_frequency.yaml").read_text(encoding="utf-8")
    text = text.replace("    symbols: {K: [1000, 5000], M: [2, 10], m: [1, 8]}\n", f"    {symbols}\n" if symbols else "")
    path = tmp_path / "t.yaml"
    path.write_text(text, encoding="utf-8")
    shutil.copy(FIXTURES / "solvers.py", tmp_path)
    with pytest.raises(BankError) as info:
        load_template(path)
    assert any(message in str(e) and re.search(r"t\.yaml:\d+:\d+: part \(\w+\), ", str(e)) for e in info.value.errors)


# ---- the fixture template, end to end --------------------------------------------------------------

def test_the_fixture_validates_like_any_template(fixture_bank):
    report = validate_template(fixture_bank.get("fixture.pulley_frequency"), seeds=60)
    assert report.problems == [] and report.warnings == []


def test_sheet_and_key_show_the_formula_as_math(variant):
    text = " ".join(variant_text(variant, key=True).split())
    assert "[an expression in K, M and m]" in text and "2.159 Hz (b)" in text
    sheet = build_sheet(Assignment("hw6", "Homework 6", (QuestionSpec("q1", variant.template.id),)), Student("s1"),
                        load_bank([FIXTURES]), SECRET)
    key = key_markdown(sheet, {})
    assert r"**$\frac{1}{2\pi}\sqrt{\frac{2K}{3M + 8m}}$**" in key and "any equivalent form, within 0.1 %" in key
    assert r"$f_n = \frac{1}{2\pi}\sqrt{\frac{2K}{3M + 8m}}$" in key  # the worked line
    assert "expression in K, M and m" in sheet_markdown(sheet, {})
    pdf = key_pdf(sheet)
    assert pdf.startswith(b"%PDF")


def test_answer_file_lists_the_symbols_and_the_syntax(fixture_bank):
    sheet = _sheet(fixture_bank)
    form = answer_form(sheet)
    line = next(line for line in form.splitlines() if line.strip().startswith("a:"))
    assert "[expression in K, M, m; e.g. 2*K^2/(3*m)]" in line
    assert "2K is 2*K" in form and "sqrt()" in form and "pi (or π)" in form


def _sheet(bank, student="s1"):
    assignment = Assignment("hw6", "Homework 6", (QuestionSpec("q1", "fixture.pulley_frequency"),))
    return build_sheet(assignment, Student(student), bank, SECRET)


def _value_from(sheet, formula: str) -> str:
    """What a student gets for (b) by putting the sheet's numbers into `formula`."""
    values = {p.name: float(p.si) for p in sheet.questions[0].variant.params}
    return f"{Expression.parse(formula, SYMBOLS)(**values):.5g} Hz"


@pytest.mark.parametrize("form", ["yaml", "csv", "json"])
def test_answer_files_of_every_format_are_graded_with_feedback_and_error_carried_forward(fixture_bank, tmp_path, form):
    students = [Student("right"), Student("omega"), Student("typo"), Student("unrelated")]
    typed = {"right": "(2K/(3M+8m))^(1/2)/(2π)", "omega": "sqrt(2K/(3M+8m))", "typo": "sqrt(2k/(3M+8m))/(2pi)",
             "unrelated": "K/M"}
    worked_from = {**typed, "typo": typed["right"]}  # (b) from the formula the student meant
    assignment = Assignment("hw6", "Homework 6", (QuestionSpec("q1", "fixture.pulley_frequency"),))
    for student in students:
        sheet = build_sheet(assignment, student, fixture_bank, SECRET)
        answers = {"q1": {"a": typed[student.id], "b": _value_from(sheet, worked_from[student.id])}}
        _write(tmp_path / f"{student.id}.{form}", form, sheet, answers)
    batch = grade_batch(assignment, fixture_bank, SECRET, tmp_path, roster=students)
    parts = {s.student.id: {p.part_id: p for p in s.questions[0].parts} for s in batch.sheets}
    assert parts["right"]["a"].status == CORRECT and parts["right"]["b"].status == CORRECT
    assert parts["omega"]["a"].status == WRONG and parts["omega"]["a"].mistake == "omega_for_f"
    assert "angular speed ω" in parts["omega"]["a"].message
    assert parts["omega"]["b"].status == CARRIED  # (b) worked right from the student's own (a)
    assert parts["typo"]["a"].status == UNREADABLE and "did you mean K?" in parts["typo"]["a"].message
    assert "format problem, not a wrong answer" in parts["typo"]["a"].message
    assert parts["unrelated"]["a"].status == WRONG and "not equivalent" in parts["unrelated"]["a"].message
    assert parts["typo"]["b"].status == CORRECT and parts["unrelated"]["b"].status == CARRIED
    out = write_results(batch, tmp_path / "results")
    feedback = (out["feedback"] / "omega.md").read_text(encoding="utf-8")
    assert "angular speed ω" in feedback


def _write(path: Path, form: str, sheet, answers):
    if form == "yaml":
        text = answer_form(sheet)
        for part, value in answers["q1"].items():
            text = text.replace(f'    {part}: ""', f"    {part}: {json.dumps(value, ensure_ascii=False)}", 1)
    elif form == "json":
        text = json.dumps({"student": sheet.student.id, "code": sheet.code, "answers": answers}, ensure_ascii=False)
    else:
        buffer = io.StringIO()
        writer = csv.writer(buffer)
        writer.writerows([("student", sheet.student.id), ("code", sheet.code)])
        writer.writerows(("q1", part, value) for part, value in answers["q1"].items())
        text = buffer.getvalue()
    path.write_text(text, encoding="utf-8")
    assert read_submission(path).answers["q1"]["a"] == answers["q1"]["a"]


def test_the_named_mistake_beats_the_generic_slip(variant):
    result = grade_variant(variant, {"a": "sqrt(2*K/(3*M+8*m))", "b": ""})
    part = result.parts[0]
    assert part.mistake == "omega_for_f" and part.points == 0


def test_a_formula_from_the_wrong_method_carries_forward_through_the_solver(variant):
    values = {p.name: float(p.si) for p in variant.params}
    wrong = "sqrt(K/(M+4m))/(2pi)"
    carried = f"{Expression.parse(wrong, SYMBOLS)(**values):.6g}"
    parts = grade_variant(variant, {"a": wrong, "b": carried}).parts
    assert parts[0].mistake == "point_mass_pulley" and parts[1].status == CARRIED


def test_the_guides_shorthand_loads_with_the_default_range(tmp_path):
    """docs/templates.md offers `symbols: [K, M, m]`: each symbol then ranges over the default 0.5 to 5."""
    text = (FIXTURES / "pulley_frequency.yaml").read_text(encoding="utf-8")
    text = text.replace("    symbols: {K: [1000, 5000], M: [2, 10], m: [1, 8]}\n", "    symbols: [K, M, m]\n")
    path = tmp_path / "t.yaml"
    path.write_text(text, encoding="utf-8")
    shutil.copy(FIXTURES / "solvers.py", tmp_path)
    template = load_template(path)
    part = next(p for p in template.parts if p.type == "symbolic")
    assert part.options["ranges"] == tuple((name, 0.5, 5.0) for name in ("K", "M", "m"))
