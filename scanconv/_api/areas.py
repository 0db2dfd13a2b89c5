"""The Python API: filled areas and anti-aliasing (``scanconv polygon``, ``fill``, ``antialias``). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..core import lazy
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
from ..display import answers
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
    from ..algorithms.choices import WuEnds
    from ..algorithms.process_choices import AAMethod, Across, Divide, FillRule, Order, Subgrid
    from ..answers import antialias as answers_antialias
    from ..answers import fill as answers_fill
    from ..answers import polygon as answers_polygon
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_antialias = lazy.module("scanconv.answers.antialias")
    answers_fill = lazy.module("scanconv.answers.fill")
    answers_polygon = lazy.module("scanconv.answers.polygon")


@answers
def polygon(vertices: PointsLike, rule: FillRule | FillRuleName = "even-odd") -> Solution:
    """The scan-line fill of the polygon ``vertices`` (``scanconv polygon``): the edge table,
    the active edge table per scan line, the spans and the pixels.

    >>> sol = polygon([(0, 0), (4, 0), (2, 3)])
    >>> list(sol.pixels())
    [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
    """
    return answers_polygon.polygon_solution(_flat(vertices, "vertices"), _choice(rule, "rule"))


@answers
def fill(
    method: FillMethodName,
    seed: PointLike,
    *,
    vertices: PointsLike | None = None,
    rows: str | Sequence[str] | None = None,
    connectivity: NumberLike = 4,
    order: Order | OrderName = "stack",
    span: bool = False,
) -> Solution:
    """A seed fill (``scanconv fill boundary``, ``scanconv fill flood``): ``method`` is
    ``"boundary"`` or ``"flood"``, over the Bresenham outline of the polygon ``vertices`` or
    over the grid ``rows`` (text, top row first: ``#`` boundary, ``.`` empty); ``span`` gives the
    span (scan-line seed) fill.

    >>> sorted(fill("flood", (1, 1), rows="####/#..#/####").pixels())
    [(1, 1), (2, 1)]
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
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    method: AAMethod | AAMethodName = "area",
    samples: NumberLike | None = None,
    levels: NumberLike = 8,
    ends: WuEnds | WuEndsName | None = None,
    width: NumberLike = 1,
    across: Across | AcrossName = "minor",
    subgrid: Subgrid | SubgridName | None = None,
    divide: Divide | DivideName | None = None,
) -> Solution:
    """An anti-aliased line (``scanconv antialias line``): ``method`` ``"wu"`` (Xiaolin Wu's
    algorithm), ``"area"`` or ``"supersample"`` (``samples`` x ``samples`` per pixel).
    ``ends`` (Wu only): ``"full"`` (the default) or ``"coverage"`` (the end columns weighted
    by the part of them the line covers, as Wikipedia's pseudocode). ``width`` (area and
    supersample): the line's width w, measured ``across`` the minor axis (``"minor"``, the
    default) or ``"perpendicular"`` to the line. ``"subpixel"``: Hearn & Baker's
    supersampling, Bresenham on the ``samples x samples`` sub-pixel grid (default 3; the
    ``supersample`` default is 4), its ``subgrid`` ``"span"`` (the default) or ``"centre"``,
    and ``divide``: ``I = c / n`` (``"n"``, the default) or ``c / n²`` (``"n2"``).

    >>> sol = antialias_line(0, 0, 4, 3, width=2, across="perpendicular")
    >>> sol.derived[-2].text
    'sum of I = 10 = the exact area of the shape'

    >>> [s.extra[4] for s in antialias_line(0, 0, 4, 1, method="wu").steps()]
    [1, Fraction(3, 4), Fraction(1, 2), Fraction(1, 4), 1]
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
    r: NumberLike,
    center: PointLike = (0, 0),
    method: AAMethod | AAMethodName = "area",
    samples: NumberLike = 4,
    levels: NumberLike = 8,
) -> Solution:
    """An anti-aliased circle one pixel wide (``scanconv antialias circle``).

    >>> round(sum(float(v) for _, v, *_ in antialias_circle(3).tables[0].rows()), 6)
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
    vertices: PointsLike,
    method: AAMethod | AAMethodName = "area",
    samples: NumberLike = 4,
    levels: NumberLike = 8,
    rule: FillRule | FillRuleName = "even-odd",
) -> Solution:
    """An anti-aliased polygon (``scanconv antialias polygon``): exact covered areas, or the
    fraction of ``samples`` x ``samples`` samples inside.

    >>> antialias_polygon([(0, 0), (2, 0), (2, 1), (0, 1)]).derived[-2].value
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
