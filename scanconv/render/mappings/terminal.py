"""The ``rich`` format, for a terminal: the full worked answer, with colour, fitted to the width.

The terminal shows what the documents show: the title, the given values, the working with
the numbers substituted, the notes, the tables, the pixels and the grid. ``--brief``
(:attr:`Options.brief`) leaves the derivation out.

Every line fits :attr:`Options.width` (80 if unset):

- a table wider than the terminal is split into parts that each repeat its first column;
- text (the working, the notes, the pixel list) is wrapped between words, never inside a
  coordinate pair ``(x, y)``;
- a grid too wide is drawn with one-character cells, and if even that does not fit it is
  left out with a notice on stderr saying how to see it.

Returns rich renderables for the CLI's console to print. Text cells are ``Text`` objects, so
pixel lists like ``[(1, 2)]`` are never read as markup or emoji.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from itertools import islice
from typing import Any

from rich import box
from rich.cells import cell_len
from rich.table import Table as RichTable
from rich.text import Text

from ...core.numeric import fmt_pixel
from ...core.records import Column, Solution
from ...core.working import visible
from ...document import (
    Contents,
    Document,
    Drawing,
    Given,
    Notes,
    Pixels,
    Pseudocode,
    Question,
    StepTable,
    Table,
    Title,
    Working,
    as_document,
)
from .. import Notice, Options
from ..cells import numeric_column, segments_unicode, unicode_heading, wrap_items
from ..figures import grid as gridmod
from .text import figure_text, grid_block, pixel_count, step_rows, table_rows

CHUNK_ROWS = 1000
"""A long table is printed as several boxed tables of this many rows each."""

DEFAULT_WIDTH = 80
"""The width when none is known."""


def table_width(widths: Sequence[int]) -> int:
    """Characters a table with columns of these content widths takes (``SIMPLE_HEAVY`` box:
    one space of padding either side of each cell, one column between cells and at each edge).

    >>> table_width([1, 6])
    14
    """
    return sum(widths) + 3 * len(widths) + 1


def column_parts(widths: Sequence[int], width: int) -> list[list[int]]:
    """Split columns into parts that each fit ``width``, every part after the first repeating
    column 0 (the step number or the point the row is about).

    >>> column_parts([2, 10, 10, 10], 40)
    [[0, 1, 2], [0, 3]]
    >>> column_parts([2, 10], 80)
    [[0, 1]]
    """
    parts: list[list[int]] = []
    current = [0]
    for i in range(1, len(widths)):
        if len(current) > 1 and table_width([widths[j] for j in [*current, i]]) > width:
            parts.append(current)
            current = [0]
        current.append(i)
    parts.append(current)
    return parts


def _words(text: str, level: int = 0) -> list[tuple[str, str]]:
    """The words of ``text`` as (the spaces before it, the word): split at the spaces inside
    at most ``level`` brackets (0: outside every bracket)."""
    words: list[tuple[str, str]] = []
    depth, start, space = 0, 0, ""
    for i, ch in enumerate(text):
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth = max(0, depth - 1)
        elif ch == " " and depth <= level:
            if i > start:
                words.append((space, text[start:i]))
                space = ""
            space += " "
            start = i + 1
    if start < len(text):
        words.append((space, text[start:]))
    return words


def _fitted(words: list[tuple[str, str]], room: int) -> list[tuple[str, str]]:
    """The words, each bracket group wider than ``room`` split at the spaces one bracket
    further in (and so on), so that a wrapped line keeps its indent: rich would otherwise
    break it at the screen's edge and start the rest at column 0 (issue 39, item 8)."""
    out: list[tuple[str, str]] = []
    for space, word in words:
        level, parts = 0, [(space, word)]
        while any(cell_len(w) > room for _, w in parts) and " " in word and level < len(word):
            level += 1
            parts = _words(word, level)
            parts[0] = (space, parts[0][1])
        out += parts
    return out


