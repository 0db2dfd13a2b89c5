"""scanconv's performance targets, measured side by side: ``python benchmarks/bench.py``.

Prints one Markdown table (the one in the README's "Performance" section). Every ratio is
taken in the same run, each contestant timed in turn (round robin), median of the repeats:

* bulk rasterizers (:mod:`scanconv.raster`) against ``skimage.draw`` (the ``bench`` extra),
  with the pixels compared too;
* the Bresenham step generator in records per second (the PyPI ``bresenham`` package, which
  yields bare pixels, for scale);
* peak RSS of the streaming CSV and JSON output of a 2,000,001-pixel line, and of one ten
  times shorter;
* start-up of the CLI against ``python -c "import typer"``.

Start-up is measured the way an installed scanconv runs: with compiled bytecode. The children
get ``PYTHONPYCACHEPREFIX`` (a temporary folder, so the source tree stays clean) and no
``PYTHONDONTWRITEBYTECODE``, and one warm-up run each fills the cache first.

Options: ``--repeat N`` (default 7; start-up uses 3N), ``--quick`` (smaller streaming lines
and fewer repeats, for a smoke test), ``--no-streaming``.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import deque
from collections.abc import Callable
from importlib.metadata import version
from typing import Any

import numpy as np

from scanconv import raster
from scanconv.algorithms.lines import bresenham

Row = tuple[str, str, str, str, str]


def race(contestants: dict[str, Callable[[], Any]], repeat: int) -> dict[str, float]:
    """Median wall time of each contestant, run in turn ``repeat`` times after a warm-up."""
    for fn in contestants.values():
        fn()
    times: dict[str, list[float]] = {name: [] for name in contestants}
    for _ in range(repeat):
        for name, fn in contestants.items():
            t0 = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - t0)
    return {name: statistics.median(ts) for name, ts in times.items()}


def verdict(ok: bool) -> str:
    return "yes" if ok else "**no**"


def ms(seconds: float) -> str:
    return f"{seconds * 1e3:.1f} ms"


def pixel_keys(xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """The distinct pixels as sorted int64 keys (for comparing pixel sets)."""
    return np.unique((xs.astype(np.int64) + 2**31) * 2**32 + (ys.astype(np.int64) + 2**31))


Coords = tuple[np.ndarray, np.ndarray]


def versus_skimage(
    ours: Callable[[], Coords], theirs: Callable[[], Coords], repeat: int
) -> tuple[float, float, Coords, Coords]:
    """Median times of scanconv and skimage, and their pixels as ``(xs, ys)`` both."""
    t = race({"scanconv": ours, "skimage": theirs}, repeat)
    rr, cc = theirs()
    return t["scanconv"], t["skimage"], ours(), (cc, rr)


def bench_line(repeat: int) -> Row:
    import skimage.draw

    n = 10**7
    x2, y2 = n - 1, 3_141_592  # left to right, a slope with no small period
    t = race(
        {
            "scanconv": lambda: raster.line(0, 0, x2, y2),
            "one thread": lambda: raster.line(0, 0, x2, y2, parallel=False),
            "skimage": lambda: skimage.draw.line(0, 0, y2, x2),
        },
        repeat,
    )
    (xs, ys), (rr, cc) = raster.line(0, 0, x2, y2), skimage.draw.line(0, 0, y2, x2)
    same = np.array_equal(xs, cc) and np.array_equal(ys, rr)
    return (
        f"line, {n:,} pixels: `raster.line` / `skimage.draw.line`",
        f"{ms(t['scanconv'])} / {ms(t['skimage'])}; identical pixels: {verdict(same)}; "
        f"on one thread (`parallel=False`): {ms(t['one thread'])}, "
        f"{t['one thread'] / t['skimage']:.2f}x",
        f"{t['scanconv'] / t['skimage']:.2f}",
        "<= 1.0",
        verdict(t["scanconv"] <= t["skimage"] and same),
    )


def speedup(label: str, t_ours: float, t_sk: float, same: bool, factor: int, *, exact: bool) -> Row:
    """A row for "at least ``factor`` times faster"; ``exact``: the pixel sets must agree."""
    shown = verdict(same) if exact else ("yes" if same else "no")
    return (
        label,
        f"{ms(t_sk)} / {ms(t_ours)}; same pixel set: {shown}",
        f"{t_sk / t_ours:.1f}x",
        f">= {factor}x",
        verdict(t_sk >= factor * t_ours and (same or not exact)),
    )


def bench_circle(repeat: int) -> Row:
    import skimage.draw

    r = 10**6
    t_ours, t_sk, ours, theirs = versus_skimage(
        lambda: raster.circle(r),
        lambda: skimage.draw.circle_perimeter(0, 0, r, method="bresenham"),
        repeat,
    )
    same = np.array_equal(pixel_keys(*ours), pixel_keys(*theirs))
    label = (
        f"circle, r = {r:,}: `skimage.draw.circle_perimeter(method='bresenham')` / `raster.circle`"
    )
    return speedup(label, t_ours, t_sk, same, 10, exact=True)


def bench_ellipse(repeat: int) -> Row:
    import skimage.draw

    rx, ry = 10**6, 6 * 10**5
    t_ours, t_sk, ours, theirs = versus_skimage(
        lambda: raster.ellipse(rx, ry), lambda: skimage.draw.ellipse_perimeter(0, 0, ry, rx), repeat
    )
    # skimage draws Zingl's ellipse, not the midpoint one: the same set is not a target
    same = np.array_equal(pixel_keys(*ours), pixel_keys(*theirs))
    label = (
        f"ellipse, rx = {rx:,}, ry = {ry:,}: `skimage.draw.ellipse_perimeter` / `raster.ellipse`"
    )
    return speedup(label, t_ours, t_sk, same, 5, exact=False)


def bench_records(repeat: int) -> Row:
    n = 10**6
    contestants: dict[str, Callable[[], Any]] = {
        "scanconv": lambda: deque(bresenham(0, 0, n, n // 3), maxlen=0),
    }
    try:
        from bresenham import bresenham as bare

        contestants["pypi"] = lambda: deque(bare(0, 0, n, n // 3), maxlen=0)
    except ImportError:
        pass
    t = race(contestants, repeat)
    rate = n / t["scanconv"]
    scale = (
        f"; PyPI `bresenham` (bare pixels): {n / t['pypi'] / 1e6:.2f} M/s" if "pypi" in t else ""
    )
    return (
        "Bresenham step records per second (`scanconv.lines.bresenham`)",
        f"{rate / 1e6:.2f} M records/s{scale}",
        f"{rate / 1e6:.2f} M/s",
        ">= 1.5 M/s",
        verdict(rate >= 1.5e6),
    )


def cli() -> list[str]:
    exe = shutil.which("scanconv", path=os.path.dirname(sys.executable))
    return [exe] if exe else [sys.executable, "-m", "scanconv"]


# Runs a command with stdout to /dev/null and prints its peak RSS (KiB) and wall time. A
# fresh, small launcher process: a child forked straight from this one (which holds large
# arrays by now) would count this process's resident memory as its own peak.
LAUNCHER = """
import os, subprocess, sys, time
t0 = time.perf_counter()
with open(os.devnull, "w") as null:
    proc = subprocess.Popen(sys.argv[1:], stdout=null)
    _, status, usage = os.wait4(proc.pid, 0)
