"""The words that say what a draw decides, and the texts that state them whatever the draw says.

The draw decides each of a template's word choices (a rotor's sense, clockwise or counter-clockwise; the
turn, left or right; a material) and so the answer of each choice part (raises the bow or lowers it).
A text shown beside a variant (a mistake's feedback, a hint) that names one of those values, or a word
students write for it (anticlockwise is counter-clockwise), in words it prints in every draw, states a
fact of some draws as a fact of all: a student whose sheet says otherwise is told the opposite of their
own data. Such a text must be written from the variant (`{{ turn }}`, a `{% if %}`, a word step of the
solver: `{{ steps.spin_vector }}`) or not state it. The words come from each template's own choices,
never from a list: a value is a word of three letters or more ("1", "A" and "AB" name labels, not facts).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..answertypes.choice import canonical, choice_aliases
from ..load.mistake_messages import message_for
from ..load.template import PartSpec, Template
from ..load.text import fixed_parts

_WORD = re.compile(r"[a-z]+(?:'[a-z]+)?")
_TEXT_WORD = re.compile(r"[A-Za-z]+(?:'[A-Za-z]+)?")
_WORTH = re.compile(r"[A-Za-z][A-Za-z \-]{2,}")


@dataclass(frozen=True)
class DrawWord:
    """A run of words that names one value the draw decides: `value` of the parameter or choice part `owner`."""

    words: tuple[str, ...]
    value: str
    owner: str  # "sense" (a parameter) or "part (b)" (a choice answer)
    param: str = ""  # the parameter's name, when the owner is one

    @property
    def text(self) -> str:
        return " ".join(self.words)


#: draw_words by template (kept with it, so that its id names it while cached): validate asks once a variant.
_WORDS: dict[int, tuple[Template, tuple]] = {}


def draw_words(template: Template) -> tuple[DrawWord, ...]:
    """Every run of words that names a value the template's draw decides, longest first."""
    cached = _WORDS.get(id(template))
    if cached is None or cached[0] is not template:
        cached = _WORDS[id(template)] = (template, _draw_words(template))
    return cached[1]


def _draw_words(template: Template) -> tuple[DrawWord, ...]:
    found: list[DrawWord] = []
    for spec in template.params:  # one that only chooses what the figure draws is stated by no text
        if spec.given and spec.choices and all(isinstance(c, str) for c in spec.choices):
            found += _named(spec.choices, spec.name, spec.name)
    for part in template.parts:
        if part.type == "choice":
            found += _named(part.options.get("choices", ()), f"part ({part.id})")
    unique = {(w.words, w.owner): w for w in found}
    names = _names_on_every_sheet(template)
    kept = [w for w in unique.values() if not spans(names, (w,))]
    return tuple(sorted(kept, key=lambda w: -len(w.words)))


def _names_on_every_sheet(template: Template) -> list[str]:
    """The words the statement and the asks print in every draw: what every sheet names (the sun, the ring
    and the arm of an epicyclic; a car's front left wheel) is a thing of the machine, not a fact of the draw."""
    runs = []
    for text in [template.statement] + [p.ask for p in template.parts]:
        try:
            runs += list(fixed_parts(text))
        except ValueError:
            continue
    return [w for run in runs for w in tokens(run) + ["|"]]


def _named(values, owner: str, param: str = "") -> list[DrawWord]:
    """The runs of words for each value that is a word, and for the aliases of each; one value only, so
    that a run two values share (the 'the bow' of 'raises the bow' and 'lowers the bow') names neither."""
    values = [str(v) for v in dict.fromkeys(values) if _WORTH.fullmatch(str(v))]
    if len(values) < 2:
        return []
    aliases: dict[str, list[str]] = {}
    for alias, target in choice_aliases().items():
        aliases.setdefault(canonical(target), []).append(alias)
    runs = []
    for value in values:
        for phrase in [value, *aliases.get(canonical(value), ())]:
            words = tuple(_WORD.findall(canonical(phrase)))
            if words and len("".join(words)) >= 3:
                runs.append(DrawWord(words, value, owner, param))
    return runs


def tokens(text: str) -> list[str]:
    """A text's words as the draw's words are matched, in lower case; a word joined to the one before it by
    a hyphen starts with "-" ("counter", "-clockwise"), so that a run is matched as whole words only (the
    "right" of "right-hand rule" is no turn)."""
    text = text.replace("\u2212", "-").replace("\u2011", "-").replace("_", " ")
    return [("-" if m.start() > 1 and text[m.start() - 1] == "-" and text[m.start() - 2].isalpha() else "")
            + m.group().lower() for m in _TEXT_WORD.finditer(text)]


