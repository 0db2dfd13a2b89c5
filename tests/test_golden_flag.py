"""The ``--update-golden`` flag rewrites a stale golden file and then fails; the next run passes."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parent.parent


def _pytest(golden: Path, *flags: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--no-cov",
         str(ROOT / "tests" / "test_golden.py"), *flags],
        capture_output=True,
        text=True,
        env={**os.environ, "SCANCONV_GOLDEN_DIR": str(golden)},
        cwd=ROOT,
        timeout=300,
    )  # fmt: skip


def test_update_golden_rewrites_then_fails(tmp_path: Path):
    source = ROOT / "golden" / "lines" / "line-bresenham-2-2-10-6.csv"
    stale = tmp_path / source.name
    command, _, expected = source.read_text().partition("\n")
    stale.write_text(f"{command}\nk,p,decision,x,y,p_next\n0,999,E,0,0,0\n")

    assert _pytest(tmp_path).returncode == 1  # a stale file fails
    assert stale.read_text().endswith("0,999,E,0,0,0\n")

    updated = _pytest(tmp_path, "--update-golden")
    assert updated.returncode == 1 and "rewritten" in updated.stdout
    assert stale.read_text() == f"{command}\n{expected}"

    assert _pytest(tmp_path).returncode == 0
