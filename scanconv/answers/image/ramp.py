"""The worked answer of the notes' grayscale example: ``i + j`` folded back at ``L - 1``, as a
table of levels and a shaded picture."""

from __future__ import annotations

from collections.abc import Iterator

from ...algorithms.ramp import ramp_size, ramp_values
from ...algorithms.storage import bits_per_pixel
from ...core.numeric import Number
from ...core.records import Plot, ShadedMatrix, Solution, Table, Walk, worked
from ._shared import matrix_columns, picture_note
from .storage import storage_quantity


def ramp_solution(m: Number, n: Number, levels: Number) -> Solution:
    """The notes' grayscale example (``i + j`` folded at ``L - 1``) as a worked answer.

    Rows are computed as they are printed (constant memory in M).

    >>> sol = ramp_solution(8, 8, 8)
    >>> print(sol.derived[1].text)
    f(i, j) = s if s ≤ L - 1, else 2(L - 1) - s = 14 - s, where s = (i + j) mod 2(L - 1) = (i + j) mod 14
    >>> next(iter(sol.tables[0].rows()))
    (0, 0, 1, 2, 3, 4, 5, 6, 7)
    """
    M, N, L = ramp_size(m, n, levels)
    P = 2 * (L - 1)
    k = bits_per_pixel(L)

    def rows() -> Iterator[tuple[int, ...]]:
        # ramp_solution(8, 8, 8) -> (0, 0 1 2 3 4 5 6 7), (1, 1 2 3 4 5 6 7 6), ...
        for i in range(M):
            yield (i, *ramp_values(i, N, L))

    bits_q = worked(
        "k",
        k,
        f"k = \\lceil \\log_2 L \\rceil = \\lceil \\log_2 {L} \\rceil = {k} \\text{{ bits per "
        f"pixel (levels 0 to {L - 1})}}",
    )
    fold = worked(
        "rule",
        None,
        f"f(i, j) = s \\text{{ if }} s \\le L - 1, \\text{{ else }} 2(L - 1) - s = {P} - s, "
        f"\\text{{ where }} s = (i + j) \\bmod 2(L - 1) = (i + j) \\bmod {P}",
    )
    note = picture_note(M, N)
    return Solution(
        primitive="image",
        algorithm="ramp",
        title=f"Grayscale ramp image: {M} x {N}, L = {L}",
        given=(
            worked("M", M, f"M = {M} \\text{{ rows}}"),
            worked("N", N, f"N = {N} \\text{{ columns}}"),
            worked("L", L, f"L = {L} \\text{{ gray levels}}"),
        ),
        derived=(bits_q, fold, storage_quantity(M, N, L)),
        notes=(
            "Row i from the top, column j from the left; 0 is black and L − 1 white.",
            *((note,) if note else ()),
        ),
        walk=Walk(tables=(Table("Gray levels f(i, j)", matrix_columns(N), rows),)),
        plot=Plot(
            figures=() if note else (ShadedMatrix(tuple(tuple(r[1:]) for r in rows()), L, N),)
        ),
    )
