"""Free-vibration sketches drawn to each variant's data (course text chapter 6): pendulums, springs and
a mass, a disc on a shaft, a stepped shaft, a cantilever, and a mass on springs with a dashpot.

Lengths are drawn in proportion within each figure (a pendulum's cord, a shaft's steps and their
diameters), between bounds that keep every figure readable; labels print values as the sheet does.
"""
from __future__ import annotations

import math

from .flywheels import need
from .svg import LINE, THIN, Drawing, lerp
from .symbols import ball, block, dashpot, dimension, ground, spring
from .values import choice, shown


def _scaled(value: float, low: float, high: float, px_low: float, px_high: float) -> float:
    """A length drawn between px_low and px_high as value runs from low to high (clamped)."""
    t = min(1.0, max(0.0, (value - low) / (high - low)))
    return px_low + (px_high - px_low) * t


def simple_pendulum(variant) -> str:
    """A bob on a cord of the drawn length, swung a little from the vertical."""
    l, m = need(variant, "l"), need(variant, "m")
    length = _scaled(l.si, 0.2, 2.5, 90, 230)
    d = Drawing()
    top = (0.0, 0.0)
    ground(d, top, (1, 0), 70, side=1)
    swing = math.radians(18)
    bob = (top[0] + length * math.sin(swing), top[1] + length * math.cos(swing))
    d.line(top, (0, length + 10), THIN, dash="5 4", cls="vertical")
    d.line(top, bob, LINE, cls="cord")
    ball(d, bob, 11)
    d.path(f"M 0 40 A 40 40 0 0 0 {40 * math.sin(swing):.2f} {40 * math.cos(swing):.2f}", THIN, cls="angle")
    d.text((7, 58), "θ", style="italic")
    mid = lerp(top, bob, 0.55)
    d.place([((mid[0] + 10, mid[1]), "start"), ((mid[0] - 14, mid[1]), "end")], l.label("l"))
    d.place([((bob[0] + 18, bob[1] + 5), "start"), ((bob[0], bob[1] + 30), "middle")], m.label("m"))
    return d.svg("Simple pendulum")


def compound_pendulum(variant) -> str:
    """A connecting rod hanging from a knife edge in its small end, its centre of gravity h below."""
    h, k_g, m = need(variant, "h"), need(variant, "k_G"), need(variant, "m")
    scale = 230 / max(0.25, h.si * 1.8)
    small, big = 16.0, 30.0
    hp = h.si * scale
    length = hp * 1.6 + 10
    d = Drawing()
    eye = small - 5  # the knife edge bears on the top of the eye's bore, at the origin
    d.polygon([(0, 0), (-12, -18), (12, -18)], fill="white", width=LINE)
    ground(d, (0, -18), (1, 0), 50, side=1)
    d.circle((0, eye), small, LINE, cls="rod")
    d.circle((0, length), big, LINE, cls="rod")
    for s in (-1, 1):
        d.line((s * small * 0.6, eye + small * 0.8), (s * big * 0.5, length - big * 0.85), LINE, cls="rod")
    g = (0.0, hp)
    d.circle(g, 3, THIN, fill="black", cls="cg")
    dimension(d, (0, 0), g, h.label("h"), side=-1, offset=small + 30)
    web = small * 0.6 + (big * 0.5 - small * 0.6) * (hp - eye) / (length - eye)
    d.place([((web + 6, g[1] + 5), "start"), ((web + 6, g[1] + 20), "start")], "G", style="italic")
    d.place([((big + 16, length + 5), "start"), ((big + 16, length + 24), "start")], f"{k_g.label('k')} about G")
    d.place([((big + 16, length + 24), "start"), ((big + 16, length + 43), "start")], m.label("m"))
    d.place([((30, -4), "start"), ((30, 12), "start")], "knife edge", size=13, style="italic")
    return d.svg("Connecting rod on a knife edge")


def spring_mass(variant) -> str:
    """Two springs in series (one below the other) or in parallel (side by side) carrying a block."""
    k1, k2, m = need(variant, "K1"), need(variant, "K2"), need(variant, "m")
    series = choice(variant, "arrangement", "parallel") == "series"
    d = Drawing()
    ground(d, (0, 0), (1, 0), 120, side=1)
    if series:
        spring(d, (0, 0), (0, 80))
        d.line((-22, 80), (22, 80), LINE * 1.4, cls="plate")
        spring(d, (0, 80), (0, 160))
        block(d, (0, 185), 80, 50, m.label("m"))
        d.place([((18, 42), "start")], k1.label("K₁"))
        d.place([((18, 122), "start")], k2.label("K₂"))
    else:
        for x, k in ((-30, k1), (30, k2)):
            spring(d, (x, 0), (x, 110))
            d.place([((x + (16 if x > 0 else -16), 58), "start" if x > 0 else "end")],
                    k.label("K₁" if k is k1 else "K₂"))
        block(d, (0, 135), 110, 50, m.label("m"))
    return d.svg(f"Mass on two springs in {'series' if series else 'parallel'}")


