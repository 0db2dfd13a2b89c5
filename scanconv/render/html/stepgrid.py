"""The HTML page's SVG: the stepper's pixel grid (every pixel a ``<rect>`` the script lights)
and the answer's extra figures (a comparison's grid, a shaded matrix), drawn as the figures of
:mod:`scanconv.render.figures.figure` draw them (the same cells, axes, primitive and colours), with a
scale that fits any size.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from fractions import Fraction
from typing import Any

from ...core.ideal import (
    ControlPolygon,
    Ideal,
    IdealCircle,
    IdealEllipse,
    IdealLine,
    Polyline,
    control_points,
    ideal_kinds,
)
from ...core.numeric import round_half_up
from ...core.records import Pixel, PixelFigure, ShadedMatrix
from ...document import Document, Pixels, Table
from .. import Options
from ..figures.figure import CELL, cells_extent, grey_of
from .mathml import esc
from .stepper import Stepping

MAX_FIGURE_CELLS = 200
"""Largest side, in cells, of an extra figure (a shaded matrix, a comparison's grid)."""

GRID_LINES = 100
"""Cell lines are drawn when the grid is at most this many cells wide and high."""

LABELS = 40
"""Step numbers are written in the pixels when the grid is at most this many cells a side."""


class _Frame:
    """Solution coordinates (pixel centres on integers, y up) to SVG coordinates."""

    PAD_LEFT, PAD_TOP, PAD_RIGHT, PAD_BOTTOM = 44.0, 14.0, 34.0, 30.0

    def __init__(self, cells: tuple[int, int, int, int], top_left: bool, room: float) -> None:
        self.x0, self.y0, self.x1, self.y1 = cells
        self.cols, self.rows = self.x1 - self.x0 + 1, self.y1 - self.y0 + 1
        self.s = float(
            min(CELL, room / max(self.cols, self.rows))
        )  # at most room px: labels and size bounded
        self.top_left = top_left
        # room for the widest row label on the left and half the last column label on the
        # right (about 7 px a digit at 11 px)
        y_digits = max(len(str(self.y0)), len(str(self.y1)))
        self.x_digits = x_digits = max(len(str(self.x0)), len(str(self.x1)))
        self.left, self.top = max(self.PAD_LEFT, 7.0 * y_digits + 12), self.PAD_TOP
        self.right = self.left + self.cols * self.s
        self.bottom = self.top + self.rows * self.s
        self.width = self.right + max(self.PAD_RIGHT, 3.5 * x_digits + 24)
        self.height = self.bottom + self.PAD_BOTTOM

    def px(self, x: Any) -> float:
        return self.left + (float(x) - self.x0 + 0.5) * self.s

    def py(self, y: Any) -> float:
        rows = (float(y) - self.y0 + 0.5) if self.top_left else (self.y1 + 0.5 - float(y))
        return self.top + rows * self.s

    def corner(self, x: int, y: int) -> tuple[float, float]:
        """The top-left corner of pixel ``(x, y)``'s cell."""
        return self.px(x - 0.5), self.py(y - 0.5 if self.top_left else y + 0.5)


def _n(v: float) -> str:
    s = f"{v:.2f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _ticks(room: float) -> int:
    """Label every n-th line so the labels keep ``room`` px apart: n of 1, 2, 5, 10, 20, 50
    and so on, however many cells there are (a grid of 10^9 columns labels a few dozen).

    >>> _ticks(1.0), _ticks(0.3), _ticks(0.15), _ticks(1e-9)
    (1, 5, 10, 1000000000)
    """
    n = 1
    while True:
        for m in (1, 2, 5):
            if n * m * room >= 1:
                return n * m
        n *= 10


def _multiples(lo: int, hi: int, n: int) -> range:
    """The multiples of ``n`` from ``lo`` to ``hi``: the labelled lines, without visiting
    the others.

    >>> list(_multiples(-7, 12, 5))
    [-5, 0, 5, 10]
    """
    return range(-(-lo // n) * n, hi + 1, n)


def _grid_lines(f: _Frame) -> list[str]:
    out: list[str] = []
    if f.cols <= GRID_LINES and f.rows <= GRID_LINES:
        d = [f"M{_n(f.left + j * f.s)} {_n(f.top)}V{_n(f.bottom)}" for j in range(f.cols + 1)]
        d += [f"M{_n(f.left)} {_n(f.top + j * f.s)}H{_n(f.right)}" for j in range(f.rows + 1)]
        out.append(f'<path class="sc-cells" d="{"".join(d)}"/>')
    else:
        out.append(
            f'<rect class="sc-cells" x="{_n(f.left)}" y="{_n(f.top)}" '
            f'width="{_n(f.right - f.left)}" height="{_n(f.bottom - f.top)}"/>'
        )
    if f.x0 <= 0 <= f.x1:
        out.append(
            f'<line class="sc-axis" x1="{_n(f.px(0))}" y1="{_n(f.top)}" '
            f'x2="{_n(f.px(0))}" y2="{_n(f.bottom)}"/>'
        )
    if f.y0 <= 0 <= f.y1:
        out.append(
            f'<line class="sc-axis" x1="{_n(f.left)}" y1="{_n(f.py(0))}" '
            f'x2="{_n(f.right)}" y2="{_n(f.py(0))}"/>'
        )
    return out


def _axes(f: _Frame) -> list[str]:
    out: list[str] = []
    for x in _multiples(f.x0, f.x1, _ticks(f.s / (7.0 * f.x_digits + 6))):
        out.append(
            f'<text x="{_n(f.px(x))}" y="{_n(f.bottom + 15)}" font-size="11" '
            f'text-anchor="middle">{x}</text>'
        )
    for y in _multiples(f.y0, f.y1, _ticks(f.s / 14.0)):
        out.append(
            f'<text x="{_n(f.left - 6)}" y="{_n(f.py(y) + 4)}" font-size="11" '
            f'text-anchor="end">{y}</text>'
        )
    out.append(
        f'<text x="{_n(f.right + 6)}" y="{_n(f.bottom + 15)}" font-size="11">x \u2192</text>'
    )
    arrow = "\u2193" if f.top_left else "\u2191"
    out.append(
        f'<text x="{_n(f.left - 6)}" y="{_n(f.top - 2)}" font-size="11" '
        f'text-anchor="end">y {arrow}</text>'
    )
    return out


def _primitive(ideal: Iterable[Ideal], f: _Frame) -> list[str]:
    out: list[str] = []
    for shape in ideal:
        match shape:
            case IdealLine(x1, y1, x2, y2):
                out.append(
                    f'<line class="sc-ideal" x1="{_n(f.px(x1))}" y1="{_n(f.py(y1))}" '
                    f'x2="{_n(f.px(x2))}" y2="{_n(f.py(y2))}"/>'
                )
            case IdealCircle(xc, yc, r):
                out.append(
                    f'<circle class="sc-ideal" cx="{_n(f.px(xc))}" cy="{_n(f.py(yc))}" '
                    f'r="{_n(float(r) * f.s)}"/>'
                )
            case IdealEllipse(xc, yc, rx, ry):
                out.append(
                    f'<ellipse class="sc-ideal" cx="{_n(f.px(xc))}" cy="{_n(f.py(yc))}" '
                    f'rx="{_n(float(rx) * f.s)}" ry="{_n(float(ry) * f.s)}"/>'
                )
            case Polyline(points) if points:
                pts = " ".join(f"{_n(f.px(x))},{_n(f.py(y))}" for x, y in points)
                out.append(f'<polyline class="sc-ideal" points="{pts}"/>')
            case ControlPolygon(points) if points:
                pts = " ".join(f"{_n(f.px(x))},{_n(f.py(y))}" for x, y in points)
                out.append(f'<polyline class="sc-control" points="{pts}"/>')
    return out


def _marks(block: Pixels, f: _Frame) -> list[str]:
    out: list[str] = []
    control = control_points(block.ideal)
    on_control = {(round_half_up(Fraction(x)), round_half_up(Fraction(y))) for x, y in control}
    arm = max(f.s * 0.22, 2.0)
    for x, y in block.marks:
        if (x, y) in on_control:
            continue
        cx, cy = f.px(x), f.py(y)
        out.append(
            f'<path class="sc-mark" d="M{_n(cx - arm)} {_n(cy - arm)}L{_n(cx + arm)} '
            f'{_n(cy + arm)}M{_n(cx - arm)} {_n(cy + arm)}L{_n(cx + arm)} {_n(cy - arm)}"/>'
        )
    for qx, qy in control:
        out.append(
            f'<circle class="sc-cpoint" cx="{_n(f.px(qx))}" cy="{_n(f.py(qy))}" '
            f'r="{_n(max(f.s * 0.3, 3.0))}"/>'
        )
    return out


def _levels(tables: list[Table], f: _Frame) -> list[str]:
    """Construction points drawn over the grid: the rows of :attr:`Table.points` tables (de
    Casteljau's intermediate points at ``--at``)."""
    out: list[str] = []
    for table in tables:
        if not table.points:
            continue
        for row in table.rows():
            points = [
                v
                for v in row
                if isinstance(v, tuple) and len(v) == 2 and not isinstance(v[0], tuple)
            ]
            if len(points) >= 2:
                pts = " ".join(f"{_n(f.px(x))},{_n(f.py(y))}" for x, y in points)
                out.append(f'<polyline class="sc-levelline" points="{pts}"/>')
            for x, y in points:
                out.append(
                    f'<circle class="sc-level" cx="{_n(f.px(x))}" cy="{_n(f.py(y))}" '
                    f'r="{_n(max(f.s * 0.14, 2.0))}"/>'
                )
    return out


def _svg_open(f: _Frame, cls: str, label: str) -> str:
    return (
        f'<svg class="sc-grid {cls}" xmlns="http://www.w3.org/2000/svg" role="img" '
        f'aria-label="{esc(label)}" width="{_n(f.width)}" height="{_n(f.height)}" '
        f'viewBox="0 0 {_n(f.width)} {_n(f.height)}">'
    )


def step_grid(doc: Document, st: Stepping, options: Options, at: int = 0) -> tuple[str, bool]:
    """The stepper's SVG (the grid, every drawn pixel, lit by the script, the primitive), and
    whether it numbers the pixels."""
    block: Pixels = doc.get(Pixels)
    outline = list(dict.fromkeys(block.outline))
    cells = cells_extent(st.pixels, (*block.marks, *block.outline), block.ideal)
    f = _Frame(cells, options.origin == "top-left", 620.0)
    plotted = set(st.pixels)
    out = [_svg_open(f, "sc-stepgrid", f"pixel grid of {doc.title}")]
    for x, y in outline:
        if (x, y) not in plotted:
            cx, cy = f.corner(x, y)
            out.append(
                f'<rect class="sc-outline" x="{_n(cx)}" y="{_n(cy)}" '
                f'width="{_n(f.s)}" height="{_n(f.s)}"/>'
            )
    out.extend(_cells(block, st, f, set(outline), at))
    out.extend(_grid_lines(f))
    out.extend(_primitive(block.ideal, f))
    out.extend(_levels(doc.every(Table), f))
    out.extend(_marks(block, f))
    labels = _labels(block, st, f, at)
    out.extend(labels)
    out.extend(_axes(f))
    out.append("</svg>")
    return "".join(out), bool(labels)


def _cells(block: Pixels, st: Stepping, f: _Frame, edge: set[Pixel], at: int) -> Iterator[str]:
    """A ``<rect>`` for every drawn pixel, classed by when it lights and what it is."""
    shades = block.shades or {}
    s = _n(f.s)
    for i, (x, y) in enumerate(st.pixels):
        cx, cy = f.corner(x, y)
        cls = "sc-px" + (" on" if st.pos[i] <= at else "") + (" sc-new" if st.pos[i] == at else "")
        if st.kind[i]:
            cls += " sc-m"
        if st.region[i] > 1:
            cls += " sc-r2"
        if (x, y) in edge:
            cls += " sc-edge"
        grey = f' style="fill:{grey_of(shades[(x, y)], block.levels)}"' if (x, y) in shades else ""
        yield (
            f'<rect class="{cls}" data-i="{i}" data-x="{x}" data-y="{y}" x="{_n(cx)}" '
            f'y="{_n(cy)}" width="{s}" height="{s}"{grey}/>'
        )


def _labels(block: Pixels, st: Stepping, f: _Frame, at: int) -> list[str]:
    """The step numbers written in the pixels, when the grid is small enough to read them."""
    out: list[str] = []
    if f.cols > LABELS or f.rows > LABELS or len(st.pixels) > 4 * LABELS * LABELS:
        return out
    labels = block.labels()
    for i, p in enumerate(st.pixels):
        if p not in labels:
            continue
        text = str(labels[p])
        size = min(13.0, (f.s - 6) / (0.62 * len(text)))
        if size < 6:
            continue
        lit = " on" if st.pos[i] <= at else ""
        out.append(
            f'<text class="sc-lb{lit}" data-i="{i}" x="{_n(f.px(p[0]))}" '
            f'y="{_n(f.py(p[1]) + 0.36 * size)}" font-size="{_n(size)}" '
            f'text-anchor="middle">{text}</text>'
        )
    return out


def legend(doc: Document, st: Stepping, numbered: bool) -> str:
    """The key under the stepper's grid: what each colour and mark stands for."""
    block: Pixels = doc.get(Pixels)
    control = control_points(block.ideal)
    parts = ['<i style="background:var(--sc-px)"></i>plotted pixel']
    if any(st.kind):
        parts.append('<i style="background:var(--sc-mirror)"></i>mirror image')
    if any(r > 1 for r in st.region):
        parts.append('<i style="background:var(--sc-r2)"></i>region 2')
    parts.append('<i style="background:#fff;border:2px solid var(--sc-new)"></i>this step')
    if block.outline:
        parts.append(f'<i style="background:#f4b183"></i>{esc(block.outline_name)}')
    if block.shades is not None:
        parts.append(f"grey: intensity level (black = {block.levels - 1})")
    kinds = ideal_kinds(block.ideal)
    if kinds:
        parts.append(f'<i style="background:#d62728"></i>ideal {esc(" and ".join(kinds))}')
    if control:
        parts.append('<i style="background:#2ca02c"></i>control polygon')
    if block.construction:
        parts.append(f'<i style="background:#7b3294"></i>{esc(block.construction)}')
    if block.marks and not control:
        parts.append(f"\u00d7 {esc(block.marks_label)}")
    if numbered:
        parts.append(esc(block.numbering()))
    return '<p class="sc-legend">' + "".join(f"<span>{p}</span>" for p in parts) + "</p>"


def figure_svg(figure: PixelFigure | ShadedMatrix, origin: str) -> str:
    """One of :attr:`Solution.figures` as a static SVG in a ``<figure>``, or a note that it
    is too large to draw."""
    if isinstance(figure, ShadedMatrix):
        rows, width = len(figure.rows), figure.width
        if rows > MAX_FIGURE_CELLS or width > MAX_FIGURE_CELLS:
            return f'<p class="sc-more">The shaded picture ({width} x {rows}) is too large to draw here.</p>'
        s = min(24.0, 360.0 / max(rows, width, 1))
        w, h = width * s + 2, rows * s + 2
        out = [
            f'<figure><svg class="sc-grid" xmlns="http://www.w3.org/2000/svg" role="img" '
            f'aria-label="shaded picture" width="{_n(w)}" height="{_n(h)}" '
            f'viewBox="0 0 {_n(w)} {_n(h)}">'
        ]
        top = figure.levels - 1
        for r, row in enumerate(figure.rows):
            for c, level in enumerate(row):
                grey = grey_of(top - int(level), figure.levels)
                out.append(
                    f'<rect x="{_n(1 + c * s)}" y="{_n(1 + r * s)}" width="{_n(s)}" '
                    f'height="{_n(s)}" fill="{grey}"/>'
                )
        out.append(
            f'<rect x="1" y="1" width="{_n(w - 2)}" height="{_n(h - 2)}" fill="none" stroke="#555"/>'
        )
        out.append(
            f"</svg><figcaption>Shaded picture: level 0 black, level {top} white; "
            "row 0 at the top.</figcaption></figure>"
        )
        return "".join(out)
    cells = figure.bbox
    cols, rows = cells[2] - cells[0] + 1, cells[3] - cells[1] + 1
    title = f"<strong>{esc(figure.title)}</strong> " if figure.title else ""
    if cols > MAX_FIGURE_CELLS or rows > MAX_FIGURE_CELLS:
        return f'<p class="sc-more">{title}The figure ({cols} x {rows} cells) is too large to draw here.</p>'
    f = _Frame(cells, origin == "top-left", 360.0)
    out = [f"<figure>{_svg_open(f, 'sc-figure', figure.title or 'figure')}"]
    marks = set(figure.marks)
    for x, y in dict.fromkeys(figure.pixels):
        cx, cy = f.corner(x, y)
        extra = " sc-edge" if (x, y) in marks else ""
        out.append(
            f'<rect class="sc-fpx{extra}" x="{_n(cx)}" y="{_n(cy)}" width="{_n(f.s)}" height="{_n(f.s)}"/>'
        )
    for x, y in dict.fromkeys(figure.marks):
        if (x, y) in set(figure.pixels):
            continue
        cx, cy = f.corner(x, y)
        out.append(
            f'<rect class="sc-outline" x="{_n(cx)}" y="{_n(cy)}" width="{_n(f.s)}" height="{_n(f.s)}"/>'
        )
    out.extend(_grid_lines(f))
    out.extend(_axes(f))
    key = "blue: # of the text grid; orange: o"
    legend = f"{key} ({figure.legend})" if figure.legend else key
    out.append(f"</svg><figcaption>{title}{esc(legend)}</figcaption></figure>")
    return "".join(out)
