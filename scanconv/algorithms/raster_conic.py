"""Bulk circles and ellipses for :mod:`scanconv.raster`: every pixel at once, as numpy arrays.

The midpoint circle and ellipse of :mod:`scanconv.algorithms.circles` and
:mod:`scanconv.algorithms.ellipses`, in the same order, with no Python loop per pixel (the lines
are in :mod:`scanconv.algorithms.raster`, whose conventions on inputs and results apply here).

Each decision compares ``(q t)**2`` with ``4 p**2 d``, up to ``4 * 10**36``, which no machine
integer holds. They are estimated in float64 (:func:`_odd_below`), whose error is bounded far
below the margin used, and every value within that margin of a decision boundary is decided
again in exact Python integers.

Examples
--------
>>> xs, ys = circle(3)
>>> list(zip(xs.tolist(), ys.tolist()))[:4]
[(0, 3), (0, -3), (3, 0), (-3, 0)]
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable

import numpy as np

from ..core.checks import check_integer
from . import circles
from .raster import BLOCK, Array, Coords, _exact
from .raster_fill import check_pixels

Image = tuple[bool, int, int]
"""How a symmetric image is made from an octant point ``(a, b)``: ``(swap, sx, sy)`` gives
``(xc + sx u, yc + sy v)`` with ``(u, v) = (b, a)`` if ``swap`` else ``(a, b)``."""

IMAGES: tuple[Image, ...] = (
    (False, 1, 1),
    (False, -1, 1),
    (False, 1, -1),
    (False, -1, -1),
    (True, 1, 1),
    (True, -1, 1),
    (True, 1, -1),
    (True, -1, -1),
)
"""The 8 images in :func:`scanconv.algorithms.circles.images` order; the first 4 are the ellipse's."""

Segment = tuple[Array, Array, tuple[Image, ...], int, int]
"""Points ``(a, b)``, the images each one gives, and the centre ``(xc, yc)``."""


def _int(value: object, name: str, *, negative: bool = True) -> int:
    """An integer argument within :data:`COORD_LIMIT`, as a Python ``int``."""
    return check_integer(_exact(value, name), name, negative=negative)


_FLOAT_EXACT = 2.0**50
"""Counts from here on are decided in exact integers: float64 no longer resolves their units."""


