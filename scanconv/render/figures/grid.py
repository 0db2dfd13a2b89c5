"""The text pixel grid printed under every answer.

ASCII only, so it survives every format: ``#`` a plotted pixel, ``o`` a marked point (a
control point or the centre), ``@`` both, ``.`` an empty cell. Rows are labelled with y and
grow upward, as in the notes' 5 x 5 grid; ``origin="top-left"`` draws screen addressing
(y grows downward) instead. The grid covers the pixels' bounding box plus a margin.
"""

from __future__ import annotations

from collections.abc import Iterable

from ...core.records import MAX_GRID_CELLS as MAX_CELLS
from ...core.records import Pixel, PixelFigure

MARGIN = 1
"""Empty cells around the bounding box."""


def too_large(bbox: tuple[int, int, int, int], margin: int = MARGIN) -> str | None:
    """Why the grid of ``bbox`` would not be readable, or ``None`` if it fits.

    >>> too_large((0, 0, 10, 10)) is None
    True
    >>> too_large((0, 0, 500, 3))
    'grid left out: 503 x 6 cells is more than 100 columns; the table and pixel list are complete'
    """
    cols = bbox[2] - bbox[0] + 1 + 2 * margin
    rows = bbox[3] - bbox[1] + 1 + 2 * margin
    if cols > MAX_CELLS or rows > MAX_CELLS:
        what = "columns" if cols > MAX_CELLS else "rows"
        return (
            f"grid left out: {cols} x {rows} cells is more than {MAX_CELLS} {what}; "
            "the table and pixel list are complete"
        )
    return None


def render_grid(
    pixels: Iterable[Pixel],
    bbox: tuple[int, int, int, int],
    *,
    origin: str = "bottom-left",
    marks: Iterable[Pixel] = (),
    margin: int = MARGIN,
    legend: str | None = None,
    mark_label: str = "marked point",
    compact: bool = False,
) -> list[str]:
    """The grid as lines of text (no trailing newlines).

    ``legend`` replaces the key to the symbols (``# = plotted pixel...``) in the last line,
    for figures whose ``#`` and ``o`` mean something else (``scanconv compare``);
    ``mark_label`` says what ``o`` is in the usual key (``centre``, ``control point``).
    ``compact`` draws each cell one character wide and labels x every 5 columns, for a
    narrow terminal (see :func:`width`).

    >>> print("\\n".join(render_grid([(0, 0), (1, 1), (2, 1)], (0, 0, 2, 1))))
     2 | .  .  .  .  .
     1 | .  .  #  #  .
     0 | .  #  .  .  .
    -1 | .  .  .  .  .
       +---------------
         -1 0  1  2  3
    # = plotted pixel; x to the right, y up
    """
    x0, y0 = bbox[0] - margin, bbox[1] - margin
    x1, y1 = bbox[2] + margin, bbox[3] + margin
    plotted = {p for p in pixels if x0 <= p[0] <= x1 and y0 <= p[1] <= y1}
    marked = {p for p in marks if x0 <= p[0] <= x1 and y0 <= p[1] <= y1}
    w = 1 if compact else max(len(str(x)) for x in (x0, x1))
    lw = max(len(str(y)) for y in (y0, y1))
    ys = range(y0, y1 + 1) if origin == "top-left" else range(y1, y0 - 1, -1)
    lines = [
        f"{str(y).rjust(lw)} | "
        + " ".join(_cell((x, y), plotted, marked).ljust(w) for x in range(x0, x1 + 1)).rstrip()
        for y in ys
    ]
    ncols = x1 - x0 + 1
    lines.append(" " * lw + " +" + "-" * (ncols * (w + 1)))
    lines.append(" " * (lw + 3) + _x_labels(x0, x1, w, compact))
    if legend is None:
        legend = "# = plotted pixel"
        if marked:
            legend += f", o = {mark_label}, @ = both"
    direction = "y down (screen addressing)" if origin == "top-left" else "y up"
    lines.append(f"{legend}; x to the right, {direction}")
    return lines


def _cell(p: Pixel, plotted: set[Pixel], marked: set[Pixel]) -> str:
    """``@`` plotted and marked, ``#`` plotted, ``o`` marked, ``.`` neither."""
    if p in plotted:
        return "@" if p in marked else "#"
    return "o" if p in marked else "."


def _x_labels(x0: int, x1: int, w: int, compact: bool) -> str:
    """The x axis's labels: every column, or (``compact``) every fifth that fits."""
    if not compact:
        return " ".join(str(x).ljust(w) for x in range(x0, x1 + 1)).rstrip()
    ncols = x1 - x0 + 1
    row = [" "] * (ncols * (w + 1) + 4)
    end = -1
    for i, x in enumerate(range(x0, x1 + 1)):
        text = str(x)
        start = i * (w + 1)
        if x % 5 == 0 and start > end and start + len(text) <= ncols * (w + 1):
            row[start : start + len(text)] = text
            end = start + len(text)
    return "".join(row).rstrip()


def figure_grid(figure: PixelFigure, origin: str) -> list[str]:
    """The lines of a :class:`~scanconv.core.records.PixelFigure`: its title, then its grid
    (or, for a titled figure too large to draw, why it is left out).

    >>> print("\\n".join(figure_grid(PixelFigure(((0, 0),), ((1, 0),), (0, 0, 1, 0), "key", "A:"), "bottom-left")))
    A:
     1 | .  .  .  .
     0 | .  #  o  .
    -1 | .  .  .  .
       +------------
         -1 0  1  2
    key; x to the right, y up
    """
    reason = too_large(figure.bbox)
    lines = [] if figure.title is None else [figure.title]
    if reason:
        return [*lines, reason] if lines else []
    return lines + render_grid(
        figure.pixels, figure.bbox, origin=origin, marks=figure.marks, legend=figure.legend
    )


def width(bbox: tuple[int, int, int, int], *, compact: bool = False, margin: int = MARGIN) -> int:
    """Characters of the widest line of the grid of ``bbox`` (the legend aside).

    >>> width((0, 0, 2, 1)), width((-12, -12, 12, 12)), width((-12, -12, 12, 12), compact=True)
    (19, 113, 59)
    """
    x0, y0, x1, y1 = bbox[0] - margin, bbox[1] - margin, bbox[2] + margin, bbox[3] + margin
    w = 1 if compact else max(len(str(x)) for x in (x0, x1))
    lw = max(len(str(y)) for y in (y0, y1))
    return lw + 2 + (x1 - x0 + 1) * (w + 1)
