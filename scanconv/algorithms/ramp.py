"""The notes' grayscale ramp: ``i + j`` folded back at ``L - 1``, for any size and L."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..core.checks import check_positive
from ..core.numeric import Number
from .image_limits import check_cells, check_levels
from .quantize import level_dtype

if TYPE_CHECKING:
    import numpy as np


def ramp_values(i: int, n: int, levels: int) -> list[int]:
    """Row ``i`` of the ramp as a list (:func:`ramp_row` without numpy, for the answer's table).

    >>> ramp_values(1, 8, 8)
    [1, 2, 3, 4, 5, 6, 7, 6]
    """
    period = 2 * (levels - 1)
    return [s if s <= levels - 1 else period - s for s in ((i + j) % period for j in range(n))]


def ramp_row(i: int, n: int, levels: int) -> np.ndarray:
    """Row ``i`` of the ramp: ``i + j`` folded back at ``L - 1``, for ``j = 0 .. n - 1``.

    >>> ramp_row(1, 8, 8).tolist()
    [1, 2, 3, 4, 5, 6, 7, 6]
    """
    import numpy as np

    period = 2 * (levels - 1)
    s = (i + np.arange(n, dtype=np.int64)) % period
    return np.where(s > levels - 1, period - s, s).astype(level_dtype(levels))


def ramp(m: Number, n: Number, levels: Number) -> np.ndarray:
    """The notes' grayscale ramp as an M × N matrix of L levels.

    Notes
    -----
    Row ``i``, column ``j`` holds ``s = (i + j) mod 2(L - 1)`` if ``s <= L - 1``, else
    ``2(L - 1) - s``: the sum ``i + j`` rises to ``L - 1`` and folds back (a triangle wave of
    period ``2(L - 1)`` along each row and column). For 8 × 8 and L = 8 this is the notes'
    example matrix exactly.

    Examples
    --------
    >>> print(ramp(8, 8, 8))
    [[0 1 2 3 4 5 6 7]
     [1 2 3 4 5 6 7 6]
     [2 3 4 5 6 7 6 5]
     [3 4 5 6 7 6 5 4]
     [4 5 6 7 6 5 4 3]
     [5 6 7 6 5 4 3 2]
     [6 7 6 5 4 3 2 1]
     [7 6 5 4 3 2 1 0]]
    """
    import numpy as np

    M, N, L = ramp_size(m, n, levels)
    out = np.empty((M, N), dtype=level_dtype(L))
    # ramp(8, 8, 8) -> row 0: 0 1 2 3 4 5 6 7 ; row 1: 1 2 3 4 5 6 7 6 ; ... row 7: 7 6 5 ... 0
    for i in range(M):
        out[i] = ramp_row(i, N, L)
    return out


def ramp_size(m: Number, n: Number, levels: Number) -> tuple[int, int, int]:
    """M, N and L of a ramp, checked (sizes, levels, then the cell limit).

    >>> ramp_size(8, 6, 4)
    (8, 6, 4)
    """
    M = check_positive(m, "M (rows)", param="m")
    N = check_positive(n, "N (columns)", param="n")
    L = check_levels(levels)
    check_cells(M, N)
    return M, N, L
