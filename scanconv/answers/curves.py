"""Curves: parametric functions, Bezier curves, B-splines and the continuity of a join.

Every curve is tabulated at ``N + 1`` values of its parameter, ``t_k = t_0 + k (t_1 - t_0) / N``
(``--samples N``: N equal steps, both ends included). When the range, the control points and
the knots are rational, ``t_k`` and every weight and coordinate are exact fractions; the tables
show them to 3 decimals. Transcendental values (``cos t``) are floats.

Rasterizing: each sample point becomes a pixel by the one rounding rule, ``floor(v + 1/2)``
(:func:`~scanconv.core.numeric.round_half_up`); a float is first written to 9 decimals, so that
float noise (``5 sin(pi/6) = 2.4999999999999996``) cannot move a pixel. Successive sample pixels
are joined with Bresenham's line (:func:`scanconv.algorithms.lines.bresenham`), so the plotted curve is
8-connected; a pixel reached twice is plotted once (:func:`curve_pixels`).

The algorithms are generators of :class:`~scanconv.core.records.Step` records with ``p`` and
``decision`` ``None`` and the algorithm's columns in ``extra``: :func:`parametric`,
:func:`bezier`, :func:`de_casteljau` and :func:`bspline`. The ``*_solution`` functions wrap them
with the working an exam answer writes (:class:`~scanconv.core.records.Solution`).
"""

from __future__ import annotations

import bisect
import itertools
import math
import operator
import re
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Any

import numpy as np

from ..algorithms.lines import bresenham
from ..core.expr import MAX_BITS, Expr, compile_expr
from ..core.numeric import (
    COORD_LIMIT,
    Number,
    check_between,
    fmt,
    fmt_short,
    fmt_value,
    normalize,
    paren,
    round_half_up,
)
from ..core.records import Column, Pixel, PixelFigure, Quantity, Solution, Step, Table

Value = Number | float
"""A coordinate or parameter value: exact where the input is rational, else a float."""

Point = tuple[Value, Value]
"""A point ``(x, y)``."""


def _norm(v: Any) -> Any:
    """Integral fractions become ``int``; floats (and numpy arrays) are left alone."""
    return normalize(v) if isinstance(v, (int, Fraction)) else v


PARAMETRIC = ("circle", "ellipse", "parabola", "line", "custom")
"""The parametric curves, by their command names."""

KNOTS = ("open", "uniform")
"""Named knot vectors (an explicit list is the third choice)."""

DEFAULT_SAMPLES = 16
"""Steps of t when ``--samples`` is not given (the parametric line uses max(|dx|, |dy|))."""

MAX_SAMPLES = 10**5
"""Most steps of t accepted. A parametric curve evaluates every sample before it prints
anything (to report a domain error or the bounding box first): 10**5 exact samples take a few
seconds."""

MAX_POINTS = 100
"""Most control points accepted (the tables have one column per point)."""

MAX_DEGREE = 10
"""Highest B-spline degree accepted. Every row evaluates Cox–de Boor exactly, at a cost that
grows with p (100 points at p = 10 already take about 20 ms a row); the notes use p <= 3."""

MAX_WEIGHTS = 10**5
"""Most exact weights in a Bezier or B-spline table: ``(samples + 1) × control points``.

Each weight is an exact fraction, and a row of a 100-point curve takes several milliseconds;
the limit keeps the slowest accepted table (one pass per output section) to about a minute."""

MAX_CURVE_PIXELS = 10**6
"""Longest accepted pixel path of a curve: the Bresenham joins between successive samples,
``max(|dx|, |dy|)`` summed. The plotted pixels are listed once each, so all of them are held
in memory (about 140 bytes a pixel: 140 MB at the limit)."""

_DENSE = 2049
"""Most points of the dense float polyline in ``geometry``."""


# --- sampling and rasterizing --------------------------------------------------------------


def check_samples(samples: int) -> int:
    """Return ``samples`` if ``1 <= samples <= MAX_SAMPLES``, else raise ``ValueError``.

    >>> check_samples(0)
    Traceback (most recent call last):
    ...
    ValueError: samples must be at least 1, got 0
    """
    return check_between(samples, "samples", 1, MAX_SAMPLES)


def check_weights(samples: int, points: int) -> None:
    """Refuse a table of more than :data:`MAX_WEIGHTS` exact weights, before any is computed.

    >>> check_weights(10**5, 4)
    Traceback (most recent call last):
    ...
    ValueError: (samples + 1) x control points = 100001 x 4 = 400,004 exact weights is too many (at most 100,000); use fewer --samples
    """
    cells = (samples + 1) * points
    if cells > MAX_WEIGHTS:
        raise ValueError(
            f"(samples + 1) x control points = {samples + 1} x {points} = {cells:,} exact "
            f"weights is too many (at most {MAX_WEIGHTS:,}); use fewer --samples"
        )


def check_path(polygons: Iterable[Sequence[Point]], samples: int) -> None:
    """Refuse curves whose pixel path could exceed :data:`MAX_CURVE_PIXELS`, before any work.

    A Bezier curve or B-spline is no longer than its control polygon (in any norm: the
    derivative is a convex combination of the polygon's edges, scaled), and rounding each
    sample adds at most one pixel per step, so the polygon's ``max(|dx|, |dy|)`` summed plus
    ``samples`` bounds the pixels joined, for each polygon.

    >>> check_path([[(0, 0), (10**6, 0)]], 16)
    Traceback (most recent call last):
    ...
    ValueError: the control polygon is 1,000,000 pixels long (max(|dx|, |dy|) summed) and 16 samples add up to 16 more: the curve could need 1,000,016 pixels, more than 1,000,000
    """
    for pts in polygons:
        edges = (
            max(abs(Fraction(q[0]) - Fraction(p[0])), abs(Fraction(q[1]) - Fraction(p[1])))
            for p, q in itertools.pairwise(pts)
        )
        length = math.ceil(sum(edges, Fraction(0)))
        if length + samples > MAX_CURVE_PIXELS:
            raise ValueError(
                f"the control polygon is {length:,} pixels long (max(|dx|, |dy|) summed) and "
                f"{samples} samples add up to {samples} more: the curve could need "
                f"{length + samples:,} pixels, more than {MAX_CURVE_PIXELS:,}"
            )


def check_exact(values: Iterable[Any], what: str) -> None:
    """Refuse exact values with more than :data:`~scanconv.core.expr.MAX_BITS` bits, too long to show.

    >>> check_exact([Fraction(1, 3**3000)], "B(t)")
    Traceback (most recent call last):
    ...
    ValueError: B(t): exact values would need more than 4096 bits (give fewer decimals, fewer control points or a lower degree)
    """
    for v in values:
        if isinstance(v, Fraction):
            _check_bits(max(v.numerator.bit_length(), v.denominator.bit_length()), what)


def _check_bits(bits: int, what: str) -> None:
    if bits > MAX_BITS:
        raise ValueError(
            f"{what}: exact values would need more than {MAX_BITS} bits (give fewer "
            "decimals, fewer control points or a lower degree)"
        )


def _check_row(steps: Iterator[Step], what: str) -> None:
    """Evaluate the row at ``k = 1`` (``t = 1/N`` carries the largest denominators) and refuse
    it if its exact values are too long (:func:`check_exact`)."""
    row = next(itertools.islice(steps, 1, None), None)
    if row is not None:
        check_exact(row.extra, what)


def sample_ts(t0: Value, t1: Value, samples: int) -> Iterator[Value]:
    """The ``samples + 1`` values ``t_k = t0 + k (t1 - t0) / samples``, exact if t0 and t1 are.

    >>> [fmt_short(t) for t in sample_ts(0, 1, 4)]
    ['0', '0.25', '0.5', '0.75', '1']
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

    Raises ``ValueError`` beyond :data:`~scanconv.core.numeric.COORD_LIMIT`.

    >>> coord(Fraction(5, 2)), coord(5 * math.sin(math.pi / 6)), coord(-2.5)
    (3, 3, -2)
    """
    if isinstance(v, float):
        if not abs(v) <= COORD_LIMIT:
            raise ValueError(f"curve point coordinate {v:.6g} is out of range (|v| <= 1e+09)")
        return round_half_up(Fraction(f"{v:.9f}"))
    if abs(q := Fraction(v)) > COORD_LIMIT:
        shown = fmt(q) if abs(q) < 10**15 else f"{float(q):.6g}"
        raise ValueError(f"curve point coordinate {shown} is out of range (|v| <= 1e+09)")
    return round_half_up(v)


def curve_pixel(x: Value, y: Value) -> Pixel:
    """The pixel of a curve point.

    >>> curve_pixel(Fraction(17, 8), 1.875)
    (2, 2)
    """
    return coord(x), coord(y)


