"""One work budget for every answer, decided from its arguments before any work starts.

:func:`check_work` is the one check: the command line calls it for a command in its output
format, the Python API (:mod:`scanconv.display`) for an answer it is about to compute or show,
and a sheet, practice set, exam or ``check`` for each question (:func:`check_question`) and for
the whole document (:func:`document`). It estimates the answer's size from its arguments
(:mod:`scanconv.render.work`) and refuses, with an :class:`~scanconv.core.checks.InputError`
naming the parameter, the size and the limit, an answer beyond any of:

* the rows a format prints (:data:`TABLE_ROWS`: rich lays out each row) and the cells of a
  matrix (:data:`MATRIX_CELLS`);
* :data:`ALL_ROWS`, the most rows of any table in any format (the pixels of a longer line come
  from :mod:`scanconv.raster`);
* :data:`SECONDS` of CPU time: the rows times the measured cost of a row of this command,
  method and format (:data:`scanconv.render.work.COSTS`; Wu's line costs ten times
  Bresenham's, json twice csv, rich fifty times).

A document (a sheet, a practice set, an exam book) is built in memory: each question is checked
in the costliest document format and the questions' total against :data:`SHEET_ROWS` and
:data:`SHEET_SECONDS`. ``check --batch`` is bounded by :func:`check_batch`.

The messages state the rule and name formats, never a command-line flag: the caller words
the way out (:attr:`BudgetError.ways`).
"""

from __future__ import annotations

import contextlib
import contextvars
import itertools
from collections.abc import Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError
from . import FORMATS, Format
from .work import BASE_COSTS, BYTES, COSTS, Work, estimate

if TYPE_CHECKING:
    from ..algorithms import image_limits as algorithms_image_limits
    from ..core.records import Solution
    from ..marking import mark as answers_marking
    from ..marking import student_table as core_student_table
    from .html import stepper
else:  # the limits of the checks that only some answers reach, loaded by their first use
    algorithms_image_limits = lazy.module("scanconv.algorithms.image_limits")
    answers_marking = lazy.module("scanconv.marking.mark")
    core_student_table = lazy.module("scanconv.marking.student_table")
    stepper = lazy.module("scanconv.render.html.stepper")

MATRIX_CELLS: dict[Format, int] = {
    Format(f): spec.matrix_cells
    for f, spec in FORMATS.items()
    if spec.renderer and spec.matrix_cells is not None
}
"""Most cells of a matrix answer (``sample``, ``image ramp``) a format prints; csv and json
print up to :data:`~scanconv.algorithms.image_limits.MAX_CELLS`."""

TABLE_ROWS: dict[Format, int] = {
    Format(f): spec.table_rows
    for f, spec in FORMATS.items()
    if spec.renderer and spec.table_rows is not None
}
"""Most step-table rows a format prints beyond :data:`ALL_ROWS`; the others stream up to it."""

ALL_ROWS = 2_000_000
"""Most step-table rows any format prints (a bare quantizer's table in csv and json aside):
2,000,000 Bresenham rows stream in about 7 s as csv on a quiet machine; the costlier formats
and methods print fewer within :data:`SECONDS`. The pixels of a longer line or circle come
from :mod:`scanconv.raster` (numpy, milliseconds)."""

SECONDS = 40
"""Most CPU seconds of estimated work of one answer (rows times the measured row cost): with
the start-up and a loaded machine, every accepted answer ends within a minute."""

MEMORY = 500 * 10**6
"""Most bytes a format may hold at once for one answer (the html page holds its rows)."""

SHEET_ROWS = 200_000
"""Most table rows (or matrix cells) of a whole document (sheet, practice set, exam book),
which is built in memory: a json sheet holds about 2.4 KB a row (477 MB at the budget; 1.16 GB
for 500,000 rows)."""

SHEET_SECONDS = 30
"""Most CPU seconds of estimated work of a whole document, each question costed in the
costliest document format (:data:`DOCUMENT`)."""

PDF_ROWS = 3_000
"""Most table rows of a document typeset by pdflatex (``--pdf``): each row of a long table
and each cell of a pixel grid costs pdflatex about 17 ms of CPU over its passes (50 questions
of 80 rows, each with its grid: 4,000 rows, 68 s of CPU), so 3,000 rows end within a minute;
a longer document is refused before pdflatex runs."""

DOCUMENT = tuple(Format(f) for f, spec in FORMATS.items() if spec.renderer and spec.sheet)
"""The formats a document's answers are written in (a quiz file's feedback is ``plain``)."""

ROWS_IN_MEMORY = 500_000
"""Most rows :meth:`scanconv.display.Answer.rows` builds as a list of dictionaries (about
500 bytes a row)."""

