import pytest

from exgen.errors import InvalidDraw
from exgen.load.template import default_symbol
from exgen.solve.derivation import Derivation, Params
from exgen.solve.variant import answer_for, rerun


@pytest.mark.parametrize("name, symbol", [
    ("mu", r"\mu"), ("d1", "d_1"), ("N12", "N_{12}"), ("T_max", r"T_{\mathrm{max}}"), ("omega_2", r"\omega_2"),
    ("theta", r"\theta"), ("X", "X"), ("alpha_open", r"\alpha_{\mathrm{open}}"), ("T_c", "T_c"),
])
def test_default_symbol(name, symbol):
    assert default_symbol(name) == symbol


def test_tables_stand_where_the_solver_places_them():
    d = Derivation(Params({"m": 2.0, "r": 0.5}, {}))
    d.step("mr", 1.0, "kg*m", formula=r"@m\,@r")
    table = d.table("Planes", [("Plane",), ("$m r$", "kg*m")], [["1", "@mr"]], total=["Σ", "@mr"])
    d.step("B", 2.0, "kg")
    assert table.at == 1 and table.names == {"mr"} and table.hides == {"mr"}
    kept = d.table("Again", [("x",)], [["@mr"]], shown=("mr",))
    assert kept.hides == set() and kept.at == 2


def test_steps_record_and_overrides_replace():
    d = Derivation(Params({"a": 2.0}, {}), overrides={"b": 10.0})
    b = d.step("b", 2 * d.params.a, "m", formula=r"2\,@a")
    c = d.step("c", b + 1, "m")
    assert (b, c) == (10.0, 11.0) and d["b"].overridden and not d["c"].overridden


def test_require_rejects_or_warns():
    with pytest.raises(InvalidDraw, match="too fast"):
        Derivation(Params({}, {})).require(False, "too fast")
    lenient = Derivation(Params({}, {}), strict=False)
    lenient.require(False, "too fast")
    assert lenient.warnings == ["too fast"]


def test_rerun_carries_an_earlier_answer_forward(bank):
    from exgen.solve.variant import make_variant

    variant = make_variant(bank.get("belts.flat_belt_power"), 7)
    part_c = variant.template.part("c")
    same = rerun(variant, {})
    assert answer_for(part_c, same).value == pytest.approx(variant.answers["c"].value)
    # a different angle of contact in (a) gives a different, consistent power in (c)
    theta = variant.step("theta").value
    moved = answer_for(part_c, rerun(variant, {"theta": theta * 0.9}))
    assert moved.value < variant.answers["c"].value
