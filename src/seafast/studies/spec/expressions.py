"""Derived-key expressions (``cargo.wall_thickness_m: cargo.diameter_m / 110``): parsing and evaluation.

A small arithmetic language over numbers and dotted case keys, parsed with :mod:`ast` and
evaluated by walking the tree (never ``eval``); anything else is a :class:`StudyError` naming
what is allowed.
"""

from __future__ import annotations

import ast
import functools
import math
import operator
import typing
from typing import Any

from seafast.studies.spec.errors import StudyError

__all__ = ["expression_keys", "evaluate_expression"]

_BINARY_OPS: dict[type, Any] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.Pow: operator.pow,
}
_UNARY_OPS: dict[type, Any] = {ast.USub: operator.neg, ast.UAdd: operator.pos}
_FUNCTIONS: dict[str, Any] = {
    "min": min,
    "max": max,
    "floor": math.floor,
    "ceil": math.ceil,
    "round": round,
    "abs": abs,
    "sqrt": math.sqrt,
    "log": math.log,
    "exp": math.exp,
}
_ALLOWED_TEXT = f"numbers, dotted case keys, + - * / ** , parentheses and {', '.join(_FUNCTIONS)}"


def _dotted_name(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        head = _dotted_name(node.value)
        return None if head is None else f"{head}.{node.attr}"
    return None


@functools.lru_cache(maxsize=256)  # studies evaluate the same derived expressions at every point
def _parse_expression(text: str) -> ast.Expression:
    try:
        tree = ast.parse(str(text), mode="eval")
    except SyntaxError:
        raise StudyError(f"derived expression {text!r} is not valid; allowed: {_ALLOWED_TEXT}") from None
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            if not (isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS) or node.keywords or not node.args:
                raise StudyError(f"derived expression {text!r} calls '{ast.unparse(node.func)}'; allowed: {_ALLOWED_TEXT}")
            continue
        if isinstance(node, ast.Name) and node.id in _FUNCTIONS:
            continue
        allowed = (
            ast.Expression,
            ast.BinOp,
            ast.UnaryOp,
            ast.Constant,
            ast.Name,
            ast.Attribute,
            ast.Load,
            ast.Call,
            *_BINARY_OPS,
            *_UNARY_OPS,
        )
        if not isinstance(node, allowed) or (isinstance(node, ast.Constant) and not isinstance(node.value, (int, float))):
            raise StudyError(
                f"derived expression {text!r} uses '{ast.unparse(node) if isinstance(node, ast.expr) else type(node).__name__}'; "
                f"allowed: {_ALLOWED_TEXT}"
            )
    return tree


def expression_keys(text: str) -> list[str]:
    """The dotted case keys an expression refers to, in order of appearance."""
    tree = _parse_expression(text)
    keys: list[str] = []

    def visit(node: ast.AST) -> None:
        if isinstance(node, ast.Call):
            for arg in node.args:
                visit(arg)
            return
        name = _dotted_name(node)
        if name is not None:
            if name not in keys:
                keys.append(name)
            return
        for child in ast.iter_child_nodes(node):
            visit(child)

    visit(tree.body)
    return keys


def evaluate_expression(text: str, lookup: typing.Callable[[str], float]) -> float:
    """Evaluate a derived-key expression such as ``"cargo.diameter_m / 110"``.

    Parameters
    ----------
    text : str
        Arithmetic over numbers and dotted case keys (``+ - * / **``, parentheses) and the
        functions ``min, max, floor, ceil, round, abs, sqrt, log, exp``.
    lookup : callable
        Returns the value of a dotted case key (SI units).

    Returns
    -------
    float
        The value, in the units of the derived key.
    """
    tree = _parse_expression(text)

    def ev(node: ast.AST) -> float:
        if isinstance(node, ast.Call):
            assert isinstance(node.func, ast.Name)
            return float(_FUNCTIONS[node.func.id](*(ev(a) for a in node.args)))
        name = _dotted_name(node)
        if name is not None:
            return float(lookup(name))
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):  # the only constants parsing admits
            return float(node.value)
        if isinstance(node, ast.BinOp):
            return _BINARY_OPS[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp):
            return _UNARY_OPS[type(node.op)](ev(node.operand))
        raise StudyError(f"derived expression {text!r}: unsupported element")  # pragma: no cover

    return ev(tree.body)
