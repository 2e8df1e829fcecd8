"""Page layout of sheets and keys, read from where Typst actually placed things.

A question's heading, statement, figure and parts stay on one page when they fit on one; a table
never leaves its header alone at a page's foot and repeats it on the next page; a heading never
ends a page. The layouts leave invisible marks (metadata with the page they landed on) that
`typst.query` reads back from the laid-out document.
"""
import json
from pathlib import Path

import pytest
import typst

from exgen.figures.metrics import FAMILY
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet, load_assignment
from exgen.render.jinja import render
from exgen.render.mathtext import typst_string
from exgen.render.pdf import key_typst, sheet_typst

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def marks(source: str, label: str) -> list[dict]:
    return json.loads(typst.query(source.encode("utf-8"), f"<{label}>", field="value"))


@pytest.fixture(scope="module")
def documents(bank):
    out = []
    for name in ("tutorial1.yaml", "tutorial2.yaml"):
        assignment = load_assignment(EXAMPLES / name, bank)
        for student in (Student("A21001", "Nur Aisyah binti Rahman"), Student("A21002", "Lim Wei Jie")):
            sheet = build_sheet(assignment, student, bank, b"layout" * 6)
            out += [(f"{name} {student.id} sheet", sheet_typst(sheet)), (f"{name} {student.id} key", key_typst(sheet))]
    # questions the layout measures (their size is not surely below a page before typesetting)
    tall = ("gears.robot_arm", "linkages.coupler_point", "gears.lift_counterweight")
    assignment = Assignment(id="tall", title="Tall questions", questions=tuple(
        QuestionSpec(f"q{i}", t) for i, t in enumerate(tall, start=1)))
    sheet = build_sheet(assignment, Student("A21003"), bank, b"layout" * 6)
    return out + [("tall sheet", sheet_typst(sheet)), ("tall key", key_typst(sheet))]


def test_a_question_that_fits_on_a_page_is_never_split(documents):
    for name, source in documents:
        placed: dict[int, dict[str, tuple[int, bool]]] = {}
        for mark in marks(source, "exgen-layout"):
            placed.setdefault(mark["question"], {})[mark["what"]] = (mark["page"], mark["fits"])
        assert placed, name
        for question, where in placed.items():
            (start, fits), (end, _) = where["start"], where["end"]
            assert fits, (name, question, "a question taller than a page")
            assert start == end, (name, question, f"starts on page {start}, ends on page {end}")


@pytest.fixture(scope="module")
def preamble():
    """The key's preamble and definitions, without a sheet."""
    context = {"doc_title": "t", "doc_author": "a", "closing": "", "footer_left": "", "font": FAMILY, "course": "",
               "title": "", "student_name": "", "student_id": "", "code": "", "due": "", "assignment_id": "",
               "total": "", "instructions": "", "questions": [], "form": False, "form_regions": False}
    return render("key.typ.j2", context).split("\n#sheet-header")[0] + "\n"


def _mark(name: str) -> str:
    return f'#context [#metadata((name: "{name}", page: here().page())) <probe>]'


@pytest.mark.parametrize("gap", [560, 620, 650, 665, 680, 700])
def test_a_table_keeps_its_header_with_a_row_and_repeats_it(preamble, gap):
    rows = ", ".join(f"([{_mark(f'row{i}')}{i}], [1], [2])" for i in range(40))
    source = preamble + f'#v({gap}pt)\n#work-table([{_mark("title")}Planes], ([{_mark("head")}A], [B], [C]), ' \
                        f'({rows},), none)\n'
    found = marks(source, "probe")
    page = {m["name"]: m["page"] for m in found}
    heads = sorted(m["page"] for m in found if m["name"] == "head")
    assert page["title"] == heads[0] == page["row0"]  # no title or header alone at a foot
    last = max(m["page"] for m in found if m["name"].startswith("row"))
    assert heads == list(range(heads[0], last + 1))  # the header again on every page the table reaches


