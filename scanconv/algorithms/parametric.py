"""Parametric curves ``(x(t), y(t))``: the formulas tabulated at equal steps of t.

:func:`parametric` is a generator of :class:`~scanconv.core.records.Step` records with ``p``
and ``decision`` ``None`` and ``(t, x(t), y(t))`` in ``extra``.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from fractions import Fraction

import numpy as np

from ..core.expr import Expr, compile_expr
from ..core.records import Step
from .curve_limits import DEFAULT_SAMPLES, Value, check_samples, norm_value
from .sampling import curve_pixel, sample_ts

CHUNK = 4096
"""Samples evaluated together (one numpy call) by :func:`parametric`."""


def evaluate(f: Expr, ts: list[Value], floats: np.ndarray) -> list[Value]:
    """``f`` at every ``t`` of a chunk: exactly where ``f`` is rational and ``t`` exact, else in
    float64 with one numpy call for the whole chunk (``floats`` holds the same ``t`` as floats).

    >>> f = compile_expr("t**2", ("t",))
    >>> evaluate(f, [Fraction(1, 2), 3], np.array([0.5, 3.0]))
    [Fraction(1, 4), 9]
    >>> evaluate(compile_expr("cos(t)", ("t",)), [0, 0], np.array([0.0, 0.0]))
    [1.0, 1.0]
    """
    if f.rational and not isinstance(ts[0], float):
        return [norm_value(f.exact(t=Fraction(t))) for t in ts]
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
    ts = sample_ts(t0, t1, check_samples(samples))
    k = 0
    while chunk := list(itertools.islice(ts, CHUNK)):  # bounded: CHUNK values of t at a time
        floats = np.array([float(t) for t in chunk])
        for t, px, py in zip(
            chunk, evaluate(fx, chunk, floats), evaluate(fy, chunk, floats), strict=True
        ):
            yield Step(k, None, None, curve_pixel(px, py), (t, px, py))
            k += 1
