"""Worked derivation for a simple epicyclic train (course text §1.3.3, Examples 1.10 and 1.11).

Sun S, planet P, ring R and arm A; the sun or the ring is held, and either the arm or the other
gear is driven. The key works the text's table row by row: row 1, every member +1 turn; row 2, the
arm held and the fixed member turned -1, the others following through their meshes (external -,
internal +); row 3 = row 1 + row 2, scaled so the driver has its given speed. It then checks the result
with the train-value formula (ω_R - ω_A)/(ω_S - ω_A) = e. Speeds are signed, counter-clockwise
positive, as on the sheet.
"""
from __future__ import annotations

from ..mechanics import gears as mg

MEMBERS = ("arm", "sun", "planet", "ring")
SYMBOL = {"sun": r"\omega_S", "ring": r"\omega_R", "arm": r"\omega_A", "planet": r"\omega_P"}
TEETH = {"sun": "@ts", "ring": "@tR", "planet": "@tp"}


def _members(p) -> tuple[str, str, str]:
    """(fixed, driver, output) member names."""
    free = "ring" if p.fixed == "sun" else "sun"
    driver = "arm" if p.driver == "arm" else free
    output = free if driver == "arm" else "arm"
    return p.fixed, driver, output


def _held_rows(d, fixed: str, free: str, ts: float, tp: float, t_ring: float) -> dict[str, float]:
    """Row 2 as steps: the fixed member -1, then the planet and the free gear through their meshes."""
    held = mg.arm_held_turns(fixed, ts, tp, t_ring)
    d.step("b_fixed", held[fixed], "", symbol=rf"n_{{{fixed[0].upper()},2}}",
           note=f"table row 1: every member +1 turn. Row 2: hold the arm and turn the {fixed} -1, "
                f"so that rows 1 and 2 added leave the {fixed} at rest")
    planet_sign = "+" if fixed == "ring" else "-"
    held["planet"] = d.step("b_planet", held["planet"], "", symbol=r"n_{P,2}",
                            formula=rf"@b_fixed\left({planet_sign}\frac{{{TEETH[fixed]}}}{{@tp}}\right)",
                            note="planet and ring turn the same way (internal mesh, +); sun and planet "
                                 "opposite ways (external, -)")
    free_sign = "+" if free == "ring" else "-"
    held[free] = d.step("b_free", held["planet"] * mg.pair_ratio(tp, t_ring if free == "ring" else ts,
                                                                    mg.INTERNAL if free == "ring" else mg.EXTERNAL),
                        "", symbol=rf"n_{{{free[0].upper()},2}}",
                        formula=rf"@b_planet\left({free_sign}\frac{{@tp}}{{{TEETH[free]}}}\right)")
    return held


def epicyclic(p, d):
    fixed, driver, output = _members(p)
    free = "ring" if fixed == "sun" else "sun"
    t_ring = d.step("tR", int(round(mg.ring_teeth(p.ts, p.tp))), "", symbol="t_R", formula=r"@ts + 2\,@tp",
                    note="one module and a common axis: the ring's pitch radius is the sun's plus a planet's diameter")
    d.mistake("tR", "planet_counted_once", int(round(p.ts + p.tp)))
    d.step("e", mg.epicyclic_value(p.ts, t_ring), "", symbol="e", formula=r"-\frac{@ts}{@tR}",
           note=r"$e = (\omega_R - \omega_A)/(\omega_S - \omega_A)$: the arm held, sun to ring through the planet")
    d.mistake("e", "ratio_inverted", -t_ring / p.ts)
    d.mistake("e", "sign_ignored", p.ts / t_ring)

    held = _held_rows(d, fixed, free, p.ts, p.tp, t_ring)
    c_planet = d.step("c_planet", 1 + held["planet"], "", symbol=r"n_{P,3}", formula=r"1 + @b_planet",
                      note="row 3 = row 1 + row 2: the arm +1, the fixed member 0")
    c_free = d.step("c_free", 1 + held[free], "", symbol=rf"n_{{{free[0].upper()},3}}", formula=r"1 + @b_free")
    total = {"arm": 1.0, fixed: 0.0, "planet": c_planet, free: c_free}
    d.require(abs(c_free) > 0.05, "the free gear barely turns")
    turns = {"1: every member +1": {m: 1 for m in MEMBERS},
             "2: arm held": {"arm": 0, fixed: "@b_fixed", "planet": "@b_planet", free: "@b_free"},
             "3 = 1 + 2": {"arm": 1, fixed: 0, "planet": "@c_planet", free: "@c_free"}}
    d.table("The tabular method: turns of each member", [("Row",)] + [(m.capitalize(),) for m in MEMBERS],
            [[row] + [cells[m] for m in MEMBERS] for row, cells in turns.items()],
            shown=("b_fixed", "b_planet", "b_free"))

    w_in = d.step("w_in", mg.signed(p.N_in, p.sense_in), "rad/s", symbol=SYMBOL[driver], shown="rpm",
                  note=f"the {driver} is driven; counter-clockwise positive")
    scale = w_in / total[driver]
    across = r"\frac{@w_in}{@c_free}" if driver != "arm" else r"@w_in"
    out = d.step("N_out", scale * total[output], "rad/s", symbol=SYMBOL[output], shown="rpm",
                 formula=(rf"{across}\,@c_free" if output != "arm" else across),
                 note="row 3 scaled so that the driver turns at its given speed")
    planet = d.step("N_planet", scale * c_planet, "rad/s", symbol=SYMBOL["planet"], formula=rf"{across}\,@c_planet",
                    shown="rpm")

    d.step("N_fixed", 0.0, "rad/s", symbol=SYMBOL[fixed], note=f"the {fixed} is held: row 3 gives it 0")
    d.step("n_train", out / w_in, "", symbol=rf"\frac{{{SYMBOL[output]}}}{{{SYMBOL[driver]}}}",
           formula=r"\frac{@N_out}{@w_in}", note=f"the train's speed ratio, {output} to {driver}")
    speeds = {fixed: 0.0, driver: w_in, output: out}
    d.step("e_check", (speeds["ring"] - speeds["arm"]) / (speeds["sun"] - speeds["arm"]), "",
           symbol=r"\frac{\omega_R - \omega_A}{\omega_S - \omega_A}",
           formula=_check_formula(fixed, driver, output), note="the train-value formula gives e again: a check")
    _mistakes(p, d, fixed, driver, output, held, t_ring, w_in, out, planet)


def _check_formula(fixed: str, driver: str, output: str) -> str:
    value = {fixed: "0", driver: "@w_in", output: "@N_out"}
    return rf"\frac{{{value['ring']} - {value['arm']}}}{{{value['sun']} - {value['arm']}}}"


def _mistakes(p, d, fixed, driver, output, held, t_ring, w_in, out, planet):
    if driver == "arm":
        relative = w_in * held[output]
    else:
        relative = w_in / held[driver]
    d.mistake("N_out", "arm_not_subtracted", relative)
    wrong = mg.epicyclic_speeds(fixed, driver, w_in, p.ts, p.tp, t_ring, ring_sign=mg.EXTERNAL)
    for name in (output, "planet"):  # the ring's mesh may not lie on the path: then the slip does not show
        d.mistake("N_out" if name == output else "N_planet", "internal_mesh_sign", wrong[name], if_apart=True)
    relative_planet = w_in / (1 + held[driver]) * held["planet"]  # row 2 alone: the speed seen from the arm
    d.mistake("N_planet", "planet_relative", relative_planet)
