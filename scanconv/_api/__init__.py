"""The Python API: one function per command of the command line, each returning an
:class:`~scanconv.display.Answer` (a :class:`~scanconv.core.records.Solution` that shows
itself).

The keywords are the library's parameter names; the choices are strings or the library's enums
(:class:`LineAlgorithm`, :class:`CircleMethod`, :class:`Rounding`). A number may be an ``int``,
a :class:`~fractions.Fraction`, a ``float`` (read as the decimal it prints as, so ``0.1`` is
exactly 1/10, as on the command line) or a string (``"5/2"``, ``"-3"``, ``"1e3"``); a formula
parameter (``t``, ``t_range``, ``domain``, ``value_range`` of :func:`sample`) also takes a
constant expression such as ``"2*pi"``. Bad input raises
:class:`~scanconv.core.checks.InputError` (a ``ValueError``) naming the parameter where this
module finds it, and the library's ``ValueError`` otherwise.

Render a solution with :func:`scanconv.render.render`, or read it directly:

>>> sol = circle(5, method="bresenham")
>>> [step.pixel for step in sol.steps()]
[(0, 5), (1, 5), (2, 5), (3, 4)]

The library modules are imported inside the functions: importing this module stays cheap.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from enum import Enum
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..algorithms.choices import (
    Convention,
    Layout,
    LineAlgorithm,
    Rounding,
    Start,
    Tie,
)
from ..core.checks import InputError
from ..core.numeric import COORD_LIMIT, Number, fmt_short, parse_number
from ..display import answers

if TYPE_CHECKING:
    from decimal import Decimal

    import numpy as np

    from ..algorithms.circle_choices import P0, CircleMethod, Loop, Update
    from ..algorithms.process_choices import (
        AAMethod,
        FillRule,
        LineClipMethod,
        Order,
        PolygonClipMethod,
    )
    from ..core.records import Solution

__all__ = [
    "CircleMethod",
    "LineAlgorithm",
    "LineClipMethod",
    "PolygonClipMethod",
    "Rounding",
    "antialias_circle",
    "antialias_line",
    "antialias_polygon",
    "bezier",
    "bezier_at",
    "bspline",
    "bspline_at",
    "bspline_basis",
    "circle",
    "clip_line",
    "clip_polygon",
    "compare_circles",
    "compare_curves",
    "compare_lines",
    "continuity",
    "ellipse",
    "fill",
    "line",
    "local_control",
    "parametric_circle",
    "parametric_custom",
    "parametric_ellipse",
    "parametric_line",
    "parametric_parabola",
    "pipeline_line",
    "pipeline_polygon",
    "polygon",
    "quantize",
    "ramp",
    "sample",
    "storage",
    "transform",
    "viewport",
]

if TYPE_CHECKING:
    NumberLike = int | Fraction | float | Decimal | str | np.integer[Any] | np.floating[Any]
else:  # decimal is imported only by callers that pass a Decimal (start-up time)
    NumberLike = int | Fraction | float | str
"""What a number parameter takes: an int, Fraction, float, decimal.Decimal, numpy scalar or
string."""

PointLike = tuple[NumberLike, NumberLike]
"""A point ``(x, y)``."""

PointsLike = Sequence[PointLike] | Sequence[NumberLike]
"""Control points: ``[(x0, y0), (x1, y1), ...]`` or flat, ``[x0, y0, x1, y1, ...]``."""

FormulaLike = NumberLike
"""A number, or a constant expression in a string (``"2*pi"``, ``"1/3"``)."""

TRangeLike = tuple[FormulaLike, FormulaLike]
"""The range of a curve's parameter t: two formulas (``(0, "2*pi")``)."""


# --- lines, circles, ellipses ------------------------------------------------------------------