def _segment(a: Pixel, b: Pixel) -> Iterator[Pixel]:
    """Bresenham's pixels from ``a`` (excluded) to ``b`` (included), in that order.

    :func:`~scanconv.algorithms.lines.bresenham` walks toward increasing major coordinate; a segment going
    the other way is drawn as the point reflection of the walk from ``-a`` to ``-b``, so pixels
    stream in curve order without being buffered.

    >>> list(_segment((0, 0), (3, 1))), list(_segment((3, 1), (0, 0)))
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
            for q in (p,) if prev is None else _segment(prev, p):
                if q not in seen:
                    seen.add(q)
                    yield q
            prev = p


def _bbox(pixels: Iterable[Pixel]) -> tuple[int, int, int, int]:
    xs, ys = zip(*pixels, strict=True)
    return min(xs), min(ys), max(xs), max(ys)


def _dense_ts(t0: Value, t1: Value, samples: int) -> np.ndarray:
    count = min(max(8 * samples + 1, 129), _DENSE)
    return np.linspace(float(t0), float(t1), count)


def _polyline(xs: np.ndarray, ys: np.ndarray) -> list[tuple[float, float]]:
    return [(float(x), float(y)) for x, y in zip(xs, ys, strict=True)]


# --- display helpers ---------------------------------------------------------------------------


def _v(v: Value) -> str:
    """A value in the working: exact values briefly (``1.5``, ``1/3``), floats to 3 decimals."""
    return fmt(v) if isinstance(v, float) else fmt_short(v)


def _pt(p: Point) -> str:
    return f"({_v(p[0])}, {_v(p[1])})"


def _paren(v: Value) -> str:
    return paren(_v(v))


def _exact_point(p: Point) -> Point:
    return normalize(Fraction(p[0])), normalize(Fraction(p[1]))


def check_points(points: Sequence[Point], least: int, what: str) -> tuple[Point, ...]:
    """Validate a control polygon: at least ``least`` and at most :data:`MAX_POINTS` points.

    >>> check_points([(0, 0)], 2, "a Bezier curve")
    Traceback (most recent call last):
    ...
    ValueError: a Bezier curve needs at least 2 control points, got 1
    """
    if len(points) < least:
        raise ValueError(f"{what} needs at least {least} control points, got {len(points)}")
    if len(points) > MAX_POINTS:
        raise ValueError(f"{what} takes at most {MAX_POINTS} control points, got {len(points)}")
    return tuple(_exact_point(p) for p in points)


def pairs(coords: Sequence[Number]) -> list[Point]:
    """Group ``x0 y0 x1 y1 ...`` into points; an odd count is an error.

    >>> pairs([0, 0, 1, 2])
    [(0, 0), (1, 2)]
    >>> pairs([0, 0, 1])
    Traceback (most recent call last):
    ...
    ValueError: control points are x y pairs: got 3 numbers, an odd count
    """
    if len(coords) % 2:
        raise ValueError(f"control points are x y pairs: got {len(coords)} numbers, an odd count")
    return [(normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, len(coords), 2)]


def _combine(weights: Sequence[Any], points: Sequence[Point]) -> tuple[Any, Any]:
    """``sum w_i P_i`` for exact values, floats or numpy arrays of weights."""
    x: Any = 0
    y: Any = 0
    for w, (px, py) in zip(weights, points, strict=True):
        x = x + w * px
        y = y + w * py
    return _norm(x), _norm(y)


def _given_points(points: Sequence[Point], name: str = "P", tex: str = "P") -> list[Quantity]:
    return [
        Quantity(f"{name}{i}", p, f"{name}{i} = {_pt(p)}", f"{tex}_{{{i}}} = {_pt(p)}")
        for i, p in enumerate(points)
    ]


def _step_quantity(t0: Value, t1: Value, samples: int, lo: str, hi: str, tex_lo: str, tex_hi: str):
    """``Δt = (t1 - t0) / N``, with the range as the answer names it."""
    if isinstance(t0, float) or isinstance(t1, float):
        dt: Value = (float(t1) - float(t0)) / samples
        shown = f"≈ {fmt(dt)}"
        tex_shown = f"\\approx {fmt(dt)}"
    else:
        dt = normalize(Fraction(t1 - t0) / samples)
        shown = "= " + fmt_value(dt)
        tex_shown = "= " + fmt_value(dt).replace("≈", "\\approx")
    return Quantity(
        "dt",
        dt,
        f"{lo} ≤ t ≤ {hi}; Δt = ({hi} - {paren(lo)}) / {samples} {shown}"
        f"   ({samples} steps, {samples + 1} values of t)",
        f"{tex_lo} \\le t \\le {tex_hi}; \\quad \\Delta t = \\frac{{{tex_hi} - "
        f"{paren(tex_lo)}}}{{{samples}}} {tex_shown}",
    )


_JOIN_NOTE = (
    "Successive sample pixels are joined with Bresenham's line, walked in the curve's direction "
    "(a tie steps the minor axis, as in scanconv line), so the plotted curve is 8-connected; a "
    "pixel reached twice is plotted once."
)
_ROUND_NOTE = "Pixels are round half up, floor(v + 1/2), of each coordinate."
_FLOAT_ROUND_NOTE = (
    "Pixels are round half up, floor(v + 1/2), of each coordinate (a float is taken to 9 "
    "decimals first, so float noise cannot move a pixel)."
)


def _marks(points: Iterable[Point]) -> tuple[Pixel, ...]:
    """The control points as grid marks."""
    return tuple(curve_pixel(*p) for p in points)


_KT = (Column("k", "k", "k"), Column("t", "t", "t", 3))
"""The first two columns of the Bezier and B-spline tables."""


def _xy_columns() -> tuple[Column, ...]:
    return (
        Column("x_t", "x(t)", "x(t)", 3),
        Column("y_t", "y(t)", "y(t)", 3),
        Column("pixel", "pixel (x, y)", r"\text{pixel } (x, y)"),
    )


# --- parametric curves -------------------------------------------------------------------------


_CHUNK = 4096
"""Samples evaluated together (one numpy call) by :func:`parametric`."""


def _evaluate(f: Expr, ts: list[Value], floats: np.ndarray) -> list[Value]:
    """``f`` at every ``t`` of a chunk: exactly where ``f`` is rational and ``t`` exact, else in
    float64 with one numpy call for the whole chunk."""
    if f.rational and not isinstance(ts[0], float):
        return [_norm(f.exact(t=Fraction(t))) for t in ts]
    return [float(v) for v in f(t=floats)]


def parametric(
    x: Expr | str, y: Expr | str, t0: Value, t1: Value, samples: int = DEFAULT_SAMPLES
) -> Iterator[Step]:
    """Tabulate the parametric curve ``(x(t), y(t))`` for ``t0 <= t <= t1``.

    ``x`` and ``y`` are formulas in ``t`` (see :mod:`scanconv.core.expr`). Yields ``samples + 1``
    steps with ``extra = (t, x(t), y(t))`` and the rounded point as ``pixel``.

    Notes
    -----
    ``t_k = t0 + k (t1 - t0) / samples``; rational formulas at rational ``t`` are evaluated
    exactly, anything else in float64. Pixels are ``floor(v + 1/2)`` of each coordinate.

    Examples
    --------
    The notes' parabola x = t, y = t^2:

    >>> for s in parametric("t", "t**2", -1, 1, 4):
    ...     print(s.k, *(fmt(v) for v in s.extra), s.pixel)
    0 -1 -1 1 (-1, 1)
    1 -0.500 -0.500 0.250 (0, 0)
    2 0 0 0 (0, 0)
    3 0.500 0.500 0.250 (1, 0)
    4 1 1 1 (1, 1)
    """
    fx = x if isinstance(x, Expr) else compile_expr(x, ("t",))
    fy = y if isinstance(y, Expr) else compile_expr(y, ("t",))
    # parametric("5*cos(t)", "5*sin(t)", 0, 2*pi, 4) -> t: 0 1.571 3.142 4.712 6.283 ;
    #   pixels (5, 0) (0, 5) (-5, 0) (0, -5) (5, 0)
    ts = sample_ts(t0, t1, check_samples(samples))
    k = 0
    while chunk := list(itertools.islice(ts, _CHUNK)):  # bounded: _CHUNK values of t at a time
        floats = np.array([float(t) for t in chunk])
        for t, px, py in zip(
            chunk, _evaluate(fx, chunk, floats), _evaluate(fy, chunk, floats), strict=True
        ):
            yield Step(k, None, None, curve_pixel(px, py), (t, px, py))
            k += 1


def _affine(a: Value, c: Value, var: str) -> str:
    """``a + c·var`` as the working writes it: ``0 + 5 cos t``, ``2 - t²``, ``0 + 10t``.

    >>> _affine(0, 5, "cos t"), _affine(2, -1, "t²"), _affine(0, Fraction(1, 2), "t")
    ('0 + 5 cos t', '2 - t²', '0 + 0.5t')
    """
    mag: Value = -c if c < 0 else c
    coef = "" if mag == 1 else _v(mag) + ("" if var.startswith("t") else " ")
    return f"{_v(a)} {'-' if c < 0 else '+'} {coef}{var}"


def _lit(v: Value) -> str:
    """A number as an expression literal: ``(-1/3)``."""
    s = str(normalize(Fraction(v)))
    return s if s.isdigit() else f"({s})"


def _tex_expr(text: str) -> str:
    """A formula typed by the user, as LaTeX math."""
    s = " ".join(text.split()).replace("**", "^").replace("*", r" \cdot ")
    s = re.sub(r"\b(sin|cos|tan|exp|log)\b", r"\\\1", s)
    return re.sub(r"\bpi\b", r"\\pi", s)


class _Range:
    """A parameter bound: its value (exact or float) and how the working shows it."""

    def __init__(self, value: Value, text: str | None = None, tex: str | None = None) -> None:
        self.value = value
        self.text = text if text is not None else _v(value)
        self.tex = tex if tex is not None else self.text


TWO_PI = _Range(2 * math.pi, "2π", r"2\pi")


def parametric_solution(
    kind: str,
    *,
    points: Sequence[Number] = (),
    center: Point = (0, 0),
    radius: Number = 1,
    a: Number = 1,
    b: Number = 1,
    vertex: Point = (0, 0),
    x: str = "",
    y: str = "",
    t_range: tuple[Value | str, Value | str] | None = None,
    samples: int | None = None,
) -> Solution:
    """The worked solution of one of the parametric curves of :data:`PARAMETRIC`.

    ``points`` are ``x0 y0 x1 y1`` for ``line``; ``center`` and ``radius`` for ``circle``;
    ``center``, ``a`` and ``b`` for ``ellipse``; ``vertex`` and ``a`` for ``parabola``
    (``x = h + t``, ``y = k + a t^2``); the formulas ``x`` and ``y`` for ``custom``. A bound of
    ``t_range`` may be a formula (``"2*pi"``).

    >>> sol = parametric_solution("circle", radius=5, samples=4)
    >>> [q.text for q in sol.derived[:2]]
    ['x(t) = xc + r cos t = 0 + 5 cos t', 'y(t) = yc + r sin t = 0 + 5 sin t']
    >>> list(sol.pixels())[:3]
    [(5, 0), (4, 1), (3, 2)]
    """
    if kind == "line":
        if len(points) != 4:
            raise ValueError("parametric line needs x0 y0 x1 y1")
        x0, y0, x1, y1 = (normalize(v) for v in points)
        dx, dy = normalize(x1 - x0), normalize(y1 - y0)
        spec = _Spec(
            f"{_lit(x0)} + t*{_lit(dx)}",
            f"{_lit(y0)} + t*{_lit(dy)}",
            ("x(t) = x0 + t(x1 - x0)", "x(t) = x_0 + t(x_1 - x_0)", _affine(x0, dx, "t")),
            ("y(t) = y0 + t(y1 - y0)", "y(t) = y_0 + t(y_1 - y_0)", _affine(y0, dy, "t")),
            (_Range(0), _Range(1)),
            [
                Quantity("P0", (x0, y0), f"P0 = {_pt((x0, y0))}", f"P_0 = {_pt((x0, y0))}"),
                Quantity("P1", (x1, y1), f"P1 = {_pt((x1, y1))}", f"P_1 = {_pt((x1, y1))}"),
            ],
            max(1, math.ceil(max(abs(Fraction(dx)), abs(Fraction(dy))))),
            f"Parametric line: {_pt((x0, y0))} to {_pt((x1, y1))}",
        )
    elif kind in ("circle", "ellipse"):
        xc, yc = _exact_point(center)
        if kind == "circle":
            ra = rb = normalize(radius)
            if ra <= 0:
                raise ValueError(f"radius must be positive, got {fmt_short(ra)}")
            names, given = ("r", "r"), [Quantity("r", ra, f"r = {_v(ra)}", f"r = {_v(ra)}")]
            title = f"Parametric circle: centre {_pt((xc, yc))}, r = {_v(ra)}"
        else:
            ra, rb = normalize(a), normalize(b)
            if ra <= 0 or rb <= 0:
                raise ValueError(f"a and b must be positive, got a = {_v(ra)}, b = {_v(rb)}")
            names = ("a", "b")
            given = [
                Quantity("a", ra, f"a = {_v(ra)}", f"a = {_v(ra)}"),
                Quantity("b", rb, f"b = {_v(rb)}", f"b = {_v(rb)}"),
            ]
            title = f"Parametric ellipse: centre {_pt((xc, yc))}, a = {_v(ra)}, b = {_v(rb)}"
        spec = _Spec(
            f"{_lit(xc)} + {_lit(ra)}*cos(t)",
            f"{_lit(yc)} + {_lit(rb)}*sin(t)",
            (
                f"x(t) = xc + {names[0]} cos t",
                f"x(t) = x_c + {names[0]} \\cos t",
                _affine(xc, ra, "cos t"),
            ),
            (
                f"y(t) = yc + {names[1]} sin t",
                f"y(t) = y_c + {names[1]} \\sin t",
                _affine(yc, rb, "sin t"),
            ),
            (_Range(0), TWO_PI),
            [
                Quantity(
                    "center", (xc, yc), f"centre {_pt((xc, yc))}", f"(x_c, y_c) = {_pt((xc, yc))}"
                ),
                *given,
            ],
            DEFAULT_SAMPLES,
            title,
            marks=((xc, yc),),
        )
    elif kind == "parabola":
        h, kk = _exact_point(vertex)
        av = normalize(a)
        if av == 0:
            raise ValueError("a must not be 0 (y = k + a t^2 would be a line)")
        spec = _Spec(
            f"{_lit(h)} + t",
            f"{_lit(kk)} + {_lit(av)}*t**2",
            ("x(t) = h + t", "x(t) = h + t", f"{_v(h)} + t"),
            ("y(t) = k + a t²", "y(t) = k + a t^2", _affine(kk, av, "t²")),
            (_Range(-3), _Range(3)),
            [
                Quantity(
                    "vertex", (h, kk), f"vertex (h, k) = {_pt((h, kk))}", f"(h, k) = {_pt((h, kk))}"
                ),
                Quantity("a", av, f"a = {_v(av)}", f"a = {_v(av)}"),
            ],
            DEFAULT_SAMPLES,
            f"Parametric parabola: vertex {_pt((h, kk))}, a = {_v(av)}",
        )
    elif kind == "custom":
        if not x.strip() or not y.strip():
            empty = "--x" if not x.strip() else "--y"
            raise ValueError(
                f"custom curve needs both --x and --y formulas in t ({empty} is empty)"
            )
        compile_expr(x, ("t",))
        compile_expr(y, ("t",))
        spec = _Spec(
            x,
            y,
            ("x(t)", "x(t)", " ".join(x.split())),
            ("y(t)", "y(t)", " ".join(y.split())),
            (_Range(0), _Range(1)),
            [],
            DEFAULT_SAMPLES,
            "Parametric curve: x(t) = {}, y(t) = {}".format(
                " ".join(x.split()), " ".join(y.split())
            ),
            tex_formulas=True,
        )
    else:
        raise ValueError(f"unknown parametric curve {kind!r} (choose from {', '.join(PARAMETRIC)})")
    lo, hi = spec.t_range if t_range is None else (_bound(t_range[0]), _bound(t_range[1]))
    if not (isinstance(lo.value, float) or isinstance(hi.value, float)) and lo.value > hi.value:
        raise ValueError(f"t range must run upward: {lo.text} > {hi.text}")
    if float(lo.value) > float(hi.value):
        raise ValueError(f"t range must run upward: {lo.text} > {hi.text}")
    return _parametric_solution(kind, spec, lo, hi, spec.samples if samples is None else samples)


def _bound(v: Value | str) -> _Range:
    """A ``--t-range`` bound: a number, or a formula such as ``2*pi`` (exact if rational)."""
    if not isinstance(v, str):
        return _Range(_norm(v))
    from ..core.expr import parse_exact

    value = parse_exact(v)
    if isinstance(value, Fraction):
        return _Range(normalize(value))
    text = " ".join(v.split())
    return _Range(value, text, _tex_expr(text))


class _Spec:
    """What distinguishes one parametric curve: formulas, their working and defaults."""

    def __init__(
        self,
        x: str,
        y: str,
        x_work: tuple[str, str, str],
        y_work: tuple[str, str, str],
        t_range: tuple[_Range, _Range],
        given: list[Quantity],
        samples: int,
        title: str,
        *,
        marks: tuple[Point, ...] = (),
        tex_formulas: bool = False,
    ) -> None:
        self.x, self.y = compile_expr(x, ("t",)), compile_expr(y, ("t",))
        self.x_work, self.y_work = x_work, y_work
        self.t_range = t_range
        self.given = given
        self.samples = samples
        self.title = title
        self.marks = marks
        self.tex_formulas = tex_formulas


def _formula(key: str, work: tuple[str, str, str], tex_formulas: bool) -> Quantity:
    general, tex_general, substituted = work
    tex_sub = _tex_expr(substituted) if tex_formulas else substituted.replace("²", "^2")
    tex_sub = re.sub(r"\b(cos|sin) t\b", r"\\\1 t", tex_sub)
    if general == key:
        return Quantity(
            key, substituted, f"{general} = {substituted}", f"{tex_general} = {tex_sub}"
        )
    return Quantity(
        key,
        substituted,
        f"{general} = {substituted}",
        f"{tex_general} = {tex_sub}",
    )


def _parametric_solution(kind: str, spec: _Spec, lo: _Range, hi: _Range, samples: int) -> Solution:
    check_samples(samples)
    fx, fy = spec.x, spec.y
    t0, t1 = lo.value, hi.value
    marks = tuple(curve_pixel(*m) for m in spec.marks)

    def steps() -> Iterator[Step]:
        return parametric(fx, fy, t0, t1, samples)

    def pixels() -> Iterator[Pixel]:
        return curve_pixels(s.pixel for s in steps())

    # One pass evaluates every sample: a domain error, an out-of-range point or a pixel path
    # that is too long is reported here, before any output, and gives the bounding box.
    bbox = _extent(steps(), marks)
    try:
        ts = _dense_ts(t0, t1, samples)
        polyline = _polyline(fx(t=ts), fy(t=ts))
    except ValueError:  # a singularity between the samples: draw the samples only
        polyline = [(float(s.extra[1]), float(s.extra[2])) for s in steps()]
    derived = [
        _formula("x(t)", spec.x_work, spec.tex_formulas),
        _formula("y(t)", spec.y_work, spec.tex_formulas),
        _step_quantity(t0, t1, samples, lo.text, hi.text, lo.tex, hi.tex),
    ]
    exact = not (isinstance(t0, float) or isinstance(t1, float)) and fx.rational and fy.rational
    notes = [
        "x(t) and y(t) are computed exactly (fractions) at each t_k."
        if exact
        else "x(t) and y(t) are computed in floating point and shown to 3 decimals.",
        _ROUND_NOTE if exact else _FLOAT_ROUND_NOTE,
        _JOIN_NOTE,
    ]
    if marks:
        notes.append("The centre is marked o in the grid.")
    return Solution(
        primitive="parametric",
        algorithm=kind,
        title=spec.title,
        given=tuple(spec.given),
        derived=tuple(derived),
        columns=(
            Column("k", "k", "k"),
            Column("t", "t_k", "t_k", 3),
            *_xy_columns(),
        ),
        extra_keys=("t", "x_t", "y_t"),
        steps=steps,
        pixels=pixels,
        bbox=bbox,
        notes=tuple(notes),
        marks=marks,
        geometry={"polyline": polyline},
        data={"x_formula": fx.text, "y_formula": fy.text},
    )


def _extent(steps: Iterable[Step], marks: Iterable[Pixel]) -> tuple[int, int, int, int]:
    """The bounding box of the sample pixels and ``marks`` (evaluates every step once).

    Refuses the curve as soon as the Bresenham joins between successive sample pixels add up
    to more than :data:`MAX_CURVE_PIXELS`.

    >>> _extent(iter([Step(0, None, None, (0, 0), ()), Step(1, None, None, (3, -2), ())]), [(5, 5)])
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
                raise ValueError(
                    f"the curve's pixel path is more than {MAX_CURVE_PIXELS:,} pixels long "
                    f"(reached at t_{s.k}); use a smaller curve or t range"
                )
            x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
        prev = (x, y)
    return _bbox([(x0, y0), (x1, y1), *marks])


