"""Bulk rasterizers: every pixel of a primitive at once, as numpy arrays.

The step generators (:mod:`scanconv.algorithms.lines`, :mod:`scanconv.algorithms.circles`, :mod:`scanconv.algorithms.ellipses`)
explain an algorithm one record at a time; the functions here give the same pixels, in the
same order, computed from closed forms with no Python loop per pixel. Use them to draw.

Every function returns ``(xs, ys)``, two 1-D ``numpy.int64`` arrays of equal length, like
``skimage.draw`` returns ``(rr, cc)``: pixel ``i`` is ``(xs[i], ys[i])`` in scanconv's
coordinates (x right, y up). ``np.column_stack((xs, ys))`` gives an ``(N, 2)`` array and
``img[ys, xs] = 1`` draws into an image whose row index is y.

Integer types
-------------
Inputs are Python ``int`` (or numpy integers) and, where an algorithm takes fractional end
points, :class:`fractions.Fraction`; floats are refused because they are not exact. Every
coordinate and size must satisfy ``|v| <= COORD_LIMIT`` (``10**9``). Results are ``int64``,
because a centre plus a radius reaches ``2 * 10**9``, beyond int32; every intermediate is kept
far inside int64 (or decided exactly in Python integers):

* lines: each coordinate is ``offset + floor(alpha + beta * k)`` with exact rationals
  ``alpha`` and ``beta`` (:func:`_floor_affine`). It is evaluated block by block
  (:data:`BLOCK` pixels) with the integer part of each block's first value split off in
  Python integers, so what is left is below ``c * (BLOCK + 1)`` for the common denominator
  ``c``: integer end points give ``c <= 4 * 10**9``. It is computed in int64 fixed point
  (scale ``2**k >= 8c``, an add and a shift per pixel, exact by a proven bound) whenever the
  scaled values fit, which they do for every line with integer end points; else it
  is divided in int64; denominators near ``2**63`` (fractional end points only) fall back to
  exact Python integers (slow, never wrong).
* circles and ellipses: each decision compares ``(q t)**2`` with ``4 p**2 d``, up to
  ``4 * 10**36``, which no machine integer holds. They are estimated in float64
  (:func:`_odd_below`), whose error is bounded far below the margin used, and every value
  within that margin of a decision boundary is decided again in exact Python integers.

Examples
--------
>>> xs, ys = line(2, 2, 10, 6)
>>> xs.dtype, list(zip(xs.tolist(), ys.tolist()))[:4]
(dtype('int64'), [(2, 2), (3, 3), (4, 3), (5, 4)])
"""

from __future__ import annotations

import bisect
import math
import operator
import threading
from collections.abc import Callable
from fractions import Fraction

import numpy as np
import numpy.typing as npt

from ..core.checks import check_integer
from ..core.numeric import COORD_LIMIT, Number, as_int, fmt_exact, normalize, round_half_up
from . import circles
from .lines import dda_increments, dda_steps, orient
from .raster_fill import check_pixels
from .raster_fill import line_aa as line_aa  # the bulk Wu line and fill: scanconv.raster too
from .raster_fill import polygon as polygon

Coords = tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]
"""``(xs, ys)``: two 1-D int64 arrays of equal length."""

LINE_ALGORITHMS = ("bresenham", "dda", "basic")
"""The line algorithms :func:`line` computes, by their ``--algo`` names."""

BLOCK = 1 << 15
"""Pixels computed per block: small enough for the temporaries to stay in cache."""

PARALLEL_MIN = 1 << 20
"""Lines with at least this many pixels compute x and y on two threads (see :func:`line`)."""

_INT64_MAX = int(np.iinfo(np.int64).max)


def _exact(value: object, name: str) -> Number:
    """``value`` as an exact ``int`` or ``Fraction`` within :data:`COORD_LIMIT`."""
    v: Number
    if isinstance(value, Fraction):
        v = normalize(value)
    else:
        try:
            v = operator.index(value)  # type: ignore[arg-type]
        except TypeError:
            raise TypeError(
                f"{name} must be an int or a Fraction, got {type(value).__name__}"
            ) from None
    if not -COORD_LIMIT <= v <= COORD_LIMIT:
        raise ValueError(f"{name} = {fmt_exact(v)} is out of range (|{name}| <= {COORD_LIMIT:.0e})")
    return v


