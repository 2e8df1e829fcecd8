"""Golden files: every template's drawn parameters and answers at fixed seeds, in tests/golden/<id>.json.

A change that would alter issued problems (a range, a constraint, a solver's number) fails
tests/test_golden.py. When the change is deliberate, regenerate the files it touches and say so in the
commit message:

    python -m tests.golden --update                      # every template
    python -m tests.golden --update belts.flat_belt_power # one (or several) templates
    python -m tests.golden --check                       # what differs, without writing

A new template has no golden file until it is created the same way.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

FOLDER = Path(__file__).parent
#: Fixed seeds: small ones, and ones of the size per-student seeds have (64-bit).
SEEDS = (0, 1, 2, 3, 5, 8, 13, 2**32 + 7, 2**63 + 11, 2**64 - 1)
#: Numbers are compared to this relative precision (last-bit differences of a platform's libm are not changes).
REL = 1e-9
UPDATE = "python -m tests.golden --update {ids}"


def path_for(template_id: str) -> Path:
    return FOLDER / f"{template_id}.json"


def _value(value):
    """An answer's value as JSON: numbers as numbers, a size at an angle as both, anything else as text."""
    if isinstance(value, bool) or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        return float(value)
    if hasattr(value, "magnitude") and hasattr(value, "angle_deg"):
        return {"magnitude": float(value.magnitude), "angle_deg": float(value.angle_deg)}
    return str(value)


def record(template) -> dict:
    """What the template draws and answers at each seed."""
    from exgen.solve.variant import make_variant

    seeds = {}
    for seed in SEEDS:
        variant = make_variant(template, seed)
        seeds[str(seed)] = {
            "params": {p.name: p.text for p in variant.params},
            "answers": {part_id: {"value": _value(a.value), "text": a.text} for part_id, a in variant.answers.items()},
        }
    return {"template": template.id, "seeds": seeds}


def differences(stored: dict, now: dict) -> list[str]:
    """What changed between a stored record and a fresh one, one line each (at most a few per seed)."""
    lines = []
    for seed, was in stored["seeds"].items():
        new = now["seeds"].get(seed)
        if new is None:
            lines.append(f"seed {seed}: no longer recorded")
            continue
        if was["params"] != new["params"]:
            changed = sorted(k for k in set(was["params"]) | set(new["params"])
                             if was["params"].get(k) != new["params"].get(k))
            shown = ", ".join(f"{k} {was['params'].get(k)} -> {new['params'].get(k)}" for k in changed[:3])
            lines.append(f"seed {seed}: drawn {shown}")
            continue
        for part in sorted(set(was["answers"]) | set(new["answers"])):
            a, b = was["answers"].get(part), new["answers"].get(part)
            if a is None or b is None or not _same(a["value"], b["value"]):
                lines.append(f"seed {seed}: answer ({part}) {a and a['text']} -> {b and b['text']}")
    if set(now["seeds"]) - set(stored["seeds"]):
        lines.append("the seeds recorded changed")
    return lines


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or math.isclose(a, b, rel_tol=REL, abs_tol=1e-300)
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    return a == b


def write(template) -> Path:
    path = path_for(template.id)
    path.write_text(json.dumps(record(template), indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return path


def main(argv: list[str]) -> int:
    from exgen.load.bank import load_bank

    bank = load_bank()
    update = "--update" in argv
    ids = [a for a in argv if not a.startswith("--")] or [t.id for t in bank]
    status = 0
    for template_id in ids:
        template = bank.get(template_id)
        path = path_for(template_id)
        if update:
            print(f"wrote {write(template).relative_to(Path.cwd()) if path.is_relative_to(Path.cwd()) else path}")
            continue
        if not path.is_file():
            print(f"{template_id}: no golden file ({UPDATE.format(ids=template_id)} creates it)")
            status = 1
            continue
        lines = differences(json.loads(path.read_text(encoding="utf-8")), record(template))
        for line in lines:
            print(f"{template_id}: {line}")
        status |= bool(lines)
    return status
