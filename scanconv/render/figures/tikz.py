"""Drawn figures for LaTeX: the pixel grid of :mod:`scanconv.render.figures.figure` as a TikZ picture.

The SVG figure is the model: :func:`~scanconv.render.figures.figure.build` lays out the shapes (the
cells, the filled pixels, grey levels and outlines, the ideal primitive, control polygons,
marked points, step numbers and the numbered axes) and this module writes the same shapes as
TikZ commands, scaled to fit the page. The figure's title is the answer's heading already, so
it is left out; its legend becomes a caption under the picture, in the text's own font. The
typewriter grid stays for the plain text and the terminal.

A worksheet gets the same grid empty (:func:`tikz_grid` with ``empty``): the cells and the
numbered axes only, of the extent the answer needs, to plot the pixels on.

Needs ``\\usepackage{tikz}`` (and, for type of any size, ``\\RequirePackage{fix-cm}`` before
``\\documentclass``: without it TeX substitutes the nearest size, with a warning).
"""

from __future__ import annotations

from collections.abc import Container, Iterator
from fractions import Fraction

from ...core.numeric import round_half_up
from ...core.records import PixelFigure, ShadedMatrix, Solution
from ...core.working import tex_text
from ...document import Document
from .figure import CELL, PAINT, Figure, Shape, build

SCALE = 0.45
"""Points of the page per unit of the figure: a 32-unit cell is 14.4pt, about 5 mm."""

MAX_WIDTH = 325.0
"""The widest picture, in points: an article's 345pt text width, less room for the axis
names and numbers, which do not shrink below :data:`MIN_FONT`."""

MAX_HEIGHT = 360.0
"""The tallest picture, in points: about half an A4 page's text, so a table fits beside it."""

MIN_FONT = 4.5
"""The smallest type in a picture, in points (the axis numbers of a very wide grid)."""

EMPTY = frozenset({"cell", "axis", "tick"})
"""The shapes of an empty grid: the cells, the axes x = 0 and y = 0, the axis numbers."""


def tikz_grid(
    solution: Solution | Document, origin: str = "bottom-left", *, empty: bool = False
) -> str | None:
    """The answer's figure as a TikZ picture with its caption in a minipage (never split
    over a page), or ``None`` when it has no figure (no pixels, or too large to draw).

    >>> from scanconv.answers.primitives.line import line_solution
    >>> tex = tikz_grid(line_solution("bresenham", 2, 2, 10, 6))
    >>> tex.count("rectangle"), "\\\\begin{tikzpicture}" in tex, "filled: plotted pixel" in tex
    (9, True, True)
    >>> tikz_grid(line_solution("bresenham", 2, 2, 10, 6), empty=True).count("rectangle")
    0
    """
    try:
        fig = build(solution, origin)
    except ValueError:
        return None
    legend = [s.text for s in fig.shapes if s.cls == "legend"]
    if empty:
        caption = "Plot the pixels on this grid."
    else:
        caption = "Figure: " + "; ".join(legend).rstrip(".") + "." if legend else ""
    return _boxed(fig, EMPTY if empty else None, caption)


def grid_height(solution: Solution | Document, origin: str = "bottom-left") -> float | None:
    """About how tall :func:`tikz_grid`'s picture is set, in points (its ``% height``), or
    ``None`` when it draws none: what a table above it leaves room for to keep it.

    >>> from scanconv.answers.primitives.line import line_solution
    >>> round(grid_height(line_solution("bresenham", 2, 2, 10, 6)))
    177
    """
    try:
        fig = build(solution, origin)
    except ValueError:
        return None
    return _tall(fig, any(s.cls == "legend" for s in fig.shapes), False)


def _tall(fig: Figure, caption: bool, title: bool) -> float:
    """The height of a boxed picture with its caption and title lines, in points."""
    return fig.height * scale(fig) + 14 * (caption + title) + 10


def _boxed(fig: Figure, keep: Container[str] | None, caption: str, title: str = "") -> str:
    """The picture of ``fig`` and its caption (and a title above) in a minipage: never
    split by a page break. A ``% height`` comment says about how tall it is, in points (the
    sheet's page estimate reads it)."""
    tall = _tall(fig, bool(caption), bool(title))
    out = [
        f"\n% height {tall:.0f}pt\n\\par\\noindent\\begin{{minipage}}{{\\linewidth}}\\centering\n"
    ]
    if title:
        out.append(f"{{\\small {tex_text(title)}\\par}}\\smallskip\n")
    out.extend(to_tikz(fig, keep))
    if caption:
        out.append(f"\\par\\smallskip{{\\footnotesize {tex_text(caption)}\\par}}\n")
    out.append("\\end{minipage}\\par\\medskip\n")
    return "".join(out)


