"""A worked-solution formula: LaTeX with @name slots, parsed once, filled with numbers per variant.

A regex cannot tell what a reader of a key needs: which slots stand in a trigonometric argument
(an angle there is shown in degrees), which in an exponent (an angle there is a number of
radians), where a long line may break (before a top-level + or −, never inside a function's
argument), how wide a line is, and what a filled-in line evaluates to (a shown line must
reproduce its shown value). Parses are cached per formula string: once per process.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

_TOKEN = re.compile(r"@([A-Za-z_][A-Za-z0-9_]*)|\\([A-Za-z]+|.)|(\d+(?:\.\d+)?)|([{}^_])|(\s+)|(.)", re.DOTALL)
TRIG = frozenset({"sin", "cos", "tan", "cot", "sec", "csc", "cosec"})
INVERSE = frozenset({"arcsin", "arccos", "arctan"})
#: Functions of a number, not of an angle.
OTHER = frozenset({"ln", "log", "exp"})
#: Commands whose one braced argument is text, kept as written.
TEXT = frozenset({"text", "mathrm", "operatorname", "mathit", "mathbf", "textrm", "mbox"})
SPACING = frozenset({",", ";", ":", "!", " ", "quad", "qquad"})
OPERATORS = frozenset({"times", "cdot", "pm", "mp"})


@dataclass(frozen=True)
class Tok:
    kind: str            # slot, cmd, num, char, space
    text: str


@dataclass(frozen=True)
class Group:
    items: tuple


@dataclass(frozen=True)
class Cmd:
    """\\frac{a}{b}, \\sqrt{a}, \\text{...}: a command with its braced arguments."""

    name: str
    args: tuple


@dataclass(frozen=True)
class Delim:
    """\\left( ... \\right): a pair of sized delimiters."""

    left: str
    body: Group
    right: str


@dataclass(frozen=True)
class Paren:
    """( ... ) written with plain brackets, kept as one operand so that (a - b)^2 squares all of it."""

    body: Group


@dataclass(frozen=True)
class Script:
    base: object
    sup: object = None
    sub: object = None


@dataclass(frozen=True)
class Arg:
    """The argument of a function. `bracket`: more than one factor, so once numbers stand in it, it is
    bracketed: cos 2θ reads cos(2 × 30°). `kind`: "trig" (an angle), "inverse" (the ratio of sin⁻¹ and
    the like) or "other" (the number of ln)."""

    body: Group
    bracket: bool
    kind: str

    @property
    def inverse(self) -> bool:
        return self.kind == "inverse"


class FormulaError(ValueError):
    """LaTeX outside the subset worked solutions use."""


def _tokens(latex: str) -> list[Tok]:
    out = []
    for m in _TOKEN.finditer(latex):
        slot, cmd, num, special, space, char = m.groups()
        kind, text = next((k, t) for k, t in (("slot", slot), ("cmd", cmd), ("num", num), ("char", special),
                                               ("space", space), ("char", char)) if t is not None)
        out.append(Tok(kind, " " if kind == "space" else text))
    return out


SPACE = Tok("space", " ")


class _Parser:
    ARITY = {"frac": 2, "dfrac": 2, "tfrac": 2, "sqrt": 1}

    def __init__(self, tokens):
        self.tokens, self.at = tokens, 0

    def peek(self):
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def take(self):
        tok = self.peek()
        self.at += 1
        return tok

    def sequence(self, stop=None) -> Group:
        items, opened, bars = [], [], []
        while True:
            tok = self.peek()
            if tok is None:
                if stop is not None:
                    raise FormulaError(f"a group is not closed ({stop} missing)")
                return Group(_with_arguments(items))
            if stop == "}" and tok == Tok("char", "}"):
                self.take()
                return Group(_with_arguments(items))
            if stop == "right" and tok == Tok("cmd", "right"):
                return Group(_with_arguments(items))
            if tok.kind == "char" and tok.text in "^_":
                self.take()
                if not items:
                    raise FormulaError("a script with nothing before it")
                base = items[-1] if isinstance(items[-1], Script) else Script(items[-1])
                arg = self.argument()
                items[-1] = Script(base.base, arg, base.sub) if tok.text == "^" else Script(base.base, base.sup, arg)
                continue
            if tok == Tok("char", "|"):  # |x|: a bare pair of bars in one group is an absolute value
                self.take()
                if bars:
                    start = bars.pop()
                    items[start:] = [Delim("|", Group(_with_arguments(items[start:])), "|")]
                else:
                    bars.append(len(items))
                continue
            if tok == Tok("char", "(") or (tok == Tok("char", ")") and opened):
                self.take()
                if tok.text == "(":
                    opened.append(len(items))
                    continue
                start = opened.pop()
                items[start:] = [Paren(Group(_with_arguments(items[start:])))]
                continue
            items.append(self.item())

    def argument(self):
        while self.peek() == SPACE:
            self.take()
        tok = self.peek()
        if tok is None:
            raise FormulaError("an argument is missing")
        if tok == Tok("char", "{"):
            self.take()
            return self.sequence("}")
        return self.item()

    def item(self):
        tok = self.take()
        if tok == Tok("char", "{"):
            return self.sequence("}")
        if tok.kind == "cmd" and tok.text == "left":
            left = self.take()
            body = self.sequence("right")
            self.take()
            right = self.take()
            if left is None or right is None:
                raise FormulaError("\\left without its \\right")
            return Delim(_delimiter(left), body, _delimiter(right))
        if tok.kind == "cmd" and tok.text in TEXT:
            return Cmd(tok.text, (self._raw(),))
        if tok.kind == "cmd" and tok.text in self.ARITY:
            return Cmd(tok.text, tuple(self.argument() for _ in range(self.ARITY[tok.text])))
        return tok

    def _raw(self) -> str:
        """The text inside \\text{...}, as written."""
        if self.take() != Tok("char", "{"):
            raise FormulaError("\\text needs braces")
        depth, parts = 1, []
        while (tok := self.take()) is not None:
            depth += {"{": 1, "}": -1}.get(tok.text, 0) if tok.kind == "char" else 0
            if depth == 0:
                return "".join(parts)
            parts.append({"cmd": "\\", "slot": "@"}.get(tok.kind, "") + tok.text)
        raise FormulaError("\\text is not closed")


def _delimiter(tok: Tok) -> str:
    return ("\\" + tok.text) if tok.kind == "cmd" else tok.text


def function_name(item) -> str | None:
    base = item.base if isinstance(item, Script) else item
    if isinstance(base, Tok) and base.kind == "cmd" and base.text in TRIG | INVERSE | OTHER:
        return base.text
    return None


def is_inverse(item) -> bool:
    name = function_name(item)
    return name in INVERSE or (bool(name) and isinstance(item, Script) and _flat(item.sup) == "-1")


def _flat(node) -> str:
    if isinstance(node, Group):
        return "".join(_flat(i) for i in node.items)
    return node.text if isinstance(node, Tok) else "?"


def _with_arguments(items: list) -> tuple:
    """Gather each trigonometric function's argument into an Arg: a bracketed or braced group, a
    fraction, or an optional number and one operand (cos 2θ, sin β, tan⁻¹ x/y)."""
    out, i = [], 0
    while i < len(items):
        item = items[i]
        out.append(item)
        i += 1
        if not function_name(item):
            continue
        while i < len(items) and items[i] == SPACE:
            i += 1
        start = i
        if i < len(items) and isinstance(items[i], (Group, Delim, Cmd, Paren)):
            i += 1
        else:
            if i < len(items) and isinstance(items[i], Tok) and items[i].kind == "num":
                i += 1
                while i < len(items) and items[i] in (SPACE, Tok("cmd", ",")):
                    i += 1
            if i < len(items) and _is_operand(items[i]):
                i += 1
        body = [x for x in items[start:i] if x != SPACE]
        if not body:
            raise FormulaError(f"\\{function_name(item)} has no argument")
        kind = "inverse" if is_inverse(item) else "other" if function_name(item) in OTHER else "trig"
        out.append(Arg(Group(tuple(items[start:i])), len(body) > 1, kind))
    return tuple(out)


def _is_operand(item) -> bool:
    base = item.base if isinstance(item, Script) else item
    if isinstance(base, Tok):
        if base.kind in ("slot", "num"):
            return True
        if base.kind == "cmd":
            return base.text not in SPACING and base.text not in OPERATORS and function_name(base) is None
        return base.kind == "char" and base.text.isalpha()
    return isinstance(base, (Group, Delim, Cmd, Paren))


# ---- analysis -----------------------------------------------------------------------------------

@dataclass(frozen=True)
class Slot:
    """One occurrence of @name, with where it stands."""

    index: int
    name: str
    trig: bool        # in a trigonometric argument: an angle is shown in degrees
    exponent: bool    # in an exponent: an angle is a number of radians
    inverse: bool     # in the argument of an inverse trigonometric function (a ratio)


@dataclass(frozen=True)
class Formula:
    latex: str
    tree: Group
    slots: tuple[Slot, ...]
    inverse_first: bool      # the whole formula is an inverse trigonometric function of something
    has_pi: bool
    has_degree: bool
    order: dict              # id of each slot's token -> its index in `slots`

    def slot_of(self, tok) -> Slot:
        return self.slots[self.order[id(tok)]]


@lru_cache(maxsize=4096)
def parse(latex: str) -> Formula:
    tree = _Parser(_tokens(latex)).sequence()
    slots: list[Slot] = []
    order: dict[int, int] = {}
    _mark(tree, slots, order, False, False, False)
    items = [i for i in tree.items if i != SPACE]
    inverse_first = len(items) == 2 and is_inverse(items[0])
    return Formula(latex, tree, tuple(slots), inverse_first, "\\pi" in latex, "\\circ" in latex, order)


def _mark(node, slots, order, trig, exponent, inverse):
    if isinstance(node, Group):
        for item in node.items:
            _mark(item, slots, order, trig, exponent, inverse)
    elif isinstance(node, Arg):
        _mark(node.body, slots, order, trig or node.kind == "trig", exponent, inverse or node.inverse)
    elif isinstance(node, Script):
        _mark(node.base, slots, order, trig, exponent, inverse)
        if node.sub is not None:
            _mark(node.sub, slots, order, trig, exponent, inverse)
        if node.sup is not None and function_name(node.base) is None:
            _mark(node.sup, slots, order, trig, True, inverse)
    elif isinstance(node, Cmd):
        for arg in node.args:
            if not isinstance(arg, str):
                _mark(arg, slots, order, trig, exponent, inverse)
    elif isinstance(node, (Delim, Paren)):
        _mark(node.body, slots, order, trig, exponent, inverse)
    elif isinstance(node, Tok) and node.kind == "slot":
        order[id(node)] = len(slots)
        slots.append(Slot(len(slots), node.text, trig, exponent, inverse))


# ---- writing ------------------------------------------------------------------------------------

@lru_cache(maxsize=16384)
def written(latex: str, fills: tuple[str, ...], numbers: bool = False) -> str:
    """`write` of the formula `latex` with slot i filled by fills[i], kept: a template's formula is written with
    the same symbols (and often the same numbers) on every sheet."""
    return write(parse(latex), lambda slot: fills[slot.index], numbers)


def write(formula: Formula, fill, numbers: bool = False) -> str:
    """The formula as LaTeX, each slot replaced by fill(slot). With `numbers` (the substituted line), a
    thin space beside a slot becomes \\times and a trig argument of several factors is bracketed."""
    return re.sub(r" {2,}", " ", _write(formula.tree, fill, numbers, formula.slot_of)).strip()


_THIN = Tok("cmd", ",")


def _write(node, fill, numbers, slots) -> str:
    if isinstance(node, Group):
        out = []
        for i, item in enumerate(node.items):
            text = _write(item, fill, numbers, slots)
            if not numbers and _is_slot(item) and not isinstance(item, Script) and text.lstrip().startswith("\\frac") \
                    and (_factor(_next(node.items, i, -1)) or _factor(_next(node.items, i, 1))):
                text = f"\\left({text.strip()}\\right)"  # v (v₂/v₁), not v v₂/v₁: a ratio's symbol as a factor
            if numbers and item == _THIN and (_is_slot(_next(node.items, i, -1)) or
                                                        _is_slot(_next(node.items, i, 1))):
                text = " \\times "
            out.append(text)
        return "".join(out)
    if isinstance(node, Arg):
        body = _write(node.body, fill, numbers, slots).strip()
        if numbers and node.bracket:
            return f"\\left({body}\\right)"
        return " " + body if body[:1] not in "({\\" else body
    if isinstance(node, Tok):
        if node.kind == "slot":
            return fill(slots(node))
        if node.kind == "cmd":
            return "\\" + node.text + (" " if node.text[:1].isalpha() else "")
        return node.text
    if isinstance(node, Script):
        text = _write(node.base, fill, numbers, slots).rstrip()
        if node.sup is not None and _is_slot(node) and not _SINGLE.match(text):
            text = f"\\left({text}\\right)"  # (m_A r_A)^2, (3 \times 10^{8})^2, not m_A r_A^2
        if node.sub is not None:
            text += "_{" + _write(node.sub, fill, numbers, slots).strip() + "}"
        if node.sup is not None:
            text += "^{" + _write(node.sup, fill, numbers, slots).strip() + "}"
        return text
    if isinstance(node, Cmd):
        if node.name in TEXT:
            return f"\\{node.name}{{{node.args[0]}}}"
        return "\\" + node.name + "".join("{" + _write(a, fill, numbers, slots).strip() + "}" for a in node.args)
    if isinstance(node, Delim):
        return f"\\left{node.left}" + _write(node.body, fill, numbers, slots) + f"\\right{node.right}"
    if isinstance(node, Paren):
        return "(" + _write(node.body, fill, numbers, slots) + ")"
    raise FormulaError(f"cannot write {node!r}")


def _next(items, i, step):
    j = i + step
    while 0 <= j < len(items) and items[j] == SPACE:
        j += step
    return items[j] if 0 <= j < len(items) else None


def _factor(item) -> bool:
    """Whether a neighbour multiplies what stands beside it (a symbol, a bracket, a number), not an operator."""
    if item is None or item == _THIN:
        return item == _THIN
    return not (isinstance(item, Tok) and item.kind != "slot" and item.text.strip() in ("+", "-", "=", "/", ""))


def _is_slot(item) -> bool:
    base = item.base if isinstance(item, Script) else item
    return isinstance(base, Tok) and base.kind == "slot"


_SINGLE = re.compile(r"^([-+]?[\d.]+|\\?[A-Za-z]+(_\{(?:[^{}]|\{[^{}]*\})*\}|_[A-Za-z0-9])?'*|\(.*\)|"
                     r"\\text\{#\d+#\})$")
_PIECE = re.compile(r"\\left\\?.|\\right\\?.|\\[A-Za-z]+|\\.|.", re.DOTALL)
_AFTER_OPERATOR = re.compile(r"(\\times|\\cdot|[=+\-(\[{^_]|\\left\\?.)\s*$")


def terms(latex: str) -> list[str]:
    """LaTeX split before each top-level binary + and − (a long line breaks there and only there)."""
    out, depth, current = [], 0, ""
    for piece in _PIECE.findall(latex):
        if piece in ("{", "(", "[") or piece.startswith("\\left"):
            depth += 1
        elif piece in ("}", ")", "]") or piece.startswith("\\right"):
            depth -= 1
        if depth == 0 and piece in ("+", "-") and current.strip() and not _AFTER_OPERATOR.search(current):
            out.append(current.strip())
            current = ""
        current += piece
    if current.strip():
        out.append(current.strip())
    return out
