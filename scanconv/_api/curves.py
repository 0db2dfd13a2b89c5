"""The Python API: curves (``scanconv bezier``, ``bspline``, ``continuity``, ``local-control``; the parametric curves are :mod:`scanconv._api.parametric`). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, Any

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .params import DEGREE, KNOTS, POINTS, SAMPLES
from .values import (
    FormulaLike,
    NumberLike,
    PointsLike,
    _formula,
    _knots,
    _pair,
    _points,
    _whole,
)

if TYPE_CHECKING:
    from ..algorithms import curve_limits
else:
    curve_limits = lazy.module("scanconv.algorithms.curve_limits")

if TYPE_CHECKING:
    from ..answers.curves import bezier as answers_bezier
    from ..answers.curves import bspline as answers_bspline
    from ..answers.curves import bspline_basis as answers_bspline_basis_at
    from ..answers.curves import continuity as answers_continuity
    from ..answers.curves import local_control as answers_local_control
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_bezier = lazy.module("scanconv.answers.curves.bezier")
    answers_bspline = lazy.module("scanconv.answers.curves.bspline")
    answers_bspline_basis_at = lazy.module("scanconv.answers.curves.bspline_basis")
    answers_continuity = lazy.module("scanconv.answers.curves.continuity")
    answers_local_control = lazy.module("scanconv.answers.curves.local_control")


@answers
def bezier(
    points: Annotated[PointsLike, POINTS],
    samples: Annotated[NumberLike | None, SAMPLES] = None,
    t: Annotated[
        FormulaLike | None,
        Opt(
            "--at",
            metavar="T",
            help="De Casteljau's construction at this t in [0, 1].",
            kind="text",
        ),
    ] = None,
) -> Solution:
    """The Bezier curve of ``points``, tabulated at even steps of t by its Bernstein weights
    (``scanconv bezier``).

    Parameters
    ----------
    points : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The control points P0 .. Pn, exact numbers.
    samples : int, optional
        The number of steps of t over [0, 1] (``samples + 1`` rows); default 16.
    t : number or formula, optional
        One t in [0, 1]: the answer is then De Casteljau's construction at it
        (:func:`bezier_at`, ``scanconv bezier --at``), and ``samples`` is not used.

    Returns
    -------
    Answer
        The Bernstein polynomials ``B_i,n(t) = C(n, i) t^i (1 - t)^(n - i)``, the table of
        t, the weights and the point ``C(t) = Σ B_i,n(t) P_i`` with its pixel (rounded half
        up), and the pixels joined by Bresenham's line.

    Notes
    -----
    The Bernstein form (G. Farin, *Curves and Surfaces for CAGD*, 5th ed., 2002), exact at
    rational t.

    Examples
    --------
    >>> sol = bezier([(0, 0), (1, 2), (3, 3), (4, 0)], 8)
    >>> [s.pixel for s in sol.steps()][:4]
    [(0, 0), (0, 1), (1, 1), (1, 2)]
    >>> list(sol.pixels())
    [(0, 0), (0, 1), (1, 1), (1, 2), (2, 2), (3, 2), (4, 1), (4, 0)]
    >>> bezier([0, 0, 1, 2, 3, 3, 4, 0], t="1/2").title == bezier_at([0, 0, 1, 2, 3, 3, 4, 0], "1/2").title
    True
    """
    if t is not None:
        return bezier_at(points, t)
    pts = _points(points)
    return answers_bezier.bezier_solution(
        pts, _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples")
    )


@answers
def bezier_at(points: PointsLike, t: FormulaLike) -> Solution:
    """De Casteljau's construction of the Bezier curve at one ``t`` (``scanconv bezier --at``).

    Parameters
    ----------
    points : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The control points P0 .. Pn, exact numbers.
    t : number or formula
        The parameter, in [0, 1] (``"1/2"``, ``0.25``).

    Returns
    -------
    Answer
        Each level of linear interpolations ``P_i^r = (1 - t) P_i^(r-1) + t P_(i+1)^(r-1)``,
        the point ``C(t)`` (checked against the Bernstein form) and its pixel.

    Notes
    -----
    De Casteljau's algorithm (G. Farin, *Curves and Surfaces for CAGD*, 5th ed., 2002).

    Examples
    --------
    >>> sol = bezier_at([0, 0, 1, 2, 3, 3, 4, 0], "1/2")  # C(1/2) = (2, 1.875)
    >>> list(sol.pixels())
    [(2, 2)]
    """
    pts = _points(points)
    return answers_bezier.bezier_at_solution(pts, _formula(t, "t"))


@answers
def bspline(
    points: Annotated[
        PointsLike | None,
        Arg(
            "Control points as x y pairs (none with --basis and an explicit --knots list).",
            "[X0 Y0 X1 Y1 ...]",
        ),
    ] = None,
    degree: Annotated[NumberLike, DEGREE] = 3,
    knots: Annotated[str | Sequence[NumberLike], KNOTS] = "open",
    *,
    basis: Annotated[
        bool, Opt("--basis", help="Print only the table of basis values N_i,p(t).")
    ] = False,
    t: Annotated[
        FormulaLike | None,
        Opt(
            "--at",
            metavar="T",
            help="Evaluate one t: Cox-de Boor, the non-zero terms, C(t).",
            kind="text",
        ),
    ] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The B-spline of ``degree`` over ``points``, tabulated over its knot range by the
    Cox-de Boor recursion (``scanconv bspline``).

    Parameters
    ----------
    points : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The control points P0 .. Pn, exact numbers (none only with ``basis``: see
        :func:`bspline_basis`).
    degree : int, default 3
        The degree p (order p + 1), at most n for n + 1 control points.
    knots : {"open", "uniform"}, str or sequence of numbers, default "open"
        ``"open"``: clamped uniform, p + 1 equal knots at each end and integer steps inside;
        ``"uniform"``: 0, 1, ..., m; or the n + p + 2 knot values themselves (a list, or
        text as ``"0,0,0,1,2,2,2"``).
    basis : bool, default False
        Only the table of the basis values (:func:`bspline_basis`, ``scanconv bspline
        --basis``).
    t : number or formula, optional
        One t: the answer is then the curve (or, with ``basis``, the basis) at it
        (:func:`bspline_at`, ``scanconv bspline --at``), and ``samples`` is not used.
    samples : int, optional
        The number of steps of t; default a few per knot span.

    Returns
    -------
    Answer
        The knot vector, the table of t, the basis values ``N_i,p(t)`` and the point
        ``C(t) = Σ N_i,p(t) P_i`` with its pixel, and the pixels joined by Bresenham's line.

    Notes
    -----
    The Cox-de Boor recursion (C. de Boor, J. Approximation Theory 6, 1972; M. G. Cox, IMA J.
    Appl. Math. 10, 1972), exact at rational t.

    Examples
    --------
    >>> sol = bspline([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, samples=4)
    >>> [s.pixel for s in sol.steps()]  # an open B-spline starts at P0 and ends at Pn
    [(0, 0), (2, 2), (3, 3), (4, 1), (5, 2)]
    >>> bspline(degree=2, knots=[0, 0.25, 0.5, 0.75, 1], basis=True).tables[0].title
    'Basis functions N_(i,2)(t) over the whole knot range'
    """
    if basis:
        if t is not None:
            return bspline_at(points or [], t, degree, knots)
        return bspline_basis(points, degree, knots, samples)
    if not points:
        raise InputError(
            "missing control points X0 Y0 X1 Y1 ... (only the basis functions alone are "
            "asked with a degree and a knot list but no points)",
            "points",
        )
    if t is not None:
        return bspline_at(points, t, degree, knots)
    return _bspline(points, degree, knots, samples, basis_only=False)


