"""A whitelist grammar for answers that are formulas: "sqrt(2*K/(3*M + 8*m))/(2*pi)", "(2K/(3M+8m))^(1/2)/(2π)".

Student text is data: it is never given to Python's evaluator or parser, nor to sympy. Limits are
checked before any work (length, then characters, then bracket depth in one pass), and a tree is
built by a small recursive-descent parser over this grammar:

    sum     = product {("+" | "-") product}
    product = unary {("*" | "/" | juxtaposition) unary}     2K, 2(K + m), (a)(b): implicit "*"
    unary   = {"+" | "-"} power
    power   = atom ["^" unary]                               "**" is "^"; no power in an exponent
    atom    = number | symbol | pi | function "(" sum ")" | "(" sum ")" | "√" power

Numbers are 2, 2.5, .5, 1.5e3; symbols are the ones a part declares (nothing else); functions are
FUNCTIONS; π, −, ×, ·, ÷, √ and superscript powers (K², x⁻¹) are read as their ASCII forms. After "/",
a product written without "*" is refused as ambiguous (1/2K: is it K/2 or 1/(2K)?): brackets decide.
A tree is nested tuples: ("num", 2.0), ("sym", "K"), ("pi",), ("neg", x), (op, a, b) for op in
add sub mul div pow, ("call", name, x).
"""
from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass
from typing import Mapping

from ..errors import FormatProblem
from ..load.template import default_symbol

MAX_LENGTH = 200          # characters, checked before anything else
MAX_DEPTH = 12            # brackets inside brackets
MAX_EXPONENT = 10         # |n| of a number used as an exponent
FUNCTIONS = {
    "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin,
    "acos": math.acos, "atan": math.atan, "exp": math.exp, "ln": math.log, "log10": math.log10, "abs": abs,
}
CONSTANTS = {"pi": math.pi}

_GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ζ": "zeta", "η": "eta", "θ": "theta",
    "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu", "ξ": "xi", "π": "pi", "ρ": "rho", "σ": "sigma", "τ": "tau",
    "φ": "phi", "χ": "chi", "ψ": "psi", "ω": "omega", "Δ": "Delta", "Θ": "Theta", "Φ": "Phi", "Ω": "Omega",
}
_SIGNS = str.maketrans({"\u2212": "-", "\u2013": "-", "\u00d7": "*", "\u00b7": "*", "\u22c5": "*", "\u2217": "*",
                        "\u00f7": "/", "\u00a0": " ", "\u2009": " ", "\u202f": " ", "[": "(", "]": ")", "{": "(",
                        "}": ")", **_GREEK})
_SUPERSCRIPT = re.compile("[\u207a\u207b]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+")
_SUPERSCRIPT_DIGITS = str.maketrans("\u207a\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079",
                                    "+-0123456789")
_ALLOWED = re.compile(r"[A-Za-z0-9_.+\-*/^()\s\u221a]*")
_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
                    r"|(?P<op>\*\*|[-+*/^()\u221a]))")
_PLUS, _TIMES, _POWER = 1, 2, 4   # precedence when printing: sums, products, powers


class ExpressionError(FormatProblem):
    """Text that is not an expression of the allowed grammar over the allowed symbols."""


@dataclass(frozen=True)
class Expression:
    """A parsed expression over named symbols: evaluated by walking its tree, printed as text or LaTeX."""

    tree: tuple
    symbols: tuple[str, ...]

    @classmethod
    def parse(cls, text: str, symbols) -> "Expression":
        """Read `text` over the `symbols` given (names); ExpressionError saying why it cannot be read."""
        symbols = tuple(symbols)
        return cls(_Parser(text, symbols).parse(), symbols)

    def __call__(self, **values: float) -> float:
        """The value with each symbol given (SI floats); ValueError, ZeroDivisionError or OverflowError
        where it is undefined."""
        return evaluate(self.tree, values)

    def names(self) -> set[str]:
        return set(_names(self.tree))

    def __str__(self) -> str:
        """Plain text the grammar reads back: sqrt(2*K/(3*M + 8*m))/(2*pi)."""
        return _text(self.tree)

    def latex(self) -> str:
        r"""The expression as LaTeX: \frac{1}{2\pi}... for keys and worked solutions."""
        return _latex(self.tree)