@answers
def line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    algo: LineAlgorithm | str = "bresenham",
    *,
    rounding: Rounding | str | None = None,
    tie: Tie | str | None = None,
    start: Start | str | None = None,
    convention: Convention | str | None = None,
    layout: Layout | str = "notes",
    derive: bool = False,
    pseudocode: bool = False,
) -> Solution:
    """The line from ``(x1, y1)`` to ``(x2, y2)`` by ``algo``, worked as in the notes
    (``scanconv line``).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2. A float is read as the decimal it prints as (``0.1`` is
        1/10); a string may be ``"5/2"``. NaN, infinities and ``|value| > 10**9`` are refused.
    algo : {"bresenham", "dda", "basic", "wu"} or LineAlgorithm, default "bresenham"
        The line algorithm.
    rounding : {"half-up", "trunc", "half-even", "c-cast", "half-away"}, optional
        How the DDA and the basic method round a coordinate to a pixel (default half-up).
    tie : {"step", "keep"}, optional
        Bresenham: what a decision parameter of 0 does (default step).
    start : {"swap", "given"}, optional
        Which end is plotted first: Bresenham swaps to the end with the smaller major
        coordinate, the DDA starts at P1 (``given``).
    convention : {"notes", "hearn-baker", "foley", "wikipedia"}, optional
        A named preset of the conventions above; a convention given alone overrides it.
    layout : {"notes", "textbook"}, default "notes"
        The table's rows: the notes' (the decision, then the pixel it chooses) or the
        textbook's (one row per plotted pixel).
    derive, pseudocode : bool, default False
        Add the derivation with these numbers, and the pseudocode of the variant used.

    Returns
    -------
    Answer
        The worked answer: ``.steps()`` (the table's rows), ``.pixels()``, ``.rows()``,
        ``.to("markdown")``.

    Raises
    ------
    InputError
        A bad value; ``.param`` names the parameter.

    Examples
    --------
    >>> list(line(0, 0, 3, 1).pixels())
    [(0, 0), (1, 0), (2, 1), (3, 1)]
    >>> list(line(2, 2, 10, 6, algo="dda").pixels())
    [(2, 2), (3, 3), (4, 3), (5, 4), (6, 4), (7, 5), (8, 5), (9, 6), (10, 6)]
    >>> list(line(4, 2, 0, 0).pixels()), list(line(4, 2, 0, 0, start="given").pixels())
    ([(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)], [(4, 2), (3, 1), (2, 1), (1, 0), (0, 0)])
    >>> [s.pixel for s in line("1/2", 0, 3.5, 1, algo=LineAlgorithm.dda).steps()]
    [(1, 0), (2, 0), (3, 1), (4, 1)]
    >>> list(line(0, 0, 4, 2, tie="keep").pixels())
    [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]
    """
    from ..answers.line import line_solution

    coords = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return line_solution(
        _choice(algo, "algo"),
        *coords,
        rounding=_maybe(rounding, "rounding"),
        tie=_maybe(tie, "tie"),
        start=_maybe(start, "start"),
        convention=_maybe(convention, "convention"),
        layout=_choice(layout, "layout"),
        derive=derive,
        pseudocode=pseudocode,
        annotate=True,
    )


@answers
def circle(
    r: NumberLike,
    center: PointLike = (0, 0),
    method: CircleMethod | str = "midpoint",
    rounding: Rounding | str | None = None,
    *,
    tie: Tie | str | None = None,
    p0: P0 | str | None = None,
    loop: Loop | str | None = None,
    update: Update | str | None = None,
    convention: Convention | str | None = None,
    layout: Layout | str = "notes",
    derive: bool = False,
    pseudocode: bool = False,
) -> Solution:
    """The circle of radius ``r`` about ``center`` by ``method``, worked as in the notes
    (``scanconv circle``).

    Parameters
    ----------
    r : int, Fraction, float, Decimal, numpy scalar or str
        The radius, a whole number >= 0.
    center : (x, y), default (0, 0)
        The centre, whole numbers.
    method : {"midpoint", "bresenham", "polynomial", "general", "trig", "symmetric-dda"}
        The method (default midpoint); a CircleMethod too.
    rounding : {"half-up", "trunc", "half-even", "c-cast", "half-away"}, optional
        How the floating-point methods (polynomial, trig, symmetric-dda) round to a pixel.
    tie : {"step", "keep"}, optional
        The decision methods: what a decision parameter of 0 does.
    p0 : {"1-r", "5/4-r"}, optional
        The midpoint method's initial decision parameter.
    loop : {"strict", "inclusive"}, optional
        Whether the octant's loop runs while x < y or x <= y.
    update : {"new", "old"}, optional
        Whether the decision update uses the new x (and y) or the old.
    convention : {"notes", "hearn-baker", "foley", "wikipedia"}, optional
        A named preset of the conventions above.
    layout : {"notes", "textbook"}, default "notes"
        The table's rows, as for :func:`line`.
    derive, pseudocode : bool, default False
        Add the derivation and the pseudocode.

    Returns
    -------
    Answer
        The worked answer: the octant's table (``.steps()``) and every pixel by 8-way
        symmetry (``.pixels()``).

    Raises
    ------
    InputError
        A bad value (a negative or fractional radius, an unknown method).

    Examples
    --------
    >>> [s.pixel for s in circle(5).steps()]
    [(0, 5), (1, 5), (2, 5), (3, 4), (4, 3)]
    >>> list(circle(5).pixels())[:4]
    [(0, 5), (0, -5), (5, 0), (-5, 0)]
    >>> [s.pixel for s in circle(5, layout="textbook").steps()]
    [(1, 5), (2, 5), (3, 4), (4, 3)]
    >>> [s.p for s in circle(5, method="general").steps()]
    [0, -5, 0, 1]
    >>> circle(5, (10, 10), method="trig", rounding="trunc").data["rounding"]
    'trunc'
    """
    from ..answers.circle import circle_solution

    radius = _number(r, "r")
    xc, yc = _pair(center, "center")
    return circle_solution(
        _choice(method, "method"),
        radius,
        xc,
        yc,
        rounding=_maybe(rounding, "rounding"),
        tie=_maybe(tie, "tie"),
        p0=_maybe(p0, "p0"),
        loop=_maybe(loop, "loop"),
        update=_maybe(update, "update"),
        convention=_maybe(convention, "convention"),
        layout=_choice(layout, "layout"),
        derive=derive,
        pseudocode=pseudocode,
        annotate=True,
    )


