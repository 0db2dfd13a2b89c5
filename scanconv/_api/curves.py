"""The Python API: curves (``scanconv parametric``, ``bezier``, ``bspline``, ``continuity``, ``local-control``). See :mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError
from ..display import answers
from .values import (
    FormulaLike,
    NumberLike,
    PointLike,
    PointsLike,
    TRangeLike,
    _bounds,
    _formula,
    _knots,
    _number,
    _numbers,
    _pair,
    _points,
    _whole,
)

if TYPE_CHECKING:
    from ..algorithms import curve_limits
else:
    curve_limits = lazy.module("scanconv.algorithms.curve_limits")

if TYPE_CHECKING:
    from ..answers import bezier as answers_bezier
    from ..answers import bspline as answers_bspline
    from ..answers import bspline_basis_at as answers_bspline_basis_at
    from ..answers import continuity as answers_continuity
    from ..answers import local_control as answers_local_control
    from ..answers import parametric as answers_parametric
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_bezier = lazy.module("scanconv.answers.bezier")
    answers_bspline = lazy.module("scanconv.answers.bspline")
    answers_bspline_basis_at = lazy.module("scanconv.answers.bspline_basis_at")
    answers_continuity = lazy.module("scanconv.answers.continuity")
    answers_local_control = lazy.module("scanconv.answers.local_control")
    answers_parametric = lazy.module("scanconv.answers.parametric")


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
    pts = _points(points)
    return answers_bezier.bezier_solution(
        pts, _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples")
    )


@answers
def bezier_at(points: PointsLike, t: FormulaLike) -> Solution:
    """De Casteljau's construction at one ``t`` in [0, 1] (``scanconv bezier --at``).

    >>> list(bezier_at([0, 0, 1, 2, 3, 3, 4, 0], "1/2").pixels())  # B(1/2) = (2, 1.875)
    [(2, 2)]
    """
    pts = _points(points)
    return answers_bezier.bezier_at_solution(pts, _formula(t, "t"))


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
    """Only the table of the basis values ``N_i,p(t)`` (``scanconv bspline --basis``).

    Without control points (``points`` empty or ``None``) the degree and an explicit knot list
    define the basis, tabulated over the whole knot range ``[u_0, u_m]``.

    >>> [c.key for c in bspline_basis([0, 0, 1, 2, 3, 3], 2).tables[0].columns][:3]
    ['k', 't', 'N0']
    >>> len(list(bspline_basis(None, 2, [0, 0.25, 0.5, 0.75, 1]).tables[0].rows()))
    9
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
    """One ``t``: the Cox-de Boor triangle and the weighted sum (``scanconv bspline --at``).

    Without control points (``points`` empty or ``None``) the degree and an explicit knot list
    define the basis, and every ``N_i,d(t)`` is worked (``scanconv bspline --basis --at``).

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
    first: PointsLike, second: PointsLike, samples: NumberLike | None = None
) -> Solution:
    """C0, C1, C2 at the join of two Bezier segments (``scanconv continuity``).

    >>> continuity([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)]).data["continuity"]
    'C1'
    """
    a, b = _points(first, "first"), _points(second, "second")
    steps = _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples")
    return answers_continuity.continuity_solution(a, b, steps)


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
    pts = _points(points)
    spec = _knots(knots)
    return answers_local_control.local_control_solution(
        pts,
        _whole(index, "index"),
        _pair(moved, "moved"),
        _whole(degree, "degree"),
        spec,
        _whole(curve_limits.DEFAULT_SAMPLES if samples is None else samples, "samples"),
    )


def _parametric(
    kind: str,
    t_range: TRangeLike | None,
    samples: NumberLike | None,
    **given: Any,
) -> Solution:
    return answers_parametric.parametric_solution(
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
    pts = _points(points)
    spec = _knots(knots)
    return answers_bspline.bspline_solution(
        pts,
        _whole(degree, "degree"),
        spec,
        None if samples is None else _whole(samples, "samples"),
        basis_only=basis_only,
    )
