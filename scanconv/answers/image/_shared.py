"""What the image answers share: integers as the working writes them, the columns of a level
matrix and the note for a shaded picture too large to draw."""

from __future__ import annotations

from ...core.records import MAX_GRID_CELLS as PICTURE_LIMIT
from ...core.records import Column, heading


def int_text(n: int) -> str:
    """``6,291,456``; numbers below 10,000 stay as they are (``1024``).

    >>> int_text(6291456), int_text(1024)
    ('6,291,456', '1024')
    """
    return f"{n:,}" if abs(n) >= 10_000 else str(n)


def int_tex(n: int) -> str:
    """``6{,}291{,}456`` (a comma in math mode without the space after it).

    >>> int_tex(6291456)
    '6{,}291{,}456'
    """
    return int_text(n).replace(",", "{,}")


def matrix_columns(n: int) -> tuple[Column, ...]:
    """Columns of a level matrix: the row index ``i``, then one per column ``j = 0 .. N-1``.

    >>> [c.key for c in matrix_columns(3)]
    ['i', '0', '1', '2']
    """
    return (heading("i", "i", role="label"), *(heading(str(j), str(j)) for j in range(n)))


def picture_note(m: int, n: int) -> str | None:
    """The note that the shaded picture of an M × N matrix is left out, or ``None``.

    >>> picture_note(8, 8) is None, picture_note(8, 101)
    (True, 'Shaded picture left out: 8 x 101 is more than 100 columns; the matrix is complete.')
    """
    if m > PICTURE_LIMIT or n > PICTURE_LIMIT:
        return (
            f"Shaded picture left out: {m} x {n} is more than {PICTURE_LIMIT} "
            f"{'columns' if n > PICTURE_LIMIT else 'rows'}; the matrix is complete."
        )
    return None
