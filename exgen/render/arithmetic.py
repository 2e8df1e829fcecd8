"""The value of a worked-solution formula with numbers in its slots.

A key shows each step as formula = numbers = value; a reader checks it with a calculator. This
evaluates the same parse the key is written from, so the key can show enough figures for the
numbers on the line to give the value on the line, and the tests can check that every line of
every key does. Degrees are written as 30^{\\circ}; every angle is worked in radians inside.
"""
from __future__ import annotations

import math

from .formula import (SPACE, Arg, Cmd, Delim, Formula, FormulaError, Group, Paren, Script, Tok, function_name,
                      is_inverse)

FUNCTIONS = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "cot": lambda x: 1 / math.tan(x),
             "sec": lambda x: 1 / math.cos(x), "csc": lambda x: 1 / math.sin(x), "cosec": lambda x: 1 / math.sin(x)}
FUNCTIONS.update({"ln": math.log, "log": math.log10, "exp": math.exp})
INVERSES = {"sin": math.asin, "cos": math.acos, "tan": math.atan, "arcsin": math.asin, "arccos": math.acos,
            "arctan": math.atan}
_SKIP = {SPACE, Tok("cmd", ","), Tok("cmd", ";"), Tok("cmd", ":"), Tok("cmd", "!"), Tok("cmd", "quad"),
         Tok("cmd", " ")}
_TIMES = {Tok("cmd", "times"), Tok("cmd", "cdot")}
# tokens compared against at every step, made once (a frozen dataclass is slow to make)
_SIGNS = (Tok("char", "+"), Tok("char", "-"))
_SLASH, _PI, _E = Tok("char", "/"), Tok("cmd", "pi"), Tok("char", "e")
_DEGREE = [Tok("cmd", "circ")]
_CONSTANTS = (_PI, _E)


class NotArithmetic(FormulaError):
    """The formula holds something that is not a number (a symbol, text)."""


def evaluate(formula: Formula, values: dict[int, float]) -> float:
    """The formula's value with slot i standing for values[i] (angles in radians)."""
    return _Evaluator(formula, values).group(formula.tree)


class _Evaluator:
    def __init__(self, formula, values):
        self.formula, self.values = formula, values

    def group(self, node: Group) -> float:
        items = [i for i in node.items if i not in _SKIP]
        value, at = self.expression(items, 0)
        if at != len(items):
            raise NotArithmetic(f"cannot read {items[at]!r}")
        return value

    def expression(self, items, at):
        value, at = self.term(items, at)
        while at < len(items) and items[at] in _SIGNS:
            sign = 1 if items[at].text == "+" else -1
            right, at = self.term(items, at + 1)
            value += sign * right
        return value, at

    def term(self, items, at):
        value, at = self.unary(items, at)
        while at < len(items):
            item = items[at]
            if item in _TIMES:
                right, at = self.unary(items, at + 1)
                value *= right
            elif item == _SLASH:
                right, at = self.unary(items, at + 1)
                value /= right
            elif self.starts_operand(item):
                right, at = self.power(items, at)
                value *= right
            else:
                break
        return value, at

    @staticmethod
    def starts_operand(item) -> bool:
        if isinstance(item, (Group, Delim, Cmd, Script, Paren)) or function_name(item):
            return True
        return isinstance(item, Tok) and (item.kind in ("num", "slot") or item in _CONSTANTS)

    def unary(self, items, at):
        if at < len(items) and items[at] in _SIGNS:
            sign = -1 if items[at].text == "-" else 1
            value, at = self.unary(items, at + 1)
            return sign * value, at
        return self.power(items, at)

    def power(self, items, at):
        if at >= len(items):
            raise NotArithmetic("an operand is missing")
        item = items[at]
        if function_name(item):
            if at + 1 >= len(items) or not isinstance(items[at + 1], Arg):
                raise NotArithmetic("a function without its argument")
            inner = self.group(items[at + 1].body)
            name = function_name(item)
            value = INVERSES[name](inner) if is_inverse(item) else FUNCTIONS[name](inner)
            return value, at + 2
        if isinstance(item, Script):
            if item.sup is not None and _is_degree(item.sup):
                return math.radians(self.primary(item.base)), at + 1
            base = math.e if item.base == _E else self.primary(item.base)
            return self.scripts(base, item), at + 1
        return self.primary(item), at + 1

    def scripts(self, value, script):
        if script is None or script.sup is None:
            return value
        return value ** self.group(_as_group(script.sup))

    def primary(self, item) -> float:
        if isinstance(item, Tok):
            if item.kind == "num":
                return float(item.text)
            if item.kind == "slot":
                return self.values[self.formula.order[id(item)]]
            if item == _PI:
                return math.pi
            raise NotArithmetic(f"{item.text!r} is not a number")
        if isinstance(item, (Group, Paren)):
            return self.group(item if isinstance(item, Group) else item.body)
        if isinstance(item, Delim):
            inner = self.group(item.body)
            if item.left == "|":
                return abs(inner)
            if item.left == "\\lceil":
                return float(math.ceil(inner - 1e-9))
            if item.left == "\\lfloor":
                return float(math.floor(inner + 1e-9))
            return inner
        if isinstance(item, Cmd):
            if item.name in ("frac", "dfrac", "tfrac"):
                top = self.group(_as_group(item.args[0]))
                return top / self.group(_as_group(item.args[1]))
            if item.name == "sqrt":
                return math.sqrt(self.group(_as_group(item.args[0])))
        raise NotArithmetic(f"{item!r} is not a number")


def _as_group(node) -> Group:
    return node if isinstance(node, Group) else Group((node,))


def _is_degree(node) -> bool:
    items = node.items if isinstance(node, Group) else (node,)
    return [i for i in items if i != SPACE] == _DEGREE