def spans(words_of_text: list[str], words: tuple[DrawWord, ...]) -> list[tuple[int, int, tuple[DrawWord, ...]]]:
    """(start, end, owners) of each run of the draw's words among a text's words (`tokens`), as whole
    words, each run once where it stands (a longer run first: "counter-clockwise" is not also
    "clockwise"), with every owner those words name (three sites may each draw a slot)."""
    bare = [w.lstrip("-") for w in words_of_text]
    taken = [False] * len(words_of_text)
    found = []
    for run in dict.fromkeys(w.words for w in words):
        n = len(run)
        for start in range(len(words_of_text) - n + 1):
            whole = not words_of_text[start].startswith("-") and not (
                start + n < len(words_of_text) and words_of_text[start + n].startswith("-"))
            if whole and tuple(bare[start:start + n]) == run and not any(taken[start:start + n]):
                taken[start:start + n] = [True] * n
                found.append((start, start + n, tuple(w for w in words if w.words == run)))
    return sorted(found, key=lambda f: f[0])


def named_in(text: str, words: tuple[DrawWord, ...]) -> list[tuple[DrawWord, ...]]:
    """The owners of each run of the draw's words a text names (see spans)."""
    return [owners for _, _, owners in spans(tokens(text), words)]


def part_texts(part: PartSpec) -> list[tuple[str, str, str]]:
    """(where, text, mistake) of every text a part shows beside a variant: each named mistake's feedback (its
    `say:` or the name's default text, with the mistake's name) and each hint (with none)."""
    texts = [(f"mistake {m.when!r}" + ("" if m.say else " (its default text)"), message_for(m.when, m.say), m.when)
             for m in part.mistakes]
    return texts + [(f"hint {i}", hint, "") for i, hint in enumerate(part.hints, 1)]


def shown_texts(variant) -> list[tuple[str, str, str, str]]:
    """(part id, where, text, mistake) of every text of the template a student can be shown beside this
    variant: the feedback of each mistake a part names that the variant records, and each hint."""
    return [(part.id, where, text, mistake) for part in variant.template.parts
            for where, text, mistake in part_texts(part) if not mistake or mistake in variant.mistakes[part.id]]


def misstatements(variant) -> list[str]:
    """Each text shown beside the variant that cannot be written with it, or that states, in words it
    prints in every draw, a value the draw decided otherwise: in any text, a value of a word choice other
    than the one drawn; in a mistake's feedback, which speaks of this sheet's case, an option of a choice
    part other than its answer (unless the run names two options or more: a rule that tells cases apart,
    as a hint states a rule, "isochronous when F is proportional to r", before the answer is known)."""
    words = draw_words(variant.template)
    params_only = tuple(w for w in words if w.param)
    problems = []
    import jinja2

    for part_id, where, text, mistake in shown_texts(variant):
        try:
            variant.fill(text)
            fixed = fixed_parts(text)
        except (ValueError, jinja2.TemplateError) as exc:  # a text's error is the template's, named with it
            problems.append(f"part {part_id}, {where}: cannot be written: {exc}")
            continue
        for run in fixed:
            named = named_in(run, words if mistake else params_only)
            wrong = disagreeing(named, variant)
            if wrong:
                said = described(wrong, variant)
                problems.append(f"part {part_id}, {where}: says {said} whatever the draw: "
                                + ("give the part a `say:` written from the variant" if "default" in where else
                                   "write it from the variant ({{ name }}, {% if %}, {{ steps.name }}) or leave it out"))
    return problems


def disagreeing(named: list[tuple[DrawWord, ...]], variant) -> list[DrawWord]:
    """Of the runs a text names, those whose every owner the variant decided otherwise (a run naming two
    options or more of one choice part is a rule between cases, and agrees)."""
    every = [w for group in named for w in group]
    return [group[0] for group in named if not any(_agrees(w, variant, every) for w in group)]


def _own(word: DrawWord, variant) -> str:
    """The value the variant has for the word's owner: the parameter drawn, or the choice part's answer."""
    if word.param:
        return variant.param(word.param).text
    return str(variant.answers[word.owner[len("part ("):-1]].value)


def _agrees(word: DrawWord, variant, named: list[DrawWord]) -> bool:
    if canonical(word.value) == canonical(_own(word, variant)):
        return True
    if word.param:
        return False
    return len({canonical(w.value) for w in named if w.owner == word.owner}) > 1


def described(wrong: list[DrawWord], variant) -> str:
    """"'clockwise' (a value of sense, counter-clockwise here), ..." """
    return ", ".join(dict.fromkeys(f"'{w.text}' ({_whose(w)}, {_own(w, variant)} here)" for w in wrong))


def _whose(word: DrawWord) -> str:
    return f"a value of {word.owner}" if word.param else f"an option of {word.owner}"