# --- Bezier curves -----------------------------------------------------------------------------


def bernstein(n: int, t: Any, s: Any = None) -> tuple[Any, ...]:
    """The Bernstein weights ``B_{i,n}(t) = C(n, i) t^i (1 - t)^(n - i)``, ``i = 0 .. n``.

    Exact for exact ``t``; works elementwise on numpy arrays too. With ``s`` given it stands for
    ``1 - t``: ``bernstein(n, k, N - k)`` gives the integer numerators of the weights at
    ``t = k / N`` (their common denominator is ``N^n``).

    >>> [fmt_short(w) for w in bernstein(3, Fraction(1, 2))]
    ['0.125', '0.375', '0.375', '0.125']
    >>> bernstein(3, 1, 1)
    (1, 3, 3, 1)
    """
    if s is None:
        s = 1 - t
    return tuple(math.comb(n, i) * t**i * s ** (n - i) for i in range(n + 1))


def bezier(points: Sequence[Point], samples: int = DEFAULT_SAMPLES) -> Iterator[Step]:
    """Tabulate the Bezier curve of ``points`` at ``t = k / samples``, ``k = 0 .. samples``.

    ``Step.extra`` is ``(t, B_{0,n}(t), ..., B_{n,n}(t), x(t), y(t))``, exact for rational
    control points.

    Notes
    -----
    ``B(t) = sum_i B_{i,n}(t) P_i`` with the Bernstein weights of :func:`bernstein`, degree
    ``n = len(points) - 1``; each row is computed directly (no accumulated error). Pixels are
    ``floor(v + 1/2)`` of each coordinate.

    Examples
    --------
    >>> for s in bezier([(0, 0), (1, 2), (3, 3), (4, 0)], 2):
    ...     print(s.k, *(fmt(v) for v in s.extra), s.pixel)
    0 0 1 0 0 0 0 0 (0, 0)
    1 0.500 0.125 0.375 0.375 0.125 2 1.875 (2, 2)
    2 1 0 0 0 1 4 0 (4, 0)
    """
    pts = check_points(points, 2, "a Bezier curve")
    n = len(pts) - 1
    big_n = check_samples(samples)
    # Integer arithmetic: at t = k/N the weights are c_i / N^n with integer c_i, and with the
    # points scaled to integers by their common denominator L, x(t) = sum c_i X_i / (N^n L).
    den = big_n**n
    scale = math.lcm(*(Fraction(c).denominator for p in pts for c in p))
    xs = [int(p[0] * scale) for p in pts]
    ys = [int(p[1] * scale) for p in pts]
    # bezier([(0,0), (1,2), (3,3), (4,0)], 8) -> t = 1/2: B = 1/8 3/8 3/8 1/8 ; point (2, 1.875)
    for k in range(big_n + 1):
        c = bernstein(n, k, big_n - k)
        w = tuple(normalize(Fraction(ci, den)) for ci in c)
        x = normalize(Fraction(sum(map(operator.mul, c, xs)), den * scale))
        y = normalize(Fraction(sum(map(operator.mul, c, ys)), den * scale))
        yield Step(k, None, None, curve_pixel(x, y), (normalize(Fraction(k, big_n)), *w, x, y))


