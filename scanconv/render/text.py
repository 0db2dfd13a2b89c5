"""The ``markdown`` and ``plain`` formats, and the table writer they share.

Markdown: GitHub pipe tables with ``$...$`` math headings, working in ``$...$`` math, the grid
in a fenced code block. Plain: ASCII only, nothing a terminal could misread.

Tables up to :data:`BUFFER_ROWS` rows are padded into aligned columns; longer tables are
written as their rows are produced (the first rows fix the widths), so output streams in
constant memory however long the line.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from functools import partial
from itertools import islice

from ..core.numeric import fmt_pixel
from ..core.records import Column, Figure, ShadedMatrix, Solution, Table, step_getter
from ..core.working import ascii_text, visible
from ..document.numbering import marks_label
from . import Notice, Options
from . import grid as gridmod
from .cells import (
    cell,
    note_segments,
    note_unicode,
    numeric_column,
    prose_math,
    wrap_items,
)
from .shade import matrix_lines

BUFFER_ROWS = 1000
"""Tables with more rows than this are streamed instead of padded."""


def table_lines(
    headers: Sequence[str],
    right: Sequence[bool],
    rows: Iterable[Sequence[str]],
    *,
    markdown: bool,
) -> Iterator[str]:
    """Lines of a text table; padded if short, streamed if long.

    >>> print("\\n".join(table_lines(["k", "pixel"], [True, False], [["0", "(1, 2)"]], markdown=True)))
    |   k |  pixel  |
    |----:|:-------:|
    |   0 | (1, 2)  |
    >>> print("\\n".join(table_lines(["k", "pixel"], [True, False], [["0", "(1, 2)"]], markdown=False)))
    k   pixel
    -  ------
    0  (1, 2)
    """
    it = iter(rows)
    head = list(islice(it, BUFFER_ROWS + 1))
    streaming = len(head) > BUFFER_ROWS
    if markdown and not streaming:
        yield from _tabulated(headers, right, head)
        return
    widths = [len(h) for h in headers]
    for r in head:
        for i, c in enumerate(r):
            widths[i] = max(widths[i], len(c))
    if markdown:
        widths = [max(w, 3) for w in widths]

    def pad(c: str, i: int) -> str:
        if right[i]:
            return c.rjust(widths[i])
        return c.center(widths[i])

    def line(cells: Sequence[str], escape: Callable[[str], str] = md_cell) -> str:
        if markdown:
            if streaming:
                return "| " + " | ".join(escape(c) for c in cells) + " |"
            return "| " + " | ".join(pad(escape(c), i) for i, c in enumerate(cells)) + " |"
        return "  ".join(pad(c, i) for i, c in enumerate(cells)).rstrip()

    yield line(headers, _md_heading)
    if markdown:
        yield (
            "|"
            + "|".join(
                ("-" * (w + 1) + ":") if right[i] else (":" + "-" * w + ":")
                for i, w in enumerate(widths)
            )
            + "|"
        )
    else:
        yield "  ".join("-" * w for w in widths)
    for r in head:
        yield line(r)
    for r in it:
        yield line(r)


def md_cell(text: str) -> str:
    """A Markdown table cell: a blank cell (a worksheet's room to write) as it is, any other
    text through :func:`md_text`.

    >>> md_cell("   "), md_cell("a|b*"), md_cell("-3")
    ('   ', 'a\\\\|b\\\\*', '-3')
    """
    if not text.strip():
        return text
    return "".join(f"${t}$" if math else md_text(t) for math, t in prose_math(text))


def _md_heading(text: str) -> str:
    """A column heading (``$...$`` math scanconv wrote) in a Markdown table: its ``|`` escaped."""
    return text.replace("|", "\\|")


def _tabulated(
    headers: Sequence[str], right: Sequence[bool], rows: list[Sequence[str]]
) -> Iterator[str]:
    """A padded Markdown pipe table, by tabulate: numbers right-aligned, the rest centred,
    every cell kept exactly as written (``disable_numparse``: ``2.500`` stays ``2.500``).

    tabulate is imported here, not at the top: it costs about 35 ms (it imports
    ``importlib.metadata``), which only a Markdown answer pays, never the terminal or ``plain``.

    >>> print("\\n".join(_tabulated(["k", "pixel"], [True, False], [["0", "(1, 2)"]])))
    |   k |  pixel  |
    |----:|:-------:|
    |   0 | (1, 2)  |
    """
    from tabulate import tabulate

    table = tabulate(
        [[md_cell(c) for c in r] for r in rows],
        headers=[_md_heading(h) for h in headers],
        tablefmt="pipe",
        disable_numparse=True,
        colalign=["right" if r else "center" for r in right],
    )
    yield from table.splitlines()


def step_rows(
    solution: Solution, columns: Sequence[Column], exact: bool = False
) -> Iterator[list[str]]:
    """Display cells of every step, in column order."""
    get = step_getter(columns, solution.extra_keys)
    for step in solution.steps():
        yield [cell(v, c, exact) for v, c in zip(get(step), columns, strict=True)]


def table_rows(table: Table, exact: bool = False) -> Iterator[list[str]]:
    """Display cells of a secondary table."""
    for row in table.rows():
        yield [cell(v, c, exact) for v, c in zip(row, table.columns, strict=True)]


def pixel_lines(solution: Solution) -> Iterator[str]:
    """The plotted pixels, wrapped, in plotting order."""
    if solution.pixels is None:
        return iter(())
    return wrap_items(fmt_pixel(p) for p in solution.pixels())


def pixel_count(solution: Solution) -> int:
    """How many pixels are plotted (runs the generator once more; constant memory)."""
    return 0 if solution.pixels is None else sum(1 for _ in solution.pixels())


def grid_block(
    solution: Solution, options: Options, *, compact: bool = False
) -> Iterator[str | Notice]:
    """The grid lines (one-character cells with ``compact``), or a :class:`Notice` saying
    why it was left out."""
    if not options.grid or solution.pixels is None:
        return
    reason = gridmod.too_large(solution.bbox)
    if reason:
        yield Notice(reason)
        return
    yield from gridmod.render_grid(
        solution.pixels(),
        solution.bbox,
        origin=options.origin,
        marks=solution.marks,
        mark_label=marks_label(solution),
        compact=compact,
    )


def figure_lines(
    solution: Solution, options: Options, *, compact: bool = False
) -> tuple[list[str], list[Notice]]:
    """The ASCII figures under the answer (the pixel grid, a custom figure) and notices."""
    chunks = list(grid_block(solution, options, compact=compact))
    lines = [c for c in chunks if isinstance(c, str)]
    if options.grid:
        for figure in solution.figures:
            drawn = figure_text(figure, options.origin)
            if drawn and lines:
                lines.append("")
            lines.extend(drawn)
    return lines, [c for c in chunks if isinstance(c, Notice)]


def figure_text(figure: Figure, origin: str) -> list[str]:
    """The text lines of one of :attr:`Solution.figures <scanconv.core.records.Solution.figures>`."""
    if isinstance(figure, ShadedMatrix):
        return matrix_lines(figure)
    return gridmod.figure_grid(figure, origin)


Rows = Callable[[], Iterator[list[str]]]
"""A factory of display rows: a fresh iterator on every call (a renderer may read them twice)."""


def all_tables(
    solution: Solution, exact: bool = False
) -> Iterator[tuple[str | None, Sequence[Column], Rows]]:
    """``(title, columns, rows)`` of the step table (if any) and every secondary table."""
    if solution.columns and solution.show_steps:
        yield None, solution.columns, partial(step_rows, solution, solution.columns, exact)
    for table in solution.tables:
        yield table.title, table.columns, partial(table_rows, table, exact)


def _parts(
    name: str, cols: Sequence[Column], rows: Rows, *, markdown: bool
) -> Iterator[tuple[list[int], str, Iterator[list[str]]]]:
    """The parts a table is set in: one, whole, in markdown and plain alike. A table that
    belongs together (a comparison, the circle's 9-column symmetry table) stays one table,
    as the PDF sets it; pandoc and a browser wrap or scroll it (the terminal's own format,
    ``rich``, fits its width by splitting, :mod:`.terminal`)."""
    yield list(range(len(cols))), name, rows()


_MD_SPECIAL = None
_MD_LINKS = None


def md_text(text: str) -> str:
    """User text made literal in Markdown (pandoc's ``markdown`` and ``gfm``, GitHub's): the
    one Markdown escaper. Every character that could start markup, math, a table cell, an
    entity or raw HTML is backslash-escaped; the ``:`` of ``http://``, the ``.`` of
    ``www.`` and every ``@`` too, so that no autolink (GFM's bare URLs and e-mail addresses)
    can swallow the escapes after it; control characters and bidirectional overrides are
    shown as U+FFFD and line breaks as spaces (:func:`~scanconv.core.working.visible`).

    >>> print(md_text("x(t) = t**2+t**3 <b> | $1 & a@b.c"))
    x(t) = t\\*\\*2+t\\*\\*3 \\<b\\> \\| \\$1 \\& a\\@b.c
    >>> print(md_text("T http://a.b/><img src=x> www.c.d"))
    T http\\://a.b/\\>\\<img src=x\\> www\\.c.d
    """
    import re

    global _MD_SPECIAL, _MD_LINKS
    if _MD_SPECIAL is None or _MD_LINKS is None:
        _MD_SPECIAL = re.compile(r"([\\`*_{}\[\]<>#|$~^&@])")
        _MD_LINKS = re.compile(r"(?i)(?<=[a-z0-9])(:)(?=/)|(?<![a-z0-9])(www)(\.)")
    text = _MD_SPECIAL.sub(r"\\\1", visible(text))
    return _MD_LINKS.sub(lambda m: "\\:" if m.group(1) else m.group(2) + "\\.", text)


def note_md(note: str) -> str:
    """A note in Markdown: its ``$...$`` formulas kept as math, its text escaped.

    >>> print(note_md("$p_k < 0$ chooses E for <b>"))
    $p_k < 0$ chooses E for \\<b\\>
    """
    return "".join(f"${t}$" if math else md_text(t) for math, t in note_segments(note))


def render_text(solution: Solution, options: Options, *, markdown: bool) -> Iterator[str | Notice]:
    """Markdown or plain text, one line per chunk."""
    if markdown:
        yield f"## {md_text(solution.title)}\n\n"
        if solution.given:
            yield "**Given:** " + ", ".join(f"${q.tex}$" for q in solution.given) + "\n\n"
        if solution.derived:
            yield "**Working:**\n\n"
            for q in solution.derived:
                yield f"- ${q.tex}$\n"
            yield "\n"
        for i, note in enumerate(solution.notes):
            yield f"{'>' + chr(10) if i else ''}> {note_md(note)}\n"
        if solution.notes:
            yield "\n"
    else:
        heading_line = ascii_text(solution.title)
        yield f"{heading_line}\n{'=' * len(heading_line)}\n\n"
        if solution.given:
            yield "Given: " + ", ".join(ascii_text(q.text) for q in solution.given) + "\n\n"
        if solution.derived:
            yield "Working:\n"
            for q in solution.derived:
                yield f"  {ascii_text(q.text)}\n"
            yield "\n"
        if solution.notes:
            yield "Notes:\n"
            for note in solution.notes:
                yield f"  - {ascii_text(note_unicode(note))}\n"
            yield "\n"

    def heading(col: Column) -> str:
        return f"${col.tex}$" if markdown else ascii_text(col.text)

    for title, cols, rows in all_tables(solution, options.exact):
        name = title or "Step table"
        for part, label, part_rows in _parts(name, cols, rows, markdown=markdown):
            yield f"**{label}:**\n\n" if markdown else f"{ascii_text(label)}:\n"
            part_cols = [cols[i] for i in part]
            for line in table_lines(
                [heading(c) for c in part_cols],
                [numeric_column(c) for c in part_cols],
                part_rows if markdown else ([ascii_text(c) for c in r] for r in part_rows),
                markdown=markdown,
            ):
                yield line + "\n"
            yield "\n"
    if solution.pixels is not None:
        count = pixel_count(solution)
        yield f"**Pixels plotted ({count}):**\n\n" if markdown else f"Pixels plotted ({count}):\n"
        for line in pixel_lines(solution):
            yield (line if markdown else "  " + line) + "\n"
    lines, notices = figure_lines(solution, options)
    yield from notices
    if lines:
        yield "\n" + ("```text\n" if markdown else "")
        for line in lines:
            yield line + "\n"
        if markdown:
            yield "```\n"
    if markdown:
        yield "\n"  # answers appended with >> stay apart
