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
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError, check_positive
from ..core.numeric import Number, fmt, fmt_short, normalize
from .image_limits import check_cells, check_levels
from .quantize import Quantizer, level_dtype

if TYPE_CHECKING:
    from ..core import expr as core_expr
else:
    core_expr = lazy.module("scanconv.core.expr")

if TYPE_CHECKING:
    import numpy as np

BLOCK_SAMPLES = 1 << 20
"""Samples of f evaluated at once (8 MiB of float64 per temporary array)."""

EXACT_CHECK_WORK = 2 * 10**6
"""Most exact work spent on the cells whose float64 level could be wrong: cells checked ×
the size of f (:attr:`~scanconv.core.expr.Expr.size`). About 2 µs an operation: a second or two
at most. A matrix with more such cells keeps its float64 levels, and says so
(:attr:`Sampled.unchecked`)."""

RELATIVE_ERROR = 1e-9
"""How far (relative to the largest |f|) a float64 sample of f may be from the exact value;
a cell whose level could change within it is recomputed exactly. float64 carries about 16
digits, so this leaves 7 for the rounding of the formula's own operations."""

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
    f_min: Number | float
    """The smallest sample of f (exact when f and the domain are rational)."""
    f_max: Number | float
    """The largest sample of f (exact when f and the domain are rational)."""
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
    checked: int = 0
    """Cells whose float64 level lay within rounding error of a level boundary (or whose
    value was near f's minimum or maximum), recomputed exactly."""
    unchecked: int = 0
    """Cells near a boundary left in float64 because checking them exactly was beyond
    :data:`EXACT_CHECK_WORK` (0 when every level is exact or f is not rational)."""


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

    M = check_positive(m, "M (rows)", param="m")
    N = check_positive(n, "N (columns)", param="n")
    L = check_levels(levels)
    check_cells(M, N)
    if origin not in ORIGINS:
        raise InputError(f"unknown origin {origin!r} (choose from {', '.join(ORIGINS)})", "origin")
    f = core_expr.compile_expr(expr, ("x", "y"))
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
    exact = _Exact.of(f, (x0, x1, y0, y1), (M, N), origin, value_range, lo_f, hi_f)
    f_min: Number | float = lo_f
    f_max: Number | float = hi_f
    if exact is not None:
        f_min, f_max = exact.extremes(blocks(), lo_f, hi_f)
    out = np.zeros((M, N), dtype=level_dtype(L))
    if value_range is not None:
        q: Quantizer | None = Quantizer.make(*value_range, L, integer=False)
    elif f_max > f_min:
        q = Quantizer.make(f_min, f_max, L, integer=False)
    else:
        q = None
    clipped = 0
    if q is not None:
        lo, hi = float(q.lo), float(q.hi)
        for start, block in blocks():
            if value_range is not None:
                clipped += int(np.count_nonzero((block < lo) | (block > hi)))
            out[start : start + block.shape[0]] = q.levels_of(block)
            if exact is not None:
                exact.collect_near(start, block, q)
        if exact is not None:
            clipped += exact.fix_levels(out, q, value_range is not None)
    return Sampled(
        levels=out,
        x=xs,
        y=ys,
        quantizer=q,
        f_min=f_min,
        f_max=f_max,
        clipped=clipped,
        expr=expr,
        domain=(x0, x1, y0, y1),
        range_given=value_range is not None,
        origin=origin,
        L=L,
        checked=0 if exact is None else exact.checked,
        unchecked=0 if exact is None else exact.unchecked,
    )


