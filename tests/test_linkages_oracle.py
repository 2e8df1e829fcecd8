"""The linkage physics against an independent kinematics package (pylinkage, test-only).

pylinkage places a joint by intersecting circles (a four-bar's rocker pin) or a circle and a
line (a slider), choosing the intersection nearest a hint, and raises UnbuildableError when
there is none. exgen follows the course text's half-angle equations (7.3-7.8) and its
slider-crank equations (7.10-7.14), so agreement checks the text's formulas, our reading of
its circuits and our assembly checks. The hint is placed far out on the side of the diagonal
BD (four-bar) or far along the line of slide (slider-crank) that the circuit names, so
pylinkage picks the circuit by geometry alone. Grashof's table is checked against what
pylinkage can build: a link turns fully relative to its neighbour exactly when the linkage
assembles with it at 0° and at 180°, where the diagonal is longest and shortest.
"""
import math

import numpy as np
import pytest

pytest.importorskip("pylinkage")
from pylinkage import Crank, Ground, RRPDyad, RRRDyad, UnbuildableError  # noqa: E402
from pylinkage.linkage.transmission import compute_transmission_angle  # noqa: E402

from exgen.figures.linkage_poses import joints, pose  # noqa: E402
from exgen.mechanics import linkages as lk  # noqa: E402
from exgen.mechanics.slider_cranks import BRANCHES, slider_crank  # noqa: E402

CASES = 1000       # assemblable linkages, each solved in both circuits
TOL = 1e-6
FAR = 1e4          # how far out the circuit hint lies, in link lengths


def pylinkage_fourbar(ground, crank, coupler, rocker, theta2, circuit, origin=(0.0, 0.0), theta1=0.0):
    """C from pylinkage (or None when it cannot build), with the hint on the circuit's side of BD."""
    a = Ground(*origin)
    d = Ground(origin[0] + ground * math.cos(theta1), origin[1] + ground * math.sin(theta1))
    arm = Crank(anchor=a, radius=crank, initial_angle=theta2)
    b = arm.output.position
    mid = ((b[0] + d.x) / 2, (b[1] + d.y) / 2)
    normal = (-(d.y - b[1]), d.x - b[0])  # points to the left of B -> D
    sign = FAR * max(ground, crank, coupler, rocker) / math.hypot(*normal) * (1 if circuit == 1 else -1)
    dyad = RRRDyad(anchor1=arm.output, anchor2=d, distance1=coupler, distance2=rocker,
                   x=mid[0] + sign * normal[0], y=mid[1] + sign * normal[1])
    try:
        dyad.reload(0)
    except UnbuildableError:
        return None
    return b, (dyad.x, dyad.y), (d.x, d.y)


def _angle_gap(a, b):
    return abs(lk.wrap(a - b))


def random_fourbars(rng, count):
    """Lengths from 0.5 to 10 in a random frame; half of the draws cannot assemble at their θ2."""
    for _ in range(count):
        lengths = rng.uniform(0.5, 10.0, 4)
        yield (*lengths, rng.uniform(-math.pi, math.pi), tuple(rng.uniform(-20, 20, 2)), rng.uniform(-math.pi, math.pi))


def test_four_bar_positions_agree_with_pylinkage_in_both_circuits():
    rng = np.random.default_rng(20240607)
    agreed = refused = 0
    worst = 0.0
    for ground, crank, coupler, rocker, theta2, origin, theta1 in random_fourbars(rng, 4000):
        local = theta2 - theta1
        bd = lk.diagonal(ground, crank, local)
        margin = min(coupler + rocker - bd, bd - abs(coupler - rocker))
        if abs(margin) < 1e-6 * max(ground, crank, coupler, rocker):
            continue  # on the edge of assembly both answers are ill-conditioned
        for circuit in lk.CIRCUITS:
            theirs = pylinkage_fourbar(ground, crank, coupler, rocker, theta2, circuit, origin, theta1)
            if theirs is None:
                assert not lk.can_assemble(ground, crank, coupler, rocker, local)
                with pytest.raises(lk.NotAssemblable):
                    pose(ground, crank, coupler, rocker, local, circuit)
                refused += 1
                continue
            b, c, d = theirs
            ours = joints(ground, crank, coupler, rocker, theta2, circuit, origin, theta1)
            pos = pose(ground, crank, coupler, rocker, local, circuit)
            worst = max(worst, math.dist(ours["C"], c), math.dist(ours["B"], b),
                        _angle_gap(pos.theta3 + theta1, math.atan2(c[1] - b[1], c[0] - b[0])),
                        _angle_gap(pos.theta4 + theta1, math.atan2(c[1] - d[1], c[0] - d[0])),
                        abs(math.degrees(pos.gamma) - compute_transmission_angle(b, c, d)) * math.pi / 180)
            assert worst < TOL, (ground, crank, coupler, rocker, theta2, circuit)
            agreed += 1
        if agreed >= 2 * CASES and refused >= 200:
            break
    assert agreed >= 2 * CASES and refused >= 200


