"""Local control: the same control points, one moved, on a Bezier curve (global control) and
on a B-spline (local control), sample by sample (:func:`local_control`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from ..core.numeric import Number
from ..core.records import Step
from .bezier import bezier
from .bspline import bspline
from .curve_limits import DEFAULT_SAMPLES, Point, check_index, check_points, exact_point


def local_control(
    points: Sequence[Point],
    index: int,
    moved: Point,
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int = DEFAULT_SAMPLES,
) -> Iterator[Step]:
    """The same control points, one moved: which samples of each curve move.

    Step ``k`` compares the Bezier curve at ``t = k / samples`` and the B-spline at
    ``t = u_p + k (u_{n+1} - u_p) / samples``, before and after ``P_index`` moves to ``moved``.
    ``extra`` is ``(t_bezier, pixel before, pixel after, moved?, t_bspline, pixel before,
    pixel after, moved?)`` where ``moved?`` compares the exact points; ``pixel`` is the
    B-spline's pixel after the move.

    Notes
    -----
    A Bezier weight ``B_{i,n}(t)`` is positive on all of ``0 < t < 1``, so moving any control
    point moves every point but the ends (global control). A B-spline basis function
    ``N_{i,p}`` is zero outside ``[u_i, u_{i+p+1}]``, so only that stretch moves (local
    control).

    Examples
    --------
    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> rows = list(local_control(pts, 5, (7, 5), 2, "open", 4))
    >>> [(str(s.extra[0]), s.extra[3], str(s.extra[4]), s.extra[7]) for s in rows]
    [('0', False, '0', False), ('1/4', True, '1', False), ('1/2', True, '2', False), ('3/4', True, '3', False), ('1', True, '4', True)]
    """
    pts = check_points(points, 2, "the control polygon")
    check_index(index, len(pts))
    after = list(pts)
    after[index] = exact_point(moved)
    # local_control(6 points, move P5, p=2 open) -> Bezier moves for t > 0 ;
    #   B-spline only for t > u_5 = 3
    for before_z, after_z, before_s, after_s in zip(
        bezier(pts, samples),
        bezier(after, samples),
        bspline(pts, degree, knots, samples),
        bspline(after, degree, knots, samples),
        strict=True,
    ):
        yield Step(
            before_z.k,
            None,
            None,
            after_s.pixel,
            (
                before_z.extra[0],
                before_z.pixel,
                after_z.pixel,
                before_z.extra[-2:] != after_z.extra[-2:],
                before_s.extra[0],
                before_s.pixel,
                after_s.pixel,
                before_s.extra[-2:] != after_s.extra[-2:],
            ),
        )