def _lerp(p: Point, q: Point, t: Value) -> Point:
    return _norm(p[0] + t * (q[0] - p[0])), _norm(p[1] + t * (q[1] - p[1]))


def de_casteljau(points: Sequence[Point], t: Value) -> Iterator[Step]:
    """De Casteljau's construction of the Bezier point at ``t``: one step per level.

    Step ``r`` holds the points ``P_i^(r)``, ``i = 0 .. n - r``, in ``extra`` (padded with
    ``None`` to ``n + 1`` entries); the last step holds the curve point alone. ``pixel`` is the
    rounded ``P_0^(r)`` (the control points of the left half of the subdivided curve).

    Notes
    -----
    ``P_i^(0) = P_i`` and ``P_i^(r) = (1 - t) P_i^(r-1) + t P_{i+1}^(r-1)``; exact for rational
    ``t`` and points. The final point equals the Bernstein form ``B(t)``.

    Examples
    --------
    >>> for s in de_casteljau([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2)):
    ...     print(s.k, *(fmt_short(v) if v is None else f"({fmt(v[0])}, {fmt(v[1])})"
    ...                  for v in s.extra if v is not None))
    0 (0, 0) (1, 2) (3, 3) (4, 0)
    1 (0.500, 1) (2, 2.500) (3.500, 1.500)
    2 (1.250, 1.750) (2.750, 2)
    3 (2, 1.875)
    """
    level = check_points(points, 2, "a Bezier curve")
    n = len(level) - 1
    # de_casteljau([(0,0), (1,2), (3,3), (4,0)], 1/2) -> r=1: (0.5,1) (2,2.5) (3.5,1.5) ;
    #   r=2: (1.25,1.75) (2.75,2) ; r=3: (2, 1.875)
    for r in range(n + 1):
        yield Step(r, None, None, curve_pixel(*level[0]), (*level, *(None,) * r))
        level = tuple(_lerp(p, q, t) for p, q in itertools.pairwise(level))


def _power(base: str, k: int) -> str:
    return (
        ""
        if k == 0
        else base
        if k == 1
        else f"{base}²"
        if k == 2
        else f"{base}³"
        if k == 3
        else f"{base}^{k}"
    )


def _bernstein_text(i: int, n: int) -> tuple[str, str]:
    """``3t(1 - t)²`` and its LaTeX."""
    c = math.comb(n, i)
    text = ("" if c == 1 else str(c)) + _power("t", i) + _power("(1 - t)", n - i)
    tex = (
        ("" if c == 1 else str(c))
        + ("" if i == 0 else "t" if i == 1 else f"t^{{{i}}}")
        + ("" if n == i else "(1 - t)" if n - i == 1 else f"(1 - t)^{{{n - i}}}")
    )
    return text or "1", tex or "1"


def _bezier_derived(pts: Sequence[Point]) -> list[Quantity]:
    n = len(pts) - 1
    out = [
        Quantity(
            "n",
            n,
            f"n = number of control points - 1 = {n + 1} - 1 = {n}",
            f"n = {n + 1} - 1 = {n}",
        )
    ]
    for i in range(n + 1):
        text, tex = _bernstein_text(i, n)
        out.append(
            Quantity(
                f"B{i}",
                text,
                f"B_{{{i},{n}}}(t) = C({n},{i}) t^{i} (1 - t)^{n - i} = {text}",
                f"B_{{{i},{n}}}(t) = \\binom{{{n}}}{{{i}}} t^{{{i}}} (1-t)^{{{n - i}}} = {tex}",
            )
        )
    terms = [_bernstein_text(i, n) for i in range(n + 1)]
    out.append(
        Quantity(
            "B(t)",
            None,
            "B(t) = " + " + ".join(f"{t}·{_pt(p)}" for (t, _), p in zip(terms, pts, strict=True)),
            "B(t) = "
            + " + ".join(f"{tex} \\cdot {_pt(p)}" for (_, tex), p in zip(terms, pts, strict=True)),
        )
    )
    return out


def _control_geometry(pts: Sequence[Point]) -> list[tuple[float, float]]:
    return [(float(x), float(y)) for x, y in pts]


def bezier_solution(points: Sequence[Point], samples: int = DEFAULT_SAMPLES) -> Solution:
    """The worked solution of a Bezier curve sampled at ``t = k / samples``.

    >>> sol = bezier_solution([(0, 0), (1, 2), (3, 3), (4, 0)], 8)
    >>> sol.derived[2].text
    'B_{1,3}(t) = C(3,1) t^1 (1 - t)^2 = 3t(1 - t)²'
    >>> list(sol.pixels())
    [(0, 0), (0, 1), (1, 1), (1, 2), (2, 2), (3, 2), (4, 1), (4, 0)]
    """
    pts = check_points(points, 2, "a Bezier curve")
    check_samples(samples)
    check_weights(samples, len(pts))
    check_path([pts], samples)
    n = len(pts) - 1
    marks = _marks(pts)

    def steps() -> Iterator[Step]:
        return bezier(pts, samples)

    _check_row(steps(), "Bezier curve")

    ts = _dense_ts(0, 1, samples)
    dense = _combine(bernstein(n, ts), _control_geometry(pts))
    derived = [
        *_bezier_derived(pts),
        _step_quantity(0, 1, samples, "0", "1", "0", "1"),
    ]
    return Solution(
        primitive="curve",
        algorithm="bezier",
        title=f"Bezier curve of degree {n}: {n + 1} control points, {samples} steps of t",
        given=tuple(_given_points(pts)),
        derived=tuple(derived),
        columns=(
            *_KT,
            *(Column(f"B{i}", f"B_{{{i},{n}}}", f"B_{{{i},{n}}}", 3) for i in range(n + 1)),
            *_xy_columns(),
        ),
        extra_keys=("t", *(f"B{i}" for i in range(n + 1)), "x_t", "y_t"),
        steps=steps,
        pixels=lambda: curve_pixels(s.pixel for s in steps()),
        # The curve lies in the convex hull of its control points, so their box contains it.
        bbox=_bbox(marks),
        notes=(
            "Weights and points are exact fractions (3 decimals shown); the weights of each "
            "row sum to 1.",
            _ROUND_NOTE,
            _JOIN_NOTE,
            "The curve starts at P0, ends at Pn and lies in the convex hull of the control "
            "points (marked o in the grid).",
        ),
        marks=marks,
        geometry={"polyline": _polyline(*dense), "control": _control_geometry(pts)},
    )


def check_unit_t(t: Value) -> Value:
    """``t`` if ``0 <= t <= 1``, else ``ValueError``.

    >>> check_unit_t(Fraction(3, 2))
    Traceback (most recent call last):
    ...
    ValueError: t must lie in [0, 1] for a Bezier curve, got t = 1.5
    """
    if not 0 <= t <= 1:
        raise ValueError(f"t must lie in [0, 1] for a Bezier curve, got t = {_v(t)}")
    return _norm(t)


def _point_columns(count: int, name: str, tex: str) -> tuple[Column, ...]:
    return tuple(Column(f"point_{i}", f"{name}_{i}", f"{tex}_{{{i}}}") for i in range(count))


