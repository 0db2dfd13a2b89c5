"""The worked answer of a parametric curve: the formulas with the numbers substituted, the step
of t, the table of samples and the joined pixels.

Each curve of :data:`PARAMETRIC` is described by a :class:`_Spec` (its formulas, their working,
the default range of t and the given values), built by the factory its record names.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import NamedTuple

from ...algorithms.curve_limits import DEFAULT_SAMPLES, Point, Value, check_samples, exact_point
from ...algorithms.parametric import check_float_path, exact_values, float_reason, parametric
from ...algorithms.sampling import curve_pixel, curve_pixels, dense_ts, path_bbox, polyline
from ...core.checks import InputError
from ...core.expr import Expr, compile_expr, parse_exact
from ...core.ideal import Polyline
from ...core.numeric import Number, fmt_short, normalize
from ...core.records import Pixel, Plot, Quantity, Solution, Step, Walk, heading, worked
from ...core.working import tex_text, tex_to_unicode
from ..curves._shared import (
    FLOAT_ROUND_NOTE,
    JOIN_NOTE,
    ROUND_NOTE,
    point_text,
    step_quantity,
    value_text,
    xy_columns,
)


def _affine(a: Value, c: Value, var: str) -> str:
    """``a + c·var`` in TeX as the working writes it: ``0 + 5 \\cos t``, ``2 - t^2``, ``0 + 10t``.

    >>> _affine(0, 5, r"\\cos t"), _affine(2, -1, "t^2"), _affine(0, Fraction(1, 2), "t")
    ('0 + 5 \\\\cos t', '2 - t^2', '0 + 0.5t')
    """
    mag: Value = -c if c < 0 else c
    coef = "" if mag == 1 else value_text(mag) + ("" if var.startswith("t") else " ")
    return f"{value_text(a)} {'-' if c < 0 else '+'} {coef}{var}"


def _expr_literal(v: Value) -> str:
    """A number as a literal of a formula: ``3``, ``(-1/3)``.

    >>> _expr_literal(3), _expr_literal(Fraction(-1, 3))
    ('3', '(-1/3)')
    """
    s = str(normalize(Fraction(v)))
    return s if s.isdigit() else f"({s})"


def _words(text: str) -> str:
    """A formula with its whitespace collapsed, as the working shows it."""
    return " ".join(text.split())


def _typed(text: str) -> str:
    """A formula typed by the user, in TeX: as typed, in typewriter type.

    >>> _typed("3*cos(t)")
    '\\\\texttt{3*cos(t)}'
    """
    return f"\\texttt{{{tex_text(text)}}}"


@dataclass(frozen=True, slots=True)
class _Range:
    """A parameter bound: its value (exact or float), its text for messages and its TeX for
    the working."""

    value: Value
    text: str
    tex: str

    @classmethod
    def of(cls, value: Value, text: str | None = None, tex: str | None = None) -> _Range:
        """A bound shown as ``text`` (default: the value) and ``tex`` (default: ``text``)."""
        shown = text if text is not None else value_text(value)
        return cls(value, shown, tex if tex is not None else shown)


TWO_PI = _Range(2 * math.pi, "2π", r"2\pi")


class _Working(NamedTuple):
    """One coordinate's formula in TeX: in general, and with the numbers substituted."""

    tex: str
    substituted: str


@dataclass(frozen=True, slots=True)
class _Spec:
    """What distinguishes one parametric curve: formulas, their working and defaults."""

    x: Expr
    y: Expr
    x_work: _Working
    y_work: _Working
    t_range: tuple[_Range, _Range]
    given: tuple[Quantity, ...]
    samples: int
    title: str
    marks: tuple[Point, ...] = ()


@dataclass(frozen=True, slots=True)
class _Inputs:
    """The keyword arguments of :func:`parametric_solution` that describe the curve."""

    points: Sequence[Number]
    center: Point
    radius: Number
    a: Number
    b: Number
    vertex: Point
    x: str
    y: str


def _formulas(x: str, y: str) -> tuple[Expr, Expr]:
    return compile_expr(x, ("t",)), compile_expr(y, ("t",))


def _line_spec(inp: _Inputs) -> _Spec:
    if len(inp.points) != 4:
        raise InputError("parametric line needs x0 y0 x1 y1", "points")
    x0, y0, x1, y1 = (normalize(v) for v in inp.points)
    dx, dy = normalize(x1 - x0), normalize(y1 - y0)
    p0, p1 = point_text((x0, y0)), point_text((x1, y1))
    return _Spec(
        *_formulas(
            f"{_expr_literal(x0)} + t*{_expr_literal(dx)}",
            f"{_expr_literal(y0)} + t*{_expr_literal(dy)}",
        ),
        _Working("x(t) = x_0 + t(x_1 - x_0)", _affine(x0, dx, "t")),
        _Working("y(t) = y_0 + t(y_1 - y_0)", _affine(y0, dy, "t")),
        (_Range.of(0), _Range.of(1)),
        (worked("P0", (x0, y0), f"P_0 = {p0}"), worked("P1", (x1, y1), f"P_1 = {p1}")),
        max(1, math.ceil(max(abs(Fraction(dx)), abs(Fraction(dy))))),
        f"Parametric line: {p0} to {p1}",
    )