LONG_TABLES = ("quantize",)
"""Costs keys whose table may pass :data:`ALL_ROWS` in csv and json: ``quantize --bits 24`` is
2^24 rows (0.5 us a row), and those rows are the answer (with ``--range`` each row carries
exact fractions: ``quantize/range`` keeps the budget of every format)."""

DEFAULT_COSTS = {f: spec.row_cost for f, spec in FORMATS.items() if spec.renderer}
"""Microseconds a row for a command/method missing from :data:`~scanconv.render.work.COSTS`."""

MIN_COST = 0.2
"""The least cost of a row, in microseconds (a table printed without its rows still costs)."""

UNLIMITED = tuple(Format(f) for f, spec in FORMATS.items() if spec.streams)
"""The formats a budget refusal points to: they stream at a few microseconds a cell."""


class BudgetError(InputError):
    """A request beyond the work budget of its output format.

    ``ways`` names the formats that would print it (``("csv", "json")``); the command line
    words them as its own options.
    """

    def __init__(self, message: str, ways: tuple[str, ...], param: str | None = None) -> None:
        super().__init__(message, param)
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


# --- the one check ------------------------------------------------------------------------------


def row_cost(work: Work, fmt: Format) -> float:
    """Microseconds of CPU for one row of ``work`` in ``fmt`` (its weight included).

    >>> from scanconv.render.work import estimate
    >>> wu, bresenham = (estimate("line", {"x1": 0, "y1": 0, "x2": 9, "y2": 1, "algo": a})
    ...                  for a in ("wu", "bresenham"))
    >>> row_cost(wu, Format.csv) > 5 * row_cost(bresenham, Format.csv)
    True
    """
    return unit_cost(work.key, fmt.value) * work.weight


def unit_cost(key: str, fmt: str) -> float:
    """Microseconds of one row (or matrix cell) of costs key ``key`` (or of its command, the
    part before ``/``) in format ``fmt``: its measured cost, else its base (csv) cost times the
    format's :attr:`~scanconv.render.Spec.row_factor`, else the format's
    :attr:`~scanconv.render.Spec.row_cost`; at least :data:`MIN_COST`.

    >>> unit_cost("matrix", "json"), unit_cost("no-such-key", "json")
    (0.3, 60.0)
    """
    if key not in COSTS and key not in BASE_COSTS:
        key = key.split("/")[0]
    us = COSTS.get(key, {}).get(fmt)
    if us is None:
        base, factor = BASE_COSTS.get(key), FORMATS[fmt].row_factor
        us = base * factor if base and factor else DEFAULT_COSTS.get(fmt, 100.0)
    return max(us, MIN_COST)


def row_limit(work: Work, fmt: Format) -> int:
    """The most rows of ``work``'s kind that ``fmt`` prints within the budget."""
    limit = min(int(SECONDS * 1e6 / row_cost(work, fmt)), _memory_limit(work, fmt))
    if not (work.key in LONG_TABLES and fmt in UNLIMITED):
        limit = min(limit, ALL_ROWS)
    return min(limit, TABLE_ROWS.get(fmt, limit))


def _memory_limit(work: Work, fmt: Format) -> int:
    """The most rows of ``work`` that ``fmt`` holds within :data:`MEMORY` (no limit: a
    number beyond any table)."""
    held = BYTES.get(work.key, {}).get(fmt.value, 0.0) * work.weight
    if held and MEMORY / held < _held_rows(fmt):
        return int(MEMORY / held)
    return 2**62


def _held_rows(fmt: Format) -> int:
    """How many rows ``fmt`` holds at most (the html page steps through at most
    :data:`~scanconv.render.html.stepper.MAX_STEPS`)."""
    return stepper.MAX_STEPS if fmt is Format.html else ALL_ROWS


def check_work(name: str, arguments: Mapping[str, Any], fmt: Format | None) -> Work | None:
    """Refuse, before any work, the answer of library function ``name`` for ``arguments``
    when it is beyond the budget of ``fmt`` (``None``: of every format); return its estimated
    :class:`~scanconv.render.work.Work` (``None``: not estimated, see
    :data:`~scanconv.render.work.BOUNDED`).

    >>> check_work("line", {"x1": 0, "y1": 0, "x2": 10**9, "y2": 1}, None)
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,000,001 rows; no format prints more than 2,000,000 (a minute of output)
    >>> check_work("line", {"x1": 0, "y1": 0, "x2": 10**6, "y2": 1, "algo": "wu"}, Format.csv)
    ... # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: the table has about 1,000,001 rows; line/wu in csv costs about ... us a row, so csv prints at most ... in 40 s
    >>> check_work("line", {"x1": 0, "y1": 0, "x2": 10**6, "y2": 1}, Format.csv).rows
    1000001
    """
    work = estimate(name, arguments)
    if work is None:
        return None
    if work.kind == "matrix":
        _check_matrix(work, fmt)
        return work
    if fmt is None:  # before anything is shown: refuse only what no format prints
        fmt = max((f for f in Format if f is not Format.auto), key=lambda f: row_limit(work, f))
    if work.rows > row_limit(work, fmt):
        _refuse_rows(work, fmt)
    return work