def bezier_at_solution(points: Sequence[Point], t: Value) -> Solution:
    """De Casteljau's construction at one ``t`` in [0, 1], checked against Bernstein's form.

    >>> sol = bezier_at_solution([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2))
    >>> sol.derived[-1].text
    'B(0.5) = (2, 1.875) -> pixel (2, 2)'
    """
    pts = check_points(points, 2, "a Bezier curve")
    t = check_unit_t(t)
    n = len(pts) - 1
    if not isinstance(t, float):  # level r of the construction has denominators den(t)^r
        scale = math.lcm(*(Fraction(c).denominator for p in pts for c in p))
        bits = n * Fraction(t).denominator.bit_length() + scale.bit_length()
        _check_bits(bits, "de Casteljau's construction")
    *_, last = de_casteljau(pts, t)
    point: Point = last.extra[0]
    w = tuple(_norm(v) for v in bernstein(n, t if isinstance(t, float) else Fraction(t)))
    bern = _combine(w, pts)
    if bern != point and not isinstance(t, float):  # pragma: no cover - an invariant
        raise AssertionError("de Casteljau and Bernstein disagree")
    marks = _marks(pts)
    pixel = curve_pixel(*point)
    ts = _v(t)
    derived = [
        Quantity(
            "recurrence",
            t,
            f"P_i^(r) = (1 - t)·P_i^(r-1) + t·P_(i+1)^(r-1) = {_v(1 - t)}·P_i^(r-1) + {ts}·P_(i+1)^(r-1)",
            f"P_i^{{(r)}} = (1 - t) P_i^{{(r-1)}} + t P_{{i+1}}^{{(r-1)}} = {_v(1 - t)} "
            f"P_i^{{(r-1)}} + {ts} P_{{i+1}}^{{(r-1)}}",
        ),
        Quantity(
            "bernstein",
            w,
            f"Bernstein check: B({ts}) = "
            + " + ".join(f"{_v(wi)}·{_pt(p)}" for wi, p in zip(w, pts, strict=True))
            + f" = {_pt(bern)}",
            f"B({ts}) = "
            + " + ".join(f"{_v(wi)} \\cdot {_pt(p)}" for wi, p in zip(w, pts, strict=True))
            + f" = {_pt(bern)}",
        ),
        Quantity(
            "point",
            point,
            f"B({ts}) = {_pt(point)} -> pixel {pixel}",
            f"B({ts}) = {_pt(point)} \\to \\text{{pixel }} {pixel}",
        ),
    ]

    def rows() -> Iterator[tuple[Any, ...]]:
        for s in de_casteljau(pts, t):
            yield (s.k, *s.extra)

    return Solution(
        primitive="curve",
        algorithm="de-casteljau",
        title=f"De Casteljau's construction of a Bezier curve of degree {n} at t = {ts}",
        given=(
            *_given_points(pts),
            Quantity("t", t, f"t = {ts}", f"t = {ts}"),
        ),
        derived=tuple(derived),
        tables=(
            Table(
                f"De Casteljau levels at t = {ts} (row r holds P_i^(r))",
                (Column("r", "r", "r"), *_point_columns(n + 1, "P", "P")),
                rows,
            ),
        ),
        pixels=lambda: iter((pixel,)),
        bbox=_bbox((*marks, pixel)),
        notes=(
            "Each level interpolates neighbouring points of the level above at t; the last "
            "level is the curve point, equal to the Bernstein form.",
            _ROUND_NOTE,
        ),
        marks=marks,
        geometry={
            "polyline": [(float(point[0]), float(point[1]))],
            "control": _control_geometry(pts),
        },
    )


# --- B-splines ---------------------------------------------------------------------------------


def knot_vector(kind: str | Sequence[Number], n: int, p: int) -> tuple[Number, ...]:
    """The knot vector ``u_0 .. u_m`` (``m = n + p + 1``) for ``n + 1`` points of degree ``p``.

    ``open``: clamped uniform, ``p + 1`` equal knots at each end and integer steps inside;
    ``uniform``: ``0, 1, ..., m``; or an explicit sequence, which is validated: ``m = n + p + 1``,
    non-decreasing, no knot repeated more than ``p + 1`` times, a non-empty domain
    ``u_p < u_{n+1}``. Also checks ``1 <= p <= n``.

    >>> knot_vector("open", 4, 2)
    (0, 0, 0, 1, 2, 3, 3, 3)
    >>> knot_vector([0, 0, 1, 1], 3, 3)
    Traceback (most recent call last):
    ...
    ValueError: knot vector needs m + 1 = n + p + 2 = 8 values (m = n + p + 1 with n = 3, p = 3), got 4
    """
    if not 1 <= p <= n:
        raise ValueError(
            f"degree must satisfy 1 <= p <= n = {n} (n + 1 = {n + 1} control points), got p = {p}"
        )
    if p > MAX_DEGREE:
        raise ValueError(f"degree p = {p} is too high (at most {MAX_DEGREE})")
    m = n + p + 1
    if kind == "open":
        inner = n - p + 1
        return (0,) * p + tuple(range(inner + 1)) + (inner,) * p
    if kind == "uniform":
        return tuple(range(m + 1))
    if isinstance(kind, str):
        raise ValueError(f"unknown knot vector {kind!r} (open, uniform or a comma list)")
    knots = tuple(normalize(Fraction(u)) for u in kind)
    if len(knots) != m + 1:
        raise ValueError(
            f"knot vector needs m + 1 = n + p + 2 = {m + 1} values "
            f"(m = n + p + 1 with n = {n}, p = {p}), got {len(knots)}"
        )
    for i in range(m):
        if knots[i] > knots[i + 1]:
            raise ValueError(
                f"knot vector must be non-decreasing: u_{i} = {_v(knots[i])} > "
                f"u_{i + 1} = {_v(knots[i + 1])}"
            )
    for u in set(knots):
        if knots.count(u) > p + 1:
            raise ValueError(
                f"a knot may repeat at most p + 1 = {p + 1} times: {_v(u)} appears "
                f"{knots.count(u)} times"
            )
    if knots[p] == knots[n + 1]:
        raise ValueError(
            f"the domain u_p <= t <= u_(n+1) is empty: u_{p} = u_{n + 1} = {_v(knots[p])}"
        )
    return knots


def parse_knots(text: str) -> str | tuple[Fraction, ...]:
    """``open``, ``uniform`` or a comma list ``0,0,0,1,2,2,2`` of exact numbers.

    >>> parse_knots("0, 1/2,1")
    (Fraction(0, 1), Fraction(1, 2), Fraction(1, 1))
    """
    from ..core.numeric import parse_number

    s = text.strip().lower()
    if s in KNOTS:
        return s
    if "," not in s and not s.replace(".", "").replace("/", "").lstrip("+-").isdigit():
        raise ValueError(f"unknown knot vector {text!r} (open, uniform or a comma list)")
    try:
        return tuple(parse_number(u) for u in s.split(","))
    except ValueError as err:
        raise ValueError(f"bad knot vector {text!r}: {err}") from None


def _last_span(knots: Sequence[Any], n: int) -> int:
    """The last non-empty span ``[u_s, u_{s+1})`` with ``s <= n`` (closed at the domain's end)."""
    s = n
    while knots[s] == knots[s + 1]:
        s -= 1
    return s


def span(knots: Sequence[Number], n: int, t: Value) -> int:
    """The index ``s`` with ``u_s <= t < u_{s+1}``; at ``t = u_{n+1}`` the last non-empty span.

    >>> span((0, 0, 0, 1, 2, 2, 2), 3, 1), span((0, 0, 0, 1, 2, 2, 2), 3, 2)
    (3, 3)
    """
    if t >= knots[n + 1]:
        return _last_span(knots, n)
    return bisect.bisect_right(knots, t) - 1


def _raise_degree(
    knots: Sequence[Any], d: int, t: Any, row: Sequence[Any], window: range | None = None
) -> list[Any]:
    """Cox–de Boor: the degree-``d`` basis row from the degree ``d - 1`` row, with 0/0 = 0.

    Only the entries in ``window`` are computed (the others are 0); all of them by default.
    """
    out: list[Any] = [0] * (len(row) - 1)
    for i in range(len(out)) if window is None else window:
        a = knots[i + d] - knots[i]
        b = knots[i + d + 1] - knots[i + 1]
        left = (t - knots[i]) / a * row[i] if a else 0
        right = (knots[i + d + 1] - t) / b * row[i + 1] if b else 0
        out[i] = left + right
    return out


def basis_levels(knots: Sequence[Number], p: int, n: int, t: Value) -> list[list[Value]]:
    """Every row of Cox–de Boor at ``t``: ``N_{i,d}(t)`` for ``d = 0 .. p``.

    Row ``d`` has ``len(knots) - 1 - d`` entries; only ``N_{s-d,d} .. N_{s,d}`` (``s`` the span
    of ``t``) can be non-zero, so only those are computed. ``t`` must lie in the domain
    ``[u_p, u_{n+1}]``.

    >>> [[fmt_short(v) for v in row] for row in basis_levels((0, 0, 0, 1, 1, 1), 2, 2, Fraction(1, 2))]
    [['0', '0', '1', '0', '0'], ['0', '0.5', '0.5', '0'], ['0.25', '0.5', '0.25']]
    """
    s = span(knots, n, t)
    row: list[Any] = [1 if i == s else 0 for i in range(len(knots) - 1)]
    if not isinstance(t, float):
        t = Fraction(t)
    levels = [row]
    for d in range(1, p + 1):
        row = _raise_degree(knots, d, t, row, range(max(s - d, 0), min(s, len(row) - 2) + 1))
        levels.append(row)
    return [[_norm(v) for v in r] for r in levels]


def basis(knots: Sequence[Number], p: int, n: int, t: Value) -> tuple[Value, ...]:
    """``N_{i,p}(t)`` for ``i = 0 .. n`` (Cox–de Boor, 0/0 = 0, right end closed).

    >>> [fmt_short(v) for v in basis((0, 0, 0, 0, 1, 1, 1, 1), 3, 3, 1)]
    ['0', '0', '0', '1']
    """
    return tuple(basis_levels(knots, p, n, t)[p][: n + 1])


def _basis_dense(knots: Sequence[Number], p: int, n: int, ts: np.ndarray) -> list[Any]:
    """The same basis for a float array of ``t`` (dense sampling for the figure)."""
    kf = [float(u) for u in knots]
    s = np.searchsorted(kf, ts, side="right") - 1
    s = np.where(ts >= kf[n + 1], _last_span(kf, n), s)
    row: list[Any] = [(s == i).astype(float) for i in range(len(kf) - 1)]
    for d in range(1, p + 1):
        row = _raise_degree(kf, d, ts, row)
    return row[: n + 1]


def _domain(knots: Sequence[Number], p: int, n: int) -> tuple[Number, Number]:
    return knots[p], knots[n + 1]


def bspline_samples(knots: Sequence[Number], p: int, n: int) -> int:
    """The default steps of t for a B-spline: the same power of two in every knot span.

    The smallest power of two per non-empty span that gives at least :data:`DEFAULT_SAMPLES`
    steps in all, so that with integer knots every t is a short decimal.

    >>> bspline_samples((0, 0, 0, 1, 2, 3, 3, 3), 2, 4), bspline_samples((0,) * 4 + (1,) * 4, 3, 3)
    (24, 16)
    """
    spans = sum(1 for i in range(p, n + 1) if knots[i] < knots[i + 1])
    per = 1
    while spans * per < DEFAULT_SAMPLES:
        per *= 2
    return spans * per


