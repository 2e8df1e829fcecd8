"""The Jinja2 environment for output layouts (exgen/render/layouts/*.j2).

StrictUndefined: a misspelt name in a layout is an error, not an empty string. Layouts get
text already written for their format (context.py), so nothing is escaped here.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import jinja2

from .context import wider_than_text
from .mathtext import typst_string

LAYOUTS = Path(__file__).parent / "layouts"


@lru_cache(maxsize=1)
def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(LAYOUTS)), undefined=jinja2.StrictUndefined, autoescape=False,
        trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True,
    )
    env.filters["typst_str"] = typst_string
    env.filters["wider_than_text"] = lambda svg: "true" if wider_than_text(svg) else "false"
    return env


def render(layout: str, context: dict) -> str:
    return environment().get_template(layout).render(context)
