"""A template's texts: Jinja2 with StrictUndefined, so a misspelt parameter is an error, not a blank.

A statement and an ask see the given values by name. A text shown beside a variant once it is solved (a
mistake's `say:`, a hint) sees them too, and the solver's steps whose values are words under STEPS
(`{{ steps.spin_vector }}` prints "towards the bow"), so that what it says of the draw is written from it.
"""
from __future__ import annotations

import re
from functools import lru_cache

#: The name a feedback text or a hint reads the solver's word steps under.
STEPS = "steps"


@lru_cache(maxsize=1)
def environment():
    import jinja2  # only for texts with more than {{ name }} in them: most commands never need it

    return jinja2.Environment(undefined=jinja2.StrictUndefined, autoescape=False,
                              keep_trailing_newline=False, trim_blocks=True, lstrip_blocks=True)


@lru_cache(maxsize=1024)
def _compile(text: str):
    return environment().from_string(text)


def undeclared_names(text: str) -> set[str]:
    """Names a text refers to; raises ValueError on a Jinja syntax error."""
    import jinja2.meta

    try:
        return set(jinja2.meta.find_undeclared_variables(environment().parse(text)))
    except jinja2.TemplateSyntaxError as exc:
        raise ValueError(f"template syntax error on line {exc.lineno}: {exc.message}") from exc


#: `{{ name }}`: the only markup most statements and asks use, filled in without Jinja (what Jinja would
#: print: str() of the value); a text with any other markup, or a name missing, goes through Jinja.
_PLAIN_NAME = re.compile(r"\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}")


def render_text(text: str, context: dict) -> str:
    if "{%" not in text and "{#" not in text and "\r" not in text:
        try:
            filled = _PLAIN_NAME.sub(lambda m: str(context[m.group(1)]), text)
        except KeyError:
            filled = None
        if filled is not None and "{{" not in _PLAIN_NAME.sub("", text):
            return filled.strip()
    return _compile(text).render(context).strip()


@lru_cache(maxsize=4096)
def fixed_parts(text: str) -> tuple[str, ...]:
    """The words a text prints in every draw: its literal runs outside any `{% if %}` or `{% for %}`
    (what `{{ }}` prints, and what a branch prints, are written from the variant). Raises ValueError
    on a Jinja syntax error."""
    import jinja2
    from jinja2 import nodes

    try:
        tree = environment().parse(text)
    except jinja2.TemplateSyntaxError as exc:
        raise ValueError(f"template syntax error on line {exc.lineno}: {exc.message}") from exc
    return tuple(node.data for output in tree.body if isinstance(output, nodes.Output)
                 for node in output.nodes if isinstance(node, nodes.TemplateData))
