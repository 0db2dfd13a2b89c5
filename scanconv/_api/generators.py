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

from ..algorithms import circles, ellipses, lines
from ..core.checks import InputError
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
from ..core.records import Step
from .values import NumberLike, _number, _whole


def _radius(value: NumberLike, param: str) -> int:
    r = _whole(value, param)
    if r < 0:
        raise InputError(f"{param} must be a non-negative integer, got {r}", param)
    return r


def bresenham_line(
    x1: NumberLike, y1: NumberLike, x2: NumberLike, y2: NumberLike, tie: TieName = "step",
    start: StartName = "swap",
) -> Iterator[Step]:  # fmt: skip
    """:func:`scanconv.algorithms.lines.bresenham`, its end points checked."""
    ends = (_whole(x1, "x1"), _whole(y1, "y1"), _whole(x2, "x2"), _whole(y2, "y2"))
    return lines.bresenham(*ends, tie, start)


def dda_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    rounding: RoundingName = "half-up",
) -> Iterator[Step]:
    """:func:`scanconv.algorithms.lines.dda`, its end points read exactly."""
    ends = (_number(x1, "x1"), _number(y1, "y1"), _number(x2, "x2"), _number(y2, "y2"))
    return lines.dda(*ends, rounding)


def basic_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    rounding: RoundingName = "half-up",
) -> Iterator[Step]:
    """:func:`scanconv.algorithms.lines.basic`, its end points read exactly."""
    ends = (_number(x1, "x1"), _number(y1, "y1"), _number(x2, "x2"), _number(y2, "y2"))
    return lines.basic(*ends, rounding)


def midpoint_circle(
    r: NumberLike,
    tie: TieName = "step",
    p0: P0Name = "1-r",
    loop: LoopName = "strict",
    update: UpdateName = "new",
) -> Iterator[Step]:
    """:func:`scanconv.algorithms.circles.midpoint`, its radius checked."""
    return circles.midpoint(_radius(r, "r"), tie, p0, loop, update)


def bresenham_circle(
    r: NumberLike, tie: TieName = "step", xstep: XStepName = "last"
) -> Iterator[Step]:  # fmt: skip
    """:func:`scanconv.algorithms.circles.bresenham`, its radius checked."""
    return circles.bresenham(_radius(r, "r"), tie, xstep)


def midpoint_ellipse(
    rx: NumberLike,
    ry: NumberLike,
    loop: LoopName = "strict",
    tie: TieName = "step",
    p0: EllipseP0Name = "exact",
) -> Iterator[Step]:
    """:func:`scanconv.algorithms.ellipses.midpoint_ellipse`, its semi-axes checked."""
    return ellipses.midpoint_ellipse(_radius(rx, "rx"), _radius(ry, "ry"), loop, tie, p0)
