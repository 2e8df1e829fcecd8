"""Key-only figures for balancing (course text §2.1-2.3): the couple and force polygons the working
closes, drawn to scale, and the primary and secondary crank diagrams of in-line engines.

Vectors are drawn head to tail in the sheet's own angle convention, so each side is parallel to its
mass in the sheet's end view; the closing side, from the last head back to the start, is the
correction the working finds, labelled with its value. Each polygon has its own scale bar.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from .. import units
from .balancing import _si
from .shafts import Convention, Spoke, end_view
from .svg import FONT_SIZE, LINE, NOTE_SIZE, THIN, Drawing
from .values import shown

PANEL = 210.0         # px: the largest extent of a polygon
PANEL_GAP = 90.0      # px between two panels
FROM_VERTICAL = Convention(-math.pi / 2, True)      # §2.2 and the engines: clockwise from the vertical
FROM_REFERENCE = Convention(0.0, False)             # counter-clockwise from a named mass
UNITS = {"kg*m": "kg·m", "kg*m^2": "kg·m²", "N": "N", "N*m": "N·m"}


@dataclass(frozen=True)
class Side:
    """One vector of a polygon: its label, signed size (SI) and angle (radians, the sheet's convention)."""

    name: str
    size: float
    angle: float


def side(variant, name: str, size: str, angle: str | None, factor: str | None = None) -> Side:
    """A side from the variant's values: `size` (times `factor`) at `angle` (None: on the 0° line)."""
    value = _si(variant, size) * (_si(variant, factor) if factor else 1.0)
    return Side(name, value, 0.0 if angle is None else _si(variant, angle))


def _nice(value: float) -> float:
    """1, 2 or 5 times a power of ten, at most `value`."""
    exponent = math.floor(math.log10(value))
    return max(m * 10.0 ** e for e in (exponent - 1, exponent) for m in (1, 2, 5) if m * 10.0 ** e <= value * (1 + 1e-9))


def polygon(d: Drawing, x0: float, sides: list[Side], closing: Side, unit: str, conv: Convention) -> tuple[float, float]:
    """A vector polygon with its left edge at x0, the sides head to tail and the closing side back to the
    start, heavier and labelled with its value. Returns (px per unit, the polygon's extent in units)."""
    screen = [(s.size * math.cos(conv.screen(s.angle)), s.size * math.sin(conv.screen(s.angle))) for s in sides]
    points = [(0.0, 0.0)]
    for dx, dy in screen:
        points.append((points[-1][0] + dx, points[-1][1] + dy))
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    extent = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    scale = PANEL / extent
    origin = (x0 - min(xs) * scale, -PANEL / 2 - min(ys) * scale)
    at = [(origin[0] + x * scale, origin[1] + y * scale) for x, y in points]
    for i, s in enumerate(sides):
        _vector(d, at[i], at[i + 1], LINE, f"side side-{s.name}")
    _vector(d, at[-1], at[0], 2.6, "closing")
    d.circle(at[0], 2.5, THIN, fill="black")
    value = f"{closing.name} = {units.format_number(abs(closing.size), 4)} {UNITS.get(unit, unit)}"
    _side_label(d, at[-1], at[0], value, weight="bold")
    for i, s in enumerate(sides):
        _side_label(d, at[i], at[i + 1], s.name)
    return scale, extent


def _scale_bar(d: Drawing, x0: float, y: float, scale: float, extent: float, unit: str, title: str) -> None:
    """A bar of a round length in the polygon's units, and the polygon's title beneath."""
    bar = _nice(extent / 3)
    d.line((x0, y), (x0 + bar * scale, y), 1.6, cls="scale-bar")
    for x in (x0, x0 + bar * scale):
        d.line((x, y - 4), (x, y + 4), THIN)
    d.text((x0 + bar * scale + 8, y + 5), f"{bar:g} {UNITS.get(unit, unit)}", anchor="start", size=NOTE_SIZE)
    d.text((x0 + PANEL / 2, y + 28), title, size=NOTE_SIZE, style="italic")


def _vector(d: Drawing, a, b, width: float, cls: str) -> None:
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    if length < 1e-6:
        return
    d.line(a, b, width, cls=cls)
    head = min(9.0, 0.4 * length)
    d.arrowhead(b, (b[0] - a[0], b[1] - a[1]), head)


def _side_label(d: Drawing, a, b, text: str, weight: str = "") -> None:
    """A side's label beside it, nearest its middle on whichever side is clear."""
    length = math.hypot(b[0] - a[0], b[1] - a[1]) or 1.0
    nx, ny = -(b[1] - a[1]) / length, (b[0] - a[0]) / length
    candidates = []
    for away in (8.0, 16.0, 28.0, 42.0, 60.0, 80.0):
        for share in (0.5, 0.35, 0.65, 0.2, 0.8):
            mx, my = a[0] + (b[0] - a[0]) * share, a[1] + (b[1] - a[1]) * share
            for sign in (1, -1):
                ux, uy = sign * nx, sign * ny
                anchor = "start" if ux > 0.3 else "end" if ux < -0.3 else "middle"
                # the text's baseline sits so that its box, not its anchor point, keeps the distance
                y = my + uy * away + (0.75 * FONT_SIZE if uy > 0.3 else 0.3 * FONT_SIZE if uy > -0.3 else 0.0)
                candidates.append(((mx + ux * away, y), anchor))
    d.place(candidates, text, weight=weight, cls="side-label")


def panels(title: str, *drawn) -> str:
    """Polygons side by side, each item (sides, closing, unit, title, convention); their scale bars and
    titles in a row beneath them all."""
    d = Drawing()
    x, placed = 0.0, []
    for sides, closing, unit, caption, conv in drawn:
        scale, extent = polygon(d, x, sides, closing, unit, conv)
        placed.append((x, scale, extent, unit, caption))
        x = max(d.box[2], x + PANEL) + PANEL_GAP
    y = d.box[3] + 22
    for x0, scale, extent, unit, caption in placed:
        _scale_bar(d, x0, y, scale, extent, unit, caption)
    return d.svg(title)


# ---- rotating masses --------------------------------------------------------------------------------

def static_polygon(variant) -> str:
    """Example 2.1: the force polygon of m·r; B·b closes it."""
    sides = [side(variant, "1", "mr1", None), side(variant, "2", "mr2", "theta2"), side(variant, "3", "mr3", "theta3")]
    return panels("Force polygon: B·b closes it", (sides, side(variant, "B·b", "Bb", "theta_b"), "kg*m",
                                                  "force polygon (m·r)", FROM_REFERENCE))


def two_plane_polygons(variant) -> str:
    """Examples 2.2, 2.5: the couple polygon about P closed by Q, then the force polygon closed by P."""
    couple = [side(variant, str(i), f"mrl{i}", f"theta{i}") for i in (1, 2, 3)]
    force = [side(variant, str(i), f"mr{i}", f"theta{i}") for i in (1, 2, 3)] + [side(variant, "Q", "mrQ", "theta_Q")]
    return panels("Couple polygon about P, closed by Q; force polygon, closed by P",
                  (couple, side(variant, "Q", "mrQ", "theta_Q", "lQ"), "kg*m^2", "couple polygon about P (m·r·l)",
                   FROM_VERTICAL),
                  (force, side(variant, "P", "mP", "theta_P", "rP"), "kg*m", "force polygon (m·r)", FROM_VERTICAL))


def position_polygons(variant) -> str:
    """Example 2.3: the couple polygon about B closed by D, then the force polygon closed by B."""
    couple = [side(variant, "A", "mrlA", "thetaA"), side(variant, "C", "mrlC", None)]
    force = [side(variant, "A", "mrA", "thetaA"), side(variant, "C", "mrC", None), side(variant, "D", "mrD", "theta_D")]
    return panels("Couple polygon about B, closed by D; force polygon, closed by B",
                  (couple, side(variant, "D", "mrlD", "theta_D"), "kg*m^2", "couple polygon about B (m·r·l)",
                   FROM_REFERENCE),
                  (force, side(variant, "B", "mrB", "theta_B"), "kg*m", "force polygon (m·r)", FROM_REFERENCE))


def masses_polygons(variant) -> str:
    """Problem 2.2: the couple polygon about A closed by D; the force polygon closed by A and D together."""
    couple = [side(variant, "B", "mrlB", None), side(variant, "C", "mrlC", "thetaC")]
    force = [side(variant, "B", "mrB", None), side(variant, "C", "mrC", "thetaC"), side(variant, "D", "mrD", "theta_D")]
    return panels("Couple polygon about A, closed by D; force polygon, closed by A",
                  (couple, side(variant, "D", "mrlD", "theta_D"), "kg*m^2", "couple polygon about A (m·r·l)",
                   FROM_REFERENCE),
                  (force, side(variant, "A", "mrA", "thetaA"), "kg*m", "force polygon (m·r)", FROM_REFERENCE))


def bearing_polygons(variant) -> str:
    """Example 2.4: the couple polygon about X closed by Y's reaction, then the force polygon closed by X's."""
    names = [("A", None), ("B", "thetaB"), ("C", "thetaC")]
    couple = [side(variant, n, f"mrl{n}", a) for n, a in names]
    force = [side(variant, n, f"mr{n}", a) for n, a in names] + [side(variant, "Y", "RY", "theta_RY")]
    return panels("Couple polygon about X, closed by Y; force polygon, closed by X",
                  (couple, side(variant, "Y", "RY", "theta_RY", "lY"), "kg*m^2", "couple polygon about X (m·r·l)",
                   FROM_REFERENCE),
                  (force, side(variant, "X", "RX", "theta_RX"), "kg*m", "force polygon (m·r)", FROM_REFERENCE))


def primary_polygons(variant) -> str:
    """Problem 2.1: the primary couple polygon about B closed by C, then the force polygon closed by B."""
    couple = [side(variant, "A", "mrlA", None), side(variant, "D", "mrlD", "phi")]
    force = [side(variant, "A", "mrA", None), side(variant, "C", "mrC", "theta_C"), side(variant, "D", "mrD", "phi")]
    return panels("Primary couple polygon about B, closed by C; force polygon, closed by B",
                  (couple, side(variant, "C", "mrlC", "theta_C"), "kg*m^2", "couple polygon about B (m·r·l)",
                   FROM_VERTICAL),
                  (force, side(variant, "B", "mB", "theta_B", "r"), "kg*m", "force polygon (m·r)", FROM_VERTICAL))


# ---- in-line engines: where the cranks are, and where their secondary images are --------------------

def crank_diagrams(variant) -> str:
    """Examples 2.6, 2.7: the primary crank diagram (cranks at θ) beside the secondary one (at 2θ);
    cranks that coincide share a spoke and a label."""
    count = next(i for i in itertools.count(1) if shown(variant, f"theta{i}") is None) - 1
    angles = [_si(variant, f"theta{i}") for i in range(1, count + 1)]  # given, or found by the working
    d = Drawing()
    x = 0.0
    for harmonic, caption in ((1, "primary cranks (θ)"), (2, "secondary cranks (2θ)")):
        groups: dict[int, list[str]] = {}
        for i, a in enumerate(angles, start=1):
            key = round(math.degrees(harmonic * a)) % 360
            groups.setdefault(key, []).append(str(i))
        spokes = [Spoke(",".join(names), f"{', '.join(names)}: {deg}°", 1.0, math.radians(deg))
                  for deg, names in sorted(groups.items())]
        centre = (x + 70 + 40, 0.0)
        end_view(d, centre, spokes, FROM_VERTICAL_LINE, caption)
        x = d.box[2] + 60
    return d.svg("Crank diagrams: primary cranks at their angles, secondary cranks at twice their angles")


FROM_VERTICAL_LINE = Convention(-math.pi / 2, True, "0°")


def _engine_sides(variant, harmonic: int, couple: bool) -> list[Side]:
    """Example 2.6's sides: each crank's force (m r ω², or over n for the secondary) at kθ, times its signed
    distance x from the centre plane for a couple."""
    pitch = _si(variant, "a")
    size = _si(variant, "F1" if harmonic == 1 else "F2")
    sides = []
    for i in range(1, 5):
        x = (i - 2.5) * pitch
        sides.append(Side(str(i), size * (x if couple else 1.0), harmonic * _si(variant, f"theta{i}")))
    return sides


def engine_primary_polygons(variant) -> str:
    """Example 2.6: the primary force polygon and the primary couple polygon about the centre plane, each
    closed by the force or couple that balances it."""
    return panels("Primary force and couple polygons, each closed by what balances it",
                  (_engine_sides(variant, 1, False), side(variant, "Fp", "Fp", "theta_Fp"), "N",
                   "primary forces, at θ", FROM_VERTICAL),
                  (_engine_sides(variant, 1, True), side(variant, "Cp", "Cp", "theta_Cp"), "N*m",
                   "primary couples, x from the centre", FROM_VERTICAL))


def engine_secondary_polygons(variant) -> str:
    """Example 2.6: the secondary polygons, cranks at 2θ, each side m r ω²/n."""
    return panels("Secondary force and couple polygons (cranks at 2θ), each closed by what balances it",
                  (_engine_sides(variant, 2, False), side(variant, "Fs", "Fs", "theta_Fs"), "N",
                   "secondary forces, at 2θ", FROM_VERTICAL),
                  (_engine_sides(variant, 2, True), side(variant, "Cs", "Cs", "theta_Cs"), "N*m",
                   "secondary couples, at 2θ", FROM_VERTICAL))
