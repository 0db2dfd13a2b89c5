"""``scanconv ... | head -1``: the reader leaves early; scanconv stops quietly with status 0.

``tests/test_cli.py`` covers the CSV line; this covers the other streamed formats and a curve.
``set -o pipefail`` makes the shell's status scanconv's own, so a non-zero exit shows.
"""

from __future__ import annotations

import shlex
import subprocess
import sys

import pytest

LONG_LINE = ["line", "0", "0", "1000000", "3"]
#: Each case is a real shell pipeline (two processes, about 0.3 s of CPU): the first stays in
#: the inner loop, the others run in the whole suite (``slow``).
SLOW = pytest.mark.slow
PIPES = [
    pytest.param([*LONG_LINE, "--format", "json"], '{"primitive": "line"', id="line json"),
    pytest.param(
        [*LONG_LINE, "--format", "markdown"], "## Bresenham", id="line markdown", marks=SLOW
    ),
    pytest.param([*LONG_LINE, "--format", "plain"], "Bresenham", id="line plain", marks=SLOW),
    pytest.param([*LONG_LINE, "--format", "latex"], "% scanconv", id="line latex", marks=SLOW),
    # rich prints at most 10,000 rows (scanconv.render.budget): the longest line it takes
    pytest.param(
        ["line", "0", "0", "9999", "3", "--format", "rich"], "Bresenham", id="line rich", marks=SLOW
    ),
    pytest.param(
        ["bezier", "0", "0", "300", "900", "1000", "0", "--samples", "30000", "--format", "csv"],
        "k,x,y,t,B0,B1,B2,x_t,y_t",
        id="bezier csv",
        marks=SLOW,
    ),
    pytest.param(
        ["parametric", "circle", "--radius", "1000", "-n", "20000", "--format", "markdown"],
        "## Parametric circle",
        id="parametric circle markdown",
        marks=SLOW,
    ),
]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(("args", "first"), PIPES)
def test_head_closes_the_pipe_and_scanconv_exits_quietly(args, first):
    command = " ".join(shlex.quote(a) for a in (sys.executable, "-m", "scanconv", *args))
    proc = subprocess.run(
        ["bash", "-c", f"set -o pipefail; {command} | head -1"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith(first), proc.stdout[:200]
    assert proc.stdout.count("\n") == 1
    assert proc.stderr == "", proc.stderr  # no BrokenPipeError, no "Exception ignored"


@pytest.mark.slow
def test_the_help_into_a_closed_pipe_is_quiet() -> None:
    """``scanconv | true``: the bare command's help into a pipe whose reader has gone exits
    0 with nothing on stderr (it printed a BrokenPipeError traceback)."""
    import subprocess
    import sys

    for _ in range(3):
        p = subprocess.Popen(
            [sys.executable, "-m", "scanconv"], stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        assert p.stdout is not None and p.stderr is not None
        p.stdout.close()
        err = p.stderr.read()
        p.wait(timeout=60)
        assert err == b"" and p.returncode == 0, err[-300:]
