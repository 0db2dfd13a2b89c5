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
from typing import Any

from ...core.numeric import fmt_pixel
from ...core.records import Column, Figure, ShadedMatrix, Solution, step_getter
from ...core.records import Table as CoreTable
from ...core.working import ascii_text, visible
from ...document import (
    Contents,
    Document,
    Drawing,
    Given,
    Notes,
    Pixels,
    Prose,
    Pseudocode,
    Question,
    StepTable,
    Table,
    Title,
    Working,
    as_document,
)
from .. import Notice, Options
from ..cells import (
    cell,
    note_segments,
    numeric_column,
    prose_math,
    segments_unicode,
    wrap_items,
)
from ..figures import grid as gridmod
from ..figures.shade import matrix_lines

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


def step_rows(table: StepTable, exact: bool = False) -> Iterator[list[str]]:
    """Display cells of every step, in column order."""
    columns = table.columns
    get = step_getter(columns, table.extra_keys)
    for step in table.steps():
        yield [cell(v, c, exact) for v, c in zip(get(step), columns, strict=True)]


def table_rows(table: Table | CoreTable, exact: bool = False) -> Iterator[list[str]]:
    """Display cells of a secondary table."""
    for row in table.rows():
        yield [cell(v, c, exact) for v, c in zip(row, table.columns, strict=True)]


def pixel_lines(pixels: Pixels) -> Iterator[str]:
    """The plotted pixels, wrapped, in plotting order."""
    return wrap_items(fmt_pixel(p) for p in pixels.pixels())


def pixel_count(pixels: Pixels) -> int:
    """How many pixels are plotted (runs the generator once more; constant memory)."""
    return sum(1 for _ in pixels.pixels())


def grid_block(
    pixels: Pixels | None, options: Options, *, compact: bool = False
) -> Iterator[str | Notice]:
    """The grid lines (one-character cells with ``compact``), or a :class:`Notice` saying
    why it was left out."""
    if not options.grid or pixels is None:
        return
    reason = gridmod.too_large(pixels.bbox)
    if reason:
        yield Notice(reason)
        return
    yield from gridmod.render_grid(
        pixels.pixels(),
        pixels.bbox,
        origin=options.origin,
        marks=pixels.marks,
        mark_label=pixels.marks_label,
        compact=compact,
    )


def figure_text(figure: Figure, origin: str) -> list[str]:
    """The text lines of a :class:`~scanconv.document.Drawing`'s figure."""
    if isinstance(figure, ShadedMatrix):
        return matrix_lines(figure)
    return gridmod.figure_grid(figure, origin)


Rows = Callable[[], Iterator[list[str]]]
"""A factory of display rows: a fresh iterator on every call (a renderer may read them twice)."""


def all_tables(
    answer: Solution | Document, exact: bool = False
) -> Iterator[tuple[str | None, Sequence[Column], Rows]]:
    """``(title, columns, rows)`` of the step table (if shown) and every further table."""
    for block in as_document(answer).blocks:
        if isinstance(block, StepTable) and block.columns and block.shown:
            yield None, block.columns, partial(step_rows, block, exact)
        elif isinstance(block, Table):
            yield block.title, block.columns, partial(table_rows, block, exact)


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


def prose_md(note: Prose) -> str:
    """A note's segments in Markdown: the math as ``$...$``, the text escaped."""
    return "".join(f"${t}$" if math else md_text(t) for math, t in note.segments)


def note_md(note: str) -> str:
    """A note in Markdown: its ``$...$`` formulas kept as math, its text escaped.

    >>> print(note_md("$p_k < 0$ chooses E for <b>"))
    $p_k < 0$ chooses E for \\<b\\>
    """
    return "".join(f"${t}$" if math else md_text(t) for math, t in note_segments(note))


Handler = Callable[[Any, Options, list[str]], Iterator[str | Notice]]
"""A format's handler of one block type: ``(block, options, drawn)``, yielding chunks; the
drawings (the grid, the figures) go into ``drawn``, set together after the last block."""


