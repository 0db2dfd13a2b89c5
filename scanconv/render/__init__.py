"""Renderers: turn an answer's :class:`~scanconv.document.Document` (or the
:class:`~scanconv.core.records.Solution` it is built from) into output, without printing.

:data:`FORMATS` declares every format once, single answers and documents (sheets, the exam
book, practice sets, quiz files) alike. :func:`render` is the one dispatch point for a single
answer's ``--format`` (:func:`scanconv.render.documents.sheet.sheet_document` for a document's), and each
format is one mapping from the document's block types to output (``text.PLAIN``,
``text.MARKDOWN``, ``latex.LATEX``, ``terminal.RICH``, ``html.HTML``; csv and json in
:mod:`.data`). Every renderer is a generator that
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
    """The formats of a single answer: ``auto`` and every :data:`FORMATS` entry with a
    renderer (a test holds the two together). ``auto`` is resolved by the CLI before
    :func:`render` is called."""

    auto = "auto"
    rich = "rich"
    markdown = "markdown"
    latex = "latex"
    csv = "csv"
    json = "json"
    plain = "plain"
    html = "html"


class Spec(NamedTuple):
    """What a format is and what it writes: one entry of :data:`FORMATS`."""

    renderer: str = ""
    """``module:function`` in :mod:`scanconv.render` writing a single answer, called
    ``(document, options)`` and yielding chunks; imported on first use (start-up time).
    ``""``: it writes no single answer (a quiz file)."""
    extensions: tuple[str, ...] = ()
    """The file extensions that name it (``-o answer.tex``), for every command."""
    binding: bool = False
    """A file whose extension names it refuses a ``--format`` that says otherwise (every
    command: answers and documents alike)."""
    row_cost: float = 100.0
    """Microseconds a table row, for a command with no cost of its own (the budget)."""
    matrix_cells: int | None = None
    """Most cells of a matrix answer it prints; ``None``: as many as csv and json."""
    table_rows: int | None = None
    """Most step-table rows it prints; ``None``: the budget's limit for every format."""
    sheet: str = ""
    """``module:function`` in :mod:`scanconv.render` writing a whole document (a sheet, the
    exam book, a practice set), called ``(sheet, answered, kind, standalone)`` and yielding
    text and :class:`Notice` chunks (:func:`scanconv.render.documents.sheet.sheet_document`); each
    answer in it goes through a single-answer mapping. ``""``: no documents in it."""
    streams: bool = False
    """It streams at a few microseconds a cell: a budget refusal points to it."""
    row_factor: float = 0.0
    """A table row's cost in this format over its cost in csv, for a method whose record
    (:attr:`~scanconv.answers.methods.Method.cost`) does not measure this format: the largest
    ratio measured for the stepped commands' methods (``benchmarks/bench_budget.py``), so an
    unmeasured format is never costed below the measured ones. A new format states this one
    number, not a cost per method. ``0``: not a single-answer format."""
    sheet_rows: int | None = None
    """Most table rows of a whole document it writes; ``None``: the budget's
    :data:`~scanconv.render.budget.SHEET_ROWS`. A GIFT quiz writes each blank as a question
    carrying the stem and the working: about 4.7 KB a row (80,000 rows: 373 MB, 1.58 GB of
    memory), so it holds 10,000 rows (about 47 MB)."""
    mapping: str = ""
    """``module:NAME`` in :mod:`scanconv.render` of its mapping from block types to text, for
    a block written alone (``exam --contents``: the contents with nothing answered); ``""``:
    none (json writes the contents as data, the others have no such page)."""

    @property
    def serves(self) -> tuple[str, ...]:
        """What it writes: ``"answer"`` (a single answer), ``"document"`` (a sheet, exam
        book or practice set), or both.

        >>> FORMATS["latex"].serves, FORMATS["csv"].serves, FORMATS["gift"].serves
        (('answer', 'document'), ('answer',), ('document',))
        """
        return ("answer",) * bool(self.renderer) + ("document",) * bool(self.sheet)


