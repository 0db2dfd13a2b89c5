"""The Python API: filled areas and anti-aliasing (``scanconv polygon``, ``fill``, ``antialias``). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated

from ..algorithms.choices import WuEnds
from ..algorithms.process_choices import AAMethod, Across, Divide, FillRule, Order, Subgrid
from ..core import lazy
from ..core.declare import Arg, Opt
from ..display import answers
from .params import CENTER, VERTICES, WU_ENDS
from .values import (
    NumberLike,
    PointLike,
    PointsLike,
    _choice,
    _flat,
    _maybe,
    _number,
    _numbers,
    _pair,
    _whole,
)

if TYPE_CHECKING:
    from ..answers.process.antialias import sampling as answers_antialias
    from ..answers.process.fill import scanline as answers_polygon
    from ..answers.process.fill import seed as answers_fill
    from ..core.choices import (
        AAMethodName,
        AcrossName,
        DivideName,
        FillMethodName,
        FillRuleName,
        OrderName,
        SubgridName,
        WuEndsName,
    )
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_antialias = lazy.module("scanconv.answers.process.antialias.sampling")
    answers_fill = lazy.module("scanconv.answers.process.fill.seed")
    answers_polygon = lazy.module("scanconv.answers.process.fill.scanline")


RULE = Opt("--rule", help="Fill rule: even-odd (alternate) or nonzero winding.")
LEVELS = Opt(
    "--levels", "-L", help="Intensity levels L (level = round(I (L - 1))).", kind="integer"
)
AA_SAMPLES = Opt(
    "--samples", "-n", help="Supersampling: N x N samples per pixel (1-16).", kind="integer"
)
AA_METHOD = Opt(
    "--method",
    "-m",
    help="area: exact covered area; supersample: N x N samples; wu: Wu's line; subpixel: "
    "Hearn & Baker's Bresenham on sub-pixels (wu and subpixel: lines only).",
)


@answers
def polygon(
    vertices: Annotated[PointsLike, VERTICES],
    rule: Annotated[FillRule | FillRuleName, RULE] = "even-odd",
) -> Solution:
    """The scan-line fill of a polygon (``scanconv polygon``): the edge table, the active edge table
    per scan line, the spans and the pixels.

    Parameters
    ----------
    vertices : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The polygon's vertices in order, exact numbers.
    rule : {"even-odd", "nonzero"} or FillRule, default "even-odd"
        The inside rule: odd crossings (alternate), or a nonzero winding number.

    Returns
    -------
    Answer
        The edge table (``y_min``, x at ``y_min``, ``1/m``, ``y_max``, sorted by y_min then x), the
        active edges and spans of each scan line, and the filled pixels, bottom row first.

    Notes
    -----
    Hearn & Baker's scan-line fill (section 3-11): scan line y meets an edge when
    ``y_min <= y < y_max`` (the upper end excluded, so a vertex between two edges is counted once
    and horizontal edges drop out); a span runs from ``ceil(x_left)`` to ``ceil(x_right) - 1``
    (:func:`scanconv.raster.polygon` gives the same pixels in bulk).

    Examples
    --------
    >>> sol = polygon([(0, 0), (4, 0), (2, 3)])
    >>> [t.title for t in sol.tables]
    ['Edge table (sorted by y_min, then x)', 'Scan lines (AET entries: edge: x, 1/m, y_max)']
    >>> list(sol.pixels())
    [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
    >>> print(polygon([(0, 0), (4, 0), (2, 3)]).grid(), end="")
     4 | .  .  .  .  .  .  .
     3 | .  .  .  .  .  .  .
     2 | .  .  .  #  .  .  .
     1 | .  .  #  #  #  .  .
     0 | .  #  #  #  #  .  .
    -1 | .  .  .  .  .  .  .
       +---------------------
         -1 0  1  2  3  4  5
    # = plotted pixel; x to the right, y up
    """
    return answers_polygon.polygon_solution(_flat(vertices, "vertices"), _choice(rule, "rule"))


@answers
def fill(
    method: FillMethodName,
    seed: Annotated[
        PointLike, Opt("--seed", "-s", metavar="X Y", help="The seed pixel.", kind="integer")
    ],
    *,
    vertices: Annotated[
        PointsLike | None,
        Arg(
            "A polygon whose Bresenham outline is the boundary (or give --rows).",
            "[X1 Y1 X2 Y2 X3 Y3 ...]",
        ),
    ] = None,
    rows: Annotated[
        str | Sequence[str] | None,
        Opt(
            "--rows",
            "-r",
            metavar="ROWS",
            help="The grid as text rows, top row first, separated by '/': '#' boundary, '.' "
            "empty, '*' fill colour, other letters other colours; the bottom row is y = 0.",
            show_default=False,
        ),
    ] = None,
    connectivity: Annotated[
        NumberLike, Opt("--connectivity", "-k", help="Neighbours: 4 or 8.", kind="integer")
    ] = 4,
    order: Annotated[
        Order | OrderName,
        Opt("--order", help="stack: last in first out; queue: first in first out."),
    ] = "stack",
    span: Annotated[
        bool, Opt("--span", help="The span (scan-line seed) fill: a whole run per seed.")
    ] = False,
) -> Solution:
    """A seed fill, step by step (``scanconv fill boundary``, ``scanconv fill flood``).

    Parameters
    ----------
    method : {"boundary", "flood"}
        ``"boundary"``: fill up to the boundary colour; ``"flood"``: replace the seed's colour.
    seed : (x, y)
        The seed pixel, integers.
    vertices : sequence of (x, y), or flat numbers, optional
        A polygon whose Bresenham outline is the boundary.
    rows : str or sequence of str, optional
        The grid instead, top row first: ``#`` boundary, ``.`` empty (``"####/#..#/####"``, or a
        list of rows). Give ``vertices`` or ``rows``.
    connectivity : {4, 8}, default 4
        The neighbours visited.
    order : {"stack", "queue"} or Order, default "stack"
        The pending pixels last in first out (the recursion's order) or first in first out.
    span : bool, default False
        The span (scan-line seed) fill: fill each run of the row, push one seed per run above and
        below.

    Returns
    -------
    Answer
        The trace (each pixel popped, filled, and the neighbours pushed) and the filled pixels.

    Examples
    --------
    >>> sol = fill("flood", (1, 1), rows="####/#..#/####")
    >>> sorted(sol.pixels())
    [(1, 1), (2, 1)]
    >>> len(list(fill("boundary", (2, 2), vertices=[(0, 0), (5, 0), (5, 4), (0, 4)]).pixels()))
    12
    """
    texts = None if rows is None else ([rows] if isinstance(rows, str) else list(rows))
    sx, sy = _pair(seed, "seed")
    return answers_fill.seed_fill_solution(
        _choice(method, "method"),
        (_whole(sx, "seed"), _whole(sy, "seed")),
        vertices=None if vertices is None else _flat(vertices, "vertices"),
        rows=texts,
        connectivity=_whole(connectivity, "connectivity"),
        order=_choice(order, "order"),
        span=bool(span),
    )


@answers
def antialias_line(
    x1: Annotated[NumberLike, Arg()],
    y1: Annotated[NumberLike, Arg()],
    x2: Annotated[NumberLike, Arg()],
    y2: Annotated[NumberLike, Arg()],
    method: Annotated[AAMethod | AAMethodName, AA_METHOD] = "area",
    samples: Annotated[
        NumberLike | None,
        Opt(
            "--samples",
            "-n",
            help="N x N samples (supersample, 1-16, default 4) or sub-pixels (subpixel, "
            "default 3) per pixel.",
            kind="integer",
            show_default=False,
        ),
    ] = None,
    levels: Annotated[NumberLike, LEVELS] = 8,
    ends: Annotated[WuEnds | WuEndsName | None, WU_ENDS] = None,
    width: Annotated[
        NumberLike,
        Opt(
            "--width",
            "-w",
            help="area, supersample: the line's width w (default 1 pixel).",
            metavar="W",
        ),
    ] = 1,
    across: Annotated[
        Across | AcrossName,
        Opt(
            "--across",
            help="area, supersample: w measured along the minor axis (minor, the default: a "
            "parallelogram) or perpendicular to the line (a rectangle).",
        ),
    ] = "minor",
    subgrid: Annotated[
        Subgrid | SubgridName | None,
        Opt(
            "--subgrid",
            help="subpixel: the sub-pixel line from P1's first sub-pixel over every sub-column "
            "of the end pixels (span, the default) or between the end pixels' centre "
            "sub-pixels (centre).",
        ),
    ] = None,
    divide: Annotated[
        Divide | DivideName | None,
        Opt(
            "--divide",
            help="subpixel: intensity c / n (n, the default: n levels above zero) or c / n^2 "
            "(n2: the fraction of the pixel's sub-pixels).",
        ),
    ] = None,
) -> Solution:
    """An anti-aliased line (``scanconv antialias line``).

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The end points.
    method : {"area", "supersample", "wu", "subpixel"} or AAMethod, default "area"
        ``"area"``: exact covered area of the line's rectangle (w wide) per pixel;
        ``"supersample"``: the fraction of ``samples x samples`` points inside; ``"wu"``:
        Xiaolin Wu's algorithm, two pixels per step of the major axis; ``"subpixel"``: Hearn &
        Baker's supersampling, Bresenham's line on the ``samples x samples`` sub-pixel grid.
    samples : int, optional
        Per pixel side: default 4 (``"supersample"``), 3 (``"subpixel"``).
    levels : int, default 8
        The grey levels an intensity is quantized to.
    ends : {"full", "coverage"} or WuEnds, optional
        Wu only: end points at full intensity (default), or weighted by the part of the end
        column the line covers (xgap, as Wikipedia's pseudocode).
    width : number, default 1
        The line's width w (``"area"``, ``"supersample"``).
    across : {"minor", "perpendicular"} or Across, default "minor"
        How w is measured: along the minor axis, or perpendicular to the line.
    subgrid : {"span", "centre"} or Subgrid, optional
        ``"subpixel"``: the sub-pixel line from end to end of the pixels (default), or between the
        end pixels' centres.
    divide : {"n", "n2"} or Divide, optional
        ``"subpixel"``: the intensity ``I = c / n`` (default) or ``c / n²`` for c sub-pixels on.

    Returns
    -------
    Answer
        The table of intensities (``"wu"``: per step, both pixels with their intensities and
        levels) and the derivation, ending in the check that the intensities sum to the area.

    Notes
    -----
    Wu's line: Wu, "An efficient antialiasing technique", SIGGRAPH 1991; the two pixels of
    column x share ``1 - frac(y)`` and ``frac(y)`` of the ideal ``y = y1 + m (x - x1)``.

    Examples
    --------
    >>> sol = antialias_line(0, 0, 4, 3, width=2, across="perpendicular")
    >>> sol.derived[-2].text
    'sum of I = 10 = the exact area of the shape'
    >>> [(s.extra[2], s.extra[4], s.extra[5]) for s in antialias_line(0, 0, 4, 1, method="wu").steps()]
    [((0, 0), 1, 0), ((1, 0), Fraction(3, 4), Fraction(1, 4)), ((2, 0), Fraction(1, 2), Fraction(1, 2)), ((3, 0), Fraction(1, 4), Fraction(3, 4)), ((4, 1), 1, 0)]
    """
    return answers_antialias.antialias_solution(
        "line",
        _numbers(x1=x1, y1=y1, x2=x2, y2=y2),
        method=_choice(method, "method"),
        samples=None if samples is None else _whole(samples, "samples"),
        levels=_whole(levels, "levels"),
        ends=_maybe(ends, "ends"),
        width=_number(width, "width"),
        across=_choice(across, "across"),
        subgrid=_maybe(subgrid, "subgrid"),
        divide=_maybe(divide, "divide"),
    )


@answers
def antialias_circle(
    r: Annotated[NumberLike, Arg()],
    center: Annotated[PointLike, CENTER] = (0, 0),
    method: Annotated[AAMethod | AAMethodName, AA_METHOD] = "area",
    samples: Annotated[NumberLike, AA_SAMPLES] = 4,
    levels: Annotated[NumberLike, LEVELS] = 8,
) -> Solution:
    """An anti-aliased circle one pixel wide (``scanconv antialias circle``).

    Parameters
    ----------
    r : number
        The radius.
    center : (x, y), default (0, 0)
        The centre.
    method : {"area", "supersample"} or AAMethod, default "area"
        ``"area"``: each pixel's intensity is the exact area of the shape over the pixel's unit
        square (centred on the integer point); ``"supersample"``: the fraction of
        ``samples x samples`` sample points inside.
    samples : int, default 4
        Sample points per pixel side (``"supersample"``).
    levels : int, default 8
        The grey levels an intensity I is quantized to (``round(I (levels - 1))``).

    Returns
    -------
    Answer
        The table ``pixel, intensity, exact, level`` of the pixels with I > 0, bottom row first.

    Examples
    --------
    >>> sol = antialias_circle(3)
    >>> list(sol.tables[0].rows())[0]
    ((-2, -3), 0.35165884296966743, '-', 2)
    >>> round(sum(float(v) for _, v, *_ in sol.tables[0].rows()), 6)  # the ring's area, 2πr
    18.849556
    """
    return answers_antialias.antialias_solution(
        "circle",
        (_number(r, "r"), *_pair(center, "center")),
        method=_choice(method, "method"),
        samples=_whole(samples, "samples"),
        levels=_whole(levels, "levels"),
    )


@answers
def antialias_polygon(
    vertices: Annotated[PointsLike, VERTICES],
    method: Annotated[AAMethod | AAMethodName, AA_METHOD] = "area",
    samples: Annotated[NumberLike, AA_SAMPLES] = 4,
    levels: Annotated[NumberLike, LEVELS] = 8,
    rule: Annotated[FillRule | FillRuleName, RULE] = "even-odd",
) -> Solution:
    """An anti-aliased polygon (``scanconv antialias polygon``): exact covered areas, or the
    fraction of samples inside.

    Parameters
    ----------
    vertices : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The polygon's vertices in order, exact numbers.
    method : {"area", "supersample"} or AAMethod, default "area"
        ``"area"``: each pixel's intensity is the exact area of the shape over the pixel's unit
        square (centred on the integer point); ``"supersample"``: the fraction of
        ``samples x samples`` sample points inside.
    samples : int, default 4
        Sample points per pixel side (``"supersample"``).
    levels : int, default 8
        The grey levels an intensity I is quantized to (``round(I (levels - 1))``).
    rule : {"even-odd", "nonzero"} or FillRule, default "even-odd"
        The inside rule.

    Returns
    -------
    Answer
        The table ``pixel, intensity, exact, level`` of the pixels with I > 0, bottom row first,
        and the check that the intensities sum to the polygon's area.

    Examples
    --------
    >>> sol = antialias_polygon([(0, 0), (2, 0), (2, 1), (0, 1)])
    >>> [(row[0], row[2]) for row in sol.tables[0].rows()][:3]
    [((0, 0), '1/4'), ((1, 0), '1/2'), ((2, 0), '1/4')]
    >>> sol.derived[-2].value  # the area
    2
    """
    return answers_antialias.antialias_solution(
        "polygon",
        _flat(vertices, "vertices"),
        method=_choice(method, "method"),
        samples=_whole(samples, "samples"),
        levels=_whole(levels, "levels"),
        rule_name=_choice(rule, "rule"),
    )
