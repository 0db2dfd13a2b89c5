"""Re-measure the row costs of the work budget (:data:`scanconv.render.work.COSTS`).

For every (command, method) and every output format, run ``scanconv`` twice in a subprocess
(output to /dev/null): once with a tiny table and once with a table of about ``--seconds`` of
work, and take the CPU time (user + system, from ``wait4``) per row between the two, in
microseconds. The peak resident size of the big run is printed beside it. The result is the
``COSTS`` table as Python source, ready to paste into ``scanconv/render/work.py``, then each
measured cost against the one in the code (a ratio over 1.5 means the budget is too generous
on this machine).

``python benchmarks/bench_budget.py`` (about ten minutes on a quiet 2-CPU machine);
``--only WORD`` measures the entries whose key contains WORD; ``--formats csv,json`` only those
formats. Benchmarks never run in the tests.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
SCANCONV = [sys.executable, "-m", "scanconv"]
FORMATS = ("csv", "json", "plain", "markdown", "latex", "html", "rich")

Argv = Callable[[int], list[str]]
Args = Callable[[int], dict[str, Any]]
Case = tuple[Args, Argv]


def _line(cmd: list[str], flag: str, method: str) -> Case:
    opts = [flag, method] if method else []
    return (
        lambda n: {"x1": 0, "y1": 0, "x2": n - 1, "y2": 1, "algo": method, "method": method},
        lambda n: [*cmd, "0", "0", str(n - 1), "1", *opts, "--no-grid"],
    )


def _circle(method: str) -> Case:
    def r(n: int) -> int:  # one octant: about r / sqrt(2) rows
        return math.ceil(n * math.sqrt(2))

    return (
        lambda n: {"r": r(n), "method": method},
        lambda n: ["circle", str(r(n)), "--method", method, "--no-grid"],
    )


def _ellipse() -> Case:
    def a(n: int) -> str:
        return str(math.ceil(n / math.sqrt(2)))

    return (lambda n: {"rx": a(n), "ry": a(n)}, lambda n: ["ellipse", a(n), a(n), "--no-grid"])


def _pipeline(algo: str) -> Case:
    def argv(n: int) -> list[str]:
        w = str(n - 1)
        window = ["0", "0", w, "1"]
        return [
            "pipeline", "line", *window, "--window", *window, "--viewport", *window,
            "--algo", algo, "--no-grid",
        ]  # fmt: skip

    return lambda n: {"viewport": [0, 0, n - 1, 1], "algo": algo}, argv


def _samples(cmd: list[str], points: list[str] | None = None) -> Case:
    return (
        lambda n: {"samples": n - 1, "points": points},
        lambda n: [*cmd, *(points or []), "--samples", str(n - 1)],
    )


def _polygon() -> Case:
    # scan lines of a thin triangle n - 1 high: one row each
    return (
        lambda n: {"vertices": [0, 0, 3, 0, 1, n - 1]},
        lambda n: ["polygon", "0", "0", "3", "0", "1", str(n - 1)],
    )


def _bits(n: int) -> int:  # 2^bits rows: the nearest power of two
    return max(1, round(math.log2(n)))


def _quantize(ranged: bool) -> Case:
    extra = ["--range", "0", "1", "--input", "real"] if ranged else []
    return (
        lambda n: {"bits": _bits(n), "value_range": extra[1:3] or None},
        lambda n: ["quantize", "--bits", str(_bits(n)), *extra],
    )


def _side(n: int) -> int:
    return max(1, math.isqrt(n) - 2)


def _aa(shape: str, method: str) -> Case:
    # the box of the shape: about n cells (at most MAX_AA_CELLS = 10^4)
    extra = ["--method", method, *(["--samples", "16"] if method == "supersample" else [])]
    common = {"method": method, "samples": 16}
    if shape == "circle":
        return (
            lambda n: {"r": _side(n) // 2, **common},
            lambda n: ["antialias", "circle", str(_side(n) // 2), *extra],
        )
    if shape == "line":
        return (
            lambda n: {"x1": 0, "y1": 0, "x2": _side(n), "y2": _side(n), **common},
            lambda n: ["antialias", "line", "0", "0", str(_side(n)), str(_side(n)), *extra],
        )
    return (
        lambda n: {"vertices": [0, 0, _side(n), 0, _side(n), _side(n)], **common},
        lambda n: ["antialias", "polygon", "0", "0", *[str(_side(n))] * 2, "0", str(_side(n)),
                   *extra],
    )  # fmt: skip


def _matrix() -> Case:
    def side(n: int) -> str:
        return str(max(2, math.isqrt(n)))

    return (
        lambda n: {"size": side(n)},
        lambda n: ["sample", "x*y+1/3", "--size", side(n), "-L", "8"],
    )


POINTS = ["0", "0", "3", "9", "6", "9", "9", "0", "12", "4", "15", "8", "18", "1", "21", "5"]
LINES = ("basic", "dda", "bresenham", "wu", "midpoint", "symmetric-dda")
CIRCLES = ("midpoint", "bresenham", "polynomial", "general", "trig", "symmetric-dda")

#: (costs key, library function, its arguments and the command line for about n rows).
CASES: list[tuple[str, str, Case]] = [
    *[(f"line/{m}", "line", _line(["line"], "--algo", m)) for m in LINES],
    *[(f"circle/{m}", "circle", _circle(m)) for m in CIRCLES],
    ("ellipse/midpoint", "ellipse", _ellipse()),
    ("antialias_line/wu", "antialias_line", _line(["antialias", "line"], "--method", "wu")),
    *[
        (f"antialias_{s}/{m}", f"antialias_{s}", _aa(s, m))
        for s in ("line", "circle", "polygon")
        for m in ("area", "supersample")
    ],
    *[(f"pipeline_line/{m}", "pipeline_line", _pipeline(m)) for m in LINES[:3]],
    ("polygon/scan-line", "polygon", _polygon()),
    ("quantize", "quantize", _quantize(False)),
    ("quantize/range", "quantize", _quantize(True)),
    ("parametric", "parametric_circle", _samples(["parametric", "circle", "--radius", "100"])),
    ("curve", "bezier", _samples(["bezier"], points=POINTS)),
    ("compare_lines", "compare_lines", _line(["compare", "line"], "", "")),
    ("matrix", "sample", _matrix()),
]

#: Rows of the big run per format: about a second of output at the format's usual cost.
BIG_ROWS = {"rich": 2_000, "html": 20_000, "markdown": 20_000, "latex": 20_000}
SMALL_ROWS = 16


def big_rows(key: str, fmt: str, rows: int) -> int:
    """The rows of the big run of ``key`` in ``fmt``."""
    big = BIG_ROWS.get(fmt, rows)
    if key.endswith("/wu") or "symmetric" in key or key.startswith("compare"):
        big //= 5
    if key.startswith("antialias_") and not key.endswith("/wu"):  # a box of 10^4 cells at most
        big = min(big, 9_000) // (10 if "supersample" in key else 1)
    if "symmetric" in key:  # r <= algorithms.circles.SDDA_MAX_RADIUS: 11,585 rows
        big = min(big, 8_000)
    if key == "matrix" and fmt in ("rich", "latex", "markdown"):
        big = min(big, 65_536)
    if key.startswith("compare"):
        big = min(big, 10_000)
    return big


def run(argv: list[str], fmt: str) -> tuple[float, int]:
    """CPU seconds and peak KB of ``scanconv ARGV --format FMT`` (stdout to /dev/null)."""
    proc = subprocess.Popen(
        [*SCANCONV, *argv, "--format", fmt],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        cwd=ROOT,
        env={**os.environ, "COLUMNS": "120"},
    )
    _, _, usage = os.wait4(proc.pid, 0)
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss


def measure(function: str, case: Case, fmt: str, big: int) -> tuple[float, int]:
    """Microseconds of CPU per estimated row (of weight 1), and the big run's peak KB."""
    from scanconv.render.work import estimate

    args, argv = case

    def rows(n: int) -> float:
        work = estimate(function, args(n))
        assert work is not None, (function, args(n))
        return work.size * work.weight

    t0, _ = run(argv(SMALL_ROWS), fmt)
    t1, kb = run(argv(big), fmt)
    return max(t1 - t0, 0.0) / (rows(big) - rows(SMALL_ROWS)) * 1e6, kb


