"""The worked answer of the join of two Bezier segments: positions, first and second
derivatives at the join, and the highest of C0, C1, C2 that holds."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

from ...algorithms.bezier import bernstein, bezier
from ...algorithms.continuity import continuity_level, end_derivatives, same_direction
from ...algorithms.curve_limits import (
    DEFAULT_SAMPLES,
    Point,
    check_path,
    check_points,
    check_row,
    check_samples,
    check_weights,
)
from ...algorithms.sampling import bbox, curve_pixels, dense_curve, dense_ts, float_points
from ...core.ideal import ControlPolygon, Polyline
from ...core.records import Pixel, Plot, Quantity, Solution, Table, Walk, heading, worked
from ._shared import JOIN_NOTE, control_marks, given_points, point_text

_ORDERS = ("C0", "C1", "C2")


def _verdict(level: int) -> str:
    """The classification in words.

    >>> _verdict(-1), _verdict(1), _verdict(2)
    ('none: the segments do not meet (C0 fails)', 'C1 (C0 and C1 hold; C2 fails)', 'C2 (C0 and C1 and C2 hold)')
    """
    if level < 0:
        return "none: the segments do not meet (C0 fails)"
    holds = " and ".join(_ORDERS[: level + 1])
    verdict = f"{_ORDERS[level]} ({holds} {'hold' if level else 'holds'}"
    return verdict + (f"; {_ORDERS[level + 1]} fails)" if level < 2 else ")")


_COLUMNS = (
    heading("order", r"\text{order}"),
    heading("quantity", r"\text{compared}"),
    heading("point_A", r"A \text{ at } t = 1"),
    heading("point_B", r"B \text{ at } t = 0"),
    heading("equal", r"\text{equal}"),
)
_QUANTITIES = ("position", "first derivative", "second derivative")


def _checked_segments(
    first: Sequence[Point], second: Sequence[Point], samples: int
) -> tuple[tuple[Point, ...], tuple[Point, ...]]:
    a_pts = check_points(first, 2, "the first segment", param="first")
    b_pts = check_points(second, 2, "the second segment", param="second")
    check_samples(samples)
    check_weights(samples, len(a_pts) + len(b_pts))
    check_path([a_pts, b_pts], samples)
    check_row(bezier(a_pts, samples), "the first segment")
    check_row(bezier(b_pts, samples), "the second segment")
    return a_pts, b_pts


def _join_derived(
    a_pts: Sequence[Point],
    b_pts: Sequence[Point],
    a: Sequence[Point],
    b: Sequence[Point],
    level: int,
) -> tuple[Quantity, ...]:
    """Both segments' position, first and second derivative at the join, and the verdict."""
    n, m = len(a_pts) - 1, len(b_pts) - 1
    a_end, a_before = point_text(a_pts[-1]), point_text(a_pts[-2])
    b_start, b_next = point_text(b_pts[0]), point_text(b_pts[1])
    return (
        worked("A(1)", a[0], f"A(1) = P_{{{n}}} = {point_text(a[0])}"),
        worked("B(0)", b[0], f"B(0) = Q_0 = {point_text(b[0])}"),
        worked(
            "A'(1)",
            a[1],
            f"A'(1) = n(P_{{{n}}} - P_{{{n - 1}}}) = {n} \\cdot ({a_end} - {a_before}) = "
            f"{point_text(a[1])}",
        ),
        worked(
            "B'(0)",
            b[1],
            f"B'(0) = m(Q_1 - Q_0) = {m} \\cdot ({b_next} - {b_start}) = {point_text(b[1])}",
        ),
        _second("A''(1)", a_pts[::-1], a[2], "P", n, True),
        _second("B''(0)", b_pts, b[2], "Q", m, False),
        worked(
            "continuity",
            _ORDERS[level] if level >= 0 else None,
            f"\\text{{continuity at the join: {_verdict(level)}}}",
        ),
    )


