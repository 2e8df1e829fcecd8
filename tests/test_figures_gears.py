"""Gear figures: valid SVG, deterministic, drawn to the data, no answer printed, no sense given away."""
import math
import re

import pytest

from exgen import units
from exgen.figures import figure_svg
from exgen.figures import gear_trains, gears, hoists
from exgen.solve.variant import make_variant
from svg_helpers import SVG, circles, root, texts, variant_of

GEAR_FIGURES = ["gears.pitch_geometry", "gears.teeth_for_centre_distance", "gears.gear_pair_power",
                "gears.simple_train", "gears.compound_train", "gears.reverted_train", "gears.epicyclic",
                "gears.hoist_torque", "gears.lift_counterweight", "gears.haulage_power"]










def radius(svg, cls):
    (circle,) = circles(svg, cls)
    return float(circle.get("r"))


def centre(circle):
    return float(circle.get("cx")), float(circle.get("cy"))


def pitch(svg, name):
    """The pitch circles of the gears named `name` (class 'pitch <name>')."""
    return [c for c in circles(svg, "pitch") if name in c.get("class").split()]


def bars(svg):
    """Gear bars of a side-view train: white four-cornered polygons, as (x, y_top, y_bottom)."""
    out = []
    for poly in root(svg).iter(f"{SVG}polygon"):
        points = [tuple(map(float, p.split(","))) for p in poly.get("points").split()]
        if poly.get("fill") == "white" and len(points) == 4:
            xs, ys = [p[0] for p in points], [p[1] for p in points]
            out.append(((min(xs) + max(xs)) / 2, min(ys), max(ys)))
    return out


def rotation_senses(svg):
    """For each rotation arrow, True if it turns clockwise on the page (SVG arc sweep flag 1)."""
    return [path.get("d").split()[7] == "1" for path in root(svg).iter(f"{SVG}path")
            if path.get("class") == "rotation"]


@pytest.mark.parametrize("template_id", GEAR_FIGURES)
def test_valid_svg_of_one_width_and_repeatable(bank, template_id):
    template = bank.get(template_id)
    assert template.figure, template_id
    for seed in range(5):
        svg = figure_svg(make_variant(template, seed))
        tree = root(svg)
        assert tree.tag == f"{SVG}svg"
        _, _, width, height = map(float, tree.get("viewBox").split())
        assert 630 <= width <= 720 and 150 < height < 480, (template_id, seed, width, height)
        assert svg == figure_svg(make_variant(template, seed))


def _numbers(text):
    return set(re.findall(r"\d+(?:\.\d+)?", text))


@pytest.mark.parametrize("template_id", GEAR_FIGURES)
def test_no_answer_is_printed(bank, template_id):
    for seed in range(12):
        variant = make_variant(bank.get(template_id), seed)
        shown = set().union(*(_numbers(t) for t in texts(figure_svg(variant))))
        printed = set().union(*(_numbers(str(p)) for p in variant.params))
        for answer in variant.answers.values():
            value = answer.value
            candidates = [str(value)] if isinstance(value, int) else (
                [units.format_number(value, sig) for sig in (2, 3, 4)] if isinstance(value, float) else [])
            for number in candidates:
                assert number in printed or number not in shown, (template_id, seed, answer.part.id, number)


@pytest.mark.parametrize("t1, t2", [(20, 60), (12, 120), (32, 36)])
def test_gear_pair_is_drawn_to_the_teeth(bank, t1, t2):
    svg = gears.gear_pair(variant_of(bank, "gears.pitch_geometry", t1=t1, t2=t2, m=4, N1=900))
    (p1,), (p2,) = pitch(svg, "driver"), pitch(svg, "driven")
    r1, r2 = float(p1.get("r")), float(p2.get("r"))
    assert r2 / r1 == pytest.approx(t2 / t1, rel=2e-3)
    assert math.dist(centre(p1), centre(p2)) == pytest.approx(r1 + r2, abs=0.02)  # pitch circles touch
    labels = texts(svg)
    assert f"{t1} teeth" in labels and f"{t2} teeth" in labels and "C = ?" in labels
    assert "\u03c9\u2081 = 900 rpm" in labels and "module m = 4 mm" in labels


