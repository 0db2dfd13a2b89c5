"""Every command at its documented limit, in csv or json: wall time and peak memory, measured
with ``/usr/bin/time -v`` (issue 19: within 60 s and 500 MB on a 2-CPU machine; ``sample`` at
4096 x 4096 in csv within 10 s and 300 MB).

``python benchmarks/bench_limits.py`` prints one Markdown table (``--only WORD`` runs the rows
whose command contains WORD). Output goes to ``/dev/null`` through a file, as a redirected run
would write it; the rows run one after another. Benchmarks never run in the tests.
"""

from __future__ import annotations

import argparse
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCANCONV = [sys.executable, "-m", "scanconv"]
TARGET_SECONDS, TARGET_MB = 60, 500

#: A 500-character polynomial (the formula limit): the issue's six-minute parametric case.
POLYNOMIAL = "+".join(f"{i % 9 + 1}*t**{i % 12}" for i in range(60))[:500].rstrip("+*t")
POINTS_100 = [str((i * 7919) % 1000 if i % 2 else (i * 104729) % 997) for i in range(200)]
SQUARE_1000 = ["0", "0", "999", "0", "999", "999", "0", "999"]  # a 1000 x 1000 box: 10**6 cells
SEED_ROWS = "/".join(["#" * 100] + ["#" + "." * 98 + "#"] * 98 + ["#" * 100])  # 10**4 cells
CHECK = ROOT / "tests" / "data" / "check" / "slip.csv"

#: (what is at its limit, argv). Each is the largest input its limit accepts.
CASES: list[tuple[str, list[str]]] = [
    ("side 4096, L 256", ["sample", "x*y", "--size", "4096", "--levels", "256", "-f", "csv"]),
    ("side 4096, L 256", ["sample", "x*y", "--size", "4096", "--levels", "256", "-f", "json"]),
    (
        "side 4096, L 2^24",
        ["sample", "sin(x/99)*cos(y/70)", "--size", "4096", "-L", "16777216", "-f", "csv"],
    ),
    ("side 4096", ["image", "ramp", "--size", "4096", "--levels", "256", "-f", "csv"]),
    (
        "10^5 samples, 500-char formula",
        ["parametric", "custom", "--x", POLYNOMIAL, "--y", "t", "-n", "100000", "-f", "csv"],
    ),
    (
        "10^5 samples, 500-char formula",
        ["parametric", "custom", "--x", POLYNOMIAL, "--y", "t", "-n", "100000", "-f", "json"],
    ),
    (
        "10^5 samples, path near 10^6",
        ["parametric", "circle", "--radius", "150000", "-n", "100000", "-f", "csv"],
    ),
    (
        "10^5 samples",
        ["parametric", "ellipse", "--a", "1000", "--b", "600", "-n", "100000", "-f", "json"],
    ),
    ("10^5 samples", ["parametric", "parabola", "--a", "1/3", "-n", "100000", "-f", "csv"]),
    ("10^5 samples", ["parametric", "line", "0", "0", "99999", "7", "-n", "100000", "-f", "csv"]),
    ("10^5 weights, 100 points", ["bezier", *POINTS_100, "--samples", "999", "-f", "csv"]),
    (
        "10^5 weights, 100 points, p = 10",
        ["bspline", *POINTS_100, "--degree", "10", "--samples", "999", "-f", "csv"],
    ),
    (
        "10^5 weights, 2 x 50 points",
        ["continuity", *POINTS_100[:100], ":", *POINTS_100[100:], "-n", "999", "-f", "json"],
    ),
    (
        "10^5 weights, 100 points, p = 10",
        [
            "local-control",
            *POINTS_100,
            "--move",
            "50",
            "1",
            "1",
            "--degree",
            "10",
            "-n",
            "999",
            "-f",
            "csv",
        ],
    ),
    ("rx = ry = 10^6", ["ellipse", "1000000", "1000000", "-f", "csv"]),
    ("rx = ry = 10^6", ["ellipse", "1000000", "1000000", "-f", "json"]),
    ("length 10^4", ["compare", "line", "0", "0", "10000", "3", "-f", "csv"]),
    ("r = 2000", ["compare", "circle", "2000", "-f", "csv"]),
    ("10^6 fill cells", ["polygon", *SQUARE_1000, "-f", "json"]),
    ("10^4 seed cells", ["fill", "flood", "--rows", SEED_ROWS, "--seed", "1", "1", "-f", "csv"]),
    (
        "10^4 AA cells, 16 x 16 samples",
        ["antialias", "circle", "48", "--method", "supersample", "--samples", "16", "-f", "csv"],
    ),
    ("10^4 question rows", ["check", str(CHECK), "--", "line", "0", "0", "9999", "1", "-f", "csv"]),
    ("24 bits: 2^24 rows (streamed)", ["quantize", "--bits", "24", "-f", "csv"]),
    ("24 bits: 2^24 rows (streamed)", ["quantize", "--bits", "24", "-f", "json"]),
    (
        "no limit of its own: 2 x 10^6 rows (streamed)",
        ["line", "0", "0", "1999999", "1", "-f", "csv"],
    ),
    ("no limit of its own: r = 2 x 10^6 (streamed)", ["circle", "2000000", "-f", "csv"]),
    (
        "any size (exact integers)",
        [
            "storage",
            "1000000000",
            "1000000000",
            "--bits",
            "24",
            "--frames",
            "1000000000",
            "-f",
            "json",
        ],
    ),
    (
        "refused at once: 4096^2 in rich",
        ["sample", "x*y", "--size", "4096", "--levels", "256", "-f", "rich"],
    ),
    (
        "refused at once: 2048^2 in latex",
        ["sample", "x*y", "--size", "2048", "--levels", "256", "-f", "latex"],
    ),
    ("refused at once: 1.4 M rows in rich", ["ellipse", "1000000", "1000000", "-f", "rich"]),
    (
        "refused at once: path over 10^6",
        ["parametric", "custom", "--x", "t*10000000", "--y", "t", "-n", "100000", "-f", "csv"],
    ),
]