def tikz_figure(figure: PixelFigure | ShadedMatrix, origin: str = "bottom-left") -> str | None:
    """One of an answer's own figures drawn (:attr:`Solution.figures
    <scanconv.core.records.Solution.figures>`): a two-set pixel figure (``#`` blue, ``o``
    orange, ``@`` both) or a matrix of grey levels (each cell in its grey, its level
    written in it); ``None`` if it is too large to draw (the text picture stays).

    >>> from scanconv.core.records import ShadedMatrix, PixelFigure
    >>> tex = tikz_figure(ShadedMatrix(((0, 1), (1, 0)), 2, 2))
    >>> tex.count("rectangle"), "level 0 black" in tex
    (4, True)
    >>> tikz_figure(PixelFigure(((0, 0),), ((1, 0),), (0, 0, 1, 0), "# = a, o = b")).count("scpixel]")
    1
    """
    if isinstance(figure, ShadedMatrix):
        return _matrix(figure)
    x0, y0, x1, y1 = figure.bbox
    x0, y0, x1, y1 = x0 - 1, y0 - 1, x1 + 1, y1 + 1
    cols, rows = x1 - x0 + 1, y1 - y0 + 1
    if cols > MAX_FIGURE_CELLS or rows > MAX_FIGURE_CELLS:
        return None
    top = origin == "top-left"

    def corner(x: int, y: int) -> tuple[float, float]:
        return 40.0 + (x - x0) * CELL, 10.0 + ((y - y0) if top else (y1 - y)) * CELL

    fig = Figure(40.0 + cols * CELL + 30, 10.0 + rows * CELL + 30, "")
    add = fig.shapes.append
    both = set(figure.pixels) & set(figure.marks)
    for p in dict.fromkeys(figure.marks):
        add(Shape("rect", "outline", corner(*p)))
    for p in dict.fromkeys(figure.pixels):
        add(Shape("rect", "pixel", corner(*p)))
    for p in both:
        add(Shape("rect", "on-outline", corner(*p)))
    _cells(fig, corner(x0, y1 if not top else y0), cols, rows)
    bottom = 10.0 + rows * CELL
    for x in range(x0, x1 + 1):
        add(Shape("text", "tick", (corner(x, y0)[0] + CELL / 2, bottom + 15), str(x), 11, "middle"))
    for y in range(y0, y1 + 1):
        add(Shape("text", "tick", (34.0, corner(x0, y)[1] + CELL / 2 + 4), str(y), 11, "end"))
    legend = figure.legend or "# = plotted pixel, o = marked point"
    for mark, colour in (("#", "blue"), ("o", "orange"), ("@", "blue, outlined")):
        legend = legend.replace(f"{mark} = ", f"{colour}: ")
    return _boxed(fig, None, legend, figure.title or "")


MAX_FIGURE_CELLS = 100
"""The widest or tallest figure drawn, in cells (the text grid's own limit)."""


def _cells(fig: Figure, top_left: tuple[float, float], cols: int, rows: int) -> None:
    """The grid lines of ``cols`` x ``rows`` cells from ``top_left``."""
    left, top = top_left
    for j in range(cols + 1):
        x = left + j * CELL
        fig.shapes.append(Shape("line", "cell", (x, top, x, top + rows * CELL)))
    for j in range(rows + 1):
        y = top + j * CELL
        fig.shapes.append(Shape("line", "cell", (left, y, left + cols * CELL, y)))


def _matrix(matrix: ShadedMatrix) -> str | None:
    """A grey-level matrix: row 0 at the top, level 0 black, L - 1 white (as the text
    picture), each cell's level written in it."""
    rows, width, levels = len(matrix.rows), matrix.width, matrix.levels
    if rows > MAX_FIGURE_CELLS or width > MAX_FIGURE_CELLS or not rows:
        return None
    fig = Figure(40.0 + width * CELL + 10, 10.0 + rows * CELL + 30, "")
    add = fig.shapes.append
    for i, row in enumerate(matrix.rows):
        for j, level in enumerate(row):
            v = round_half_up(Fraction(255 * level, max(levels - 1, 1)))
            at = (40.0 + j * CELL, 10.0 + i * CELL)
            add(Shape("rect", "shade", at, fill=f"#{v:02x}{v:02x}{v:02x}"))
            centre = (at[0] + CELL / 2, at[1] + CELL / 2 + 4)
            ink = None if v > 110 else "#ffffff"
            add(Shape("text", "step", centre, str(level), 10, "middle", fill=ink))
    _cells(fig, (40.0, 10.0), width, rows)
    for i in range(rows):
        add(Shape("text", "tick", (34.0, 10.0 + i * CELL + CELL / 2 + 4), str(i), 11, "end"))
    for j in range(width):
        at = (40.0 + j * CELL + CELL / 2, 10.0 + rows * CELL + 15)
        add(Shape("text", "tick", at, str(j), 11, "middle"))
    caption = f"grey levels 0 .. {levels - 1}: level 0 black, level {levels - 1} white"
    return _boxed(fig, _MATRIX, caption)


_MATRIX = frozenset({"shade", "cell", "tick", "step"})


