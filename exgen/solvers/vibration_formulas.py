"""Natural frequency as a formula in K, M and m (course text §6.5, Example 6.2), for a small catalogue of
systems: pulleys with inertia (floating, fixed, stepped) and uniform levers on one or two springs.

Each system is worked by the equivalent method at one reference point: the equivalent stiffness and mass
as formulas, then ω_n = √(K'/m') and f_n = ω_n/2π, and the frequency for the printed values from the
formula the student gives (error carried forward). Known wrong formulas are recorded as mistakes.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..answertypes.symbolic import Expression

SYMBOLS = ("K", "M", "m")


@dataclass(frozen=True)
class System:
    """One arrangement: where the reference point is, its equivalent stiffness and mass as formulas, and
    the wrong equivalent masses or stiffnesses known slips give (name -> (stiffness, mass))."""

    reference: str
    stiffness: str
    mass: str
    why_stiffness: str
    why_mass: str
    slips: dict[str, tuple[str, str]] = field(default_factory=dict)


SYSTEMS = {
    # Example 6.2: the pulley rolls on the fixed cord about O, its rim; the spring holds its centre (r
    # from O) and the mass hangs from the free cord (2r from O, so it moves twice as far).
    "floating pulley": System(
        "the pulley's centre", "K", "3*M/2 + 4*m",
        r"the spring moves with the centre: $K' = K$",
        r"the pulley turns about O, where it leaves the fixed cord: $I_O = Mr^2/2 + Mr^2 = 3Mr^2/2$, so $3M/2$ at $r$; "
        r"the free cord is $2r$ from O, so $m$ counts $m(2r/r)^2 = 4m$",
        {"wrong_axis": ("K", "M/2 + 4*m"), "ratio_not_squared": ("K", "3*M/2 + 2*m")}),
    # a uniform pulley on a fixed axle, the cord over it: the spring on one side, the mass on the other
    "fixed pulley": System(
        "the pulley's rim", "K", "M/2 + m",
        r"the spring moves with the cord: $K' = K$",
        r"a uniform disc about its axle has $I = Mr^2/2$, so $M/2$ at its rim; the mass moves with the cord",
        {"pulley_as_ring": ("K", "M + m"), "pulley_ignored": ("K", "m")}),
    # a stepped pulley: the spring's cord on a hub of radius r, the mass's cord on the rim of radius 2r
    "stepped pulley": System(
        "the pulley's rim (radius 2r), where the mass hangs", "K/4", "M/2 + m",
        r"the spring's cord is on the hub, $r$ from the axle: $K(r/2r)^2 = K/4$",
        r"the uniform disc of radius $2r$ has $I = M(2r)^2/2$, so $M/2$ at its rim; the mass hangs at the rim",
        {"ratio_not_squared": ("K/2", "M/2 + m"), "ratio_inverted": ("4*K", "M/2 + m")}),
    # a uniform rod pivoted at one end, held level by a spring at its other end, a mass at its middle
    "lever": System(
        "the rod's free end, where the spring acts", "K", "M/3 + m/4",
        r"the spring is at the reference point: $K' = K$",
        r"the rod turns about its end: $I = Ml^2/3$, so $M/3$ at $l$; the mass at $l/2$ counts $m(1/2)^2 = m/4$",
        {"wrong_axis": ("K", "M/12 + m/4"), "ratio_not_squared": ("K", "M/3 + m/2")}),
    # a uniform rod pivoted at its middle, a spring at each end, a mass at one end
    "two springs": System(
        "one end of the rod", "2*K", "M/3 + m",
        r"both springs are $l/2$ from the pivot, at the reference radius: they add, $2K$",
        r"the rod turns about its middle: $I = Ml^2/12 = (M/3)(l/2)^2$, so $M/3$ at $l/2$; the mass is at the end",
        {"one_spring": ("K", "M/3 + m"), "wrong_axis": ("2*K", "4*M/3 + m")}),
}

FREQUENCY = "sqrt(({k})/({m}))/(2*pi)"


def _expr(text: str) -> Expression:
    return Expression.parse(text, SYMBOLS)


def _with_values(expression: Expression) -> str:
    """The formula's LaTeX with its symbols as @K, @M, @m, so the key fills in the printed values
    (a number or symbol written next to another gets a × between the numbers)."""
    latex = re.sub(r"(?<![\\A-Za-z])([KMm])(?![A-Za-z])", r"@\1", expression.latex())
    return re.sub(r"(\d|@[KMm])\s*(?=@)", r"\1\\,", latex)


def natural_frequency_formula(p, d):
    """The natural frequency of the chosen system in terms of K, M and m, then for the printed values."""
    system = SYSTEMS[p.system]
    d.step("K_eq", _expr(system.stiffness), symbol="K'", note=f"at {system.reference}: {system.why_stiffness}")
    d.step("m_eq", _expr(system.mass), symbol="m'", note=system.why_mass)
    d.step("omega_expr", _expr(f"sqrt(({system.stiffness})/({system.mass}))"), symbol=r"\omega_n",
           note=r"$\omega_n = \sqrt{K'/m'}$ in rad/s")
    f_expr = d.step("f_expr", _expr(FREQUENCY.format(k=system.stiffness, m=system.mass)), symbol="f_n",
                    note=r"$f_n = \omega_n/2\pi$ in Hz")
    d.mistake("f_expr", "omega_for_f", _expr(f"sqrt(({system.stiffness})/({system.mass}))"))
    for name, (stiffness, mass) in system.slips.items():
        d.mistake("f_expr", name, _expr(FREQUENCY.format(k=stiffness, m=mass)))
    f = d.step("f", f_expr(K=p.K, M=p.M, m=p.m), "Hz", symbol="f", formula=_with_values(f_expr),
               note="the formula with the values given")
    d.require(0.3 <= f <= 30, "a natural frequency outside 0.3-30 Hz")
    right = _expr(FREQUENCY.format(k=system.stiffness, m=system.mass))
    d.mistake("f", "omega_for_f", _expr(f"sqrt(({system.stiffness})/({system.mass}))")(K=p.K, M=p.M, m=p.m))
    for name, (stiffness, mass) in system.slips.items():
        value = _expr(FREQUENCY.format(k=stiffness, m=mass))(K=p.K, M=p.M, m=p.m)
        if abs(value - right(K=p.K, M=p.M, m=p.m)) > 0.03 * f:
            d.mistake("f", name, value)
