"""Raw LaTeX never reaches plain text: answer files, `exgen solve` and `exgen list`, feedback and reports.

Templates write math as $LaTeX$; every plain output writes it as Unicode (e = (ω_R − ω_A)/(ω_S − ω_A)),
and the Markdown pages quote error messages without HTML entities a reader would see.
"""
import re

from exgen.cli import main
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.render.answer_form import answer_form
from graders.report import _escape

#: What raw LaTeX looks like: a command, a math span, a braced script, an HTML entity.
RAW = re.compile(r"\\[A-Za-z]+|\$[^$\n]+\$|[_^]\{|&(lt|gt|amp|#\d+);")


def every_template_sheet(bank):
    specs = tuple(QuestionSpec(f"q{i}", t.id) for i, t in enumerate(bank, start=1))
    return build_sheet(Assignment("all", "Every template", specs), Student("s1", "Ann"), bank, b"p" * 32)


def test_the_answer_file_writes_asks_and_titles_without_latex(bank):
    form = answer_form(every_template_sheet(bank))
    comments = [line.split("#", 1)[1] for line in form.splitlines() if "#" in line]
    assert not [c for c in comments if RAW.search(c)]
    assert "e = (ω_R − ω_A)/(ω_S − ω_A)" in form or "(ω_R − ω_A)/(ω_S − ω_A)" in form


def test_solve_and_list_print_plain_text(bank, capsys):
    given = ["ts=30", "tp=35", "fixed=sun", "driver=arm", "N_in=1200rpm", "sense_in=clockwise"]
    assert main(["solve", "gears.epicyclic", *[x for g in given for x in ("--set", g)]]) == 0
    out = capsys.readouterr().out
    assert "(ω_R − ω_A)/(ω_S − ω_A)" in out and not RAW.search(out)
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "maximum power when T_c = T₁/3" in out and not RAW.search(out)


def test_feedback_and_reports_quote_messages_as_a_reader_sees_them():
    message = "cannot read answers.yaml: expected <block end>, but found '<stream end>' (line 3) & more &amp; so"
    shown = _escape(message)
    assert "‹stream end›" in shown and "&lt;" not in shown and "<" not in shown
    assert "&amp;" not in shown and "& more" in shown
    assert _escape(r"the train value $e = (\omega_R - \omega_A)/(\omega_S - \omega_A)$") == \
        "the train value e = (ω_R − ω_A)/(ω_S − ω_A)"


def test_prose_writes_its_symbols_as_math(bank):
    """Titles, sources, statements, asks, labels and worked-solution notes write a symbol as $T_c$, which
    every output can set, never as raw T_c or \\omega (feedback messages, say:, are plain text)."""
    from exgen.render.unicode_math import split_math
    from exgen.solve.variant import make_variant

    raw = re.compile(r"\\[A-Za-z]|[_^{}]")
    found = []
    for template in bank:
        variant = make_variant(template, 3)
        texts = [template.title, template.source, variant.statement, *variant.asks.values(),
                 *(p.label for p in variant.params), *(s.note for s in variant.steps)]
        found += [(template.id, text) for text in texts
                  if any(not math and raw.search(chunk) for math, chunk in split_math(text or ""))]
    assert not found, found[:5]
