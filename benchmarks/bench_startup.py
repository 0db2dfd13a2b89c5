"""Start-up of an installed scanconv against ``python -c "import typer"``, paired runs.

Usage: ``python benchmarks/bench_startup.py VENV [--pairs 21] [--format plain]``

``VENV`` is a virtual environment with a *regular* (not editable) install of scanconv::

    python3 -m venv /tmp/regvenv && /tmp/regvenv/bin/pip install -q .
    # after each change: /tmp/regvenv/bin/pip install -q --force-reinstall --no-deps .
    python benchmarks/bench_startup.py /tmp/regvenv

Each pair runs ``VENV/bin/python -c "import typer"`` then ``VENV/bin/scanconv line 2 2 10 6
--algo bresenham --format plain`` back to back, so both see the same load on a shared
machine. It prints, for wall time and for CPU time (user + sys of the child), the medians of
each side, their ratio and the median of the paired ratios (the figure the target reads:
at most 1.3). Three warm-up pairs fill the bytecode cache first.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path


def timed(cmd: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds of one run of ``cmd``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("venv", type=Path, help="a venv with a regular install of scanconv")
    parser.add_argument("--pairs", type=int, default=21, help="paired runs (default 21)")
    parser.add_argument("--format", default="plain", help="the answer's --format")
    args = parser.parse_args(argv)
    typer_run = [str(args.venv / "bin" / "python"), "-c", "import typer"]
    scanconv_run = [str(args.venv / "bin" / "scanconv"), "line", "2", "2", "10", "6"]
    scanconv_run += ["--algo", "bresenham", "--format", args.format]
    for _ in range(3):
        timed(typer_run)
        timed(scanconv_run)
    pairs = [(timed(typer_run), timed(scanconv_run)) for _ in range(args.pairs)]
    for index, name in ((0, "wall"), (1, "cpu")):
        base = statistics.median(a[index] for a, _ in pairs)
        ours = statistics.median(b[index] for _, b in pairs)
        paired = statistics.median(b[index] / a[index] for a, b in pairs)
        print(
            f"{name}: typer {base * 1000:.1f} ms, scanconv {ours * 1000:.1f} ms, "
            f"ratio of medians {ours / base:.2f}, median paired ratio {paired:.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
