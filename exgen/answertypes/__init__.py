"""The answer types: one module each (number, angle, integer, choice, polar, ...), asked by name.

Every module in this package that defines `TYPE` (an `base.AnswerType`) is a type; adding a type is
adding its module. Bank loading, variants, validate, the renderers and the grader reach a type only
through `answer_type(part)` and never branch on its name.
"""
from __future__ import annotations

import importlib
import pkgutil
from functools import lru_cache

from ..load.template import PartSpec
from .base import AnswerType, Given


@lru_cache(maxsize=1)
def registry() -> dict[str, AnswerType]:
    """Every type, by name, found among this package's modules."""
    found = {}
    for info in pkgutil.iter_modules(__path__):
        kind = getattr(importlib.import_module(f"{__name__}.{info.name}"), "TYPE", None)
        if isinstance(kind, AnswerType):
            found[kind.name] = kind
    return found


def names() -> tuple[str, ...]:
    return tuple(sorted(registry()))


def answer_type(part_or_name: PartSpec | str) -> AnswerType:
    """The type of a part (or the type of that name); KeyError names the known types."""
    name = part_or_name if isinstance(part_or_name, str) else part_or_name.type
    try:
        return registry()[name]
    except KeyError:
        raise KeyError(f"{name!r} is not an answer type; the types are {', '.join(names())}") from None


def read(text: str, part: PartSpec) -> Given:
    """What a student typed for `part`, in the asked form: FormatProblem if it cannot be read,
    WrongKind if it is an answer of another kind. Never evaluates the text."""
    return answer_type(part).read(text, part)
