"""Figure text: measured with the font's own metrics, never overlapping other text or sitting on a
line, in every figure of every template over many seeds; set in the sheets' one family, embedded."""
import json
import os
import re
from importlib import resources

import pytest

from exgen.figures import draw_figures, figure_svg, key_figure_svgs
from exgen.figures.checks import collisions, labels
from exgen.figures.layout import TextBox, boxes_overlap, circle_hits, path_points, runs, segment_hits, text_box
from exgen.figures.metrics import FAMILY, TABLE, build_table, covered, measure
from exgen.figures.svg import MAX_WIDTH, PT_PER_PX
from exgen.solve.variant import make_variant

#: Seeds per template; EXGEN_FIGURE_SEEDS=150 checks more by hand.
SEEDS = range(int(os.environ.get("EXGEN_FIGURE_SEEDS", "40")))


def _all_figures(bank, seeds):
    for template in bank:
        if not (template.figure or template.key_figures):
            continue
        for seed in seeds:
            variant = make_variant(template, seed)
            if template.figure:
                yield template.id, seed, "figure", figure_svg(variant)
            for name, svg in key_figure_svgs(variant):
                yield template.id, seed, name, svg


@pytest.fixture(scope="module")
def every_figure(bank):
    return list(_all_figures(bank, SEEDS))


def test_no_text_overlaps_text_or_sits_on_a_line(every_figure):
    bad = [f"{tid} seed {seed} {name}: {problem}" for tid, seed, name, svg in every_figure
           for problem in collisions(svg)]
    assert not bad, f"{len(bad)} problems, e.g.\n" + "\n".join(bad[:15])


def test_every_character_of_figure_text_is_measured(every_figure):
    missing = {(tid, label.text) for tid, _, _, svg in every_figure for label in labels(svg)
               if not covered("".join(r.text for r in runs(label.text)))}
    assert not missing


def test_every_figure_prints_at_the_common_scale(every_figure):
    for tid, seed, name, svg in every_figure:
        view = re.search(r'viewBox="\S+ \S+ (\S+) (\S+)" width="(\S+)pt"', svg)
        width, printed = float(view.group(1)), float(view.group(3))
        assert width <= MAX_WIDTH, (tid, seed, name, width)
        assert printed == pytest.approx(width * PT_PER_PX, abs=0.01)


def test_the_metrics_table_is_the_font_typst_embeds():
    stored = json.loads(resources.files("exgen.figures").joinpath(TABLE).read_text(encoding="utf-8"))
    assert build_table() == stored, "regenerate with: python -m exgen.figures.metrics"


def test_label_widths_match_typst_shaping_whole_labels():
    """Sums of advances against Typst's own shaping of the whole string (kerning included)."""
    import typst

    samples = [("d = 400 mm", False, False), ("Gear 2", True, False), ("positions from the left end", False, True),
               ("A to C = ?", False, False), ("firing order 1-3-4-2, 4-stroke", False, True), ("ω = 1250 rpm", False, False),
               ("Countershaft", True, False), ("P (ref.)", True, False)]
    cells = ", ".join(f'measure(text(font: "{FAMILY}", size: 100pt, weight: "{"bold" if b else "regular"}", '
                      f'style: "{"italic" if i else "normal"}", {json.dumps(t, ensure_ascii=False)})).width.pt()'
                      for t, b, i in samples)
    source = f"#context [#metadata(({cells},))<w>]"
    widths = typst.query(source.encode(), "<w>", field="value", one=True, ignore_system_fonts=True)
    widths = json.loads(widths) if isinstance(widths, str) else widths
    for (text, bold, italic), typst_width in zip(samples, widths):
        assert measure(text, bold, italic).width * 100 == pytest.approx(typst_width, rel=0.02), text


def test_scripts_are_smaller_digits_of_the_same_font():
    assert [(r.text, r.shift) for r in runs("ω₁₂ = 2 m/s²")] == [("ω", 0), ("12", 1), (" = 2 m/s", 0), ("2", -1)]
    plain, scripted = text_box((0, 0), "d2", size=14), text_box((0, 0), "d₂", size=14)
    assert scripted.x1 < plain.x1 and scripted.y1 > plain.y1  # narrower, and lower


