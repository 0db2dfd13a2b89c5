"""The library's error messages name parameters, never a command-line flag: only the CLI knows
the flags (it prefixes a message with the flag of the error's parameter, ``--solid: ...``).

Word lists that the library itself reads (a 3D transform's ``--rotate-x 30 --about ...``
words, the question grammar of :mod:`scanconv.questions`, the word readers of
:mod:`scanconv._api.words`) are their own grammar and may name their words.
"""

from __future__ import annotations

import ast
import re
from fractions import Fraction
from pathlib import Path

import pytest

from scanconv.core.checks import InputError

from .helpers import run

PACKAGE = Path(__file__).resolve().parent.parent / "scanconv"
GRAMMARS = {"questions", "cli", "site", "mcp_server"}  # packages that speak in flags
WORD_READERS = {"_api/words.py", "answers/space/transform.py"}
FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def _message_text(node: ast.expr) -> str:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(_message_text(v) for v in node.values if isinstance(v, ast.Constant))
    if isinstance(node, ast.BinOp):
        return _message_text(node.left) + _message_text(node.right)
    return ""


def flagged_messages() -> list[str]:
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if rel.split("/")[0] in GRAMMARS or rel in WORD_READERS:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "InputError"):
                continue
            text = _message_text(node.args[0]) if node.args else ""
            if FLAG.search(text):
                found.append(f"{rel}:{node.lineno}: {text!r}")
    return found


def test_no_library_message_names_a_flag():
    assert flagged_messages() == []


def test_the_scan_finds_a_flag_in_a_message(tmp_path, monkeypatch):
    planted = tmp_path / "scanconv" / "answers"
    planted.mkdir(parents=True)
    (planted / "bad.py").write_text('raise InputError(f"give --solid {x}", "solid")\n')
    monkeypatch.setattr(__import__(__name__, fromlist=["x"]), "PACKAGE", tmp_path / "scanconv")
    assert len(flagged_messages()) == 1


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["3d", "project", "0", "0", "0", "--solid", "cube", "--parallel", "orthographic"],
            "error: --solid: give the vertices or a named solid, not both",
        ),
        (["3d", "project", "--solid", "cube"], "error: --parallel: choose one projection"),
        (["color", "rgb", "0.5", "0", "0"], "error: --unit: R = 0.5 must be an integer 0..255"),
    ],
)
def test_the_cli_names_the_flag_of_the_parameter(argv, line):
    r = run(*argv)
    assert r.code == 2 and r.out == ""
    assert len(r.err.strip().splitlines()) == 1 and line in r.err


def test_the_library_error_carries_the_parameter_not_the_flag():
    import scanconv

    with pytest.raises(InputError) as err:
        scanconv.color("rgb", Fraction(1, 2), 0, 0)
    assert err.value.param == "unit" and "--" not in str(err.value)
