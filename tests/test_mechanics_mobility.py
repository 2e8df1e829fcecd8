"""Mobility counting (exgen.mechanics.mobility and the catalogue) against the course text and against
an independent count: the rank of the mechanism's constraint equations at its drawn position.

Each moving link gets a pose (x, y, φ); a pin where links meet says their copies of the point
coincide, a slider keeps its point on the guide's line and its angle, a pin in a slot keeps its
point on the slot's line, and meshing gears roll (r₂ dφ₂ + r₃ dφ₃ = 0). The freedom left is the
number of pose coordinates less the rank of those equations' Jacobian: Gruebler's count when no
constraint repeats another, and 0 for a structure with members to spare (Gruebler's M < 0).
"""
import itertools
import math

import numpy as np
import pytest

from exgen.mechanics.mechanism_catalogue import ADDITIONS, BASES, build, misleading
from exgen.mechanics.mobility import GROUND, mobility


def _world(mech, q, body, point):
    x, y = mech.points[point]
    if body == GROUND:
        return np.array([x, y])
    bx, by, phi = q[3 * body: 3 * body + 3]
    return np.array([bx + x * math.cos(phi) - y * math.sin(phi), by + x * math.sin(phi) + y * math.cos(phi)])


def _angle(q, body):
    return 0.0 if body == GROUND else q[3 * body + 2]


def _equations(mech, q):
    out = []
    for point in mech.points:
        bodies = mech.bodies_at(point)
        for other in bodies[1:]:
            out.extend(_world(mech, q, bodies[0], point) - _world(mech, q, other, point))
    for slider in mech.sliders:
        t = _angle(q, slider.guide)
        dx, dy = slider.direction
        normal = np.array([-(dx * math.sin(t) + dy * math.cos(t)), dx * math.cos(t) - dy * math.sin(t)])
        out.append(normal @ (_world(mech, q, slider.block, slider.point) - _world(mech, q, slider.guide, slider.point)))
        out.append(_angle(q, slider.block) - t)
    for slot in mech.slots:
        t = _angle(q, slot.body)
        dx, dy = slot.direction
        normal = np.array([-(dx * math.sin(t) + dy * math.cos(t)), dx * math.cos(t) - dy * math.sin(t)])
        out.append(normal @ (_world(mech, q, slot.pin_link, slot.point) - _world(mech, q, slot.body, slot.point)))
    for mesh in mech.meshes:
        radii = [math.dist(mech.points[mech.links[g].points[0]], mech.points[mesh.contact]) for g in (mesh.a, mesh.b)]
        out.append(radii[0] * _angle(q, mesh.a) + radii[1] * _angle(q, mesh.b))
    return np.array(out)


def freedom_by_rank(mech) -> tuple[int, int]:
    """(freedom, redundant equations) from the Jacobian at the drawn position."""
    n = 3 * len(mech.links)
    q0, h = np.zeros(n), 1e-6
    columns = [(_equations(mech, q0 + h * e) - _equations(mech, q0 - h * e)) / (2 * h) for e in np.eye(n)]
    jacobian = np.array(columns).T
    rank = np.linalg.matrix_rank(jacobian, tol=1e-7 * max(1.0, np.abs(jacobian).max()))
    return n - rank, jacobian.shape[0] - rank


@pytest.mark.parametrize("base", BASES)
def test_every_catalogue_mechanism_moves_as_gruebler_counts(base):
    """Over all 343 ways of filling the three sites; those Gruebler misleads on are never drawn."""
    for additions in itertools.product(ADDITIONS, repeat=3):
        mech = build(base, additions)
        freedom, redundant = freedom_by_rank(mech)
        m = mech.mobility
        agrees = freedom == max(m, 0) and redundant == max(-m, 0)
        assert agrees != misleading(mech), (base, additions, m, freedom, redundant)