def bspline(
    points: Sequence[Point],
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int | None = None,
) -> Iterator[Step]:
    """Tabulate the B-spline ``C(t) = sum_i N_{i,p}(t) P_i`` over its domain.

    ``t_k = u_p + k (u_{n+1} - u_p) / samples`` (default: :func:`bspline_samples`);
    ``Step.extra`` is
    ``(t, N_{0,p}(t), ..., N_{n,p}(t), x(t), y(t))``, exact for rational points and knots.

    Notes
    -----
    Cox–de Boor: ``N_{i,0}(t) = 1`` on ``u_i <= t < u_{i+1}``, else 0, and
    ``N_{i,d} = (t - u_i)/(u_{i+d} - u_i) N_{i,d-1} + (u_{i+d+1} - t)/(u_{i+d+1} - u_{i+1})
    N_{i+1,d-1}`` with a term whose denominator is 0 taken as 0. At ``t = u_{n+1}`` (the right
    end of the domain) the last non-empty span is closed, so a clamped curve ends exactly on
    its last control point; the half-open rule alone would give all-zero basis values there.

    Examples
    --------
    A quadratic with open knots (0, 0, 0, 1, 2, 3, 3, 3), starting on P0 and ending on P4:

    >>> for s in bspline([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", 2):
    ...     print(s.k, *(fmt(v) for v in s.extra), s.pixel)
    0 0 1 0 0 0 0 0 0 (0, 0)
    1 1.500 0 0.125 0.750 0.125 0 2.875 2.500 (3, 3)
    2 3 0 0 0 0 1 5 2 (5, 2)
    """
    pts = check_points(points, 2, "a B-spline")
    n = len(pts) - 1
    u = knot_vector(knots, n, degree)
    t0, t1 = _domain(u, degree, n)
    # bspline(4 points, p=3, open knots 0,0,0,0,1,1,1,1, 2) -> t = 1/2: N = 1/8 3/8 3/8 1/8
    #   (a clamped B-spline with no inner knot is the Bezier curve) ; point (2, 1.875)
    steps = bspline_samples(u, degree, n) if samples is None else check_samples(samples)
    for k, t in enumerate(sample_ts(t0, t1, steps)):
        w = basis(u, degree, n, t)
        x, y = _combine(w, pts)
        yield Step(k, None, None, curve_pixel(x, y), (t, *w, x, y))


def _knot_text(knots: Sequence[Number]) -> str:
    return "(" + ", ".join(_v(u) for u in knots) + ")"


def _bspline_derived(
    pts: Sequence[Point], p: int, knots: Sequence[Number], kind: str
) -> list[Quantity]:
    n = len(pts) - 1
    m = n + p + 1
    t0, t1 = _domain(knots, p, n)
    how = {
        "open": f"open: p + 1 = {p + 1} equal knots at each end, uniform inside",
        "uniform": "uniform: equally spaced, not clamped",
    }.get(kind, "as given")
    terms = " + ".join(f"N_{{{i},{p}}}(t)·{_pt(pt)}" for i, pt in enumerate(pts))
    tex_terms = " + ".join(f"N_{{{i},{p}}}(t) \\cdot {_pt(pt)}" for i, pt in enumerate(pts))
    return [
        Quantity(
            "n",
            n,
            f"n = number of control points - 1 = {n + 1} - 1 = {n}; degree p = {p}",
            f"n = {n + 1} - 1 = {n}; \\quad p = {p}",
        ),
        Quantity(
            "m",
            m,
            f"m = n + p + 1 = {n} + {p} + 1 = {m}: knots u_0 … u_{m}",
            f"m = n + p + 1 = {n} + {p} + 1 = {m}: \\; u_0 \\ldots u_{{{m}}}",
        ),
        Quantity(
            "knots",
            tuple(knots),
            f"U = {_knot_text(knots)}   ({how})",
            f"U = {_knot_text(knots)} \\quad \\text{{({kind if kind != 'explicit' else 'as given'})}}",
        ),
        Quantity(
            "domain",
            (t0, t1),
            f"domain u_p ≤ t ≤ u_(n+1): u_{p} = {_v(t0)} ≤ t ≤ u_{n + 1} = {_v(t1)}",
            f"u_p \\le t \\le u_{{n+1}}: \\; u_{{{p}}} = {_v(t0)} \\le t \\le u_{{{n + 1}}} = {_v(t1)}",
        ),
        Quantity(
            "N0",
            None,
            "N_{i,0}(t) = 1 if u_i ≤ t < u_(i+1), else 0",
            r"N_{i,0}(t) = 1 \text{ if } u_i \le t < u_{i+1}, \text{ else } 0",
        ),
        Quantity(
            "Np",
            None,
            "N_{i,p}(t) = (t - u_i)/(u_(i+p) - u_i)·N_{i,p-1}(t) + "
            "(u_(i+p+1) - t)/(u_(i+p+1) - u_(i+1))·N_{i+1,p-1}(t)   (0/0 = 0)",
            r"N_{i,p}(t) = \frac{t - u_i}{u_{i+p} - u_i} N_{i,p-1}(t) + "
            r"\frac{u_{i+p+1} - t}{u_{i+p+1} - u_{i+1}} N_{i+1,p-1}(t) \quad (0/0 = 0)",
        ),
        Quantity("C(t)", None, f"C(t) = {terms}", f"C(t) = {tex_terms}"),
    ]


_BSPLINE_NOTES = (
    "Cox–de Boor with 0/0 taken as 0; at the right end of the domain the last non-empty span "
    "is closed, so a clamped curve ends exactly on its last control point.",
)


def _bspline_setup(
    points: Sequence[Point], degree: int, knots: str | Sequence[Number]
) -> tuple[tuple[Point, ...], int, tuple[Number, ...], str]:
    pts = check_points(points, 2, "a B-spline")
    n = len(pts) - 1
    u = knot_vector(knots, n, degree)
    kind = knots if isinstance(knots, str) else "explicit"
    return pts, n, u, kind


def bspline_solution(
    points: Sequence[Point],
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int | None = None,
    *,
    basis_only: bool = False,
) -> Solution:
    """The worked solution of a B-spline; ``basis_only``: only the table of ``N_{i,p}(t)``.

    >>> sol = bspline_solution([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", 4)
    >>> sol.derived[2].text
    'U = (0, 0, 0, 1, 2, 3, 3, 3)   (open: p + 1 = 3 equal knots at each end, uniform inside)'
    >>> list(sol.pixels())[-1]
    (5, 2)
    """
    pts, n, u, kind = _bspline_setup(points, degree, knots)
    samples = bspline_samples(u, degree, n) if samples is None else check_samples(samples)
    check_weights(samples, n + 1)
    if not basis_only:
        check_path([pts], samples)
    t0, t1 = _domain(u, degree, n)

    def steps() -> Iterator[Step]:
        return bspline(pts, degree, u, samples)

    _check_row(steps(), "B-spline")

    derived = [
        *_bspline_derived(pts, degree, u, kind),
        _step_quantity(t0, t1, samples, _v(t0), _v(t1), _v(t0), _v(t1)),
    ]
    basis_cols = tuple(
        Column(f"N{i}", f"N_{{{i},{degree}}}", f"N_{{{i},{degree}}}", 3) for i in range(n + 1)
    )
    title = (
        f"B-spline of degree {degree}: {n + 1} control points, knots {_knot_text(u)}, "
        f"{samples} steps of t"
    )
    if basis_only:

        def rows() -> Iterator[tuple[Any, ...]]:
            for s in steps():
                yield (s.k, *s.extra[: n + 2])

        return Solution(
            primitive="curve",
            algorithm="bspline-basis",
            title="Basis functions of a " + title,
            given=(Quantity("p", degree, f"p = {degree}", f"p = {degree}"),),
            derived=tuple(q for q in derived if q.key != "C(t)"),
            tables=(
                Table(
                    f"Basis functions N_(i,{degree})(t) (each row sums to 1)",
                    (*_KT, *basis_cols),
                    rows,
                ),
            ),
            notes=_BSPLINE_NOTES,
        )
    marks = _marks(pts)
    ts = _dense_ts(t0, t1, samples)
    dense = _combine(_basis_dense(u, degree, n, ts), _control_geometry(pts))
    return Solution(
        primitive="curve",
        algorithm="bspline",
        title=title,
        given=tuple(_given_points(pts)),
        derived=tuple(derived),
        columns=(*_KT, *basis_cols, *_xy_columns()),
        extra_keys=("t", *(f"N{i}" for i in range(n + 1)), "x_t", "y_t"),
        steps=steps,
        pixels=lambda: curve_pixels(s.pixel for s in steps()),
        # Basis values are >= 0 and sum to 1 on the domain: the curve lies in the convex hull.
        bbox=_bbox(marks),
        notes=(
            *_BSPLINE_NOTES,
            "Basis values and points are exact fractions (3 decimals shown).",
            _ROUND_NOTE,
            _JOIN_NOTE,
            "Control points are marked o in the grid; a clamped (open) curve passes through the "
            "first and last of them, an unclamped one in general through none.",
        ),
        marks=marks,
        geometry={"polyline": _polyline(*dense), "control": _control_geometry(pts)},
    )


