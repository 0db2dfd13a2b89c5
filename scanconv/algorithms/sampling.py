"""Sampling a curve's parameter and rasterizing the samples.

Every curve is tabulated at ``N + 1`` values of its parameter, ``t_k = t_0 + k (t_1 - t_0) / N``
(N equal steps, both ends included). When the range, the control points and the knots are
rational, ``t_k`` and every weight and coordinate are exact fractions. Transcendental values
(``cos t``) are floats.

Rasterizing: each sample point becomes a pixel by the one rounding rule, ``floor(v + 1/2)``
(:func:`~scanconv.core.numeric.round_half_up`); a float is first written to 9 decimals, so that
float noise (``5 sin(pi/6) = 2.4999999999999996``) cannot move a pixel. Successive sample pixels
are joined with Bresenham's line (:func:`scanconv.algorithms.lines.bresenham`), so the plotted
curve is 8-connected; a pixel reached twice is plotted once (:func:`curve_pixels`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Any

from ..core.checks import InputError
from ..core.numeric import COORD_LIMIT, fmt, normalize, round_half_up
from ..core.records import Pixel, Step
from .curve_limits import MAX_CURVE_PIXELS, Point, Value, norm_value
from .lines import bresenham

DENSE_POINTS = 2049
"""Most points of the dense float polyline drawn under a curve (:func:`dense_ts`)."""


def sample_ts(t0: Value, t1: Value, samples: int) -> Iterator[Value]:
    """The ``samples + 1`` values ``t_k = t0 + k (t1 - t0) / samples``, exact if t0 and t1 are.

    >>> [str(t) for t in sample_ts(0, 1, 4)]
    ['0', '1/4', '1/2', '3/4', '1']
    >>> list(sample_ts(0.0, 1, 2))
    [0.0, 0.5, 1.0]
    """
    if isinstance(t0, float) or isinstance(t1, float):
        a, b = float(t0), float(t1)
        for k in range(samples):
            yield a + (b - a) * k / samples
        yield b
        return
    step = Fraction(t1 - t0) / samples
    for k in range(samples + 1):
        yield normalize(t0 + k * step)


def coord(v: Value) -> int:
    """The pixel coordinate of ``v``: ``floor(v + 1/2)``; a float is taken to 9 decimals first.

    Raises ``InputError`` beyond :data:`~scanconv.core.numeric.COORD_LIMIT`.

    >>> coord(Fraction(5, 2)), coord(2.4999999999999996), coord(-2.5)
    (3, 3, -2)
    """
    if isinstance(v, float):
        if not abs(v) <= COORD_LIMIT:
            raise InputError(f"curve point coordinate {v:.6g} is out of range (|v| <= 1e+09)")
        return round_half_up(Fraction(f"{v:.9f}"))
    if abs(q := Fraction(v)) > COORD_LIMIT:
        shown = fmt(q) if abs(q) < 10**15 else f"{float(q):.6g}"
        raise InputError(f"curve point coordinate {shown} is out of range (|v| <= 1e+09)")
    return round_half_up(v)


def curve_pixel(x: Value, y: Value) -> Pixel:
    """The pixel of a curve point.

    >>> curve_pixel(Fraction(17, 8), 1.875)
    (2, 2)
    """
    return coord(x), coord(y)


def segment(a: Pixel, b: Pixel) -> Iterator[Pixel]:
    """Bresenham's pixels from ``a`` (excluded) to ``b`` (included), in that order.

    :func:`~scanconv.algorithms.lines.bresenham` walks toward increasing major coordinate; a
    segment going the other way is drawn as the point reflection of the walk from ``-a`` to
    ``-b``, so pixels stream in curve order without being buffered.

    >>> list(segment((0, 0), (3, 1))), list(segment((3, 1), (0, 0)))
    ([(1, 0), (2, 1), (3, 1)], [(2, 1), (1, 0), (0, 0)])
    """
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    forward = (dy if abs(dy) > abs(dx) else dx) > 0
    if forward:
        for s in bresenham(ax, ay, bx, by):
            yield s.pixel
    elif a != b:
        for s in bresenham(-ax, -ay, -bx, -by):
            yield -s.pixel[0], -s.pixel[1]


def curve_pixels(*runs: Iterable[Pixel]) -> Iterator[Pixel]:
    """Join the successive pixels of each run with Bresenham lines; every pixel once.

    Separate runs (two curve segments) are not joined to each other.

    >>> list(curve_pixels([(0, 0), (3, 1), (3, 1), (0, 0)]))
    [(0, 0), (1, 0), (2, 1), (3, 1)]
    """
    seen: set[Pixel] = set()
    for run in runs:
        prev: Pixel | None = None
        for p in run:
            for q in (p,) if prev is None else segment(prev, p):
                if q not in seen:
                    seen.add(q)
                    yield q
            prev = p


def combine(weights: Sequence[Any], points: Sequence[Point]) -> tuple[Any, Any]:
    """``sum w_i P_i`` for exact values or floats of weights.

    >>> combine((Fraction(1, 4), Fraction(3, 4)), [(0, 0), (4, 2)])
    (3, Fraction(3, 2))
    """
    x: Any = 0
    y: Any = 0
    for w, (px, py) in zip(weights, points, strict=True):
        x = x + w * px
        y = y + w * py
    return norm_value(x), norm_value(y)


def bbox(pixels: Iterable[Pixel]) -> tuple[int, int, int, int]:
    """``(xmin, ymin, xmax, ymax)`` of at least one pixel.

    >>> bbox([(3, 1), (0, 4)])
    (0, 1, 3, 4)
    """
    xs, ys = zip(*pixels, strict=True)
    return min(xs), min(ys), max(xs), max(ys)


def path_bbox(steps: Iterable[Step], marks: Iterable[Pixel]) -> tuple[int, int, int, int]:
    """The bounding box of the sample pixels and ``marks`` (evaluates every step once).

    Refuses the curve as soon as the Bresenham joins between successive sample pixels add up
    to more than :data:`~scanconv.algorithms.curve_limits.MAX_CURVE_PIXELS`.

    >>> path_bbox(iter([Step(0, None, None, (0, 0), ()), Step(1, None, None, (3, -2), ())]), [(5, 5)])
    (0, -2, 5, 5)
    """
    x0 = y0 = x1 = y1 = length = 0
    prev: Pixel | None = None
    for s in steps:
        x, y = s.pixel
        if prev is None:
            x0, y0, x1, y1 = x, y, x, y
        else:
            length += max(abs(x - prev[0]), abs(y - prev[1]))
            if length > MAX_CURVE_PIXELS:
                raise InputError(
                    f"the curve's pixel path is more than {MAX_CURVE_PIXELS:,} pixels long "
                    f"(reached at t_{s.k}); use a smaller curve or t range"
                )
            x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
        prev = (x, y)
    return bbox([(x0, y0), (x1, y1), *marks])


def linspace(start: float, stop: float, count: int) -> list[float]:
    """``count`` equally spaced floats from ``start`` to ``stop``, both included, as numpy's
    ``linspace`` computes them (``start + k * step``, the last one ``stop``), without numpy.

    >>> linspace(0.0, 1.0, 5)
    [0.0, 0.25, 0.5, 0.75, 1.0]
    """
    div = count - 1
    if div <= 0:
        return [start][:count]
    delta = stop - start
    step = delta / div
    if step == 0:  # numpy's rule for a denormal step
        out = [k / div * delta + start for k in range(count)]
    else:
        out = [k * step + start for k in range(count)]
    out[-1] = stop
    return out


def dense_ts(t0: Value, t1: Value, samples: int) -> list[float]:
    """Float values of t for the ideal curve under the pixels: 8 per sample step, between 129
    and :data:`DENSE_POINTS` of them.

    >>> len(dense_ts(0, 1, 4)), len(dense_ts(0, 1, 100)), len(dense_ts(0, 1, 10**5))
    (129, 801, 2049)
    """
    count = min(max(8 * samples + 1, 129), DENSE_POINTS)
    return linspace(float(t0), float(t1), count)


def polyline(xs: Iterable[Any], ys: Iterable[Any]) -> list[tuple[float, float]]:
    """Coordinate sequences as a list of float points.

    >>> polyline([0.0, 1.5], [2.0, 3.0])
    [(0.0, 2.0), (1.5, 3.0)]
    """
    return [(float(x), float(y)) for x, y in zip(xs, ys, strict=True)]


def dense_curve(
    weights: Callable[[float], Sequence[Any]], points: Sequence[Point], ts: Iterable[float]
) -> list[tuple[float, float]]:
    """The float points ``sum_i w_i(t) P_i`` of a curve at every ``t`` of ``ts`` (the ideal
    curve drawn under the pixels), from its weight functions.

    >>> dense_curve(lambda t: (1 - t, t), [(0, 0), (4, 2)], [0.0, 0.5, 1.0])
    [(0.0, 0.0), (2.0, 1.0), (4.0, 2.0)]
    """
    fpts = float_points(points)
    out = []
    for t in ts:
        x, y = combine(weights(t), fpts)
        out.append((float(x), float(y)))
    return out


def float_points(points: Iterable[Point]) -> list[tuple[float, float]]:
    """Exact points as floats (the control polygon drawn under a curve).

    >>> float_points([(0, Fraction(1, 2))])
    [(0.0, 0.5)]
    """
    return [(float(x), float(y)) for x, y in points]
