"""Renderers: turn an answer's :class:`~scanconv.document.Document` (or the
:class:`~scanconv.core.records.Solution` it is built from) into output, without printing.

:func:`render` is the one dispatch point for ``--format``; :data:`FORMATS` declares every
format once, and each format is one mapping from the document's block types to output
(``text.PLAIN``, ``text.MARKDOWN``, ``latex.LATEX``, ``terminal.RICH``, ``html.HTML``; csv and
json in :mod:`.data`). Every renderer is a generator that
yields text chunks for stdout (each ending in a newline), :class:`Notice` objects for stderr,
and, for the ``rich`` format only, rich renderables. The CLI writes them out; nothing here
prints, and rich is imported only by the ``rich`` renderer.
"""

from collections.abc import Callable, Iterator
from enum import Enum
from typing import TYPE_CHECKING, Any, NamedTuple

from ..core import lazy
from ..core.records import Solution

if TYPE_CHECKING:
    from .. import document
    from ..document import Document
else:
    document = lazy.module("scanconv.document")  # what render needs; Format alone does not


class Format(str, Enum):
    """Output formats. ``auto`` is resolved by the CLI before :func:`render` is called."""

    auto = "auto"
    rich = "rich"
    markdown = "markdown"
    latex = "latex"
    csv = "csv"
    json = "json"
    plain = "plain"
    html = "html"


class Spec(NamedTuple):
    """What a format is, beside its renderer: one entry of :data:`FORMATS`."""

    renderer: str
    """``module:function`` in :mod:`scanconv.render`, called ``(document, options)`` and
    yielding chunks; imported on first use (start-up time)."""
    extensions: tuple[str, ...] = ()
    """The file extensions that name it (``-o answer.tex``)."""
    binding: bool = False
    """A file whose extension names it refuses a ``--format`` that says otherwise."""
    row_cost: float = 100.0
    """Microseconds a table row, for a method the measured costs do not list (the budget)."""
    matrix_cells: int | None = None
    """Most cells of a matrix answer it prints; ``None``: as many as csv and json."""
    table_rows: int | None = None
    """Most step-table rows it prints; ``None``: the budget's limit for every format."""
    document: bool = False
    """A sheet, exam book or practice set may be written in it (the budget costs a
    document's questions in the costliest such format)."""
    streams: bool = False
    """It streams at a few microseconds a cell: a budget refusal points to it."""


FORMATS: dict[Format, Spec] = {
    Format.rich: Spec("terminal:render_rich", (), False, 3000.0, 256 * 256, 10_000),
    Format.latex: Spec("latex:render_latex", (".tex",), True, 100.0, 256 * 256, document=True),
    Format.markdown: Spec(
        "text:render_markdown", (".md", ".markdown"), False, 90.0, 256 * 256, document=True
    ),
    Format.plain: Spec("text:render_plain", (".txt",), False, 60.0, 1024 * 1024, document=True),
    Format.csv: Spec("data:render_csv", (".csv",), True, 20.0, streams=True),
    Format.json: Spec("data:render_json", (".json",), True, 60.0, document=True, streams=True),
    Format.html: Spec("html:render_html", (".html", ".htm"), True, 150.0, document=True),
}
"""Every format but ``auto``, declared once: its renderer (a mapping from the document's
blocks), its file extensions and its budget. The CLI's extension map and the work budget read
this table; a new format is its :class:`Format` member, its entry here and its module."""


class Options(NamedTuple):
    """Rendering options shared by every format (a NamedTuple: cheaper to define than a
    dataclass, and start-up time counts)."""

    grid: bool = True
    """Draw the text pixel grid (if it fits, see :mod:`scanconv.render.grid`)."""
    origin: str = "bottom-left"
    """``bottom-left`` (y up, as in the notes) or ``top-left`` (screen addressing, y down)."""
    brief: bool = False
    """``rich`` only: leave the derivation (given values, working with the numbers
    substituted, notes) out. By default the terminal shows the full worked answer, as the
    document formats (markdown, latex, plain) always do."""
    exact: bool = False
    """Table cells: exact values as fractions (``34/27``) instead of 3 decimals (the rule is
    :func:`scanconv.render.cells.cell`'s). csv and json always carry the exact values."""
    width: int | None = None
    """``rich`` only: the terminal's width in columns; every line is made to fit it (wide
    tables are split, pixel lists wrapped between pairs, a grid too wide is left out with a
    hint). ``None``: 80."""


class Notice(NamedTuple):
    """A one-line message for stderr (for example why the grid was left out)."""

    message: str
    ways: tuple[str, ...] = ()
    """How else to see what was left out, by name (``"plain"``: another format, ``"svg"``: a
    figure file, ``"no-grid"``: leave it out); the CLI words them with its own flags."""


Chunk = Any  # str | Notice | a rich renderable
"""What a renderer yields."""


def render(
    solution: "Solution | Document", fmt: Format, options: Options | None = None
) -> Iterator[Chunk]:
    """Render ``solution`` (or its :class:`~scanconv.document.Document`) in ``fmt``: the single
    dispatch for every ``--format``; each format is a mapping from the document's blocks.

    >>> from scanconv.answers.line import line_solution
    >>> chunks = render(line_solution("bresenham", 0, 0, 2, 1), Format.csv)
    >>> print("".join(chunks), end="")
    k,p,decision,x,y,p_next
    0,0,NE,1,1,-2
    1,-2,E,2,1,0
    """
    options = options or Options()
    if fmt is Format.auto:
        raise ValueError("Format.auto must be resolved before rendering")
    renderer: Callable[[Document, Options], Iterator[Chunk]]
    renderer = lazy.load(f"{__name__}.{FORMATS[fmt].renderer}")
    return renderer(document.as_document(solution), options)