@pytest.mark.parametrize("gap", [640, 660, 675, 690])
def test_a_section_heading_never_ends_a_page(preamble, gap):
    source = preamble + f'#v({gap}pt)\n#section[{_mark("heading")}Worked solution]\n{_mark("next")}Text that follows.\n'
    page = {m["name"]: m["page"] for m in marks(source, "probe")}
    assert page["heading"] == page["next"]


#: Measures each worked line instead of drawing it: its equation's natural width against the room beside
#: the part column (the rows are planned before typesetting, from an estimate of each term's width).
MEASURED_LINE = r'''
#let work-line(equation, parts, note) = layout(size => {
  let room = size.width - measure(strong(parts)).width - 0.8em.to-absolute()
  [#metadata((width: measure(equation).width.pt(), room: room.pt())) <line-width>]
})
'''


def test_no_worked_line_is_wider_than_the_page(bank):
    templates = [t.id for t in bank]
    for seed in (b"w" * 32, b"v" * 32):
        assignment = Assignment("w", "Widths", tuple(QuestionSpec(f"q{i}", t) for i, t in enumerate(templates, start=1)))
        source = key_typst(build_sheet(assignment, Student("A1"), bank, seed))
        # figures take no part in a line's room (lines stand outside the question blocks): left out, they
        # are not parsed and laid out for nothing
        source = "\n".join(line for line in source.split("\n") if not line.startswith("#svg-figure("))
        assert "#svg-figure(" not in source.split("#let section(")[1]
        at = source.index("#let section(")
        source = source[:at] + MEASURED_LINE + source[at:]
        lines = marks(source, "line-width")
        assert len(lines) > 5 * len(templates)
        too_wide = [m for m in lines if m["width"] > m["room"] + 0.5]
        assert not too_wide, too_wide[:5]



def test_a_long_footer_never_runs_into_the_page_number(preamble):
    """A footer that filled its line only by narrowing its spaces (the paragraph is justified) read
    'Sheet DB44-CC2DPage 1 of 11'; footers of every length around one line's must keep a gap."""
    import io

    import pypdf

    title = "Instructor key · BMCM 2723 Mechanics of Machines · Tutorial 5: Gyroscopes and free vibration"
    for extra in range(12):
        footer = title + " x" * extra + " · Sheet DB44-CC2D"
        source = preamble.replace("[],\n      [Page", f"[{footer}],\n      [Page") + "Body.\n"
        assert footer in source
        text = pypdf.PdfReader(io.BytesIO(typst.compile(source.encode("utf-8")))).pages[0].extract_text()
        assert "CC2DPage" not in text and "Page 1 of 1" in text, (extra, text)


@pytest.mark.parametrize("gap", [560, 600, 620, 640, 660, 680])
def test_a_question_s_answers_stay_on_one_page_with_their_heading(preamble, gap):
    """A key's Answers table ran from the foot of one page onto the next."""
    cells = ", ".join(f"[({chr(97 + i)}) {_mark(f'row{i}')}], [*1.234 kN*], [1 %], [1 mark]" for i in range(8))
    source = preamble + f"#v({gap}pt)\n#answers-table({cells})\n"
    pages = {m["page"] for m in marks(source, "probe")}
    assert len(pages) == 1


@pytest.mark.parametrize("width", [153.48, 469.96, 470.5, 470.6, 520.0])
def test_a_figure_is_shrunk_exactly_when_typst_finds_it_wider_than_the_column(preamble, width):
    """Whether a figure is wider than the text block is read from its SVG when the source is written;
    Typst's own measure of the image against the column must agree."""
    from exgen.render.context import wider_than_text

    svg = (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 40" width="{width}pt" height="40pt">'
           '<rect x="0" y="0" width="100" height="40" fill="white"/></svg>')
    probe = ('#layout(size => [#metadata(measure(image(bytes(' + typst_string(svg) + '), format: "svg")).width'
             ' > size.width) <wide>])\n')
    assert marks(preamble + probe, "wide") == [wider_than_text(svg)]
    wide = str(wider_than_text(svg)).lower()
    typst.compile((preamble + f"#svg-figure({typst_string(svg)}, [A figure], wide: {wide})\n").encode("utf-8"))
