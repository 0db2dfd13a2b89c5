"""Bulk versions of the polygon fill and Wu's line: every pixel at once, as numpy arrays.

They give exactly the pixels (and intensities) of the step tables of
:mod:`scanconv.algorithms.polygon` and :mod:`scanconv.algorithms.wu`, in the same order,
without a Python loop per pixel. Like :mod:`scanconv.algorithms.raster`, inputs are integers
(floats are refused: they are not exact) within ``|v| <= COORD_LIMIT``, and results are
``int64`` arrays ``(xs, ys)`` in scanconv's coordinates (x right, y up).

Exactness: an edge's crossing of scan line y is ``x0 + (y - y0) Δx / Δy``; its pixel boundary
``ceil`` is computed as ``-((-(x0 Δy + (y - y0) Δx)) // Δy)`` in int64, whose operands stay
below ``6 * 10**18 < 2**63`` for coordinates within ``10**9``. Only ``ceil(x)`` decides a pixel
(a centre ``p`` is right of a crossing ``x`` exactly when ``ceil(x) <= p``), so the crossings
are sorted by it, and the spans are read off a cumulative sum: even-odd fills where the running
count of crossings is odd, nonzero where the running winding number is not zero. Every scan
line's crossings sum to an even count and a zero winding number, so the sums never carry from
one scan line to the next.

Compared with :func:`skimage.draw.polygon`: scikit-image fills every pixel whose centre is
inside *or on* the polygon (a closed polygon), scanconv the half-open one (centres on a right or
top edge, or on a top vertex, are left to the neighbour). The fills agree everywhere else;
``tests/test_polygon.py`` checks that the difference is exactly the centres on the boundary.
Compared with :func:`skimage.draw.line_aa` (Zingl's algorithm): the same pixel pairs, but its
intensity is ``1 - d cos θ`` with ``d`` the vertical distance to the pixel centre (a
perpendicular distance), Wu's is ``1 - d``; so its columns sum to more than 1.

>>> xs, ys = polygon([0, 4, 2], [0, 0, 3])
>>> list(zip(xs.tolist(), ys.tolist()))
[(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
"""

from __future__ import annotations

import operator
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..core.checks import InputError
from ..core.numeric import COORD_LIMIT
from .polygon import RULES, fill_rule

if TYPE_CHECKING:
    from ..core.choices import FillRuleName

Array = npt.NDArray[np.int64]

PIXEL_BUDGET = 2 * 10**7
"""Most pixels one call of :mod:`scanconv.raster` returns: their int64 coordinates take 16
bytes a pixel, so 320 MB (and a few seconds) at the budget, where a line of 10**9 pixels
needed 16 GB. Checked from the arguments before any array is allocated."""


def check_pixels(count: int, param: str) -> None:
    """Refuse a primitive of more than :data:`PIXEL_BUDGET` pixels, naming ``param``.

    >>> check_pixels(10**9 + 1, "x2")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: about 1,000,000,001 pixels: scanconv.raster returns at most 20,000,000 at once (320 MB of coordinates); draw it in parts
    """
    if count > PIXEL_BUDGET:
        raise InputError(
            f"about {count:,} pixels: scanconv.raster returns at most {PIXEL_BUDGET:,} at once "
            f"({PIXEL_BUDGET * 16 // 10**6:,} MB of coordinates); draw it in parts",
            param,
        )


def _ints(values: Sequence[object] | npt.ArrayLike, name: str) -> Array:
    """Integer coordinates as int64, or an error naming the problem."""
    arr = np.asarray(values)
    if arr.ndim != 1:
        raise InputError(f"{name} must be a 1-D sequence of integers", name)
    if arr.dtype.kind not in "iu":
        if arr.dtype.kind == "O":
            try:
                arr = np.array([operator.index(v) for v in arr.tolist()], dtype=np.int64)
            except TypeError:
                raise InputError(f"{name} must be integers (floats are not exact)", name) from None
        else:
            raise InputError(f"{name} must be integers (floats are not exact)", name)
    arr = arr.astype(np.int64)
    if arr.size and int(np.abs(arr).max()) > COORD_LIMIT:
        raise InputError(f"{name} out of range (|value| <= {COORD_LIMIT:.0e})", name)
    return arr


