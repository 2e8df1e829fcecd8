"""What a sheet prints, read back in SI, and the checks that hold a key's answers and its named mistakes to
values worked out again from it: by the oracles of chapters 1, 2 and 6 (code of their own) and by the
mistake checks of every chapter.

Units are converted by this table, not by exgen's: a slip in exgen.units would otherwise cancel out.
"""
from __future__ import annotations

import math
from decimal import Decimal
from types import SimpleNamespace

import pytest

from exgen.solve.variant import make_variant

#: SI value of one of each unit a template gives or asks in.
TO_SI = {
    "": 1.0, "m": 1.0, "cm": 1e-2, "mm": 1e-3, "in": 0.0254, "mm^2": 1e-6, "kg": 1.0, "t": 1e3, "s": 1.0,
    "N": 1.0, "kN": 1e3, "N*m": 1.0, "kN*m": 1e3, "J": 1.0, "kJ": 1e3, "W": 1.0, "kW": 1e3, "N/m": 1.0, "kN/m": 1e3,
    "N/mm": 1e3, "N*s/m": 1.0, "N*m*s": 1.0, "MPa": 1e6, "MN/m^2": 1e6, "GN/m^2": 1e9, "kg/m^3": 1.0, "kg*m^2": 1.0,
    "kg*mm": 1e-3, "kg*mm*m": 1e-3, "m/s": 1.0, "m/min": 1 / 60, "km/h": 1 / 3.6, "m/s^2": 1.0, "rad/s": 1.0, "rad/s^2": 1.0,
    "rpm": 2 * math.pi / 60, "Hz": 1.0, "deg": math.pi / 180, "percent": 1e-2, "teeth/in": 1 / 0.0254,
}
G = 9.81
SEEDS = range(60)


def printed(v, *names, optional=()) -> SimpleNamespace:
    """The givens as the sheet prints them (statement and asks), in SI; a choice as its text. A name in
    `optional` may be left unsaid when it is zero ("pivoted on the axis")."""
    sheet = v.statement + "\n" + "\n".join(v.asks.values())
    out = {}
    for name in names + tuple(optional):
        p = v.param(name)
        if name in optional and p.text == "0":
            out[name] = 0.0
            continue
        assert str(p) in sheet, f"{v.template.id} seed {v.seed}: {name} = {p} is not on the sheet"
        out[name] = float(Decimal(p.text.replace("\u2212", "-"))) * TO_SI[p.unit] if isinstance(p.exact, Decimal) else p.text
    return SimpleNamespace(**out)


def asked(value, part):
    """An SI value in the form a part asks for it: a number in the part's unit; a (size, angle in rad) pair
    for a size at an angle; text or a formula as it is."""
    if isinstance(value, (str, bool)) or callable(value):
        return value
    if isinstance(value, tuple):
        return value[0] / TO_SI[part.unit], math.degrees(value[1])
    return value / TO_SI[part.unit]


def same(ours, theirs, part, rel=1e-9) -> bool:
    """Whether a value worked out here is the one the key records (to `rel`; a direction modulo a turn)."""
    if isinstance(ours, str):
        return ours == theirs
    if callable(ours):  # a formula: compared at points across its symbols' ranges
        points = [{name: low + (high - low) * k / 4 for name, low, high in part.options["ranges"]} for k in range(1, 4)]
        return all(ours(**at) == pytest.approx(theirs(**at), rel=rel) for at in points)
    if isinstance(ours, tuple):
        if ours[0] == theirs.magnitude == 0:  # a polygon that closes: no direction
            return True
        turn = (ours[1] - theirs.angle_deg + 180) % 360 - 180
        return ours[0] == pytest.approx(theirs.magnitude, rel=rel) and abs(turn) < 1e-7
    if part.type == "angle":
        return abs((ours - theirs + 180) % 360 - 180) < 1e-7
    return ours == pytest.approx(theirs, rel=rel, abs=1e-12)


def check_answers(bank, template_id, oracle, seeds=SEEDS):
    """Every part's answer over many draws is the oracle's, worked from what the sheet prints."""
    template = bank.get(template_id)
    for seed in seeds:
        variant = make_variant(template, seed)
        expected = oracle(variant)[0]
        assert sorted(expected) == sorted(variant.answers), seed
        for part in template.parts:
            value = variant.answers[part.id].value
            assert same(asked(expected[part.id], part), value, part), (seed, part.id, variant.answers[part.id].text)


def check_mistakes(bank, template_id, worked, seeds=SEEDS):
    """Every mistake a part names, wherever the key records it, has the value `worked` gives it from the
    sheet; each is met at least once over the seeds."""
    template = bank.get(template_id)
    named = {(p.id, m.when) for p in template.parts for m in p.mistakes}
    met = set()
    for seed in seeds:
        variant = make_variant(template, seed)
        ours = worked(variant)
        for part in template.parts:
            recorded = variant.mistakes[part.id]
            for mistake in part.mistakes:
                if mistake.when not in recorded:
                    continue
                assert mistake.when in ours.get(part.id, {}), f"no value worked out for ({part.id}) {mistake.when}"
                value = asked(ours[part.id][mistake.when], part)
                assert same(value, recorded[mistake.when], part), (seed, part.id, mistake.when, value,
                                                                   recorded[mistake.when])
                met.add((part.id, mistake.when))
    assert met == named, f"never recorded apart from the answer over {len(seeds)} seeds: {sorted(named - met)}"