def shaft_disc(variant) -> str:
    """A disc on the end of a shaft held rigidly at the far end, seen from the side."""
    big_d, small_d, l, m = need(variant, "D"), need(variant, "d"), need(variant, "l"), need(variant, "m")
    length = _scaled(l.si, 0.3, 2.0, 160, 360)
    thick = _scaled(small_d.si, 0.02, 0.1, 8, 22)
    disc = _scaled(big_d.si, 0.3, 1.5, 90, 200)
    d = Drawing()
    ground(d, (0, 0), (0, 1), disc * 0.9, side=1)
    d.polygon([(0, -thick / 2), (length, -thick / 2), (length, thick / 2), (0, thick / 2)], fill="#ececec", width=LINE)
    d.polygon([(length, -disc / 2), (length + 18, -disc / 2), (length + 18, disc / 2), (length, disc / 2)],
              fill="#d8d8d8", width=LINE)
    d.line((-6, 0), (length + 30, 0), THIN, dash="10 3 2 3", cls="axis")
    dimension(d, (0, thick / 2), (length, thick / 2), l.label("l"), side=-1, offset=disc / 2 - thick / 2 + 14)
    dimension(d, (length + 18, -disc / 2), (length + 18, disc / 2), big_d.label("D"), side=1, offset=22)
    d.place([((length * 0.45, -thick / 2 - 10), "middle"), ((length * 0.3, -thick / 2 - 10), "middle")],
            small_d.label("d"))
    d.place([((length + 9, -disc / 2 - 10), "middle")], m.label("m"))
    return d.svg("Disc on a shaft fixed at its far end")


def stepped_shaft(variant) -> str:
    """Flywheel at A, steps AB, BC, CD drawn to their lengths and diameters, the shaft held at D."""
    ls = [need(variant, n) for n in ("l1", "l2", "l3")]
    ds = [need(variant, n) for n in ("d1", "d2", "d3")]
    k = need(variant, "k")
    total = sum(x.si for x in ls)
    scale_x = 420 / total
    scale_d = 60 / max(x.si for x in ds)
    d = Drawing()
    wheel = _scaled(k.si, 0.3, 0.8, 110, 170)
    d.polygon([(-22, -wheel / 2), (0, -wheel / 2), (0, wheel / 2), (-22, wheel / 2)], fill="#d8d8d8", width=LINE)
    x = 0.0
    ends = [0.0]
    for length, diameter in zip(ls, ds):
        w, h = length.si * scale_x, diameter.si * scale_d
        d.polygon([(x, -h / 2), (x + w, -h / 2), (x + w, h / 2), (x, h / 2)], fill="#ececec", width=LINE)
        x += w
        ends.append(x)
    ground(d, (x, 0), (0, 1), 110, side=-1)
    d.line((-30, 0), (x + 6, 0), THIN, dash="10 3 2 3", cls="axis")
    half = max(x.si for x in ds) * scale_d / 2
    for letter, at in zip("ABCD", ends):
        y = half + 18
        d.place([((at + 9, y), "start"), ((at - 9, y), "end"), ((at + 9, y + 16), "start")], letter, style="italic")
    y_dim = half + 36
    subscript = str.maketrans("123", "₁₂₃")
    for i, (length, diameter) in enumerate(zip(ls, ds)):
        a, b = ends[i], ends[i + 1]
        d.line((a, half + 2), (a, y_dim + 4), THIN, cls="extension")
        d.line((b, half + 2), (b, y_dim + 4), THIN, cls="extension")
        d.dimension((a, y_dim), (b, y_dim))
    for i, (length, diameter) in enumerate(zip(ls, ds)):
        a, b = ends[i], ends[i + 1]
        mid = (a + b) / 2
        d.place([((mid, y_dim + 17), "middle"), ((mid, y_dim + 34), "middle"), ((mid, y_dim + 51), "middle")],
                length.label(f"l{i + 1}".translate(subscript)))
        top = -diameter.si * scale_d / 2
        d.place([((mid, top - 8), "middle"), ((mid, top - 26), "middle"), ((mid + 20, -wheel / 2 - 8), "start")],
                diameter.label(f"d{i + 1}".translate(subscript)))
    d.place([((-28, 5), "end"), ((-11, -wheel / 2 - 10), "middle")], "flywheel")
    return d.svg("Stepped shaft ABCD with a flywheel at A")