@answers
def ellipse(
    rx: NumberLike,
    ry: NumberLike,
    center: PointLike = (0, 0),
    *,
    loop: Loop | str | None = None,
    tie: Tie | str | None = None,
    p0: str | None = None,
    convention: Convention | str | None = None,
    derive: bool = False,
    pseudocode: bool = False,
) -> Solution:
    """The midpoint ellipse with semi-axes ``rx``, ``ry`` about ``center``, worked in its two
    regions (``scanconv ellipse``).

    Parameters
    ----------
    rx, ry : int, Fraction, float, Decimal, numpy scalar or str
        The semi-axes along x and y, whole numbers >= 0.
    center : (x, y), default (0, 0)
        The centre, whole numbers.
    loop : {"strict", "inclusive"}, optional
        Region 1's loop condition.
    tie : {"step", "keep"}, optional
        ``step``: p = 0 chooses SE in both regions; ``keep``: E in region 1, S in region 2.
    p0 : {"exact", "rounded"}, optional
        The initial decision parameters, exact or rounded as Hearn & Baker's C code.
    convention : {"notes", "hearn-baker", "foley", "wikipedia"}, optional
        A named preset of the conventions above.
    derive, pseudocode : bool, default False
        Add the derivation and the pseudocode.

    Returns
    -------
    Answer
        The worked answer: the quadrant's table over both regions (``.steps()``) and every
        pixel by 4-way symmetry (``.pixels()``).

    Raises
    ------
    InputError
        A bad value.

    Examples
    --------
    >>> [s.pixel for s in ellipse(3, 2).steps()]
    [(1, 2), (2, 1), (3, 0)]
    >>> sorted(ellipse(2, 1).pixels())
    [(-2, 0), (-1, -1), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 1), (2, 0)]
    """
    from ..answers.ellipse import ellipse_solution

    a, b = _numbers(rx=rx, ry=ry)
    xc, yc = _pair(center, "center")
    return ellipse_solution(
        a,
        b,
        xc,
        yc,
        loop=_maybe(loop, "loop"),
        tie=_maybe(tie, "tie"),
        p0=_maybe(p0, "p0"),
        convention=_maybe(convention, "convention"),
        derive=derive,
        pseudocode=pseudocode,
        annotate=True,
    )


@answers
def compare_lines(
    x1: NumberLike, y1: NumberLike, x2: NumberLike, y2: NumberLike, theory: bool = False
) -> Solution:
    """The basic method, DDA and Bresenham side by side (``scanconv compare line``).

    >>> len(list(compare_lines(2, 8, 10, 4).tables[0].rows()))  # x = 2 .. 10
    9
    """
    from ..answers.compare import compare_lines as solution

    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return solution(a, b, c, d, theory=theory)


@answers
def compare_circles(r: NumberLike, theory: bool = False) -> Solution:
    """Every circle method over the first octant (``scanconv compare circle``).

    >>> len(list(compare_circles(10).tables[0].rows()))
    8
    """
    from ..answers.compare import compare_circles as solution

    return solution(_number(r, "r"), theory=theory)


@answers
def compare_curves() -> Solution:
    """Bezier vs B-spline: the points of the notes' comparison (``scanconv compare curves``).

    >>> compare_curves().title
    'Bezier vs B-spline curves'
    """
    from ..answers.compare import compare_curves as solution

    return solution()


# --- image representation ---------------------------------------------------------------------


@answers
def storage(
    m: NumberLike,
    n: NumberLike,
    *,
    levels: NumberLike | None = None,
    bits: NumberLike | None = None,
    binary: bool = False,
    color: str | None = None,
    frames: NumberLike = 1,
) -> Solution:
    """The storage of an ``m`` x ``n`` image (``scanconv storage``): give exactly one of
    ``levels``, ``bits``, ``binary`` or ``color="rgb24"``.

    >>> storage(1024, 768, levels=256).data["sizes"]["KiB"]
    Fraction(768, 1)
    """
    from ..answers.storage import storage_solution

    return storage_solution(
        *_numbers(m=m, n=n),
        levels=_optional(levels, "levels"),
        bits=_optional(bits, "bits"),
        binary=binary,
        color=None if color is None else _choice(color, "color"),
        frames=_number(frames, "frames"),
    )


@answers
def quantize(
    bits: NumberLike,
    value_range: tuple[NumberLike, NumberLike] | None = None,
    *,
    integer: bool = True,
    recon: str = "midpoint",
) -> Solution:
    """The quantization table for ``bits`` bits over ``value_range`` (``scanconv quantize``):
    integer inputs ``LO..HI``, or with ``integer=False`` real ones in ``[LO, HI]``; ``recon`` is
    ``"midpoint"`` or ``"lower"``.

    >>> [row[-1] for row in quantize(2, (0, 255)).tables[0].rows()]
    [32, 96, 160, 224]
    """
    from ..answers.quantize import quantize_solution

    return quantize_solution(
        _number(bits, "bits"),
        None if value_range is None else _pair(value_range, "value_range"),
        integer=integer,
        recon=_choice(recon, "recon"),
    )


