"""Hints never hand over an answer: over every template and many seeds, a student who asks every hint of
every part before answering anything is shown no number that is the answer to a part not yet answered
right (in any unit of its kind, with either sign, within the part's tolerance), and typing any number a
hint shows into any part is not marked right. Numbers of the method (the 2 of 2π, the 60 of rpm) and
the givens printed on the sheet are the student's already and are not counted."""
import re

import pytest

from exgen.answertypes import answer_type
from exgen.draw.seeds import PRACTICE_SEEDS
from exgen.load.bank import load_bank
from exgen.render.solution import Filled, solution
from exgen.render.targets import PLAIN
from exgen.render.text import line_text
from exgen.solve.variant import make_variant
from exgen.units import DimensionError, QuantityError, convert, from_si, same_dimension
from graders.grade import grade_variant
from graders.results import CARRIED, CORRECT
from practice.hints import hint_ladder

SEEDS = [PRACTICE_SEEDS.start + 7919 * k for k in range(20)]
#: The units a student converts between, written here apart from exgen's own tables: a test of the rule,
#: not of its implementation. Each is also tried with a k or m prefix on its value.
UNITS = ("", "%", "deg", "rad", "rad/s", "rpm", "Hz", "rad/s^2", "s", "min", "ms", "m", "mm", "cm", "km",
         "m^2", "mm^2", "m/s", "km/h", "m/min", "m/s^2", "kg", "g", "t", "kg*m", "kg*mm", "kg*m^2", "kg*mm^2",
         "kg/m", "N", "kN", "MN", "N*m", "kN*m", "N*mm", "J", "kJ", "MJ", "W", "kW", "MW", "N/m", "kN/m", "N/mm",
         "Pa", "kPa", "MPa", "N*s/m", "kg*m^2/s", "N*m*s")
PREFIXES = (1.0, 1e3, 1e-3)
#: A number as the terminal writes it ("0.1991", "−3.5", "2.4×10⁻³"), and a unit written after it.
NUMBER = re.compile(r"(?<![\w.])([-\u2212]?\d+(?:\.\d+)?)(?:\s*\u00d7\s*10([\u207b]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+))?"
                    r"(?:\s?([A-Za-z\u00b0%][A-Za-z\u00b7/\u00b2\u00b3]*))?")
POWER = str.maketrans("\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079", "-0123456789")


def numbers(text: str) -> list[tuple[float, str, str]]:
    """(value, as written, unit written after it or "") of every number in a plain text."""
    out = []
    for mantissa, power, unit in NUMBER.findall(text):
        value = float(mantissa.replace("\u2212", "-")) * 10.0 ** int((power or "0").translate(POWER))
        out.append((value, mantissa + (f"e{power.translate(POWER)}" if power else ""), unit))
    return out


def kinds_of(unit: str) -> list[str]:
    try:
        return [u for u in UNITS if same_dimension(u, unit)] or [unit]
    except QuantityError:
        return [unit]


def reveals(value: float, answer) -> bool:
    """The test's own reading of the rule: the number, in some unit of the answer's kind (either sign,
    with or without a prefix), is the answer within the part's tolerance."""
    part, kind = answer.part, answer_type(answer.part)
    key = answer.value
    if kind.name in ("choice", "symbolic"):
        return False
    def direction(v, k):  # a direction modulo a turn; its mirror image −θ is another one
        return min((v - k) % 360, (k - v) % 360) <= part.tol.abs

    if kind.name == "polar":
        halves = [(key.magnitude, part.unit, lambda v, k: abs(abs(v) - k) <= part.tol.rel * abs(k), PREFIXES),
                  (key.angle_deg, "deg", direction, (1.0,))]
    elif kind.name == "angle":
        halves = [(key, part.unit, lambda v, k: kind.matches(v, k, part), (1.0,))]
    else:  # a size: with either sign
        halves = [(key, part.unit, lambda v, k: kind.matches(v, k, part) or kind.matches(-v, k, part),
                   (1.0,) if kind.name == "integer" else PREFIXES)]
    for expected, unit, close, prefixes in halves:
        for other in kinds_of(unit):
            try:
                read = convert(value, other, unit) if unit else value
            except DimensionError:
                continue
            if any(close(read * prefix, expected) for prefix in prefixes):
                return True
    return False


