"""Issued problems do not change by accident: each template's drawn parameters and answers at fixed seeds
are kept in tests/golden/ and regenerated only deliberately (see tests/golden/__init__.py)."""
import json

import pytest

import golden


def test_every_template_has_a_golden_file_and_every_file_a_template(bank):
    missing = [t.id for t in bank if not golden.path_for(t.id).is_file()]
    assert not missing, (f"no golden file for {', '.join(missing)}: if the template is new, create it with "
                         f"`{golden.UPDATE.format(ids=' '.join(missing))}` and commit tests/golden/")
    stale = sorted(p.stem for p in golden.FOLDER.glob("*.json") if p.stem not in bank.templates)
    assert not stale, f"golden files for templates no longer in the bank: {', '.join(stale)}; delete them"


def test_drawn_parameters_and_answers_are_as_recorded(bank):
    changed = {}
    for template in bank:
        path = golden.path_for(template.id)
        if path.is_file():
            lines = golden.differences(json.loads(path.read_text(encoding="utf-8")), golden.record(template))
            if lines:
                changed[template.id] = lines
    report = "\n".join(f"  {tid}: {line}" for tid, lines in changed.items() for line in lines[:4])
    assert not changed, (f"issued problems would change:\n{report}\nIf that is deliberate, regenerate with "
                         f"`{golden.UPDATE.format(ids=' '.join(changed))}` and say so in the commit message.")


def test_a_change_is_caught_and_named(bank):
    template = bank.get("belts.flat_belt_power")
    stored = golden.record(template)
    now = json.loads(json.dumps(stored))
    first = next(iter(now["seeds"].values()))
    part = next(iter(first["answers"]))
    first["answers"][part]["value"] *= 1.001
    param = next(iter(first["params"]))
    assert golden.differences(stored, now) == [f"seed 0: answer ({part}) {first['answers'][part]['text']} -> "
                                               f"{first['answers'][part]['text']}"]
    first["params"][param] = "999"
    assert golden.differences(stored, now)[0].startswith(f"seed 0: drawn {param} ")


@pytest.mark.parametrize("a, b, same", [(1.0, 1.0 + 1e-12, True), (1.0, 1.0001, False), ("x", "x", True),
                                        ({"magnitude": 2.0, "angle_deg": 30.0}, {"magnitude": 2.0, "angle_deg": 30.1},
                                         False)])
def test_numbers_compare_to_the_last_bits_only(a, b, same):
    assert golden._same(a, b) is same
