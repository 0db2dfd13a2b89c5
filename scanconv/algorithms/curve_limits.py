"""The limits of the curve algorithms and the checks that enforce them before any work.

Every curve is tabulated at ``N + 1`` values of its parameter (``samples = N`` equal steps, both
ends included); a control polygon has at most :data:`MAX_POINTS` points. A check raises
:class:`~scanconv.core.checks.InputError` naming the library parameter it is about
(``samples``, ``points``, ``t``, ``index``); the message states the rule, never a command-line
flag.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Any

from ..core.checks import InputError, check_count
from ..core.expr import MAX_BITS
from ..core.numeric import Number, fmt, fmt_short, normalize
from ..core.records import Step

Value = Number | float
"""A coordinate or parameter value: exact where the input is rational, else a float."""

Point = tuple[Value, Value]
"""A point ``(x, y)``."""

DEFAULT_SAMPLES = 16
"""Steps of t when none are given (the parametric line uses max(|dx|, |dy|))."""

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


EXACT_WORK = 10**6
"""Most exact evaluations of a parametric curve: ``(samples + 1) × size`` of its rational
formulas (:attr:`~scanconv.core.expr.Expr.size`, operations, names and numbers). Beyond it the
formulas are evaluated in float64, vectorised (a long polynomial at 10**5 values of t took six
minutes exactly, a few seconds in float64). Not a refusal: the answer says which it did."""


def norm_value(v: Any) -> Any:
    """Integral fractions become ``int``; floats (and numpy arrays) are left alone.

    >>> norm_value(Fraction(4, 2)), norm_value(0.5)
    (2, 0.5)
    """
    return normalize(v) if isinstance(v, (int, Fraction)) else v


def exact_point(p: Point) -> Point:
    """``p`` with exact coordinates (a float becomes the fraction it stands for).

    >>> exact_point((Fraction(4, 2), 0.5))
    (2, Fraction(1, 2))
    """
    return normalize(Fraction(p[0])), normalize(Fraction(p[1]))


def _shown(v: Value) -> str:
    """A value in a message: exact values briefly, floats to 3 decimals.

    >>> _shown(Fraction(3, 2)), _shown(2 / 3)
    ('1.5', '0.667')
    """
    return fmt(v) if isinstance(v, float) else fmt_short(v)


def check_samples(samples: int) -> int:
    """Return ``samples`` if ``1 <= samples <= MAX_SAMPLES``, else raise ``InputError``.

    >>> check_samples(0)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: samples must be at least 1, got 0
    """
    return check_count(samples, "samples", 1, MAX_SAMPLES, param="samples")


def check_weights(samples: int, points: int) -> None:
    """Refuse a table of more than :data:`MAX_WEIGHTS` exact weights, before any is computed.

    >>> check_weights(10**5, 4)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: (samples + 1) x control points = 100001 x 4 = 400,004 exact weights is too many (at most 100,000); use fewer samples
    """
    cells = (samples + 1) * points
    if cells > MAX_WEIGHTS:
        raise InputError(
            f"(samples + 1) x control points = {samples + 1} x {points} = {cells:,} exact "
            f"weights is too many (at most {MAX_WEIGHTS:,}); use fewer samples",
            "samples",
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
    scanconv.core.checks.InputError: the control polygon is 1,000,000 pixels long (max(|dx|, |dy|) summed) and 16 samples add up to 16 more: the curve could need 1,000,016 pixels, more than 1,000,000
    """
    for pts in polygons:
        edges = (
            max(abs(Fraction(q[0]) - Fraction(p[0])), abs(Fraction(q[1]) - Fraction(p[1])))
            for p, q in itertools.pairwise(pts)
        )
        length = math.ceil(sum(edges, Fraction(0)))
        if length + samples > MAX_CURVE_PIXELS:
            raise InputError(
                f"the control polygon is {length:,} pixels long (max(|dx|, |dy|) summed) and "
                f"{samples} samples add up to {samples} more: the curve could need "
                f"{length + samples:,} pixels, more than {MAX_CURVE_PIXELS:,}",
                "points",
            )


