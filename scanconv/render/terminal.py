"""The ``rich`` format, for a terminal: the answer with colour and a boxed table.

By default the terminal shows the answer: the title, the tables, the pixels and the grid.
``--explain`` (:attr:`Options.explain`) adds the derivation the documents always carry: the
given values, the working with the numbers substituted, and the notes.

Returns rich renderables for the CLI's console to print. Text cells are ``Text`` objects, so
pixel lists like ``[(1, 2)]`` are never read as markup or emoji.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import islice
from typing import Any

from rich import box
from rich.table import Table as RichTable
from rich.text import Text

from ..core.records import Column, Solution
from . import Options
from .cells import numeric_column
from .text import all_tables, figure_lines, pixel_count, pixel_lines

CHUNK_ROWS = 1000
"""A long table is printed as several boxed tables of this many rows each."""


def _tables(title: str, columns: tuple[Column, ...], rows: Iterator[list[str]]) -> Iterator[Any]:
    first = True
    while True:
        chunk = list(islice(rows, CHUNK_ROWS))
        if not chunk and not first:
            return
        t = RichTable(title=title if first else None, box=box.SIMPLE_HEAVY, show_header=first)
        for c in columns:
            t.add_column(
                Text(c.text, style="bold"), justify="right" if numeric_column(c) else "center"
            )
        for r in chunk:
            t.add_row(*(Text(x) for x in r))
        yield t
        first = False
        if len(chunk) < CHUNK_ROWS:
            return


def render_rich(solution: Solution, options: Options) -> Iterator[Any]:
    """The worked solution as rich renderables."""
    yield Text(solution.title, style="bold underline")
    yield Text("")
    if options.explain:
        yield from _derivation(solution)
    for title, cols, rows in all_tables(solution):
        yield from _tables(title or "Step table", tuple(cols), rows())
    if solution.pixels is not None:
        yield Text(f"Pixels plotted ({pixel_count(solution)}):", style="bold")
        for line in pixel_lines(solution):
            yield Text("  " + line)
    lines, notices = figure_lines(solution, options)
    yield from notices
    for line in lines:
        if "|" not in line:
            yield Text(line, style="dim")
        else:
            label, _, cells = line.partition("|")
            yield Text(label + "|").append_text(_cells(cells))
    yield Text("")


def _derivation(solution: Solution) -> Iterator[Text]:
    """What ``--explain`` adds: the given values, the working and the notes, as in markdown."""
    if solution.given:
        given = Text("Given: ", style="bold")
        given.append(", ".join(q.text for q in solution.given))
        yield given
    if solution.derived:
        yield Text("Working:", style="bold")
        for q in solution.derived:
            yield Text("  " + q.text, style="cyan")
    for note in solution.notes:
        yield Text("  " + note, style="dim")


def _cells(cells: str) -> Text:
    t = Text()
    for ch in cells:
        style = {"#": "bold green", "o": "bold magenta", "@": "bold yellow", ".": "dim"}.get(ch)
        t.append(ch, style=style)
    return t