def _scale_bits(c: int) -> int:
    """k with ``S = 2**k`` the smallest power of two ``>= 8c``: the fixed-point scale."""
    return (8 * c - 1).bit_length()


def _floor_affine(
    alpha: Number, beta: Number, n: int, *, offset: int = 0, sign: int = 1
) -> npt.NDArray[np.int64]:
    """``offset + sign * floor(alpha + beta * k)`` for ``k = 0 .. n-1``, exactly, as int64.

    With ``c`` the common denominator this is ``floor((a + b k) / c)`` for integers a, b
    (``-floor(N / c) = floor((c - 1 - N) / c)`` folds the sign in). Block by block, the
    integer part ``q`` of the block's first value is split off in Python integers, leaving
    ``floor((r + b j) / c)`` with ``0 <= r < c`` and ``j < BLOCK``:

    * in fixed point, with ``S = 2**k >= 8c``: ``floor(j b S / c)`` is computed once, and each
      block adds ``floor((4r + 1) S / 4c)`` (and ``q S`` when it fits, see
      :func:`_affine_path`) and shifts right by k. Without the floors the sum would be
      ``S (m + (f + 1/4) / c)`` for the wanted ``m = floor((r + b j) / c)`` and some
      ``0 <= f < c``; the two floors take off less than ``2 <= S / (4c)``, so the sum stays
      within ``[S m, S (m + 1))`` and the shift gives exactly m;
    * else in int64, ``r + (b mod c) j < c (BLOCK + 1)`` divided exactly;
    * denominators beyond even that use exact Python integers (slow, never wrong).

    >>> _floor_affine(Fraction(1, 2), Fraction(1, 2), 5).tolist()
    [0, 1, 1, 2, 2]
    >>> _floor_affine(Fraction(1, 2), Fraction(1, 2), 5, offset=10, sign=-1).tolist()
    [10, 9, 9, 8, 8]
    """
    alpha, beta = Fraction(alpha), Fraction(beta)
    c = math.lcm(alpha.denominator, beta.denominator)
    a = offset * c + sign * alpha.numerator * (c // alpha.denominator)
    a += c - 1 if sign < 0 else 0
    b = sign * beta.numerator * (c // beta.denominator)
    path = _affine_path(a, b, c, n)
    if path == "constant":
        return np.full(n, a // c, dtype=np.int64)
    if path == "arange":
        return np.arange(a, a + n * b, b, dtype=np.int64)
    if path == "object":
        ks = np.arange(n, dtype=np.int64).astype(object)
        return ((a + b * ks) // c).astype(np.int64)
    block = min(BLOCK, n)
    out = np.empty(n, dtype=np.int64)
    ramp = np.arange(block, dtype=np.int64)
    if path in ("fixed", "fixed+q"):
        k, fold = _scale_bits(c), path == "fixed"
        # floor(j b S / c) = j u + floor(j v / c), where 0 <= j v < c block < span / 8 fits
        u, v = divmod(b << k, c)
        step = ramp * u + ramp * v // c
        for k0 in range(0, n, block):
            m = min(block, n - k0)
            q, r = divmod(a + b * k0, c)
            o = out[k0 : k0 + m]
            np.add(step[:m], ((4 * r + 1) << k) // (4 * c) + (q << k if fold else 0), out=o)
            o >>= k
            if not fold:
                o += q
        return out
    b0, b1 = divmod(b, c)
    b1j, b0j = ramp * b1, ramp * b0
    itmp = np.empty_like(ramp)
    for k0 in range(0, n, block):
        m = min(block, n - k0)
        q, r = divmod(a + b * k0, c)  # numerator = c q + r + (c b0 + b1) j, 0 <= r < c
        o = out[k0 : k0 + m]
        np.add(b1j[:m], r, out=itmp[:m])
        np.floor_divide(itmp[:m], c, out=o)
        if b0:
            o += b0j[:m]
        o += q
    return out


def _affine_path(a: int, b: int, c: int, n: int) -> str:
    """Which method :func:`_floor_affine` uses for ``floor((a + b k) / c)``, ``k < n``:
    ``constant``, ``arange``, ``fixed`` (q folded in), ``fixed+q``, ``int64`` or ``object``.

    Fixed point, with ``S = 2**k >= 8c`` (:func:`_scale_bits`): a block's sums
    ``floor(j b S / c) + floor((4r + 1) S / 4c)`` stay below
    ``span = S (block (|b| // c + 1) + 2)`` in magnitude, which must fit in int64 (so
    ``c block < span / 8`` does too). Every block's integer part q has ``|q| <= q_bound``;
    ``fixed`` when ``q S`` fits in beside the sum as well, else ``fixed+q`` adds q after the
    shift.
    """
    if b == 0 or n <= 1:
        return "constant"
    if c == 1:
        return "arange"
    block = min(BLOCK, n)
    k = _scale_bits(c)
    span = (block * (abs(b) // c + 1) + 2) << k
    if span < _INT64_MAX:
        q_bound = max(abs(a), abs(a + b * (n - 1))) // c + 1
        return "fixed" if span + (q_bound << k) < _INT64_MAX else "fixed+q"
    return "int64" if c * (block + 1) < _INT64_MAX else "object"


def line(
    x1: int | Fraction,
    y1: int | Fraction,
    x2: int | Fraction,
    y2: int | Fraction,
    algo: str = "bresenham",
    *,
    parallel: bool = True,
) -> Coords:
    """Every pixel of a line, in the order ``line_solution(algo, ...).pixels()`` plots them.

    Parameters
    ----------
    x1, y1, x2, y2 : int or Fraction
        End points, ``|v| <= 10**9``. ``bresenham`` needs integers; ``dda`` and ``basic``
        also take fractions.
    algo : {"bresenham", "dda", "basic"}
        The algorithm whose pixels are wanted (see :mod:`scanconv.algorithms.lines`).
    parallel : bool
        For lines of at least :data:`PARALLEL_MIN` pixels, compute one coordinate array on a
        second thread while this one computes the other (numpy releases the GIL; each array
        is written once, so the two threads share no data). ``False`` stays on the calling
        thread. The result is the same either way.

    Returns
    -------
    xs, ys : (N,) ndarray of int64
        ``N = max(|Δx|, |Δy|) + 1`` for integer end points.

    Notes
    -----
    Closed forms of the generators, exact for every input:

    * ``bresenham``: walking from the end point with the smaller major coordinate (the
      generator swaps the same way), with ``Δ`` the major and ``δ`` the minor difference,
      ``p_k = 2δ(k + 1) - Δ(2 m_k + 1)`` where ``m_k`` is the number of minor steps taken
      before step ``k``. The minor axis steps when ``p_k >= 0``, that is when
      ``δ(k + 1) / Δ >= m_k + 1/2``, so by induction ``m_k = floor(δ k / Δ + 1/2)``: the
      ideal minor offset rounded half up, ties stepping, as the tie rule ``p_k = 0`` says.
    * ``dda``: ``round_half_up(x1 + k Δx / steps)`` for ``k = 0 .. steps``, and the same for y;
      a row that rounds to the pixel before it (fractional end points only) is dropped.
    * ``basic``: the major coordinate runs from ``round_half_up(P1)`` to
      ``round_half_up(P2)``; the minor is the line equation rounded half up.

    Examples
    --------
    >>> xs, ys = line(2, 2, 10, 6)
    >>> xs.tolist(), ys.tolist()
    ([2, 3, 4, 5, 6, 7, 8, 9, 10], [2, 3, 3, 4, 4, 5, 5, 6, 6])
    >>> xs, ys = line(2, 2, 5, 10, algo="dda")
    >>> list(zip(xs.tolist(), ys.tolist()))[:4]
    [(2, 2), (2, 3), (3, 4), (3, 5)]
    """
    p = [_exact(v, n) for v, n in ((x1, "x1"), (y1, "y1"), (x2, "x2"), (y2, "y2"))]
    dx, dy = (abs(Fraction(p[i + 2]) - Fraction(p[i])) for i in (0, 1))
    check_pixels(math.ceil(max(dx, dy)) + 2, "x2" if dx >= dy else "y2")
    if algo == "bresenham":
        ix1, iy1, ix2, iy2 = (
            as_int(v, n) for v, n in zip(p, ("x1", "y1", "x2", "y2"), strict=True)
        )
        sx, sy, _, _, steep, dmaj, dmin, s, _, _ = orient(ix1, iy1, ix2, iy2)
        smaj, smin = (sy, sx) if steep else (sx, sy)
        major, minor = _pair(
            parallel and dmaj + 1 >= PARALLEL_MIN,
            lambda: _floor_affine(smaj, 1, dmaj + 1),
            lambda: _floor_affine(
                Fraction(1, 2), Fraction(dmin, dmaj or 1), dmaj + 1, offset=smin, sign=s
            ),
        )
        return (minor, major) if steep else (major, minor)
    if algo == "dda":
        n = dda_steps(*p) + 1
        xi, yi = dda_increments(*p)
        half = Fraction(1, 2)
        xs, ys = _pair(
            parallel and n >= PARALLEL_MIN,
            lambda: _floor_affine(p[0] + half, xi, n),
            lambda: _floor_affine(p[1] + half, yi, n),
        )
        if all(isinstance(v, int) for v in p):  # the major coordinate moves 1 per row
            return xs, ys
        # fractional end points can round two rows to one pixel, listed once (lines._once)
        keep = np.ones(n, dtype=bool)
        keep[1:] = (xs[1:] != xs[:-1]) | (ys[1:] != ys[:-1])
        return (xs, ys) if keep.all() else (xs[keep], ys[keep])
    if algo == "basic":
        return _basic(*p)
    raise ValueError(f"unknown line algorithm {algo!r} (choose from {', '.join(LINE_ALGORITHMS)})")


def _pair(
    threaded: bool, first: Callable[[], Array], second: Callable[[], Array]
) -> tuple[Array, Array]:
    """``(first(), second())``; with ``threaded``, ``first`` runs on a second thread."""
    if not threaded:
        return first(), second()
    box: list[Array | BaseException] = []

    def run() -> None:
        try:
            box.append(first())
        except BaseException as exc:  # handed to the caller below
            box.append(exc)

    worker = threading.Thread(target=run, name="scanconv-raster", daemon=True)
    worker.start()
    try:
        other = second()
    finally:
        worker.join()
    (result,) = box
    if isinstance(result, BaseException):
        raise result
    return result, other


def _basic(x1: Number, y1: Number, x2: Number, y2: Number) -> Coords:
    """The direct method's pixels (see :func:`scanconv.algorithms.lines.basic`)."""
    dx, dy = Fraction(x2 - x1), Fraction(y2 - y1)
    steep = abs(dy) > abs(dx)
    a1, b1, a2, db, da = (y1, x1, y2, dx, dy) if steep else (x1, y1, x2, dy, dx)
    start, end = round_half_up(a1), round_half_up(a2)
    direction = 1 if end >= start else -1
    slope = db / da if da else Fraction(0)
    n = abs(end - start) + 1
    major = _floor_affine(start, direction, n)
    minor = _floor_affine(b1 + slope * (start - a1) + Fraction(1, 2), slope * direction, n)
    return (minor, major) if steep else (major, minor)


# --- circles and ellipses ---------------------------------------------------------------------

Array = npt.NDArray[np.int64]

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


def _odd_below(d: Array, p: int, q: int, *, strict: bool) -> Array:
    """How many odd ``t >= 1`` satisfy ``t < g`` (or ``t <= g``), ``g = 2p·sqrt(d)/q``, exactly.

    The midpoint decisions are all of this form: the circle's y at column x is the number of
    odd t with ``t < 2 sqrt(r² - x²)``. g is estimated in float64 (relative error below
    ``4·2**-53``); where ``(g + 1) / 2`` lies within ``10**-12 (g + 1)`` of an integer (a
    margin thousands of times that error) the count is decided again by comparing
    ``(q t)²`` with ``4 p² d`` in exact Python integers. Negative d counts as 0.

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
