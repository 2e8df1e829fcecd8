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
from functools import lru_cache

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
    """Evaluate an expression with the given variable values (a text is read and checked once, then
    run as compiled from then on: a template's conditions are evaluated at every draw)."""
    try:
        run = compiled(text_or_tree) if isinstance(text_or_tree, str) else _compile(text_or_tree.body)
        return run(names)
    except RecursionError as exc:
        raise ExpressionError("expression nested too deeply") from exc


@lru_cache(maxsize=4096)
def compiled(text: str):
    """The expression as a function of the names' values, built from the whitelisted tree: each node
    becomes a closure, so it is walked once, not on every call."""
    try:
        return _compile(parse(text).body)
    except RecursionError as exc:
        raise ExpressionError("expression nested too deeply") from exc


def _compile(node: ast.AST):
    """A closure evaluating `node`: numbers, names, arithmetic, comparisons, logic and FUNCTIONS; anything
    else is refused when it would run (its operands evaluated first), with ExpressionError."""
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        value = node.value
        return lambda names: value
    if isinstance(node, ast.Name):
        name = node.id

        def look_up(names):
            if name in names:
                return names[name]
            if name in CONSTANTS:
                return CONSTANTS[name]
            raise ExpressionError(f"unknown name {name!r}")
        return look_up
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd, ast.Not)):
        operand = _compile(node.operand)
        if isinstance(node.op, ast.USub):
            return lambda names: -operand(names)
        if isinstance(node.op, ast.UAdd):
            return lambda names: +operand(names)
        return lambda names: not operand(names)
    if isinstance(node, ast.BinOp) and (isinstance(node.op, ast.Pow) or type(node.op) in _BINARY):
        left, right = _compile(node.left), _compile(node.right)
        if isinstance(node.op, ast.Pow):
            def power(names):
                base, exponent = left(names), right(names)
                if abs(exponent) > MAX_POWER or (abs(base) > 1 and abs(exponent) > 1000):
                    raise ExpressionError("power too large")
                return base ** exponent
            return power
        operation = _BINARY[type(node.op)]
        return lambda names: operation(left(names), right(names))
    if isinstance(node, ast.BoolOp):
        values = [_compile(v) for v in node.values]
        combine = all if isinstance(node.op, ast.And) else any
        return lambda names: combine([v(names) for v in values])
    if isinstance(node, ast.Compare):
        first = _compile(node.left)
        chain = [(_COMPARE.get(type(op)), _compile(c)) for op, c in zip(node.ops, node.comparators)]

        def compare(names):
            left = first(names)
            for operation, comparator in chain:
                right = comparator(names)
                if operation is None or not operation(left, right):
                    return False
                left = right
            return True
        return compare
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        function_name = node.func.id
        args = [_compile(a) for a in node.args]

        def call(names):
            if function_name not in FUNCTIONS:
                raise ExpressionError(f"unknown function {function_name!r}")
            return FUNCTIONS[function_name](*(a(names) for a in args))
        return call
    kind = type(node).__name__
    # anything else is refused, once its operands (if any) have been evaluated
    operands = [_compile(n) for n in ((node.operand,) if isinstance(node, ast.UnaryOp) else
                                      (node.left, node.right) if isinstance(node, ast.BinOp) else ())]

    def refuse(names):
        for operand in operands:
            operand(names)
        raise ExpressionError(f"{kind} is not allowed in an expression")
    return refuse
