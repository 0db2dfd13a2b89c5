"""Marks are declared where the test is defined, and the suite asserts no speed.

``tests/conftest.py`` once marked tests slow by file and test name (``SLOW_FILES``,
``SLOW_TESTS``): renaming a test silently dropped its mark. A mark now sits on the test
(``@pytest.mark.slow``) or in its file (``pytestmark``); the only mark conftest adds is derived
from another mark (an ``external`` test is slow too). Hypothesis runs without a deadline: a
test must not fail because a shared machine was busy.
"""

from __future__ import annotations

import ast
from pathlib import Path

from hypothesis import settings

TESTS = Path(__file__).resolve().parent
CONFTEST = TESTS / "conftest.py"
#: What names a test or its file: a mark chosen from one of these is a mark by name.
_NAMING = {"name", "originalname", "nodeid", "path", "fspath", "module", "cls", "function"}


def _add_marker_calls(tree: ast.AST) -> list[ast.Call]:
    return [
        node
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr in ("add_marker", "applymarker")
    ]


def _naming_attributes(tree: ast.AST) -> set[str]:
    return {n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute)} & _NAMING


def test_conftest_marks_no_test_by_its_name_or_file():
    tree = ast.parse(CONFTEST.read_text())
    hooks = [
        node
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef) and _add_marker_calls(node)
    ]
    assert [h.name for h in hooks] in ([], ["pytest_collection_modifyitems"]), [
        h.name for h in hooks
    ]
    for hook in hooks:
        named = _naming_attributes(hook)
        assert not named, (
            f"conftest.py {hook.name} reads {sorted(named)}: declare the mark on the test "
            "(@pytest.mark.slow) or in its file (pytestmark = pytest.mark.slow) instead"
        )
    top_level_sets = [
        t.id
        for node in tree.body
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Set | ast.List | ast.Tuple)
        for t in node.targets
        if isinstance(t, ast.Name) and ("SLOW" in t.id or "EXTERNAL" in t.id)
    ]
    assert not top_level_sets, top_level_sets


def test_the_check_catches_a_mark_by_name():
    """The check above fails on the old conftest's way (a mark chosen from the file name)."""
    old = ast.parse(
        "def pytest_collection_modifyitems(config, items):\n"
        "    for item in items:\n"
        "        if item.path.name in SLOW_FILES:\n"
        "            item.add_marker(pytest.mark.slow)\n"
    )
    assert _add_marker_calls(old) and _naming_attributes(old) == {"name", "path"}


def test_hypothesis_has_no_deadline_in_any_profile():
    assert settings.default.deadline is None
    for name in ("ci", "dev"):
        assert settings.get_profile(name).deadline is None, name
