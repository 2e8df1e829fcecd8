"""Every error exgen raises on purpose, under one base class.

Each carries the data it is about (file, key, line, template) and builds a message
that names it, so the CLI can print it and exit without a traceback.
"""
from __future__ import annotations

import difflib


class ExgenError(Exception):
    """Base class: an expected failure with a message meant for the user."""


class TemplateError(ExgenError, ValueError):
    """A template file that cannot be used; names the file, the line and column, and the key (`words`: the
    key as an author reads it, "part (b), tol", where `key` is "parts.1.tol")."""

    def __init__(self, path, key: str, message: str, line: int | None = None, column: int | None = None,
                 words: str | None = None):
        self.path, self.key, self.line, self.column, self.detail = str(path), key, line, column, message
        said = words if words is not None else key
        where = _where(self.path, line, column)
        super().__init__(f"{where}: {said}: {message}" if said else f"{where}: {message}")


class BankError(ExgenError, ValueError):
    """Several template problems found in one pass over a bank."""

    def __init__(self, errors: list[TemplateError]):
        self.errors = errors
        lines = "\n".join(f"  {e}" for e in errors)
        super().__init__(f"{len(errors)} problem(s) in the template bank:\n{lines}")


class UnknownTemplate(ExgenError, KeyError):
    def __init__(self, template_id: str, known: list[str]):
        self.template_id = template_id
        close = [k for k in known if template_id.split(".")[-1] in k][:5] or \
            difflib.get_close_matches(template_id, known, n=3, cutoff=0.8)  # a typo: 'flat_belt_powr'
        hint = f" Did you mean: {', '.join(close)}?" if close else " Run `exgen list` to see them."
        super().__init__(f"no template with id {template_id!r}.{hint}")

    def __str__(self) -> str:  # KeyError would quote the message
        return self.args[0]


class InvalidDraw(ExgenError, ValueError):
    """Drawn values that give no valid problem: a template's `require:`, a solver's `d.require(...)`, or a
    solver raising it by name. The one error that makes a draw be retried."""


class NoAnswer(ExgenError, ValueError):
    """A solver step that holds no answer of the asked kind (not a finite number, not an expression)."""


class SolverFailure(ExgenError, RuntimeError):
    """A solver that raised anything but InvalidDraw. In a draw it is a defect in the solver or its
    physics, never a redraw; for values a user gave (`given`), the physics refusing them. Names the
    template, the seed, the exception and where it rose."""

    def __init__(self, template_id: str, error: BaseException, where: str = "", seed: int | None = None,
                 given: str = ""):
        self.template_id, self.error, self.where, self.seed, self.given = template_id, error, where, seed, given
        self.reason = f"{type(error).__name__}: {error}" if str(error) else type(error).__name__
        of = f"{template_id}, seed {seed}" if seed is not None else template_id
        at = f" at {where}" if where else ""
        if given:
            super().__init__(f"{of}: the solver cannot work from {given}: {self.plain}" if self._worded else
                             f"{of}: the solver cannot work from {given}: {self.reason}{at}")
        else:
            super().__init__(f"{of}: the solver failed with {self.reason}{at}")


    @property
    def _worded(self) -> bool:
        """Whether the error says in words what is wrong (the physics refusing a value), not Python's terms."""
        return isinstance(self.error, ValueError) and str(self.error) not in ("", "math domain error") \
            and type(self.error) is ValueError

    @property
    def plain(self) -> str:
        """What went wrong, for someone who gave the values: the physics' own words where it has them."""
        return str(self.error) if self._worded else "the working reaches an impossible step: " + (
            "a square root or inverse sine of a value out of its range" if "math domain" in str(self.error)
            else self.reason)


class DrawError(ExgenError, RuntimeError):
    """A template whose constraints could not be satisfied within the allowed tries."""

    def __init__(self, template_id: str, tries: int, last_reason: str):
        self.template_id, self.tries, self.last_reason = template_id, tries, last_reason
        super().__init__(
            f"{template_id}: no valid problem in {tries} draws (last rejection: {last_reason}); "
            "widen the parameter ranges or relax the constraints"
        )


class FormatProblem(ExgenError, ValueError):
    """An answer that cannot be read: a format problem, told apart from a wrong answer (no marks, no penalty)."""


class QuantityError(FormatProblem):
    """Text that cannot be read as a quantity (a format problem, not a wrong answer)."""


class WrongKind(ExgenError, ValueError):
    """A readable answer of the wrong kind (a length where a force is asked): wrong, and said why."""


class DimensionError(ExgenError, ValueError):
    """A quantity of the wrong kind, e.g. a length where a force was asked."""

    def __init__(self, given_unit: str, given_dim: str, asked_unit: str, asked_dim: str):
        self.given_unit, self.given_dim, self.asked_unit, self.asked_dim = given_unit, given_dim, asked_unit, asked_dim
        super().__init__(
            f"'{given_unit}' is {_article(given_dim)} {given_dim}, but {_article(asked_dim)} {asked_dim} is asked (in {asked_unit})"
        )


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


class AssignmentError(ExgenError, ValueError):
    """An assignment file or roster that cannot be used; names the file, the line and column where known,
    and the problem (several problems: one line each)."""

    def __init__(self, path, message: str, line: int | None = None, column: int | None = None,
                 more: tuple[tuple[str, int | None, int | None], ...] = ()):
        self.path, self.line, self.column, self.detail = str(path), line, column, message
        self.problems = ((message, line, column), *more)
        lines = [f"{_where(self.path, ln, col)}: {text}" for text, ln, col in self.problems]
        head = f"{len(lines)} problems in {self.path}:\n  " if more else ""
        super().__init__(head + "\n  ".join(lines))


def _where(path: str, line: int | None, column: int | None) -> str:
    return (f"{path}:{line}:{column}" if column else f"{path}:{line}") if line else path


class SecretError(ExgenError, RuntimeError):
    """No course secret available, or one that does not match what was issued."""


class SubmissionError(ExgenError, ValueError):
    """An answer file that cannot be read at all; names the file and, when known, the line."""

    def __init__(self, path, message: str, line: int | None = None):
        self.path, self.line, self.detail = str(path), line, message
        where = f"{self.path}:{line}" if line else self.path
        super().__init__(f"{where}: {message}")
