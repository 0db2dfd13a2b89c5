"""Parametric curves ``(x(t), y(t))``: the formulas tabulated at equal steps of t.

:func:`parametric` is a generator of :class:`~scanconv.core.records.Step` records with ``p``
and ``decision`` ``None`` and ``(t, x(t), y(t))`` in ``extra``.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator
from fractions import Fraction

from ..core.checks import InputError
from ..core.expr import Expr, compile_expr
from ..core.records import Step
from .curve_limits import (
    DEFAULT_SAMPLES,
    EXACT_WORK,
    MAX_CURVE_PIXELS,
    Value,
    check_samples,
    norm_value,
)
from .sampling import curve_pixel, linspace, sample_ts

CHUNK = 4096
"""Samples evaluated together by :func:`parametric`."""


def evaluate(f: Expr, ts: list[Value]) -> list[Value]:
    """``f`` at every ``t`` of a chunk: exactly where ``f`` is rational and ``t`` exact, else in
    float64 (scalar arithmetic, no numpy: :meth:`~scanconv.core.expr.Expr.__call__`).

    >>> f = compile_expr("t**2", ("t",))
    >>> evaluate(f, [Fraction(1, 2), 3])
    [Fraction(1, 4), 9]
    >>> evaluate(compile_expr("cos(t)", ("t",)), [0, 0])
    [1.0, 1.0]
    """
    if f.rational and not isinstance(ts[0], float):
        return [norm_value(f.exact(t=Fraction(t))) for t in ts]
    return [f(t=float(t)) for t in ts]


def exact_work(fx: Expr, fy: Expr, samples: int) -> int:
    """The exact evaluations a table of ``samples`` steps needs: ``(samples + 1)`` times the
    size of the rational formulas (a formula with ``cos`` is evaluated in float64 anyway).

    >>> exact_work(compile_expr("t", ("t",)), compile_expr("cos(t)", ("t",)), 9)
    10
    """
    return (samples + 1) * sum(f.size for f in (fx, fy) if f.rational)


def exact_values(fx: Expr, fy: Expr, t0: Value, t1: Value, samples: int) -> bool:
    """True if :func:`parametric` computes ``x(t)`` and ``y(t)`` exactly: both formulas are
    rational, ``t0`` and ``t1`` exact, and the work is within
    :data:`~scanconv.algorithms.curve_limits.EXACT_WORK`.

    >>> f = compile_expr("t**2 + t", ("t",))
    >>> exact_values(f, f, 0, 1, 16), exact_values(f, f, 0, 1, 10**5), exact_values(f, f, 0.0, 1, 16)
    (True, False, False)
    """
    if isinstance(t0, float) or isinstance(t1, float):
        return False
    return fx.rational and fy.rational and exact_work(fx, fy, samples) <= EXACT_WORK


def float_reason(fx: Expr, fy: Expr, t0: Value, t1: Value, samples: int) -> str:
    """Why rational formulas at exact values of t are computed in float64: ``""`` if they are
    not, or the exact work is within its budget.

    >>> f = compile_expr("t**2 + t", ("t",))
    >>> float_reason(f, f, 0, 1, 10**5)
    ' Exactly, the 100,001 values of t would take 1,000,010 evaluations, more than 1,000,000.'
    """
    if isinstance(t0, float) or isinstance(t1, float) or not (fx.rational and fy.rational):
        return ""
    work = exact_work(fx, fy, samples)
    if work <= EXACT_WORK:
        return ""
    return (
        f" Exactly, the {samples + 1:,} values of t would take {work:,} evaluations, more "
        f"than {EXACT_WORK:,}."
    )


def check_float_path(fx: Expr, fy: Expr, t0: Value, t1: Value, samples: int) -> None:
    """Refuse at once a curve whose pixel path is certainly longer than
    :data:`~scanconv.algorithms.curve_limits.MAX_CURVE_PIXELS`, from its samples in float64
    (one vectorised pass, milliseconds for 10**5 samples; one pass in Python where numpy
    is missing, as in the browser).

    A float sample's pixel is at most one off the exact one in each coordinate, so the exact
    path after ``k`` steps is at least the float path minus ``2k``; only a curve that is too long
    by that margin is refused here (the exact pass refuses the rest). A formula undefined at
    some sample is left to the exact pass too, which names the value of t.

    >>> check_float_path(compile_expr("t", ("t",)), compile_expr("0", ("t",)), 0, 10**6, 10)
    >>> check_float_path(compile_expr("t", ("t",)), compile_expr("0", ("t",)), 0, 10**7, 10)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the curve's pixel path is more than 1,000,000 pixels long (reached by t_2); use a smaller curve or t range
    """
    try:
        import numpy as np
    except ImportError:  # the browser's Python has no numpy: the same pass, one sample at a time
        _check_float_path_scalar(fx, fy, float(t0), float(t1), samples)
        return
    ts = np.linspace(float(t0), float(t1), samples + 1)
    try:
        xs, ys = (np.broadcast_to(f(t=ts), ts.shape) for f in (fx, fy))
    except ValueError:
        return
    with np.errstate(all="ignore"):
        px, py = np.floor(xs + 0.5), np.floor(ys + 0.5)
        steps = np.maximum(np.abs(np.diff(px)), np.abs(np.diff(py)))
    if not np.isfinite(steps).all():
        return
    beyond = np.cumsum(steps) - 2 * np.arange(1, samples + 1) > MAX_CURVE_PIXELS
    if beyond.any():
        _too_long(int(np.argmax(beyond)) + 1)


def _too_long(k: int) -> None:
    raise InputError(
        f"the curve's pixel path is more than {MAX_CURVE_PIXELS:,} pixels long "
        f"(reached by t_{k}); use a smaller curve or t range"
    )


def _check_float_path_scalar(fx: Expr, fy: Expr, t0: float, t1: float, samples: int) -> None:
    """:func:`check_float_path` without numpy (milliseconds become about a second at 10**5)."""
    length = 0
    previous: tuple[int, int] | None = None
    for k, t in enumerate(linspace(t0, t1, samples + 1)):
        try:
            here = (math.floor(fx(t=t) + 0.5), math.floor(fy(t=t) + 0.5))
        except (ValueError, OverflowError):
            return
        if previous is not None:
            length += max(abs(here[0] - previous[0]), abs(here[1] - previous[1]))
            if length - 2 * k > MAX_CURVE_PIXELS:
                _too_long(k)
        previous = here


def parametric(
    x: Expr | str, y: Expr | str, t0: Value, t1: Value, samples: int = DEFAULT_SAMPLES
) -> Iterator[Step]:
    """Tabulate the parametric curve ``(x(t), y(t))`` for ``t0 <= t <= t1``.

    ``x`` and ``y`` are formulas in ``t`` (see :mod:`scanconv.core.expr`). Yields ``samples + 1``
    steps with ``extra = (t, x(t), y(t))`` and the rounded point as ``pixel``.

    Notes
    -----
    ``t_k = t0 + k (t1 - t0) / samples``; rational formulas at rational ``t`` are evaluated
    exactly, anything else in float64, vectorised; so is everything when the exact work is
    beyond :data:`~scanconv.algorithms.curve_limits.EXACT_WORK` (:func:`exact_values`).
    Pixels are ``floor(v + 1/2)`` of each coordinate.

    Examples
    --------
    The notes' parabola x = t, y = t^2:

    >>> for s in parametric("t", "t**2", -1, 1, 4):
    ...     print(s.k, *(str(v) for v in s.extra), s.pixel)
    0 -1 -1 1 (-1, 1)
    1 -1/2 -1/2 1/4 (0, 0)
    2 0 0 0 (0, 0)
    3 1/2 1/2 1/4 (1, 0)
    4 1 1 1 (1, 1)
    """
    fx = x if isinstance(x, Expr) else compile_expr(x, ("t",))
    fy = y if isinstance(y, Expr) else compile_expr(y, ("t",))
    # parametric("5*cos(t)", "5*sin(t)", 0, 2*pi, 4) -> t: 0 1.571 3.142 4.712 6.283 ;
    #   pixels (5, 0) (0, 5) (-5, 0) (0, -5) (5, 0)
    check_samples(samples)
    if exact_work(fx, fy, samples) > EXACT_WORK:
        t0, t1 = float(t0), float(t1)
    ts = sample_ts(t0, t1, samples)
    k = 0
    while chunk := list(itertools.islice(ts, CHUNK)):  # bounded: CHUNK values of t at a time
        for t, px, py in zip(chunk, evaluate(fx, chunk), evaluate(fy, chunk), strict=True):
            yield Step(k, None, None, curve_pixel(px, py), (t, px, py))
            k += 1