@answers
def sample(
    expr: str,
    size: str | int | tuple[int, int],
    levels: NumberLike,
    *,
    domain: tuple[FormulaLike, FormulaLike, FormulaLike, FormulaLike] | None = None,
    value_range: tuple[FormulaLike, FormulaLike] | None = None,
    origin: str = "bottom-left",
) -> Solution:
    """Sample ``f(x, y) = expr`` on an M x N grid and quantize it to ``levels`` levels
    (``scanconv sample``). ``size`` is ``"MxN"``, ``M`` or ``(M, N)``; ``domain`` is
    ``(X0, X1, Y0, Y1)``; ``value_range`` the range of f mapped onto the levels.

    >>> next(iter(sample("x + y", "8x8", 8).tables[0].rows()))
    (0, 4, 4, 5, 5, 6, 6, 7, 7)
    """
    from ..algorithms.sample import sample_levels
    from ..answers.sample import sample_solution

    m, n = _size(size)
    sampled = sample_levels(
        expr,
        m,
        n,
        _number(levels, "levels"),
        domain=None if domain is None else _formulas(domain, "domain", 4),
        value_range=None if value_range is None else _formulas(value_range, "value_range", 2),
        origin=_choice(origin, "origin"),
    )
    return sample_solution(sampled)


@answers
def ramp(size: str | int | tuple[int, int] = "8", levels: NumberLike = 8) -> Solution:
    """The notes' grayscale ramp, ``i + j`` folded back at ``L - 1`` (``scanconv image ramp``).

    >>> next(iter(ramp(8, 8).tables[0].rows()))
    (0, 0, 1, 2, 3, 4, 5, 6, 7)
    """
    from ..answers.ramp import ramp_solution

    m, n = _size(size)
    return ramp_solution(m, n, _number(levels, "levels"))


# --- curves -----------------------------------------------------------------------------------


@answers
def parametric_circle(
    center: PointLike = (0, 0),
    radius: NumberLike = 1,
    *,
    t_range: TRangeLike | None = None,
    samples: NumberLike | None = None,
) -> Solution:
    """``x = xc + r cos t``, ``y = yc + r sin t`` (``scanconv parametric circle``).

    ``samples`` steps of t over ``t_range`` (default: 16 steps over ``0 .. 2*pi``).

    >>> list(parametric_circle(radius=5, samples=4).pixels())[:3]
    [(5, 0), (4, 1), (3, 2)]
    """
    return _parametric(
        "circle",
        t_range,
        samples,
        center=_pair(center, "center"),
        radius=_number(radius, "radius"),
    )


@answers
def parametric_ellipse(
    center: PointLike = (0, 0),
    a: NumberLike = 2,
    b: NumberLike = 1,
    *,
    t_range: TRangeLike | None = None,
    samples: NumberLike | None = None,
) -> Solution:
    """``x = xc + a cos t``, ``y = yc + b sin t`` (``scanconv parametric ellipse``).

    >>> list(parametric_ellipse(a=8, b=4, samples=4).pixels())[0]
    (8, 0)
    """
    point = _pair(center, "center")
    a, b = _numbers(a=a, b=b)
    return _parametric("ellipse", t_range, samples, center=point, a=a, b=b)


@answers
def parametric_parabola(
    vertex: PointLike = (0, 0),
    a: NumberLike = 1,
    *,
    t_range: TRangeLike | None = None,
    samples: NumberLike | None = None,
) -> Solution:
    """``x = h + t``, ``y = k + a t^2`` (``scanconv parametric parabola``; t from -3 to 3).

    >>> [s.pixel for s in parametric_parabola(samples=2).steps()]
    [(-3, 9), (0, 0), (3, 9)]
    """
    point = _pair(vertex, "vertex")
    return _parametric("parabola", t_range, samples, vertex=point, a=_number(a, "a"))


@answers
def parametric_line(
    x0: NumberLike,
    y0: NumberLike,
    x1: NumberLike,
    y1: NumberLike,
    *,
    t_range: TRangeLike | None = None,
    samples: NumberLike | None = None,
) -> Solution:
    """``x = x0 + t (x1 - x0)``, ``y = y0 + t (y1 - y0)`` (``scanconv parametric line``).

    >>> list(parametric_line(0, 0, 4, 2).pixels())
    [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    """
    points = _numbers(x0=x0, y0=y0, x1=x1, y1=y1)
    return _parametric("line", t_range, samples, points=points)


@answers
def parametric_custom(
    x: str,
    y: str,
    *,
    t_range: TRangeLike | None = None,
    samples: NumberLike | None = None,
) -> Solution:
    """Your own ``x(t)`` and ``y(t)`` (``scanconv parametric custom``).

    >>> list(parametric_custom("t", "t*t", t_range=(0, 2), samples=2).pixels())
    [(0, 0), (1, 1), (1, 2), (2, 3), (2, 4)]
    """
    return _parametric("custom", t_range, samples, x=x, y=y)


@answers
def bezier(points: PointsLike, samples: NumberLike | None = None) -> Solution:
    """The Bezier curve of ``points`` at ``samples`` steps of t (default 16)
    (``scanconv bezier``).

    >>> list(bezier([(0, 0), (1, 2), (3, 3), (4, 0)], 8).pixels())
    [(0, 0), (0, 1), (1, 1), (1, 2), (2, 2), (3, 2), (4, 1), (4, 0)]
    """
    from ..algorithms.curve_limits import DEFAULT_SAMPLES
    from ..answers.bezier import bezier_solution

    pts = _points(points)
    return bezier_solution(pts, _whole(DEFAULT_SAMPLES if samples is None else samples, "samples"))


