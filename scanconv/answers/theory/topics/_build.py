"""How a theory answer is put together: the notes' structure (definition, explanation, key
points, the notes' tables, advantages and limitations) and a live example, as one
:class:`~scanconv.core.records.Solution`, so every renderer shows it without a change.

The prose is :attr:`Solution.notes <scanconv.core.records.Solution.notes>` (each a paragraph,
formulas between ``$...$`` in TeX); lists are two-column tables (``#``, the point), short
enough to fit a page in every format; an example borrows another answer's working (as math
paragraphs), step table, secondary tables and pixels (the grid, or a titled figure).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any, NamedTuple

from ....core.records import (
    Code,
    Column,
    Figure,
    Pixel,
    PixelFigure,
    Plot,
    Solution,
    Table,
    Theory,
    Walk,
    heading,
    step_getter,
)

LONGEST_CELL = 76
"""Longest text of a list item or table cell (so a LaTeX table fits the page)."""


class Example(NamedTuple):
    """What an example adds to a theory answer."""

    notes: tuple[str, ...] = ()
    tables: tuple[Table, ...] = ()
    figures: tuple[Figure, ...] = ()
    plot: Solution | None = None
    """The solution whose pixels are the answer's own pixel list and grid."""
    code: tuple[Code, ...] = ()
    """The example's pseudocode listings, titled ``label: ...``."""


class Topic(NamedTuple):
    """One theory answer: its name (``scanconv theory NAME``), its section of the notes, the
    exam questions of the notes it answers and how to build it."""

    name: str
    section: str
    title: str
    questions: tuple[str, ...]
    build: Callable[[], Solution]


def listing(title: str, items: Sequence[str], head: str = "point") -> Table:
    """A numbered list as a table: ``#`` and the item, padded to one width (so the text
    formats keep it left-aligned).

    >>> [row for row in listing("Key points", ["a", "bcd"]).rows()]
    [(1, 'a  '), (2, 'bcd')]
    """
    width = max(len(item) for item in items)
    rows = tuple((i, item.ljust(width)) for i, item in enumerate(items, 1))
    return Table(
        title,
        (heading("k", r"\#", role="label"), heading("point", rf"\text{{{head}}}")),
        lambda: rows,
    )


def text_table(title: str, heads: Sequence[str], rows: Iterable[Sequence[Any]]) -> Table:
    """A table of words (the notes' tables): every column centred, headed in text.

    >>> text_table("t", ["Case", "Condition"], [("Case 1", "0 ≤ m ≤ 1")]).columns[1].key
    'point_1'
    """
    data = tuple(tuple(r) for r in rows)
    cols = tuple(heading(f"point_{i}", rf"\text{{{h}}}") for i, h in enumerate(heads))
    return Table(title, cols, lambda: data)


def steps_table(title: str, sol: Solution, columns: Sequence[Column] | None = None) -> Table:
    """An answer's step table, under another title."""
    cols = tuple(columns or sol.columns)
    get = step_getter(cols, sol.extra_keys)
    return Table(title, cols, lambda: (get(s) for s in sol.steps()))


def embed(
    label: str, sol: Solution, *, working: bool = True, tables: bool = True, plot: bool = True
) -> Example:
    """Another answer as the example of a theory answer: its given values and working as
    math paragraphs, its step table and tables titled ``label: ...``, its pixels as the grid
    (``plot``) or as a titled figure."""
    notes = [f"Example: {label}."]
    label = label[:1].upper() + label[1:]
    if sol.given:
        notes.append("Given: " + ", ".join(f"${q.tex}$" for q in sol.given) + ".")
    if working:
        notes.extend(f"${q.tex}$" for q in sol.derived)
    found: list[Table] = []
    code: tuple[Code, ...] = ()
    if tables:
        if sol.columns and sol.show_steps:
            found.append(steps_table(f"{label}: step table", sol))
        # read, not stepped through: no stepper over a comparison, no construction points
        found.extend(
            t._replace(title=f"{label}: {t.title}", stepped=False, points=False) for t in sol.tables
        )
        code = tuple(c._replace(title=f"{label}: {c.title}") for c in sol.code)
    figures: tuple[Figure, ...] = sol.figures
    if not plot and sol.pixels is not None:
        figures = (figure(f"{label}:", sol.pixels(), sol.bbox, sol.marks), *figures)
    return Example(tuple(notes), tuple(found), figures, sol if plot else None, code)


def figure(
    title: str,
    pixels: Iterable[Pixel],
    bbox: tuple[int, int, int, int],
    marks: Iterable[Pixel] = (),
    legend: str | None = None,
) -> PixelFigure:
    """A titled pixel figure."""
    return PixelFigure(tuple(pixels), tuple(marks), bbox, legend, title)


def answer(
    topic: str,
    title: str,
    *,
    definition: str,
    paragraphs: Sequence[str] = (),
    points: Sequence[str] = (),
    tables: Sequence[Table] = (),
    advantages: Sequence[str] = (),
    limitations: Sequence[str] = (),
    examples: Sequence[Example] = (),
    figures: Sequence[Figure] = (),
    points_title: str = "Key points",
) -> Solution:
    """The theory answer: definition first, then the explanation, the notes' lists and
    tables, then the examples."""
    notes = [f"Definition: {definition}", *paragraphs]
    found: list[Table] = []
    if points:
        found.append(listing(points_title, points))
    found.extend(tables)
    if advantages:
        found.append(listing("Advantages", advantages, "advantage"))
    if limitations:
        found.append(listing("Limitations", limitations, "limitation"))
    drawn: list[Figure] = []
    plot: Solution | None = None
    code: list[Code] = []
    for ex in examples:
        notes.extend(ex.notes)
        found.extend(ex.tables)
        code.extend(ex.code)
        drawn.extend(ex.figures)
        plot = plot or ex.plot
    return Solution(
        primitive="theory",
        algorithm=topic,
        title=title,
        given=(),
        derived=(),
        notes=tuple(notes),
        walk=Walk(tables=tuple(found)),
        plot=Plot(figures=(*drawn, *figures))
        if plot is None
        else plot.plot._replace(figures=(*drawn, *figures), construction=None),
        theory=Theory(code=tuple(code)),
        data={"topic": topic},
    )