def wrap_text(text: str, width: int, indent: str = "", first: str = "") -> list[str]:
    """``first`` + ``text`` wrapped to ``width`` at spaces outside brackets, so a pair
    ``(2, 5)`` or an interval ``[0, 1]`` is never split; later lines start with ``indent``.
    A bracket group wider than the line is split at the spaces inside it, so that no line is
    wider than ``width`` unless one word is.

    >>> wrap_text("Start at (2, 2), plotted before (3, 3).", 20, "  ")
    ['Start at (2, 2),', '  plotted before', '  (3, 3).']
    >>> wrap_text("tie = step (a decision of 0 steps (if p < 0 keep it)).", 24, "    ")
    ['tie = step (a decision', '    of 0 steps', '    (if p < 0 keep it)).']
    """
    text = text.replace("' '", "'\0'")  # a quoted space (a shade's character) is one word
    words = _fitted(_words(text), max(1, width - max(cell_len(indent), cell_len(first))))
    lines: list[str] = []
    line = first
    fresh = True
    for space, word in words:
        if not fresh and cell_len(line) + len(space) + cell_len(word) > width:
            lines.append(line)
            line, fresh = indent, True
        line = line + word if fresh else f"{line}{space}{word}"
        fresh = False
    if line.strip() or not lines:
        lines.append(line)
    return [x.replace("\0", " ") for x in lines]


def render_rich(answer: Solution | Document, options: Options) -> Iterator[Any]:
    """The worked answer as rich renderables, every line at most ``options.width`` wide:
    each block by :data:`RICH`, then the drawings (the grid, the figures)."""
    width = options.width or DEFAULT_WIDTH
    drawn: list[list[str]] = []
    for block in as_document(answer).blocks:
        if options.brief and isinstance(block, Given | Working | Notes):
            continue
        yield from RICH[type(block)](block, options, width, drawn)
    for i, lines in enumerate(drawn):
        if i:
            yield Text("")
        yield from _grid_text(lines, width)
    if drawn:
        yield Text("")