def test_mirrored_mechanisms_count_the_same():
    for base, additions in [("four-bar", ("dyad", "slider", "shared")), ("gear-pair", ("slot", "brace", "loose")),
                            ("slotted-lever", ("shared", "slot", "dyad"))]:
        plain, turned = build(base, additions), build(base, additions, mirror=True)
        assert (turned.link_count, turned.lower_pairs, turned.higher_pairs) == \
            (plain.link_count, plain.lower_pairs, plain.higher_pairs)
        assert freedom_by_rank(turned) == freedom_by_rank(plain)


@pytest.mark.parametrize("base, counts", [
    ("four-bar", (4, 4, 0, 1)),        # Figure 7.8, the car wiper: M = 3(4 - 1) - 2(4) - 0 = 1
    ("slider-crank", (4, 4, 0, 1)),    # Figure 7.10
    ("slotted-lever", (3, 2, 1, 1)),   # a pin in a slot, Figure 7.7
    ("gear-pair", (3, 2, 1, 1)),       # a gear mesh counted as J2 (§7.2)
    ("five-bar", (5, 5, 0, 2)),        # two inputs (§7.6)
    ("truss", (3, 3, 0, 0)),           # a structure (Figure 7.12b)
])
def test_the_bases(base, counts):
    mech = build(base)
    assert (mech.link_count, mech.lower_pairs, mech.higher_pairs, mech.mobility) == counts


def test_a_pin_shared_by_three_links_is_two_joints():
    """Figure 7.11: where links 2, 3 and 4 share one pin, J1 counts two joints there."""
    mech = build("four-bar", ("shared", "none", "none"))
    assert mech.pins()["A"] == 2 and mech.shared_extra == 1
    assert mech.mobility == mobility(6, 7) == 1     # a Stephenson-type six-bar on a shared pin


def test_six_bars_of_watt_and_stephenson():
    watt = build("four-bar", ("none", "dyad", "none"))        # a dyad from the rocker to the ground
    stephenson = build("four-bar", ("dyad", "none", "none"))  # a dyad from the coupler to the ground
    for mech in (watt, stephenson):
        assert (mech.link_count, mech.lower_pairs, mech.mobility) == (6, 7, 1)
    assert sum(1 for link in watt.links if len(link.points) == 3) == 1


def test_unknown_names_are_refused():
    with pytest.raises(ValueError, match="no base"):
        build("ten-bar")
    with pytest.raises(ValueError, match="no addition"):
        build("four-bar", ("cam",))


@pytest.mark.parametrize("base", BASES)
def test_the_mobility_the_geometry_gives_is_the_rank_count(base):
    # exgen's own rank (instantaneous_mobility, which linkages.mobility_exceptions asks) against this file's
    # numerical Jacobian, for every catalogue diagram, the ones Gruebler misleads on included
    from exgen.mechanics.mobility import instantaneous_mobility

    for additions in itertools.product(ADDITIONS, repeat=3):
        mech = build(base, additions)
        assert instantaneous_mobility(mech) == freedom_by_rank(mech)[0], (base, additions)


@pytest.mark.parametrize("case, gruebler, true", [
    ("four-bar", 1, 1), ("three cranks", 0, 1), ("three cranks, one askew", 0, 0), ("four cranks", -1, 1)])
def test_parallel_cranks_move_where_grueblers_count_says_they_cannot(case, gruebler, true):
    # §7.4: "The KMoGE does not account for link sizes and shapes. It can give misleading results in the case
    # of unique geometric configurations": a crank parallel and equal to a parallelogram's is redundant
    from exgen.mechanics.mechanism_catalogue import parallel_cranks
    from exgen.mechanics.mobility import instantaneous_mobility

    for theta in (55, 90, 125):
        for mirror in (False, True):
            mech = parallel_cranks(case, math.radians(theta), mirror)
            assert (mech.mobility, instantaneous_mobility(mech), freedom_by_rank(mech)[0]) == (gruebler, true, true)