def pylinkage_slider(crank, coupler, offset, theta2, slide, branch):
    a = Ground(0.0, 0.0)
    far = FAR * (crank + coupler + abs(offset))
    if slide == "horizontal":
        ends, hint = ((-1.0, -offset), (1.0, -offset)), (far if branch == "right" else -far, -offset)
    else:
        ends, hint = ((offset, -1.0), (offset, 1.0)), (offset, -far if branch == "below" else far)
    arm = Crank(anchor=a, radius=crank, initial_angle=theta2)
    block = RRPDyad(revolute_anchor=arm.output, line_anchor1=Ground(*ends[0]), line_anchor2=Ground(*ends[1]),
                    distance=coupler, x=hint[0], y=hint[1])
    try:
        block.reload(0)
    except UnbuildableError:
        return None
    return arm.output.position, (block.x, block.y)


@pytest.mark.parametrize("slide", ["horizontal", "vertical"])
def test_slider_crank_positions_agree_with_pylinkage_on_both_branches(slide):
    rng = np.random.default_rng(7 if slide == "horizontal" else 11)
    agreed = refused = 0
    for _ in range(4000):
        crank, coupler = rng.uniform(0.5, 10.0, 2)
        offset = rng.uniform(-8.0, 8.0) * (rng.random() < 0.8)   # a fifth of them in-line
        theta2 = rng.uniform(-math.pi, math.pi)
        reach = (offset + crank * math.sin(theta2)) if slide == "horizontal" else (offset - crank * math.cos(theta2))
        if abs(abs(reach) - coupler) < 1e-6 * coupler:
            continue
        for branch in BRANCHES[slide]:
            theirs = pylinkage_slider(crank, coupler, offset, theta2, slide, branch)
            if theirs is None:
                with pytest.raises(lk.NotAssemblable):
                    slider_crank(crank, coupler, offset, theta2, slide, branch)
                refused += 1
                continue
            b, c = theirs
            ours = slider_crank(crank, coupler, offset, theta2, slide, branch)
            assert math.dist(ours.c, c) < TOL and math.dist(ours.b, b) < TOL, (crank, coupler, offset, theta2, branch)
            assert _angle_gap(ours.direction, math.atan2(c[1] - b[1], c[0] - b[0])) < TOL
            agreed += 1
        if agreed >= 2 * CASES and refused >= 200:
            break
    assert agreed >= 2 * CASES and refused >= 200


def turns_fully(fixed, mover, far_link, near_link):
    """Whether `mover` turns fully about its pivot on `fixed`: pylinkage builds it at 0° and 180°."""
    return all(pylinkage_fourbar(fixed, mover, far_link, near_link, angle, 1) is not None for angle in (0.0, math.pi))


def test_grashof_table_agrees_with_what_pylinkage_can_build():
    rng = np.random.default_rng(5)
    seen = {}
    for _ in range(3000):
        ground, crank, coupler, rocker = lengths = rng.uniform(1.0, 10.0, 4)
        ordered = sorted(lengths)
        if min(np.diff(ordered)) < 1e-3 or abs(ordered[0] + ordered[3] - ordered[1] - ordered[2]) < 1e-3:
            continue  # ties and change points are classed by the table alone
        crank_turns = turns_fully(ground, crank, coupler, rocker)
        rocker_turns = turns_fully(ground, rocker, coupler, crank)
        coupler_turns_on_crank = turns_fully(crank, coupler, rocker, ground)
        kind = lk.grashof(ground, crank, coupler, rocker).kind
        if crank_turns and rocker_turns:
            expected = "double-crank"
        elif crank_turns or rocker_turns:
            expected = "crank-rocker"
        else:
            expected = "double-rocker" if coupler_turns_on_crank else "triple-rocker"
        assert kind == expected, lengths
        seen[kind] = seen.get(kind, 0) + 1
    assert set(seen) == {"crank-rocker", "double-crank", "double-rocker", "triple-rocker"}
    assert min(seen.values()) >= 50
