"""CI fails when any check fails: lint, format, types, the layers contract, tests or coverage
under 90 %.

``tests/test_docs.py`` checks that ``.ci/run`` runs the README's test command verbatim. Here the
command itself is run with stand-ins for ruff, mypy and pytest that succeed or fail on demand,
so the test shows that each failure reaches the exit status of ``.ci/run``.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")
CI = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
TEST_COMMAND = re.findall(r"```sh\n(.*?)\n```", README, flags=re.S)[1].split(
    "pip install -e '.[test]' && ", 1
)[1]

STUB = """#!/usr/bin/env bash
echo "$(basename "$0")${*:+ $*}" >> "$STUB_LOG"
key="$(basename "$0")${1:+ $1}"
[ "$key" = "$STUB_FAIL" ] && exit 1
exit 0
"""


def test_the_test_command_is_the_last_line_of_ci():
    """Its status is the script's: nothing runs after it (and set -e / pipefail are on)."""
    lines = [ln for ln in CI.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    assert lines[-1] == TEST_COMMAND
    assert "set -euo pipefail" in CI


def test_the_command_checks_lint_format_types_and_coverage():
    steps = [s.strip() for s in TEST_COMMAND.split("&&")]
    assert steps == [
        "ruff check .",
        "ruff format --check .",
        "mypy",
        "lint-imports --no-cache",
        "python -m slipcover --source scanconv --json --out .coverage.json -m pytest -n auto",
        "python tests/coverage_floor.py .coverage.json 90",
    ]
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert re.search(r'\[tool\.coverage\.run\]\nsource = \["scanconv"\]', pyproject)
    assert re.search(r'\[tool\.mypy\][^\[]*files = \["scanconv"\]', pyproject)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    "failing",
    [
        None,
        "ruff check",
        "ruff format",
        "mypy",
        "lint-imports --no-cache",
        "python -m",  # the tests under SlipCover
        "python tests/coverage_floor.py",  # coverage under 90 %
    ],
    ids=str,
)
def test_any_failing_check_fails_the_run(failing, tmp_path):
    for tool in ("ruff", "mypy", "lint-imports", "python"):
        stub = tmp_path / tool
        stub.write_text(STUB)
        stub.chmod(0o755)
    log = tmp_path / "log"
    proc = subprocess.run(
        ["bash", "-c", f"set -euo pipefail\n{TEST_COMMAND}\n"],
        env={
            "PATH": f"{tmp_path}:/usr/bin:/bin",
            "STUB_LOG": str(log),
            "STUB_FAIL": failing or "",
        },
        capture_output=True,
        text=True,
        timeout=60,
    )
    ran = log.read_text().splitlines()
    if failing is None:
        assert proc.returncode == 0
        assert ran == [
            "ruff check .",
            "ruff format --check .",
            "mypy",
            "lint-imports --no-cache",
            "python -m slipcover --source scanconv --json --out .coverage.json -m pytest -n auto",
            "python tests/coverage_floor.py .coverage.json 90",
        ]
    else:
        assert proc.returncode != 0, ran
        assert ran[-1].startswith(failing)  # it stopped at the failing check


_INNER = """
import time
import pytest

def test_loops():
    while True:
        time.sleep(0.05)

def test_needs_a_program():
    pytest.skip("no frobnicator on PATH (apt-get install frobnicator)")
"""


@pytest.mark.slow  # an inner pytest run
def test_a_hanging_test_fails_and_a_skip_is_named(tmp_path):
    """The project's pytest options (pyproject's addopts) make a looping test fail with a
    timeout instead of hanging the run (here shortened from 300 s to 3 s), and list every
    skip with its reason, so a machine without chromium or pdflatex says what it skipped."""
    (tmp_path / "test_inner.py").write_text(_INNER)
    addopts = re.search(r'^addopts = "(.*)"$', (ROOT / "pyproject.toml").read_text(), re.M)
    assert addopts is not None
    opts = [o for o in addopts[1].split() if not o.startswith("--timeout")]
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-p",
            "no:cacheprovider",
            "-o",
            "addopts=",
            *[o for o in opts if o not in ("--dist", "worksteal")],
            "--timeout=3",
            str(tmp_path),
        ],
        capture_output=True,
        text=True,
        timeout=120,  # a guard: the inner run ends in seconds
        cwd=tmp_path,
        # a run of its own: not the outer run's SlipCover, xdist or hypothesis settings
        env={
            k: v
            for k, v in os.environ.items()
            if not k.startswith(("PYTEST_", "SLIPCOVER_", "COV_CORE_", "HYPOTHESIS_"))
        },
    )
    assert proc.returncode == 1, proc.stdout
    assert "Timeout" in proc.stdout and "1 failed, 1 skipped" in proc.stdout
    assert "SKIPPED [1]" in proc.stdout and "no frobnicator on PATH" in proc.stdout
    assert "--timeout=300" in addopts[1] and "-rs" in addopts[1].split()
