"""The ``latex`` format: a fragment to ``\\input`` into a document.

Needs ``\\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}`` in the preamble (the
fragment says so in its first line, then defines ``\\scneed`` if the document has not). The
table is written by hand rather than with tabulate's ``latex_booktabs``, which escapes ``$``
and ``_`` and so breaks math headings; a cell that is one of scanconv's numbers or points
(:func:`math_cell`) is set in math mode so minus signs are real minus signs, and every other
cell is escaped text (a student's file name can never reach math mode), its formulas in the
ASCII notation (``x^2``) set as math (:func:`prose_tex`).

Tables stay whole where they can: a short table (:data:`KEEP_ROWS`) is a ``tabular`` and its
heading makes room for it on the page (``\\scneed``); a longer one is a ``longtable`` that
continues on the next page with its heading repeated. A table too wide for the text width has
its long text columns wrapped (a comparison's sentences) or, when short, has its headings
set on their sides; only a long table too wide even in ``\\scriptsize`` is set in parts of
its columns, each repeating the first column. Nothing is set below ``\\scriptsize`` (7 pt),
nor scaled down: print is read on paper. Each plotted pixel is its own ``$...$``, so the pixel list
breaks between pixels, ragged-right. The pixel grid and the answer's figures are drawn with
TikZ (:mod:`scanconv.render.figures.tikz`); a figure too large to draw stays a typewriter picture.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from functools import partial
from itertools import chain, islice

from ...core.numeric import fmt_pixel
from ...core.records import Column, Solution
from ...core.working import ascii_text, tex_text
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
from ..cells import note_segments, numeric_column, prose_math, wrap_items
from ..figures.grid import too_large
from ..figures.tikz import tikz_figure, tikz_grid
from .latex_breaks import breakable_math, kept_with_grid
from .latex_fit import (
    GRID_SIZES,
    RESIZE_ROWS,
    SAMPLE_ROWS,
    TEXT_WIDTH,
    WRAP_CHARS,
    Layout,
    fold,
    grid_size,
    heading_chars,
    heading_row,
    select_columns,
    sideways_layout,
    split_columns,
    strips,
    table_layout,
)
from .text import Rows, figure_text, grid_block, pixel_count, step_rows, table_rows

MATH_TOKENS = (
    r"[-+*/(), ]",  # an operator, a bracket, a comma, a space
    r"[0-9]+(?![0-9])",  # all of a run of digits
    r"(?<=[0-9])(?<!\.[0-9])\.(?=[0-9])",  # a decimal point: 2.500, never 1.2.3 or 5.
    r"sqrt",
    r"[a-z]{1,2}(?![a-z.])",  # a one- or two-letter name, all of its run of letters
)
r"""The pieces of a math cell (:data:`_MATH_CELL`). At any place of a cell at most one of them
matches, in one way (each run of digits or letters is taken whole), so a cell is matched in
one pass whatever it holds: ``[0-9]+(?:\.[0-9]+)?`` repeated could split a run of *n* digits
in 2^(n-1) ways, and a 32-digit file name took minutes to be refused."""

_MATH_CELL = re.compile(rf"(?=[-(0-9])(?:{'|'.join(MATH_TOKENS)})+")
r"""What scanconv writes for a number, a point or an exact value: ``-3``, ``2.500``, ``34/27``,
``(3, -4)``, ``(0.500, 1.000)``, ``-1 + 3*sqrt(2)/2``, ``(xc + x, yc - y)``: digits, operators,
``sqrt`` and one- or two-letter names, starting with a digit, a minus or a bracket. Only such a
cell is set in math mode (where a ``\``, ``{``, ``^`` or ``_`` could never reach); any other
text is escaped."""


def math_cell(text: str) -> bool:
    r"""Whether a cell is a number or a point that scanconv wrote (set in math mode, its
    minus signs real minus signs); any other text, a student's file name above all, is text.

    >>> math_cell("-3"), math_cell("(0.5, 1/2)"), math_cell("(xc - y, -1 + sqrt(2))")
    (True, True, True)
    >>> math_cell("0\\input{x}.csv"), math_cell("0(abc).csv"), math_cell("0 a.csv")
    (False, False, False)
    >>> math_cell("0" * 10_000 + ".csv")  # one pass, however long the run of digits
    False
    """
    return _MATH_CELL.fullmatch(text) is not None


def _cell(text: str) -> str:
    r"""A table cell: a number or point in math mode, anything else escaped as text.

    >>> _cell("-"), _cell("-2.500"), _cell(r"0\input{^^2fetc}.csv")
    ('--', '$-2.500$', '0\\textbackslash{}input\\{\\textasciicircum{}\\textasciicircum{}2fetc\\}.csv')
    """
    if text == "-":
        return "--"
    if math_cell(text):  # a list of points breaks between them (a wrapped column's cell)
        return "$" + _BETWEEN_POINTS.sub(r")\1$ $(", text) + "$"
    return prose_tex(text)


_BETWEEN_POINTS = re.compile(r"\)(,?) \(")
"""The space between two points of a cell (``(3, 2) (1, 2)``, ``(3, 2), (1, 2)``)."""


def prose_tex(text: str) -> str:
    r"""Text in LaTeX: escaped, the formulas written in it in the ASCII notation
    (:func:`~scanconv.render.cells.prose_math`) in math mode; a ``$`` is only text.

    >>> prose_tex("Centre: x^2 + y^2 = r^2, $5")
    'Centre: $x^2$ + $y^2$ = $r^2$, \\$5'
    """
    return "".join(f"${t}$" if math else tex_text(t) for math, t in prose_math(text))


NEED = r"""\makeatletter
\providecommand{\scneed}[1]{\par\penalty-100\begingroup\setlength{\dimen@}{#1}%
\vskip\z@\@plus\dimen@\penalty-100\vskip\z@\@plus-\dimen@\vskip\dimen@
\penalty9999\vskip-\dimen@\vskip\z@skip\endgroup}
\providecommand{\scneedor}[2]{\begingroup\setlength{\dimen@}{#1}\addtolength{\dimen@}{#2}%
\ifdim\dimen@>.9\textheight\setlength{\dimen@}{#1}\fi\scneed{\the\dimen@}\endgroup}
\makeatother
"""
r"""``\scneed{h}``: a page break here unless ``h`` of the page is left (needspace's way):
a table's heading never ends a page without its table. ``\\scneedor{h}{g}``: room for
``h + g`` (a table and the grid under it) when that fits in 0.9 of the page, else for ``h``."""

KEEP_ROWS = 15
"""A table of at most this many rows starts on the next page rather than be split; a longer
one starts where it is, with at least a few rows under its heading."""


def _heading(title: str, rows: int, after: float = 0) -> str:
    r"""A table's heading, kept with its table (or its first rows).

    Set ragged right, in a group ended by its own ``\\par``: a long title (a command line
    in it) breaks at its spaces, never past the margin.

    >>> print(_heading("Step table", 2), end="")
    \scneed{71pt}{\raggedright\paragraph{Step table}\mbox{}\\[1ex]\par}
    """
    need = 45 + 13 * (rows if rows <= KEEP_ROWS else 5)
    room = f"\\scneed{{{need}pt}}"
    if rows <= KEEP_ROWS and after:  # the grid below kept with it where the page can hold both
        room = f"\\scneedor{{{need}pt}}{{{after:.0f}pt}}"
    title = tex_text(title)
    return f"{room}{{\\raggedright\\paragraph{{{title}}}\\mbox{{}}\\\\[1ex]\\par}}\n"


def _tables(title: str, columns: Sequence[Column], rows: Rows, after: float = 0) -> Iterator[str]:
    """One table, whole whenever it can be: in the largest type that fits the text width;
    with its long text columns wrapped (a comparison's sentences) rather than set smaller
    than ``\\small``; its wide headings set on their sides when it has at most
    :data:`RESIZE_ROWS` rows; only a long table too wide for the page is set in parts of its
    columns, each part repeating the first column (its headings on their sides too if a part
    fits no other way). Never shrunk below ``\\scriptsize`` (7 pt)."""
    first = rows()
    head = list(islice(first, SAMPLE_ROWS))
    parts = split_columns(columns, head)
    small = parts[0][1][0] in ("\\footnotesize", "\\scriptsize")
    wrapped = wrap_spec(columns, head) if len(parts) > 1 or small else None
    if wrapped is not None:
        yield _heading(title, len(head), after)
        yield from _tabular(columns, ("\\small", True), chain(head, first), wrapped)
        yield "\n"
        return
    side = sideways_layout(columns, head) if len(head) <= RESIZE_ROWS else None
    if side is not None and (len(parts) > 1 or table_layout(columns, head) is None):
        yield _heading(title, len(head), after)
        yield from _tabular(columns, side, chain(head, first), sideways=True)
        yield "\n"
        return
    for n, (part, layout) in enumerate(parts, 1):
        label = title if len(parts) == 1 else f"{title}, part {n} of {len(parts)}"
        yield _heading(label, len(head), after if n == len(parts) else 0)
        cols, sample = select_columns(columns, head, part)
        sideways = table_layout(cols, sample) is None  # the last resort: headings on their sides
        if len(parts) == 1:  # the whole table: the rows already started, read on
            yield from _tabular(columns, layout, chain(head, first), sideways=sideways)
        else:  # each part reads the rows afresh, keeping its own columns
            part_rows = ([r[i] for i in part] for r in rows())
            yield from _tabular(cols, layout, part_rows, sideways=sideways)
        yield "\n"


def wrap_spec(columns: Sequence[Column], rows: Sequence[list[str]]) -> str | None:
    """The column spec of a table whose long text columns wrap (``p`` columns sharing the
    width the other columns leave, at ``\\small`` with 3pt gaps), or ``None`` if no text
    column is long enough to wrap or the rest would not fit.

    >>> from scanconv.core.records import Column
    >>> cols = [Column("point", "point", ""), Column("work", "DDA", "")]
    >>> wrap_spec(cols, [["speed", "slower"]]) is None
    True
    >>> wrap_spec(cols, [["error", "round-off accumulates along the line, and more"]])
    'l>{\\\\raggedright\\\\arraybackslash}p{293.8pt}'
    """
    longest = [max((len(r[i]) for r in rows), default=0) for i in range(len(columns))]
    wrap = [  # text, or a list of points (it breaks between them)
        n > WRAP_CHARS and any(not math_cell(r[i]) or _BETWEEN_POINTS.search(r[i]) for r in rows)
        for i, n in enumerate(longest)
    ]
    if not any(wrap):
        return None
    fixed = sum(
        4.4 * max(n, heading_chars(c)) + 6
        for c, n, w in zip(columns, longest, wrap, strict=True)
        if not w
    )
    room = 0.95 * TEXT_WIDTH - fixed - 6 * sum(wrap)  # 5% to spare: the estimate is rough
    if room < 60 * sum(wrap):
        return None
    widths = _shared_room(room, columns, rows, longest, wrap)
    if widths is None:
        return None
    return "".join(
        f">{{\\raggedright\\arraybackslash}}p{{{widths[i]:.1f}pt}}"
        if w
        else ("r" if all(math_cell(r[i]) or r[i] == "-" for r in rows) else "l")
        for i, w in enumerate(wrap)
    )


def _shared_room(
    room: float,
    columns: Sequence[Column],
    rows: Sequence[list[str]],
    longest: list[int],
    wrap: list[bool],
) -> dict[int, float] | None:
    """The wrapping columns' widths: ``room`` shared in proportion to their longest text, but
    never narrower than the column's heading or longest word (the depth sort's "outcome"
    column ran past its share); ``None`` if those alone do not fit."""
    total = sum(n for n, w in zip(longest, wrap, strict=True) if w)
    share = {i: room * longest[i] / total for i, w in enumerate(wrap) if w}
    least = {
        i: 5.0
        * max([heading_chars(columns[i])] + [len(word) for r in rows for word in r[i].split()])
        for i in share
    }
    short = {i for i in share if share[i] < least[i]}
    if not short:
        return share
    left = room - sum(least[i] for i in short)
    rest = sum(longest[i] for i in share if i not in short)
    if left <= 0 or not rest:
        return None
    return {i: least[i] if i in short else left * longest[i] / rest for i in share}


def _tabular(
    columns: Sequence[Column],
    layout: Layout,
    rows: Iterable[list[str]],
    spec: str = "",
    *,
    sideways: bool = False,
) -> Iterator[str]:
    """Every row in ``rows`` in the font size and spacing of ``layout``: a ``tabular``, which
    never breaks, when there are at most :data:`KEEP_ROWS` rows (its heading has made room
    for it), else a ``longtable`` that continues on the next page with its heading. ``sideways``: headings wider than their
    cells are set on their sides (:func:`sideways_layout`)."""
    spec = spec or "".join("r" if numeric_column(c) else "c" for c in columns)
    it = iter(rows)
    head = list(islice(it, KEEP_ROWS + 1))
    short = len(head) <= KEEP_ROWS
    heading = heading_row(columns, head, sideways)
    size, tight = layout
    yield "{" + size + ("\\setlength{\\tabcolsep}{3pt}" if tight else "") + "\n"
    if short:
        yield f"\\par\\centering\\begin{{tabular}}{{{spec}}}\n\\toprule\n"
        yield heading + " \\\\\n\\midrule\n"
    else:
        yield f"\\begin{{longtable}}{{{spec}}}\n\\toprule\n"
        yield heading + " \\\\\n\\midrule\n\\endhead\n"
    for r in chain(head, it):
        yield " & ".join(_cell(c) for c in r) + " \\\\\n"
    if short:
        yield "\\bottomrule\n\\end{tabular}\\par\\medskip}\n"
    else:
        yield "\\bottomrule\n\\end{longtable}\n}\n"


def _wrap_key(line: str, width: int = GRID_SIZES[0][0]) -> list[str]:
    """A figure's key (``shades: '@' = 0 (black), ...``) wrapped between its items, so a long
    key does not cut the whole picture into strips; drawing and axis lines are kept.

    >>> _wrap_key("shades: 'a' = 0, 'b' = 1", 16)
    ["shades: 'a' = 0,", "  'b' = 1"]
    """
    if len(line) <= width or "|" in line or " = " not in line:
        return [line]
    out = list(wrap_items(line.split("; "), width=width - 2, sep="; "))
    if max(len(x) for x in out) > width - 2:
        out = list(wrap_items(line.split(", "), width=width - 2))
    return [out[0], *("  " + x for x in out[1:])]


def note_tex(note: str) -> str:
    """A note in LaTeX: its text escaped, its ``$...$`` formulas kept as math.

    >>> note_tex("$p_k < 0$ chooses E; 50% of it")
    '$p_k < 0$ chooses E; 50\\\\% of it'
    """
    return prose_tex_segments(note_segments(note))


def prose_tex_segments(segments: Iterable[tuple[bool, str]]) -> str:
    """Prose segments (a :class:`~scanconv.document.Prose`'s) in LaTeX: math as math, the
    text escaped."""
    return "".join(f"${t}$" if math else tex_text(t) for math, t in segments)


def render_latex(answer: Solution | Document, options: Options) -> Iterator[str | Notice]:
    """The worked answer as a LaTeX fragment: each block by :data:`LATEX`."""
    doc = as_document(answer)
    yield "% scanconv answer; needs \\usepackage{booktabs,amsmath,longtable,array,graphicx,tikz}\n"
    yield NEED
    kept, after = kept_with_grid(doc, options)
    for i, block in enumerate(doc.blocks):
        if i == kept:
            yield from LATEX[type(block)](block, options, doc, after)
        else:
            yield from LATEX[type(block)](block, options, doc)


def _title(block: Title, options: Options, doc: Document) -> Iterator[str]:
    unit = "subsection" if block.level <= 2 else "subsubsection"
    yield f"\\{unit}*{{\\raggedright {tex_text(block.text)}}}\n\n"  # breaks, never overfull


def _question(block: Question, options: Options, doc: Document) -> Iterator[str]:
    """A question's heading (a ``\\subsection*``: a document's sections are
    ``\\section*``), its wording and its command line."""
    yield f"\\subsection*{{{tex_text(block.heading)}}}\n"
    if block.entry:
        entry = f"{block.number}. {tex_text(block.entry)}"
        yield f"\\addcontentsline{{toc}}{{subsection}}{{{entry}}}\n"
    if block.wording:
        yield f"\\emph{{{tex_text(block.wording)}}}\\par\\medskip\n"
    if block.command:
        yield tex_command(block.command) + "\n\n"


def _contents(block: Contents, options: Options, doc: Document) -> Iterator[str]:
    """Above the questions, LaTeX's own contents with page numbers (filled in from the
    ``\\addcontentsline`` of each listed heading: pdflatex twice), then a new page; alone,
    the questions as a list."""
    if block.linked:
        yield "\\tableofcontents\n\\clearpage\n"
        return
    items = (f"  \\item {e.number}. {tex_text(e.wording)}" for e in block.entries)
    yield "\n".join(["\\section*{Contents}", "\\begin{itemize}", *items, "\\end{itemize}", ""])


def tex_command(command: str) -> str:
    r"""A command line in typewriter type, breakable at its spaces, every hyphen kept.

    >>> tex_command("scanconv sample 'x_1 % 2' --size 4")
    "{\\raggedright\\ttfamily scanconv sample 'x\\_1 \\% 2' -{}-size 4\\par}"
    """
    return "{\\raggedright\\ttfamily " + tex_text(command) + "\\par}"


def _given(block: Given, options: Options, doc: Document) -> Iterator[str]:
    """The given values in one paragraph; the words of a value (``\\text{shape: ...}``) are
    set as text, so the line can break inside them (a box of math cannot)."""
    items = ", ".join(breakable_math(q.tex) for q in block.quantities)
    if len(items) > RAGGED_GIVEN:  # many lines of boxed points: too few spaces to justify
        yield "{\\raggedright\\paragraph{Given} " + items + "\\par}\n\n"
        return
    yield "\\paragraph{Given} " + items + "\n\n"


RAGGED_GIVEN = 480
"""A given paragraph longer than this (in characters of its LaTeX: about three lines) is set
ragged right: a line of points in math has no space to stretch (``3d backface --solid cube``'s
six faces ran 3.5 pt past the margin)."""


def _working(block: Working, options: Options, doc: Document) -> Iterator[str]:
    yield "\\paragraph{Working}\n\\begin{itemize}\\raggedright\n"  # lines break, never past the edge
    for q in block.lines:
        yield f"  \\item {breakable_math(q.tex)}\n"
    yield "\\end{itemize}\n\n"


def _notes(block: Notes, options: Options, doc: Document) -> Iterator[str]:
    """The notes as a list, one bullet each (as the terminal and Markdown set them apart),
    never one paragraph after another that reads as one run of text."""
    if not block.notes:
        return
    yield "\\paragraph{Notes}\n\\begin{itemize}\\raggedright\n"
    for note in block.notes:
        yield f"  \\item {prose_tex_segments(note.segments)}\n"
    yield "\\end{itemize}\n\n"


def _step_table(
    block: StepTable, options: Options, doc: Document, after: float = 0
) -> Iterator[str]:
    if block.columns and block.shown:
        rows = partial(step_rows, block, options.exact)
        yield from _tables("Step table", block.columns, rows, after)


def _table(block: Table, options: Options, doc: Document, after: float = 0) -> Iterator[str]:
    yield from _tables(block.title, block.columns, partial(table_rows, block, options.exact), after)


def _code(block: Pseudocode, options: Options, doc: Document) -> Iterator[str]:
    r"""The listing: its heading kept with it, the numbered lines in typewriter type in a
    minipage (never split across a page), each character as it is (:func:`tt_text`), set
    small enough to fit the text width.

    >>> print("".join(_code(Pseudocode("t", ("a", "  b^2")), Options(), None)), end="")
    \scneed{71pt}{\raggedright\paragraph{t}\mbox{}\\[1ex]\par}
    <BLANKLINE>
    \noindent\begin{minipage}{\linewidth}\ttfamily
    \mbox{}1~~a\\
    \mbox{}2~~~~b{\char94}2
    \end{minipage}
    <BLANKLINE>
    """
    lines = fold(block.numbered())
    yield _heading(block.title, len(lines))
    yield "\n\\noindent\\begin{minipage}{\\linewidth}" + grid_size(lines) + "\\ttfamily\n"
    yield "\\\\\n".join("\\mbox{}" + tt_text(line) for line in lines)
    yield "\n\\end{minipage}\n\n"


_TT_SPECIAL = frozenset("\\{}$&#^_%~<>|\"'`-")


def tt_text(line: str) -> str:
    r"""A line of code in typewriter type, shown character for character: ASCII (anything
    else transliterated, :func:`~scanconv.core.working.ascii_text`), every character TeX or
    the OT1 encoding would read otherwise set as the typewriter font's own glyph
    (``\char``), every space a fixed space that does not collapse or break.

    >>> print(tt_text(r"  if p <= 0: x_k = {a}\ % 2^n"))
    ~~if~p~{\char60}=~0:~x{\char95}k~=~{\char123}a{\char125}{\char92}~{\char37}~2{\char94}n
    """
    return "".join(
        f"{{\\char{ord(c)}}}" if c in _TT_SPECIAL else "~" if c == " " else c
        for c in ascii_text(line)
    )


def _pixels(block: Pixels, options: Options, doc: Document) -> Iterator[str | Notice]:
    """The pixel list, then the grid drawn with TikZ (:mod:`scanconv.render.figures.tikz`); a grid
    too large to draw stays a typewriter picture, or is left out with a notice saying why."""
    yield f"\\paragraph{{Pixels plotted ({pixel_count(block)})}}\n"
    yield "{\\raggedright\n"
    for line in wrap_items(f"${fmt_pixel(p)}$" for p in block.pixels()):
        yield line + "\n"
    yield "\\par}\n"
    drawn = None
    if options.grid and not too_large(block.bbox):
        drawn = tikz_grid(doc, options.origin)
    if drawn is not None:
        yield drawn
        return
    chunks = list(grid_block(block, options))
    lines = [c for c in chunks if isinstance(c, str)]
    if max((len(line) for line in lines), default=0) > GRID_SIZES[-1][0]:
        lines = [c for c in grid_block(block, options, compact=True) if isinstance(c, str)]
    yield from (c for c in chunks if isinstance(c, Notice))
    yield from _verbatim(lines)


def _drawing(block: Drawing, options: Options, doc: Document) -> Iterator[str]:
    """One of the answer's own figures (a two-set pixel figure, an image's grey levels)
    drawn with TikZ; one too large to draw stays a typewriter picture."""
    if options.grid:
        picture = tikz_figure(block.figure, options.origin)
        if picture is None:
            yield from _verbatim(figure_text(block.figure, options.origin))
        else:
            yield picture


LATEX: dict[type, Callable[..., Iterator[str | Notice]]] = {
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
"""The ``latex`` format: one handler per block type, called with the block, the options and
the document (a table's handler also takes the room its grid needs below it)."""


def _verbatim(lines: Sequence[str]) -> Iterator[str]:
    """A typewriter picture in a minipage (never split across a page), set small enough to
    fit the text width."""
    lines = [part for line in lines for part in _wrap_key(line)]
    for strip in strips(lines) if lines else []:
        size = grid_size(strip)
        yield "\n\\noindent\\begin{minipage}{\\linewidth}\n" + (f"{size}\n" if size else "")
        yield "\\begin{verbatim}\n"
        for line in strip:
            yield line + "\n"
        yield "\\end{verbatim}\n\\end{minipage}\n"