def check_bits(bits: int, what: str) -> None:
    """Refuse exact values of more than :data:`~scanconv.core.expr.MAX_BITS` bits.

    >>> check_bits(4097, "B(t)")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: B(t): exact values would need more than 4096 bits (give fewer decimals, fewer control points or a lower degree)
    """
    if bits > MAX_BITS:
        raise InputError(
            f"{what}: exact values would need more than {MAX_BITS} bits (give fewer "
            "decimals, fewer control points or a lower degree)"
        )


def check_exact(values: Iterable[Any], what: str) -> None:
    """Refuse exact values with more than :data:`~scanconv.core.expr.MAX_BITS` bits, too long to show.

    >>> check_exact([Fraction(1, 3**3000)], "B(t)")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: B(t): exact values would need more than 4096 bits (give fewer decimals, fewer control points or a lower degree)
    """
    for v in values:
        if isinstance(v, Fraction):
            check_bits(max(v.numerator.bit_length(), v.denominator.bit_length()), what)


def check_row(steps: Iterator[Step], what: str) -> None:
    """Evaluate the row at ``k = 1`` (``t = 1/N`` carries the largest denominators) and refuse
    it if its exact values are too long (:func:`check_exact`).

    >>> rows = iter([Step(0, None, None, (0, 0), (0,)), Step(1, None, None, (0, 0), (Fraction(1, 2**5000),))])
    >>> check_row(rows, "B(t)")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: B(t): exact values would need more than 4096 bits (give fewer decimals, fewer control points or a lower degree)
    """
    row = next(itertools.islice(steps, 1, None), None)
    if row is not None:
        check_exact(row.extra, what)


def check_points(
    points: Sequence[Point], least: int, what: str, *, param: str = "points"
) -> tuple[Point, ...]:
    """Validate a control polygon: at least ``least`` and at most :data:`MAX_POINTS` points.

    Returns the points with exact coordinates.

    >>> check_points([(0, 0)], 2, "a Bezier curve")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: a Bezier curve needs at least 2 control points, got 1
    """
    if len(points) < least:
        raise InputError(f"{what} needs at least {least} control points, got {len(points)}", param)
    if len(points) > MAX_POINTS:
        raise InputError(
            f"{what} takes at most {MAX_POINTS} control points, got {len(points)}", param
        )
    return tuple(exact_point(p) for p in points)


def check_unit_t(t: Value) -> Value:
    """``t`` if ``0 <= t <= 1``, else ``InputError``.

    >>> check_unit_t(Fraction(3, 2))
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: t must lie in [0, 1] for a Bezier curve, got t = 1.5
    """
    if not 0 <= t <= 1:
        raise InputError(f"t must lie in [0, 1] for a Bezier curve, got t = {_shown(t)}", "t")
    shown: Value = norm_value(t)
    return shown


def check_index(index: int, count: int) -> int:
    """``index`` if it numbers one of ``count`` control points (``0 .. count - 1``).

    >>> check_index(9, 4)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the index of the moved control point must be 0 .. 3, got 9
    """
    if not 0 <= index < count:
        raise InputError(
            f"the index of the moved control point must be 0 .. {count - 1}, got {index}", "index"
        )
    return index


def pairs(coords: Sequence[Number]) -> list[Point]:
    """Group ``x0 y0 x1 y1 ...`` into points; an odd count is an error.

    >>> pairs([0, 0, 1, 2])
    [(0, 0), (1, 2)]
    >>> pairs([0, 0, 1])
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: control points are x y pairs: got 3 numbers, an odd count
    """
    if len(coords) % 2:
        raise InputError(
            f"control points are x y pairs: got {len(coords)} numbers, an odd count", "points"
        )
    return [(normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, len(coords), 2)]