def _check_matrix(work: Work, fmt: Format | None) -> None:
    if fmt is None or work.size > algorithms_image_limits.MAX_CELLS:
        return  # beyond the input limit: the function refuses it, naming that limit
    try:
        check_matrix(work.rows, work.cols or 1, fmt)
    except BudgetError as err:
        raise BudgetError(str(err), err.ways, work.param) from None


def _refuse_rows(work: Work, fmt: Format) -> None:
    """The refusal of ``work`` in ``fmt``: the all-format limit, the format's own, or time."""
    try:
        check_rows(work.rows, fmt, every_format=work.key not in LONG_TABLES)
    except BudgetError as err:
        ways = err.ways if err.ways == ("raster",) else _faster(work)
        raise BudgetError(str(err), ways, work.param) from None
    limit = row_limit(work, fmt)
    if limit == _memory_limit(work, fmt):
        held = BYTES[work.key][fmt.value] * work.weight
        why = f"holds about {held:,.0f} bytes a row, so at most {limit:,} in {MEMORY // 10**6} MB"
    else:
        us = row_cost(work, fmt)
        why = (
            f"costs about {us:.0f} us a row, so {fmt.value} prints at most {limit:,} in {SECONDS} s"
        )
    raise BudgetError(
        f"the table has about {work.rows:,} rows; {work.key} in {fmt.value} {why}",
        _faster(work) or ("raster",),
        work.param,
    )


def _faster(work: Work) -> tuple[str, ...]:
    """The formats that print all of ``work`` within the budget, in the usual order."""
    order = (Format.plain, Format.markdown, Format.csv, Format.json)
    return tuple(f.value for f in order if row_limit(work, f) >= work.rows)


def check_rows_in_memory(work: Work) -> None:
    """Refuse a list of more than :data:`ROWS_IN_MEMORY` rows (``Answer.rows()``)."""
    if work.size > ROWS_IN_MEMORY:
        raise BudgetError(
            f"the table has about {work.size:,} rows; at most {ROWS_IN_MEMORY:,} are listed in "
            "memory (iterate over steps() instead)",
            (),
            work.param,
        )


# --- documents: every question, and their total -------------------------------------------------


class _Ledger:
    """The running total of a document's questions, and the most rows its outputs hold."""

    def __init__(self, outputs: Sequence[str] = ()) -> None:
        self.rows, self.seconds, self.questions = 0, 0.0, 0
        self.limit, self.holder = SHEET_ROWS, "a document"
        for name in outputs:
            most = PDF_ROWS if name == "pdf" else FORMATS[name].sheet_rows
            if most is not None and most < self.limit:
                self.limit = most
                self.holder = "a PDF (pdflatex)" if name == "pdf" else f"a {name} document"


_DOCUMENT: contextvars.ContextVar[_Ledger | None] = contextvars.ContextVar(
    "scanconv_document", default=None
)


@contextlib.contextmanager
def document(outputs: Sequence[str] = ()) -> Iterator[None]:
    """Count the questions checked by :func:`check_question` inside this block as one
    document (a sheet, a practice set, an exam book), refusing the question that takes the
    total beyond :data:`SHEET_ROWS` rows or :data:`SHEET_SECONDS` of work. ``outputs``: the
    formats the document is written in (``"pdf"``: typeset by pdflatex); the fewest rows any
    of them holds (:attr:`scanconv.render.Spec.sheet_rows`, :data:`PDF_ROWS`) is the limit.

    >>> with document(["markdown", "pdf"]):
    ...     _ = check_question("line", {"x1": 0, "y1": 0, "x2": 3999, "y2": 1})
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: with the questions before it, the document has about 4,000 table rows; a PDF (pdflatex) holds at most 3,000 (split the questions)
    """
    token = _DOCUMENT.set(_Ledger(outputs))
    try:
        yield
    finally:
        _DOCUMENT.reset(token)