@answers
def bezier_at(points: PointsLike, t: FormulaLike) -> Solution:
    """De Casteljau's construction at one ``t`` in [0, 1] (``scanconv bezier --at``).

    >>> list(bezier_at([0, 0, 1, 2, 3, 3, 4, 0], "1/2").pixels())  # B(1/2) = (2, 1.875)
    [(2, 2)]
    """
    from ..answers.bezier import bezier_at_solution

    pts = _points(points)
    return bezier_at_solution(pts, _formula(t, "t"))


@answers
def bspline(
    points: PointsLike,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
    samples: NumberLike | None = None,
) -> Solution:
    """The B-spline of ``degree`` over ``points`` (``scanconv bspline``). ``knots`` is
    ``"open"``, ``"uniform"``, or the ``n + p + 2`` knot values (a list or ``"0,0,1,2,2"``);
    ``samples`` defaults to a few steps per knot span.

    >>> list(bspline([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, samples=4).pixels())[-1]
    (5, 2)
    """
    return _bspline(points, degree, knots, samples, basis_only=False)


@answers
def bspline_basis(
    points: PointsLike | None,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
    samples: NumberLike | None = None,
) -> Solution:
    """Only the table of the basis values ``N_i,p(t)`` (``scanconv bspline --basis``).

    Without control points (``points`` empty or ``None``) the degree and an explicit knot list
    define the basis, tabulated over the whole knot range ``[u_0, u_m]``.

    >>> [c.key for c in bspline_basis([0, 0, 1, 2, 3, 3], 2).tables[0].columns][:3]
    ['k', 't', 'N0']
    >>> len(list(bspline_basis(None, 2, [0, 0.25, 0.5, 0.75, 1]).tables[0].rows()))
    9
    """
    if not points:
        from ..answers.bspline import bspline_basis_knots_solution

        spec = _knots(knots)
        if isinstance(spec, str):
            raise InputError(
                "without control points the basis needs an explicit knot list "
                f"(got {spec!r}: open and uniform are defined by the number of points)",
                "knots",
            )
        return bspline_basis_knots_solution(
            _whole(degree, "degree"),
            spec,
            None if samples is None else _whole(samples, "samples"),
        )
    return _bspline(points, degree, knots, samples, basis_only=True)


@answers
def bspline_at(
    points: PointsLike,
    t: FormulaLike,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
) -> Solution:
    """One ``t``: the Cox-de Boor triangle and the weighted sum (``scanconv bspline --at``).

    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)]
    >>> list(bspline_at(pts, 1.5, 2).pixels())  # C(1.5) = (2.875, 2.5)
    [(3, 3)]
    """
    from ..answers.bspline import bspline_at_solution

    pts = _points(points)
    spec = _knots(knots)
    return bspline_at_solution(pts, _whole(degree, "degree"), spec, _formula(t, "t"))


@answers
def continuity(
    first: PointsLike, second: PointsLike, samples: NumberLike | None = None
) -> Solution:
    """C0, C1, C2 at the join of two Bezier segments (``scanconv continuity``).

    >>> continuity([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)]).data["continuity"]
    'C1'
    """
    from ..algorithms.curve_limits import DEFAULT_SAMPLES
    from ..answers.continuity import continuity_solution

    a, b = _points(first, "first"), _points(second, "second")
    steps = _whole(DEFAULT_SAMPLES if samples is None else samples, "samples")
    return continuity_solution(a, b, steps)


@answers
def local_control(
    points: PointsLike,
    index: NumberLike,
    moved: PointLike,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
    samples: NumberLike | None = None,
) -> Solution:
    """Move control point ``index`` to ``moved``: what changes on the Bezier curve and on the
    B-spline (``scanconv local-control``).

    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> sol = local_control(pts, 5, (7, 5), 2, samples=8)
    >>> sol.data["bezier_samples_moved"], sol.data["bspline_samples_moved"]
    (8, 2)
    """
    from ..algorithms.curve_limits import DEFAULT_SAMPLES
    from ..answers.local_control import local_control_solution

    pts = _points(points)
    spec = _knots(knots)
    return local_control_solution(
        pts,
        _whole(index, "index"),
        _pair(moved, "moved"),
        _whole(degree, "degree"),
        spec,
        _whole(DEFAULT_SAMPLES if samples is None else samples, "samples"),
    )


def _parametric(
    kind: str,
    t_range: TRangeLike | None,
    samples: NumberLike | None,
    **given: Any,
) -> Solution:
    from ..answers.parametric import parametric_solution

    return parametric_solution(
        kind,
        t_range=None if t_range is None else _bounds(t_range),
        samples=None if samples is None else _whole(samples, "samples"),
        **given,
    )


def _bspline(
    points: PointsLike,
    degree: NumberLike,
    knots: str | Sequence[NumberLike],
    samples: NumberLike | None,
    *,
    basis_only: bool,
) -> Solution:
    from ..answers.bspline import bspline_solution

    pts = _points(points)
    spec = _knots(knots)
    return bspline_solution(
        pts,
        _whole(degree, "degree"),
        spec,
        None if samples is None else _whole(samples, "samples"),
        basis_only=basis_only,
    )


# --- reading the arguments ----------------------------------------------------------------------


