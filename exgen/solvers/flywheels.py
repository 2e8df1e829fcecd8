"""Worked derivations for turning-moment diagrams (course text chapter 3, Examples 3.1-3.2, Problem 3.1).

The text's method: call the energy at the first crossing of the torque curve and the mean line
U (here 0), add each loop above the line and take away each loop below it, crossing by
crossing; the greatest and least energies are where the speed is greatest and least, and
their difference, scaled by what one mm² of the diagram stands for, is the maximum
fluctuation of energy ΔE = I ω² C_s (eq 3.5).
"""
from __future__ import annotations

import math
import string
from itertools import accumulate

from ..mechanics import flywheels as fw
from ..mechanics import grid_loops

MM2 = 1e-6


def _loop_areas(p, count: int) -> list[float]:
    """The loop areas in mm², signed: above the mean line positive."""
    areas = [round(getattr(p, f"a{i}") / MM2, 9) for i in range(1, count + 1)]
    return fw.alternate(areas, first_above=(p.first == "above"))


def _crossings(p, d, count: int, name_extremes: bool) -> tuple[float, float]:
    """Energy at each crossing (mm² of diagram, from E_A = 0), and where it is greatest and least.

    Returns ΔA, greatest less least, and the largest single loop (a known slip takes it for ΔA).
    When a part asks where the speed is greatest or least, no two crossings may nearly tie.
    """
    return _levels(d, _loop_areas(p, count), name_extremes, "mm^2", "mm² of the diagram")


def _levels(d, signed: list[float], name_extremes: bool, unit: str, measure: str,
            note: str = "greatest less least energy, in mm² of diagram") -> tuple[float, float]:
    """The crossings' energies from signed loop areas in `unit` (see _crossings)."""
    count = len(signed)
    levels = fw.crossing_energies(signed)
    letters = string.ascii_uppercase[: count + 1]
    for letter, level in zip(letters, levels):
        d.step(f"E_{letter}", level, unit)
    d.table(f"Energy at each crossing, in {measure}, the energy at A taken as U = 0: each loop above "
            "the mean line adds its area, each loop below takes it away; over the cycle they balance",
            [("Crossing",), ("Loop before it", unit), ("Energy above U", unit)],
            [[letter, signed[i - 1] if i else None, f"@E_{letter}"] for i, letter in enumerate(letters)])
    swing, high, low = fw.fluctuation_from_areas(signed)
    if name_extremes:
        ranked = sorted(levels[:-1], reverse=True)
        d.require(ranked[0] - ranked[1] >= 0.02 * swing and ranked[-2] - ranked[-1] >= 0.02 * swing,
                  "two crossings nearly tie for the greatest or least energy")
        d.step("fastest", letters[high], "", symbol=r"\text{crossing of }\omega_{\max}", note="the greatest energy")
        d.step("slowest", letters[low], "", symbol=r"\text{crossing of }\omega_{\min}", note="the least energy")
        d.mistake("fastest", "least_for_greatest", letters[low])
        d.mistake("slowest", "least_for_greatest", letters[high])
    dA = d.step("dA", swing, unit, symbol=r"\Delta A", formula=rf"@E_{letters[high]} - @E_{letters[low]}",
                note=note)
    return dA, max(abs(a) for a in signed)


def _energy(p, d, dA: float, largest: float, per: str = "J/mm^2",
            note: str = "one mm² of the diagram: torque per mm × radians per mm") -> float:
    """ΔE in joules from ΔA in mm² (or in squares of a grid, `per` "J"), with the slips of the scales."""
    e = d.step("e", fw.energy_per_area(p.Ts, p.As), per, symbol=r"e", formula=r"@Ts\,@As", note=note)
    delta_e = d.step("dE", dA * e, "J", symbol=r"\Delta E", formula=r"@dA\,@e")
    d.mistake("dE", "one_scale_only", dA * p.Ts)
    d.mistake("dE", "angle_scale_in_degrees", dA * p.Ts * math.degrees(p.As))
    d.mistake("dE", "largest_loop", largest * e, if_apart=True)
    return delta_e


def speed_fluctuation(p, d):
    """Example 3.1: energies at the crossings, ΔE, and the coefficient of fluctuation of speed."""
    dA, largest = _crossings(p, d, 6, name_extremes=True)
    delta_e = _energy(p, d, dA, largest)
    inertia = d.step("I", p.m * p.k ** 2, "kg*m^2", formula=r"@m\,@k^2")
    cs = d.step("Cs", fw.coefficient_of_fluctuation(delta_e, inertia, p.N), "", symbol=r"C_s",
                formula=r"\frac{@dE}{@I\,@N^2}", note="eq 3.5: the total band (ω₁ − ω₂)/ω")
    d.mistake("Cs", "rpm_as_rad_s", delta_e / (inertia * (p.N * 60 / (2 * math.pi)) ** 2))
    d.mistake("Cs", "half_band", cs / 2)
    d.mistake("Cs", "k_not_squared", delta_e / (p.m * p.k * p.N ** 2))