def test_unknown_teeth_are_drawn_to_size_and_labelled_with_a_question_mark(bank):
    variant = variant_of(bank, "gears.teeth_for_centre_distance", C=240, m=4, k=3, N1=960)
    svg = figure_svg(variant)
    assert texts(svg).count("? teeth") == 2 and "C = 240 mm" in texts(svg)
    (p1,), (p2,) = pitch(svg, "driver"), pitch(svg, "driven")
    assert float(p2.get("r")) / float(p1.get("r")) == pytest.approx(3.0, rel=2e-3)  # 90 : 30 teeth


@pytest.mark.parametrize("idlers", [1, 2])
@pytest.mark.parametrize("sense", ["clockwise", "counter-clockwise"])
def test_simple_train_shows_every_mesh_and_only_the_drivers_sense(bank, idlers, sense):
    variant = variant_of(bank, "gears.simple_train", idlers=idlers, t1=20, ta=40, tb=25, t2=60, sense1=sense)
    svg = gears.simple_train(variant)
    faces = pitch(svg, "driver") + pitch(svg, "idler") + pitch(svg, "driven")
    assert len(faces) == idlers + 2
    faces.sort(key=lambda c: centre(c)[0])
    teeth = [20, 40] + ([25] if idlers == 2 else []) + [60]
    for a, b, ta, tb in zip(faces, faces[1:], teeth, teeth[1:]):
        ra, rb = float(a.get("r")), float(b.get("r"))
        assert rb / ra == pytest.approx(tb / ta, rel=2e-3)
        assert math.dist(centre(a), centre(b)) == pytest.approx(ra + rb, abs=0.02)
    assert rotation_senses(svg) == [sense == "clockwise"]  # the driven gear's sense is the question
    assert "\u03c9\u2082 = ?" in texts(svg) and "C = ?" in texts(svg)


@pytest.mark.parametrize("ts, tp", [(30, 35), (15, 40), (40, 15)])
def test_epicyclic_is_coaxial_and_drawn_to_the_teeth(bank, ts, tp):
    svg = gears.epicyclic(variant_of(bank, "gears.epicyclic", ts=ts, tp=tp, fixed="sun", driver="arm"))
    r_sun, r_ring = float(pitch(svg, "sun")[0].get("r")), float(pitch(svg, "ring")[0].get("r"))
    planets = pitch(svg, "planet")
    assert len(planets) == 3
    r_planet = float(planets[0].get("r"))
    assert r_planet / r_sun == pytest.approx(tp / ts, rel=2e-3)
    assert r_ring == pytest.approx(r_sun + 2 * r_planet, rel=2e-3)
    for planet in planets:  # each planet touches the sun and the ring
        assert math.hypot(*centre(planet)) == pytest.approx(r_sun + r_planet, abs=0.02)
    labels = texts(svg)
    assert f"sun: {ts} teeth" in labels and f"planets: {tp} teeth" in labels and "ring: ? teeth" in labels


@pytest.mark.parametrize("fixed, driver, sense", [("sun", "arm", "clockwise"), ("ring", "gear", "counter-clockwise"),
                                                  ("sun", "gear", "clockwise")])
def test_epicyclic_marks_the_fixed_member_and_the_input(bank, fixed, driver, sense):
    variant = variant_of(bank, "gears.epicyclic", ts=24, tp=30, fixed=fixed, driver=driver, N_in=600, sense_in=sense)
    svg = gears.epicyclic(variant)
    labels = texts(svg)
    assert "fixed" in labels and "input, 600 rpm" in labels
    assert rotation_senses(svg) == [sense == "clockwise"]
    ground = [line for line in root(svg).iter(f"{SVG}line") if line.get("class") == "ground"]
    assert ground and f"the {fixed} fixed" in root(svg).find(f"{SVG}title").text