def _number(value: NumberLike, param: str) -> Number:
    """An exact number within :data:`~scanconv.core.numeric.COORD_LIMIT`, as the command line
    reads one: an ``int``, a numpy integer or a ``Fraction`` as given; a ``float`` (numpy's
    too) as the decimal it prints as; a ``Decimal`` or a string through
    :func:`~scanconv.core.numeric.parse_number`. NaN and infinities are refused.

    >>> _number(Fraction(5, 2), "x"), _number(2.5, "x"), _number("-3", "x")
    (Fraction(5, 2), Fraction(5, 2), Fraction(-3, 1))
    """
    import numbers

    if isinstance(value, bool):
        raise InputError(f"{param} must be a number, got {value!r}", param)
    if isinstance(value, int | Fraction):
        if not -COORD_LIMIT <= value <= COORD_LIMIT:
            raise InputError(
                f"{param} = {value} is out of range (|value| <= {COORD_LIMIT:.0e})", param
            )
        return value
    decimal = sys.modules.get("decimal")  # a Decimal exists only if its module is loaded
    if isinstance(value, numbers.Integral):  # numpy's integers
        return _number(int(value), param)
    if isinstance(value, float) or (
        isinstance(value, numbers.Real) and not isinstance(value, numbers.Rational)
    ):  # numpy's floats too, whose repr is np.float64(2.5)
        text = repr(float(value))
    elif decimal is not None and isinstance(value, decimal.Decimal):
        text = str(value)
    elif isinstance(value, str):
        text = value
    else:
        raise InputError(f"{param} must be a number, got {value!r}", param)
    try:
        return parse_number(text)
    except ValueError as err:
        raise InputError(str(err), param) from None


def _numbers(**values: NumberLike) -> tuple[Number, ...]:
    return tuple(_number(v, name) for name, v in values.items())


def _optional(value: NumberLike | None, param: str) -> Number | None:
    return None if value is None else _number(value, param)


def _whole(value: NumberLike, param: str) -> int:
    v = _number(value, param)
    if isinstance(v, Fraction):
        if v.denominator != 1:
            raise InputError(f"{param} must be an integer, got {fmt_short(v)}", param)
        return v.numerator
    return v


def _pair(values: Sequence[NumberLike], param: str) -> tuple[Number, Number]:
    """A point or a range: two numbers."""
    if isinstance(values, str) or len(values) != 2:
        raise InputError(f"{param} takes 2 numbers, got {values!r}", param)
    return _number(values[0], param), _number(values[1], param)


def _formula(value: FormulaLike, param: str) -> Any:
    """A value of a parameter such as ``t``: a number, or a constant expression (exact when it
    is rational; ``"pi/4"`` is a float)."""
    if isinstance(value, str):
        from ..core.expr import parse_exact

        try:
            parsed: Any = parse_exact(value)
        except ValueError as err:
            raise InputError(str(err), param) from None
    else:
        parsed = _number(value, param)
    if isinstance(parsed, Fraction) and parsed.denominator == 1:
        return parsed.numerator
    return parsed


def _formulas(values: Sequence[FormulaLike], param: str, count: int) -> tuple[Any, ...]:
    """``domain`` and ``value_range`` of :func:`sample`: numbers or constant expressions."""
    if isinstance(values, str) or len(values) != count:
        raise InputError(f"{param} takes {count} values, got {values!r}", param)
    from ..core.expr import parse_exact

    out = []
    for v in values:
        try:
            out.append(parse_exact(v) if isinstance(v, str) else _number(v, param))
        except ValueError as err:
            raise InputError(str(err), param) from None
    return tuple(out)


def _bounds(values: TRangeLike) -> tuple[Any, Any]:
    """``t_range``: formulas stay text, for the answer to show them as given (``2π``)."""
    if isinstance(values, str) or len(values) != 2:
        raise InputError(f"t_range takes 2 values, got {values!r}", "t_range")
    lo, hi = (v if isinstance(v, str) else _number(v, "t_range") for v in values)
    return lo, hi


def _points(values: PointsLike, param: str = "points") -> list[Any]:
    """Control points, as pairs or flat, as the library's exact pairs."""
    from ..algorithms.curve_limits import pairs

    flat: list[Any] = []
    for v in values:
        if not isinstance(v, tuple | list):
            flat.append(v)
        elif len(v) == 2:
            flat.extend(v)
        else:
            raise InputError(f"a point is a pair (x, y), got {v!r}", param)
    try:
        return pairs([_number(v, param) for v in flat])
    except InputError:
        raise
    except ValueError as err:
        raise InputError(str(err), param) from None


def _knots(value: str | Sequence[NumberLike]) -> str | tuple[Number, ...]:
    if not isinstance(value, str):
        return tuple(_number(v, "knots") for v in value)
    from ..algorithms.bspline import parse_knots

    try:
        return parse_knots(value)
    except ValueError as err:
        raise InputError(str(err), "knots") from None


def _size(value: str | int | tuple[int, int]) -> tuple[int, int]:
    if isinstance(value, str):
        from ..algorithms.image_limits import parse_size

        try:
            return parse_size(value)
        except ValueError as err:
            raise InputError(str(err), "size") from None
    if isinstance(value, tuple):
        m, n = value
        return _whole(m, "size"), _whole(n, "size")
    side = _whole(value, "size")
    return side, side


def _maybe(value: Enum | str | None, param: str) -> str | None:
    """:func:`_choice`, or ``None`` for a convention left to the preset or default."""
    return None if value is None else _choice(value, param)