FORMATS: dict[str, Spec] = {
    "rich": Spec(
        "mappings.terminal:render_rich", (), False, 3000.0, 256 * 256, 10_000, row_factor=400
    ),
    "latex": Spec(
        "mappings.latex:render_latex",
        (".tex",),
        True,
        100.0,
        256 * 256,
        sheet="documents.sheet_latex:latex_sheet",
        row_factor=15,
        mapping="mappings.latex:LATEX",
    ),
    "markdown": Spec(
        "mappings.text:render_markdown",
        (".md", ".markdown"),
        False,
        90.0,
        256 * 256,
        sheet="documents.sheet:markdown_sheet",
        row_factor=14,
        mapping="mappings.text:MARKDOWN",
    ),
    "plain": Spec(
        "mappings.text:render_plain",
        (".txt",),
        False,
        60.0,
        1024 * 1024,
        sheet="documents.sheet:plain_sheet",
        row_factor=9,
        mapping="mappings.text:PLAIN",
    ),
    "csv": Spec("mappings.data:render_csv", (".csv",), True, 20.0, streams=True, row_factor=1),
    "json": Spec(
        "mappings.data:render_json",
        (".json",),
        True,
        60.0,
        sheet="documents.sheet:json_sheet",
        streams=True,
        row_factor=8,
    ),
    "html": Spec(
        "mappings.html:render_html",
        (".html", ".htm"),
        True,
        150.0,
        sheet="documents.sheet_html:html_sheet",
        row_factor=16,
    ),
    "moodle": Spec(extensions=(".xml",), binding=True, sheet="documents.moodle:moodle_sheet"),
    "gift": Spec(
        extensions=(".gift",), binding=True, sheet="documents.gift:gift_sheet", sheet_rows=10_000
    ),
}
"""Every format, declared once by its name (``auto`` aside): what it writes (its single-answer
renderer, a mapping from the document's blocks, and its document writer), its file
extensions, whether they bind, and its budget. The :class:`Format` members are its
single-answer formats; the CLI's ``--format`` choices, its extension map (:data:`EXTENSIONS`)
and its one rule of format conflicts, and the work budget read this table. A new format is
its module and its entry here (and a :class:`Format` member if it writes single answers)."""

EXTENSIONS: dict[str, str] = {
    ext: name for name, spec in FORMATS.items() for ext in spec.extensions
}
"""The format a file's extension names, for every command (``.tex``: ``latex``, ``.xml``:
``moodle``)."""


def formats(serving: str) -> tuple[str, ...]:
    """The names of the formats that write ``serving`` (``"answer"`` or ``"document"``), in
    the order of :data:`FORMATS`.

    >>> formats("document")
    ('latex', 'markdown', 'plain', 'json', 'html', 'moodle', 'gift')
    """
    return tuple(name for name, spec in FORMATS.items() if serving in spec.serves)


def load(entry: str) -> Any:
    """The function an entry of :data:`FORMATS` names (``"mappings.text:render_plain"``), imported on
    first use (:func:`scanconv.core.lazy.load`: start-up time)."""
    return lazy.load(f"{__name__}.{entry}")


class Options(NamedTuple):
    """Rendering options shared by every format (a NamedTuple: cheaper to define than a
    dataclass, and start-up time counts)."""

    grid: bool = True
    """Draw the text pixel grid (if it fits, see :mod:`scanconv.render.figures.grid`)."""
    origin: str = "bottom-left"
    """``bottom-left`` (y up, as in the notes) or ``top-left`` (screen addressing, y down)."""
    brief: bool = False
    """Leave the tool's notes (the conventions stated, the table's layout, the errata) out, in
    every format; ``rich`` leaves the derivation (given values, working with the numbers
    substituted) out too. By default every format shows the full worked answer."""
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

    >>> from scanconv.answers.primitives.line import line_solution
    >>> chunks = render(line_solution("bresenham", 0, 0, 2, 1), Format.csv)
    >>> print("".join(chunks), end="")
    k,p,decision,x,y,p_next
    0,0,NE,1,1,-2
    1,-2,E,2,1,0
    """
    options = options or Options()
    if fmt is Format.auto:
        raise ValueError("Format.auto must be resolved before rendering")
    renderer: Callable[[Document, Options], Iterator[Chunk]] = load(FORMATS[fmt].renderer)
    doc = document.as_document(solution)
    if options.brief:  # homework without the tool's notes, in every format
        doc = doc._replace(blocks=tuple(b for b in doc.blocks if not isinstance(b, document.Notes)))
    return renderer(doc, options)