sys.exit(print(usage.ru_maxrss, time.perf_counter() - t0) or os.waitstatus_to_exitcode(status))
"""


def peak_rss_kb(args: list[str], env: dict[str, str] | None = None) -> tuple[int, float]:
    """Peak resident memory (KiB) and wall time of a command whose stdout goes to /dev/null."""
    done = subprocess.run(
        [sys.executable, "-c", LAUNCHER, *args], env=env, capture_output=True, text=True
    )
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(args)} failed: {done.stderr}")
    kb, seconds = done.stdout.split()
    return int(kb), float(seconds)


def bench_streaming(n: int, env: dict[str, str]) -> list[Row]:
    rows = []
    peak_rss_kb([*cli(), "line", "0", "0", "1", "1", "--format", "csv"], env)  # fill the cache
    for fmt in ("csv", "json"):
        long_kb, long_s = peak_rss_kb(
            [*cli(), "line", "0", "0", str(n), "1", "-a", "bresenham", "-f", fmt], env
        )
        short_kb, _ = peak_rss_kb(
            [*cli(), "line", "0", "0", str(n // 10), "1", "-a", "bresenham", "-f", fmt], env
        )
        rows.append(
            (
                f"streaming peak RSS: `scanconv line 0 0 {n} 1 --algo bresenham --format {fmt}`",
                f"{long_kb / 1024:.1f} MiB ({long_s:.1f} s); {n // 10:,} long: "
                f"{short_kb / 1024:.1f} MiB",
                f"{long_kb / 1024:.1f} MiB",
                "< 80 MB, <= the shorter line",
                # a page or two of allocator noise is not growth
                verdict(long_kb * 1024 < 80e6 and long_kb <= short_kb + 256),
            )
        )
    return rows


ONE_ARGUMENT_APP = """
import typer