def measure(argv: list[str], timeout: float) -> tuple[float, float, int]:
    """``(seconds, peak MB, exit status)`` of one run, from ``/usr/bin/time -v``."""
    with tempfile.TemporaryDirectory() as tmp:
        report = Path(tmp) / "time.txt"
        try:
            proc = subprocess.run(
                ["/usr/bin/time", "-v", "-o", str(report), *SCANCONV, *argv],
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                timeout=timeout,
                cwd=ROOT,
            )
        except subprocess.TimeoutExpired:
            return timeout, float("nan"), -1
        text = report.read_text()
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    assert wall and rss, text
    parts = [float(p) for p in wall.group(1).split(":")]
    seconds = sum(p * 60**i for i, p in enumerate(reversed(parts)))
    status = re.search(r"Exit status: (\d+)", text)
    return seconds, int(rss.group(1)) / 1024, int(status.group(1)) if status else proc.returncode


def _shown(argv: list[str]) -> str:
    words = [a if len(a) <= 24 else a[:12] + "…" for a in argv]
    if len(words) > 14:
        words = [*words[:10], "…", *words[-4:]]
    return "`scanconv " + " ".join(shlex.quote(w) for w in words).replace("|", "\\|") + "`"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="run the rows whose command contains this")
    parser.add_argument("--timeout", type=float, default=600)
    args = parser.parse_args()
    print("| command | at the limit | wall time | peak RSS | exit | within 60 s and 500 MB |")
    print("|---|---|--:|--:|:-:|:-:|")
    for what, argv in CASES:
        if args.only and args.only not in " ".join(argv):
            continue
        seconds, mb, status = measure(argv, args.timeout)
        ok = "yes" if seconds <= TARGET_SECONDS and mb <= TARGET_MB else "**no**"
        print(
            f"| {_shown(argv)} | {what} | {seconds:.2f} s | {mb:.0f} MB | {status} | {ok} |",
            flush=True,
        )


if __name__ == "__main__":
    main()
