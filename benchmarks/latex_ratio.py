"""How much faster the in-process Typst route is than the LaTeX route, for the same sheet and key.

    python benchmarks/latex_ratio.py [STUDENTS] [ASSIGNMENT]

The LaTeX route is what a LaTeX-based generator does per student: write a .tex file and run pdflatex
twice (the second pass for page references: "Page 2 of 5"). The .tex holds the same content as
exgen's own outputs: the same header fields, statements, figures (converted to PDF beforehand, not
timed), parts, given tables, worked lines as display math and answer tables, all from the same sheet
context exgen's layouts read. Prints medians of both routes, and the ratio. Needs pdflatex (Debian:
texlive-latex-base and texlive-latex-recommended); without it the script says so and stops.
"""
from __future__ import annotations

import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import unicodedata
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from clock import allocator, load  # noqa: E402

HERE = Path(__file__).parent
_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
            "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}
_MATH = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$")


_SYMBOLS = {"°": r"\ensuremath{^\circ}", "·": r"\ensuremath{\cdot}", "−": "-", "×": r"\ensuremath{\times}",
            "≤": r"\ensuremath{\le}", "≥": r"\ensuremath{\ge}", "…": r"\ldots{}", "’": "'", "–": "--", "—": "---",
            "′": "'", "≈": r"\ensuremath{\approx}", "π": r"\ensuremath{\pi}", "√": r"\ensuremath{\surd}"}
_DIGITS = {"ZERO": 0, "ONE": 1, "TWO": 2, "THREE": 3, "FOUR": 4, "FIVE": 5, "SIX": 6, "SEVEN": 7, "EIGHT": 8,
           "NINE": 9, "MINUS": "-"}


def declarations(tex: str) -> str:
    """\DeclareUnicodeCharacter for every character beyond ASCII in the document (pdflatex reads bytes):
    Greek letters as math, script digits raised or lowered, a few symbols; anything else as '?'."""
    out = []
    for ch in sorted({c for c in tex if ord(c) > 127}):
        name = unicodedata.name(ch, "")
        if name.startswith("GREEK"):
            letter = name.split()[-1].lower()
            shown = rf"\ensuremath{{\{letter.capitalize() if 'CAPITAL' in name else letter}}}"
        elif name.startswith(("SUBSCRIPT", "SUPERSCRIPT")) and name.split()[-1] in _DIGITS:
            digit = _DIGITS[name.split()[-1]]
            shown = rf"\text{'subscript' if name.startswith('SUB') else 'superscript'}{{{digit}}}"
        else:
            shown = _SYMBOLS.get(ch, "?")
        out.append(rf"\DeclareUnicodeCharacter{{{ord(ch):04X}}}{{{shown}}}")
    return "\n".join(out)


def prose(text: str) -> str:
    return "".join(_SPECIAL.get(ch, ch) for ch in str(text))


def text(text_with_math: str) -> str:
    """Prose with $LaTeX$ spans: the prose escaped, the math kept."""
    out, at = [], 0
    for match in _MATH.finditer(text_with_math):
        out += [prose(text_with_math[at:match.start()].replace("\\$", "$")), f"${match.group(1)}$"]
        at = match.end()
    return "".join(out + [prose(text_with_math[at:].replace("\\$", "$"))])


