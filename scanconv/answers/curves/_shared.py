"""What the curve answers share: how values and points are written in the working, the given
control points, the step of t, the grid marks and the common notes and columns."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction

from ...algorithms.curve_limits import Point, Value
from ...algorithms.sampling import curve_pixel
from ...core.numeric import Number, fmt, fmt_short, fmt_value, normalize
from ...core.records import Column, Pixel, Quantity, heading, worked
from ...core.working import tex_to_unicode


def value_text(v: Value) -> str:
    """A value in the working: exact values briefly (``1.5``, ``1/3``), floats to 3 decimals.

    >>> value_text(Fraction(3, 2)), value_text(Fraction(1, 3)), value_text(2 / 3)
    ('1.5', '1/3', '0.667')
    """
    return fmt(v) if isinstance(v, float) else fmt_short(v)


def point_text(p: Point) -> str:
    """A point in the working: ``(2, 1.875)``.

    >>> point_text((2, Fraction(15, 8)))
    '(2, 1.875)'
    """
    return f"({value_text(p[0])}, {value_text(p[1])})"


def knot_text(knots: Sequence[Number]) -> str:
    """A knot vector in the working: ``(0, 0, 0, 1, 2, 2, 2)``.

    >>> knot_text((0, 0, Fraction(1, 2), 1))
    '(0, 0, 0.5, 1)'
    """
    return "(" + ", ".join(value_text(u) for u in knots) + ")"


def given_points(points: Sequence[Point], name: str = "P") -> list[Quantity]:
    """The control points as given quantities ``P0``, ``P1``, ...

    >>> [q.text for q in given_points([(0, 0), (1, 2)])]
    ['P₀ = (0, 0)', 'P₁ = (1, 2)']
    """
    return [
        worked(f"{name}{i}", p, f"{name}_{{{i}}} = {point_text(p)}") for i, p in enumerate(points)
    ]


def step_quantity(t0: Value, t1: Value, samples: int, lo: str, hi: str) -> Quantity:
    """``Δt = (t1 - t0) / N``, with the range as the answer names it (``lo`` and ``hi`` in TeX).

    >>> step_quantity(0, 1, 8, "0", "1").text
    '0 ≤ t ≤ 1; Δt = (1 - 0) / 8 = 0.125   (8 steps, 9 values of t)'
    """
    if isinstance(t0, float) or isinstance(t1, float):
        dt: Value = (float(t1) - float(t0)) / samples
        shown = f"\\approx {fmt(dt)}"
    else:
        dt = normalize(Fraction(t1 - t0) / samples)
        shown = "= " + fmt_value(dt).replace("≈", "\\approx")
    sub = f"({lo})" if tex_to_unicode(lo).startswith("-") else lo
    return worked(
        "dt",
        dt,
        f"{lo} \\le t \\le {hi};\\ \\Delta t = \\frac{{{hi} - {sub}}}{{{samples}}} {shown} "
        f"\\quad ({samples} \\text{{ steps, }} {samples + 1} \\text{{ values of }} t)",
    )


JOIN_NOTE = (
    "Successive sample pixels are joined with Bresenham's line, walked in the curve's direction "
    "(a tie steps the minor axis, as in scanconv line), so the plotted curve is 8-connected; a "
    "pixel reached twice is plotted once."
)
ROUND_NOTE = "Pixels are round half up, floor(v + 1/2), of each coordinate."
FLOAT_ROUND_NOTE = (
    "Pixels are round half up, floor(v + 1/2), of each coordinate (a float is taken to 9 "
    "decimals first, so float noise cannot move a pixel)."
)


def control_marks(points: Iterable[Point]) -> tuple[Pixel, ...]:
    """The control points as grid marks.

    >>> control_marks([(0, 0), (Fraction(5, 2), 1)])
    ((0, 0), (3, 1))
    """
    return tuple(curve_pixel(*p) for p in points)


K_T_COLUMNS = (heading("k", "k", role="label"), heading("t", "t", 3))
"""The first two columns of the Bezier and B-spline tables."""


def xy_columns() -> tuple[Column, ...]:
    """The last three columns of a curve table: ``x(t)``, ``y(t)`` and the pixel."""
    return (
        heading("x_t", "x(t)", 3),
        heading("y_t", "y(t)", 3),
        heading("pixel", r"\text{pixel } (x, y)"),
    )
