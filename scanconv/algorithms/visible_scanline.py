"""The scan-line method of visible-surface detection on a small grid, in exact arithmetic
(Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-4).

One edge table holds every polygon's edges (each polygon's scan-line fill rule:
:func:`scanconv.algorithms.polygon.edge_table`, an edge on scan line y when
``y_min <= y < y_max``), one polygon table each polygon's plane. On each scan line, from the
top, the active edges are sorted by x; crossing an edge turns its polygon's in/out flag over.
Between two crossings the flags do not change: where none is on, the background; where one is
on, that polygon; where several are on, their depths are compared at each pixel
(``z = (-Ax - By - D)/C``, the ``depth`` and ``ties`` conventions as the z-buffer's). A pixel
belongs to the interval ``[x_a, x_b)`` its centre lies in.

>>> polys = (("A", ((0, 0, 1), (4, 0, 1), (0, 4, 1))), ("B", ((1, 0, 2), (4, 0, 2), (4, 3, 2))))
>>> row = next(r for r in scanline(polys, 5, 5) if r.y == 1)
>>> [(c.polygon, c.x) for c in row.crossings]
[(0, 0), (1, 2), (0, 3), (1, 4)]
>>> [(i.on, [p.shown for p in i.pixels]) for i in row.intervals]
[((0,), [0, 0]), ((0, 1), [1]), ((1,), [1])]
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator, Mapping
from typing import NamedTuple

from ..core.numeric import Number
from .polygon import Edge, edge_table
from .visible import Plane
from .visible_zbuffer import Named, check_grid, check_plane, depth_at, nearer


class Crossing(NamedTuple):
    """An active edge on a scan line."""

    polygon: int
    edge: int
    x: Number


class Shown(NamedTuple):
    """One pixel of an interval: the depths compared (where several flags are on) and the
    polygon shown."""

    x: int
    depths: tuple[tuple[int, Number], ...]
    shown: int


class Interval(NamedTuple):
    """Between two crossings: the flags on and the pixels."""

    x_start: Number
    x_end: Number
    on: tuple[int, ...]
    """The polygons whose flag is on, in order."""
    pixels: tuple[Shown, ...]


class ScanRow(NamedTuple):
    """One scan line: its active edge list and its intervals with a flag on."""

    y: int
    crossings: tuple[Crossing, ...]
    intervals: tuple[Interval, ...]


def edges_of(polygons: Named) -> list[tuple[int, Edge]]:
    """The edge table of every polygon, by polygon then y_min."""
    return [
        (i, e)
        for i, (_, f) in enumerate(polygons)
        for e in edge_table([(v[0], v[1]) for v in f])[0]
    ]


def _pixels(
    on: tuple[int, ...],
    planes: tuple[Plane, ...],
    y: int,
    xa: Number,
    xb: Number,
    width: int,
    knobs: Mapping[str, str],
) -> tuple[Shown, ...]:
    out = []
    for x in range(max(math.ceil(xa), 0), min(math.ceil(xb) - 1, width - 1) + 1):
        depths = tuple((i, depth_at(planes[i], x, y)) for i in on)
        best = depths[0]
        for d in depths[1:]:
            if nearer(d[1], best[1], knobs["depth"], knobs["ties"]):
                best = d
        out.append(Shown(x, depths if len(on) > 1 else (), best[0]))
    return tuple(out)


def scanline(
    polygons: Named, width: int, height: int, knobs: Mapping[str, str] | None = None
) -> Iterator[ScanRow]:
    """Each scan line of the grid that meets a polygon, from the top."""
    k = {"depth": "larger-nearer", "ties": "keep", **(knobs or {})}
    check_grid(width, height)
    planes = tuple(check_plane(n, f) for n, f in polygons)
    edges = edges_of(polygons)
    for y in range(height - 1, -1, -1):
        crossings = sorted(
            (Crossing(i, e.idx, e.x_at(y)) for i, e in edges if e.y_min <= y < e.y_max),
            key=lambda c: (c.x, c.polygon, c.edge),
        )
        if not crossings:
            continue
        flags: set[int] = set()
        intervals = []
        for a, b in itertools.pairwise(crossings):
            flags ^= {a.polygon}
            if flags and a.x < b.x:
                on = tuple(sorted(flags))
                intervals.append(Interval(a.x, b.x, on, _pixels(on, planes, y, a.x, b.x, width, k)))
        yield ScanRow(y, tuple(crossings), tuple(intervals))


def frame_of(rows: list[ScanRow]) -> dict[tuple[int, int], int]:
    """The final frame buffer: pixel to polygon index."""
    return {(p.x, r.y): p.shown for r in rows for i in r.intervals for p in i.pixels}