def test_compound_train_of_example_1_7_to_scale(bank):
    variant = variant_of(bank, "gears.compound_train", N2=1800, sense2="clockwise", t2=12, P23=12, d3=2.5,
                         t4=15, P45=10, d5=3, d6=1.5, t7=32, P67=8)
    svg = gear_trains.compound_train(variant)
    found = bars(svg)
    assert len(found) == 6
    heights = [b[2] - b[1] for b in found]  # gears 2 to 7, in order
    diameters = [1.0, 2.5, 1.5, 3.0, 1.5, 4.0]
    for h, dia in zip(heights, diameters):
        assert h / heights[0] == pytest.approx(dia / diameters[0], rel=2e-3)
    for lower, upper in ((0, 1), (2, 3), (4, 5)):  # meshing bars share a column and touch
        assert found[lower][0] == found[upper][0]
        assert found[lower][1] == pytest.approx(found[upper][2], abs=0.02)
    shafts = sorted({float(line.get("y1")) for line in root(svg).iter(f"{SVG}line")
                     if "shaft" in line.get("class", "").split()})
    assert shafts[-1] - shafts[0] == pytest.approx(6.75 * heights[0], rel=2e-3)  # C = 6.75 in, d2 = 1 in
    labels = texts(svg)
    for expected in ("t\u2082 = 12", "Pd = 12 teeth/in", "d\u2083 = 2.5 in", "1800 rpm clockwise", "\u03c9\u2087 = ?", "C = ?"):
        assert expected in labels


def test_reverted_train_of_example_1_8_is_coaxial(bank):
    variant = variant_of(bank, "gears.reverted_train", m1=2, m2=3, t1=24, t2=120, t3=24, NA=1000)
    svg = gear_trains.reverted_train(variant)
    (g1, g2, g3, g4) = bars(svg)
    radii = [(b[2] - b[1]) / 2 for b in (g1, g2, g3, g4)]
    assert [r / radii[0] for r in radii] == pytest.approx([1, 5, 1.5, 4.5], rel=2e-3)  # 2x24, 2x120, 3x24, 3x72
    assert radii[0] + radii[1] == pytest.approx(radii[2] + radii[3], rel=2e-3)  # one centre distance
    assert g1[1] + radii[0] == pytest.approx(g4[1] + radii[3], abs=0.02)        # A and B in line
    labels = texts(svg)
    assert "t\u2084 = ?" in labels and "A turns at 1000 rpm" in labels and "B turns at ?" in labels


def test_hoist_gears_drum_and_load(bank):
    variant = variant_of(bank, "gears.hoist_torque", t1=20, t2=200, dD=1.2, M=250, a=1.2, slope=10)
    svg = hoists.hoist(variant)
    (p1,), (p2,) = pitch(svg, "motor-gear"), pitch(svg, "drum-gear")
    assert float(p2.get("r")) / float(p1.get("r")) == pytest.approx(10, rel=2e-3)
    (drum,) = circles(svg, "drum")
    assert centre(drum) == centre(p2)
    labels = texts(svg)
    for expected in ("M = 250 kg", "a = 1.2 m/s\u00b2", "\u03b8 = 10\u00b0", "drum: 1.2 m diameter", "gear: 20 teeth"):
        assert expected in labels


def test_a_larger_drum_is_drawn_larger(bank):
    small = radius(hoists.hoist(variant_of(bank, "gears.hoist_torque", dD=0.6)), "drum")
    large = radius(hoists.hoist(variant_of(bank, "gears.hoist_torque", dD=1.6)), "drum")
    assert large > small


def test_lift_of_problem_1_2(bank):
    variant = variant_of(bank, "gears.lift_counterweight", t1=80, t2=100, t3=20, t4=40, ml=2000, a=0.5)
    svg = hoists.lift(variant)
    r = [float(pitch(svg, f"gear{i}")[0].get("r")) for i in range(1, 5)]
    assert [x / r[0] for x in r] == pytest.approx([1, 100 / 80, 20 / 80, 40 / 80], rel=2e-3)
    c = [centre(pitch(svg, f"gear{i}")[0]) for i in range(1, 5)]
    assert math.dist(c[0], c[1]) == pytest.approx(r[0] + r[1], abs=0.02)  # 1 meshes 2
    assert c[1] == c[2]                                                   # 2 and 3 share a shaft
    assert math.dist(c[2], c[3]) == pytest.approx(r[2] + r[3], abs=0.02)  # 3 meshes 4
    labels = texts(svg)
    assert "M\u2082 = ?" in labels and "2000 kg" in labels and "gear 4 (drum): 40 teeth" in labels


def test_haulage_labels_the_slope_and_hides_the_mass(bank):
    variant = variant_of(bank, "gears.haulage_power", s=20, t1=25, t2=125, dD=0.8, f=1750, a=0.8)
    labels = texts(hoists.haulage(variant))
    for expected in ("M = ?", "slope 1 in 20", "f = 1750 N", "a = 0.8 m/s\u00b2", "drum gear: 125 teeth"):
        assert expected in labels