def _conic_spec(
    center: Point, ra: Number, rb: Number, names: tuple[str, str], given: list[Quantity], title: str
) -> _Spec:
    """The circle and the ellipse: ``x = xc + ra cos t``, ``y = yc + rb sin t``, 0 ≤ t ≤ 2π."""
    xc, yc = center
    c = point_text(center)
    return _Spec(
        *_formulas(
            f"{_expr_literal(xc)} + {_expr_literal(ra)}*cos(t)",
            f"{_expr_literal(yc)} + {_expr_literal(rb)}*sin(t)",
        ),
        _Working(f"x(t) = x_c + {names[0]} \\cos t", _affine(xc, ra, r"\cos t")),
        _Working(f"y(t) = y_c + {names[1]} \\sin t", _affine(yc, rb, r"\sin t")),
        (_Range.of(0), TWO_PI),
        (worked("center", center, f"\\text{{centre }} (x_c, y_c) = {c}"), *given),
        DEFAULT_SAMPLES,
        title,
        marks=(center,),
    )


def _given(key: str, v: Number) -> Quantity:
    return worked(key, v, f"{key} = {value_text(v)}")


def _circle_spec(inp: _Inputs) -> _Spec:
    center = exact_point(inp.center)
    r = normalize(inp.radius)
    if r <= 0:
        raise InputError(f"radius must be positive, got {fmt_short(r)}", "radius")
    title = f"Parametric circle: centre {point_text(center)}, r = {value_text(r)}"
    return _conic_spec(center, r, r, ("r", "r"), [_given("r", r)], title)


def _ellipse_spec(inp: _Inputs) -> _Spec:
    center = exact_point(inp.center)
    a, b = normalize(inp.a), normalize(inp.b)
    if a <= 0 or b <= 0:
        raise InputError(
            f"a and b must be positive, got a = {value_text(a)}, b = {value_text(b)}",
            "a" if a <= 0 else "b",
        )
    title = (
        f"Parametric ellipse: centre {point_text(center)}, a = {value_text(a)}, b = {value_text(b)}"
    )
    return _conic_spec(center, a, b, ("a", "b"), [_given("a", a), _given("b", b)], title)


def _parabola_spec(inp: _Inputs) -> _Spec:
    h, k = exact_point(inp.vertex)
    a = normalize(inp.a)
    if a == 0:
        raise InputError("a must not be 0 (y = k + a t^2 would be a line)", "a")
    v = point_text((h, k))
    return _Spec(
        *_formulas(f"{_expr_literal(h)} + t", f"{_expr_literal(k)} + {_expr_literal(a)}*t**2"),
        _Working("x(t) = h + t", f"{value_text(h)} + t"),
        _Working("y(t) = k + a t^2", _affine(k, a, "t^2")),
        (_Range.of(-3), _Range.of(3)),
        (worked("vertex", (h, k), f"\\text{{vertex }} (h, k) = {v}"), _given("a", a)),
        DEFAULT_SAMPLES,
        f"Parametric parabola: vertex {v}, a = {value_text(a)}",
    )


def _custom_spec(inp: _Inputs) -> _Spec:
    for name, formula in (("x", inp.x), ("y", inp.y)):
        if not formula.strip():
            raise InputError(
                f"a custom curve needs both formulas x(t) and y(t) ({name}(t) is empty)", name
            )
    fx, fy = _formulas(inp.x, inp.y)
    x, y = _words(inp.x), _words(inp.y)
    return _Spec(
        fx,
        fy,
        _Working("x(t)", _typed(x)),
        _Working("y(t)", _typed(y)),
        (_Range.of(0), _Range.of(1)),
        (),
        DEFAULT_SAMPLES,
        f"Parametric curve: x(t) = {x}, y(t) = {y}",
    )


class _Curve(NamedTuple):
    """A parametric curve, declared once: its name and how its :class:`_Spec` is built from
    the inputs."""

    name: str
    build: Callable[[_Inputs], _Spec]


_CURVES = (
    _Curve("circle", _circle_spec),
    _Curve("ellipse", _ellipse_spec),
    _Curve("parabola", _parabola_spec),
    _Curve("line", _line_spec),
    _Curve("custom", _custom_spec),
)

PARAMETRIC = tuple(c.name for c in _CURVES)
"""The parametric curves, by their names: circle, ellipse, parabola, line, custom."""


