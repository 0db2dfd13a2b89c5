"""The pieces of a marking: the student's rows read as marked *steps*, and the records a
marking is made of.

A question asks for n steps; a step is the decision parameter p_k, the decision it takes and
the point (x_{k+1}, y_{k+1}) the step reaches (and p_{k+1} where the table has that column).
Every layout a method can print holds the same steps, written differently:

* the textbooks' layout: row k holds p_k, the decision and the point it reaches;
* the notes' layout: row k holds p_k, the decision and the point (x_k, y_k) it stands at, so
  step k is row k's p and decision with row k + 1's point; row 0's point is the start.

:func:`steps_of` reads a student's rows as steps in one :class:`Layout`, with or without the
start row; the start pixel, given in the question, is shown but never scored.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, NamedTuple

from ..core.decisions import same_move
from ..core.numeric import Number
from ..core.records import Pixel
from .models import State
from .student_table import Cell, StudentTable

Pair = tuple[Cell | None, Cell | None]


class Got(NamedTuple):
    """One step as the student wrote it (or one row of a table marked without a model)."""

    where: str
    """The row holding p_k and the decision (``line 4``)."""
    p: Cell | None
    decision: str | None
    point: Pair | None
    exact: Pair | None
    p_next: Cell | None
    pixel_where: str = ""
    """The row holding the point (in the notes' layout the row after :attr:`where`)."""


class Expected(NamedTuple):
    """What a step should hold, and the state its decision is taken in (for the words)."""

    point: Pixel
    p: Number | None
    decision: str | None = None
    p_next: Number | None = None
    exact: tuple[Number, Number] | None = None
    state: State | None = None
    """The state the step is taken from (the student's own point and p after a slip)."""
    rule: str = ""
    """The rule that decides at :attr:`state`: ``p >= 0 chooses NE``."""
    taken: State | None = None
    """The state the student's own move reaches (where the next step starts)."""
    prev: State | None = None
    """The state the step before was taken from (``None``: the first step, p0)."""
    ruled: State | None = None
    """The state the rule's own move reaches (the student's next p may follow from it when
    their point is a slip of the pen)."""


class Verdict(NamedTuple):
    """The mark of one step."""

    row: int
    """1-based position among the marked steps (0: the given start row, not scored)."""
    where: str
    got: Got | None
    expected: Expected | None
    mark: str
    """``right``, ``right (follow-through)``, ``wrong``, ``missing``, ``extra`` or
    ``given (not scored)``."""
    wrong: tuple[str, ...] = ()
    """The fields that are wrong: ``pixel``, ``exact``, ``p``, ``decision``, ``p_next``."""


class RowText(NamedTuple):
    """A row of a table marked by its own columns (:mod:`.marking_table`), as words:
    ``t = 2/7, type = entering``."""

    text: str


class Marking(NamedTuple):
    """A marked table."""

    verdicts: tuple[Verdict, ...]
    right: int
    total: int
    """The number of steps the question asks for, whichever layout the student used."""
    first_error: str
    diagnosis: str
    follow_through: bool
    """False: the command has no step model here, later rows are compared with the answer."""
    fields: tuple[str, ...]
    """What was marked: among ``pixel``, ``exact``, ``p``, ``decision``, ``p_next``."""
    skipped: str = ""
    """The given start row (shown, not scored)."""
    rules: str = ""
    """The marking rules in words, where they are not the pixel walk's."""


class Layout(NamedTuple):
    """How a student's rows hold the steps."""

    shape: str
    """``at`` (the notes' layout) or ``after`` (the textbooks')."""
    start: bool
    """The first row is the start row (the given start pixel)."""


LAYOUTS = (
    Layout("at", True),
    Layout("after", False),
    Layout("after", True),
    Layout("at", False),
)


# --- reading the student's rows ---------------------------------------------------------------


def _pair(cells: dict[str, Any], pair: str, x: str, y: str) -> Pair:
    if pair in cells:
        v = cells[pair]
        return (None, None) if v is None else v
    return (cells.get(x), cells.get(y))


_SOURCES = {
    "pxy": ("pxy", "px", "py"),
    "px": ("pxy", "px", "py"),
    "xy": ("xy", "x", "y"),
    "x": ("xy", "x", "y"),
}


def _one(v: Any) -> Cell | None:
    return v if isinstance(v, Cell) else None


def _sources(table: StudentTable, exact_algorithm: bool) -> tuple[str | None, str | None]:
    """Which columns hold the pixel and which the exact values (the DDA's), by field."""
    f = set(table.fields)
    rounded = "pxy" if "pxy" in f else "px" if "px" in f or "py" in f else None
    plain = "xy" if "xy" in f else "x" if "x" in f else None
    if not exact_algorithm or plain is None:
        return rounded or plain, None
    if rounded is not None:
        return rounded, plain
    fractional = any(
        c is not None and c.value.denominator != 1
        for r in table.rows
        for c in _pair(r.cells, "xy", "x", "y")
    )
    return (None, plain) if fractional else (plain, None)


def _marked(table: StudentTable, pixel_src: str | None, exact_src: str | None) -> set[str]:
    f = set(table.fields)
    marked = {"pixel"} if pixel_src else set()
    if exact_src:
        marked.add("exact")
    marked |= {name for name in ("p", "p_next") if name in f}
    if "decision" in f and any(isinstance(r.cells.get("decision"), str) for r in table.rows):
        marked.add("decision")
    return marked


def _point(cells: dict[str, Any], fields: set[str], src: str | None) -> Any:
    """A row's point from the pixel columns (``x, y, round(y)`` pairs the whole x)."""
    if src is None:
        return None
    point = _pair(cells, *_SOURCES[src])
    if point is not None and src == "px" and "px" not in fields:  # x, y, round(y)
        point = (_one(cells.get("x")), point[1])
    if point is not None and src == "px" and "py" not in fields:  # x, round(x), y
        point = (point[0], _one(cells.get("y")))
    return point


def student_rows(table: StudentTable, exact_algorithm: bool) -> tuple[list[Got], set[str]]:
    """The student's rows as :class:`Got` (one per row), and the fields that will be marked.

    A pixel column is the pixel; a column of plain coordinates is the pixel too, except for
    the DDA where it holds the exact values (next to a rounded column, or with fractions).
    A rounded y next to a whole x (``x, y, round(y)``) is the pixel with that x.
    """
    pixel_src, exact_src = _sources(table, exact_algorithm)
    fields = set(table.fields)
    rows = []
    for r in table.rows:
        c = r.cells
        decision = c.get("decision")
        rows.append(
            Got(
                r.where,
                _one(c.get("p")),
                decision if isinstance(decision, str) else None,
                _point(c, fields, pixel_src),
                _pair(c, *_SOURCES[exact_src]) if exact_src else None,
                _one(c.get("p_next")),
                r.where,
            )
        )
    return rows, _marked(table, pixel_src, exact_src)


def steps_of(rows: list[Got], lay: Layout, marked: set[str]) -> tuple[list[Got], Got | None]:
    """The student's steps in layout ``lay``, and the start row (shown, not scored)."""
    if lay.shape == "after":
        return (rows[1:], rows[0]) if lay.start and rows else (rows, None)
    next_col = "p_next" in marked

    def joined(a: Got | None, b: Got, last: bool) -> Got:
        p_next = a.p_next if (a is not None and next_col) else (b.p if last else None)
        if a is None:
            return Got(b.where, None, None, b.point, b.exact, None, b.where)
        return Got(a.where, a.p, a.decision, b.point, b.exact, p_next, b.where)

    if lay.start:
        if not rows:
            return [], None
        n = len(rows)
        return [joined(rows[i], rows[i + 1], i + 2 == n) for i in range(n - 1)], rows[0]
    n = len(rows)
    return [joined(rows[i - 1] if i else None, rows[i], i + 1 == n) for i in range(n)], None


def pixel_of(got: Got) -> Pixel | None:
    """The student's point as whole numbers (``None``: blank or not whole)."""
    if got.point is None or got.point[0] is None or got.point[1] is None:
        return None
    x, y = got.point[0].value, got.point[1].value
    if x.denominator != 1 or y.denominator != 1:
        return None
    return int(x), int(y)


def exact_of(got: Got) -> tuple[Fraction, Fraction] | None:
    if got.exact is None or got.exact[0] is None or got.exact[1] is None:
        return None
    return got.exact[0].value, got.exact[1].value


def same(c: Cell | None, v: Number | None) -> bool:
    """A student's number equals an exact value: exactly, or written to 2 or more decimals
    and within one unit of the last one (``2.333`` for 7/3, ``0.66`` for 2/3; a float's
    17 digits within 10^-12)."""
    if c is None or v is None:
        return c is None and v is None
    tolerance = Fraction(1, 10 ** min(c.places, 12))  # a float's digits: to 12 places
    return c.value == v or (c.places >= 2 and abs(c.value - v) <= tolerance)


def wrong_fields(got: Got, exp: Expected, marked: set[str], last: bool) -> tuple[str, ...]:
    """The fields of a step that differ from what it should hold (a blank p_{k+1} in the
    last step is not judged: the table may stop there)."""
    wrong = []
    if "pixel" in marked and pixel_of(got) != exp.point:
        wrong.append("pixel")
    if "exact" in marked and exp.exact is not None:
        e = got.exact or (None, None)
        if not (same(e[0], exp.exact[0]) and same(e[1], exp.exact[1])):
            wrong.append("exact")
    if "p" in marked and exp.p is not None and not same(got.p, exp.p):
        wrong.append("p")
    if (
        "decision" in marked
        and exp.decision is not None
        and not same_move(got.decision, exp.decision)
    ):
        wrong.append("decision")
    if (
        "p_next" in marked
        and exp.p_next is not None
        and not (got.p_next is None and last)
        and not same(got.p_next, exp.p_next)
    ):
        wrong.append("p_next")
    return tuple(wrong)
