"""The worked answers of a Bezier curve: the table of Bernstein weights and points, and de
Casteljau's construction at one t checked against the Bernstein form."""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms.bezier import bernstein, bezier, de_casteljau
from ...algorithms.curve_limits import (
    DEFAULT_SAMPLES,
    Point,
    Value,
    check_bits,
    check_path,
    check_points,
    check_row,
    check_samples,
    check_unit_t,
    check_weights,
    norm_value,
)
from ...algorithms.sampling import (
    bbox,
    combine,
    curve_pixel,
    curve_pixels,
    dense_curve,
    dense_ts,
    float_points,
)
from ...core.ideal import ControlPolygon, Polyline
from ...core.records import Column, Plot, Quantity, Solution, Step, Table, Walk, heading, worked
from ...core.working import tex_to_unicode
from ._shared import (
    JOIN_NOTE,
    K_T_COLUMNS,
    ROUND_NOTE,
    control_marks,
    given_points,
    point_text,
    step_quantity,
    value_text,
    xy_columns,
)


def bernstein_tex(i: int, n: int) -> str:
    """``B_{i,n}(t)`` multiplied out, in TeX: ``3t(1 - t)^{2}``.

    >>> bernstein_tex(1, 3), bernstein_tex(0, 1), bernstein_tex(3, 3)
    ('3t(1 - t)^{2}', '(1 - t)', 't^{3}')
    """
    c = math.comb(n, i)
    tex = (
        ("" if c == 1 else str(c))
        + ("" if i == 0 else "t" if i == 1 else f"t^{{{i}}}")
        + ("" if n == i else "(1 - t)" if n - i == 1 else f"(1 - t)^{{{n - i}}}")
    )
    return tex or "1"


def _bezier_derived(pts: Sequence[Point]) -> list[Quantity]:
    n = len(pts) - 1
    out = [worked("n", n, f"n = \\text{{number of control points}} - 1 = {n + 1} - 1 = {n}")]
    for i in range(n + 1):
        tex = bernstein_tex(i, n)
        out.append(
            worked(
                f"B{i}",
                tex_to_unicode(tex),
                f"B_{{{i},{n}}}(t) = \\binom{{{n}}}{{{i}}} t^{{{i}}} (1 - t)^{{{n - i}}} = {tex}",
            )
        )
    terms = " + ".join(f"{bernstein_tex(i, n)} \\cdot {point_text(p)}" for i, p in enumerate(pts))
    out.append(worked("B(t)", None, f"B(t) = {terms}"))
    return out


def bezier_solution(points: Sequence[Point], samples: int = DEFAULT_SAMPLES) -> Solution:
    """The worked solution of a Bezier curve sampled at ``t = k / samples``.

    >>> sol = bezier_solution([(0, 0), (1, 2), (3, 3), (4, 0)], 8)
    >>> sol.derived[2].text
    'B_{1,3}(t) = C(3, 1) t¹ (1 - t)² = 3t(1 - t)²'
    >>> list(sol.pixels())
    [(0, 0), (0, 1), (1, 1), (1, 2), (2, 2), (3, 2), (4, 1), (4, 0)]
    """
    pts = check_points(points, 2, "a Bezier curve")
    check_samples(samples)
    check_weights(samples, len(pts))
    check_path([pts], samples)
    n = len(pts) - 1
    marks = control_marks(pts)

    def steps() -> Iterator[Step]:
        return bezier(pts, samples)

    check_row(steps(), "Bezier curve")

    dense = dense_curve(lambda t: bernstein(n, t), pts, dense_ts(0, 1, samples))
    derived = [
        *_bezier_derived(pts),
        step_quantity(0, 1, samples, "0", "1"),
    ]
    return Solution(
        primitive="curve",
        algorithm="bezier",
        title=f"Bezier curve of degree {n}: {n + 1} control points, {samples} steps of t",
        given=tuple(given_points(pts)),
        derived=tuple(derived),
        notes=(
            "Weights and points are exact fractions (3 decimals shown); the weights of each "
            "row sum to 1.",
            ROUND_NOTE,
            JOIN_NOTE,
            "The curve starts at $P_0$, ends at $P_n$ and lies in the convex hull of the control "
            "points (marked o in the grid).",
        ),
        walk=Walk(
            columns=(
                *K_T_COLUMNS,
                *(heading(f"B{i}", f"B_{{{i},{n}}}", 3) for i in range(n + 1)),
                *xy_columns(),
            ),
            extra_keys=("t", *(f"B{i}" for i in range(n + 1)), "x_t", "y_t"),
            steps=steps,
        ),
        plot=Plot(
            pixels=lambda: curve_pixels(s.pixel for s in steps()),
            # The curve lies in the convex hull of its control points, so their box contains it.
            bbox=bbox(marks),
            marks=marks,
            ideal=(Polyline(dense), ControlPolygon(float_points(pts))),
        ),
    )