def scale(fig: Figure) -> float:
    """Points per figure unit: :data:`SCALE`, less if the picture would be wider than
    :data:`MAX_WIDTH` or taller than :data:`MAX_HEIGHT`.

    >>> scale(Figure(200, 200, "")), round(scale(Figure(1000, 200, "")), 3)
    (0.45, 0.325)
    """
    return min(SCALE, MAX_WIDTH / fig.width, MAX_HEIGHT / fig.height)


def to_tikz(fig: Figure, keep: Container[str] | None = None) -> Iterator[str]:
    """The figure's shapes (those whose class is in ``keep``, or all but the title and the
    legend) as a ``tikzpicture``, in figure units scaled by :func:`scale`, y down as in SVG.
    Each CSS class of the figure is a TikZ style of its name with ``sc`` before it (its
    colours, strokes and type size: ``scpixel``), so a shape is one short command.

    >>> fig = Figure(100, 100, "t", [Shape("text", "tick", (10, 20), "x_1 & 5%", anchor="end")])
    >>> print("".join(to_tikz(fig)).splitlines()[-2])
    \\node[sctick,anchor=base east] at (10,20) {x\\_1 \\& 5\\%};
    """
    s = scale(fig)
    shapes = [
        shape
        for shape in fig.shapes
        if shape.cls not in ("title", "legend") and (keep is None or shape.cls in keep)
    ]
    sizes: dict[str, float] = {}
    for shape in shapes:
        if shape.kind == "text":
            sizes.setdefault(shape.cls, shape.size)
    styles = [f"sc{cls}/.style={{{_style(cls, s, sizes.get(cls))}}}" for cls in _classes(shapes)]
    yield f"\\begin{{tikzpicture}}[x={s:.4f}pt,y=-{s:.4f}pt,line cap=round,line join=round,\n"
    yield ",\n".join(styles) + "]\n"
    for shape in shapes:
        yield _command(shape, s, sizes) + "\n"
    yield "\\end{tikzpicture}\n"


TEXT_GROWTH = 1.25
"""Type in a picture is set this much larger than the SVG's (which is read on a screen)."""


def _classes(shapes: list[Shape]) -> list[str]:
    return list(dict.fromkeys(shape.cls for shape in shapes))


def _font(size: float, s: float) -> str:
    points = max(MIN_FONT, size * s * TEXT_GROWTH)
    return f"font=\\fontsize{{{_num(points)}}}{{{_num(1.2 * points)}}}\\selectfont"


def _style(cls: str, s: float, size: float | None) -> str:
    """The TikZ style of a CSS class of :data:`~scanconv.render.figures.figure.PAINT`."""
    paint = PAINT[cls]
    if size is not None:
        return f"inner sep=0pt,{_font(size, s)},text={_color(paint.fill or '#000000')}"
    style = []
    if paint.fill:
        style.append(f"fill={_color(paint.fill)}")
    if paint.stroke:
        style.append(f"draw={_color(paint.stroke)},line width={_num(paint.width * s)}pt")
    if paint.dash:
        on, off = (_num(d * s) for d in paint.dash)
        style.append(f"dash pattern=on {on}pt off {off}pt")
    return ",".join(style)


def _color(hex_colour: str) -> str:
    """An ``#rrggbb`` colour in xcolor's syntax.

    >>> _color("#d62728")
    '{rgb,255:red,214;green,39;blue,40}'
    """
    r, g, b = (int(hex_colour[i : i + 2], 16) for i in (1, 3, 5))
    return f"{{rgb,255:red,{r};green,{g};blue,{b}}}"


def _num(v: float) -> str:
    text = f"{v:.2f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


_ANCHORS = {"start": "base west", "middle": "base", "end": "base east"}


def _command(shape: Shape, s: float, sizes: dict[str, float]) -> str:
    """One shape as a TikZ command in its class's style."""
    at = [_num(v) for v in shape.at]
    opts = "sc" + shape.cls
    if shape.kind == "text":
        opts += f",anchor={_ANCHORS[shape.anchor]}"
        if shape.size != sizes.get(shape.cls):
            opts += "," + _font(shape.size, s)
        if shape.fill:
            opts += f",text={_color(shape.fill)}"
        return f"\\node[{opts}] at ({at[0]},{at[1]}) {{{tex_text(shape.text)}}};"
    if shape.fill:
        opts += f",fill={_color(shape.fill)}"
    if shape.kind == "rect":
        return f"\\path[{opts}] ({at[0]},{at[1]}) rectangle +({CELL},{CELL});"
    if shape.kind == "line":
        return f"\\path[{opts}] ({at[0]},{at[1]}) -- ({at[2]},{at[3]});"
    if shape.kind == "circle":
        return f"\\path[{opts}] ({at[0]},{at[1]}) circle[radius={at[2]}];"
    if shape.kind == "ellipse":
        return f"\\path[{opts}] ({at[0]},{at[1]}) ellipse[x radius={at[2]},y radius={at[3]}];"
    points = " -- ".join(f"({x},{y})" for x, y in zip(at[::2], at[1::2], strict=True))
    return f"\\path[{opts}] {points};"
