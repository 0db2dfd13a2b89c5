"""The step generators as the library exports them (``scanconv.bresenham_line``,
``scanconv.midpoint_circle``, ...): the algorithms of :mod:`scanconv.algorithms`, with their
arguments read as the API reads numbers first (:func:`~scanconv._api.values._number`): numpy
integers become exact Python integers (no silent int64 overflow), NaN, infinities and values
beyond the coordinate limit are an :class:`~scanconv.core.checks.InputError` naming the
parameter, and a radius or semi-axis is checked before the first step. The generators inside
the library take integers already checked and stay unwrapped (their loops are the hot path).

>>> import numpy as np
>>> [s.p for s in midpoint_circle(np.int64(5))][:2]
[-4, -1]
>>> next(bresenham_line(0, 0, float("nan"), 1))
Traceback (most recent call last):
...
scanconv.core.checks.InputError: 'nan' is not a finite number
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..algorithms import circles, ellipses, lines
from ..algorithms.choices import Rounding, Start, Tie
from ..algorithms.circle_choices import P0, EllipseP0, Loop, Update, XStep
from ..core.checks import InputError
from ..core.records import Step
from .values import NumberLike, _number, _whole

if TYPE_CHECKING:
    from ..core.choices import (
        EllipseP0Name,
        LoopName,
        P0Name,
        RoundingName,
        StartName,
        TieName,
        UpdateName,
        XStepName,
    )


def _radius(value: NumberLike, param: str) -> int:
    r = _whole(value, param)
    if r < 0:
        raise InputError(f"{param} must be a non-negative integer, got {r}", param)
    return r


def bresenham_line(
    x1: NumberLike, y1: NumberLike, x2: NumberLike, y2: NumberLike, tie: Tie | TieName = "step",
    start: Start | StartName = "swap",
) -> Iterator[Step]:  # fmt: skip
    """Bresenham's line algorithm as a generator of steps (:func:`scanconv.algorithms.lines.bresenham`).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2 (integers), read as :func:`scanconv.line` reads them (numpy
        integers become exact Python integers; NaN, infinities and ``|v| > 10**9`` are refused).
    tie : {"step", "keep"} or Tie, default "step"
        What ``p_k = 0`` does: step the minor axis (the notes' and Hearn & Baker's ``if p < 0``),
        or keep it (the widely copied ``if p <= 0``).
    start : {"swap", "given"} or Start, default "swap"
        Walk from the end with the smaller major coordinate (the notes), or from P1 as given.

    Returns
    -------
    Iterator[Step]
        One :class:`~scanconv.core.records.Step` per unit of the major axis: ``p`` is p_k,
        ``decision`` the move, ``pixel`` is ``(x_{k+1}, y_{k+1})`` and ``extra`` is
        ``(p_{k+1},)``. The start pixel is plotted before the loop and is not a step.

    Notes
    -----
    ``p0 = 2Δminor - Δmajor``; ``p_k < 0``: keep the minor coordinate, ``p += 2Δminor``;
    otherwise step it, ``p += 2Δminor - 2Δmajor`` (Bresenham, IBM Systems Journal 4(1), 1965;
    Hearn & Baker, section 3-5).

    Examples
    --------
    >>> [(s.p, s.decision.value, s.pixel) for s in bresenham_line(0, 0, 4, 2)]
    [(0, 'NE', (1, 1)), (-4, 'E', (2, 1)), (0, 'NE', (3, 2)), (-4, 'E', (4, 2))]
    >>> [s.pixel for s in bresenham_line(0, 0, 4, 2, tie="keep")]
    [(1, 0), (2, 1), (3, 1), (4, 2)]
    """
    ends = (_whole(x1, "x1"), _whole(y1, "y1"), _whole(x2, "x2"), _whole(y2, "y2"))
    return lines.bresenham(*ends, tie, start)


def dda_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    rounding: Rounding | RoundingName = "half-up",
) -> Iterator[Step]:
    """The simple DDA as a generator of steps (:func:`scanconv.algorithms.lines.dda`).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2 (exact numbers, fractions allowed), read as :func:`scanconv.line` reads them (numpy
        integers become exact Python integers; NaN, infinities and ``|v| > 10**9`` are refused).
    rounding : {"half-up", "trunc", "half-even", "c-cast", "half-away"} or Rounding, default "half-up"
        How ``x_k`` and ``y_k`` become a pixel: ``floor(v + 1/2)``, toward zero, to even, C's
        ``(int)`` cast, or halves away from zero.

    Returns
    -------
    Iterator[Step]
        ``steps + 1`` rows (``steps = max(|Δx|, |Δy|)``), the first plotting P1 and the last P2:
        ``pixel`` is the rounded point and ``extra`` is ``(x_k, y_k, round(x_k), round(y_k))``,
        exact.

    Examples
    --------
    >>> [s.extra[:2] for s in dda_line(0, 0, 4, 2)][:3]
    [(0, 0), (1, Fraction(1, 2)), (2, 1)]
    >>> [s.pixel for s in dda_line(0, 0, 4, 2)]
    [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    >>> [s.pixel for s in dda_line(0, 0, 4, 2, rounding="trunc")]
    [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    """
    ends = (_number(x1, "x1"), _number(y1, "y1"), _number(x2, "x2"), _number(y2, "y2"))
    return lines.dda(*ends, rounding)


def basic_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    rounding: Rounding | RoundingName = "half-up",
) -> Iterator[Step]:
    """The basic (direct) line method, ``y = m x + c`` at each step of the major axis, as a
    generator of steps (:func:`scanconv.algorithms.lines.basic`).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2 (exact numbers, fractions allowed), read as :func:`scanconv.line` reads them (numpy
        integers become exact Python integers; NaN, infinities and ``|v| > 10**9`` are refused).
    rounding : {"half-up", "trunc", "half-even", "c-cast", "half-away"} or Rounding, default "half-up"
        How the exact minor coordinate becomes a pixel.

    Returns
    -------
    Iterator[Step]
        One row per major coordinate: ``extra`` is ``(major, minor_exact, minor_rounded)``.

    Examples
    --------
    >>> [s.extra for s in basic_line(0, 0, 4, 2)][:3]
    [(0, 0, 0), (1, Fraction(1, 2), 1), (2, 1, 1)]
    >>> [s.pixel for s in basic_line(0, 0, 4, 2)]
    [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    """
    ends = (_number(x1, "x1"), _number(y1, "y1"), _number(x2, "x2"), _number(y2, "y2"))
    return lines.basic(*ends, rounding)


def midpoint_circle(
    r: NumberLike,
    tie: Tie | TieName = "step",
    p0: P0 | P0Name = "1-r",
    loop: Loop | LoopName = "strict",
    update: Update | UpdateName = "new",
) -> Iterator[Step]:
    """The midpoint circle algorithm's first octant as a generator of steps
    (:func:`scanconv.algorithms.circles.midpoint`).

    Parameters
    ----------
    r : int, numpy integer or str
        The radius, a whole number >= 0, checked before the first step.
    tie : {"step", "keep"} or Tie, default "step"
        What ``p = 0`` does: step y (``if p < 0`` keeps it) or keep y.
    p0 : {"1-r", "5/4-r"} or P0, default "1-r"
        The initial decision parameter as printed: the integer ``1 - r`` or the exact ``5/4 - r``.
    loop : {"strict", "inclusive"} or Loop, default "strict"
        The octant's loop runs while ``x < y`` or while ``x <= y``.
    update : {"new", "old"} or Update, default "new"
        The increments written with the new x and y (``2x_{k+1} + 1``) or the old.

    Returns
    -------
    Iterator[Step]
        One step per unit of x from ``(0, r)``: ``p`` is p_k, ``pixel`` is ``(x_{k+1}, y_{k+1})``
        and ``extra`` is ``(2x_{k+1}, 2y_{k+1})``. The start point is not a step.

    Notes
    -----
    Hearn & Baker, section 3-9: ``p0 = 1 - r``; ``p_k < 0``: ``p += 2x_{k+1} + 1``, else y
    steps and ``p += 2x_{k+1} + 1 - 2y_{k+1}``.

    Examples
    --------
    >>> [(s.p, s.pixel) for s in midpoint_circle(5)]
    [(-4, (1, 5)), (-1, (2, 5)), (4, (3, 4)), (3, (4, 3))]
    >>> [s.p for s in midpoint_circle(5, p0="5/4-r")][:2]
    [Fraction(-15, 4), Fraction(-3, 4)]
    """
    return circles.midpoint(_radius(r, "r"), tie, p0, loop, update)


def bresenham_circle(
    r: NumberLike, tie: Tie | TieName = "step", xstep: XStep | XStepName = "last"
) -> Iterator[Step]:  # fmt: skip
    """Bresenham's circle (``d0 = 3 - 2r``) as a generator of steps
    (:func:`scanconv.algorithms.circles.bresenham`).

    Parameters
    ----------
    r : int, numpy integer or str
        The radius, a whole number >= 0, checked before the first step.
    tie : {"step", "keep"} or Tie, default "step"
        What ``d = 0`` does.
    xstep : {"last", "first"} or XStep, default "last"
        d updated before ``x += 1`` (the notes) or after it, as widely copied code does.

    Returns
    -------
    Iterator[Step]
        One step per plotted point of the octant, from ``(0, r)``: ``p`` is d_k and ``pixel`` the
        point plotted with it.

    Notes
    -----
    ``d0 = 3 - 2r``; ``d < 0``: ``d += 4x + 6``, else y steps and ``d += 4(x - y) + 10``
    (Bresenham, CACM 20(2), 1977; Foley et al., section 3.3).

    Examples
    --------
    >>> [(s.p, s.pixel) for s in bresenham_circle(5)]
    [(-7, (0, 5)), (-1, (1, 5)), (9, (2, 5)), (7, (3, 4))]
    """
    return circles.bresenham(_radius(r, "r"), tie, xstep)


def midpoint_ellipse(
    rx: NumberLike,
    ry: NumberLike,
    loop: Loop | LoopName = "strict",
    tie: Tie | TieName = "step",
    p0: EllipseP0 | EllipseP0Name = "exact",
) -> Iterator[Step]:
    """The midpoint ellipse's first quadrant, both regions, as a generator of steps
    (:func:`scanconv.algorithms.ellipses.midpoint_ellipse`).

    Parameters
    ----------
    rx, ry : int, numpy integer or str
        The semi-axes, whole numbers >= 0, checked before the first step.
    loop : {"strict", "inclusive"} or Loop, default "strict"
        Region 1 runs while ``2ry²x < 2rx²y`` or while ``<=``.
    tie : {"step", "keep"} or Tie, default "step"
        ``step``: p = 0 chooses SE in both regions; ``keep``: E in region 1, S in region 2.
    p0 : {"exact", "rounded"} or EllipseP0, default "exact"
        Each region's first decision parameter exact, or rounded as Hearn & Baker's C code.

    Returns
    -------
    Iterator[Step]
        Region 1's steps, then region 2's (k restarts at 0): ``p`` is p_k, ``decision`` the move
        (E/SE, then S/SE), ``pixel`` is ``(x_{k+1}, y_{k+1})`` and ``extra`` is
        ``(region, 2ry²x_{k+1}, 2rx²y_{k+1})``.

    Notes
    -----
    Hearn & Baker, section 3-10: ``p1_0 = ry² - rx²ry + rx²/4``,
    ``p2_0 = ry²(x0 + 1/2)² + rx²(y0 - 1)² - rx²ry²``.

    Examples
    --------
    >>> [(s.extra[0], s.p, s.decision.value, s.pixel) for s in midpoint_ellipse(3, 2)]
    [(1, Fraction(-47, 4), 'E', (1, 2)), (1, Fraction(1, 4), 'SE', (2, 1)), (1, Fraction(9, 4), 'SE', (3, 0))]
    """
    return ellipses.midpoint_ellipse(_radius(rx, "rx"), _radius(ry, "ry"), loop, tie, p0)