def _explicit_knots(knots: str | Sequence[NumberLike]) -> tuple[Number, ...]:
    """The knot list of a basis without control points: an explicit one, never a name."""
    spec = _knots(knots)
    if isinstance(spec, str):
        raise InputError(
            "without control points the basis needs an explicit knot list "
            f"(got {spec!r}: open and uniform are defined by the number of points)",
            "knots",
        )
    return spec


@answers
def bspline_basis(
    points: PointsLike | None,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
    samples: NumberLike | None = None,
) -> Solution:
    """Only the table of the B-spline basis values ``N_i,p(t)`` (``scanconv bspline --basis``).

    Parameters
    ----------
    points : sequence of (x, y), flat numbers, or None
        The control points (only their number matters); empty or ``None``: the degree and an
        explicit knot list define the basis, tabulated over the whole knot range [u_0, u_m].
    degree : int, default 3
        The degree p (order p + 1), at most n for n + 1 control points.
    knots : {"open", "uniform"}, str or sequence of numbers, default "open"
        ``"open"``: clamped uniform, p + 1 equal knots at each end and integer steps inside;
        ``"uniform"``: 0, 1, ..., m; or the n + p + 2 knot values themselves (a list, or
        text as ``"0,0,0,1,2,2,2"``).
        Without control points, an explicit list.
    samples : int, optional
        The number of steps of t; default a few per knot span.

    Returns
    -------
    Answer
        The table ``k, t, N0, N1, ...``.

    Examples
    --------
    >>> sol = bspline_basis([0, 0, 1, 2, 3, 3], 2)
    >>> [c.key for c in sol.tables[0].columns]
    ['k', 't', 'N0', 'N1', 'N2']
    >>> list(bspline_basis(None, 2, [0, 0.25, 0.5, 0.75, 1]).tables[0].rows())[4]
    (4, Fraction(1, 2), Fraction(1, 2), Fraction(1, 2), 1)
    """
    if not points:
        spec = _explicit_knots(knots)
        return answers_bspline.bspline_basis_knots_solution(
            _whole(degree, "degree"),
            spec,
            None if samples is None else _whole(samples, "samples"),
        )
    return _bspline(points, degree, knots, samples, basis_only=True)


