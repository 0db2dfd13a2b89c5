"""The worked octant tables of the circle methods that compute with square roots, sines and
exact fractions (polynomial, trig, symmetric DDA): their coordinates are rounded by a named
rule. :mod:`.circle` puts them in the answer."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from fractions import Fraction
from typing import NamedTuple

from ...algorithms.circles import (
    SQRT_PLACES,
    polynomial,
    sqrt6,
    symmetric_dda,
    trig,
    trig_last,
)
from ...algorithms.conventions import rounder
from ...core.numeric import fmt, fmt_value
from ...core.records import Column, Pixel, Quantity, Step, heading, rule, worked


class Parts(NamedTuple):
    """A circle method's octant answer, as its record's ``answer`` gives it:
    :func:`~scanconv.answers.primitives.circle.circle_solution` mirrors it 8 ways."""

    title: str
    derived: tuple[Quantity, ...]
    columns: tuple[Column, ...]
    extra_keys: tuple[str, ...]
    steps: Callable[[], Iterator[Step]]
    points: Callable[[], Iterator[Pixel]]
    """The octant points, relative to the centre."""
    notes: tuple[str, ...]
    next_pixel: bool = False
    """Row k's point is ``(x_{k+1}, y_{k+1})`` (:attr:`~scanconv.core.records.Walk.next_pixel`)."""


def pixels_of(gen: Callable[[], Iterator[Step]]) -> Callable[[], Iterator[Pixel]]:
    return lambda: (s.pixel for s in gen())


def _rounded_name(rounding: str, v: str) -> str:
    """``\\operatorname{round}(v)`` or ``\\operatorname{trunc}(v)``."""
    name = "trunc" if rounding == "trunc" else "round"
    return f"\\operatorname{{{name}}}({v})"


def polynomial_parts(r: int, rounding: str) -> Parts:
    rnd = rounder(rounding)
    xmax = math.isqrt(r * r // 2)  # the last x with x <= y exactly; one more may qualify
    if xmax < r and rnd(sqrt6(r * r - (xmax + 1) ** 2)) >= xmax + 1:
        xmax += 1
    bound = Fraction(math.isqrt(r * r * SQRT_PLACES * SQRT_PLACES // 2), SQRT_PLACES)
    rounded = _rounded_name(rounding, "y")
    derived = (
        worked("equation", r * r, f"y = \\sqrt{{r^2 - x^2}} = \\sqrt{{{r * r} - x^2}}"),
        worked(
            "x_last",
            xmax,
            f"x = 0, 1, \\ldots \\text{{ while }} x \\le {rounded}\\ (\\text{{the plotted point stays "
            f"on or above the diagonal; }} r/\\sqrt{{2}} = {fmt(bound, 3)}): x = 0 \\ldots {xmax}",
        ),
    )
    columns = (
        heading("k", "x", role="label"),
        heading("y_sqrt", r"y = \sqrt{r^2 - x^2}", 3),
        heading("round_y", rounded),
        heading("pixel", r"\text{point } (x, y)"),
    )
    notes = (
        "y is computed exactly from integer square roots (shown to 3 decimals), "
        "so the rounding never depends on floating-point error.",
    )

    def steps() -> Iterator[Step]:
        return polynomial(r, rounding)

    return Parts(
        "Circle by the polynomial (square-root) method",
        derived,
        columns,
        ("y_sqrt", "round_y"),
        steps,
        pixels_of(steps),
        notes,
    )


_ZERO = rule("zero", r"r = 0:\ \text{only the centre is plotted}")


def trig_parts(r: int, rounding: str) -> Parts:
    if r == 0:
        derived: tuple[Quantity, ...] = (_ZERO,)
    else:
        kmax = trig_last(r, rounding)
        dtheta = Fraction(1, r)
        derived = (
            worked(
                "dtheta",
                dtheta,
                f"\\Delta\\theta = 1/r = 1/{r} \\text{{ rad}} = "
                + fmt_value(dtheta).replace("≈", "\\approx")
                + f" \\text{{ rad}} = {fmt(180 / (math.pi * r), 3)}^\\circ",
            ),
            worked(
                "k_last",
                kmax,
                f"\\theta_k = 90^\\circ - k \\cdot \\Delta\\theta \\text{{ from }} 90^\\circ "
                f"\\text{{ towards }} 45^\\circ\\ (\\pi \\cdot r/4 = {fmt(math.pi * r / 4, 3)} "
                f"\\text{{ steps}}),\\ \\text{{while }} {_rounded_name(rounding, 'x')} \\le "
                f"{_rounded_name(rounding, 'y')}: k = 0 \\ldots {kmax}",
            ),
            rule("equation", r"x = r \cos\theta_k,\ y = r \sin\theta_k"),
        )
    columns = (
        heading("k", "k", role="label"),
        heading("theta_deg", r"\theta_k\ (\text{deg})", 3),
        heading("theta_rad", r"\theta_k\ (\text{rad})", 3),
        heading("x_cos", r"x = r \cos\theta", 3),
        heading("y_sin", r"y = r \sin\theta", 3),
        heading("pixel", r"\text{point}"),
    )
    notes = ("cos and sin are computed in floating point (shown to 3 decimals).",)

    def steps() -> Iterator[Step]:
        return trig(r, rounding)

    return Parts(
        "Circle by the parametric (trigonometric) method",
        derived,
        columns,
        ("theta_deg", "theta_rad", "x_cos", "y_sin"),
        steps,
        pixels_of(steps),
        notes,
    )


def sdda_parts(r: int, rounding: str) -> Parts:
    name, yname = _rounded_name(rounding, "x_k"), _rounded_name(rounding, "y_k")
    if r == 0:
        derived: tuple[Quantity, ...] = (_ZERO,)
    else:
        n = r.bit_length()
        eps = Fraction(1, 2**n)
        lo, hi = 2 ** (n - 1), 2**n
        derived = (
            worked(
                "n",
                n,
                f"2^{{n-1}} \\le r < 2^n: 2^{{{n - 1}}} = {lo} \\le {r} < {hi} = 2^{{{n}}}, "
                f"\\text{{ so }} n = {n}",
            ),
            worked(
                "epsilon",
                eps,
                f"\\varepsilon = 2^{{-n}} = 2^{{-{n}}} = "
                + fmt_value(eps).replace("≈", "\\approx"),
            ),
            rule(
                "update",
                r"x_{k+1} = x_k + \varepsilon \cdot y_k,\ y_{k+1} = y_k - \varepsilon \cdot x_{k+1}"
                r"\ (\text{the new } x)",
            ),
            rule(
                "loop",
                f"\\text{{from }} (x_0, y_0) = (0, {r}) \\text{{ while }} {name} \\le {yname}",
            ),
        )
    columns = (
        heading("k", "k", role="label"),
        heading("x_k", "x_k", 3),
        heading("y_k", "y_k", 3),
        heading("pixel", f"({name}, {yname})"),
    )
    notes = ("x_k and y_k are exact fractions (shown to 3 decimals).",)

    def steps() -> Iterator[Step]:
        return symmetric_dda(r, rounding)

    return Parts(
        "Circle by the symmetric DDA",
        derived,
        columns,
        ("x_k", "y_k"),
        steps,
        pixels_of(steps),
        notes,
    )
