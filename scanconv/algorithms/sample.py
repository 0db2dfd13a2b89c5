"""Sampling ``f(x, y)`` on an M × N grid and quantizing the samples to L levels (numpy, in
blocks of rows).

The matrix is indexed like the notes' example: row ``i`` (0 at the top), column ``j`` (0 at the
left). x runs along the columns (to the right) and y along the rows, up by default, as
everywhere in scanconv.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

from ..core.checks import InputError, check_positive
from ..core.numeric import Number, fmt, fmt_short
from .image_limits import check_cells, check_levels
from .quantize import Quantizer, level_dtype

if TYPE_CHECKING:
    import numpy as np

BLOCK_SAMPLES = 1 << 20
"""Samples of f evaluated at once (8 MiB of float64 per temporary array)."""

ORIGINS = ("bottom-left", "top-left")
"""Where row 0 of a sampled image lies: y up (the default) or y down (screen addressing)."""

Domain = tuple[Number | float, Number | float, Number | float, Number | float]
"""``(X0, X1, Y0, Y1)``: the sampled rectangle."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Sampled:
    """The result of :func:`sample_levels`."""

    levels: np.ndarray
    """The M × N matrix of levels (row 0 at the top)."""
    x: np.ndarray
    """The sample x of each column, left to right."""
    y: np.ndarray
    """The sample y of each row, top to bottom."""
    quantizer: Quantizer | None
    """The quantizer of the f range; ``None`` when f is constant (every sample level 0)."""
    f_min: float
    """The smallest sample of f."""
    f_max: float
    """The largest sample of f."""
    clipped: int
    """Samples outside a given range, clamped to level 0 or L - 1."""
    expr: str
    """The expression f(x, y) as given."""
    domain: Domain
    """``(X0, X1, Y0, Y1)`` as given (or the default)."""
    range_given: bool
    """True if the quantized range was given rather than the samples' min and max."""
    origin: str
    """``bottom-left`` (y up) or ``top-left`` (y down)."""
    L: int
    """The number of levels."""


def _shown(v: Number | float) -> str:
    """A bound in a message: a short decimal, or 3 decimals.

    >>> _shown(Fraction(7, 4)), _shown(2 / 3)
    ('1.75', '0.667')
    """
    q = Fraction(v)
    s = fmt_short(q)
    return fmt(q) if "/" in s else s


def sample_axis(lo: Number | float, hi: Number | float, count: int, name: str) -> np.ndarray:
    """``count`` equally spaced samples from ``lo`` to ``hi`` (both included), as floats.

    >>> sample_axis(0, 1, 3, "x").tolist()
    [0.0, 0.5, 1.0]
    >>> sample_axis(1, 0, 3, "x")
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the domain of x must have x0 < x1, got 1 and 0
    """
    import numpy as np

    if hi < lo or (hi == lo and count > 1):
        raise InputError(
            f"the domain of {name} must have {name}0 < {name}1, got {_shown(lo)} and {_shown(hi)}",
            "domain",
        )
    return np.linspace(float(lo), float(hi), count)


def sample_levels(
    expr: str,
    m: Number,
    n: Number,
    levels: Number,
    *,
    domain: Domain | None = None,
    value_range: tuple[Number | float, Number | float] | None = None,
    origin: str = "bottom-left",
) -> Sampled:
    """Sample ``f(x, y)`` on an M × N grid and quantize the samples to L levels.

    Notes
    -----
    ``domain = (X0, X1, Y0, Y1)`` (default ``(0, N - 1, 0, M - 1)``: one sample per pixel at
    integer coordinates). Column ``j`` samples ``x_j = X0 + j Δx`` with ``Δx = (X1 - X0)/(N - 1)``;
    row ``i`` samples ``y_i = Y1 - i Δy`` (row 0 at the top, y up) or, with
    ``origin="top-left"``, ``y_i = Y0 + i Δy`` (y down, screen addressing). f is evaluated in
    float64 by the safe evaluator :func:`scanconv.core.expr.compile_expr`, in blocks of
    :data:`BLOCK_SAMPLES` samples. The samples are quantized over ``value_range`` (default: the
    smallest and largest sample) by a real :class:`~scanconv.algorithms.quantize.Quantizer`:
    ``level = min(⌊(f - f_min) L / (f_max - f_min)⌋, L - 1)``; samples outside a given range
    are clamped. A constant f gives level 0 everywhere. The size is checked against
    :data:`~scanconv.algorithms.image_limits.MAX_CELLS` before anything is allocated.

    Examples
    --------
    >>> s = sample_levels("x + y", 4, 4, 4, origin="top-left")
    >>> print(s.levels)
    [[0 0 1 2]
     [0 1 2 2]
     [1 2 2 3]
     [2 2 3 3]]
    """
    import numpy as np

    from ..core.expr import compile_expr

    M = check_positive(m, "M (rows)", param="m")
    N = check_positive(n, "N (columns)", param="n")
    L = check_levels(levels)
    check_cells(M, N)
    if origin not in ORIGINS:
        raise InputError(f"unknown origin {origin!r} (choose from {', '.join(ORIGINS)})", "origin")
    f = compile_expr(expr, ("x", "y"))
    x0, x1, y0, y1 = domain if domain is not None else (0, N - 1, 0, M - 1)
    xs = sample_axis(x0, x1, N, "x")
    ys = sample_axis(y0, y1, M, "y")
    if origin == "bottom-left":
        ys = ys[::-1].copy()
    per_block = max(1, BLOCK_SAMPLES // N)

    def blocks() -> Iterator[tuple[int, np.ndarray]]:
        # sample "x + y" 4x4, top-left -> rows of f: 0 1 2 3 ; 1 2 3 4 ; 2 3 4 5 ; 3 4 5 6
        for start in range(0, M, per_block):
            yield start, np.asarray(f(x=xs[None, :], y=ys[start : start + per_block, None]))

    lo_f, hi_f = math.inf, -math.inf
    for _, block in blocks():
        lo_f, hi_f = min(lo_f, float(block.min())), max(hi_f, float(block.max()))
    out = np.zeros((M, N), dtype=level_dtype(L))
    if value_range is not None:
        q: Quantizer | None = Quantizer.make(*value_range, L, integer=False)
    elif hi_f > lo_f:
        q = Quantizer.make(lo_f, hi_f, L, integer=False)
    else:
        q = None
    clipped = 0
    if q is not None:
        lo, hi = float(q.lo), float(q.hi)
        for start, block in blocks():
            if value_range is not None:
                clipped += int(np.count_nonzero((block < lo) | (block > hi)))
            out[start : start + block.shape[0]] = q.levels_of(block)
    return Sampled(
        levels=out,
        x=xs,
        y=ys,
        quantizer=q,
        f_min=lo_f,
        f_max=hi_f,
        clipped=clipped,
        expr=expr,
        domain=(x0, x1, y0, y1),
        range_given=value_range is not None,
        origin=origin,
        L=L,
    )
