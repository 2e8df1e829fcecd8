"""A whitelist evaluator for small arithmetic expressions over named numbers.

A template's own expressions (`require:` conditions such as "d2 > d1", `report:` values, `equals:`)
are read with `ast.parse` and walked node by node: only numbers, the given names, arithmetic,
comparisons, boolean logic and the functions below are allowed. Nothing is ever handed to Python's own
evaluator. Students' formulas never come here: they have a grammar of their own
(exgen.answertypes.expressions).
"""
from __future__ import annotations

import ast
import math
import operator

MAX_LENGTH = 300
MAX_POWER = 1e6  # keeps 9**9**9 from hanging the process

FUNCTIONS = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan,
    "asin": math.asin, "acos": math.acos, "atan": math.atan, "atan2": math.atan2,
    "sinh": math.sinh, "cosh": math.cosh, "tanh": math.tanh,
    "sqrt": math.sqrt, "exp": math.exp, "log": math.log, "ln": math.log, "log10": math.log10,
    "abs": abs, "min": min, "max": max, "radians": math.radians, "degrees": math.degrees,
}
CONSTANTS = {"pi": math.pi, "e": math.e}

_BINARY = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.Mod: operator.mod,
}
_COMPARE = {
    ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt,
    ast.GtE: operator.ge, ast.Eq: operator.eq, ast.NotEq: operator.ne,
}


class ExpressionError(ValueError):
    """The text is not an allowed expression, or names something unknown."""


def parse(text: str) -> ast.Expression:
    """Parse `text` into a tree, refusing anything longer than MAX_LENGTH characters."""
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_LENGTH} characters")
    try:
        return ast.parse(text.replace("^", "**"), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        raise ExpressionError(f"cannot read {text!r} as an expression") from exc


def names_in(tree: ast.AST) -> set[str]:
    """Variable names an expression refers to (functions and constants excluded)."""
    called = {id(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
    return {
        n.id for n in ast.walk(tree)
        if isinstance(n, ast.Name) and id(n) not in called and n.id not in CONSTANTS
    }


def evaluate(text_or_tree, names: dict[str, float]):
    """Evaluate an expression with the given variable values."""
    tree = parse(text_or_tree) if isinstance(text_or_tree, str) else text_or_tree
    try:
        return _eval(tree.body, names)
    except RecursionError as exc:
        raise ExpressionError("expression nested too deeply") from exc


def _eval(node: ast.AST, names: dict):
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return node.value
    if isinstance(node, ast.Name):
        if node.id in names:
            return names[node.id]
        if node.id in CONSTANTS:
            return CONSTANTS[node.id]
        raise ExpressionError(f"unknown name {node.id!r}")
    if isinstance(node, ast.UnaryOp):
        value = _eval(node.operand, names)
        if isinstance(node.op, ast.USub):
            return -value
        if isinstance(node.op, ast.UAdd):
            return +value
        if isinstance(node.op, ast.Not):
            return not value
    if isinstance(node, ast.BinOp):
        left, right = _eval(node.left, names), _eval(node.right, names)
        if isinstance(node.op, ast.Pow):
            if abs(right) > MAX_POWER or (abs(left) > 1 and abs(right) > 1000):
                raise ExpressionError("power too large")
            return left ** right
        if type(node.op) in _BINARY:
            return _BINARY[type(node.op)](left, right)
    if isinstance(node, ast.BoolOp):
        values = [_eval(v, names) for v in node.values]
        return all(values) if isinstance(node.op, ast.And) else any(values)
    if isinstance(node, ast.Compare):
        left = _eval(node.left, names)
        for op, comparator in zip(node.ops, node.comparators):
            right = _eval(comparator, names)
            if type(op) not in _COMPARE or not _COMPARE[type(op)](left, right):
                return False
            left = right
        return True
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        if node.func.id not in FUNCTIONS:
            raise ExpressionError(f"unknown function {node.func.id!r}")
        return FUNCTIONS[node.func.id](*(_eval(a, names) for a in node.args))
    raise ExpressionError(f"{type(node).__name__} is not allowed in an expression")