def _point_columns(count: int, name: str) -> tuple[Column, ...]:
    return tuple(heading(f"point_{i}", f"{name}_{{{i}}}") for i in range(count))


def bezier_at_solution(points: Sequence[Point], t: Value) -> Solution:
    """De Casteljau's construction at one ``t`` in [0, 1], checked against Bernstein's form.

    >>> sol = bezier_at_solution([(0, 0), (1, 2), (3, 3), (4, 0)], Fraction(1, 2))
    >>> sol.derived[-1].text
    'B(0.5) = (2, 1.875) → pixel (2, 2)'
    """
    pts = check_points(points, 2, "a Bezier curve")
    t = check_unit_t(t)
    n = len(pts) - 1
    if not isinstance(t, float):  # level r of the construction has denominators den(t)^r
        scale = math.lcm(*(Fraction(c).denominator for p in pts for c in p))
        bits = n * Fraction(t).denominator.bit_length() + scale.bit_length()
        check_bits(bits, "de Casteljau's construction")
    *_, last = de_casteljau(pts, t)
    point: Point = last.extra[0]
    w = tuple(norm_value(v) for v in bernstein(n, t if isinstance(t, float) else Fraction(t)))
    bern = combine(w, pts)
    if bern != point and not isinstance(t, float):  # pragma: no cover - an invariant
        raise AssertionError("de Casteljau and Bernstein disagree")
    marks = control_marks(pts)
    pixel = curve_pixel(*point)
    ts = value_text(t)
    terms = " + ".join(
        f"{value_text(wi)} \\cdot {point_text(p)}" for wi, p in zip(w, pts, strict=True)
    )
    derived = [
        worked(
            "recurrence",
            t,
            f"P_i^{{(r)}} = (1 - t) \\cdot P_i^{{(r-1)}} + t \\cdot P_{{i+1}}^{{(r-1)}} = "
            f"{value_text(1 - t)} \\cdot P_i^{{(r-1)}} + {ts} \\cdot P_{{i+1}}^{{(r-1)}}",
        ),
        worked(
            "bernstein",
            w,
            f"\\text{{Bernstein check: }} B({ts}) = {terms} = {point_text(bern)}",
        ),
        worked(
            "point",
            point,
            f"B({ts}) = {point_text(point)} \\to \\text{{pixel }} {pixel}",
        ),
    ]

    def rows() -> Iterator[tuple[Any, ...]]:
        for s in de_casteljau(pts, t):
            yield (s.k, *s.extra)

    return Solution(
        primitive="curve",
        algorithm="de-casteljau",
        title=f"De Casteljau's construction of a Bezier curve of degree {n} at t = {ts}",
        given=(
            *given_points(pts),
            worked("t", t, f"t = {ts}"),
        ),
        derived=tuple(derived),
        notes=(
            "Each level interpolates neighbouring points of the level above at t; the last "
            "level is the curve point, equal to the Bernstein form.",
            ROUND_NOTE,
        ),
        walk=Walk(
            tables=(
                Table(
                    f"De Casteljau levels at t = {ts} (row r holds P_i^(r))",
                    (heading("r", "r", role="label"), *_point_columns(n + 1, "P")),
                    rows,
                    points=True,
                ),
            )
        ),
        plot=Plot(
            pixels=lambda: iter((pixel,)),
            bbox=bbox((*marks, pixel)),
            marks=marks,
            ideal=(
                Polyline([(float(point[0]), float(point[1]))]),
                ControlPolygon(float_points(pts)),
            ),
            construction="de Casteljau points",
        ),
    )