def _choice(value: Enum | str, param: str) -> str:
    """A choice as the library's string (an enum member's value)."""
    if isinstance(value, Enum):
        return str(value.value)
    if isinstance(value, str):
        return value
    raise InputError(f"{param} must be a string, got {value!r}", param)


# --- the scan-conversion process: transformations, viewing, clipping ---------------------------


@answers
def transform(
    points: PointsLike, transforms: str | Sequence[str], inverse: bool = False
) -> Solution:
    """The composite of ``transforms`` applied to ``points`` (``scanconv transform``).

    ``transforms`` is a string or a list of words, applied in order: ``"rotate 90 about 2 1,
    translate 3 0"`` (see :mod:`scanconv.answers.transform`); ``inverse`` also shows M^-1.

    >>> transform([(0, 0), (4, 0)], "rotate 90 about 2 1, translate 3 0").data["after"]
    [[6, -1], [6, 3]]
    """
    from ..answers.transform import transform_solution

    return transform_solution(_flat(points, "points"), transforms, inverse_too=bool(inverse))


@answers
def viewport(
    window: Sequence[NumberLike], viewport: Sequence[NumberLike], points: PointsLike = ()
) -> Solution:
    """The window-to-viewport mapping of ``points`` (default: the window's corners)
    (``scanconv viewport``).

    >>> viewport((0, 0, 10, 10), (100, 100, 150, 200), [(5, 5)]).data["mapped"]
    [[125, 150]]
    """
    from ..answers.viewport import viewport_solution

    return viewport_solution(
        _flat(points, "points"), _rect(window, "window"), _rect(viewport, "viewport")
    )


@answers
def clip_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: Sequence[NumberLike],
    method: LineClipMethod | str = "cohen-sutherland",
) -> Solution:
    """The segment clipped against ``window`` (``scanconv clip line``).

    >>> clip_line(7, 9, 11, 4, (4, 4, 10, 8)).data["clipped"]
    [[Fraction(39, 5), 8], [10, Fraction(21, 4)]]
    """
    from ..answers.clip import clip_line_solution

    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return clip_line_solution(a, b, c, d, _rect(window, "window"), _choice(method, "method"))


@answers
def clip_polygon(
    vertices: PointsLike,
    window: Sequence[NumberLike],
    method: PolygonClipMethod | str = "sutherland-hodgman",
) -> Solution:
    """The polygon clipped against ``window`` by Sutherland-Hodgman (``scanconv clip polygon``).

    >>> clip_polygon([(0, 0), (4, 0), (0, 4)], (1, 1, 3, 3)).data["clipped"]
    [[1, 3], [1, 1], [3, 1]]
    """
    from ..answers.clip_polygon import clip_polygon_solution

    name = _choice(method, "method")
    if name != "sutherland-hodgman":
        raise InputError(f"unknown polygon clipping method {name!r} (sutherland-hodgman)", "method")
    return clip_polygon_solution(_flat(vertices, "vertices"), _rect(window, "window"))


@answers
def pipeline_line(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    window: Sequence[NumberLike],
    viewport: Sequence[NumberLike],
    algo: LineAlgorithm | str = LineAlgorithm.bresenham,
    clip: LineClipMethod | str = "cohen-sutherland",
) -> Solution:
    """A world-coordinate line clipped, mapped, rounded and scan converted
    (``scanconv pipeline line``).

    >>> pipeline_line(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10)).data["rounded"]
    [[0, 3], [20, 8]]
    """
    from ..answers.pipeline import pipeline_line_solution

    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return pipeline_line_solution(
        a,
        b,
        c,
        d,
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        algo=_choice(algo, "algo"),
        clip=_choice(clip, "clip"),
    )


@answers
def pipeline_polygon(
    vertices: PointsLike,
    window: Sequence[NumberLike],
    viewport: Sequence[NumberLike],
    fill: bool = False,
    rule: Enum | str = "even-odd",
) -> Solution:
    """A world-coordinate polygon clipped (Sutherland-Hodgman), mapped to the viewport, then
    outlined or, with ``fill``, scan-line filled (``scanconv pipeline polygon``).

    >>> pipeline_polygon([(-2, 0), (6, 0), (2, 6)], (0, 0, 4, 4), (0, 0, 8, 8)).data["device"][2]
    [0, 6]
    """
    from ..answers.pipeline import pipeline_polygon_solution

    return pipeline_polygon_solution(
        _flat(vertices, "vertices"),
        _rect(window, "window"),
        _rect(viewport, "viewport"),
        fill=bool(fill),
        rule=_choice(rule, "rule"),
    )


def _rect(values: Sequence[NumberLike], param: str) -> tuple[Number, ...]:
    """A window or viewport: four numbers ``(xmin, ymin, xmax, ymax)``."""
    if isinstance(values, str) or len(values) != 4:
        raise InputError(f"{param} takes 4 numbers (xmin ymin xmax ymax), got {values!r}", param)
    return tuple(_number(v, param) for v in values)


def _flat(values: PointsLike, param: str) -> list[Number]:
    """Points as pairs or flat, as a flat list of exact numbers (the library pairs them)."""
    flat: list[Any] = []
    for v in values:
        if not isinstance(v, tuple | list):
            flat.append(v)
        elif len(v) == 2:
            flat.extend(v)
        else:
            raise InputError(f"a point is a pair (x, y), got {v!r}", param)
    return [_number(v, param) for v in flat]


