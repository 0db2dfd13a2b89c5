"""The Python API: the parametric curves (``scanconv parametric``). See :mod:`scanconv._api`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .params import SAMPLES, T_RANGE
from .values import NumberLike, PointLike, TRangeLike, _bounds, _number, _numbers, _pair, _whole

if TYPE_CHECKING:
    from ..answers.primitives import parametric as answers_parametric
    from ..core.records import Solution
else:  # the command's answer module, loaded by its first call
    answers_parametric = lazy.module("scanconv.answers.primitives.parametric")


CURVE_CENTER = Opt("--center", metavar="X Y", help="Centre (xc, yc).")


@answers
def parametric_circle(
    r: Annotated[NumberLike | None, Arg("Radius r, as in circle (or --radius).")] = None,
    center: Annotated[PointLike, CURVE_CENTER] = (0, 0),
    radius: Annotated[
        NumberLike | None, Opt("--radius", "-r", help="Radius r (default 1).")
    ] = None,
    *,
    t_range: Annotated[TRangeLike | None, T_RANGE] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The parametric circle ``x = xc + r cos t``, ``y = yc + r sin t``, sampled at even steps of t
    (``scanconv parametric circle``).

    Parameters
    ----------
    r : number, optional
        The radius r, > 0, as ``circle`` takes it; or give ``radius``.
    center : (x, y), default (0, 0)
        The centre (xc, yc).
    radius : number, optional
        The radius, by its name (the same as ``r``: one or both, equal); default 1.
    t_range : (lo, hi) of numbers or formulas, optional
        The range of t, each end a number or a constant expression (``(0, "pi")``); default
        0 .. 2π.
    samples : int, optional
        The number of steps of t (``samples + 1`` rows); default 16.

    Returns
    -------
    Answer
        The formulas with the numbers substituted, the step of t, the table of samples
        (``k, t, x(t), y(t)`` and the pixel, each coordinate rounded half up), and the pixels
        joined by Bresenham's line (``.pixels()``).

    Examples
    --------
    >>> sol = parametric_circle(radius=5, samples=4)
    >>> [s.pixel for s in sol.steps()]  # t = 0, π/2, π, 3π/2, 2π
    [(5, 0), (0, 5), (-5, 0), (0, -5), (5, 0)]
    >>> list(sol.pixels())[:3]
    [(5, 0), (4, 1), (3, 2)]
    >>> parametric_circle(5, radius=5).title
    'Parametric circle: centre (0, 0), r = 5'
    """
    if r is not None and radius is not None and _number(r, "r") != _number(radius, "radius"):
        raise InputError(
            f"unexpected extra argument {r}: the radius is already given as {radius}",
            "radius",
        )
    chosen = r if r is not None else radius if radius is not None else 1
    return _parametric(
        "circle",
        t_range,
        samples,
        center=_pair(center, "center"),
        radius=_number(chosen, "radius"),
    )