def print_markdown(costs: dict[str, dict[str, float]]) -> None:
    """The costs, and the rows of weight 1 each format prints within the budget
    (:func:`scanconv.render.budget.row_limit`), as a Markdown table."""
    from scanconv.render import Format
    from scanconv.render.budget import row_limit
    from scanconv.render.work import Work

    print("| command/method | " + " | ".join(FORMATS) + " |")
    print("|---|" + "--:|" * len(FORMATS))
    for key, row in costs.items():
        work = Work("rows", 1, None, key)
        cells = [
            f"{row[f]:g} ({row_limit(work, Format(f)) / 1000:,.0f}k)" if f in row else "-"
            for f in FORMATS
        ]
        print(f"| {key} | " + " | ".join(cells) + " |")


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--only", default="", help="measure the keys containing this")
    parser.add_argument("--formats", default=",".join(FORMATS))
    parser.add_argument("--rows", type=int, default=100_000, help="rows of a big csv/json run")
    parser.add_argument(
        "--markdown", action="store_true", help="print the code's COSTS as a Markdown table"
    )
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from scanconv.render.work import COSTS

    if args.markdown:
        print_markdown(COSTS)
        return
    formats = args.formats.split(",")
    measured: dict[str, dict[str, float]] = {}
    for key, function, case in CASES:
        if args.only not in key:
            continue
        costs = measured.setdefault(key, {})
        for fmt in formats:
            us, kb = measure(function, case, fmt, big_rows(key, fmt, args.rows))
            costs[fmt] = round(us, 1)
            have = COSTS.get(key, {}).get(fmt)
            ratio = f"{us / have:.2f}" if have else "-"
            print(f"# {key:28} {fmt:9} {us:9.1f} us/row  peak {kb / 1024:6.0f} MB  x{ratio}")
            sys.stdout.flush()
    print("COSTS = {")
    for key, costs in measured.items():
        print(f'    "{key}": {costs!r},')
    print("}")


if __name__ == "__main__":
    main()