def document_cost(work: Work) -> tuple[int, float]:
    """Rows (cells of a matrix) and CPU seconds of ``work`` in the costliest document format."""
    if work.kind == "matrix":
        us = max(unit_cost("matrix", f.value) for f in DOCUMENT)
    else:
        us = max(row_cost(work, f) for f in DOCUMENT)
    return work.size, work.size * us / 1e6


def check_question(name: str, arguments: Mapping[str, Any]) -> Work | None:
    """Refuse a question of a document beyond the document's budget, alone or with the
    questions before it in the same :func:`document` (its matrix also beyond the cells every
    document format prints).

    >>> with document():
    ...     for _ in range(3):
    ...         _ = check_question("line", {"x1": 0, "y1": 0, "x2": 99_999, "y2": 1})
    Traceback (most recent call last):
    ...
    scanconv.render.budget.BudgetError: with the questions before it, the document has about 300,000 table rows; a document holds at most 200,000 (split the questions)
    """
    work = estimate(name, arguments)
    if work is None:
        return None
    cells = min(MATRIX_CELLS.get(f, work.size) for f in DOCUMENT)
    if work.kind == "matrix" and work.size > cells:
        raise BudgetError(
            f"a {work.rows} x {work.cols} matrix is {work.size:,} cells; a document prints at "
            f"most {cells:,} (run it alone: answers stream)",
            (),
            work.param,
        )
    rows, seconds = document_cost(work)
    _check_total(rows, seconds, "its answer has", work, "run it alone: answers stream")
    ledger = _DOCUMENT.get()
    if ledger is not None:
        ledger.rows += rows
        ledger.seconds += seconds
        ledger.questions += 1
        what = "with the questions before it, the document has"
        limit = (ledger.limit, ledger.holder)
        _check_total(ledger.rows, ledger.seconds, what, work, "split the questions", limit)
    return work


def _check_total(
    rows: int,
    seconds: float,
    what: str,
    work: Work,
    way: str,
    limit: tuple[int, str] = (SHEET_ROWS, "a document"),
) -> None:
    most, holder = limit
    if rows > most:
        raise BudgetError(
            f"{what} about {rows:,} table rows; {holder} holds at most {most:,} ({way})",
            (),
            work.param,
        )
    if seconds > SHEET_SECONDS:
        raise BudgetError(
            f"{what} about {seconds:.0f} s of work ({work.key}: {rows:,} rows); a document "
            f"does at most {SHEET_SECONDS} s ({way})",
            (),
            work.param,
        )


# --- check --batch ------------------------------------------------------------------------------

BATCH_FILES = 1000
"""Most files one ``check --batch`` marks (a class, several times over)."""

BATCH_SECONDS = 40
"""Most CPU seconds of estimated marking of one batch."""

MARK_FILE_US = 3000.0
"""Microseconds to read and mark a file of a few rows (10,000 small files: 25 s)."""

MARK_ROW_US = 150.0
"""Microseconds a row of a student's table or of the question's, marked (all wrong, with the
diagnosis: 40 files of 5,000 rows against 9,999 question rows took 82 s)."""


def check_batch(sizes: Sequence[int], question: Solution | int) -> None:
    """Refuse a batch of files (their sizes in bytes) beyond :data:`BATCH_FILES` or
    :data:`BATCH_SECONDS` of marking against ``question`` (its Solution, whose rows are
    counted up to :data:`~scanconv.marking.limits.MAX_QUESTION_ROWS`, or that count), before
    any file is read. A file's rows are estimated from its size (a row is at least 8 bytes,
    at most :data:`~scanconv.marking.student_table.MAX_TABLE_ROWS`).

    >>> check_batch([126_000] * 40, 9_999)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the folder holds 40 files: against a question of 9,999 rows they are about 90 s of marking; a batch does at most 40 s (mark the folder in parts)
    """
    if len(sizes) > BATCH_FILES:
        raise InputError(
            f"the folder holds {len(sizes):,} files; a batch marks at most {BATCH_FILES:,} "
            "(mark the folder in parts)",
            "batch",
        )
    if isinstance(question, int):
        q = question
    else:
        q = sum(
            1 for _ in itertools.islice(question.steps(), answers_marking.MAX_QUESTION_ROWS + 1)
        )
    rows = sum(min(core_student_table.MAX_TABLE_ROWS, size // 8 + 1) + q for size in sizes)
    seconds = (len(sizes) * MARK_FILE_US + rows * MARK_ROW_US) / 1e6
    if seconds > BATCH_SECONDS:
        raise InputError(
            f"the folder holds {len(sizes):,} files: against a question of {q:,} rows they "
            f"are about {seconds:.0f} s of marking; a batch does at most {BATCH_SECONDS} s "
            "(mark the folder in parts)",
            "batch",
        )