@answers
def bspline_at(
    points: PointsLike | None,
    t: FormulaLike,
    degree: NumberLike = 3,
    knots: str | Sequence[NumberLike] = "open",
) -> Solution:
    """The B-spline at one ``t``: the Cox-de Boor triangle of basis values and the weighted sum
    (``scanconv bspline --at``).

    Parameters
    ----------
    points : sequence of (x, y), flat numbers, or None
        The control points; empty or ``None``: every ``N_i,d(t)`` of the basis given by the degree
        and an explicit knot list is worked (``scanconv bspline --basis --at``).
    t : number or formula
        The parameter, within the knot range.
    degree : int, default 3
        The degree p (order p + 1), at most n for n + 1 control points.
    knots : {"open", "uniform"}, str or sequence of numbers, default "open"
        ``"open"``: clamped uniform, p + 1 equal knots at each end and integer steps inside;
        ``"uniform"``: 0, 1, ..., m; or the n + p + 2 knot values themselves (a list, or
        text as ``"0,0,0,1,2,2,2"``).

    Returns
    -------
    Answer
        The triangle ``N_i,0(t) .. N_i,p(t)``, then ``C(t) = Σ N_i,p(t) P_i`` and its pixel.

    Examples
    --------
    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)]
    >>> list(bspline_at(pts, 1.5, 2).pixels())  # C(1.5) = (2.875, 2.5)
    [(3, 3)]
    >>> [str(v) for v in bspline_at(None, "3/8", 2, [0, 0.25, 0.5, 0.75, 1]).data["basis"]]
    ['3/4', '1/8']
    """
    if not points:
        return answers_bspline_basis_at.bspline_basis_at_solution(
            _whole(degree, "degree"), _explicit_knots(knots), _formula(t, "t")
        )
    pts = _points(points)
    return answers_bspline.bspline_at_solution(
        pts, _whole(degree, "degree"), _knots(knots), _formula(t, "t")
    )


