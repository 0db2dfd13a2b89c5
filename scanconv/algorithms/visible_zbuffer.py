"""The depth-buffer (z-buffer) method on a small grid, in exact arithmetic (Hearn & Baker,
*Computer Graphics, C version*, 2nd ed., §13-3).

Each polygon is planar, ``A x + B y + C z + D = 0`` (:func:`scanconv.algorithms.visible.plane`),
projected orthographically onto the xy plane (the viewer looks along z). Its pixels are the
scan-line fill's (:func:`scanconv.algorithms.polygon.scanline_fill`: pixel centres at integer
points, half-open spans and edges), walked from the top scan line down. The depth at a pixel
is ``z = (-A x - B y - D) / C``; along a scan line ``z(x + 1) = z(x) - A/C``; down the left
edge (``y -> y - 1``, ``x -> x - 1/m``) ``z' = z + (A/m + B)/C``. The first pixel of a span
takes its depth from the left edge's, ``z = z_L - (A/C)(x - x_L)``.

Each pixel is compared with the depth buffer: written when nearer (the ``depth`` convention:
a larger z nearer, as Hearn & Baker's C version, or a smaller one), equal depths as the
``ties`` convention says (``keep``: the first polygon keeps the pixel).

>>> polys = (("A", ((0, 0, 1), (3, 0, 1), (0, 3, 1))),)
>>> [(s.pixel, s.z, s.written) for s in zbuffer(polys, 3, 3)][:3]
[((0, 2), 1, True), ((0, 1), 1, True), ((1, 1), 1, True)]
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .polygon import scanline_fill
from .visible import Face, Plane, plane

MAX_POLYGONS = 8
"""The most polygons of a z-buffer, scan-line or Warnock answer."""
MAX_SIDE = 32
"""The largest grid side (pixels across or down)."""

Named = Sequence[tuple[str, Face]]
"""Polygons with their names (``A``, ``B``, ...), in drawing order."""


def depth_at(p: Plane, x: Number, y: Number) -> Number:
    """``z = (-A x - B y - D) / C`` (``C != 0``).

    >>> depth_at(Plane(1, 1, 1, -6), 1, 2)
    3
    """
    return normalize(Fraction(-p.a * x - p.b * y - p.d) / p.c)


def check_plane(name: str, face: Face) -> Plane:
    """The polygon's plane; :class:`InputError` when it is seen edge-on (``C = 0``)."""
    p = plane(face)
    if p.c == 0:
        raise InputError(f"polygon {name} is seen edge-on (C = 0): it covers no area in x, y")
    return p


def check_grid(width: int, height: int) -> None:
    """:class:`InputError` for a grid side below 1 or above :data:`MAX_SIDE` (before work)."""
    for side, what in ((width, "width"), (height, "height")):
        if not 1 <= side <= MAX_SIDE:
            raise InputError(f"the grid's {what} is {side}; it is 1 to {MAX_SIDE} pixels", "size")


def nearer(z: Number, old: Number | None, depth: str = "larger-nearer", ties: str = "keep") -> bool:
    """Whether depth ``z`` replaces ``old`` in the buffer (``None``: the initial, farthest
    value).

    >>> nearer(2, 1), nearer(1, 1), nearer(1, 1, ties="replace"), nearer(2, 1, "smaller-nearer")
    (True, False, True, False)
    """
    if old is None:
        return True
    if z == old:
        return ties == "replace"
    return z > old if depth == "larger-nearer" else z < old


class ScanRow(NamedTuple):
    """One scan line of one polygon: its left edge and the depth there, and its pixels."""

    y: int
    edge: int
    """The left edge's index (edge i runs from vertex i to vertex i + 1)."""
    x_edge: Number
    z_edge: Number
    incremental: bool
    """``z_edge`` is the scan line above's plus ``(A/m + B)/C`` (same left edge); else from
    the plane equation."""
    inv_m: Number
    runs: tuple[tuple[int, int], ...]
    """The pixels ``(first, last)`` of each span, cut to the grid."""


