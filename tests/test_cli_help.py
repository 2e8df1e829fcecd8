"""`--help` of every command says what it does and shows it done: a description, help for every argument,
and examples that are real commands (they parse, name templates that exist and example files that exist)."""
import argparse
import shlex
from pathlib import Path

import pytest

from exgen.cli import build_parser

ROOT = Path(__file__).parent.parent


def commands() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(action.choices)


def examples(help_text: str) -> list[list[str]]:
    """The commands listed under 'example(s):' at the end of a help text, continuation lines joined."""
    lines = help_text.split("example:\n" if "example:\n" in help_text else "examples:\n", 1)[1]
    return [shlex.split(c) for c in lines.replace("\\\n", " ").splitlines() if c.startswith("  exgen ")]


@pytest.mark.parametrize("name", sorted(commands()))
def test_every_command_says_what_it_does_with_an_example(name, bank):
    parser = commands()[name]
    text = parser.format_help()
    assert parser.description and len(parser.description) > 40
    arguments = [a for a in parser._actions if not isinstance(a, argparse._HelpAction)]
    assert [a.dest for a in arguments if not a.help] == []
    found = examples(text)
    assert found
    for argv in found:
        assert argv[:2] == ["exgen", name]
        args = build_parser().parse_args(argv[1:])  # a usage mistake would exit here
        named = [v for v in vars(args).values() for v in (v if isinstance(v, list) else [v]) if isinstance(v, str)]
        for value in named:
            if value.startswith("examples/"):
                assert (ROOT / value).exists(), value
            elif "." in value and value.split(".")[0] in {t.topic for t in bank}:
                assert bank.get(value), value


def test_the_top_level_help_starts_a_newcomer_off():
    text = build_parser().format_help()
    assert "exgen generate examples/tutorial1.yaml" in text and "exgen COMMAND --help" in text
    for argv in examples(text):
        build_parser().parse_args(argv[1:])
