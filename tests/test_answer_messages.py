"""What an answer type says about an answer quotes what was typed only as exgen.echo.shown leaves it: no
control or invisible formatting characters (bidi overrides reorder what the reader sees), whatever the type.
Checked over every template of the bank, every part, at several seeds."""
import unicodedata

import pytest

from exgen.echo import _DROPPED
from exgen.solve.variant import make_variant
from graders.grade import grade_variant

HIDDEN = ["\u202e", "\u2066", "\u200f", "\u200b", "\x1b", "\u2028", "\ufeff", "\x07"]
SHAPES = ["{h}left", "12{h}.5 rpm", "clock{h}wise", "{h}{h}x{h}", "3{h} N at 40 deg", "K/{h}m", "{h}"]


def hidden_in(text: str) -> list[str]:
    return [c for c in text if unicodedata.category(c) in _DROPPED]


def test_every_part_of_every_template_keeps_hidden_characters_out_of_its_messages(bank):
    found = []
    for template in bank:
        for seed in (1, 2):
            variant = make_variant(template, seed)
            for part in template.parts:
                for hidden in HIDDEN:
                    for shape in SHAPES:
                        answer = shape.format(h=hidden)
                        result = grade_variant(variant, {part.id: answer})
                        message = next(p.message for p in result.parts if p.part_id == part.id)
                        if hidden_in(message):
                            found.append((template.id, part.id, part.type, answer, message))
    assert not found, found[:5]


@pytest.mark.parametrize("hidden", HIDDEN)
def test_a_choice_answer_that_is_no_choice_is_quoted_cleaned(bank, hidden):
    template = next(t for t in bank if any(p.type == "choice" for p in t.parts))
    part = next(p for p in template.parts if p.type == "choice")
    result = grade_variant(make_variant(template, 3), {part.id: f"{hidden}tfel{hidden} or so"})
    message = next(p.message for p in result.parts if p.part_id == part.id)
    assert "tfel or so" in message.replace("  ", " ") and not hidden_in(message)