def edge_step(p: Plane, inv_m: Number) -> Number:
    """The depth's change down an edge, one scan line: ``(A/m + B)/C``."""
    return normalize(Fraction(p.a * inv_m + p.b) / p.c)


def scan_rows(face: Face, p: Plane, width: int, height: int) -> list[ScanRow]:
    """The polygon's scan lines inside the grid, the top one first."""
    lines = list(scanline_fill([(v[0], v[1]) for v in face]))
    out: list[ScanRow] = []
    above: ScanRow | None = None
    for s in reversed(lines):
        runs = tuple(
            (max(a, 0), min(b, width - 1)) for a, b in s.runs if a <= b and b >= 0 and a < width
        )
        if not s.active or not 0 <= s.y < height:
            above = None
            continue
        left = s.active[0]
        if above is not None and above.edge == left.edge and above.y == s.y + 1:
            z, inc = normalize(above.z_edge + edge_step(p, left.inv_m)), True
        else:
            z, inc = depth_at(p, left.x, s.y), False
        row = ScanRow(
            s.y, left.edge, left.x, z, inc, left.inv_m, tuple(r for r in runs if r[0] <= r[1])
        )
        above = row
        if row.runs:
            out.append(row)
    return out


class ZStep(NamedTuple):
    """One pixel of one polygon against the depth buffer: a row of the step table."""

    k: int
    polygon: int
    """The polygon's index in drawing order."""
    pixel: tuple[int, int]
    z: Number
    first: bool
    """The first pixel of a span (``z`` from the left edge's depth), else ``z - A/C``."""
    before: Number | None
    """The buffer's depth before (``None``: the initial, farthest value)."""
    holder: int | None
    """The polygon the frame buffer held before (``None``: the background)."""
    written: bool
    edge: tuple[Number, Number] = (0, 0)
    """``(x_L, z_L)``: the left edge's x and depth on this scan line (the first pixel's)."""


def zbuffer(
    polygons: Named,
    width: int,
    height: int,
    knobs: Mapping[str, str] | None = None,
    far: Number | None = None,
) -> Iterator[ZStep]:
    """The z-buffer's steps: each polygon in order, its scan lines from the top, each pixel
    compared with the buffer (initially ``far``, or the farthest value when ``None``)."""
    k = {"depth": "larger-nearer", "ties": "keep", **(knobs or {})}
    check_grid(width, height)
    depth: dict[tuple[int, int], Number | None] = {}
    frame: dict[tuple[int, int], int] = {}
    n = 0
    for i, (name, face) in enumerate(polygons):
        p = check_plane(name, face)
        step_x = normalize(Fraction(-p.a) / p.c)
        for row in scan_rows(face, p, width, height):
            for first, last in row.runs:
                z = normalize(row.z_edge + step_x * (first - row.x_edge))
                for x in range(first, last + 1):
                    pixel = (x, row.y)
                    before = depth.get(pixel, far)
                    ok = nearer(z, before, k["depth"], k["ties"])
                    edge = (row.x_edge, row.z_edge)
                    yield ZStep(n, i, pixel, z, x == first, before, frame.get(pixel), ok, edge)
                    n += 1
                    if ok:
                        depth[pixel], frame[pixel] = z, i
                    z = normalize(z + step_x)


def buffers(
    steps: Sequence[ZStep],
) -> tuple[dict[tuple[int, int], int], dict[tuple[int, int], Number]]:
    """The final frame buffer (pixel to polygon index) and depth buffer of the steps."""
    frame: dict[tuple[int, int], int] = {}
    depth: dict[tuple[int, int], Number] = {}
    for s in steps:
        if s.written:
            frame[s.pixel], depth[s.pixel] = s.polygon, s.z
    return frame, depth


def rows_bound(polygons: int, width: int, height: int) -> int:
    """At most one step per polygon and pixel."""
    return max(1, polygons * width * height)


def grid_of(polygons: Named) -> tuple[int, int]:
    """The smallest grid from x = 0, y = 0 that holds every vertex."""
    xs = [v[0] for _, f in polygons for v in f]
    ys = [v[1] for _, f in polygons for v in f]
    return max(1, math.floor(max(xs)) + 1), max(1, math.floor(max(ys)) + 1)
