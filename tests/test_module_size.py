"""Small modules and functions: no module of scanconv over 600 lines,
no function over 80 lines (its docstring not counted), none of cyclomatic complexity over 20
(radon's measure, as `radon cc -s --min D scanconv` prints it)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "scanconv"
MODULES = sorted(PACKAGE.rglob("*.py"))
MAX_MODULE_LINES = 600
MAX_FUNCTION_LINES = 80
MAX_COMPLEXITY = 20


def _function_lines(node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """Lines from ``def`` to the end, less the docstring's."""
    assert node.end_lineno is not None
    lines = node.end_lineno - node.lineno + 1
    first = node.body[0]
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
        if isinstance(first.value.value, str) and first.end_lineno is not None:
            lines -= first.end_lineno - first.lineno + 1
    return lines


def _functions(tree: ast.AST) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
    return [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]


def test_the_measure_counts_a_long_function() -> None:
    """The measure itself: a function of 81 body lines is over, the docstring is not counted."""
    body = "".join(f"    x{i} = {i}\n" for i in range(80))
    (long,) = _functions(ast.parse(f'def f():\n    """doc\n    more"""\n{body}'))
    assert _function_lines(long) == 81


def test_no_module_is_over_600_lines() -> None:
    over = {
        str(p.relative_to(PACKAGE.parent)): n
        for p in MODULES
        if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_MODULE_LINES
    }
    assert not over, f"split these modules (lines): {over}"


def test_no_function_is_over_80_lines() -> None:
    over = [
        f"{p.relative_to(PACKAGE.parent)}:{f.lineno} {f.name} ({_function_lines(f)} lines)"
        for p in MODULES
        for f in _functions(ast.parse(p.read_text(encoding="utf-8")))
        if _function_lines(f) > MAX_FUNCTION_LINES
    ]
    assert not over, over


def test_no_function_is_over_complexity_20() -> None:
    radon = pytest.importorskip("radon.complexity", reason="radon is in the test extra")
    over = [
        f"{p.relative_to(PACKAGE.parent)}:{block.lineno} {block.fullname} ({block.complexity})"
        for p in MODULES
        for block in radon.cc_visit(p.read_text(encoding="utf-8"))
        if block.complexity > MAX_COMPLEXITY
    ]
    assert not over, over