def shown_texts(variant, part, hint) -> tuple[str, set[str]]:
    """A hint as the terminal prints it, and the numbers of its method (the same on every sheet)."""
    if hint.line is None:
        source = re.sub(r"\{\{.*?\}\}", " ", next(h for h in part.hints if variant.fill(h) == hint.text))
        return PLAIN.text(hint.text), {w for _, w, _ in numbers(PLAIN.text(source))}
    line = hint.line
    symbols = {**{p.name: p.symbol for p in variant.params}, **{s.name: s.symbol for s in variant.steps}}
    method = []  # the line with every number of the draw replaced by its symbol; a formula answer is method
    for filled in (line.formula, line.substituted):
        if filled is not None:
            method += PLAIN.terms(Filled(filled.formula, tuple(symbols[s.name] for s in filled.formula.slots),
                                         filled.numbers))
    method += [PLAIN.terms(q)[0] for q in line.values if not isinstance(q.value, (int, float))]
    return "\n".join(line_text(line, "")), {w for _, w, _ in numbers(" ".join(method))}


def visible(variant) -> list[float]:
    """What the sheet shows already: the givens in every unit of their kind, the numbers of its text."""
    seen = [v for v, _, _ in numbers(PLAIN.text(variant.statement))]
    seen += [v for ask in variant.asks.values() for v, _, _ in numbers(PLAIN.text(ask))]
    for p in variant.params:
        if isinstance(p.si, (int, float)) and not isinstance(p.si, bool):
            printed = from_si(float(p.si), p.unit) if p.unit else float(p.si)
            seen += [convert(printed, p.unit, u) for u in kinds_of(p.unit)] if p.unit else [printed]
    return seen


def leaks(variant, answered=frozenset()) -> list[str]:
    """Every number the hints show, with every part's hints asked, that gives away a part not in `answered`,
    and every such number that is marked right when typed."""
    worked = solution(variant)
    withheld = [variant.answers[p.id] for p in variant.template.parts if p.id not in answered]
    sheet = visible(variant)
    found = []
    for part in variant.template.parts:
        for level, hint in enumerate(hint_ladder(variant, part.id, worked, answered), start=1):
            text, method = shown_texts(variant, part, hint)
            for value, written_as, unit in numbers(text):
                if written_as in method or any(abs(abs(value) - abs(s)) <= 5e-4 * abs(s) for s in sheet):
                    continue
                for answer in withheld:
                    if reveals(value, answer):
                        found.append(f"hint {level} of ({part.id}) shows {written_as} {unit}: the answer to "
                                     f"({answer.part.id}) is {answer.text}\n{text}")
                typed = [written_as] + ([f"{written_as} {unit}"] if unit else [])
                for answer in withheld:
                    for attempt in typed:
                        status = grade_variant(variant, {answer.part.id: attempt}).parts[
                            [p.id for p in variant.template.parts].index(answer.part.id)].status
                        if status in (CORRECT, CARRIED):
                            found.append(f"{attempt!r} from hint {level} of ({part.id}) is marked right in "
                                         f"({answer.part.id})\n{text}")
    return found


BANK = load_bank()


@pytest.mark.parametrize("template_id", sorted(BANK.templates))
def test_no_hint_gives_away_an_answer_not_yet_found(template_id):
    template = BANK.get(template_id)
    problems = []
    for seed in SEEDS:
        problems += [f"seed {seed}: {leak}" for leak in leaks(make_variant(template, seed))]
    assert not problems, "\n\n".join(problems[:5])


def test_the_beam_on_two_springs_hint_for_c_shows_the_method_not_q_nor_omega(bank):
    """The hint for (c) showed ωₙ = √(q/I_O) = √(822/0.3709) = 47.08 rad/s before anything was answered:
    (b)'s answer, and (c)'s in rad/s."""
    variant = make_variant(bank.get("vibration.beam_two_springs"), SEEDS[0])
    shown = "\n".join("\n".join(line_text(h.line, "")) for h in hint_ladder(variant, "c"))
    q, omega = variant.step("q").value, variant.step("omega_n").value
    assert "√(q/I_O)" in shown and f"{q:.4g}" not in shown and f"{omega:.4g}" not in shown
    assert "f\u2099 = \u03c9\u2099/(2\u03c0)" in shown


def test_once_parts_are_answered_right_their_numbers_are_shown(bank):
    variant = make_variant(bank.get("vibration.beam_two_springs"), SEEDS[0])
    before = "\n".join("\n".join(line_text(h.line, "")) for h in hint_ladder(variant, "c"))
    after = "\n".join("\n".join(line_text(h.line, "")) for h in hint_ladder(variant, "c", answered=frozenset("ab")))
    q, omega = variant.step("q").value, variant.step("omega_n").value
    assert f"{q:.4g}" not in before and f"{q:.4g}" in after
    assert f"{omega:.4g}" not in after  # still (c)'s answer, in rad/s
    assert not leaks(variant, frozenset("ab"))