def main(n: int) -> None:
    print(n)

typer.run(main)
"""


def startup_env() -> tuple[dict[str, str], str]:
    cache = tempfile.mkdtemp(prefix="scanconv-bench-pycache-")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPYCACHEPREFIX"] = cache
    return env, cache


def bench_startup(repeat: int, env: dict[str, str]) -> list[Row]:
    py = sys.executable
    commands = {
        "scanconv": [
            *cli(),
            "line",
            "2",
            "2",
            "10",
            "6",
            "--algo",
            "bresenham",
            "--format",
            "plain",
        ],
        "typer": [py, "-c", "import typer"],
        # the least any typer command with one argument costs (typer 0.29 would add pydantic)
        "typer app": [py, "-c", ONE_ARGUMENT_APP, "5"],
        "python": [py, "-c", "pass"],
    }

    def runner(args: list[str]) -> Callable[[], object]:
        return lambda: subprocess.run(args, env=env, stdout=subprocess.DEVNULL, check=True)

    for args in commands.values():  # warm-up: fill the bytecode cache
        runner(args)()
    t = race({name: runner(args) for name, args in commands.items()}, repeat)
    ratio = t["scanconv"] / t["typer"]
    return [
        (
            "start-up: `scanconv line 2 2 10 6 --algo bresenham --format plain` / "
            '`python -c "import typer"`',
            f"{ms(t['scanconv'])} / {ms(t['typer'])} (bare `python -c pass`: {ms(t['python'])}; "
            f"a one-argument typer app: {ms(t['typer app'])}, so "
            f"{t['scanconv'] / t['typer app']:.2f}x that)",
            f"{ratio:.2f}",
            "<= 1.3",
            verdict(ratio <= 1.3),
        )
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7, help="repeats per measurement")
    parser.add_argument("--quick", action="store_true", help="smaller and fewer: a smoke test")
    parser.add_argument("--no-streaming", action="store_true", help="skip the streaming rows")
    args = parser.parse_args(argv)
    repeat = 2 if args.quick else args.repeat
    env, cache = startup_env()
    rows: list[Row] = []
    try:
        for bench in (bench_line, bench_circle, bench_ellipse, bench_records):
            rows.append(bench(repeat))
            print(f"  {rows[-1][0]}: {rows[-1][2]}", file=sys.stderr)
        if not args.no_streaming:
            rows.extend(bench_streaming(20_000 if args.quick else 1_999_999, env))  # ALL_ROWS
        rows.extend(bench_startup(3 * repeat, env))
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    print(
        f"Python {platform.python_version()}, numpy {np.__version__}, "
        f"scikit-image {version('scikit-image')}, "
        f"{platform.machine()}, {os.cpu_count()} CPUs; median of {repeat} runs "
        f"({3 * repeat} for start-up)\n"
    )
    print("| measurement | measured | ratio / value | target | met |")
    print("|---|---|--:|:-:|:-:|")
    for row in rows:
        print("| " + " | ".join(row) + " |")
    return 0 if all(row[-1] == "yes" for row in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