def _title(block: Title, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    for line in wrap_text(visible(block.text), width, "  "):
        yield Text(line, style="bold underline")
    yield Text("")


def _question(
    block: Question, options: Options, width: int, drawn: list[list[str]]
) -> Iterator[Any]:
    yield Text(visible(block.heading), style="bold")
    for text in (block.wording, block.command):
        for line in wrap_text(visible(text), width, "  ") if text else ():
            yield Text(line)
    yield Text("")


def _contents(
    block: Contents, options: Options, width: int, drawn: list[list[str]]
) -> Iterator[Any]:
    yield Text("Contents", style="bold")
    for section, entries in block.sections():
        for line in wrap_text(visible(section), width, "  ") if section else ():
            yield Text(line, style="italic")
        for e in entries:
            for line in wrap_text(visible(f"{e.number}. {e.wording}"), width, "      ", "  "):
                yield Text(line)
    yield Text("")


def _given(block: Given, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    text = "Given: " + ", ".join(unicode_heading(q.text) for q in block.quantities)
    for i, line in enumerate(wrap_text(text, width, "  ")):
        t = Text(line)
        if i == 0:
            t.stylize("bold", 0, len("Given:"))
        yield t
    yield Text("")


def _working(block: Working, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    yield Text("Working:", style="bold")
    for q in block.lines:
        for line in wrap_text(unicode_heading(q.text), width, "      ", "  "):
            yield Text(line, style="cyan")
    yield Text("")


def _notes(block: Notes, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    yield Text("Notes:", style="bold")
    for note in block.notes:
        text = visible(unicode_heading(segments_unicode(note.segments)))
        for line in wrap_text(text, width, "    ", "  - "):
            yield Text(line)
    yield Text("")


def _step_table(
    block: StepTable, options: Options, width: int, drawn: list[list[str]]
) -> Iterator[Any]:
    if block.columns and block.shown:
        yield from _tables("Step table", block.columns, step_rows(block, options.exact), width)


def _table(block: Table, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    yield from _tables(block.title, block.columns, table_rows(block, options.exact), width)


def _code(block: Pseudocode, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    """The title, then the numbered lines (numbers dim), each indented as written; a line
    too long for ``width`` goes on under its own indentation, four spaces further in."""
    for line in wrap_text(visible(block.title) + ":", width, "  "):
        yield Text(line, style="bold")
    numbers = len(str(len(block.lines)))
    for line in block.numbered():
        number, body = line[: numbers + 2], visible(line[numbers + 2 :])
        code = body.lstrip(" ")
        first = "  " + number + body[: len(body) - len(code)]
        for i, part in enumerate(wrap_text(code, width, " " * (len(first) + 4), first)):
            text = Text(part)
            if i == 0:
                text.stylize("dim", 0, numbers + 2)
            yield text
    yield Text("")


def _pixels(block: Pixels, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    """The pixel list, then the grid (into ``drawn``) fitted to ``width`` or left out with a
    notice saying how to see it."""
    yield Text(f"Pixels plotted ({pixel_count(block)}):", style="bold")
    for line in wrap_items((fmt_pixel(p) for p in block.pixels()), width=width - 3):
        yield Text("  " + line)
    yield Text("")
    if not options.grid:
        return
    reason = gridmod.too_large(block.bbox)
    if reason:
        yield Notice(reason)
        return
    compact = gridmod.width(block.bbox) > width
    if compact and gridmod.width(block.bbox, compact=True) > width:
        yield Notice(
            f"grid left out: {gridmod.width(block.bbox, compact=True)} characters "
            f"wide, the terminal has {width}",
            ("plain", "svg", "no-grid"),
        )
        return
    drawn.append([c for c in grid_block(block, options, compact=compact) if isinstance(c, str)])


def _drawing(block: Drawing, options: Options, width: int, drawn: list[list[str]]) -> Iterator[Any]:
    """One of the answer's figures (into ``drawn``), or a notice if it is too wide."""
    lines = figure_text(block.figure, options.origin) if options.grid else []
    if not lines:
        return
    drawing = [x for x in lines if "|" in x or x.lstrip().startswith("+")]
    if max((cell_len(x) for x in drawing), default=0) > width:
        yield Notice(f"a figure is left out: wider than the terminal's {width} columns", ("plain",))
        return
    drawn.append(lines)


RICH: dict[type, Callable[[Any, Options, int, list[list[str]]], Iterator[Any]]] = {
    Contents: _contents,
    Question: _question,
    Title: _title,
    Given: _given,
    Working: _working,
    Notes: _notes,
    StepTable: _step_table,
    Table: _table,
    Pseudocode: _code,
    Pixels: _pixels,
    Drawing: _drawing,
}
"""The ``rich`` format: one handler per block type."""


def _tables(
    title: str, columns: tuple[Column, ...], rows: Iterator[list[str]], width: int
) -> Iterator[Any]:
    headers = [unicode_heading(c.text) for c in columns]
    first = True
    while True:
        chunk = list(islice(rows, CHUNK_ROWS))
        if not chunk and not first:
            return
        widths = [
            max([cell_len(h), *(cell_len(r[i]) for r in chunk)]) for i, h in enumerate(headers)
        ]
        parts = column_parts(widths, width)
        for n, part in enumerate(parts):
            if first:
                label = title if len(parts) == 1 else f"{title} (part {n + 1} of {len(parts)})"
                for line in wrap_text(label + ":", width, "  "):
                    yield Text(line, style="bold")
            t = RichTable(box=box.SIMPLE_HEAVY, show_header=first or len(parts) > 1)
            for i in part:
                t.add_column(
                    Text(headers[i], style="bold"),
                    justify="right" if numeric_column(columns[i]) else "center",
                    no_wrap=True,
                    min_width=widths[i],
                )
            for r in chunk:
                t.add_row(*(Text(r[i]) for i in part))
            yield t
        first = False
        if len(chunk) < CHUNK_ROWS:
            return


def _grid_text(lines: Iterable[str], width: int) -> Iterator[Text]:
    for line in lines:
        if "|" not in line:
            for part in [line] if cell_len(line) <= width else wrap_text(line, width):
                yield Text(part, style="dim")
        else:
            label, _, cells = line.partition("|")
            yield Text(label + "|").append_text(_cells(cells))


def _cells(cells: str) -> Text:
    t = Text()
    for ch in cells:
        style = {"#": "bold green", "o": "bold magenta", "@": "bold yellow", ".": "dim"}.get(ch)
        t.append(ch, style=style)
    return t
