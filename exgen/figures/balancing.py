"""Balancing figures for rotating masses (course text §2.1-2.2): a side view of the shaft with its
planes and distances (the reference plane marked), and an end view with the masses at their
angles and the sheet's angle convention. Values are printed as on the sheet; unknowns are "?".
"""
from __future__ import annotations

import math

from .shafts import (MIN_WIDTH, OUTLINE, SHAFT_H, Convention, Plane, Spoke, chain, end_view, fit_width, ordinates,
                     side_view)
from .svg import NOTE_SIZE, Drawing
from .values import shown

GAP = 70.0            # between the side view and the end view
DIM_ROW = 52.0        # the dimension row, below the shaft axis
FROM_RIGHT = "0° (along {name})"


def _value(variant, name: str) -> str:
    found = shown(variant, name)
    return found.value_text if found is not None else "?"


def _si(variant, name: str) -> float:
    found = shown(variant, name)
    return found.si if found is not None else float("nan")


def _mass_spoke(variant, tag: str, mass: str, radius: str, angle: str | None) -> Spoke:
    """A mass at its radius (the arm's length) and angle; `angle` None puts it on the 0° line."""
    size, weight = _si(variant, radius), _si(variant, mass)
    theta = 0.0 if angle is None else _si(variant, angle)
    shown_angle = "0°" if angle is None else _value(variant, angle)
    return Spoke(tag, f"{tag}: {shown_angle}", size, theta, weight if math.isfinite(weight) and weight > 0 else 0.0)


def _place_end_view(d: Drawing, spokes, conv: Convention, note: str = "") -> None:
    centre = (d.box[2] + GAP + OUTLINE, 0.0)
    end_view(d, centre, spokes, conv, note)


def static_disc(variant) -> str:
    """Example 2.1: the disc with its masses at their angles from mass 1; the balancing mass unknown."""
    d = Drawing()
    spokes = [_mass_spoke(variant, "1", "m1", "r1", None)]
    spokes += [_mass_spoke(variant, str(i), f"m{i}", f"r{i}", f"theta{i}") for i in (2, 3)]
    spokes.append(Spoke("B", f"B at b = {_value(variant, 'b')}: ?", 1.0, None))
    end_view(d, (0.0, 0.0), spokes, Convention(0.0, False, FROM_RIGHT.format(name="mass 1")))
    fit_width(d, MIN_WIDTH)
    return d.svg("Disc with three masses, seen along its axis; angles counter-clockwise from mass 1")


def shaft_two_planes(variant) -> str:
    """Examples 2.2, 2.5: three masses, correction planes P (reference) and Q; positions from the left end."""
    planes = [Plane(str(i), _si(variant, f"z{i}"), "mass",
                    (str(i), _value(variant, f"m{i}"), _value(variant, f"r{i}"))) for i in (1, 2, 3)]
    planes += [Plane("P", _si(variant, "zP"), "correction", ("P (ref.)", f"r = {_value(variant, 'rP')}", "m = ?")),
               Plane("Q", _si(variant, "zQ"), "correction", ("Q", f"r = {_value(variant, 'rQ')}", "m = ?"))]
    d = Drawing()
    x_of = side_view(d, planes, ends=(0.0, max(p.z for p in planes) + 0.15))
    ordinates(d, x_of, [(p.z, _value(variant, "z" + p.name)) for p in planes])
    d.text((x_of(0.0), d.box[3] + 18), "positions from the left end", anchor="start", size=NOTE_SIZE, style="italic")
    spokes = [_mass_spoke(variant, str(i), f"m{i}", f"r{i}", f"theta{i}") for i in (1, 2, 3)]
    spokes += [Spoke("P", "P: angle ?", 1.0, None), Spoke("Q", "Q: angle ?", 1.0, None)]
    _place_end_view(d, spokes, Convention(-math.pi / 2, True, "0°"), "seen from the left end")
    return d.svg("Shaft with three masses and correction planes P and Q; positions from the left end, "
                 "angles clockwise from the vertical")