@answers
def continuity(
    first: Annotated[
        PointsLike | Sequence[NumberLike | str],
        Arg(
            "The control points of the first segment, ':', those of the second.",
            "X0 Y0 ... : X0 Y0 ...",
            kind="coordinate",
        ),
    ],
    second: PointsLike | None = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The continuity at the join of two Bezier segments: the highest of C0, C1, C2 that holds
    (``scanconv continuity``).

    Parameters
    ----------
    first, second : sequence of (x, y), or flat numbers
        The control points of the two segments; ``second`` should start where ``first`` ends.
        Without ``second``, ``first`` holds both as the command line writes them: flat
        numbers, ``":"`` between the segments.
    samples : int, optional
        The steps of t per segment for the pixels; default 16.

    Returns
    -------
    Answer
        The end derivatives ``C'(1)``, ``C''(1)`` of the first segment and ``C'(0)``, ``C''(0)``
        of the second, compared; ``.data["continuity"]`` is ``"C0"``, ``"C1"``, ``"C2"`` or
        ``None`` (not even C0).

    Examples
    --------
    >>> sol = continuity([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)])
    >>> sol.data["continuity"]
    'C1'
    >>> sol.derived[-1].text
    'continuity at the join: C1 (C0 and C1 hold; C2 fails)'
    >>> continuity([0, 0, 1, 1, 2, 0, ":", 2, 0, 3, -1, 4, 0]).data["continuity"]
    'C1'
    """
    if second is None:
        first, second = _segments(first)
    a, b = _points(first, "first"), _points(second, "second")
    steps = _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples")
    return answers_continuity.continuity_solution(a, b, steps)


@answers
def local_control(
    points: Annotated[PointsLike, POINTS],
    move: Annotated[
        tuple[NumberLike, NumberLike, NumberLike],
        Opt(
            "--move",
            metavar="I X Y",
            help="Move control point P_I to (X, Y).",
            show_default=False,
        ),
    ],
    degree: Annotated[NumberLike, DEGREE] = 3,
    knots: Annotated[str | Sequence[NumberLike], KNOTS] = "open",
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """Move control point ``i`` to ``(x, y)``: what changes on the Bezier curve and what on
    the B-spline (``scanconv local-control``).

    Parameters
    ----------
    points : sequence of (x, y), or flat x0, y0, x1, y1, ...
        The control points P0 .. Pn, exact numbers.
    move : (i, x, y)
        The control point moved, ``i`` in 0 .. n, and its new position ``(x, y)``.
    degree : int, default 3
        The degree p (order p + 1), at most n for n + 1 control points.
    knots : {"open", "uniform"}, str or sequence of numbers, default "open"
        ``"open"``: clamped uniform, p + 1 equal knots at each end and integer steps inside;
        ``"uniform"``: 0, 1, ..., m; or the n + p + 2 knot values themselves (a list, or
        text as ``"0,0,0,1,2,2,2"``).
    samples : int, optional
        The steps of t of each curve; default 16.

    Returns
    -------
    Answer
        Both curves before and after, sample by sample; ``.data`` counts the samples that moved
        (``bezier_samples_moved``, ``bspline_samples_moved``): every sample of the Bezier curve
        (global control), only those of the spans the point influences on the B-spline (local
        control).

    Examples
    --------
    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> sol = local_control(pts, (5, 7, 5), 2, samples=8)
    >>> sol.data["bezier_samples_moved"], sol.data["bspline_samples_moved"]
    (8, 2)
    """
    pts = _points(points)
    spec = _knots(knots)
    if isinstance(move, str) or len(move) != 3:
        raise InputError(f"move takes 3 numbers (i, x, y), got {move!r}", "move")
    index, x, y = move
    return answers_local_control.local_control_solution(
        pts,
        _whole(index, "index"),
        _pair((x, y), "moved"),
        _whole(degree, "degree"),
        spec,
        _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples"),
    )


def _segments(values: Sequence[Any]) -> tuple[list[Any], list[Any]]:
    """``X0 Y0 ... : X0 Y0 ...`` (numbers and one ``:``) as the two segments' values.

    >>> _segments([0, 0, 1, 1, ":", 1, 1, 2, 0])
    ([0, 0, 1, 1], [1, 1, 2, 0])
    """
    words = list(values)
    if words.count(":") != 1:
        raise InputError(
            "give two Bezier segments separated by ':', e.g. 0 0 1 1 2 0 : 2 0 3 -1 4 0"
        )
    i = words.index(":")
    return words[:i], words[i + 1 :]


def _bspline(
    points: PointsLike,
    degree: NumberLike,
    knots: str | Sequence[NumberLike],
    samples: NumberLike | None,
    *,
    basis_only: bool,
) -> Solution:
    pts = _points(points)
    spec = _knots(knots)
    return answers_bspline.bspline_solution(
        pts,
        _whole(degree, "degree"),
        spec,
        None if samples is None else _whole(samples, "samples"),
        basis_only=basis_only,
    )