def cantilever(variant) -> str:
    """A cantilever shaft fixed in a wall with a disc on its free end; the two ways it vibrates."""
    dia, l, m = need(variant, "d"), need(variant, "l"), need(variant, "m")
    length = _scaled(l.si, 0.2, 0.6, 200, 380)
    thick = _scaled(dia.si, 0.03, 0.08, 10, 24)
    d = Drawing()
    ground(d, (0, 0), (0, 1), 140, side=1)
    d.polygon([(0, -thick / 2), (length, -thick / 2), (length, thick / 2), (0, thick / 2)], fill="#ececec", width=LINE)
    d.polygon([(length - 8, -55), (length + 8, -55), (length + 8, 55), (length - 8, 55)], fill="#d8d8d8", width=LINE)
    dimension(d, (0, thick / 2), (length, thick / 2), l.label("l"), side=-1, offset=72 - thick / 2)
    d.place([((length * 0.45, -thick / 2 - 10), "middle")], dia.label("d"))
    d.place([((length + 16, -62), "start"), ((length - 12, -66), "end")], m.label("m"))
    for tail, tip, text in (((length + 40, 20), (length + 90, 20), "longitudinal"),
                            ((length + 40, -5), (length + 40, -45), "transverse")):
        d.line(tail, tip, THIN, cls="motion")
        d.arrowhead(tip, (tip[0] - tail[0], tip[1] - tail[1]))
        d.arrowhead(tail, (tail[0] - tip[0], tail[1] - tip[1]))
    d.text((length + 96, 25), "longitudinal", anchor="start", size=13, style="italic")
    d.text((length + 50, -30), "transverse", anchor="start", size=13, style="italic")
    return d.svg("Cantilever shaft with a disc at its free end")


def _mounted_mass(d: Drawing, m_label: str, spring_labels: list[str], c_label: str, springs: int = 1) -> None:
    """A block on springs and a dashpot, standing on the ground."""
    width = 70 + 50 * max(springs, 1)
    ground(d, (0, 150), (1, 0), width + 30, side=-1)
    xs = [-width / 2 + 25 + i * 50 for i in range(springs)] + [width / 2 - 25]
    for i, x in enumerate(xs[:-1]):
        spring(d, (x, 150), (x, 60))
    dashpot(d, (xs[-1], 150), (xs[-1], 60))
    block(d, (0, 35), width, 50, m_label)
    d.place([((0, 178), "middle")], ", ".join(spring_labels))
    d.place([((xs[-1] + 18, 110), "start")], c_label)


def damped_spring_mass(variant) -> str:
    """A mass on a spring and a viscous damper."""
    m, k, c = need(variant, "m"), need(variant, "K"), need(variant, "C")
    d = Drawing()
    _mounted_mass(d, m.label("m"), [k.label("K")], c.label("C"))
    return d.svg("Mass, spring and damper")


def decaying_machine(variant) -> str:
    """A machine on n springs with a dashpot, and its decaying vibration: the first amplitude a₁, the
    amplitude a_r n cycles later, the exponential envelope through both and the cycles between them."""
    m, k, a1, ar = need(variant, "m"), need(variant, "K"), need(variant, "a1"), need(variant, "a_r")
    n_s = int(float(shown(variant, "n_s").si)) if shown(variant, "n_s") else 1
    n = int(float(shown(variant, "n").si))
    d = Drawing()
    springs = f"{n_s} springs, each {k.label('K')}" if n_s > 1 else f"spring {k.label('K')}"
    _mounted_mass(d, m.label("m"), [springs], "dashpot", n_s)
    decay_plot(d, (130 + 25 * n_s, 75), a1, ar, n)
    return d.svg("Machine on springs with a dashpot, and its decaying vibration")