def shaft_correction_position(variant) -> str:
    """Example 2.2: three masses and the correction plane X at the left end; the correction B₁, whose plane
    is the unknown, appears only in the end view (drawn anywhere on the shaft, it would give x away)."""
    planes = [Plane(str(i), _si(variant, f"z{i}"), "mass",
                    (str(i), _value(variant, f"m{i}"), _value(variant, f"r{i}"))) for i in (1, 2, 3)]
    planes.append(Plane("X", 0.0, "correction", ("X (ref.)", f"r = {_value(variant, 'bX')}", "m = ?")))
    d = Drawing()
    x_of = side_view(d, planes, ends=(0.0, max(p.z for p in planes) + 0.15))
    ordinates(d, x_of, [(_si(variant, f"z{i}"), _value(variant, f"z{i}")) for i in (1, 2, 3)])
    d.text((x_of(0.0), d.box[3] + 18), f"distances from X; B₁ = {_value(variant, 'B1')} at "
           f"r = {_value(variant, 'b1')}, its plane x = ? from X", anchor="start", size=13, style="italic")
    spokes = [_mass_spoke(variant, str(i), f"m{i}", f"r{i}", f"theta{i}") for i in (1, 2, 3)]
    spokes += [Spoke("B₁", "B₁: angle ?", 1.0, None), Spoke("X", "X: angle ?", 1.0, None)]
    _place_end_view(d, spokes, Convention(-math.pi / 2, True, "0°"), "seen from the left end")
    return d.svg("Shaft with three masses, a correction B₁ in a plane x from X, and a correction in X; "
                 "angles clockwise from the vertical")


def shaft_position(variant) -> str:
    """Example 2.3: A, B, C, D with D's plane unknown (drawn dashed, not to scale); reference plane B."""
    l_ab, l_bc = _si(variant, "lAB"), _si(variant, "lBC")
    planes = [Plane("A", 0.0, "mass", ("A", _value(variant, "mA"), _value(variant, "rA"))),
              Plane("B", l_ab, "mass", ("B (ref.)", "m = ?", _value(variant, "rB"))),
              Plane("C", l_ab + l_bc, "mass", ("C", _value(variant, "mC"), _value(variant, "rC"))),
              Plane("D", l_ab + 1.6 * l_bc, "mass", ("D", _value(variant, "mD"), _value(variant, "rD")),
                    unknown_position=True)]
    d = Drawing()
    x_of = side_view(d, planes)
    chain(d, x_of, [(0.0, l_ab, _value(variant, "lAB")), (l_ab, l_ab + l_bc, _value(variant, "lBC")),
                    (l_ab + l_bc, l_ab + 1.6 * l_bc, "x = ?")], DIM_ROW)
    spokes = [_mass_spoke(variant, "C", "mC", "rC", None), _mass_spoke(variant, "A", "mA", "rA", "thetaA"),
              Spoke("B", "B: angle ?", 1.0, None), Spoke("D", "D: angle ?", 1.0, None)]
    _place_end_view(d, spokes, Convention(0.0, False, FROM_RIGHT.format(name="C")), "seen from the end at A")
    return d.svg("Shaft with masses A, B, C and D; D's plane not to scale")


