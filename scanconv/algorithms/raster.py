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
* circles and ellipses are in :mod:`scanconv.algorithms.raster_conic`.

Examples
--------
>>> xs, ys = line(2, 2, 10, 6)
>>> xs.dtype, list(zip(xs.tolist(), ys.tolist()))[:4]
(dtype('int64'), [(2, 2), (3, 3), (4, 3), (5, 4)])
"""

from __future__ import annotations

import math
import operator
import threading
from collections.abc import Callable
from fractions import Fraction
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import numpy.typing as npt

from ..core.numeric import COORD_LIMIT, Number, as_int, fmt_exact, normalize, round_half_up
from .lines import dda_increments, dda_steps, orient
from .raster_fill import check_pixels
from .raster_fill import line_aa as line_aa  # the bulk Wu line and fill: scanconv.raster too
from .raster_fill import polygon as polygon

if TYPE_CHECKING:
    from ..core.choices import RasterLineName

Coords = tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]
"""``(xs, ys)``: two 1-D int64 arrays of equal length."""

Array = npt.NDArray[np.int64]

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
    algo: RasterLineName = "bresenham",
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
    variant = next((v for v in _LINES if v.algo == algo), None)
    if variant is None:
        raise ValueError(
            f"unknown line algorithm {algo!r} (choose from {', '.join(LINE_ALGORITHMS)})"
        )
    return variant.pixels(p, parallel)


def _bresenham(p: list[Number], parallel: bool) -> Coords:
    ix1, iy1, ix2, iy2 = (as_int(v, n) for v, n in zip(p, ("x1", "y1", "x2", "y2"), strict=True))
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


def _dda(p: list[Number], parallel: bool) -> Coords:
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


class _Line(NamedTuple):
    """A line algorithm's closed form: its name and its pixels from the exact end points."""

    algo: str
    pixels: Callable[[list[Number], bool], Coords]


_LINES = (
    _Line("bresenham", _bresenham),
    _Line("dda", _dda),
    _Line("basic", lambda p, parallel: _basic(*p)),
)
"""The closed form of each of :data:`LINE_ALGORITHMS`."""


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