def decay_plot(d: Drawing, origin, a1, ar, n: int, width: float = 280.0, height: float = 70.0) -> None:
    """x(t) decaying as e^(−ζω t): a₁ at the first peak, a_r at the peak n cycles on, with the envelope."""
    x0, y0 = origin
    cycles = n + 1.0
    per = width / (cycles + 0.25)
    decay = math.log(a1.si / ar.si) / n  # per cycle: the envelope falls by e^(−δ) each cycle
    d.line((x0, y0), (x0 + width + 14, y0), THIN, cls="axis")
    d.arrowhead((x0 + width + 14, y0), (1, 0))
    d.line((x0, y0 + height + 12), (x0, y0 - height - 14), THIN, cls="axis")
    d.arrowhead((x0, y0 - height - 14), (0, -1))
    d.text((x0 + width + 14, y0 + 18), "t", anchor="end", style="italic")
    d.text((x0 - 6, y0 - height - 14), "x", anchor="end", style="italic")
    start = per * 0.25
    points, envelope = [], []
    for i in range(int((width - start) / per * 40) + 1):
        s = i / 40
        env = height * math.exp(-decay * s)
        points.append((x0 + start + s * per, y0 - env * math.cos(2 * math.pi * s)))
        envelope.append((x0 + start + s * per, y0 - env))
    d.path("M " + " L ".join(f"{p[0]:.2f} {p[1]:.2f}" for p in points), LINE, cls="response")
    d.path("M " + " L ".join(f"{p[0]:.2f} {p[1]:.2f}" for p in envelope), THIN, dash="5 4", cls="envelope")
    first = (x0 + start, y0 - height)
    last = (x0 + start + n * per, y0 - height * math.exp(-decay * n))
    for peak in (first, last):
        d.line((peak[0], peak[1]), (peak[0], y0), THIN, dash="2 3", cls="ordinate")
    d.place([((first[0] + 8, first[1] - 4), "start"), ((first[0] + 8, first[1] + 16), "start")], a1.label("a₁"))
    d.place([((last[0] + 8, last[1] - 6), "start"), ((last[0] + 8, last[1] - 22), "start")],
            ar.label(f"a{n + 1}".translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))))
    y = y0 + height + 4
    d.dimension((first[0], y), (last[0], y))
    d.place([(((first[0] + last[0]) / 2, y + 16), "middle")], f"{n} cycle{'s' if n > 1 else ''}")


def damped_shaft_disc(variant) -> str:
    """The disc on its shaft from the side, and from the shaft's end with the dashpot on an arm at radius a,
    acting along the tangent there."""
    big_d, small_d, l, a = need(variant, "D"), need(variant, "d"), need(variant, "l"), need(variant, "a")
    m, c = need(variant, "m"), need(variant, "C")
    length = _scaled(l.si, 0.3, 1.5, 140, 260)
    thick = _scaled(small_d.si, 0.02, 0.06, 8, 18)
    disc = _scaled(big_d.si, 0.3, 0.8, 110, 180)
    d = Drawing()
    ground(d, (0, 0), (0, 1), disc * 0.9, side=1)
    d.polygon([(0, -thick / 2), (length, -thick / 2), (length, thick / 2), (0, thick / 2)], fill="#ececec", width=LINE)
    d.polygon([(length, -disc / 2), (length + 16, -disc / 2), (length + 16, disc / 2), (length, disc / 2)],
              fill="#d8d8d8", width=LINE)
    d.line((-6, 0), (length + 28, 0), THIN, dash="10 3 2 3", cls="axis")
    dimension(d, (0, thick / 2), (length, thick / 2), l.label("l"), side=-1, offset=disc / 2 - thick / 2 + 14)
    d.place([((length * 0.45, -thick / 2 - 10), "middle"), ((length * 0.3, -thick / 2 - 10), "middle")],
            small_d.label("d"))
    d.place([((length + 8, -disc / 2 - 10), "middle")], m.label("m"))
    # the end view: the disc, the shaft's end at its centre, the arm to radius a and the dashpot on its tangent
    centre = (length + 125 + disc / 2, 0.0)
    d.circle(centre, disc / 2, LINE, fill="#d8d8d8")
    d.circle(centre, thick / 2, THIN, fill="#ececec")
    arm = disc / 2 * min(1.0, a.si / (big_d.si / 2))
    point = (centre[0], centre[1] - arm)
    d.line(centre, point, LINE, cls="arm")
    d.circle(point, 3, THIN, fill="white")
    dimension(d, centre, point, a.label("a"), side=1, offset=disc / 2 + 16)
    far = (centre[0] + disc / 2 + 58, point[1])
    dashpot(d, far, point)
    ground(d, far, (0, 1), 40, side=1)
    d.place([((far[0] + 14, point[1] + 5), "start"), ((far[0] + 14, point[1] - 26), "start")], c.label("C"))
    dimension(d, (centre[0] - disc / 2, centre[1] + disc / 2), (centre[0] + disc / 2, centre[1] + disc / 2),
              big_d.label("D"), side=-1, offset=14)
    return d.svg("Disc on a shaft fixed at its far end, and its end view with a dashpot on an arm")
