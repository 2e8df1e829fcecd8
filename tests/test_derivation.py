import pytest

from exgen.derivation import Derivation, Params, default_symbol, expand
from exgen.errors import InvalidDraw
from exgen.variant import answer_for, rerun


@pytest.mark.parametrize("name, symbol", [
    ("mu", r"\mu"), ("d1", "d_1"), ("N12", "N_{12}"), ("T_max", r"T_{\mathrm{max}}"), ("omega_2", r"\omega_2"),
    ("theta", r"\theta"), ("X", "X"), ("alpha_open", r"\alpha_{\mathrm{open}}"), ("T_c", "T_c"),
])
def test_default_symbol(name, symbol):
    assert default_symbol(name) == symbol


def test_expand_symbolic_and_substituted():
    symbols = {"mu": r"\mu", "theta": r"\theta", "T1": "T_1", "T2": "T_2", "v": "v"}.get
    values = {"mu": 0.3, "theta": 2.947, "T1": 2000.0, "T2": -826.2, "v": 5.236}.get
    fmt = "{:g}".format
    assert expand(r"e^{@mu\,@theta}", symbols) == r"e^{\mu\,\theta}"
    assert expand(r"e^{@mu\,@theta}", symbols, values, fmt) == r"e^{0.3 \times 2.947}"
    assert expand(r"(@T1 - @T2)\,@v", symbols, values, fmt) == r"(2000 - (-826.2)) \times 5.236"


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
    from exgen.variant import make_variant

    variant = make_variant(bank.get("belts.flat_belt_power"), 7)
    part_c = variant.template.part("c")
    same = rerun(variant, {})
    assert answer_for(part_c, same).value == pytest.approx(variant.answers["c"].value)
    # a different angle of contact in (a) gives a different, consistent power in (c)
    theta = variant.step("theta").value
    moved = answer_for(part_c, rerun(variant, {"theta": theta * 0.9}))
    assert moved.value < variant.answers["c"].value