@pytest.mark.parametrize("anchor, share", [("start", 0.0), ("middle", 0.5), ("end", 1.0)])
def test_text_box_follows_the_anchor(anchor, share):
    width = 14 * 2 * measure("m").width
    box = text_box((10.0, 50.0), "mm", anchor, 14.0)
    assert box.x0 == pytest.approx(10.0 - share * width) and box.x1 - box.x0 == pytest.approx(width)
    assert box.y0 < 50.0 - 14 * 0.4 and box.y1 == pytest.approx(50.0, abs=0.5)  # no descender


def test_turned_boxes_overlap_only_where_they_meet():
    upright = TextBox(0, -10, 40, 0)
    turned = TextBox(0, -10, 40, 0, angle=90.0, pivot=(60, 0))   # a column going down from (60, 0)
    assert not boxes_overlap(upright, turned)
    assert boxes_overlap(upright, TextBox(0, -10, 40, 0, angle=90.0, pivot=(30, -5)))


def test_lines_and_circles_through_a_box():
    box = TextBox(0, 0, 20, 10)
    assert segment_hits(box, (-5, 5), (25, 5)) and not segment_hits(box, (-5, 12), (25, 12))
    assert circle_hits(box, (10, 5), 8) and not circle_hits(box, (10, 5), 40) and not circle_hits(box, (100, 5), 8)


def test_arcs_in_paths_are_followed():
    (points,) = path_points("M 10,0 A 10 10 0 0 1 -10,0")  # clockwise on screen: through (0, 10)
    assert min(abs(x) + abs(y - 10) for x, y in points) < 0.5


def test_pdfs_use_one_family_for_text_and_figures(bank, tmp_path):
    from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
    from exgen.render.pdf import key_pdf, sheet_pdf

    ids = [t.id for t in bank if t.figure or t.key_figures]  # every figure, and every statement with one
    assignment = Assignment(id="t", title="T", questions=tuple(QuestionSpec(f"q{i}", tid) for i, tid in enumerate(ids, 1)))
    sheet = build_sheet(assignment, Student("s1"), bank, b"k" * 32)
    figures = draw_figures(sheet)
    # without the form: what is typed into it is set in the viewer's own Helvetica, and nothing is until then
    for pdf in (sheet_pdf(sheet, figures, form=False), key_pdf(sheet, figures)):
        fonts = {name.split("+", 1)[-1] for name in re.findall(rb"/BaseFont\s*/([A-Za-z0-9+-]+)", pdf)
                 for name in [name.decode()]}
        families = {f.split("-")[0] for f in fonts}
        assert families <= {"NewCM10", "NewCMMath"}, fonts


@pytest.mark.parametrize("prose, typst_text", [("gear 1's speed", "gear 1\u2019s speed"), ("l\u2083' = 2 m", "l\u2083\u2032 = 2 m"),
                                               ("the arm's joint", "the arm's joint")])
def test_apostrophes_after_digits_never_become_the_text_face_s_missing_prime(prose, typst_text):
    """Typst would set ' after a digit as a prime, which the body face lacks (another font would show)."""
    from exgen.render.mathtext import escape_typst

    assert escape_typst(prose) == typst_text


def test_primes_in_figures_come_from_the_math_face():
    from exgen.figures.svg import Drawing

    d = Drawing()
    d.text((0, 0), "B\u2032")
    assert 'font-family="New Computer Modern Math">\u2032</tspan>' in d.svg()


def test_a_units_dot_in_a_figure_is_set_tight_as_in_the_text(every_figure):
    """'C = 10810 N · s/m' in a figure beside 'N·s/m' in its statement: the text face's middle dot stands
    spaced, so every figure sets the math face's dot operator, as the sheet's prose and the keys do."""
    spaced = [(tid, seed, name) for tid, seed, name, svg in every_figure
              for text in re.findall(r"<text[^>]*>(.*?)</text>", svg) if "\u00b7" in text]
    assert not spaced, spaced[:5]
    from exgen.figures.svg import Drawing

    d = Drawing()
    box = d.text((0, 0), "I = 3.3 kg·m²")
    assert 'font-family="New Computer Modern Math">\u22c5</tspan>' in d.svg()
    assert box.x1 - box.x0 == pytest.approx(text_box((0, 0), "I = 3.3 kgm²").x1 - text_box((0, 0), "I = 3.3 kgm²").x0
                                            + 14 * measure("\u22c5").width)
