"""Levers on springs and dashpots drawn to each variant's lengths (course text §6.5-6.7, Examples 6.1
and 6.4, Problem 6.1): pivots, arms in proportion, springs and dashpots where the problem puts them.
"""
from __future__ import annotations

from .flywheels import need
from .svg import LINE, THIN, Drawing
from .symbols import ball, block, dashpot, dimension, ground, pivot, spring

ARM_PX = 420.0  # the longest arm drawn


def lever_equivalent(variant) -> str:
    """Example 6.1: rod ABC pivoted at C, a mass and a spring at A, a spring at B (to the ceiling) and a
    link BD hanging from B with a mass at D."""
    big_l, b = need(variant, "L"), need(variant, "b")
    scale = ARM_PX / big_l.si
    xa, xb, xc = 0.0, (big_l.si - b.si) * scale, big_l.si * scale
    d = Drawing()
    d.line((xa, 0), (xc, 0), LINE * 2.4, cls="rod")
    pivot(d, (xc, 0))
    spring(d, (xa, 6), (xa, 96))
    ground(d, (xa, 96), (1, 0), 50, side=-1)
    block(d, (xa, -18), 34, 26, "")
    spring(d, (xb, -6), (xb, -96))
    ground(d, (xb, -96), (1, 0), 50, side=1)
    d.line((xb, 0), (xb, 110), LINE, cls="link")
    block(d, (xb, 128), 40, 36, "")
    for letter, x, y in (("A", xa - 22, 6), ("B", xb - 14, 16), ("C", xc + 14, -8), ("D", xb + 30, 134)):
        d.text((x, y), letter, style="italic", anchor="middle")
    dimension(d, (xa, 0), (xc, 0), big_l.label("AC"), side=1, offset=150)
    dimension(d, (xb, 0), (xc, 0), b.label("BC"), side=1, offset=118)
    labels = [(need(variant, "m_A").value_text, ((xa + 24, -22), "start")),
              (need(variant, "K_A").value_text, ((xa + 16, 60), "start")),
              (need(variant, "K_B").value_text, ((xb + 16, -60), "start")),
              ("link " + need(variant, "m_BD").value_text, ((xb + 10, 70), "start")),
              (need(variant, "m_D").value_text, ((xb + 28, 150), "start")),
              ("rod " + need(variant, "m_r").value_text, (((xb + xc) / 2, -12), "middle"))]
    for text, at in labels:
        (x, y), anchor = at
        flipped = "end" if anchor == "start" else "start" if anchor == "end" else anchor
        mirror = x - 32 if anchor == "start" else x + 32 if anchor == "end" else x
        d.place([at, ((x, y + 18), anchor), ((x, y - 18), anchor), ((mirror, y), flipped)], text)
    return d.svg("Rod ABC pivoted at C, with springs at A and B and a link BD")


def beam_two_springs(variant) -> str:
    """Problem 6.1: beam AOB pivoted at O, springs at A and B, a ball at B."""
    a, b = need(variant, "a"), need(variant, "b")
    scale = ARM_PX / (a.si + b.si)
    xa, xo, xb = 0.0, a.si * scale, (a.si + b.si) * scale
    d = Drawing()
    d.line((xa, 0), (xb, 0), LINE * 2.4, cls="beam")
    pivot(d, (xo, 0))
    for x in (xa, xb):
        spring(d, (x, 6), (x, 96))
        ground(d, (x, 96), (1, 0), 50, side=-1)
    ball(d, (xb, -14), 10)
    for letter, x, y in (("A", xa - 16, -6), ("O", xo, -10), ("B", xb + 18, -6)):
        d.text((x, y), letter, style="italic")
    dimension(d, (xa, 0), (xo, 0), a.label("OA"), side=-1, offset=128)  # first: labels keep clear of its lines
    dimension(d, (xo, 0), (xb, 0), b.label("OB"), side=-1, offset=128)
    k = need(variant, "K").label("K")
    d.place([((xa + 16, 60), "start"), ((xa - 16, 60), "end")], k)   # outside the spring when O is close
    d.place([((xb - 16, 60), "end"), ((xb + 16, 60), "start")], k)
    d.place([((xb, -32), "middle"), ((xb - 16, -32), "end")], need(variant, "m_B").value_text)
    d.place([((xo - 24, -14), "end"), ((xo + 24, -14), "start")], "beam " + need(variant, "m").value_text)
    return d.svg("Beam AOB pivoted at O on two springs")


def damped_pendulum_lever(variant) -> str:
    """Example 6.4: bell crank ADE about D; dashpot under A, pendulum mass at E, horizontal spring at B."""
    a, l, b = need(variant, "a"), need(variant, "l"), need(variant, "b")
    scale = 260 / max(a.si, l.si)
    xa, ye, yb = -a.si * scale, l.si * scale, b.si * scale
    d = Drawing()
    d.line((xa, 0), (0, 0), LINE * 2.2, cls="arm")
    d.line((0, 0), (0, ye), LINE * 2.2, cls="arm")
    d.circle((0, 0), 4, LINE, fill="white", cls="pivot")
    ground(d, (0, -22), (1, 0), 40, side=1)
    d.line((0, -22), (0, -4), LINE)
    ball(d, (0, ye + 12), 13)
    dashpot(d, (xa, 150 + ye * 0.3), (xa, 4))
    ground(d, (xa, 150 + ye * 0.3), (1, 0), 50, side=-1)
    wall = 150.0
    spring(d, (4, yb), (wall, yb))
    ground(d, (wall, yb), (0, 1), 50, side=-1)
    for letter, at in (("A", (xa - 14, -6)), ("D", (-14, -8)), ("E", (22, ye + 18))):
        d.text(at, letter, style="italic")
    # dimensions first, so the labels placed after them keep clear of their lines and text
    dimension(d, (xa, 0), (0, 0), a.label("DA"), side=1, offset=34)
    dimension(d, (0, 0), (0, yb), b.label("DB"), side=1, offset=28)
    dimension(d, (0, 0), (0, ye), l.label("DE"), side=1, offset=28 + (0 if abs(ye - yb) < 1 else 150))
    d.place([((-12, yb + 5), "end"), ((-12, yb - 8), "end"), ((-22, yb + 18), "end")], "B", style="italic")
    d.place([((wall / 2, yb - 16), "middle"), ((wall / 2, yb + 26), "middle"), ((wall / 2 + 30, yb - 16), "middle")],
            need(variant, "K").label("K"))
    d.place([((22, ye + 38), "start"), ((-22, ye + 30), "end")], need(variant, "M").label("M"))
    d.place([((xa - 20, 70), "end"), ((xa + 20, 70), "start")], "piston " + need(variant, "m_p").value_text)
    return d.svg("Bell crank ADE with a pendulum mass, a spring and a dashpot")
