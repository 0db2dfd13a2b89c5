"""Golden files: one worked example per file in ``golden/``.

Line 1 of each file is the exact command (``$ scanconv ...``); everything after it is the exact
stdout. ``pytest --update-golden`` rewrites the files from the current output and then fails,
so every change to expected output is reviewed in the diff.
"""

from __future__ import annotations

import os
import shlex
from pathlib import Path

import pytest

from .helpers import run

GOLDEN = Path(
    os.environ.get("SCANCONV_GOLDEN_DIR") or Path(__file__).resolve().parent.parent / "golden"
)
FILES = sorted(p for p in GOLDEN.iterdir() if p.is_file() and not p.name.startswith("."))


def read_case(path: Path) -> tuple[list[str], str]:
    first, _, expected = path.read_text(encoding="utf-8").partition("\n")
    assert first.startswith("$ scanconv "), f"{path.name}: first line must be '$ scanconv ...'"
    return shlex.split(first[2:])[1:], expected


def test_golden_directory_is_not_empty():
    assert len(FILES) >= 1


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_golden(path: Path, request: pytest.FixtureRequest) -> None:
    args, expected = read_case(path)
    result = run(*args)
    assert result.code == 0, result.err
    if request.config.getoption("--update-golden"):
        if result.out != expected:
            first = path.read_text(encoding="utf-8").partition("\n")[0]
            path.write_text(f"{first}\n{result.out}", encoding="utf-8")
            pytest.fail(f"{path.name} rewritten; review the diff and commit it")
        return
    assert result.out == expected