@answers
def parametric_ellipse(
    center: Annotated[PointLike, CURVE_CENTER] = (0, 0),
    a: Annotated[NumberLike, Opt("--a", help="Semi-axis a (along x).")] = 2,
    b: Annotated[NumberLike, Opt("--b", help="Semi-axis b (along y).")] = 1,
    *,
    t_range: Annotated[TRangeLike | None, T_RANGE] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The parametric ellipse ``x = xc + a cos t``, ``y = yc + b sin t``, sampled at even steps of t
    (``scanconv parametric ellipse``).

    Parameters
    ----------
    center : (x, y), default (0, 0)
        The centre (xc, yc).
    a, b : number, default 2 and 1
        The semi-axes along x and y, > 0.
    t_range : (lo, hi) of numbers or formulas, optional
        The range of t, each end a number or a constant expression (``(0, "pi")``); default
        0 .. 2π.
    samples : int, optional
        The number of steps of t (``samples + 1`` rows); default 16.

    Returns
    -------
    Answer
        The formulas with the numbers substituted, the step of t, the table of samples
        (``k, t, x(t), y(t)`` and the pixel, each coordinate rounded half up), and the pixels
        joined by Bresenham's line (``.pixels()``).

    Examples
    --------
    >>> [s.pixel for s in parametric_ellipse(a=8, b=4, samples=4).steps()]
    [(8, 0), (0, 4), (-8, 0), (0, -4), (8, 0)]
    """
    point = _pair(center, "center")
    a, b = _numbers(a=a, b=b)
    return _parametric("ellipse", t_range, samples, center=point, a=a, b=b)


@answers
def parametric_parabola(
    vertex: Annotated[PointLike, Opt("--vertex", metavar="H K", help="Vertex (h, k).")] = (0, 0),
    a: Annotated[NumberLike, Opt("--a", help="Coefficient a in y = k + a t^2.")] = 1,
    *,
    t_range: Annotated[TRangeLike | None, T_RANGE] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The parametric parabola ``x = h + t``, ``y = k + a t²``, sampled at even steps of t
    (``scanconv parametric parabola``).

    Parameters
    ----------
    vertex : (h, k), default (0, 0)
        The vertex.
    a : number, default 1
        The coefficient of t², not 0.
    t_range : (lo, hi) of numbers or formulas, optional
        The range of t, each end a number or a constant expression (``(0, "pi")``); default
        -3 .. 3.
    samples : int, optional
        The number of steps of t (``samples + 1`` rows); default 16.

    Returns
    -------
    Answer
        The formulas with the numbers substituted, the step of t, the table of samples
        (``k, t, x(t), y(t)`` and the pixel, each coordinate rounded half up), and the pixels
        joined by Bresenham's line (``.pixels()``).

    Examples
    --------
    >>> [s.pixel for s in parametric_parabola(samples=2).steps()]
    [(-3, 9), (0, 0), (3, 9)]
    >>> [s.pixel for s in parametric_parabola((1, 1), "1/2", t_range=(-2, 2), samples=4).steps()]
    [(-1, 3), (0, 2), (1, 1), (2, 2), (3, 3)]
    """
    point = _pair(vertex, "vertex")
    return _parametric("parabola", t_range, samples, vertex=point, a=_number(a, "a"))


@answers
def parametric_line(
    x0: Annotated[NumberLike, Arg("x of the start point P0.", "X0")],
    y0: Annotated[NumberLike, Arg("y of the start point P0.", "Y0")],
    x1: Annotated[NumberLike, Arg("x of the end point P1.", "X1")],
    y1: Annotated[NumberLike, Arg("y of the end point P1.", "Y1")],
    *,
    t_range: Annotated[TRangeLike | None, T_RANGE] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """The parametric line ``x = x0 + t (x1 - x0)``, ``y = y0 + t (y1 - y0)``, 0 <= t <= 1
    (``scanconv parametric line``).

    Parameters
    ----------
    x0, y0, x1, y1 : number
        The end points (x0, y0) and (x1, y1).
    t_range : (lo, hi) of numbers or formulas, optional
        The range of t, each end a number or a constant expression (``(0, "pi")``); default
        0 .. 1.
    samples : int, optional
        The number of steps of t (``samples + 1`` rows); default max(|x1 - x0|, |y1 - y0|), one step per pixel of the major axis.

    Returns
    -------
    Answer
        The formulas with the numbers substituted, the step of t, the table of samples
        (``k, t, x(t), y(t)`` and the pixel, each coordinate rounded half up), and the pixels
        joined by Bresenham's line (``.pixels()``).

    Examples
    --------
    >>> [s.extra[0] for s in parametric_line(0, 0, 4, 2).steps()]  # t
    [0, Fraction(1, 4), Fraction(1, 2), Fraction(3, 4), 1]
    >>> list(parametric_line(0, 0, 4, 2).pixels())
    [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    """
    points = _numbers(x0=x0, y0=y0, x1=x1, y1=y1)
    return _parametric("line", t_range, samples, points=points)


@answers
def parametric_custom(
    x: Annotated[str, Opt("--x", help="x(t), e.g. '3*cos(t)'.", show_default=False)],
    y: Annotated[str, Opt("--y", help="y(t), e.g. '2*sin(t)'.", show_default=False)],
    *,
    t_range: Annotated[TRangeLike | None, T_RANGE] = None,
    samples: Annotated[NumberLike | None, SAMPLES] = None,
) -> Solution:
    """Your own curve ``x = x(t)``, ``y = y(t)`` (``scanconv parametric custom``).

    Parameters
    ----------
    x, y : str
        The formulas in t (``"t*t"``, ``"3*cos(t)"``; :mod:`scanconv.core.expr`: + - * / **,
        sin, cos, sqrt, pi, ...). Rational formulas at rational t are evaluated exactly.
    t_range : (lo, hi) of numbers or formulas, optional
        The range of t, each end a number or a constant expression (``(0, "pi")``); default
        0 .. 1.
    samples : int, optional
        The number of steps of t (``samples + 1`` rows); default 16.

    Returns
    -------
    Answer
        The formulas with the numbers substituted, the step of t, the table of samples
        (``k, t, x(t), y(t)`` and the pixel, each coordinate rounded half up), and the pixels
        joined by Bresenham's line (``.pixels()``).

    Examples
    --------
    >>> sol = parametric_custom("t", "t*t", t_range=(0, 2), samples=2)
    >>> [s.pixel for s in sol.steps()]  # t = 0, 1, 2
    [(0, 0), (1, 1), (2, 4)]
    >>> list(sol.pixels())  # joined by Bresenham's line
    [(0, 0), (1, 1), (1, 2), (2, 3), (2, 4)]
    """
    return _parametric("custom", t_range, samples, x=x, y=y)


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
