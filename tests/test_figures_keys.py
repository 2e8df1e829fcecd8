"""Key-only figures: the polygons close on the correction the working finds, drawn to scale; crank
diagrams put each crank at θ and 2θ; key figures reach the key's folder and outputs, never a sheet."""
import math

import pytest

from exgen.errors import BankError
from exgen.figures import key_figure_svgs
from exgen.figures.polygons import FROM_REFERENCE, FROM_VERTICAL
from exgen.issue.assignment import Assignment, QuestionSpec, Student, build_sheet
from exgen.issue.generate import write_student
from exgen.solve.variant import make_variant
from svg_helpers import elements, texts

POLYGONS = {  # template: (convention, [(closing step's size, factor, angle) per polygon, left to right])
    "balancing.static_balance": (FROM_REFERENCE, [("Bb", None, "theta_b")]),
    "balancing.two_plane_balance": (FROM_VERTICAL, [("mrQ", "lQ", "theta_Q"), ("mP", "rP", "theta_P")]),
    "balancing.complete_balance_position": (FROM_REFERENCE, [("mrlD", None, "theta_D"), ("mrB", None, "theta_B")]),
    "balancing.complete_balance_masses": (FROM_REFERENCE, [("mrlD", None, "theta_D"), ("mrA", None, "thetaA")]),
    "balancing.bearing_reactions": (FROM_REFERENCE, [("RY", "lY", "theta_RY"), ("RX", None, "theta_RX")]),
    "balancing.inline_primary_balance": (FROM_VERTICAL, [("mrlC", None, "theta_C"), ("mB", "r", "theta_B")]),
}


def _value(variant, name):
    for item in list(variant.params) + list(variant.steps):
        if item.name == name:
            return float(item.si if hasattr(item, "si") else item.value)
    raise KeyError(name)


def _vec(line):
    return (float(line.get("x2")) - float(line.get("x1")), float(line.get("y2")) - float(line.get("y1")))


@pytest.mark.parametrize("template_id", sorted(POLYGONS))
@pytest.mark.parametrize("seed", [1, 7, 23])
def test_polygons_close_on_the_correction_to_scale(bank, template_id, seed):
    conv, closings = POLYGONS[template_id]
    variant = make_variant(bank.get(template_id), seed)
    ((_, svg),) = key_figure_svgs(variant)
    sides = elements(svg, "side")
    closing_lines = elements(svg, "closing")
    assert len(closing_lines) == len(closings)
    groups = []
    for (size, factor, angle), closing in zip(closings, closing_lines):
        value = _value(variant, size) * (_value(variant, factor) if factor else 1.0)
        theta = conv.screen(_value(variant, angle))
        cx, cy = _vec(closing)
        # the closing side points along the correction's angle (as drawn in the sheet's convention)
        assert math.atan2(cy, cx) == pytest.approx(math.atan2(math.sin(theta), math.cos(theta)), abs=0.02)
        groups.append((value, math.hypot(cx, cy)))
    assert sides, "no sides drawn"
    # head to tail: every polygon's sides and closing side add up to nothing
    lines = elements(svg, "side") + elements(svg, "closing")
    total = (sum(_vec(e)[0] for e in lines), sum(_vec(e)[1] for e in lines))
    assert math.hypot(*total) < 0.1
    for value, length in groups:
        assert length > 20 and value > 0


def test_a_polygon_is_drawn_to_one_scale(bank):
    variant = make_variant(bank.get("balancing.static_balance"), 3)
    ((_, svg),) = key_figure_svgs(variant)
    lengths = {e.get("class").split()[1]: math.hypot(*_vec(e)) for e in elements(svg, "side")}
    lengths["closing"] = math.hypot(*_vec(elements(svg, "closing")[0]))
    values = {"side-1": _value(variant, "mr1"), "side-2": _value(variant, "mr2"), "side-3": _value(variant, "mr3"),
              "closing": _value(variant, "Bb")}
    scales = {name: lengths[name] / values[name] for name in values}
    assert max(scales.values()) == pytest.approx(min(scales.values()), rel=0.01)
    assert any(t.startswith("B·b = ") for t in texts(svg))


@pytest.mark.parametrize("template_id", ["balancing.inline_engine_firing", "balancing.inline_engine_unbalance"])
def test_crank_diagrams_put_every_crank_at_theta_and_twice_theta(bank, template_id):
    """The diagrams counted their cranks by steps x1, x2, ... that the working no longer records (the distances
    went into its table), and drew none; the test counted them the same way and checked nothing."""
    for seed in range(4):
        variant = make_variant(bank.get(template_id), seed)
        ((_, svg),) = key_figure_svgs(variant)
        labels = texts(svg)
        cylinders = len(variant.inserts[0].rows)  # the working's table has a row per cylinder
        angles = {i: round(math.degrees(_value(variant, f"theta{i}"))) for i in range(1, cylinders + 1)}
        assert cylinders >= 3
        for harmonic in (1, 2):
            groups = {}
            for i, a in angles.items():
                groups.setdefault((harmonic * a) % 360, []).append(str(i))
            for deg, names in groups.items():
                assert f"{', '.join(names)}: {deg}°" in labels
        assert sum(1 for t in labels if t[:1].isdigit() and t.endswith("°") and ": " in t) >= 2
        assert "primary cranks (θ)" in labels and "secondary cranks (2θ)" in labels


def test_key_figures_reach_the_key_only(bank, tmp_path):
    assignment = Assignment(id="t", title="T", questions=(QuestionSpec("q1", "balancing.two_plane_balance"),))
    sheet = build_sheet(assignment, Student("s1"), bank, b"k" * 32)
    write_student(sheet, tmp_path, pdf=False)
    student, key = tmp_path / "students" / "s1", tmp_path / "keys" / "s1"
    assert sorted(p.name for p in student.glob("*.svg")) == ["q1.svg"]
    assert sorted(p.name for p in key.glob("*.svg")) == ["q1-two_plane_polygons.svg", "q1.svg"]
    assert "q1-two_plane_polygons.svg" in (key / "key.md").read_text()
    assert "polygon" not in (student / "sheet.md").read_text().lower()


def test_the_key_pdf_embeds_the_key_figures(bank):
    from exgen.render.pdf import key_typst, sheet_typst

    assignment = Assignment(id="t", title="T", questions=(QuestionSpec("q1", "balancing.static_balance"),))
    sheet = build_sheet(assignment, Student("s1"), bank, b"k" * 32)
    assert "Force polygon" in key_typst(sheet) and "Force polygon" not in sheet_typst(sheet)


@pytest.mark.parametrize("value, message", [("polygons:two_plane_polygons", "must be a list"),
                                            (["polygons:no_such_figure"], "has no function"),
                                            (["nowhere:figure"], "no module")])
def test_bad_key_figures_are_reported_with_file_and_key(bank, tmp_path, value, message):
    import yaml

    from exgen.load.bank import load_template

    data = yaml.safe_load(bank.get("balancing.static_balance").path.read_text(encoding="utf-8"))
    data["key_figures"] = value
    source = tmp_path / "t.yaml"
    source.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    with pytest.raises(BankError) as caught:
        load_template(source)
    assert message in str(caught.value) and "key_figures" in str(caught.value)


@pytest.mark.parametrize("value, nice", [(0.3, 0.2), (7.5, 5.0), (0.05, 0.05), (123.0, 100.0),
                                         (0.001 * (1 - 1e-16), 0.001), (1e-3, 1e-3)])
def test_scale_bars_have_round_lengths(value, nice):
    from exgen.figures.polygons import _nice

    assert _nice(value) == pytest.approx(nice)