def parametric_solution(
    kind: str,
    *,
    points: Sequence[Number] = (),
    center: Point = (0, 0),
    radius: Number = 1,
    a: Number = 1,
    b: Number = 1,
    vertex: Point = (0, 0),
    x: str = "",
    y: str = "",
    t_range: tuple[Value | str, Value | str] | None = None,
    samples: int | None = None,
) -> Solution:
    """The worked solution of one of the parametric curves of :data:`PARAMETRIC`.

    ``points`` are ``x0 y0 x1 y1`` for ``line``; ``center`` and ``radius`` for ``circle``;
    ``center``, ``a`` and ``b`` for ``ellipse``; ``vertex`` and ``a`` for ``parabola``
    (``x = h + t``, ``y = k + a t^2``); the formulas ``x`` and ``y`` for ``custom``. A bound of
    ``t_range`` may be a formula (``"2*pi"``).

    >>> sol = parametric_solution("circle", radius=5, samples=4)
    >>> [q.text for q in sol.derived[:2]]
    ['x(t) = x_c + r cos t = 0 + 5 cos t', 'y(t) = y_c + r sin t = 0 + 5 sin t']
    >>> list(sol.pixels())[:3]
    [(5, 0), (4, 1), (3, 2)]
    """
    curve = next((c for c in _CURVES if c.name == kind), None)
    if curve is None:
        raise InputError(
            f"unknown parametric curve {kind!r} (choose from {', '.join(PARAMETRIC)})", "kind"
        )
    spec = curve.build(_Inputs(points, center, radius, a, b, vertex, x, y))
    lo, hi = spec.t_range if t_range is None else (_bound(t_range[0]), _bound(t_range[1]))
    exact = not (isinstance(lo.value, float) or isinstance(hi.value, float))
    if (exact and lo.value > hi.value) or float(lo.value) > float(hi.value):
        raise InputError(f"t range must run upward: {lo.text} > {hi.text}", "t_range")
    return _parametric_solution(kind, spec, lo, hi, spec.samples if samples is None else samples)


def _bound(v: Value | str) -> _Range:
    """A bound of the t range: a number, or a formula such as ``2*pi`` (exact if rational).

    >>> _bound("2*pi").text, _bound("1/2").value
    ('2*pi', Fraction(1, 2))
    """
    if not isinstance(v, str):
        return _Range.of(normalize(v) if isinstance(v, (int, Fraction)) else v)
    value = parse_exact(v)
    if isinstance(value, Fraction):
        return _Range.of(normalize(value))
    text = _words(v)
    return _Range.of(value, text, _typed(text))


def _formula(key: str, work: _Working) -> Quantity:
    """``x(t) = x_c + r cos t = 0 + 5 cos t``; its value is the substituted formula."""
    return worked(key, tex_to_unicode(work.substituted), f"{work.tex} = {work.substituted}")


def _parametric_solution(kind: str, spec: _Spec, lo: _Range, hi: _Range, samples: int) -> Solution:
    check_samples(samples)
    fx, fy = spec.x, spec.y
    t0, t1 = lo.value, hi.value
    marks = tuple(curve_pixel(*m) for m in spec.marks)

    def steps() -> Iterator[Step]:
        return parametric(fx, fy, t0, t1, samples)

    def pixels() -> Iterator[Pixel]:
        return curve_pixels(s.pixel for s in steps())

    # One pass evaluates every sample: a domain error, an out-of-range point or a pixel path
    # that is too long is reported here, before any output, and gives the bounding box.
    check_float_path(fx, fy, t0, t1, samples)  # a path certainly too long: refused at once
    bbox = path_bbox(steps(), marks)
    try:
        ts = dense_ts(t0, t1, samples)
        dense = polyline([fx(t=t) for t in ts], [fy(t=t) for t in ts])
    except ValueError:  # a singularity between the samples: draw the samples only
        dense = [(float(s.extra[1]), float(s.extra[2])) for s in steps()]
    derived = [
        _formula("x(t)", spec.x_work),
        _formula("y(t)", spec.y_work),
        step_quantity(t0, t1, samples, lo.tex, hi.tex),
    ]
    exact = exact_values(fx, fy, t0, t1, samples)
    notes = [
        "x(t) and y(t) are computed exactly (fractions) at each t_k."
        if exact
        else "x(t) and y(t) are computed in floating point and shown to 3 decimals."
        + float_reason(fx, fy, t0, t1, samples),
        ROUND_NOTE if exact else FLOAT_ROUND_NOTE,
        JOIN_NOTE,
    ]
    if marks:
        notes.append("The centre is marked o in the grid.")
    return Solution(
        primitive="parametric",
        algorithm=kind,
        title=spec.title,
        given=spec.given,
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("t", "t_k", 3),
                *xy_columns(),
            ),
            extra_keys=("t", "x_t", "y_t"),
            steps=steps,
        ),
        plot=Plot(
            pixels=pixels,
            bbox=bbox,
            marks=marks,
            marks_label="centre" if marks else None,
            ideal=(Polyline(dense),),
        ),
        data={"x_formula": fx.text, "y_formula": fy.text},
    )