# ---- reading ------------------------------------------------------------------------------------------

def _plain(text: str) -> str:
    """Unicode signs and Greek letters to the ASCII grammar: 2π -> 2pi, K² -> K^2, √ kept as the root sign."""
    text = _SUPERSCRIPT.sub(lambda m: "^(" + m.group().translate(_SUPERSCRIPT_DIGITS) + ")", text)
    return text.translate(_SIGNS).replace("**", "^")


def _screen(text: str) -> str:
    """Refuse, cheaply and before any parsing, what cannot be an answer: too long, odd characters,
    unbalanced or too deeply nested brackets."""
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_LENGTH} characters")
    text = _plain(text)
    if not text.strip():
        raise ExpressionError("no expression given")
    if not _ALLOWED.fullmatch(text):
        bad = next(c for c in text if not _ALLOWED.fullmatch(c))
        hint = " (write decimals with a point: 2.5)" if bad == "," else ""
        raise ExpressionError(f"the character {bad!r} cannot be part of an expression{hint}")
    depth = 0
    for char in text:
        depth += (char == "(") - (char == ")")
        if depth < 0:
            raise ExpressionError("unbalanced brackets: a ')' closes nothing")
        if depth > MAX_DEPTH:
            raise ExpressionError(f"brackets nested more than {MAX_DEPTH} deep")
    if depth:
        raise ExpressionError("unbalanced brackets: a '(' is never closed")
    return text


def _tokens(text: str) -> list[tuple[str, str]]:
    out, at = [], 0
    while at < len(text):
        if text[at:].strip() == "":
            break
        match = _TOKEN.match(text, at)
        if match is None:
            raise ExpressionError(f"cannot read {text[at:].strip()[:12]!r}")
        kind = match.lastgroup
        value = match.group(kind)
        out.append((kind, "^" if value == "**" else value))
        at = match.end()
    return out


