"""The ``--update-golden`` flag rewrites a stale golden file and then fails; the next run passes."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parent.parent


#: What the inner pytest must not inherit: it is a run of its own, not one of this run's
#: xdist workers (with ``PYTEST_XDIST_WORKER`` and ``SLIPCOVER_ENABLED`` SlipCover's plugin
#: instrumented scanconv in it and wrote its coverage over this worker's file: 6 s of CPU a
#: run, against 1 s now).
_OUTER = ("PYTEST_", "SLIPCOVER_", "COV_CORE_", "HYPOTHESIS_")


def _pytest(golden: Path, *flags: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(_OUTER)}
    # no plugin loaded from entry points (xdist, cov, benchmark, hypothesis's, SlipCover's):
    # the golden test needs only tests/conftest.py, which imports hypothesis itself (and so
    # not the ini file's ``--dist``, an option of xdist's)
    env |= {"SCANCONV_GOLDEN_DIR": str(golden), "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1"}
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         "-o", "addopts=--strict-markers", str(ROOT / "tests" / "test_golden.py"), *flags],
        capture_output=True,
        text=True,
        env=env,
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