def latex_document(sheet, figures, figure_pdf, key: bool) -> str:
    """The sheet (or key) as LaTeX, from the context exgen's layouts read (the Markdown one: its math is
    LaTeX; its prose is unescaped here and escaped for LaTeX)."""
    from exgen.render.context import sheet_context
    from exgen.render.targets import MARKDOWN

    svgs = {slot: f.sheet.svg for slot, f in figures.items() if f.sheet}
    key_figures = {slot: [(figure_pdf[d.svg], d.title) for d in f.key] for slot, f in figures.items()} if key else {}
    ctx = sheet_context(sheet, MARKDOWN, {slot: figure_pdf[svg] for slot, svg in svgs.items()}, svgs, key=key,
                        key_figures=key_figures)
    plain = lambda s: re.sub(r"\\([\\`*_\[\]<>|$#+\-.])", r"\1", s)  # undo Markdown's escapes  # noqa: E731
    out = [r"\documentclass[10pt,a4paper]{article}", r"\usepackage[margin=2.2cm]{geometry}",
           r"\usepackage{amsmath,amssymb,graphicx,fancyhdr,longtable,array}", r"\usepackage[T1]{fontenc}",
           r"\usepackage[utf8]{inputenc}",
           r"\pagestyle{fancy}\fancyhf{}\cfoot{Page \thepage\ of \pageref{LastPage}}", r"\begin{document}",
           rf"{{\large\bfseries {prose(sheet.assignment.title)}}}\\", rf"\textsc{{{prose(sheet.assignment.course)}}}",
           r"\begin{tabular}{|l|l|l|l|}\hline",
           rf"Student & {prose(sheet.student.name or sheet.student.id)} & ID & {prose(sheet.student.id)}\\\hline",
           rf"Sheet code & {prose(sheet.code)} & Total & {prose(ctx['total'])}\\\hline\end{{tabular}}", ""]
    for q in ctx["questions"]:
        out += [rf"\section*{{Question {q['number']} \hfill ({prose(q['marks'])})}}", text(plain(q["statement"]))]
        if q["figure"]:
            out += [r"\begin{center}", rf"\includegraphics[width=0.8\linewidth]{{{q['figure']}}}\\",
                    rf"\emph{{{prose(plain(q['caption']))}}}", r"\end{center}"]
        out += [r"\begin{enumerate}"] + [rf"\item[({p['id']})] {text(plain(p['ask']))} [{prose(plain(p['hint']))}]"
                                        rf" \hfill \emph{{{prose(p['marks'])}}}" for p in q["parts"]]
        out += [r"\end{enumerate}"]
        if not key:
            continue
        out += [r"\subsection*{Given}", r"\begin{longtable}{|c|l|p{8cm}|}\hline Symbol & Value & Quantity\\\hline"]
        out += [rf"${g['symbol']}$ & {prose(plain(g['printed']))} & {text(plain(g['label']))}\\\hline" for g in q["given"]]
        out += [r"\end{longtable}", r"\subsection*{Worked solution}"]
        for b in q["blocks"]:
            if b["kind"] == "line":
                out += [r"\begin{align*}", b["equation"] + (rf" &&\text{{{prose(b['parts'])}}}" if b["parts"] else ""),
                        r"\end{align*}"] + ([rf"{{\small\emph{{{text(plain(b['note']))}}}}}"] if b["note"] else [])
            elif b["kind"] == "table":
                cols = len(b["head"])
                out += [rf"\begin{{longtable}}{{|{'r|' * cols}}}\hline " + " & ".join(text(plain(h)) for h in b["head"])
                        + r"\\\hline"]
                out += [" & ".join(text(plain(c)) for c in row) + r"\\\hline" for row in b["rows"]]
                out += [r"\end{longtable}"]
            elif b["kind"] == "figure":
                out += [rf"\begin{{center}}\includegraphics[width=0.8\linewidth]{{{b['figure']}}}\end{{center}}"]
        out += [r"\subsection*{Answers}", r"\begin{tabular}{|c|l|l|r|}\hline Part & Answer & Tolerance & Marks\\\hline"]
        out += [rf"({p['id']}) & {text(plain(p['answer']))} & {text(plain(p['tolerance']))} & {prose(p['marks'])}\\\hline"
                for p in q["parts"]]
        out += [r"\end{tabular}"]
    tex = "\n".join(out + [r"\label{LastPage}\end{document}", ""])  # "Page 2 of 5" on the second pass
    return tex.replace(r"\begin{document}", declarations(tex) + "\n" + r"\begin{document}", 1)


def figure_pdfs(figures, folder: Path) -> dict[str, str]:
    """Each figure's SVG as a PDF file for \\includegraphics (made with Typst, before any timing)."""
    import typst

    out = {}
    for drawn in figures.values():
        for figure in ([drawn.sheet] if drawn.sheet else []) + list(drawn.key):
            path = folder / f"fig{len(out)}.pdf"
            page = "#set page(width: auto, height: auto, margin: 0pt)\n#image(bytes(sys.inputs.svg), format: \"svg\")"
            path.write_bytes(typst.compile(page.encode(), format="pdf", sys_inputs={"svg": figure.svg},
                                           ignore_system_fonts=True))
            out[figure.svg] = path.name
    return out


def pdflatex_twice(tex: str, folder: Path) -> float:
    (folder / "doc.tex").write_text(tex, encoding="utf-8")
    start = time.perf_counter()
    for _ in range(2):
        done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=folder,
                              capture_output=True, text=True)
        if done.returncode:
            raise SystemExit(f"pdflatex failed:\n{done.stdout[-2000:]}")
    return time.perf_counter() - start


def main() -> None:
    if shutil.which("pdflatex") is None:
        print("pdflatex is not installed: the LaTeX comparison needs it (Debian: apt-get install "
              "texlive-latex-base texlive-latex-recommended); nothing measured")
        return
    from exgen.figures import draw_figures
    from exgen.issue.assignment import Student, build_sheet, load_assignment
    from exgen.load.bank import load_bank
    from exgen.render.pdf import key_pdf, sheet_pdf

    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    assignment = load_assignment(Path(sys.argv[2]) if len(sys.argv) > 2 else HERE / "class_all.yaml", load_bank())
    bank = load_bank()
    rows = {"sheet": ([], []), "key": ([], [])}
    secret = b"benchmark secret, not a real one"
    warm = build_sheet(assignment, Student("W00000", "Warm-up"), bank, secret)
    sheet_pdf(warm, draw_figures(warm))  # fonts and first-use costs, on a sheet not timed: Typst keeps what it
    # laid out, so a document typeset a second time in one process costs almost nothing
    for i in range(n):
        sheet = build_sheet(assignment, Student(f"S{i:05d}", f"Student {i}"), bank, secret)
        figures = draw_figures(sheet)
        with tempfile.TemporaryDirectory() as folder:
            pdfs = figure_pdfs(figures, Path(folder))
            for kind, make in (("sheet", sheet_pdf), ("key", key_pdf)):
                start = time.perf_counter()
                make(sheet, figures)
                rows[kind][0].append(time.perf_counter() - start)
                rows[kind][1].append(pdflatex_twice(latex_document(sheet, figures, pdfs, kind == "key"), Path(folder)))
    print(f"{assignment.title}: medians of {n} students, wall time, Typst in this process ({allocator()}); {load()}")
    for kind, (typst_times, latex_times) in rows.items():
        t, tex = statistics.median(typst_times), statistics.median(latex_times)
        print(f"one {kind}: Typst in-process {t * 1e3:6.1f} ms, pdflatex twice {tex * 1e3:7.1f} ms: "
              f"Typst {tex / t:4.1f}x faster")


if __name__ == "__main__":
    main()
