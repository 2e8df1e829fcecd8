"""Template versions change exactly when something that can change a number or a verdict does."""
import textwrap

import pytest

from exgen.cli import main
from exgen.load import versions
from exgen.load.versions import data_digest, template_version

SOLVER = '''\
"""A solver."""
import math

from ..mechanics import belts


def power(p):
    """Power from tensions."""
    # the textbook's coefficient
    return (p.T1 - p.T2) * p.v * 1.0
'''


def code_hash(tmp_path, source: str, name="m.py") -> str:
    path = tmp_path / name
    path.write_text(source, encoding="utf-8")
    return versions._parsed(path)[1]


@pytest.mark.parametrize("same", [
    SOLVER.replace("# the textbook's coefficient", "# another comment"),
    SOLVER.replace('"""Power from tensions."""', '"""Power, from the two tensions and the belt speed."""'),
    SOLVER.replace("(p.T1 - p.T2) * p.v * 1.0", "(p.T1-p.T2)*p.v*1.0"),
    SOLVER + "\n\n# trailing comment\n",
    SOLVER.replace('"""A solver."""\n', ""),
])
def test_comments_docstrings_and_layout_do_not_change_a_code_hash(tmp_path, same):
    assert code_hash(tmp_path, same, "b.py") == code_hash(tmp_path, SOLVER)


@pytest.mark.parametrize("different", [
    SOLVER.replace("* 1.0", "* 1.01"), SOLVER.replace("p.T1 - p.T2", "p.T1 + p.T2"),
    SOLVER.replace("import math\n", "import math\nG = 9.81\n"),
])
def test_a_changed_coefficient_or_statement_changes_the_code_hash(tmp_path, different):
    assert code_hash(tmp_path, different, "b.py") != code_hash(tmp_path, SOLVER)


def test_data_digest_ignores_order_but_not_values():
    base = {"id": "x", "params": {"d": {"min": 1, "max": 2, "step": 0.5}}, "parts": [{"id": "a"}]}
    reordered = {"parts": [{"id": "a"}], "params": {"d": {"step": 0.5, "max": 2, "min": 1}}, "id": "x"}
    assert data_digest(base) == data_digest(reordered)
    for changed in ({**base, "id": "y"}, {**base, "params": {"d": {"min": 1.0, "max": 2, "step": 0.5}}},
                    {**base, "params": {"d": {"min": "1", "max": 2, "step": 0.5}}},
                    {**base, "parts": [{"id": "a"}, {"id": "b"}]}):
        assert data_digest(changed) != data_digest(base)


def test_a_version_covers_the_solver_the_physics_the_answer_types_and_the_grading(bank):
    version = template_version(bank.get("belts.flat_belt_power"))
    assert {"exgen/solvers/belts.py", "exgen/mechanics/belts.py", "exgen/solve/variant.py", "exgen/draw/values.py",
            "exgen/draw/seeds.py", "exgen/units.py", "graders/marking.py"} <= set(version.code)
    assert {f"exgen/answertypes/{t}.py" for t in ("number", "angle", "polar")} <= set(version.code)
    assert "exgen/data/unit_aliases.txt" in version.data and set(version.libraries) == {"numpy", "pint"}
    assert not [m for m in version.code if m.startswith(("exgen/render/", "exgen/figures/", "exgen/cli"))]
    # another chapter's solver is not part of it
    assert "exgen/solvers/balancing.py" not in version.code


def test_templates_with_other_solvers_have_other_versions(bank):
    digests = {template_version(t).digest for t in bank}
    assert len(digests) == len(bank)


def test_listing_templates_computes_no_version(monkeypatch, capsys):
    """`exgen list` is measured for speed: versions are computed only where generate and grade need them."""
    def refuse(*args):
        raise AssertionError("a version was computed")

    monkeypatch.setattr(versions, "template_version", refuse)
    monkeypatch.setattr(versions, "_parsed", refuse)
    assert main(["list"]) == 0 and "belts.flat_belt_power" in capsys.readouterr().out
