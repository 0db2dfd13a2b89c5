"""The B-spline basis of a degree and a knot vector alone, evaluated at one t: every
``N_{i,d}(t)`` of the Cox–de Boor triangle with its working (the two fractions and the two
lower-degree values, numbers in), then the row ``N_{i,p}(t)`` and its sum."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

from ...algorithms.bspline import basis_levels, domain, span
from ...algorithms.curve_limits import Value, check_exact, norm_value
from ...core.checks import InputError
from ...core.numeric import Number
from ...core.records import Quantity, Solution, Table, Walk, heading, worked
from ._shared import knot_text, value_text
from .bspline import _BSPLINE_NOTES, check_knot_list


def _term(num: str, den: str, a: Any, b: Any, lower: str, value: Value) -> str:
    """One of the two terms, ``(t - u_i)/(u_{i+d} - u_i) · N``, or ``0 (0/0 = 0)``."""
    if a == b:
        return f"0 (u = {value_text(a)} twice: 0/0 = 0)"
    return f"({num})/({den})·{lower}"


def working(u: Sequence[Number], d: int, i: int, t: Value, row: Sequence[Value]) -> str:
    """The Cox–de Boor step for ``N_{i,d}(t)`` from the degree ``d - 1`` row, numbers in.

    >>> from fractions import Fraction
    >>> working((0, 1, 2, 3), 1, 0, Fraction(3, 2), [0, 1, 0])
    '(1.5 - 0)/(1 - 0)·0 + (2 - 1.5)/(2 - 1)·1'
    """
    ts = value_text(t)
    left = _term(
        f"{ts} - {value_text(u[i])}",
        f"{value_text(u[i + d])} - {value_text(u[i])}",
        u[i + d],
        u[i],
        value_text(row[i]),
        row[i],
    )
    right = _term(
        f"{value_text(u[i + d + 1])} - {ts}",
        f"{value_text(u[i + d + 1])} - {value_text(u[i + 1])}",
        u[i + d + 1],
        u[i + 1],
        value_text(row[i + 1]),
        row[i + 1],
    )
    return f"{left} + {right}"


def _derived(
    u: tuple[Number, ...], degree: int, t: Value, s: int, w: Sequence[Value]
) -> tuple[Quantity, ...]:
    """The knots, the number of functions, the span of t, the row N_(i,p)(t) and its sum."""
    m, n = len(u) - 1, len(w) - 1
    total = norm_value(sum(w))
    d0, d1 = domain(u, degree, n)
    ts = value_text(t)
    closed = t >= u[-1]
    shown = [f"N_{{{i},{degree}}} = {value_text(v)}" for i, v in enumerate(w) if v]
    shown.append("\\text{every other is } 0" if shown else "\\text{all } 0")
    rows = [", ".join(shown[i : i + 3]) for i in range(0, len(shown), 3)]  # 3 a printed line
    inside = d0 <= t <= d1
    return (
        worked("knots", u, f"U = {knot_text(u)},\\ m = {m}"),
        worked(
            "n",
            n,
            f"n + 1 = m - p = {m} - {degree} = {n + 1} \\text{{ basis functions }} "
            f"N_{{0,{degree}}} \\ldots N_{{{n},{degree}}}",
        ),
        worked(
            "span",
            s,
            f"u_{{{s}}} = {value_text(u[s])} \\le t = {ts} "
            + ("\\le" if closed else "<")
            + f" u_{{{s + 1}}} = {value_text(u[s + 1])}:\\ N_{{{s},0}}({ts}) = 1, "
            "\\text{ every other } N_{i,0} = 0",
        ),
        worked("basis", tuple(w), f"N_{{i,{degree}}}({ts}):\\ {rows[0]}"),
        *(worked(f"basis_{k + 2}", (), f"\\quad {row}") for k, row in enumerate(rows[1:])),
        worked(
            "sum",
            total,
            f"\\sum_i N_{{i,{degree}}}({ts}) = {value_text(total)}"
            + (
                f" \\quad (t \\text{{ in the domain }} [u_{{{degree}}}, u_{{{n + 1}}}] = "
                f"[{value_text(d0)}, {value_text(d1)}])"
                if inside
                else f" \\quad (t \\text{{ outside the domain }} [{value_text(d0)}, "
                f"{value_text(d1)}]: \\text{{fewer than p + 1 functions}})"
            ),
        ),
    )


def bspline_basis_at_solution(degree: int, knots: Sequence[Number], t: Value) -> Solution:
    """Every ``N_{i,d}(t)`` of a degree-``p`` basis on ``knots`` at one ``t`` in ``[u_0, u_m]``:
    the Cox–de Boor triangle worked with its numbers, and ``N_{i,p}(t)`` for ``i = 0 .. n``.

    Shene's knots {0, 0.25, 0.5, 0.75, 1}, p = 2, at t = 3/8: N_0,2 = 3/4, N_1,2 = 1/8.

    >>> from fractions import Fraction as F
    >>> sol = bspline_basis_at_solution(2, [0, F(1, 4), F(1, 2), F(3, 4), 1], F(3, 8))
    >>> [str(v) for v in sol.data["basis"]]
    ['3/4', '1/8']
    """
    u, m, n = check_knot_list(degree, knots)
    if not u[0] <= t <= u[-1]:
        raise InputError(
            f"t must lie in the knot range [u_0, u_m] = [{value_text(u[0])}, "
            f"{value_text(u[-1])}], got t = {value_text(t)}",
            "t",
        )
    t = norm_value(t)
    levels = basis_levels(u, degree, m - 1, t)
    s = span(u, m - 1, t)
    w = levels[degree][: n + 1]
    check_exact(w, "the basis at this t")
    ts = value_text(t)

    def rows() -> Iterator[tuple[Any, ...]]:
        for d in range(1, degree + 1):
            for i in range(max(s - d, 0), min(s, m - 1 - d) + 1):
                yield (d, i, working(u, d, i, t, levels[d - 1]), levels[d][i])

    derived = _derived(u, degree, t, s, w)
    formula = (
        "N_(i,d)(t) = (t - u_i)/(u_(i+d) - u_i)·N_(i,d-1)(t) + "
        "(u_(i+d+1) - t)/(u_(i+d+1) - u_(i+1))·N_(i+1,d-1)(t); only N_(s-d,d) .. N_(s,d) "
        "can be non-zero, so only those are worked."
    )
    sol = Solution(
        primitive="curve",
        algorithm="bspline-basis-at",
        title=f"B-spline basis of degree {degree} at t = {ts}: knots {knot_text(u)}",
        given=(worked("p", degree, f"p = {degree}"), worked("t", t, f"t = {ts}")),
        derived=derived,
        notes=(
            *_BSPLINE_NOTES,
            formula,
            "No control points: the basis alone, from the degree and the knots; t may lie "
            "anywhere in [u_0, u_m], and the values sum to 1 on the domain [u_p, u_(n+1)].",
        ),
        walk=Walk(
            tables=(
                Table(
                    f"Cox–de Boor at t = {ts}, degree by degree",
                    (
                        heading("d", "d"),
                        heading("i", "i"),
                        heading("working", r"\text{working}"),
                        heading("N", "N_{i,d}(t)", 3),
                    ),
                    rows,
                ),
            )
        ),
    )
    sol.data = {**sol.data, "basis": tuple(w)}
    return sol
