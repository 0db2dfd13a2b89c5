"""The worked answer of the notes' Bezier-vs-B-spline comparison: move one control point and
count which samples and pixels of each curve change."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import NamedTuple

from ...algorithms.bezier import bezier
from ...algorithms.bspline import bspline, domain
from ...algorithms.curve_limits import (
    DEFAULT_SAMPLES,
    Point,
    check_index,
    check_path,
    check_row,
    check_samples,
    check_weights,
    exact_point,
)
from ...algorithms.local_control import local_control
from ...algorithms.sampling import bbox, curve_pixels
from ...core.numeric import Number
from ...core.records import (
    Pixel,
    PixelFigure,
    Plot,
    Quantity,
    Solution,
    Step,
    Walk,
    heading,
    worked,
)
from ._shared import JOIN_NOTE, given_points, knot_text, point_text, value_text
from .bspline import bspline_setup


def _moved_quantity(key: str, moved: int, total: int, removed: int, added: int) -> Quantity:
    name = "Bezier" if key == "bezier" else "B-spline"
    text = f"{moved} of {total} samples moved; pixels: {removed} removed, {added} added"
    return worked(f"{key}_moved", moved, f"\\text{{{name}: {text}}}")


def _changed(before: Iterable[Pixel], after: Iterable[Pixel]) -> tuple[int, int]:
    """Pixels removed and added by the move.

    >>> _changed([(0, 0), (1, 1)], [(1, 1), (2, 1), (3, 1)])
    (1, 2)
    """
    b, a = set(before), set(after)
    return len(b - a), len(a - b)


_COLUMNS = (
    heading("k", "k", role="label"),
    heading("t_bezier", r"t \ (\text{Bezier})", 3),
    heading("bezier_before", r"\text{Bezier before}"),
    heading("bezier_after", r"\text{Bezier after}"),
    heading("bezier_moved", r"\text{moved}"),
    heading("t_bspline", r"t \ (\text{B-spline})", 3),
    heading("bspline_before", r"\text{B-spline before}"),
    heading("bspline_after", r"\text{B-spline after}"),
    heading("bspline_moved", r"\text{moved}"),
)
_NOTES = (
    "Both curves use the same control points and the same number of samples; 'moved' "
    "compares the exact points before and after.",
    "Bezier curves have global control (every weight is positive inside $0 < t < 1$); "
    "B-splines have local control ($N_{i,p}$ vanishes outside $[u_i, u_{i+p+1}]$).",
    JOIN_NOTE,
)


class _Change(NamedTuple):
    """One curve before and after the move: its pixels and what changed."""

    before: list[Pixel]
    after: list[Pixel]
    moved: int
    """Samples moved."""
    removed: int
    added: int


def _checked_move(
    pts: Sequence[Point], index: int, moved: Point, degree: int, u: Sequence[Number], samples: int
) -> list[Point]:
    """The control points after the move, every limit checked first."""
    check_samples(samples)
    check_weights(samples, len(pts))
    check_index(index, len(pts))
    new = exact_point(moved)
    after = [*pts[:index], new, *pts[index + 1 :]]
    check_path([pts, after], samples)
    for polygon in (pts, after):
        check_row(bezier(polygon, samples), "Bezier curve")
        check_row(bspline(polygon, degree, u, samples), "B-spline")
    return after


def _change(
    curve: Callable[[Sequence[Point]], Iterable[Step]],
    pts: Sequence[Point],
    after: Sequence[Point],
    moved: int,
) -> _Change:
    before_px = list(curve_pixels(s.pixel for s in curve(pts)))
    after_px = list(curve_pixels(s.pixel for s in curve(after)))
    return _Change(before_px, after_px, moved, *_changed(before_px, after_px))


def _local_derived(
    pts: Sequence[Point],
    index: int,
    new: Point,
    degree: int,
    u: Sequence[Number],
    n: int,
    changes: tuple[_Change, _Change],
    total: int,
) -> tuple[Quantity, ...]:
    """The move, the knots, each curve's support and what moved."""
    z, s = changes
    lo, hi = u[index], u[index + degree + 1]
    t0, t1 = domain(u, degree, n)
    return (
        worked(
            "move",
            (index, new),
            f"P_{{{index}}} \\text{{ moves from }} {point_text(pts[index])} \\text{{ to }} {point_text(new)}",
        ),
        worked(
            "knots",
            tuple(u),
            f"\\text{{B-spline: degree }} p = {degree}, \\; U = {knot_text(u)}, \\; "
            f"\\text{{domain }} {value_text(t0)} \\le t \\le {value_text(t1)}",
        ),
        worked(
            "bezier_support",
            (0, 1),
            f"\\text{{Bezier: }} B_{{{index},{n}}}(t) > 0 \\text{{ for all }} 0 < t < 1, "
            r"\text{ so every point with } 0 < t < 1 \text{ moves}",
        ),
        _moved_quantity("bezier", z.moved, total, z.removed, z.added),
        worked(
            "bspline_support",
            (lo, hi),
            f"\\text{{B-spline: }} N_{{{index},{degree}}}(t) = 0 \\text{{ outside }} "
            f"u_{{{index}}} = {value_text(lo)} \\le t \\le u_{{{index + degree + 1}}} = "
            f"{value_text(hi)}, \\text{{ so only that stretch moves}}",
        ),
        _moved_quantity("bspline", s.moved, total, s.removed, s.added),
    )


def local_control_solution(
    points: Sequence[Point],
    index: int,
    moved: Point,
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int = DEFAULT_SAMPLES,
) -> Solution:
    """The notes' Bezier-vs-B-spline comparison as an example: move one point, count changes.

    >>> pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2), (7, 1)]
    >>> sol = local_control_solution(pts, 5, (7, 5), 2, "open", 8)
    >>> sol.data["bezier_samples_moved"], sol.data["bspline_samples_moved"]
    (8, 2)
    """
    pts, n, u, _ = bspline_setup(points, degree, knots)
    after = _checked_move(pts, index, moved, degree, u, samples)
    new = after[index]
    z_moved = s_moved = 0
    for st in local_control(pts, index, new, degree, u, samples):
        z_moved += st.extra[3]
        s_moved += st.extra[7]
    z = _change(lambda c: bezier(c, samples), pts, after, z_moved)
    s = _change(lambda c: bspline(c, degree, u, samples), pts, after, s_moved)
    legend = "# = after the move only, o = before only, @ = both"
    figures = tuple(
        PixelFigure(
            tuple(c.after), tuple(c.before), bbox([*c.before, *c.after]), legend, f"{name}:"
        )
        for name, c in (("Bezier", z), ("B-spline", s))
    )
    old = point_text(pts[index])
    return Solution(
        primitive="curve",
        algorithm="local-control",
        title=f"Local control: Bezier vs B-spline, P{index} moved from {old} to {point_text(new)}",
        given=tuple(given_points(pts)),
        derived=_local_derived(pts, index, new, degree, u, n, (z, s), samples + 1),
        notes=_NOTES,
        walk=Walk(
            columns=_COLUMNS,
            extra_keys=tuple(c.key for c in _COLUMNS[1:]),
            steps=lambda: local_control(pts, index, new, degree, u, samples),
        ),
        plot=Plot(figures=figures),
        data={
            "bezier_samples_moved": z.moved,
            "bspline_samples_moved": s.moved,
            "bezier_pixels_changed": z.removed + z.added,
            "bspline_pixels_changed": s.removed + s.added,
        },
    )
