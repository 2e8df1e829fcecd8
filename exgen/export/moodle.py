"""Moodle XML: a category per question of the pool, holding its variants (the layout moodle.xml.j2 has
every format detail; Moodle's question/format/xml/format.php is the reference it follows)."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from markupsafe import Markup

from ..errors import ExgenError
from .html import LATEX_HTML, render
from .pool import Item, Pool, make_item

#: Files in a question's text and feedback are referred to through this prefix (format.php's file areas).
PLUGINFILE = "@@PLUGINFILE@@/"


@dataclass(frozen=True)
class Category:
    heading: str
    info: Markup
    items: tuple[Item, ...]


def moodle_xml(pool: Pool) -> str:
    """The pool as one Moodle XML document (UTF-8, `<?xml` on the first line)."""
    categories = []
    for question in pool.questions:
        items = tuple(make_item(question, i, v, LATEX_HTML, PLUGINFILE) for i, v in enumerate(question.variants, 1))
        items = tuple(item for item in items if item.gaps)
        if not items:
            continue
        template = question.template
        info = LATEX_HTML.text(f"{template.title} ({template.id}" + (f", after {template.source}" if template.source else "")
                               + f"): {len(items)} variants drawn by exgen; a random question from this category "
                               f"gives each student one.")
        categories.append(Category(f"{question.slot} {template.title}", info, items))
    text = render("moodle.xml.j2", title=pool.title, questions=categories).lstrip()
    if text.count("<![CDATA[") != text.count("]]>"):
        raise ExgenError("a question's text holds ']]>', which Moodle XML cannot carry inside CDATA")
    return text


def write_moodle(pool: Pool, path: Path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(moodle_xml(pool), encoding="utf-8")
    return path