def bspline_at_solution(
    points: Sequence[Point], degree: int, knots: str | Sequence[Number], t: Value
) -> Solution:
    """One ``t``: the Cox–de Boor triangle, the non-zero ``N_{i,p}(t)``, their weighted sum.

    >>> sol = bspline_at_solution([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", Fraction(3, 2))
    >>> sol.derived[-1].text
    'C(1.5) = 0.125·(1, 2) + 0.75·(3, 3) + 0.125·(4, 0) = (2.875, 2.5) -> pixel (3, 3)'
    """
    pts, n, u, kind = _bspline_setup(points, degree, knots)
    t0, t1 = _domain(u, degree, n)
    if not t0 <= t <= t1:
        raise ValueError(
            f"t must lie in the domain [u_p, u_(n+1)] = [{_v(t0)}, {_v(t1)}], got t = {_v(t)}"
        )
    t = _norm(t)
    levels = basis_levels(u, degree, n, t)
    w = levels[degree][: n + 1]
    point = _combine(w, pts)
    check_exact((*w, *point), "the B-spline at this t")
    pixel = curve_pixel(*point)
    s = span(u, n, t)
    ts = _v(t)
    nz = [i for i in range(n + 1) if w[i] != 0]
    closed = t == t1
    span_text = (
        f"t = {ts} lies in span s = {s}: u_{s} = {_v(u[s])} ≤ t "
        + ("≤" if closed else "<")
        + f" u_{s + 1} = {_v(u[s + 1])}"
        + ("   (right end: the last non-empty span is closed)" if closed else "")
    )
    span_tex = (
        f"s = {s}: \\; u_{{{s}}} = {_v(u[s])} \\le t = {ts} "
        + ("\\le" if closed else "<")
        + f" u_{{{s + 1}}} = {_v(u[s + 1])}"
    )
    derived = [
        *(q for q in _bspline_derived(pts, degree, u, kind) if q.key not in ("N0", "Np")),
        Quantity("span", s, span_text, span_tex),
        Quantity(
            "nonzero",
            tuple(nz),
            "non-zero basis values: "
            + ", ".join(f"N_{{{i},{degree}}}({ts}) = {_v(w[i])}" for i in nz)
            + f"   (sum = {_v(sum(w[i] for i in nz))})",
            ", ".join(f"N_{{{i},{degree}}}({ts}) = {_v(w[i])}" for i in nz),
        ),
        Quantity(
            "point",
            point,
            f"C({ts}) = "
            + " + ".join(f"{_v(w[i])}·{_pt(pts[i])}" for i in nz)
            + f" = {_pt(point)} -> pixel {pixel}",
            f"C({ts}) = "
            + " + ".join(f"{_v(w[i])} \\cdot {_pt(pts[i])}" for i in nz)
            + f" = {_pt(point)} \\to \\text{{pixel }} {pixel}",
        ),
    ]
    lo = max(s - degree, 0)
    tri_cols = tuple(Column(f"N{i}", f"N_{{{i},d}}", f"N_{{{i},d}}", 3) for i in range(lo, s + 1))

    def triangle() -> Iterator[tuple[Any, ...]]:
        for d, row in enumerate(levels):
            yield (d, *(row[i] if s - d <= i < len(row) else None for i in range(lo, s + 1)))

    def weighted() -> Iterator[tuple[Any, ...]]:
        for i in nz:
            yield (i, w[i], pts[i], (_norm(w[i] * pts[i][0]), _norm(w[i] * pts[i][1])))

    marks = _marks(pts)
    return Solution(
        primitive="curve",
        algorithm="bspline-at",
        title=f"B-spline of degree {degree} at t = {ts}: knots {_knot_text(u)}",
        given=(*_given_points(pts), Quantity("t", t, f"t = {ts}", f"t = {ts}")),
        derived=tuple(derived),
        tables=(
            Table(
                f"Cox–de Boor at t = {ts}: N_(i,d) for d = 0 .. {degree} (only the span's "
                "functions can be non-zero)",
                (Column("d", "d", "d"), *tri_cols),
                triangle,
            ),
            Table(
                "Weighted sum of the non-zero terms",
                (
                    Column("i", "i", "i"),
                    Column("N", f"N_(i,{degree})(t)", f"N_{{i,{degree}}}(t)", 3),
                    Column("point_P", "P_i", "P_i"),
                    Column("point_NP", f"N_(i,{degree})(t)·P_i", f"N_{{i,{degree}}}(t) P_i"),
                ),
                weighted,
            ),
        ),
        pixels=lambda: iter((pixel,)),
        bbox=_bbox((*marks, pixel)),
        notes=(*_BSPLINE_NOTES, _ROUND_NOTE),
        marks=marks,
        geometry={
            "polyline": [(float(point[0]), float(point[1]))],
            "control": _control_geometry(pts),
        },
    )


# --- continuity of two Bezier segments ---------------------------------------------------------


def _sub(p: Point, q: Point) -> Point:
    return _norm(p[0] - q[0]), _norm(p[1] - q[1])


def _scale(c: Number, p: Point) -> Point:
    return _norm(c * p[0]), _norm(c * p[1])


def end_derivatives(points: Sequence[Point], at_end: bool) -> tuple[Point, Point, Point]:
    """Position, first and second derivative of a Bezier segment at ``t = 1`` or ``t = 0``.

    ``B'(1) = n (P_n - P_{n-1})``, ``B''(1) = n (n - 1) (P_n - 2 P_{n-1} + P_{n-2})``, and at
    ``t = 0`` the same with ``P_0, P_1, P_2`` (``B'(0) = n (P_1 - P_0)``). A degree-1 segment
    has ``B'' = 0``.

    >>> end_derivatives([(0, 0), (1, 2), (3, 3), (4, 0)], True)
    ((4, 0), (3, -9), (-6, -24))
    """
    pts = tuple(points)
    n = len(pts) - 1
    if at_end:
        pts = pts[::-1]
    d1 = _scale(n, _sub(pts[1], pts[0]))
    d2: Point = (0, 0)
    if n >= 2:
        d2 = _scale(n * (n - 1), _sub(_sub(pts[2], pts[1]), _sub(pts[1], pts[0])))
    if at_end:
        d1 = _scale(-1, d1)
    return pts[0], d1, d2


def continuity_level(first: Sequence[Point], second: Sequence[Point]) -> int:
    """The highest ``k`` in 0, 1, 2 with C^k at the join, or -1 if the segments do not meet.

    >>> continuity_level([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)])
    1
    """
    a = end_derivatives(first, True)
    b = end_derivatives(second, False)
    level = -1
    for k in range(3):
        if a[k] != b[k]:
            break
        level = k
    return level


def continuity_solution(
    first: Sequence[Point], second: Sequence[Point], samples: int = DEFAULT_SAMPLES
) -> Solution:
    """Classify the join of two Bezier segments: the highest of C0, C1, C2 that holds.

    >>> sol = continuity_solution([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)])
    >>> sol.derived[-1].text
    'continuity at the join: C1 (C0 and C1 hold; C2 fails)'
    """
    a_pts = check_points(first, 2, "the first segment")
    b_pts = check_points(second, 2, "the second segment")
    check_samples(samples)
    check_weights(samples, len(a_pts) + len(b_pts))
    check_path([a_pts, b_pts], samples)
    _check_row(bezier(a_pts, samples), "the first segment")
    _check_row(bezier(b_pts, samples), "the second segment")
    n, m = len(a_pts) - 1, len(b_pts) - 1
    a = end_derivatives(a_pts, True)
    b = end_derivatives(b_pts, False)
    level = continuity_level(a_pts, b_pts)
    names = ("C0", "C1", "C2")
    derived = [
        Quantity("A(1)", a[0], f"A(1) = P_{n} = {_pt(a[0])}", f"A(1) = P_{{{n}}} = {_pt(a[0])}"),
        Quantity("B(0)", b[0], f"B(0) = Q_0 = {_pt(b[0])}", f"B(0) = Q_0 = {_pt(b[0])}"),
        Quantity(
            "A'(1)",
            a[1],
            f"A'(1) = n(P_{n} - P_{n - 1}) = {n}·({_pt(a_pts[-1])} - {_pt(a_pts[-2])}) = {_pt(a[1])}",
            f"A'(1) = n(P_{{{n}}} - P_{{{n - 1}}}) = {n}({_pt(a_pts[-1])} - {_pt(a_pts[-2])}) = {_pt(a[1])}",
        ),
        Quantity(
            "B'(0)",
            b[1],
            f"B'(0) = m(Q_1 - Q_0) = {m}·({_pt(b_pts[1])} - {_pt(b_pts[0])}) = {_pt(b[1])}",
            f"B'(0) = m(Q_1 - Q_0) = {m}({_pt(b_pts[1])} - {_pt(b_pts[0])}) = {_pt(b[1])}",
        ),
        _second("A''(1)", a_pts[::-1], a[2], "P", n, True),
        _second("B''(0)", b_pts, b[2], "Q", m, False),
    ]
    if level < 0:
        verdict = "none: the segments do not meet (C0 fails)"
    else:
        holds = " and ".join(names[: level + 1])
        verdict = f"{names[level]} ({holds} {'hold' if level else 'holds'}"
        verdict += f"; {names[level + 1]} fails)" if level < 2 else ")"
    derived.append(
        Quantity(
            "continuity",
            names[level] if level >= 0 else None,
            f"continuity at the join: {verdict}",
            f"\\text{{continuity at the join: {verdict}}}",
        )
    )
    notes = [
        "A(t) has control points P_0 .. P_n, B(t) has Q_0 .. Q_m; each runs over 0 ≤ t ≤ 1 and "
        "they join at A(1) and B(0).",
        "C0: positions equal (position continuity); C1: first derivatives equal (tangent "
        "continuity); C2: second derivatives equal too (curvature continuity).",
    ]
    if level == 0 and _parallel(a[1], b[1]):
        notes.append(
            "The tangents point the same way but differ in length: the join is G1 (geometric "
            "tangent continuity), though not C1."
        )
    notes.append(_JOIN_NOTE)

    def rows() -> Iterator[tuple[Any, ...]]:
        labels = ("position", "first derivative", "second derivative")
        for k in range(3):
            yield (names[k], labels[k], a[k], b[k], a[k] == b[k])

    marks = _marks((*a_pts, *b_pts))

    def pixels() -> Iterator[Pixel]:
        return curve_pixels(
            (s.pixel for s in bezier(a_pts, samples)), (s.pixel for s in bezier(b_pts, samples))
        )

    ts = _dense_ts(0, 1, samples)
    xa, ya = _combine(bernstein(n, ts), _control_geometry(a_pts))
    xb, yb = _combine(bernstein(m, ts), _control_geometry(b_pts))
    return Solution(
        primitive="curve",
        algorithm="continuity",
        title=f"Continuity of two Bezier segments (degrees {n} and {m}) at their join",
        given=(*_given_points(a_pts), *_given_points(b_pts, "Q", "Q")),
        derived=tuple(derived),
        tables=(
            Table(
                "Continuity at the join",
                (
                    Column("order", "order", r"\text{order}"),
                    Column("quantity", "compared", r"\text{compared}"),
                    Column("point_A", "A at t = 1", r"A(1)"),
                    Column("point_B", "B at t = 0", r"B(0)"),
                    Column("equal", "equal", r"\text{equal}"),
                ),
                rows,
            ),
        ),
        pixels=pixels,
        bbox=_bbox(marks),
        notes=tuple(notes),
        marks=marks,
        geometry={
            "polyline": _polyline(np.concatenate([xa, xb]), np.concatenate([ya, yb])),
            "control": _control_geometry((*a_pts, *b_pts)),
        },
        data={"continuity": names[level] if level >= 0 else None},
    )