#: Densities from which a rim is cast steel (7800 kg/m³) rather than cast iron (7000-7250 kg/m³).
CAST_STEEL = 7500.0


def flywheel_rim(p, d):
    """Problem 3.1: ΔE from nine loops; the rim mass for a speed band; its rectangular section."""
    dA, largest = _crossings(p, d, 9, name_extremes=False)
    _rim(p, d, _energy(p, d, dA, largest))


def _rim(p, d, delta_e: float) -> None:
    """The rim for ΔE (Problem 3.1): its inertia for the speed band, mass, section and rim speed."""
    inertia = d.step("I", fw.inertia_for(delta_e, p.N, p.Cs), "kg*m^2", formula=r"\frac{@dE}{@N^2\,@Cs}",
                     note="eq 3.5 solved for I")
    radius = d.step("R", p.D / 2, "m", formula=r"\frac{@D}{2}", note="the rim's mean radius")
    mass = d.step("m", fw.rim_mass(inertia, radius), "kg", formula=r"\frac{@I}{@R^2}",
                  note="the rim's mass all at the mean radius; the arms are neglected")
    d.mistake("m", "rpm_as_rad_s", delta_e / ((p.N * 60 / (2 * math.pi)) ** 2 * p.Cs) / radius ** 2)
    d.mistake("m", "diameter_for_radius", inertia / p.D ** 2)
    d.mistake("m", "total_read_as_plus_minus", inertia / 2 / radius ** 2)
    area = d.step("A", fw.rim_area(mass, p.rho, radius), "m^2", formula=r"\frac{@m}{@rho\,2\pi\,@R}",
                  note="mass = density × mean circumference × section")
    thickness = d.step("t", fw.rim_thickness(area, p.ratio), "m", formula=r"\sqrt{\frac{@A}{@ratio}}",
                       note="the section is b × t with b = k t")
    d.mistake("t", "square_section", fw.rim_thickness(area, 1.0))
    d.mistake("t", "ratio_inverted", fw.rim_thickness(area, 1 / p.ratio))
    d.step("b", p.ratio * thickness, "m", formula=r"@ratio\,@t")
    d.mistake("b", "square_section", fw.rim_thickness(area, 1.0))
    d.mistake("b", "ratio_inverted", thickness / p.ratio)
    d.step("v", p.N * radius, "m/s", symbol=r"v_{\mathrm{rim}}", formula=r"@N\,@R",
           note="the rim's speed at its mean radius: " + ("within cast iron's 35 m/s; a cast-steel rim stands more"
                 if p.rho >= CAST_STEEL else "a cast-iron rim is kept under about 35 m/s"))


# ---- Problem 3.1 with its diagram read off a grid ---------------------------------------------

#: Squares a loop may stand from the mean line, so that the grid stays readable on a sheet.
TALLEST_LOOP = 12


def loop_area_reading(p, d):
    """Problem 3.1 with the loops drawn on a grid: each loop's area read by counting squares, then ΔE as
    the swing of the crossings' energies in squares × what one square stands for, then the rim."""
    count = 9
    areas = [getattr(p, f"a{i}") for i in range(1, count + 1)]
    columns = round(p.columns)
    d.require(all(a == round(a) and a >= 1 for a in areas), "a loop is not a whole number of squares")
    d.require(columns >= grid_loops.LEAST_WIDTH * count, "too few columns for the loops")
    widths = grid_loops.widths(areas, max(columns, grid_loops.LEAST_WIDTH * count))
    d.require(all(a >= w - 1 for a, w in zip(areas, widths)), "a loop too small to span its columns")
    profiles = [grid_loops.heights(max(round(a), w - 1), w) for a, w in zip(areas, widths)]
    d.require(max(max(h) for h in profiles) <= TALLEST_LOOP, "a loop too tall for the grid")
    above = p.first == "above"
    sides = ["above" if above == (i % 2 == 0) else "below" for i in range(count)]
    counted = [d.step(f"n{i + 1}", grid_loops.squares(h), "", symbol=rf"n_{{{i + 1}}}",
                      note=f"loop {i + 1}, {sides[i]} the mean line") for i, h in enumerate(profiles)]
    d.table("The loops read off the grid: the curve goes straight from grid crossing to grid crossing, so at "
            "each vertical grid line inside a loop it stands a whole number of squares from the mean line; "
            "each column is a trapezium of half the sum of its sides, and a loop's area is the sum of its "
            "heights (whole squares and the halves cut by the sloping sides)",
            [("Loop",), ("Side of the mean line",), ("Heights at the grid lines inside it, squares",),
             ("Area, squares",)],
            [[str(i + 1), sides[i], " + ".join(map(str, h)), f"@n{i + 1}"] for i, h in enumerate(profiles)])
    signed = fw.alternate(counted, first_above=above)
    dA, largest = _levels(d, signed, False, "", "squares of the grid",
                          note="greatest less least energy, in squares of the grid")
    delta_e = _energy(p, d, dA, largest, "J", note="one square of the grid: its torque × its crank angle in radians")
    e = d.value_of("e")
    for slip, count_by in (("whole_squares_only", grid_loops.whole_squares),
                           ("part_squares_as_whole", grid_loops.touched_squares)):
        # the energies at A to I from the miscounted loops (they no longer close the cycle at J)
        levels = [0.0, *accumulate(fw.alternate([count_by(h) for h in profiles], first_above=above)[:-1])]
        d.mistake("dE", slip, (max(levels) - min(levels)) * e, if_apart=True)
    _rim(p, d, delta_e)


