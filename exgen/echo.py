"""Student text, made safe to echo anywhere (feedback, reports, messages, pages): one line, no control or
invisible formatting characters (bidi overrides such as U+202E reorder what a reader sees), short.

Here, in exgen, because an answer type's own messages quote what a student typed; graders.echo adds the
escapes of Markdown and HTML."""
from __future__ import annotations

import re
import unicodedata

#: Unicode categories never echoed: controls, invisible formatting (bidi, zero-width), surrogates,
#: private use, unassigned, and line or paragraph separators.
_DROPPED = {"Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"}
ELLIPSIS = "\u2026"
_ASCII_CONTROLS = {c: " " for c in [*range(32), 127]}


class _Blanking(dict):
    """A str.translate table turning every character never echoed into a space: it learns each character
    the first time one is seen (the category looked up once, not at every echo), up to a bound."""

    def __missing__(self, code: int):
        out = " " if unicodedata.category(chr(code)) in _DROPPED else code
        if len(self) < 20_000:  # hostile text of every code point cannot grow it without end
            self[code] = out
        return out


_BLANKING = _Blanking(_ASCII_CONTROLS)


def shown(text, limit: int = 80, word: int | None = None) -> str:
    """`text` as one line of at most `limit` characters, without characters that hide or reorder text.
    With `word`, any run of more than `word` non-blank characters is cut short first, so a message
    quoting a huge answer keeps its own words ("cannot read '9999…' as a number ...")."""
    text = str(text)
    if len(text) <= limit and text.isprintable() and "  " not in text and text == text.strip() \
            and (not word or len(text) <= word or max(map(len, text.split(" "))) <= word):
        # already one clean line: most of what a grading run echoes (statuses, ids, numbers, "168.7°",
        # messages). Printable text holds no character the cleaning below drops, and no blank but the space.
        return text
    if word:
        text = re.sub(rf"\S{{{word + 1},}}", lambda m: m.group()[:word] + ELLIPSIS, text)
    if len(text) > 8 * limit:  # never scan more than needed: a 1 MB answer costs what a short one does
        text = text[: 8 * limit] + ELLIPSIS
    cleaned = text.translate(_ASCII_CONTROLS if text.isascii() else _BLANKING)
    cleaned = " ".join(cleaned.split())
    return cleaned if len(cleaned) <= limit else cleaned[: limit - 1].rstrip() + ELLIPSIS