def _second(key: str, pts: Sequence[Point], value: Point, name: str, n: int, end: bool) -> Quantity:
    """The working of ``A''(1)`` or ``B''(0)``; ``pts`` start at the join."""
    deg = "n" if name == "P" else "m"
    if n < 2:
        return Quantity(key, value, f"{key} = 0 (degree 1)", f"{key} = 0 \\; (\\text{{degree 1}})")
    idx = (n, n - 1, n - 2) if end else (0, 1, 2)
    sym = f"{name}_{idx[0]} - 2{name}_{idx[1]} + {name}_{idx[2]}"
    tex_sym = f"{name}_{{{idx[0]}}} - 2{name}_{{{idx[1]}}} + {name}_{{{idx[2]}}}"
    nums = f"{_pt(pts[0])} - 2·{_pt(pts[1])} + {_pt(pts[2])}"
    tex_nums = f"{_pt(pts[0])} - 2{_pt(pts[1])} + {_pt(pts[2])}"
    return Quantity(
        key,
        value,
        f"{key} = {deg}({deg} - 1)({sym}) = {n}·{n - 1}·({nums}) = {_pt(value)}",
        f"{key} = {deg}({deg}-1)({tex_sym}) = {n} \\cdot {n - 1} ({tex_nums}) = {_pt(value)}",
    )


def _parallel(u: Point, v: Point) -> bool:
    """Same direction (positive multiple), both non-zero."""
    cross = u[0] * v[1] - u[1] * v[0]
    dot = u[0] * v[0] + u[1] * v[1]
    return cross == 0 and dot > 0


# --- local control: Bezier vs B-spline ---------------------------------------------------------


def local_control(
    points: Sequence[Point],
    index: int,
    moved: Point,
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int = DEFAULT_SAMPLES,
) -> Iterator[Step]:
    """The same control points, one moved: which samples of each curve move.

    Step ``k`` compares the Bezier curve at ``t = k / samples`` and the B-spline at
    ``t = u_p + k (u_{n+1} - u_p) / samples``, before and after ``P_index`` moves to ``moved``.
    ``extra`` is ``(t_bezier, pixel before, pixel after, moved?, t_bspline, pixel before,
    pixel after, moved?)`` where ``moved?`` compares the exact points; ``pixel`` is the
    B-spline's pixel after the move.

    Notes
    -----
    A Bezier weight ``B_{i,n}(t)`` is positive on all of ``0 < t < 1``, so moving any control
    point moves every point but the ends (global control). A B-spline basis function
    ``N_{i,p}`` is zero outside ``[u_i, u_{i+p+1}]``, so only that stretch moves (local
    control).

    Examples
    --------
    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> rows = list(local_control(pts, 5, (7, 5), 2, "open", 4))
    >>> [(fmt_short(s.extra[0]), s.extra[3], fmt_short(s.extra[4]), s.extra[7]) for s in rows]
    [('0', False, '0', False), ('0.25', True, '1', False), ('0.5', True, '2', False), ('0.75', True, '3', False), ('1', True, '4', True)]
    """
    pts = check_points(points, 2, "the control polygon")
    _check_index(index, len(pts))
    after = list(pts)
    after[index] = _exact_point(moved)
    # local_control(6 points, move P5, p=2 open) -> Bezier moves for t > 0 ;
    #   B-spline only for t > u_5 = 3
    for before_z, after_z, before_s, after_s in zip(
        bezier(pts, samples),
        bezier(after, samples),
        bspline(pts, degree, knots, samples),
        bspline(after, degree, knots, samples),
        strict=True,
    ):
        yield Step(
            before_z.k,
            None,
            None,
            after_s.pixel,
            (
                before_z.extra[0],
                before_z.pixel,
                after_z.pixel,
                before_z.extra[-2:] != after_z.extra[-2:],
                before_s.extra[0],
                before_s.pixel,
                after_s.pixel,
                before_s.extra[-2:] != after_s.extra[-2:],
            ),
        )


def _check_index(index: int, count: int) -> None:
    if not 0 <= index < count:
        raise ValueError(f"--move index must be 0 .. {count - 1}, got {index}")


def _moved_quantity(key: str, moved: int, total: int, removed: int, added: int) -> Quantity:
    name = "Bezier" if key == "bezier" else "B-spline"
    text = f"{moved} of {total} samples moved; pixels: {removed} removed, {added} added"
    return Quantity(f"{key}_moved", moved, f"{name}: {text}", f"\\text{{{name}: {text}}}")


def _changed(before: Iterable[Pixel], after: Iterable[Pixel]) -> tuple[int, int]:
    b, a = set(before), set(after)
    return len(b - a), len(a - b)


def local_control_solution(
    points: Sequence[Point],
    index: int,
    moved: Point,
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int = DEFAULT_SAMPLES,
) -> Solution:
    """The notes' Bezier-vs-B-spline comparison as an example: move one point, count changes.

    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> sol = local_control_solution(pts, 5, (7, 5), 2, "open", 8)
    >>> sol.data["bezier_samples_moved"], sol.data["bspline_samples_moved"]
    (8, 2)
    """
    pts, n, u, _ = _bspline_setup(points, degree, knots)
    check_samples(samples)
    check_weights(samples, len(pts))
    _check_index(index, len(pts))
    moved_pts = [*pts[:index], _exact_point(moved), *pts[index + 1 :]]
    check_path([pts, moved_pts], samples)
    for polygon in (pts, moved_pts):
        _check_row(bezier(polygon, samples), "Bezier curve")
        _check_row(bspline(polygon, degree, u, samples), "B-spline")
    z_moved = s_moved = 0
    for s in local_control(pts, index, moved, degree, u, samples):  # also validates index
        z_moved += s.extra[3]
        s_moved += s.extra[7]
    new = _exact_point(moved)
    after = list(pts)
    after[index] = new
    z_before = list(curve_pixels(s.pixel for s in bezier(pts, samples)))
    z_after = list(curve_pixels(s.pixel for s in bezier(after, samples)))
    s_before = list(curve_pixels(s.pixel for s in bspline(pts, degree, u, samples)))
    s_after = list(curve_pixels(s.pixel for s in bspline(after, degree, u, samples)))
    z_rm, z_add = _changed(z_before, z_after)
    s_rm, s_add = _changed(s_before, s_after)
    lo, hi = u[index], u[index + degree + 1]
    t0, t1 = _domain(u, degree, n)
    total = samples + 1
    derived = [
        Quantity(
            "move",
            (index, new),
            f"P{index} moves from {_pt(pts[index])} to {_pt(new)}",
            f"P_{{{index}}}: {_pt(pts[index])} \\to {_pt(new)}",
        ),
        Quantity(
            "knots",
            tuple(u),
            f"B-spline: degree p = {degree}, U = {_knot_text(u)}, domain {_v(t0)} ≤ t ≤ {_v(t1)}",
            f"\\text{{B-spline: }} p = {degree}, \\; U = {_knot_text(u)}, \\; {_v(t0)} \\le t "
            f"\\le {_v(t1)}",
        ),
        Quantity(
            "bezier_support",
            (0, 1),
            f"Bezier: B_{{{index},{n}}}(t) > 0 for all 0 < t < 1, so every point with "
            "0 < t < 1 moves",
            f"\\text{{Bezier: }} B_{{{index},{n}}}(t) > 0 \\text{{ for }} 0 < t < 1",
        ),
        _moved_quantity("bezier", z_moved, total, z_rm, z_add),
        Quantity(
            "bspline_support",
            (lo, hi),
            f"B-spline: N_{{{index},{degree}}}(t) = 0 outside u_{index} = {_v(lo)} ≤ t ≤ "
            f"u_{index + degree + 1} = {_v(hi)}, so only that stretch moves",
            f"\\text{{B-spline: }} N_{{{index},{degree}}}(t) = 0 \\text{{ outside }} "
            f"u_{{{index}}} = {_v(lo)} \\le t \\le u_{{{index + degree + 1}}} = {_v(hi)}",
        ),
        _moved_quantity("bspline", s_moved, total, s_rm, s_add),
    ]

    legend = "# = after the move only, o = before only, @ = both"
    figures = tuple(
        PixelFigure(tuple(aft), tuple(before), _bbox([*before, *aft]), legend, f"{name}:")
        for name, before, aft in (("Bezier", z_before, z_after), ("B-spline", s_before, s_after))
    )

    return Solution(
        primitive="curve",
        algorithm="local-control",
        title=f"Local control: Bezier vs B-spline, P{index} moved from {_pt(pts[index])} to {_pt(new)}",
        given=tuple(_given_points(pts)),
        derived=tuple(derived),
        columns=(
            Column("k", "k", "k"),
            Column("t_bezier", "t (Bezier)", r"t_{\text{Bez}}", 3),
            Column("bezier_before", "Bezier before", r"\text{Bezier before}"),
            Column("bezier_after", "Bezier after", r"\text{Bezier after}"),
            Column("bezier_moved", "moved", r"\text{moved}"),
            Column("t_bspline", "t (B-spline)", r"t_{\text{B-spl}}", 3),
            Column("bspline_before", "B-spline before", r"\text{B-spline before}"),
            Column("bspline_after", "B-spline after", r"\text{B-spline after}"),
            Column("bspline_moved", "moved", r"\text{moved}"),
        ),
        extra_keys=(
            "t_bezier",
            "bezier_before",
            "bezier_after",
            "bezier_moved",
            "t_bspline",
            "bspline_before",
            "bspline_after",
            "bspline_moved",
        ),
        steps=lambda: local_control(pts, index, new, degree, u, samples),
        notes=(
            "Both curves use the same control points and the same number of samples; 'moved' "
            "compares the exact points before and after.",
            "Bezier curves have global control (every weight is positive inside 0 < t < 1); "
            "B-splines have local control (N_{i,p} vanishes outside [u_i, u_(i+p+1)]).",
            _JOIN_NOTE,
        ),
        figures=figures,
        data={
            "bezier_samples_moved": z_moved,
            "bspline_samples_moved": s_moved,
            "bezier_pixels_changed": z_rm + z_add,
            "bspline_pixels_changed": s_rm + s_add,
        },
    )


__all__ = [
    "KNOTS",
    "PARAMETRIC",
    "basis",
    "basis_levels",
    "bernstein",
    "bezier",
    "bezier_at_solution",
    "bezier_solution",
    "bspline",
    "bspline_at_solution",
    "bspline_solution",
    "continuity_level",
    "continuity_solution",
    "curve_pixels",
    "de_casteljau",
    "end_derivatives",
    "knot_vector",
    "local_control",
    "local_control_solution",
    "parametric",
    "parametric_solution",
    "parse_knots",
    "sample_ts",
]
