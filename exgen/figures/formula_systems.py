"""The systems of the formula question (Example 6.2 and its companions), labelled with the symbols the
answer is written in: pulleys with inertia (floating, fixed, stepped) and uniform rods on springs.
"""
from __future__ import annotations

from .svg import LINE, THIN, Drawing
from .symbols import ball, block, ground, pivot, spring
from .values import choice

R = 34.0  # px: a pulley's radius r


def _disc(d: Drawing, c, r: float) -> None:
    d.circle(c, r, LINE, fill="#e4e4e4", cls="pulley")
    d.circle(c, 3, THIN, fill="white")


def _floating(d: Drawing) -> None:
    c = (0.0, 0.0)
    _disc(d, c, R)
    ground(d, (-R - 30, -150), (1, 0), 200, side=1)
    d.line((-R, 0), (-R, -150), LINE, cls="cord")          # fixed end
    d.line((R, 0), (R, -110), LINE, cls="cord")            # free end up to the guide pulley
    guide = (R + 24, -110)
    d.circle(guide, 24, LINE, fill="white", cls="guide")
    d.line((guide[0], -134), (guide[0], -150), LINE)
    d.line((guide[0] + 24, -110), (guide[0] + 24, 20), LINE, cls="cord")
    block(d, (guide[0] + 24, 42), 36, 44, "m")
    spring(d, (0, 3), (0, 100))
    ground(d, (0, 100), (1, 0), 60, side=-1)
    d.text((-R - 10, 5), "M", anchor="end", style="italic")
    d.text((16, 62), "K", anchor="start", style="italic")
    d.text((4, -R - 8), "r", style="italic")
    d.line((0, 0), (0, -R), THIN, cls="radius")


def _fixed(d: Drawing, stepped: bool) -> None:
    big = 2 * R if stepped else R * 1.4
    c = (0.0, 0.0)
    _disc(d, c, big)
    d.line((0, 0), (0, -big - 30), LINE * 1.2, cls="hanger")
    ground(d, (0, -big - 30), (1, 0), 70, side=1)
    if stepped:
        d.circle(c, R, LINE, fill="#f4f4f4", cls="hub")
        d.line((0, 0), (R * 0.7, R * 0.7), THIN, cls="radius")
        d.text((R * 0.7 + 4, R * 0.7 + 14), "r", anchor="start", style="italic")
        d.line((0, 0), (-big * 0.7, -big * 0.7), THIN, cls="radius")
        d.text((-big * 0.7 - 4, -big * 0.7 - 4), "2r", anchor="end", style="italic")
    spring_x = R if stepped else big
    d.line((-big, 0), (-big, 90), LINE, cls="cord")
    block(d, (-big, 112), 36, 44, "m")
    d.line((spring_x, 0), (spring_x, 40), LINE, cls="cord")
    spring(d, (spring_x, 40), (spring_x, 140))
    ground(d, (spring_x, 140), (1, 0), 60, side=-1)
    d.text((spring_x + 16, 95), "K", anchor="start", style="italic")
    d.text((big * 0.75, -big * 0.75 - 6), "M", anchor="start", style="italic")


def _lever(d: Drawing, two_springs: bool) -> None:
    length = 320.0
    x0 = -length / 2 if two_springs else 0.0
    d.line((x0, 0), (x0 + length, 0), LINE * 2.4, cls="rod")
    at = 0.0 if two_springs else x0
    pivot(d, (at, 0))
    ends = (x0, x0 + length) if two_springs else (x0 + length,)
    for x in ends:
        spring(d, (x, 6), (x, 100))
        ground(d, (x, 100), (1, 0), 50, side=-1)
        d.text((x + 16, 60), "K", anchor="start", style="italic")
    mass_x = x0 + length if two_springs else x0 + length / 2
    ball(d, (mass_x, -14), 10)
    d.text((mass_x + 14, -18), "m", anchor="start", style="italic")
    d.text((x0 + length * (0.25 if not two_springs else 0.75), -10), "M", style="italic")
    d.dimension((x0, -56), (x0 + length, -56))
    d.text((x0 + length / 2, -62), "l", style="italic")
    if not two_springs:
        d.line((x0 + length / 2, -26), (x0 + length / 2, -48), THIN, dash="3 3", cls="middle")


def formula_system(variant) -> str:
    """The system the question describes, labelled K, M, m (and r, l)."""
    system = choice(variant, "system", "floating pulley")
    d = Drawing()
    if system == "floating pulley":
        _floating(d)
    elif system in ("fixed pulley", "stepped pulley"):
        _fixed(d, system == "stepped pulley")
    else:
        _lever(d, system == "two springs")
    return d.svg(CAPTIONS[system])


#: What each figure shows, as a caption reads ("The system: two springs" named the catalogue entry).
CAPTIONS = {
    "floating pulley": "A pulley hanging in a loop of cord on a spring, with the mass m on the cord",
    "fixed pulley": "A pulley on a fixed axle, the mass m on one end of its cord and the spring on the other",
    "stepped pulley": "A stepped pulley: the mass m on the rim, the spring on the hub",
    "lever": "A rod pivoted at one end on a spring, with the mass m at its middle",
    "two springs": "A rod pivoted at its middle on two springs, with the mass m at one end",
}
