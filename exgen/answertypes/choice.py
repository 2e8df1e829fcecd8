"""One of a listed set of words ("increase" or "decrease"), compared by canonical name: case, hyphens,
underscores and spacing do not matter, and the aliases in exgen/data/choice_aliases.txt are read
("ccw" is counter-clockwise). A sentence that names exactly one choice reads as it ("to the left",
"Left."). A word that is none of the choices is a format problem, not a wrong answer.
"""
from __future__ import annotations

from functools import lru_cache
from importlib import resources
from typing import Mapping

from ..echo import shown
from ..errors import FormatProblem
from ..load.template import PartSpec
from .base import AnswerType, Given, Report, refuse_long
from .lms import ChoiceGap, Wrong

MAX_CHOICE_LENGTH = 80
WRONG_CHOICE = "not the right choice"


@lru_cache(maxsize=4096)
def canonical(name: str) -> str:
    """'Crossed belt', 'crossed-belt' and ' CROSSED_belt ' all read as 'crossed belt'."""
    return " ".join(str(name).replace("-", " ").replace("_", " ").lower().split())


@lru_cache(maxsize=1)
def choice_aliases() -> dict[str, str]:
    """Other words for the choices templates use ("ccw" for counter-clockwise), from exgen's data."""
    text = resources.files("exgen").joinpath("data/choice_aliases.txt").read_text("utf-8")
    pairs = (line.split("=", 1) for line in text.splitlines() if line.strip() and not line.startswith("#"))
    return {a.strip(): b.strip() for a, b in pairs}


@lru_cache(maxsize=1)
def _canonical_aliases() -> dict[str, str]:
    return {canonical(k): canonical(v) for k, v in choice_aliases().items()}


def choice(given: str, expected: str, aliases: Mapping[str, str] | None = None) -> bool:
    """The canonical name of the given choice, after aliases ({'ccw': 'anticlockwise'}), is the expected one."""
    table = _canonical_aliases() if aliases is choice_aliases() else \
        {canonical(k): canonical(v) for k, v in (aliases or {}).items()}
    key = canonical(given)
    return table.get(key, key) == canonical(expected)


class Choice(AnswerType):
    name = "choice"
    part_keys = ("choices",)

    def load_options(self, spec: Mapping, report: Report) -> dict:
        choices = spec.get("choices")
        if not isinstance(choices, list) or not choices:
            report(("choices",), "a choice answer needs its list of choices")
            return {"choices": ()}
        return {"choices": tuple(str(c) for c in choices)}

    def problem(self, value, part: PartSpec) -> str | None:
        choices = part.options.get("choices", ())
        return None if value in choices else f"answer {value!r} is not one of {choices}"

    def hint(self, part: PartSpec) -> str:
        choices = part.options.get("choices", ())
        return "one of: " + ", ".join(choices) if choices else "a word"

    def form_hint(self, part: PartSpec) -> str:
        return "one of: " + ", ".join(part.options.get("choices", ()))

    def form_choices(self, part: PartSpec) -> tuple[str, ...]:
        return tuple(part.options.get("choices", ()))

    def read(self, text: str, part: PartSpec) -> Given:
        refuse_long(text, MAX_CHOICE_LENGTH)
        word = " ".join(text.split())
        choices = part.options.get("choices", ())
        if any(choice(word, c, choice_aliases()) for c in choices):
            return Given(text, word)
        named = named_choice(word, choices)
        if named is None:
            raise FormatProblem(f"'{shown(text, 40)}' is not one of the choices")
        return Given(text, named)

    def example(self, part: PartSpec) -> str:
        return part.options.get("choices", ("",))[0]

    def format_hint(self, part: PartSpec) -> str:
        """'write "raises the bow" or "lowers the bow"': each choice quoted, since a choice may be words."""
        quoted = [f'"{c}"' for c in part.options.get("choices", ())]
        return "write " + (", ".join(quoted[:-1]) + " or " + quoted[-1] if len(quoted) > 1 else "".join(quoted))

    def matches(self, given, expected, part: PartSpec, widen: float = 1.0) -> bool:
        return choice(str(given), str(expected), choice_aliases())

    def gives_away(self, value, answer) -> bool:
        """A worked value that is the chosen word itself ("clockwise")."""
        return isinstance(value, str) and choice(value, str(answer.value), choice_aliases())

    def wrong_message(self, given: Given, part: PartSpec) -> str:
        return WRONG_CHOICE

    def nudges(self, value, part: PartSpec) -> tuple[str, ...]:
        return tuple(c for c in part.options.get("choices", ()) if not choice(c, value, choice_aliases()))

    def overrides(self, part: PartSpec, value, variant) -> dict[str, str]:
        """The listed choice the student's word stands for, in the answer's step: later steps that
        follow from the choice (a direction, a sense) are worked from the student's."""
        meant = next((c for c in part.options.get("choices", ()) if choice(value, c, choice_aliases())), None)
        return {part.answer: meant} if meant is not None else {}

    def lms_gaps(self, part: PartSpec, value, mistakes) -> tuple[ChoiceGap, ...]:
        """The listed choices; a wrong choice a known mistake leads to carries its feedback (the first
        mistake's, in the order the grader tries them, when several lead to it)."""
        choices = tuple(part.options.get("choices", ()))
        wrong: dict[str, Wrong] = {}
        for name, (given, message) in mistakes.items():
            for c in choices:
                if c != value and c not in wrong and self.matches(given, c, part):
                    wrong[c] = Wrong(c, message, name)
        return (ChoiceGap("", choices, str(value), wrong=tuple(wrong.values())),)

    def sample_part(self) -> PartSpec:
        return PartSpec("a", "does the power increase or decrease?", "trend", type=self.name,
                        options={"choices": ("increase", "decrease")})


_NEGATIONS = frozenset({"not", "no", "neither", "nor", "never", "isn't", "isnt", "doesn't", "doesnt", "won't", "cannot"})
_PUNCTUATION = str.maketrans({c: " " for c in "()[]{}'\"`.,;:!?"})


def named_choice(text: str, choices) -> str | None:
    """The one choice a sentence names ("to the left", "Left.", "the left spring is stretched", "it is a
    mechanism"), by its words or an alias's as a whole run of words; None when it names none, more than
    one ("left, right"), or says "not" outside the choice's own words ("not left")."""
    words = canonical(text.translate(_PUNCTUATION)).replace("’", "'").split()
    phrases = [(canonical(c).split(), c) for c in choices]
    phrases += [(alias.split(), c) for alias, target in _canonical_aliases().items() for c in choices
                if target == canonical(c)]
    spans = [(start, start + len(phrase), c) for phrase, c in phrases if phrase
             for start in range(len(words) - len(phrase) + 1) if words[start:start + len(phrase)] == phrase]
    kept = [s for s in spans if not any(o[0] <= s[0] and s[1] <= o[1] and o[1] - o[0] > s[1] - s[0] for o in spans)]
    if len({c for _, _, c in kept}) != 1:
        return None
    covered = {i for start, end, _ in kept for i in range(start, end)}
    if any(w in _NEGATIONS for i, w in enumerate(words) if i not in covered):
        return None
    return kept[0][2]


TYPE = Choice()