class _Parser:
    def __init__(self, text: str, symbols: tuple[str, ...]):
        self.symbols = symbols
        self.tokens = [piece for token in _tokens(_screen(text)) for piece in self.split(token)]
        self.at = 0

    def parse(self) -> tuple:
        tree = self.sum()
        if self.at < len(self.tokens):
            raise ExpressionError(f"{self.peek_text()!r} has no operator before it")
        return tree

    # -- token helpers
    def peek(self) -> tuple[str, str] | None:
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def peek_text(self) -> str:
        token = self.peek()
        return token[1] if token else ""

    def take(self) -> tuple[str, str]:
        token = self.peek()
        if token is None:
            before = self.tokens[self.at - 1][1] if self.at else ""
            raise ExpressionError(f"the expression ends after {before!r}: something is missing")
        self.at += 1
        return token

    def starts_atom(self) -> bool:
        token = self.peek()
        return token is not None and (token[0] in ("num", "name") or token[1] in ("(", "\u221a"))

    # -- grammar
    def sum(self) -> tuple:
        tree = self.product()
        while self.peek_text() in ("+", "-"):
            op = "add" if self.take()[1] == "+" else "sub"
            tree = (op, tree, self.product())
        return tree

    def product(self) -> tuple:
        tree, loose_divisor = self.unary(), False
        while True:
            text = self.peek_text()
            if text in ("*", "/"):
                self.take()
                loose_divisor = text == "/" and self.peek_text() != "("
                tree = ("mul" if text == "*" else "div", tree, self.unary())
            elif self.starts_atom():
                if self.peek()[0] == "num":
                    raise ExpressionError(f"missing operator before {self.peek_text()!r}")
                if loose_divisor:  # 1/2K: K/2 or 1/(2K)? 1/(2π)√K is clear
                    raise ExpressionError("after '/', put a product in brackets: write 1/(2K) or (1/2)K, not 1/2K")
                tree = ("mul", tree, self.unary())
            else:
                return tree

    def unary(self) -> tuple:
        signs = 0
        while self.peek_text() in ("+", "-"):
            signs += self.take()[1] == "-"
        tree = self.power()
        return ("neg", tree) if signs % 2 else tree

    def power(self) -> tuple:
        base = self.atom()
        if self.peek_text() != "^":
            return base
        self.take()
        exponent = self.unary()
        if any(node[0] == "pow" for node in _nodes(exponent)):
            raise ExpressionError("exponents of exponents (like 9^9^9) are not accepted: use brackets")
        if not _names(exponent):
            try:
                size = abs(evaluate(exponent, {}))
            except (ValueError, ArithmeticError):
                size = math.inf
            if not size <= MAX_EXPONENT:
                raise ExpressionError(f"exponents larger than {MAX_EXPONENT} are not accepted")
        return ("pow", base, exponent)

    def atom(self) -> tuple:
        kind, text = self.take()
        if kind == "num":
            value = float(text)
            if not math.isfinite(value):
                raise ExpressionError(f"{text!r} is too large a number")
            return ("num", value)
        if text == "(":
            if self.peek_text() == ")":
                raise ExpressionError("empty brackets '()'")
            inside = self.sum()
            self.take()  # ")" (brackets are balanced, so it is there)
            return inside
        if text == "\u221a":
            return ("call", "sqrt", self.power())
        if kind == "name":
            return self.name(text)
        raise ExpressionError(f"{text!r} has nothing before it")

    def name(self, text: str) -> tuple:
        if text in FUNCTIONS:
            if self.peek_text() != "(":
                raise ExpressionError(f"{text} needs brackets: {text}(...)")
            return ("call", text, self.atom())
        if text == "log":
            raise ExpressionError("write ln(...) for the natural logarithm, or log10(...) for base 10")
        if text in self.symbols:
            return ("sym", text)
        if text in CONSTANTS:
            return ("pi",)
        raise ExpressionError(self.unknown(text))

    def split(self, token: tuple[str, str]) -> list[tuple[str, str]]:
        """'Km' as K m and '2piK' as 2 pi K: a run of letters that is known names side by side is read
        as those names, each its own factor (so Km^2 is K m^2)."""
        kind, text = token
        if kind != "name" or text in self.symbols or text in FUNCTIONS or text in CONSTANTS or text == "log":
            return [token]
        names = sorted(set(self.symbols) | set(CONSTANTS), key=len, reverse=True)
        out, rest = [], text
        while rest:
            head = next((n for n in names if rest.startswith(n)), None)
            if head is None:
                return [token]
            out.append(("name", head))
            rest = rest[len(head):]
        return out

    def unknown(self, text: str) -> str:
        known = listed(self.symbols) if self.symbols else "none: this answer is a number"
        stem = re.fullmatch(r"(.*?[A-Za-z_])(\d+)", text)
        if stem and stem.group(1) in self.symbols:
            return f"missing operator between {stem.group(1)!r} and {stem.group(2)!r} in {text!r}"
        same = [s for s in self.symbols if s.lower() == text.lower()]
        close = same or difflib.get_close_matches(text, self.symbols, n=1, cutoff=0.6)
        hint = f" (did you mean {close[0]}?)" if close else ""
        return f"unknown symbol {text!r}: the symbols are {known}{hint}"


def listed(names) -> str:
    """'K, M and m'."""
    names = list(names)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


# ---- evaluating -----------------------------------------------------------------------------------------

_BINARY = {"add": float.__add__, "sub": float.__sub__, "mul": float.__mul__, "div": float.__truediv__}


def evaluate(tree: tuple, values: Mapping[str, float]) -> float:
    """The value of a tree; ValueError, ZeroDivisionError or OverflowError where it is undefined."""
    kind = tree[0]
    if kind == "num":
        return tree[1]
    if kind == "sym":
        return float(values[tree[1]])
    if kind == "pi":
        return math.pi
    if kind == "neg":
        return -evaluate(tree[1], values)
    if kind == "call":
        result = FUNCTIONS[tree[1]](evaluate(tree[2], values))
    elif kind == "pow":
        result = math.pow(evaluate(tree[1], values), evaluate(tree[2], values))
    else:
        result = _BINARY[kind](evaluate(tree[1], values), evaluate(tree[2], values))
    if not math.isfinite(result):
        raise OverflowError("not a finite value")
    return result


