"""Whole positions of a four-bar for drawing it: the course text's equations (exgen.mechanics.linkages)
composed into BD, γ, θ3, θ4 and the joints' places. A solver works the same equations step by step, so
that a student's own BD or γ carries forward; a figure needs the whole pose at once, at the crank angle
it is drawn at (which need not be the one asked)."""
from __future__ import annotations

from dataclasses import dataclass

from ..mechanics.linkages import coupler_angle, diagonal, polar, rocker_angle, transmission_angle


@dataclass(frozen=True)
class FourBar:
    """The position of a four-bar at one crank angle: the text's BD, γ, θ3, θ4."""

    bd: float
    gamma: float
    theta3: float
    theta4: float


def pose(ground: float, crank: float, coupler: float, rocker: float, theta2: float,
            circuit: int = 1) -> FourBar:
    """BD, γ, θ3 and θ4 by the text's equations: circuit 1 by 7.5-7.6, circuit 2 by 7.7-7.8."""
    bd = diagonal(ground, crank, theta2)
    gamma = transmission_angle(coupler, rocker, bd)
    return FourBar(bd, gamma, coupler_angle(ground, crank, coupler, rocker, theta2, gamma, circuit),
                   rocker_angle(ground, crank, coupler, rocker, theta2, gamma, circuit))


def joints(ground: float, crank: float, coupler: float, rocker: float, theta2: float, circuit: int = 1,
           origin: tuple[float, float] = (0.0, 0.0), theta1: float = 0.0) -> dict[str, tuple[float, float]]:
    """A, B, C, D with A at `origin` and the ground line AD at `theta1`; θ2 is absolute (from +x)."""
    pos = pose(ground, crank, coupler, rocker, theta2 - theta1, circuit)
    a = origin
    b = polar(a, crank, theta2)
    d = polar(a, ground, theta1)
    c = polar(b, coupler, pos.theta3 + theta1)
    return {"A": a, "B": b, "C": c, "D": d}
