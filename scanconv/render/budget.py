"""Work budgets of the output formats, decided before any work starts.

Every format streams its rows, but they differ a hundredfold in what a row or a cell costs:
the ``csv`` and ``json`` writers take microseconds a cell, ``plain`` a few, ``latex`` and
``markdown`` tens (markdown lays out the whole table at once), and ``rich`` (a terminal
table, measured and laid out by rich) about a hundred. So a size that every format accepts
in a minute would be tiny; instead each format has its own budget, and a request beyond it is
refused at once, naming the formats that have no such limit (:class:`BudgetError`).

The numbers (measured on a shared 2-CPU machine, see docs/performance.md):

* a sampled 512 × 512 matrix (262,144 cells): rich 26 s, markdown 13 s, latex 9.5 s,
  plain 1.1 s, csv and json 0.6 s;
* a step table of 5,000 rows: rich 2.7 s; an ellipse's 28,285 rows: rich 56 s.

The messages state the rule and name formats, never a command-line flag: the caller words
the way out (:attr:`BudgetError.ways`).
"""

from __future__ import annotations

from ..core.checks import InputError
from . import Format

MATRIX_CELLS: dict[Format, int] = {
    Format.rich: 256 * 256,
    Format.latex: 256 * 256,
    Format.markdown: 256 * 256,
    Format.plain: 1024 * 1024,
}
"""Most cells of a matrix answer (``sample``, ``image ramp``) a format prints; csv and json
print up to :data:`~scanconv.algorithms.image_limits.MAX_CELLS`."""

TABLE_ROWS: dict[Format, int] = {Format.rich: 10_000}
"""Most step-table rows a format prints beyond :data:`ALL_ROWS`; the others stream up to it."""

ALL_ROWS = 2_000_000
"""Most step-table rows any format prints: 2,000,000 rows stream in about 7 s as csv and
35 s as json (an ellipse's wider rows) here, so every allowed table ends within a minute. The
pixels of a longer line or circle come from :mod:`scanconv.raster` (numpy, milliseconds)."""

UNLIMITED = (Format.csv, Format.json)
"""The formats a budget refusal points to: they stream at a few microseconds a cell."""


class BudgetError(InputError):
    """A request beyond the work budget of its output format.

    ``ways`` names the formats that would print it (``("csv", "json")``); the command line
    words them as its own options.
    """

    def __init__(self, message: str, ways: tuple[str, ...]) -> None:
        super().__init__(message)
        self.ways = ways


def _names(formats: list[Format]) -> str:
    """``rich, latex and markdown``.

    >>> _names([Format.rich, Format.latex, Format.markdown])
    'rich, latex and markdown'
    """
    words = [f.value for f in formats]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _ways(size: int, budgets: dict[Format, int]) -> tuple[str, ...]:
    """The formats to suggest for a request of ``size``: any whose budget holds it, then csv
    and json."""
    larger = [f for f, v in budgets.items() if v >= size]
    return tuple(f.value for f in (*larger, *UNLIMITED))


def check_matrix(m: int, n: int, fmt: Format) -> None:
    """Refuse an M × N matrix beyond the budget of ``fmt``.

    >>> check_matrix(256, 256, Format.rich), check_matrix(4096, 4096, Format.csv)
    (None, None)
    >>> check_matrix(4096, 4096, Format.rich)
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: a 4096 x 4096 matrix is 16,777,216 cells; the rich, latex and markdown formats print at most 65,536
    """
    limit = MATRIX_CELLS.get(fmt)
    if limit is None or m * n <= limit:
        return
    same = [f for f, v in MATRIX_CELLS.items() if v == limit]
    raise BudgetError(
        f"a {m} x {n} matrix is {m * n:,} cells; the {_names(same)} "
        f"format{'s' if len(same) > 1 else ''} print{'' if len(same) > 1 else 's'} at most "
        f"{limit:,}",
        _ways(m * n, MATRIX_CELLS),
    )


def check_rows(rows: int, fmt: Format, what: str = "the table", every_format: bool = True) -> None:
    """Refuse a step table of more than the budget of ``fmt`` in rows.

    >>> check_rows(10_000, Format.rich), check_rows(2_000_000, Format.csv)
    (None, None)
    >>> check_rows(10**9, Format.csv)
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,000 rows; no format prints more than 2,000,000 (a minute of output)
    >>> check_rows(1_414_215, Format.rich, "the ellipse's table")
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the ellipse's table has about 1,414,215 rows; the rich format prints at most 10,000
    """
    if every_format and rows > ALL_ROWS:
        raise BudgetError(
            f"{what} has about {rows:,} rows; no format prints more than {ALL_ROWS:,} "
            "(a minute of output)",
            ("raster",),
        )
    limit = TABLE_ROWS.get(fmt)
    if limit is None or rows <= limit:
        return
    raise BudgetError(
        f"{what} has about {rows:,} rows; the {fmt.value} format prints at most {limit:,}",
        ("plain", "markdown", *(f.value for f in UNLIMITED)),
    )