class _Exact:
    """The exact recomputation of the cells whose float64 level is in doubt.

    f is evaluated in float64 over the whole grid (numpy, fast); where f is rational and the
    domain exact, every cell whose float value lies within :data:`RELATIVE_ERROR` of a level
    boundary, of the minimum or of the maximum is evaluated again exactly (``Expr.exact``) and
    its level taken from the exact value, so the matrix is what exact arithmetic gives, at
    the cost of a few exact evaluations (none for most formulas).
    """

    def __init__(
        self, f: Any, x0: Number, dx: Fraction, yt: Number, dy: Fraction, tol: float, cap: int
    ) -> None:
        self.f, self.x0, self.dx, self.yt, self.dy = f, x0, dx, yt, dy
        self.tol, self.cap = tol, cap
        self.near: list[tuple[np.ndarray, np.ndarray]] = []
        self.count = 0
        self.checked = 0
        self.unchecked = 0

    @classmethod
    def of(
        cls,
        f: Any,
        domain: Domain,
        shape: tuple[int, int],
        origin: str,
        value_range: tuple[Number | float, Number | float] | None,
        lo_f: float,
        hi_f: float,
    ) -> _Exact | None:
        if not f.rational or any(isinstance(v, float) for v in domain) or lo_f == hi_f:
            return None  # (a constant f has level 0 everywhere: nothing to check)
        if value_range is not None and any(isinstance(v, float) for v in value_range):
            return None
        x0, x1, y0, y1 = (Fraction(v) for v in domain)  # exact: no float among them
        M, N = shape
        dx = (x1 - x0) / (N - 1) if N > 1 else Fraction(0)
        dy = (y1 - y0) / (M - 1) if M > 1 else Fraction(0)
        yt, dy = (y0, dy) if origin == "top-left" else (y1, -dy)
        scale = max(abs(lo_f), abs(hi_f), 1.0)
        return cls(f, x0, dx, yt, dy, RELATIVE_ERROR * scale, EXACT_CHECK_WORK // f.size)

    def value(self, i: int, j: int) -> Fraction:
        v: Fraction = self.f.exact(x=self.x0 + j * self.dx, y=self.yt + i * self.dy)
        return v

    def extremes(
        self, blocks: Iterator[tuple[int, np.ndarray]], lo_f: float, hi_f: float
    ) -> tuple[Number | float, Number | float]:
        """The exact minimum and maximum of f, from the cells within tolerance of the float
        ones (the floats, if there are too many such cells)."""
        import numpy as np

        cells: list[tuple[int, int]] = []
        for start, block in blocks:
            near = np.argwhere((block <= lo_f + self.tol) | (block >= hi_f - self.tol))
            if len(cells) + len(near) > self.cap:
                self.unchecked = len(cells) + len(near)  # the levels stay float64
                return lo_f, hi_f
            cells.extend((start + int(i), int(j)) for i, j in near)
        values = [self.value(i, j) for i, j in cells]
        self.cap -= len(cells)
        self.checked = len(cells)
        return normalize(min(values)), normalize(max(values))

    def collect_near(self, start: int, block: np.ndarray, q: Quantizer) -> None:
        """Remember the cells of ``block`` within tolerance of a level boundary, with their
        float values."""
        import numpy as np

        if self.unchecked:
            return
        scale = q.levels / float(q.width)
        k = (block - float(q.lo)) * scale
        near = np.argwhere(np.abs(k - np.rint(k)) <= self.tol * scale)
        self.count += len(near)
        if self.count <= self.cap:
            values = block[near[:, 0], near[:, 1]]
            near[:, 0] += start
            self.near.append((near, values))

    def fix_levels(self, out: np.ndarray, q: Quantizer, given: bool) -> int:
        """Set the remembered cells' levels exactly; return the change in the clipped count
        (``given``: the range was given, so samples outside it are counted)."""
        near, self.near = self.near, []
        if self.unchecked or self.count > self.cap:
            self.unchecked = self.unchecked or self.count
            return 0
        lo, hi = float(q.lo), float(q.hi)
        change = 0
        for cells, values in near:
            for (i, j), v_float in zip(cells.tolist(), values.tolist(), strict=True):
                v = self.value(i, j)
                out[i, j] = q.level(v)
                if given:
                    change += int(not q.lo <= v <= q.hi) - int(not lo <= v_float <= hi)
        self.checked += self.count
        return change
