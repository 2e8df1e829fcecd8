"""Linkages measured off a drawing to scale (course text §7.9 question 1, "using the scale provided by the
dimensions on the figure, measure to determine the lengths"; Problem 7.1, whose slider-crank is a figure).

Each length measured is a step of its own, an answer that later parts are worked from (error carried
forward): the rest is the working of the same problem with its lengths printed (fourbars.coupler_point,
slider_cranks.slider_crank), run on the lengths as read. The figure draws each length to a whole 10 mm, so a
careful reading, rounded, is exact.
"""
from __future__ import annotations

import math

from ..mechanics import linkages as lk
from .fourbars import GAMMA_RANGE_DEG, coupler_point
from .slider_cranks import slider_crank

#: The least turn of the crank between the position drawn and the one asked: nearer, the figure would all
#: but show the answer.
APART = math.radians(30)
#: The least distance between two joints as drawn, a fraction of the linkage's largest size: nearer, a reader
#: could take one for the other.
CLEAR = 0.12


class AsRead:
    """The givens as the student has them: a length measured off the figure is the step read for it (the
    key's reading, or a student's when the working is redone from their answers); any other name is the
    variant's own given."""

    def __init__(self, p, d, read: tuple[str, ...]):
        self._p, self._d, self._read = p, d, read

    def __getattr__(self, name: str):
        return self._d.value_of(name) if name in self._read else getattr(self._p, name)


def measured(d, readings, dimension: str) -> tuple[str, ...]:
    """Steps of the lengths read: (step, drawn param, symbol, what) each; returns the steps' names."""
    for step, param, symbol, what in readings:
        d.step(step, getattr(d.params, param), "m", symbol=symbol,
               note=f"{what}, measured off the figure and scaled by its dimension {dimension}")
    return tuple(step for step, *_ in readings)


# ---- §7.9: the suspension's links and triangular body ------------------------------------------

SUSPENSION = (("L2", "AB", "L_2", "the crank AB"), ("L3", "BC", "L_3", "the coupler BC"),
              ("L4", "DC", "L_4", "the rocker DC"), ("CP", "PC", "CP", "the plate's side CP"),
              ("BP", "PB", "BP", "the plate's side BP"))


def coupler_point_read(p, d):
    """§7.9's four-bar read off its drawing (A straight above D by the one dimension AD), then, as
    linkages.coupler_point, θ4, θ3, the triangle's angle at C and the point P at the crank angle asked."""
    read = measured(d, SUSPENSION, "AD")
    _drawn_plainly_in_the_assembly_asked(p, d)
    coupler_point(AsRead(p, d, read), d)


def _drawn_plainly_in_the_assembly_asked(p, d) -> None:
    """The figure's assembly is the one asked: the crank turns from the position drawn to the one asked (the
    short way) with the linkage assembled all along and C on the same side of BD. And the figure shows it
    plainly: away from a dead point, no ground pivot under the plate, no two joints close together."""
    a, turn = (p.xA, p.yA), (1.0 if str(p.circuit) == "2" else -1.0)   # as fourbars.coupler_point's circuits

    def reaches(theta2: float) -> bool:
        return abs(p.BC - p.DC) <= math.hypot(*lk.polar(a, p.AB, theta2)) <= p.BC + p.DC

    d.require(abs(lk.wrap(p.theta2 - p.drawn)) >= APART, "the crank is drawn too near the angle asked")
    if not (reaches(p.drawn) and reaches(p.theta2)):
        d.require(False, "the linkage cannot be assembled at the crank angle drawn or asked")
        return
    ends = [lk.rocker_pin(a, p.AB, p.BC, p.DC, t, turn) for t in (p.drawn, p.theta2)]
    d.require(lk.moves_between(a, (0.0, 0.0), *ends[0], *ends[1]),
              "the crank cannot turn from the position drawn to the one asked in the assembly drawn")
    low, high = GAMMA_RANGE_DEG
    gamma = lk.cosine_law_angle(p.BC, p.DC, math.hypot(*ends[0][0]))
    d.require(low <= math.degrees(gamma) <= high,
              "the linkage is drawn near a dead point, where its assembly is hard to see")
    drawn = {"A": a, "D": (0.0, 0.0), **lk.plate_pose(a, p.AB, p.BC, p.DC, p.drawn, turn, p.PC, p.PB,
                                                       str(p.side) == "left")}
    d.require(not any(lk.inside_triangle(drawn[q], [drawn[k] for k in "BCP"]) for q in "AD"),
              "a ground pivot is drawn under the coupler plate")
    points = list(drawn.values())
    nearest = min(math.dist(q, r) for i, q in enumerate(points) for r in points[i + 1:])
    d.require(nearest >= CLEAR * max(p.yA, p.BC, p.PB), "two of the joints are drawn too close together to tell apart")


# ---- Problem 7.1: an offset slider-crank ----------------------------------------------------

SLIDER_CRANK = (("L2", "AB", "L_2", "the crank AB"), ("L1", "offset", "L_1", "the offset of the line of slide"),
                ("tip", "piston", "CP", "the piston, from the slider pin C to its tip P"))
SENSE = {"clockwise": -1.0, "counter-clockwise": 1.0}


def slider_crank_read(p, d):
    """Problem 7.1: the crank, the offset and the piston read off the drawing (the coupler BC its one
    dimension), the crank turned from the angle drawn, then the piston tip's place as linkages.slider_crank
    finds it."""
    read = measured(d, SLIDER_CRANK, "BC")
    sense = SENSE[str(p.sense)]
    d.step("theta2", p.drawn + sense * p.turn, "rad", symbol=r"\theta_2",
           formula=rf"@drawn {'+' if sense > 0 else '-'} @turn",
           note=f"the crank turned {p.sense} from the angle drawn ({'counter-clockwise' if sense > 0 else 'clockwise'} "
                f"is {'positive' if sense > 0 else 'negative'} from +x)")
    d.mistake("theta2", "turned_other_way", p.drawn - sense * p.turn)
    slider_crank(AsRead(p, d, read + ("theta2",)), d)