def shaft_masses(variant) -> str:
    """Problem 2.2: A, B, C, D with the masses at A and D and D's plane unknown; reference plane A."""
    l_ab, l_bc = _si(variant, "lAB"), _si(variant, "lBC")
    r_ad = _value(variant, "rAD")
    planes = [Plane("A", 0.0, "mass", ("A (ref.)", "m = ?", r_ad)),
              Plane("B", l_ab, "mass", ("B", _value(variant, "mB"), _value(variant, "rBC"))),
              Plane("C", l_ab + l_bc, "mass", ("C", _value(variant, "mC"), _value(variant, "rBC"))),
              Plane("D", l_ab + 1.6 * l_bc, "mass", ("D", "m = ?", r_ad), unknown_position=True)]
    d = Drawing()
    x_of = side_view(d, planes)
    chain(d, x_of, [(0.0, l_ab, _value(variant, "lAB")), (l_ab, l_ab + l_bc, _value(variant, "lBC"))], DIM_ROW)
    chain(d, x_of, [(0.0, l_ab + 1.6 * l_bc, "A to D = ?")], DIM_ROW + 30, top=DIM_ROW + 6)
    spokes = [_mass_spoke(variant, "B", "mB", "rBC", None), _mass_spoke(variant, "C", "mC", "rBC", "thetaC"),
              Spoke("A", f"A: {_value(variant, 'thetaA')}", _si(variant, "rAD"), _si(variant, "thetaA")),
              Spoke("D", "D: angle ?", 1.0, None)]
    _place_end_view(d, spokes, Convention(0.0, False, FROM_RIGHT.format(name="B")), "seen from the end at A")
    return d.svg("Shaft with masses A, B, C and D; D's plane not to scale")


def shaft_bearings(variant) -> str:
    """Example 2.4: masses A, B, C and bearings X (reference) and Y, in the order A X B Y C."""
    gaps = [_si(variant, k) for k in ("a", "b", "c", "e")]
    z = [sum(gaps[:i]) for i in range(5)]
    planes = [Plane("A", z[0], "mass", ("A", _value(variant, "mA"), _value(variant, "rA"))),
              Plane("X", z[1], "bearing", ("X (ref.)",)),
              Plane("B", z[2], "mass", ("B", _value(variant, "mB"), _value(variant, "rB"))),
              Plane("Y", z[3], "bearing", ("Y",)),
              Plane("C", z[4], "mass", ("C", _value(variant, "mC"), _value(variant, "rC")))]
    d = Drawing()
    x_of = side_view(d, planes)
    chain(d, x_of, [(z[i], z[i + 1], _value(variant, k)) for i, k in enumerate(("a", "b", "c", "e"))],
          DIM_ROW + 12, top=SHAFT_H + 24)
    d.text((x_of(z[4]) + 34, -4), f"{_value(variant, 'N')}", anchor="start", size=NOTE_SIZE, style="italic")
    spokes = [_mass_spoke(variant, "A", "mA", "rA", None), _mass_spoke(variant, "B", "mB", "rB", "thetaB"),
              _mass_spoke(variant, "C", "mC", "rC", "thetaC")]
    _place_end_view(d, spokes, Convention(0.0, False, FROM_RIGHT.format(name="A")), "seen from the end at A")
    return d.svg("Shaft with masses A, B, C in bearings X and Y")


def shaft_four_masses(variant) -> str:
    """§2.1: four masses in planes A to D an equal distance apart; masses at one angle share a spoke."""
    pitch = _si(variant, "a")
    planes = [Plane(tag, k * pitch, "mass", (tag + (" (ref.)" if tag == "A" else ""),
                                             _value(variant, "mD" if tag == "D" else "m")))
              for k, tag in enumerate("ABCD")]
    d = Drawing()
    x_of = side_view(d, planes)
    chain(d, x_of, [(k * pitch, (k + 1) * pitch, _value(variant, "a")) for k in range(3)], DIM_ROW)
    groups: dict[int, list[str]] = {}
    for tag in "ABCD":
        groups.setdefault(round(math.degrees(variant.step(f"theta{tag}").value)) % 360, []).append(tag)
    spokes = [Spoke(",".join(tags), f"{', '.join(tags)}: {deg}°", 1.0, math.radians(deg)) for deg, tags in
              sorted(groups.items())]
    _place_end_view(d, spokes, Convention(0.0, False, "reference line"), f"all at r = {_value(variant, 'r')}")
    return d.svg("Shaft with four masses in planes A to D; angles from a reference line in the direction of rotation")