def render_text(
    answer: Solution | Document, options: Options, *, markdown: bool
) -> Iterator[str | Notice]:
    """Markdown or plain text, one line per chunk: each block by the format's mapping
    (:data:`MARKDOWN`, :data:`PLAIN`), then the drawings."""
    mapping = MARKDOWN if markdown else PLAIN
    drawn: list[str] = []
    for block in as_document(answer).blocks:
        yield from mapping[type(block)](block, options, drawn)
    if drawn:
        yield "\n" + ("```text\n" if markdown else "")
        for line in drawn:
            yield line + "\n"
        if markdown:
            yield "```\n"
    if markdown:
        yield "\n"  # answers appended with >> stay apart


def render_markdown(answer: Solution | Document, options: Options) -> Iterator[str | Notice]:
    """The ``markdown`` format (:func:`render_text`)."""
    return render_text(answer, options, markdown=True)


def render_plain(answer: Solution | Document, options: Options) -> Iterator[str | Notice]:
    """The ``plain`` format (:func:`render_text`)."""
    return render_text(answer, options, markdown=False)


def _md_title(block: Title, options: Options, drawn: list[str]) -> Iterator[str]:
    yield f"{'#' * block.level} {md_text(block.text)}\n\n"


def _md_question(block: Question, options: Options, drawn: list[str]) -> Iterator[str]:
    yield f"{'#' * block.level} {md_text(block.heading)}\n\n"
    if block.wording:
        yield f"> {md_text(block.wording)}\n\n"
    if block.command:
        yield md_code(block.command) + "\n\n"


def _md_contents(block: Contents, options: Options, drawn: list[str]) -> Iterator[str]:
    """The contents as a list: each section, its questions numbered under it."""
    lines = ["## Contents", ""]
    for section, entries in block.sections():
        lines.append(f"- {md_text(section)}")
        lines.extend(f"    {e.number}. {md_text(e.wording)}" for e in entries)
    yield "\n".join(lines) + "\n\n"


def md_code(text: str) -> str:
    """``text`` as an inline code span, fenced with more backticks than it holds.

    >>> md_code("a ` b")
    '`` a ` b ``'
    """
    import re

    runs = [len(r) for r in re.findall(r"`+", text)]
    fence = "`" * (max(runs, default=0) + 1)
    pad = " " if runs or text.startswith("`") else ""
    return f"{fence}{pad}{visible(text)}{pad}{fence}"


def _md_given(block: Given, options: Options, drawn: list[str]) -> Iterator[str]:
    yield "**Given:** " + ", ".join(f"${q.tex}$" for q in block.quantities) + "\n\n"


def _md_working(block: Working, options: Options, drawn: list[str]) -> Iterator[str]:
    yield "**Working:**\n\n"
    for q in block.lines:
        yield f"- ${q.tex}$\n"
    yield "\n"


def _md_notes(block: Notes, options: Options, drawn: list[str]) -> Iterator[str]:
    for i, note in enumerate(block.notes):
        yield f"{'>' + chr(10) if i else ''}> {prose_md(note)}\n"
    yield "\n"


def _plain_title(block: Title, options: Options, drawn: list[str]) -> Iterator[str]:
    heading_line = ascii_text(block.text)
    yield f"{heading_line}\n{'=' * len(heading_line)}\n\n"


def _plain_question(block: Question, options: Options, drawn: list[str]) -> Iterator[str]:
    head = ascii_text(block.heading)
    yield f"{head}\n{'-' * len(head)}\n\n"
    if block.wording:
        yield ascii_text(block.wording) + "\n\n"
    if block.command:
        yield f"$ {ascii_text(block.command)}\n\n"


def _plain_contents(block: Contents, options: Options, drawn: list[str]) -> Iterator[str]:
    lines = ["Contents", "--------", ""]
    for section, entries in block.sections():
        lines.append(ascii_text(section))
        lines.extend(f"  {e.number}. {ascii_text(e.wording)}" for e in entries)
    yield "\n".join(lines) + "\n\n"


def _plain_given(block: Given, options: Options, drawn: list[str]) -> Iterator[str]:
    yield "Given: " + ", ".join(ascii_text(q.text) for q in block.quantities) + "\n\n"


def _plain_working(block: Working, options: Options, drawn: list[str]) -> Iterator[str]:
    yield "Working:\n"
    for q in block.lines:
        yield f"  {ascii_text(q.text)}\n"
    yield "\n"


