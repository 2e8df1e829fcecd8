"""Default feedback for the mistakes solvers record by name, kept as data in exgen/data/mistakes.yaml.

A part's own `say:` wins; a name with neither gets UNNAMED_MISTAKE, which names the method in words.
"""
from __future__ import annotations

from functools import lru_cache
from importlib import resources

import yaml

#: When a solver records a mistake the data file does not know yet.
UNNAMED_MISTAKE = "That is what the method '{words}' gives, a known slip: check that step of your working."


@lru_cache(maxsize=1)
def default_messages() -> dict[str, str]:
    """Every default message, by mistake name."""
    text = resources.files("exgen").joinpath("data/mistakes.yaml").read_text("utf-8")
    return {str(name): " ".join(str(message).split()) for name, message in (yaml.safe_load(text) or {}).items()}


def message_for(name: str, say: str = "") -> str:
    """The template's own text if it gives one, else the default for the name."""
    return say or default_messages().get(name) or UNNAMED_MISTAKE.format(words=name.replace("_", " "))
