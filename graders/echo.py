"""Student text, made safe to echo anywhere (feedback, reports, messages): one line, no control or
invisible formatting characters (bidi overrides such as U+202E reorder what a reader sees), short
(exgen.echo), and, for Markdown and HTML, without characters they read as syntax."""
from __future__ import annotations

from exgen.echo import ELLIPSIS, shown

__all__ = ["ELLIPSIS", "LOOK_ALIKES", "look_alike", "shown", "shown_code"]

#: Characters a Markdown code span (a backtick) or HTML (a tag) would read as syntax, swapped for look-alikes.
LOOK_ALIKES = str.maketrans({"`": "'", "<": "\u2039", ">": "\u203a"})


def shown_code(text, limit: int = 80) -> str:
    """`shown` text safe inside a Markdown code span, and as HTML should the page be converted: no
    backticks or tags (look-alikes instead), never empty (an empty code span is not one)."""
    return look_alike(shown(text, limit)) or " "


def look_alike(text: str) -> str:
    """`text` with LOOK_ALIKES for backticks and angle brackets (translated only when it has any)."""
    return text.translate(LOOK_ALIKES) if "`" in text or "<" in text or ">" in text else text