# ---- Example 3.2: a torque-time diagram ----------------------------------------------------------


def torque_time(p, d):
    """Example 3.2: a constant-torque motor feeding a machine whose torque rises in one trapezoidal pulse."""
    w = p.N
    peak_area = d.step("A_pulse", fw.trapezium_width(p.t1, p.t2, p.t3, p.t4) * (p.tau_p - p.tau_0), "N*m*s",
                       symbol=r"A_{\mathrm{pulse}}", formula=r"\tfrac{1}{2}\left[(@t4 - @t1) + (@t3 - @t2)\right](@tau_p - @tau_0)",
                       note="the trapezium above the base torque")
    work = d.step("W", (p.tau_0 * p.T + peak_area) * w, "J", formula=r"(@tau_0\,@T + @A_pulse)\,@N",
                  note="work per cycle = area under the torque-time graph × ω (θ = ωt)")
    tau_m = d.step("tau_M", work / (w * p.T), "N*m", symbol=r"\tau_M", formula=r"\frac{@W}{@N\,@T}",
                   note="the motor does the same work in a cycle at constant torque")
    d.mistake("tau_M", "peak_base_average", (p.tau_p + p.tau_0) / 2)
    d.mistake("tau_M", "base_left_out", peak_area / p.T)
    d.step("P", tau_m * w, "W", symbol=r"P_M", formula=r"@tau_M\,@N")
    d.mistake("P", "rpm_as_rad_s", tau_m * w * 60 / (2 * math.pi))
    crossing = fw.trapezium_crossings(p.t1, p.t2, p.t3, p.t4, p.tau_0, p.tau_p, tau_m)
    x = d.step("x", crossing[0], "s", formula=r"@t1 + (@t2 - @t1)\frac{@tau_M - @tau_0}{@tau_p - @tau_0}",
               note="where the rising torque crosses the mean line")
    y = d.step("y", crossing[1], "s", formula=r"@t4 - (@t4 - @t3)\frac{@tau_M - @tau_0}{@tau_p - @tau_0}",
               note="where the falling torque crosses it")
    delta_e = d.step("dE", fw.trapezium_width(x, p.t2, p.t3, y) * w * (p.tau_p - tau_m), "J", symbol=r"\Delta E",
                     formula=r"\tfrac{1}{2}\left[(@y - @x) + (@t3 - @t2)\right]\,@N\,(@tau_p - @tau_M)",
                     note="the area above the mean torque line: the flywheel gives this up")
    d.mistake("dE", "area_above_base", peak_area * w)
    d.mistake("dE", "time_not_converted", delta_e / w)
    d.mistake("dE", "rpm_as_rad_s", delta_e * 60 / (2 * math.pi))
    inertia = d.step("I", p.m * p.k ** 2, "kg*m^2", formula=r"@m\,@k^2")
    cs = d.step("Cs", fw.coefficient_of_fluctuation(delta_e, inertia, w), "", symbol=r"C_s",
                formula=r"\frac{@dE}{@I\,@N^2}", note="eq 3.5: the total fluctuation (ω₁ − ω₂)/ω")
    d.mistake("Cs", "half_band", cs / 2)
    d.mistake("Cs", "rpm_as_rad_s", delta_e / (inertia * (w * 60 / (2 * math.pi)) ** 2))
