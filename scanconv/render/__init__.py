"""Renderers: turn a :class:`~scanconv.core.records.Solution` into output, without printing.

:func:`render` is the one dispatch point for ``--format``. Every renderer is a generator that
yields text chunks for stdout (each ending in a newline), :class:`Notice` objects for stderr,
and, for the ``rich`` format only, rich renderables. The CLI writes them out; nothing here
prints, and rich is imported only by the ``rich`` renderer.
"""

from __future__ import annotations

from collections.abc import Iterator
from enum import Enum
from typing import TYPE_CHECKING, Any, NamedTuple

from ..core.records import Solution

if TYPE_CHECKING:
    from ..document import Document


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
    solution: Solution | Document, fmt: Format, options: Options | None = None
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
    from ..document import as_document

    doc = as_document(solution)
    if fmt is Format.csv:
        from .data import render_csv

        return render_csv(doc)
    if fmt is Format.json:
        from .data import render_json

        return render_json(doc)
    if fmt is Format.latex:
        from .latex import render_latex

        return render_latex(doc, options)
    if fmt is Format.html:
        from .html import render_html

        return render_html(doc, options)
    if fmt is Format.rich:
        from .terminal import render_rich

        return render_rich(doc, options)
    from .text import render_text

    return render_text(doc, options, markdown=fmt is Format.markdown)