def _nodes(tree: tuple):
    yield tree
    for child in tree[1:]:
        if isinstance(child, tuple):
            yield from _nodes(child)


def _names(tree: tuple) -> list[str]:
    return [node[1] for node in _nodes(tree) if node[0] == "sym"]


# ---- printing -------------------------------------------------------------------------------------------

def _rank(tree: tuple) -> int:
    kind = tree[0]
    if kind in ("add", "sub"):
        return _PLUS
    if kind in ("mul", "div"):
        return _TIMES
    if kind == "neg":
        return _TIMES + 1
    if kind == "pow":
        return _POWER
    return _POWER + 1


def _number(value: float) -> str:
    return f"{value:.12g}"


def _text(tree: tuple) -> str:
    kind = tree[0]
    if kind == "num":
        return _number(tree[1])
    if kind == "sym":
        return tree[1]
    if kind == "pi":
        return "pi"
    if kind == "call":
        return f"{tree[1]}({_text(tree[2])})"
    if kind == "neg":
        return "-" + _wrapped(tree[1], _TIMES + 1, _text)
    left, right = tree[1], tree[2]
    if kind == "pow":
        return f"{_wrapped(left, _POWER + 1, _text)}^{_wrapped(right, _POWER + 1, _text)}"
    sign = {"add": " + ", "sub": " - ", "mul": "*", "div": "/"}[kind]
    rank = _rank(tree)
    return _wrapped(left, rank, _text) + sign + _wrapped(right, rank + (kind in ("sub", "div")), _text)


def _wrapped(tree: tuple, rank: int, show) -> str:
    """`show(tree)`, in brackets when it binds less tightly than `rank` needs."""
    shown = show(tree)
    if _rank(tree) >= rank:
        return shown
    return f"({shown})" if show is _text else rf"\left({shown}\right)"


_LATEX_CALLS = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "asin": r"\arcsin", "acos": r"\arccos",
                "atan": r"\arctan", "exp": r"\exp", "ln": r"\ln", "log10": r"\log_{10}"}


def _latex(tree: tuple) -> str:
    kind = tree[0]
    if kind == "num":
        mantissa, _, exponent = _number(tree[1]).partition("e")
        return mantissa + (rf" \times 10^{{{int(exponent)}}}" if exponent else "")
    if kind == "sym":
        return default_symbol(tree[1])
    if kind == "pi":
        return r"\pi"
    if kind == "call":
        name, inside = tree[1], _latex(tree[2])
        if name == "sqrt":
            return rf"\sqrt{{{inside}}}"
        if name == "abs":
            return rf"\left|{inside}\right|"
        return rf"{_LATEX_CALLS[name]}\left({inside}\right)"
    if kind == "neg":
        return "-" + _wrapped(tree[1], _TIMES + 1, _latex)
    left, right = tree[1], tree[2]
    if kind == "div":
        if left[0] in ("call", "pow") and not _names(right):  # sqrt(K/M)/(2 pi) as the text writes it
            return rf"\frac{{1}}{{{_latex(right)}}}" + _wrapped(left, _TIMES, _latex)
        return rf"\frac{{{_latex(left)}}}{{{_latex(right)}}}"
    if kind == "pow":
        if right == ("div", ("num", 1.0), ("num", 2.0)) or right == ("num", 0.5):
            return rf"\sqrt{{{_latex(left)}}}"
        return f"{_wrapped(left, _POWER + 1, _latex)}^{{{_latex(right)}}}"
    if kind == "mul":
        shown_left, shown_right = _wrapped(left, _TIMES, _latex), _wrapped(right, _TIMES, _latex)
        if shown_right[:1].isdigit() or shown_right[:1] == "-":
            joint = r" \cdot "
        else:
            joint = "" if left[0] == "num" else r"\,"
        return shown_left + joint + shown_right
    sign = " + " if kind == "add" else " - "
    return _wrapped(left, _PLUS, _latex) + sign + _wrapped(right, _PLUS + (kind == "sub"), _latex)