def polygon(
    xs: Sequence[int] | npt.ArrayLike,
    ys: Sequence[int] | npt.ArrayLike,
    rule: FillRuleName = "even-odd",
) -> tuple[Array, Array]:
    """Every pixel of the scan-line fill of a polygon, as numpy arrays.

    Parameters
    ----------
    xs, ys : sequence or 1-D array of int
        The vertices ``(xs[i], ys[i])`` in order, integers with ``|v| <= 10**9``, at least 3.
    rule : {"even-odd", "nonzero"}, default "even-odd"
        The inside rule: odd crossings, or a nonzero winding number.

    Returns
    -------
    xs, ys : (N,) ndarray of int64
        The filled pixels, bottom row first, left to right: exactly
        :func:`~scanconv.algorithms.polygon.fill_pixels` (``scanconv.polygon(...).pixels()``).

    Notes
    -----
    Scan line y meets an edge when ``y_min <= y < y_max``; each span runs from ``ceil(x)`` of its
    left crossing to ``ceil(x) - 1`` of its right one, all spans at once (no Python loop per
    pixel). Unlike ``skimage.draw.polygon`` the coordinates are ``(x, y)``, y up, and nothing is
    clipped to a shape.

    Examples
    --------
    >>> xs, ys = polygon([0, 4, 2], [0, 0, 3])
    >>> list(zip(xs.tolist(), ys.tolist()))
    [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
    >>> from scanconv.algorithms.polygon import fill_pixels
    >>> xs, ys = polygon([0, 4, 4, 0], [0, 4, 0, 4], rule="nonzero")  # a bow tie
    >>> list(zip(xs.tolist(), ys.tolist())) == fill_pixels([(0, 0), (4, 4), (4, 0), (0, 4)], "nonzero")
    True
    """
    if rule not in RULES:
        raise InputError(f"unknown fill rule {rule!r} (choose from {', '.join(RULES)})", "rule")
    x, y = _ints(xs, "xs"), _ints(ys, "ys")
    if x.size != y.size:
        raise InputError("xs and ys must have the same length", "ys")
    if x.size < 3:
        raise InputError(f"a polygon needs at least 3 vertices, got {x.size}", "vertices")
    xa, ya, xb, yb = x, y, np.roll(x, -1), np.roll(y, -1)
    keep = ya != yb
    xa, ya, xb, yb = xa[keep], ya[keep], xb[keep], yb[keep]
    direction = np.where(yb > ya, 1, -1)
    low = yb < ya
    x0, y0 = np.where(low, xb, xa), np.where(low, yb, ya)
    x1, y1 = np.where(low, xa, xb), np.where(low, ya, yb)
    dy, dx = y1 - y0, x1 - x0
    counts = dy  # scan lines y0 .. y1 - 1 (integer vertices: the upper end excluded)
    total = int(counts.sum())
    check_pixels(total, "vertices")
    empty = np.empty(0, dtype=np.int64)
    if total == 0:
        return empty, empty.copy()
    edge = np.repeat(np.arange(counts.size), counts)
    starts = np.cumsum(counts) - counts
    offset = np.arange(total, dtype=np.int64) - np.repeat(starts, counts)
    line = y0[edge] + offset
    num = x0[edge] * dy[edge] + offset * dx[edge]
    cx = -((-num) // dy[edge])  # ceil(x) of each crossing
    order = np.lexsort((cx, line))
    line, cx, d = line[order], cx[order], direction[edge][order]
    if fill_rule(rule).alternates:
        on = (np.arange(total) % 2) == 0  # every scan line has an even number of crossings
    else:
        on = np.cumsum(d) != 0
    a, b = cx[:-1][on[:-1]], cx[1:][on[:-1]]
    rows = line[:-1][on[:-1]]
    length = np.maximum(b - a, 0)
    n = int(length.sum())
    check_pixels(n, "vertices")
    if n == 0:
        return empty, empty.copy()
    first = np.cumsum(length) - length
    px = np.arange(n, dtype=np.int64) - np.repeat(first - a, length)
    py = np.repeat(rows, length)
    return px, py


def line_aa(x1: int, y1: int, x2: int, y2: int) -> tuple[Array, Array, npt.NDArray[np.float64]]:
    """Xiaolin Wu's anti-aliased line, every pixel at once, as numpy arrays.

    Parameters
    ----------
    x1, y1, x2, y2 : int
        The end points, integers with ``|v| <= 10**9``.

    Returns
    -------
    xs, ys : (2N,) ndarray of int64
        Two pixels per step of the major axis (the lower or left one first), in the order of
        :func:`scanconv.algorithms.wu.wu`'s table, N the major axis's length plus one.
    intensity : (2N,) ndarray of float64
        Each pixel's intensity: ``1 - frac`` and ``frac`` of the ideal minor coordinate.

    Notes
    -----
    Wu, "An efficient antialiasing technique", SIGGRAPH 1991: the end points are integers, so
    each end pixel has intensity 1 and its neighbour 0 (:func:`scanconv.antialias_line` with
    ``method="wu"`` works the same table step by step).
    Unlike ``skimage.draw.line_aa``, coordinates are ``(x, y)`` with y up.

    Examples
    --------
    >>> xs, ys, v = line_aa(0, 0, 4, 1)
    >>> list(zip(xs.tolist(), ys.tolist(), v.tolist()))[:4]
    [(0, 0, 1.0), (0, 1, 0.0), (1, 0, 0.75), (1, 1, 0.25)]
    >>> xs.size, v.sum().item()  # 5 columns, one unit of intensity each
    (10, 5.0)
    """
    for name, v in (("x1", x1), ("y1", y1), ("x2", x2), ("y2", y2)):
        try:
            v = operator.index(v)
        except TypeError:
            raise InputError(f"{name} must be an integer (floats are not exact)", name) from None
        if abs(v) > COORD_LIMIT:
            raise InputError(f"{name} = {v} is out of range (|value| <= {COORD_LIMIT:.0e})", name)
    x1, y1, x2, y2 = (operator.index(v) for v in (x1, y1, x2, y2))
    steep = abs(y2 - y1) > abs(x2 - x1)
    a1, b1, a2, b2 = (y1, x1, y2, x2) if steep else (x1, y1, x2, y2)
    if a2 < a1:
        a1, b1, a2, b2 = a2, b2, a1, b1
    da, db = a2 - a1, b2 - b1
    check_pixels(2 * (da + 1), "y2" if steep else "x2")
    k = np.arange(da + 1, dtype=np.int64)
    if da == 0:
        low, rem, den = np.array([b1], dtype=np.int64), np.zeros(1, dtype=np.int64), 1
    else:
        num = db * k  # |db| <= da <= 2e9: below 4e18
        low, rem, den = b1 + num // da, num % da, da
    a = a1 + k
    major = np.repeat(a, 2)
    minor = np.stack((low, low + 1), axis=1).ravel()
    # Both numerators and den are below 2**53: each value is the exact fraction, rounded once.
    val = np.stack(((den - rem) / den, rem / den), axis=1).ravel()
    return (minor, major, val) if steep else (major, minor, val)