def _join_notes(level: int, a_tangent: Point, b_tangent: Point) -> tuple[str, ...]:
    notes = [
        "$A(t)$ has control points $P_0 \\ldots P_n$, $B(t)$ has $Q_0 \\ldots Q_m$; each runs over "
        "$0 \\le t \\le 1$ and they join at $A(1)$ and $B(0)$.",
        "C0: positions equal (position continuity); C1: first derivatives equal (tangent "
        "continuity); C2: second derivatives equal too (curvature continuity).",
    ]
    if level == 0 and same_direction(a_tangent, b_tangent):
        notes.append(
            "The tangents point the same way but differ in length: the join is G1 (geometric "
            "tangent continuity), though not C1."
        )
    notes.append(JOIN_NOTE)
    return tuple(notes)


def _joined_polyline(
    a_pts: Sequence[Point], b_pts: Sequence[Point], samples: int
) -> list[tuple[float, float]]:
    """Both segments, sampled densely, as one polyline (for the figure)."""
    ts = dense_ts(0, 1, samples)
    return [
        *dense_curve(lambda t: bernstein(len(a_pts) - 1, t), a_pts, ts),
        *dense_curve(lambda t: bernstein(len(b_pts) - 1, t), b_pts, ts),
    ]


def continuity_solution(
    first: Sequence[Point], second: Sequence[Point], samples: int = DEFAULT_SAMPLES
) -> Solution:
    """Classify the join of two Bezier segments: the highest of C0, C1, C2 that holds.

    >>> sol = continuity_solution([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)])
    >>> sol.derived[-1].text
    'continuity at the join: C1 (C0 and C1 hold; C2 fails)'
    """
    a_pts, b_pts = _checked_segments(first, second, samples)
    n, m = len(a_pts) - 1, len(b_pts) - 1
    a = end_derivatives(a_pts, True)
    b = end_derivatives(b_pts, False)
    level = continuity_level(a_pts, b_pts)

    def rows() -> Iterator[tuple[Any, ...]]:
        for k in range(3):
            yield (_ORDERS[k], _QUANTITIES[k], a[k], b[k], a[k] == b[k])

    marks = control_marks((*a_pts, *b_pts))

    def pixels() -> Iterator[Pixel]:
        return curve_pixels(
            (s.pixel for s in bezier(a_pts, samples)), (s.pixel for s in bezier(b_pts, samples))
        )

    return Solution(
        primitive="curve",
        algorithm="continuity",
        title=f"Continuity of two Bezier segments (degrees {n} and {m}) at their join",
        given=(*given_points(a_pts), *given_points(b_pts, "Q")),
        derived=_join_derived(a_pts, b_pts, a, b, level),
        notes=_join_notes(level, a[1], b[1]),
        walk=Walk(tables=(Table("Continuity at the join", _COLUMNS, rows),)),
        plot=Plot(
            pixels=pixels,
            bbox=bbox(marks),
            marks=marks,
            ideal=(
                Polyline(_joined_polyline(a_pts, b_pts, samples)),
                ControlPolygon(float_points((*a_pts, *b_pts))),
            ),
        ),
        data={"continuity": _ORDERS[level] if level >= 0 else None},
    )


def _second(key: str, pts: Sequence[Point], value: Point, name: str, n: int, end: bool) -> Quantity:
    """The working of ``A''(1)`` or ``B''(0)``; ``pts`` start at the join."""
    deg = "n" if name == "P" else "m"
    if n < 2:
        return worked(key, value, f"{key} = 0 \\; (\\text{{degree 1}})")
    idx = (n, n - 1, n - 2) if end else (0, 1, 2)
    sym = f"{name}_{{{idx[0]}}} - 2{name}_{{{idx[1]}}} + {name}_{{{idx[2]}}}"
    nums = f"{point_text(pts[0])} - 2 \\cdot {point_text(pts[1])} + {point_text(pts[2])}"
    return worked(
        key,
        value,
        f"{key} = {deg}({deg} - 1)({sym}) = {n} \\cdot {n - 1} \\cdot ({nums}) = "
        f"{point_text(value)}",
    )
