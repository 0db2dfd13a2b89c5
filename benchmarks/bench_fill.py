"""The bulk polygon fill and Wu's line against scikit-image: ``python benchmarks/bench_fill.py``.

Prints one Markdown table. Each ratio is taken in the same run, the contestants timed in turn
(round robin), median of the repeats (``--repeat N``, default 5):

* a 1,000-vertex star-shaped polygon (about 10^6 pixels of bounding box):
  :func:`scanconv.algorithms.raster_fill.polygon` against :func:`skimage.draw.polygon`, and the
  exact table fill :func:`scanconv.algorithms.polygon.fill_pixels` for scale (once);
* a 10^6-pixel line: :func:`scanconv.algorithms.raster_fill.line_aa` (Wu, 2 pixels a column)
  against :func:`skimage.draw.line_aa`.

The pixel sets are compared too: the fills differ only by the centres on the polygon's right
and top edges (skimage fills the closed polygon), the lines have the same pixel pairs.
Benchmarks never run in the tests.
"""

from __future__ import annotations

import argparse
import math
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from skimage.draw import line_aa as sk_line_aa
from skimage.draw import polygon as sk_polygon

from scanconv.algorithms import raster_fill
from scanconv.algorithms.polygon import fill_pixels


def race(contestants: dict[str, Callable[[], Any]], repeat: int) -> dict[str, float]:
    """Median wall time of each contestant, run in turn ``repeat`` times after a warm-up."""
    for fn in contestants.values():
        fn()
    times: dict[str, list[float]] = {name: [] for name in contestants}
    for _ in range(repeat):
        for name, fn in contestants.items():
            start = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - start)
    return {name: statistics.median(t) for name, t in times.items()}


def star(n: int, radius: int = 499) -> tuple[list[int], list[int]]:
    """A star-shaped polygon of ``n`` integer vertices (radius alternating 1 and 0.6)."""
    xs, ys = [], []
    for k in range(n):
        r = radius if k % 2 == 0 else int(radius * 0.6)
        a = 2 * math.pi * k / n
        xs.append(round(radius + r * math.cos(a)))
        ys.append(round(radius + r * math.sin(a)))
    return xs, ys


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    rows = []

    xs, ys = star(1000)
    ours = raster_fill.polygon(xs, ys)
    rr, cc = sk_polygon(ys, xs)
    mine = set(zip(ours[0].tolist(), ours[1].tolist(), strict=True))
    theirs = set(zip(cc.tolist(), rr.tolist(), strict=True))
    assert mine <= theirs
    t = race(
        {"scanconv": lambda: raster_fill.polygon(xs, ys), "skimage": lambda: sk_polygon(ys, xs)},
        args.repeat,
    )
    start = time.perf_counter()
    table = fill_pixels(list(zip(xs, ys, strict=True)))
    t_table = time.perf_counter() - start
    assert len(table) == len(mine)
    rows.append(
        (
            f"polygon, 1,000 vertices, {len(mine):,} pixels ({len(theirs) - len(mine)} more "
            "in skimage: centres on the edges)",
            t["scanconv"],
            t["skimage"],
            f"table fill: {t_table:.2f} s",
        )
    )

    n = 10**6 // 2  # Wu plots two pixels a column: 10^6 pixels
    x1, y1, x2, y2 = 0, 0, n - 1, 12345
    lx, ly, _ = raster_fill.line_aa(x1, y1, x2, y2)
    sr, sc, _ = sk_line_aa(y1, x1, y2, x2)
    same = set(zip(lx.tolist(), ly.tolist(), strict=True)) >= set(
        zip(sc.tolist(), sr.tolist(), strict=True)
    )
    t = race(
        {
            "scanconv": lambda: raster_fill.line_aa(x1, y1, x2, y2),
            "skimage": lambda: sk_line_aa(y1, x1, y2, x2),
        },
        args.repeat,
    )
    rows.append(
        (
            f"Wu line, {lx.size:,} pixels (skimage's pixels a subset: {same})",
            t["scanconv"],
            t["skimage"],
            "",
        )
    )

    print("| case | scanconv | skimage | skimage / scanconv | note |")
    print("|---|---:|---:|---:|---|")
    for case, ours_t, theirs_t, note in rows:
        print(
            f"| {case} | {ours_t * 1e3:.1f} ms | {theirs_t * 1e3:.1f} ms | "
            f"{theirs_t / ours_t:.2f} | {note} |"
        )
    print(f"\nnumpy {np.__version__}; median of {args.repeat} runs")


if __name__ == "__main__":
    main()