# --- filled areas and anti-aliasing ------------------------------------------------------------


@answers
def polygon(vertices: PointsLike, rule: FillRule | str = "even-odd") -> Solution:
    """The scan-line fill of the polygon ``vertices`` (``scanconv polygon``): the edge table,
    the active edge table per scan line, the spans and the pixels.

    >>> sol = polygon([(0, 0), (4, 0), (2, 3)])
    >>> list(sol.pixels())
    [(0, 0), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1), (2, 2)]
    """
    from ..answers.polygon import polygon_solution

    return polygon_solution(_flat(vertices, "vertices"), _choice(rule, "rule"))


@answers
def fill(
    method: str,
    seed: PointLike,
    *,
    vertices: PointsLike | None = None,
    rows: str | Sequence[str] | None = None,
    connectivity: NumberLike = 4,
    order: Order | str = "stack",
    span: bool = False,
) -> Solution:
    """A seed fill (``scanconv fill boundary``, ``scanconv fill flood``): ``method`` is
    ``"boundary"`` or ``"flood"``, over the Bresenham outline of the polygon ``vertices`` or
    over the grid ``rows`` (text, top row first: ``#`` boundary, ``.`` empty); ``span`` gives the
    span (scan-line seed) fill.

    >>> sorted(fill("flood", (1, 1), rows="####/#..#/####").pixels())
    [(1, 1), (2, 1)]
    """
    from ..answers.fill import seed_fill_solution

    texts = None if rows is None else ([rows] if isinstance(rows, str) else list(rows))
    sx, sy = _pair(seed, "seed")
    return seed_fill_solution(
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
    method: AAMethod | str = "area",
    samples: NumberLike = 4,
    levels: NumberLike = 8,
) -> Solution:
    """An anti-aliased line (``scanconv antialias line``): ``method`` ``"wu"`` (Xiaolin Wu's
    algorithm), ``"area"`` or ``"supersample"`` (``samples`` x ``samples`` per pixel).

    >>> [s.extra[4] for s in antialias_line(0, 0, 4, 1, method="wu").steps()]
    [1, Fraction(3, 4), Fraction(1, 2), Fraction(1, 4), 1]
    """
    from ..answers.antialias import antialias_solution

    return antialias_solution(
        "line",
        _numbers(x1=x1, y1=y1, x2=x2, y2=y2),
        method=_choice(method, "method"),
        samples=_whole(samples, "samples"),
        levels=_whole(levels, "levels"),
    )


@answers
def antialias_circle(
    r: NumberLike,
    center: PointLike = (0, 0),
    method: AAMethod | str = "area",
    samples: NumberLike = 4,
    levels: NumberLike = 8,
) -> Solution:
    """An anti-aliased circle one pixel wide (``scanconv antialias circle``).

    >>> round(sum(float(v) for _, v, *_ in antialias_circle(3).tables[0].rows()), 6)
    18.849556
    """
    from ..answers.antialias import antialias_solution

    return antialias_solution(
        "circle",
        (_number(r, "r"), *_pair(center, "center")),
        method=_choice(method, "method"),
        samples=_whole(samples, "samples"),
        levels=_whole(levels, "levels"),
    )


@answers
def antialias_polygon(
    vertices: PointsLike,
    method: AAMethod | str = "area",
    samples: NumberLike = 4,
    levels: NumberLike = 8,
    rule: FillRule | str = "even-odd",
) -> Solution:
    """An anti-aliased polygon (``scanconv antialias polygon``): exact covered areas, or the
    fraction of ``samples`` x ``samples`` samples inside.

    >>> antialias_polygon([(0, 0), (2, 0), (2, 1), (0, 1)]).derived[-2].value
    2
    """
    from ..answers.antialias import antialias_solution

    return antialias_solution(
        "polygon",
        _flat(vertices, "vertices"),
        method=_choice(method, "method"),
        samples=_whole(samples, "samples"),
        levels=_whole(levels, "levels"),
        rule_name=_choice(rule, "rule"),
    )


#: API functions defined in this package's submodules, by name -> submodule; loaded on first
#: use (start-up time). One line per function, grouped by submodule. A submodule is never named
#: after a function it holds: importing ``scanconv._api.color`` would bind the module, not the
#: function, to ``_api.color`` (hence ``color_theory``). ``check``, which takes a question in
#: scanconv's own words, is :func:`scanconv.questions.check`, a layer above.
SUBMODULE_OF: dict[str, str] = {
    "color": "color_theory",
    "theory": "color_theory",
}

__all__ += sorted(SUBMODULE_OF)


def __getattr__(name: str) -> Any:
    """The circle, clipping and filling choices and the submodules' functions, loaded on first
    use (start-up time)."""
    if name in SUBMODULE_OF:
        import importlib

        return getattr(importlib.import_module(f"{__name__}.{SUBMODULE_OF[name]}"), name)
    if name in ("LineClipMethod", "PolygonClipMethod", "AAMethod", "FillRule", "Order"):
        from ..algorithms import process_choices

        return getattr(process_choices, name)
    if name in ("CircleMethod", "P0", "Loop", "Update"):
        from ..algorithms import circle_choices

        return getattr(circle_choices, name)
    raise AttributeError(f"module 'scanconv._api' has no attribute {name!r}")