def _withheld_shown(text, variant) -> list[str]:
    """Numbers of a page or transcript that give away an answer (the sheet's own and the method's excepted)."""
    sheet, method = visible(variant), set()
    for part in variant.template.parts:
        for hint in hint_ladder(variant, part.id):
            method |= shown_texts(variant, part, hint)[1]
    return [f"{w} {u}: ({a.part.id}) is {a.text}" for value, w, u in numbers(text)
            if w not in method and not any(abs(abs(value) - abs(s)) <= 5e-4 * abs(s) for s in sheet)
            for a in variant.answers.values() if reveals(value, a)]


@pytest.mark.parametrize("template_id", ["vibration.beam_two_springs", "belts.flat_belt_power",
                                         "balancing.two_plane_balance", "flywheels.punching_press"])
def test_in_the_browser_every_hint_asked_first_shows_no_answer(bank, tmp_path, template_id):
    """Through the app, as a student clicks: every hint of every part, then the page read as shown (the
    plain form of each formula is its MathML's alttext)."""
    import html
    import random

    from starlette.testclient import TestClient

    from practice.session import Practice
    from practice.store import Store
    from practice.web.app import create_app, loopback_hosts

    practice = Practice(bank, Store(tmp_path / "p.sqlite3"), rng=random.Random(11))
    with TestClient(create_app(practice, loopback_hosts(8000)), base_url="http://127.0.0.1:8000") as client:
        for _ in range(3):
            where = client.post("/next", data={"scope": f"template:{template_id}"}, follow_redirects=False)
            problem = practice.problem(int(where.headers["location"].rsplit("/", 1)[1]))
            for part in problem.template.parts:
                while client.post(f"{where.headers['location']}/hint", data={"part": part.id},
                                  headers={"accept": "application/json"}).json()["more"]:
                    pass
            page = client.get(where.headers["location"]).text
            hints = "\n".join(re.findall(r'<div class="hints"[^>]*>(.*?)</div>\s*<form class="hint-form"', page, re.S))
            shown = re.sub(r"<math[^>]*alttext=\"([^\"]*)\".*?</math>", r" \1 ", hints, flags=re.S)
            shown = re.sub(r"Hint \d+", "", html.unescape(re.sub(r"<[^>]+>", " ", shown)))
            assert shown.strip() and not _withheld_shown(shown, problem.variant), shown


def hint_blocks(transcript: str) -> str:
    """What the terminal printed as hints: each "Hint N:" line's text and the lines indented under it."""
    out, inside = [], False
    for line in transcript.splitlines():
        found = re.match(r"  Hint \d+:(.*)$", line)
        if found:
            out.append(found.group(1))
            inside = True
        elif inside and line.startswith("    "):
            out.append(line)
        else:
            inside = False
    return "\n".join(out)


def test_in_the_terminal_every_hint_asked_first_shows_no_answer(bank, tmp_path, monkeypatch, capsys):
    """The terminal showed "= 36.10 rad/s" for (c), and "36.10 rad/s" typed into (c) was then right."""
    import io
    import sys

    from exgen.cli import main
    from practice import session

    seed = SEEDS[3]
    monkeypatch.setattr(session, "practice_seed", lambda: seed)
    variant = make_variant(bank.get("vibration.beam_two_springs"), seed)
    typed = []
    for part in variant.template.parts:  # at each part: every hint, then move on without answering
        typed += ["h"] * 4 + [""]
    monkeypatch.setattr(sys, "stdin", io.StringIO("\n".join(typed + ["q"]) + "\n"))
    assert main(["practice", "--topic", variant.template.id, "--db", str(tmp_path / "p.sqlite3")]) == 0
    out = capsys.readouterr().out
    hints = hint_blocks(out)
    assert "\u221a(q/I_O)" in hints and not _withheld_shown(hints, variant), hints
    omega = f"{variant.step('omega_n').value:.4g}"
    assert grade_variant(variant, {"c": f"{omega} rad/s"}).parts[2].status == CORRECT  # ωₙ is (c) in rad/s ...
    assert omega not in out  # ... so no hint shows it


def test_hints_and_why_not_feedback_never_load_pint():
    """Reading a value in every unit of its kind goes through the stored unit table: building pint's
    registry took a second in the middle of a student's check."""
    import subprocess
    import sys

    script = """
import sys
from exgen.load.bank import load_bank
from exgen.solve.variant import make_variant
from graders.grade import grade_variant
from practice.hints import hint_ladder
for template in load_bank():
    variant = make_variant(template, 5)
    for part in template.parts:
        hint_ladder(variant, part.id)
    grade_variant(variant, {p.id: "123.4" for p in template.parts})
print("pint" in sys.modules)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "False"