def _plain_notes(block: Notes, options: Options, drawn: list[str]) -> Iterator[str]:
    yield "Notes:\n"
    for note in block.notes:
        yield f"  - {ascii_text(segments_unicode(note.segments))}\n"
    yield "\n"


def _text_table(
    name: str, cols: Sequence[Column], rows: Iterator[list[str]], *, markdown: bool
) -> Iterator[str]:
    """One table, whole, in markdown or plain alike: a table that belongs together (a
    comparison, the circle's 9-column symmetry table) stays one table, as the PDF sets it;
    pandoc and a browser wrap or scroll it (``rich`` fits its width by splitting)."""
    yield f"**{md_text(name)}:**\n\n" if markdown else f"{ascii_text(name)}:\n"
    for line in table_lines(
        [f"${c.tex}$" if markdown else ascii_text(c.text) for c in cols],
        [numeric_column(c) for c in cols],
        rows if markdown else ([ascii_text(c) for c in r] for r in rows),
        markdown=markdown,
    ):
        yield line + "\n"
    yield "\n"


def _step_table(markdown: bool) -> Handler:
    def handle(block: StepTable, options: Options, drawn: list[str]) -> Iterator[str]:
        if block.columns and block.shown:
            rows = step_rows(block, options.exact)
            yield from _text_table("Step table", block.columns, rows, markdown=markdown)

    return handle


def _table(markdown: bool) -> Handler:
    def handle(block: Table, options: Options, drawn: list[str]) -> Iterator[str]:
        rows = table_rows(block, options.exact)
        yield from _text_table(block.title, block.columns, rows, markdown=markdown)

    return handle


def _pixels(markdown: bool) -> Handler:
    def handle(block: Pixels, options: Options, drawn: list[str]) -> Iterator[str | Notice]:
        count = pixel_count(block)
        yield f"**Pixels plotted ({count}):**\n\n" if markdown else f"Pixels plotted ({count}):\n"
        for line in pixel_lines(block):
            yield (line if markdown else "  " + line) + "\n"
        for c in grid_block(block, options):
            if isinstance(c, Notice):
                yield c
            else:
                drawn.append(c)

    return handle


def _md_code(block: Pseudocode, options: Options, drawn: list[str]) -> Iterator[str]:
    """The title, then the numbered lines in a fenced ``text`` code block (its fence longer
    than any run of backticks in the lines)."""
    import re

    lines = [visible(line) for line in block.numbered()]
    runs = [len(r) for line in lines for r in re.findall(r"`+", line)]
    fence = "`" * max(3, max(runs, default=0) + 1)
    yield f"**{md_text(block.title)}:**\n\n{fence}text\n"
    for line in lines:
        yield line + "\n"
    yield f"{fence}\n\n"


def _plain_code(block: Pseudocode, options: Options, drawn: list[str]) -> Iterator[str]:
    yield f"{ascii_text(block.title)}:\n"
    for line in block.numbered():
        yield f"  {ascii_text(line)}\n"
    yield "\n"


def _drawing(block: Drawing, options: Options, drawn: list[str]) -> Iterator[str]:
    if options.grid:
        lines = figure_text(block.figure, options.origin)
        if lines and drawn:
            drawn.append("")
        drawn.extend(lines)
    return iter(())


MARKDOWN: dict[type, Handler] = {
    Contents: _md_contents,
    Question: _md_question,
    Title: _md_title,
    Given: _md_given,
    Working: _md_working,
    Notes: _md_notes,
    StepTable: _step_table(True),
    Table: _table(True),
    Pseudocode: _md_code,
    Pixels: _pixels(True),
    Drawing: _drawing,
}
"""The ``markdown`` format: one handler per block type."""

PLAIN: dict[type, Handler] = {
    Contents: _plain_contents,
    Question: _plain_question,
    Title: _plain_title,
    Given: _plain_given,
    Working: _plain_working,
    Notes: _plain_notes,
    StepTable: _step_table(False),
    Table: _table(False),
    Pseudocode: _plain_code,
    Pixels: _pixels(False),
    Drawing: _drawing,
}
"""The ``plain`` format: one handler per block type."""