def _odd_exact(d: int, p: int, q: int, strict: bool) -> int:
    """:func:`_odd_below` for one value, in exact integers."""
    v = 4 * p * p * d
    if v == 0:
        return 0
    return ((math.isqrt(v - 1) if strict else math.isqrt(v)) // q + 1) // 2


def _odd_below(d: Array, p: int, q: int, *, strict: bool) -> Array:
    """How many odd ``t >= 1`` satisfy ``t < g`` (or ``t <= g``), ``g = 2p·sqrt(d)/q``, exactly.

    The midpoint decisions are all of this form: the circle's y at column x is the number of
    odd t with ``t < 2 sqrt(r² - x²)``. g is estimated in float64 (relative error below
    ``4·2**-53``); where ``(g + 1) / 2`` lies within ``10**-12 (g + 1)`` of an integer (a
    margin thousands of times that error) the count is decided again by comparing
    ``(q t)²`` with ``4 p² d`` in exact Python integers, as is every count of ``2**50`` or more
    (never reached by a circle or ellipse within the coordinate limit). Negative d counts as 0.

    >>> _odd_below(np.array([0, 1, 2, 9, 16, -5], dtype=np.int64), 1, 1, strict=True).tolist()
    [0, 1, 1, 3, 4, 0]
    >>> _odd_below(np.array([9, 16], dtype=np.int64), 1, 2, strict=False).tolist()
    [2, 2]
    """
    if d.size == 0:
        return np.zeros(0, dtype=np.int64)
    d = np.maximum(d, 0)
    h = np.sqrt(d.astype(np.float64))
    h *= 2.0 * p / q
    h += 1.0
    h *= 0.5
    count = np.floor(h).astype(np.int64)
    near = np.flatnonzero(np.abs(h - np.rint(h)) <= 1e-12 * (h + 1.0))
    huge = np.flatnonzero(h >= _FLOAT_EXACT)
    if huge.size:  # beyond the circles' and ellipses' range: float64 cannot tell m from m + 1
        near = np.setdiff1d(near, huge)
        count[huge] = [_odd_exact(int(v), p, q, strict) for v in d[huge]]
    if near.size:
        m = np.rint(h[near]).astype(np.int64).astype(object)
        lhs = (q * (2 * m - 1)) ** 2  # t = 2m - 1 >= 1: the odd number nearest g
        rhs = 4 * p * p * d[near].astype(object)
        below = (lhs < rhs) if strict else (lhs <= rhs)
        count[near] = np.where(below.astype(bool), m, m - 1).astype(np.int64)
    return count


def _step_down(target: Array, start: int) -> Array:
    """``y_0 = start``, ``y_k = max(y_{k-1} - 1, target_k)``: all k at once.

    The walk of region 1: each step keeps y when the midpoint is inside (y <= target) and
    lowers it by one otherwise. ``y_k + k`` is the running maximum of ``target_j + j``.

    >>> _step_down(np.array([5, 5, 2, 1, 1], dtype=np.int64), 5).tolist()
    [5, 5, 4, 3, 2]
    """
    k = np.arange(target.size, dtype=np.int64)
    z = target + k
    z[0] = start
    np.maximum.accumulate(z, out=z)
    return z - k


def _step_up(target: Array, start: int) -> Array:
    """``x_{-1} = start``, ``x_k = min(x_{k-1} + 1, max(x_{k-1}, target_k))``: all k at once.

    The walk of region 2 toward a non-decreasing target. ``x_k - k`` is the running minimum
    of ``max(start, target_j) - j``, capped at ``start + 1``.

    >>> _step_up(np.array([3, 5, 5, 6], dtype=np.int64), 3).tolist()
    [3, 4, 5, 6]
    """
    k = np.arange(target.size, dtype=np.int64)
    w = np.maximum(target, start) - k
    np.minimum.accumulate(w, out=w)
    np.minimum(w, start + 1, out=w)
    return w + k


def _first(pred: Callable[[int], bool], hi: int) -> int:
    """The least k in ``0 .. hi`` with ``pred(k)``, for a monotone ``pred``; ``hi + 1`` if none."""
    return bisect.bisect_left(range(hi + 1), True, key=pred)


def _first_past(target: Callable[[Array], Array], r: int) -> int:
    """The least x in ``0 .. r`` with ``x >= target(x)`` (a monotone predicate), ``r + 1`` if
    none: among 33 columns around r/√2 (where a circle's octant ends) at once, by bisection
    only if it lies outside them. (Bisection alone made a small circle's few dozen pixels cost
    a dozen one-element numpy passes.)

    >>> t = lambda x: 100 - x
    >>> _first_past(t, 100), _first(lambda x: x >= 100 - x, 100)
    (50, 50)
    """
    lo = max(0, math.isqrt(r * r // 2) - 16)
    xs = np.arange(lo, min(r, lo + 32) + 1, dtype=np.int64)
    past = xs >= target(xs)
    if past[-1] and (lo == 0 or not past[0]):
        return lo + int(np.argmax(past))
    return _first(lambda x: x >= int(target(np.array([x], dtype=np.int64))[0]), r)


def _assemble(segments: list[Segment]) -> Coords:
    """The images of every segment's points, segment after segment, point after point.

    The output is allocated once and filled :data:`BLOCK` pixels at a time, one column per
    image, so the (large) result is written in a single pass.
    """
    total = sum(a.size * len(imgs) for a, _, imgs, _, _ in segments)
    xs, ys = np.empty(total, dtype=np.int64), np.empty(total, dtype=np.int64)
    at = 0
    for a, b, imgs, xc, yc in segments:
        n, m = a.size, len(imgs)
        out = (xs[at : at + n * m].reshape(n, m), ys[at : at + n * m].reshape(n, m))
        rows = max(1, BLOCK // m)
        for i in range(0, n, rows):
            part = {False: a[i : i + rows], True: b[i : i + rows]}
            made: dict[tuple[int, bool, int], Array] = {}
            for j, (swap, sx, sy) in enumerate(imgs):
                for axis, c, src, s in ((0, xc, swap, sx), (1, yc, not swap, sy)):
                    key = (axis, src, s)
                    if key not in made:
                        made[key] = c + part[src] if s > 0 else c - part[src]
                    out[axis][i : i + rows, j] = made[key]
        at += n * m
    return xs, ys


def _given(pixels: list[tuple[int, int]]) -> Segment:
    """A segment of pixels already made."""
    pts = np.array(pixels, dtype=np.int64).reshape(-1, 2)
    return pts[:, 0].copy(), pts[:, 1].copy(), IMAGES[:1], 0, 0


def circle(r: int, xc: int = 0, yc: int = 0) -> Coords:
    """Every pixel of the midpoint circle, in the order its ``Solution.pixels()`` plots them.

    Parameters
    ----------
    r : int
        Radius, ``0 <= r <= 10**9``.
    xc, yc : int
        Centre, ``|v| <= 10**9``.

    Returns
    -------
    xs, ys : (N,) ndarray of int64
        ``circle_solution("midpoint", r, xc, yc).pixels()``: each octant point's 8 images in
        :func:`scanconv.algorithms.circles.images` order, each pixel once. Bresenham's circle
        (``d0 = 3 - 2r``) plots the same pixels in the same order.

    Notes
    -----
    ``p_k = f(x + 1, y - 1/2) - 1/4`` with ``f = x² + y² - r²`` and y stays when ``p_k < 0``:
    when y is at most the largest y with ``(y - 1/2)² < r² - x²``, which is the number of odd
    t with ``t < 2 sqrt(r² - x²)`` (:func:`_odd_below`). The walk lowers y by at most one
    per step (:func:`_step_down`) and ends at the first x with ``x >= y``. The start point and
    the last one (on or just past the diagonal) go through
    :func:`scanconv.algorithms.circles.symmetric_pixels`; every point in between has 8 distinct images
    that no other point has.

    Examples
    --------
    >>> xs, ys = circle(5, 10, 10)
    >>> list(zip(xs.tolist(), ys.tolist()))[:6]
    [(10, 15), (10, 5), (15, 10), (5, 10), (11, 15), (9, 15)]
    >>> xs.size
    28
    """
    r = _int(r, "radius", negative=False)
    xc, yc = _int(xc, "xc"), _int(yc, "yc")
    check_pixels(math.ceil(4 * math.sqrt(2) * r) + 8, "r")
    head = list(circles.symmetric_pixels([(0, r)], xc, yc))
    if r == 0:
        return _assemble([_given(head)])

    def target(x: Array) -> Array:
        return _odd_below((r - x) * (r + x), 1, 1, strict=True)

    def walk(hi: int) -> tuple[Array, int]:
        ys = _step_down(target(np.arange(hi + 1, dtype=np.int64)), r)
        past = np.arange(hi + 1, dtype=np.int64) >= ys  # monotone: False then True
        return ys, int(np.argmax(past)) if past[-1] else hi + 1

    # The walk ends near the first x with x >= target(x); a few columns more cover any lag.
    guess = _first_past(target, r)
    ys, last = walk(min(guess + 8, r))
    if last > ys.size - 1:  # pragma: no cover - the lag never reaches 8 columns
        ys, last = walk(r)
    seen = len(list(circles.symmetric_pixels([(last - 1, int(ys[last - 1]))], xc, yc)))
    both = [(last - 1, int(ys[last - 1])), (last, int(ys[last]))]
    tail = list(circles.symmetric_pixels(both, xc, yc))[seen:]
    middle = np.arange(1, last, dtype=np.int64)
    return _assemble([_given(head), (middle, ys[1:last], IMAGES, xc, yc), _given(tail)])


def ellipse(rx: int, ry: int, xc: int = 0, yc: int = 0) -> Coords:
    """Every pixel of the midpoint ellipse, in the order its ``Solution.pixels()`` plots them.

    Parameters
    ----------
    rx, ry : int
        Semi-axes, ``0 <= r <= 10**9``; a zero semi-axis gives the segment between the tips.
    xc, yc : int
        Centre, ``|v| <= 10**9``.

    Returns
    -------
    xs, ys : (N,) ndarray of int64
        ``ellipse_solution(rx, ry, xc, yc).pixels()``: each quadrant point's 4 images
        ``(xc+x, yc+y), (xc-x, yc+y), (xc+x, yc-y), (xc-x, yc-y)``, each pixel once.

    Notes
    -----
    With ``f = ry²x² + rx²y² - rx²ry²``: ``p1_k = f(x + 1, y - 1/2)`` and y stays when
    ``p1_k < 0``; ``p2_k = f(x + 1/2, y - 1)`` and x stays when ``p2_k > 0``, both exact in the
    generator (``p1_0 = ry² - rx²ry + rx²/4``). So region 1 keeps y while y is at most the
    number of odd t with ``rx t < 2 ry sqrt(rx² - x²)``, and region 2 steps x while x is
    below the number of odd t with ``ry t <= 2 rx sqrt(ry² - y²)`` (:func:`_odd_below`), one
    pixel per step (:func:`_step_down`, :func:`_step_up`). Region 1 ends at the first point
    with ``ry² x >= rx² y`` (bisection, exact integers); a flat ellipse then ends along
    y = 0 to the tip, as :func:`scanconv.algorithms.ellipses.midpoint_ellipse` does.

    Examples
    --------
    >>> xs, ys = ellipse(8, 6)
    >>> list(zip(xs.tolist(), ys.tolist()))[:6]
    [(0, 6), (0, -6), (1, 6), (-1, 6), (1, -6), (-1, -6)]
    >>> xs.size
    40
    """
    rx, ry = _int(rx, "rx", negative=False), _int(ry, "ry", negative=False)
    xc, yc = _int(xc, "xc"), _int(yc, "yc")
    check_pixels(4 * (rx + ry) + 4, "rx" if rx >= ry else "ry")
    px, py = _quadrant(rx, ry)
    # x never decreases and y never increases along the walk: the points on the y axis come
    # first, then the origin (if it is a point), the points off the axes, and those on the x
    # axis last. Only points on an axis have fewer than 4 distinct images.
    n = px.size
    a = int(np.count_nonzero((px == 0) & (py > 0)))
    o = a + int(np.count_nonzero((px == 0) & (py == 0)))
    c = n - int(np.count_nonzero((py == 0) & (px > 0)))
    return _assemble(
        [
            (px[:a], py[:a], (IMAGES[0], IMAGES[2]), xc, yc),
            (px[a:o], py[a:o], IMAGES[:1], xc, yc),
            (px[o:c], py[o:c], IMAGES[:4], xc, yc),
            (px[c:], py[c:], IMAGES[:2], xc, yc),
        ]
    )


def _quadrant(rx: int, ry: int) -> tuple[Array, Array]:
    """The points of :func:`scanconv.algorithms.ellipses.quadrant_points`, as arrays."""
    if rx == 0:  # region 1 is empty; region 2 walks down the y axis
        return np.zeros(ry + 1, dtype=np.int64), np.arange(ry, -1, -1, dtype=np.int64)

    def target1(x: Array) -> Array:  # region 1: y stays while y <= target1(x)
        return _odd_below((rx - x) * (rx + x), ry, rx, strict=True)

    def region1(hi: int) -> tuple[Array, int]:
        ys = _step_down(target1(np.arange(hi + 1, dtype=np.int64)), ry)
        return ys, _first(lambda x: ry * ry * x >= rx * rx * int(ys[x]), hi)

    guess = _first(lambda x: ry * ry * x >= rx * rx * int(target1(np.array([x]))[0]), rx)
    y1, end = region1(guess + 64)
    if end > y1.size - 1:  # pragma: no cover - the lag never reaches 64 columns
        y1, end = region1(rx + ry + 1)  # the generator's walk is never longer
    x1, y1 = np.arange(end + 1, dtype=np.int64), y1[: end + 1]
    x0, y0 = end, int(y1[-1])
    y2 = np.arange(y0 - 1, -1, -1, dtype=np.int64)  # region 2: one row per step
    target2 = _odd_below((ry - y2) * (ry + y2), rx, ry, strict=False)  # x steps while below
    x2 = _step_up(target2, x0)
    tip = np.arange(int(x2[-1]) + 1 if x2.size else x0 + 1, rx + 1, dtype=np.int64)
    return np.concatenate((x1, x2, tip)), np.concatenate((y1, y2, np.zeros_like(tip)))
