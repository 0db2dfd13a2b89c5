"""The Python API: lines, circles and ellipses, and their comparisons (``scanconv line``, ``circle``, ``ellipse``, ``compare``). See :mod:`scanconv._api`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from ..algorithms.choices import (
    Convention,
    Layout,
    LineAlgorithm,
    LineAlgorithmName,
    LineScale,
    Rounding,
    Start,
    Tie,
    WuEnds,
)
from ..core import lazy
from ..core.declare import Arg, Opt
from ..display import answers
from .params import (
    CENTER,
    CONVENTION,
    DERIVE,
    LAYOUT,
    LOOP,
    PSEUDOCODE,
    ROUNDING,
    START,
    THEORY,
    TIE,
    WU_ENDS,
    X1,
    X2,
    Y1,
    Y2,
)
from .values import NumberLike, PointLike, _choice, _maybe, _number, _numbers, _pair

if TYPE_CHECKING:
    from ..algorithms import circle_choices
    from ..answers import compare as answers_compare
    from ..answers.curves import compare as answers_curves_compare
    from ..answers.primitives import circle as answers_circle
    from ..answers.primitives import ellipse as answers_ellipse
    from ..answers.primitives import line as answers_line
    from ..core.choices import (
        CircleMethodName,
        ConventionName,
        EllipseP0Name,
        LayoutName,
        LineScaleName,
        LoopName,
        P0Name,
        RoundingName,
        StartName,
        TieName,
        UpdateName,
        WuEndsName,
        XStepName,
    )
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call; the circle's choices when
    # its declaration is read (a line's run needs none of them)
    circle_choices = lazy.module("scanconv.algorithms.circle_choices")
    answers_circle = lazy.module("scanconv.answers.primitives.circle")
    answers_compare = lazy.module("scanconv.answers.compare")
    answers_curves_compare = lazy.module("scanconv.answers.curves.compare")
    answers_ellipse = lazy.module("scanconv.answers.primitives.ellipse")
    answers_line = lazy.module("scanconv.answers.primitives.line")


@answers
def line(
    x1: Annotated[NumberLike, X1],
    y1: Annotated[NumberLike, Y1],
    x2: Annotated[NumberLike, X2],
    y2: Annotated[NumberLike, Y2],
    algo: Annotated[
        LineAlgorithm | LineAlgorithmName, Opt("--algo", "-a", help="Line algorithm.")
    ] = "bresenham",
    *,
    rounding: Annotated[Rounding | RoundingName | None, ROUNDING] = None,
    tie: Annotated[Tie | TieName | None, TIE] = None,
    start: Annotated[Start | StartName | None, START] = None,
    scale: Annotated[
        LineScale | LineScaleName | None,
        Opt(
            "--scale",
            help="midpoint: d = 2F(M), integers (integer, the default) or d = F(M), halves (half).",
        ),
    ] = None,
    ends: Annotated[WuEnds | WuEndsName | None, WU_ENDS] = None,
    convention: Annotated[Convention | ConventionName | None, CONVENTION] = None,
    layout: Annotated[Layout | LayoutName, LAYOUT] = "notes",
    derive: Annotated[bool, DERIVE] = False,
    pseudocode: Annotated[bool, PSEUDOCODE] = False,
) -> Solution:
    """The line from ``(x1, y1)`` to ``(x2, y2)`` by ``algo``, worked as in the notes
    (``scanconv line``).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2. A float is read as the decimal it prints as (``0.1`` is
        1/10); a string may be ``"5/2"``. NaN, infinities and ``|value| > 10**9`` are refused.
    algo : LineAlgorithmName or LineAlgorithm, default "bresenham"
        The line algorithm, by its method record's name (``LineAlgorithmName`` lists them):
        Bresenham's, the simple DDA, the basic (direct) method ``y = m x + c``, Xiaolin Wu's
        anti-aliased line, the midpoint line, ...
    rounding : {"half-up", "trunc", "half-even", "c-cast", "half-away"}, optional
        How the DDA and the basic method round a coordinate to a pixel (default half-up).
    tie : {"step", "keep"}, optional
        Bresenham: what a decision parameter of 0 does (default step).
    start : {"swap", "given"}, optional
        Which end is plotted first: Bresenham swaps to the end with the smaller major
        coordinate, the DDA starts at P1 (``given``).
    scale : {"integer", "half"}, optional
        The midpoint line: d = 2F(M) in integers (default) or d = F(M) in halves.
    ends : {"full", "coverage"}, optional
        Wu's line: end points at full intensity (default) or weighted by the part of the end
        column the line covers (xgap, as Wikipedia's pseudocode).
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

    Notes
    -----
    The defaults are the notes' variants (``convention="notes"``): Bresenham with
    ``p0 = 2Δy - Δx``, ``p += 2Δy`` or ``2Δy - 2Δx``, a tie (``p = 0``) stepping the minor axis,
    walked from the end with the smaller major coordinate (Bresenham 1965; Hearn & Baker,
    *Computer Graphics*, §3-5); the DDA with increments ``Δx / steps`` and ``Δy / steps``,
    rounded half up; the midpoint line with ``d = 2F(M)``; Wu's line (Wu 1991) with full
    end points. ``convention`` names other books' choices (:mod:`scanconv.algorithms.conventions`).
    Coordinates are ``(x, y)`` with y up.

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
    >>> print(line(0, 0, 6, 3).grid(), end="")  # the pixels, y up
     4 | .  .  .  .  .  .  .  .  .
     3 | .  .  .  .  .  .  #  #  .
     2 | .  .  .  .  #  #  .  .  .
     1 | .  .  #  #  .  .  .  .  .
     0 | .  #  .  .  .  .  .  .  .
    -1 | .  .  .  .  .  .  .  .  .
       +---------------------------
         -1 0  1  2  3  4  5  6  7
    # = plotted pixel; x to the right, y up
    """
    coords = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_line.line_solution(
        _choice(algo, "algo"),
        *coords,
        rounding=_maybe(rounding, "rounding"),
        tie=_maybe(tie, "tie"),
        start=_maybe(start, "start"),
        scale=_maybe(scale, "scale"),
        ends=_maybe(ends, "ends"),
        convention=_maybe(convention, "convention"),
        layout=_choice(layout, "layout"),
        derive=derive,
        pseudocode=pseudocode,
        annotate=True,
    )


@answers
def circle(
    r: Annotated[NumberLike, Arg("The radius r (a whole number).", "R")],
    center: Annotated[PointLike, CENTER] = (0, 0),
    method: Annotated[
        circle_choices.CircleMethod | CircleMethodName,
        Opt(
            "--method",
            "-m",
            help="Circle method: midpoint (the notes' Topic 9 'Bresenham', p0 = 1 - r), "
            "bresenham (d0 = 3 - 2r), general (the notes' p0 = 0 at the point), polynomial "
            "(square root), trig, symmetric-dda.",
        ),
    ] = "midpoint",
    rounding: Annotated[Rounding | RoundingName | None, ROUNDING] = None,
    *,
    tie: Annotated[Tie | TieName | None, TIE] = None,
    p0: Annotated[
        circle_choices.P0 | P0Name | None,
        Opt("--p0", help="midpoint: p0 printed as 1-r (integers) or 5/4-r."),
    ] = None,
    loop: Annotated[circle_choices.Loop | LoopName | None, LOOP] = None,
    update: Annotated[
        circle_choices.Update | UpdateName | None,
        Opt("--update", help="midpoint: increments written with the new x or the old x."),
    ] = None,
    xstep: Annotated[
        circle_choices.XStep | XStepName | None,
        Opt(
            "--xstep",
            help="bresenham: d updated before x += 1 (last, Bresenham's own) or after it "
            "(first, as widely copied code does).",
        ),
    ] = None,
    convention: Annotated[Convention | ConventionName | None, CONVENTION] = None,
    layout: Annotated[Layout | LayoutName, LAYOUT] = "notes",
    derive: Annotated[bool, DERIVE] = False,
    pseudocode: Annotated[bool, PSEUDOCODE] = False,
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
    xstep : {"last", "first"}, optional
        Bresenham's circle: d updated before x += 1 (default) or after it, as widely copied
        code does.
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

    Notes
    -----
    The midpoint circle is Hearn & Baker's (§3-9): ``p0 = 1 - r`` (``5/4 - r`` exactly),
    ``p += 2x + 1`` while ``p < 0``, else ``p += 2x + 1 - 2y`` (the new x and y), the octant
    from ``(0, r)`` while ``x < y``. ``bresenham`` is the ``d0 = 3 - 2r`` form (``d += 4x + 6``
    or ``4(x - y) + 10``; Bresenham, CACM 20(2), 1977), the one skimage calls Bresenham's;
    ``general`` is the notes' decision
    method with ``p0 = 0``; ``polynomial`` rounds ``y = sqrt(r² - x²)``, ``trig`` rounds
    ``(r cos θ, r sin θ)``. Every octant point is mirrored 8 ways.

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
    >>> print(circle(3).grid(), end="")  # o: the centre
     4 | .  .  .  .  .  .  .  .  .
     3 | .  .  .  #  #  #  .  .  .
     2 | .  .  #  .  .  .  #  .  .
     1 | .  #  .  .  .  .  .  #  .
     0 | .  #  .  .  o  .  .  #  .
    -1 | .  #  .  .  .  .  .  #  .
    -2 | .  .  #  .  .  .  #  .  .
    -3 | .  .  .  #  #  #  .  .  .
    -4 | .  .  .  .  .  .  .  .  .
       +---------------------------
         -4 -3 -2 -1 0  1  2  3  4
    # = plotted pixel, o = marked point, @ = both; x to the right, y up
    """
    radius = _number(r, "r")
    xc, yc = _pair(center, "center")
    return answers_circle.circle_solution(
        _choice(method, "method"),
        radius,
        xc,
        yc,
        rounding=_maybe(rounding, "rounding"),
        tie=_maybe(tie, "tie"),
        p0=_maybe(p0, "p0"),
        loop=_maybe(loop, "loop"),
        update=_maybe(update, "update"),
        xstep=_maybe(xstep, "xstep"),
        convention=_maybe(convention, "convention"),
        layout=_choice(layout, "layout"),
        derive=derive,
        pseudocode=pseudocode,
        annotate=True,
    )


@answers
def ellipse(
    rx: Annotated[NumberLike, Arg("The semi-axis rx along x (a whole number).", "RX")],
    ry: Annotated[NumberLike, Arg("The semi-axis ry along y (a whole number).", "RY")],
    center: Annotated[PointLike, CENTER] = (0, 0),
    *,
    loop: Annotated[circle_choices.Loop | LoopName | None, LOOP] = None,
    tie: Annotated[Tie | TieName | None, TIE] = None,
    p0: Annotated[
        circle_choices.EllipseP0 | EllipseP0Name | None,
        Opt(
            "--p0",
            help="Each region's first p: exact (quarters) or rounded as Hearn & Baker's code does, "
            "int(p + 0.5).",
        ),
    ] = None,
    convention: Annotated[Convention | ConventionName | None, CONVENTION] = None,
    derive: Annotated[bool, DERIVE] = False,
    pseudocode: Annotated[bool, PSEUDOCODE] = False,
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

    Notes
    -----
    Hearn & Baker's midpoint ellipse (§3-10): region 1 with
    ``p1_0 = ry² - rx² ry + rx²/4`` while ``2ry² x < 2rx² y``, region 2 with
    ``p2_0 = ry² (x + 1/2)² + rx² (y - 1)² - rx² ry²``; exact fractions unless
    ``p0="rounded"`` (their C code's integer rounding). Each quadrant point is mirrored 4 ways.

    Examples
    --------
    >>> [s.pixel for s in ellipse(3, 2).steps()]
    [(1, 2), (2, 1), (3, 0)]
    >>> sorted(ellipse(2, 1).pixels())
    [(-2, 0), (-1, -1), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 1), (2, 0)]
    >>> print(ellipse(4, 2).grid(), end="")
     3 | .  .  .  .  .  .  .  .  .  .  .
     2 | .  .  .  #  #  #  #  #  .  .  .
     1 | .  .  #  .  .  .  .  .  #  .  .
     0 | .  #  .  .  .  o  .  .  .  #  .
    -1 | .  .  #  .  .  .  .  .  #  .  .
    -2 | .  .  .  #  #  #  #  #  .  .  .
    -3 | .  .  .  .  .  .  .  .  .  .  .
       +---------------------------------
         -5 -4 -3 -2 -1 0  1  2  3  4  5
    # = plotted pixel, o = marked point, @ = both; x to the right, y up
    """
    a, b = _numbers(rx=rx, ry=ry)
    xc, yc = _pair(center, "center")
    return answers_ellipse.ellipse_solution(
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
    x1: Annotated[NumberLike, Arg()],
    y1: Annotated[NumberLike, Arg()],
    x2: Annotated[NumberLike, Arg()],
    y2: Annotated[NumberLike, Arg()],
    theory: Annotated[bool, THEORY] = False,
) -> Solution:
    """The basic method, the DDA and Bresenham side by side over one line, column by column
    (``scanconv compare line``).

    Parameters
    ----------
    x1, y1, x2, y2 : int, Fraction, float, Decimal, numpy scalar or str
        The end points P1 and P2, read as :func:`line` reads them.
    theory : bool, default False
        Add the theory answer's table, DDA vs Bresenham, after the tables.

    Returns
    -------
    Answer
        A table with, for each major coordinate, the exact minor coordinate and each method's
        pixel (``x, y_exact, basic, dda, bresenham``, each other compared line method's,
        ``reason``; ``reason`` says why the methods
        differ, as ``tie`` where the ideal y is halfway between two pixels), then the
        arithmetic each method does per pixel.

    Notes
    -----
    The methods are the notes' variants: the basic method rounds ``y = m x + c`` half up at each
    x, the DDA adds ``m`` and rounds half up, Bresenham decides with ``p0 = 2Δy - Δx`` and steps
    on ``p = 0``; their rounding and tie conventions are those of :func:`line`'s defaults.

    Examples
    --------
    >>> sol = compare_lines(2, 8, 10, 4)
    >>> [c.key for c in sol.tables[0].columns][:5]  # then any other compared line method
    ['x', 'y_exact', 'basic', 'dda', 'bresenham']
    >>> [r[:5] for r in list(sol.tables[0].rows())[:3]]  # x = 3, y = 7.5: half up 8, Bresenham 7
    [(2, 8, 8, 8, 8), (3, Fraction(15, 2), 8, 8, 7), (4, 7, 7, 7, 7)]
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_compare.compare_lines(a, b, c, d, theory=theory)


@answers
def compare_circles(
    r: Annotated[NumberLike, Arg()], theory: Annotated[bool, THEORY] = False
) -> Solution:
    """Every circle method over the first octant of one circle, column by column
    (``scanconv compare circle``).

    Parameters
    ----------
    r : int, Fraction, float, Decimal, numpy scalar or str
        The radius, a whole number >= 0.
    theory : bool, default False
        Add the theory answer's table, the general method vs Bresenham (midpoint).

    Returns
    -------
    Answer
        A table with, for each x of the octant, the exact ``y = sqrt(r² - x²)`` and each
        method's y (``midpoint``, ``bresenham``, ``polynomial``, ``trig``, ``symmetric-dda``),
        and why they differ (``reason``).

    Notes
    -----
    The methods are those of :func:`circle` with their default conventions (midpoint
    ``p0 = 1 - r``, Bresenham ``d0 = 3 - 2r``, the floating-point methods rounded half up).

    Examples
    --------
    >>> sol = compare_circles(10)
    >>> [c.key for c in sol.tables[0].columns]
    ['x', 'y_exact', 'midpoint', 'bresenham', 'polynomial', 'general', 'trig', 'symmetric-dda', 'reason']
    >>> [row[2] for row in sol.tables[0].rows()]  # the midpoint method's y for x = 0 .. 7
    [10, 10, 10, 10, 9, 9, 8, 7]
    """
    return answers_compare.compare_circles(_number(r, "r"), theory=theory)


@answers
def compare_curves() -> Solution:
    """Bezier vs B-spline: the points of the notes' comparison (``scanconv compare curves``).

    Returns
    -------
    Answer
        One table, a row per property (control, degree, ...), a column for each curve.

    Examples
    --------
    >>> sol = compare_curves()
    >>> sol.title
    'Bezier vs B-spline curves'
    >>> list(sol.tables[0].rows())[0]
    ('control', 'global: a point moves the whole curve', 'local: only nearby spans')
    """
    return answers_curves_compare.compare_curves()
