"""The worked answers of a B-spline: the knot vector and domain, the Cox–de Boor recurrence,
the table of basis values and points (or of the basis alone), and the curve at one t."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ...algorithms.bspline import (
    basis_float,
    basis_levels,
    bspline,
    bspline_samples,
    domain,
    knot_vector,
    named_knots,
    span,
)
from ...algorithms.curve_limits import (
    MAX_DEGREE,
    Point,
    Value,
    check_exact,
    check_path,
    check_points,
    check_row,
    check_samples,
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
from ...core.checks import InputError
from ...core.ideal import ControlPolygon, Polyline
from ...core.numeric import Number
from ...core.records import Pixel, Plot, Quantity, Solution, Step, Table, Walk, heading, worked
from ._shared import (
    JOIN_NOTE,
    K_T_COLUMNS,
    ROUND_NOTE,
    control_marks,
    given_points,
    knot_text,
    point_text,
    step_quantity,
    value_text,
    xy_columns,
)


class BsplineSetup(NamedTuple):
    """A checked B-spline problem."""

    points: tuple[Point, ...]
    """The control points, exact."""
    n: int
    """The last control point's index (``n + 1`` points)."""
    knots: tuple[Number, ...]
    """The knot vector ``u_0 .. u_m``."""
    kind: str
    """``open``, ``uniform`` or ``explicit``: how the knots were given."""


def bspline_setup(
    points: Sequence[Point], degree: int, knots: str | Sequence[Number]
) -> BsplineSetup:
    """Check the control points, the degree and the knots; build the knot vector.

    >>> bspline_setup([(0, 0), (1, 2), (3, 3)], 2, "open").knots
    (0, 0, 0, 1, 1, 1)
    """
    pts = check_points(points, 2, "a B-spline")
    n = len(pts) - 1
    u = knot_vector(knots, n, degree)
    kind = knots if isinstance(knots, str) else "explicit"
    return BsplineSetup(pts, n, u, kind)


def _knots_note(kind: str, p: int) -> str:
    """What the knot vector is, as the working notes it (TeX).

    >>> print(_knots_note("open", 2), _knots_note("uniform", 2), _knots_note("explicit", 2))
    (\\text{open: } p + 1 = 3 \\text{ equal end knots, uniform inside}) (\\text{uniform: equally spaced, not clamped}) (\\text{as given})
    """
    named = named_knots(kind)
    if named is None:
        return r"(\text{as given})"
    if named.clamped:
        return f"(\\text{{{named.name}: }} p + 1 = {p + 1} \\text{{ {named.words}}})"
    return f"(\\text{{{named.name}: {named.words}}})"


def _bspline_derived(
    pts: Sequence[Point], p: int, knots: Sequence[Number], kind: str
) -> list[Quantity]:
    n = len(pts) - 1
    m = n + p + 1
    t0, t1 = domain(knots, p, n)
    # Kept short: LaTeX cannot break this line (inline math) and it must fit the page width.
    how = _knots_note(kind, p)
    terms = " + ".join(f"N_{{{i},{p}}}(t) \\cdot {point_text(pt)}" for i, pt in enumerate(pts))
    return [
        worked(
            "n",
            n,
            f"n = \\text{{number of control points}} - 1 = {n + 1} - 1 = {n};\\ "
            f"\\text{{degree }} p = {p}",
        ),
        worked(
            "m",
            m,
            f"m = n + p + 1 = {n} + {p} + 1 = {m}: \\; \\text{{knots }} u_0 \\ldots u_{{{m}}}",
        ),
        worked("knots", tuple(knots), f"U = {knot_text(knots)}\\ {how}"),
        worked(
            "domain",
            (t0, t1),
            f"\\text{{domain }} u_p \\le t \\le u_{{n+1}}: \\; u_{{{p}}} = {value_text(t0)} "
            f"\\le t \\le u_{{{n + 1}}} = {value_text(t1)}",
        ),
        worked("N0", None, r"N_{i,0}(t) = 1 \text{ if } u_i \le t < u_{i+1}, \text{ else } 0"),
        worked(
            "Np",
            None,
            r"N_{i,p}(t) = \frac{t - u_i}{u_{i+p} - u_i} \cdot N_{i,p-1}(t) + "
            r"\frac{u_{i+p+1} - t}{u_{i+p+1} - u_{i+1}} \cdot N_{i+1,p-1}(t) \quad (0/0 = 0)",
        ),
        worked("C(t)", None, f"C(t) = {terms}"),
    ]


_BSPLINE_NOTES = (
    "Cox–de Boor with 0/0 taken as 0; at the right end of the domain the last non-empty span "
    "is closed, so a clamped curve ends exactly on its last control point.",
)


def bspline_solution(
    points: Sequence[Point],
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int | None = None,
    *,
    basis_only: bool = False,
) -> Solution:
    """The worked solution of a B-spline; ``basis_only``: only the table of ``N_{i,p}(t)``.

    >>> sol = bspline_solution([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", 4)
    >>> sol.derived[2].text
    'U = (0, 0, 0, 1, 2, 3, 3, 3) (open: p + 1 = 3 equal end knots, uniform inside)'
    >>> list(sol.pixels())[-1]
    (5, 2)
    """
    pts, n, u, kind = bspline_setup(points, degree, knots)
    samples = bspline_samples(u, degree, n) if samples is None else check_samples(samples)
    check_weights(samples, n + 1)
    if not basis_only:
        check_path([pts], samples)
    t0, t1 = domain(u, degree, n)

    def steps() -> Iterator[Step]:
        return bspline(pts, degree, u, samples)

    check_row(steps(), "B-spline")

    derived = [
        *_bspline_derived(pts, degree, u, kind),
        step_quantity(t0, t1, samples, value_text(t0), value_text(t1)),
    ]
    basis_cols = tuple(heading(f"N{i}", f"N_{{{i},{degree}}}", 3) for i in range(n + 1))
    title = (
        f"B-spline of degree {degree}: {n + 1} control points, knots {knot_text(u)}, "
        f"{samples} steps of t"
    )
    if basis_only:

        def rows() -> Iterator[tuple[Any, ...]]:
            for s in steps():
                yield (s.k, *s.extra[: n + 2])

        return Solution(
            primitive="curve",
            algorithm="bspline-basis",
            title="Basis functions of a " + title,
            given=(worked("p", degree, f"p = {degree}"),),
            derived=tuple(q for q in derived if q.key != "C(t)"),
            notes=_BSPLINE_NOTES,
            walk=Walk(
                tables=(
                    Table(
                        f"Basis functions N_(i,{degree})(t) (each row sums to 1)",
                        (*K_T_COLUMNS, *basis_cols),
                        rows,
                    ),
                )
            ),
        )
    marks = control_marks(pts)
    dense = dense_curve(lambda t: basis_float(u, degree, n, t), pts, dense_ts(t0, t1, samples))
    keys = ("t", *(f"N{i}" for i in range(n + 1)), "x_t", "y_t")
    return Solution(
        primitive="curve",
        algorithm="bspline",
        title=title,
        given=tuple(given_points(pts)),
        derived=tuple(derived),
        notes=(
            *_BSPLINE_NOTES,
            "Basis values and points are exact fractions (3 decimals shown).",
            ROUND_NOTE,
            JOIN_NOTE,
            "Control points are marked o in the grid; a clamped (open) curve passes through the "
            "first and last of them, an unclamped one in general through none.",
        ),
        walk=Walk(columns=(*K_T_COLUMNS, *basis_cols, *xy_columns()), extra_keys=keys, steps=steps),
        plot=Plot(
            pixels=lambda: curve_pixels(s.pixel for s in steps()),
            # Basis values are >= 0 and sum to 1 on the domain: the curve lies in the convex hull.
            bbox=bbox(marks),
            marks=marks,
            ideal=(Polyline(dense), ControlPolygon(float_points(pts))),
        ),
    )


class _At(NamedTuple):
    """A B-spline evaluated at one t: the Cox–de Boor levels, the span, the point."""

    pts: tuple[Point, ...]
    degree: int
    u: tuple[Number, ...]
    kind: str
    t: Value
    levels: list[list[Value]]
    w: list[Value]
    """The degree-p basis values N_(i,p)(t), i = 0 .. n."""
    s: int
    """The span: u_s <= t < u_(s+1)."""
    point: tuple[Value, Value]
    pixel: Pixel
    nz: list[int]
    """The i with N_(i,p)(t) non-zero."""
    closed: bool
    """t is the domain's right end (the last non-empty span is closed)."""


def _evaluate(points: Sequence[Point], degree: int, knots: str | Sequence[Number], t: Value) -> _At:
    """The B-spline at ``t``, every input checked (t inside the domain)."""
    pts, n, u, kind = bspline_setup(points, degree, knots)
    t0, t1 = domain(u, degree, n)
    if not t0 <= t <= t1:
        raise InputError(
            f"t must lie in the domain [u_p, u_(n+1)] = [{value_text(t0)}, {value_text(t1)}], "
            f"got t = {value_text(t)}",
            "t",
        )
    t = norm_value(t)
    levels = basis_levels(u, degree, n, t)
    w = levels[degree][: n + 1]
    point = combine(w, pts)
    check_exact((*w, *point), "the B-spline at this t")
    nz = [i for i in range(n + 1) if w[i] != 0]
    return _At(
        pts, degree, u, kind, t, levels, w, span(u, n, t), point, curve_pixel(*point), nz, t == t1
    )


def _at_derived(a: _At) -> tuple[Quantity, ...]:
    """The knots and domain, the span of t, the non-zero basis values and the point."""
    s, u, w, degree, nz = a.s, a.u, a.w, a.degree, a.nz
    ts = value_text(a.t)
    span_tex = (
        f"t = {ts} \\text{{ lies in span }} s = {s}: \\; u_{{{s}}} = {value_text(u[s])} \\le t "
        + ("\\le" if a.closed else "<")
        + f" u_{{{s + 1}}} = {value_text(u[s + 1])}"
        + (r" \quad (\text{right end: the last non-empty span is closed})" if a.closed else "")
    )
    values = ", ".join(f"N_{{{i},{degree}}}({ts}) = {value_text(w[i])}" for i in nz)
    terms = " + ".join(f"{value_text(w[i])} \\cdot {point_text(a.pts[i])}" for i in nz)
    return (
        *(q for q in _bspline_derived(a.pts, degree, u, a.kind) if q.key not in ("N0", "Np")),
        worked("span", s, span_tex),
        worked(
            "nonzero",
            tuple(nz),
            f"\\text{{non-zero basis values: }} {values} \\quad "
            f"(\\text{{sum}} = {value_text(sum(w[i] for i in nz))})",
        ),
        worked(
            "point",
            a.point,
            f"C({ts}) = {terms} = {point_text(a.point)} \\to \\text{{pixel }} {a.pixel}",
        ),
    )


def _triangle_table(a: _At) -> Table:
    """The Cox–de Boor triangle: N_(i,d)(t) for d = 0 .. p, the span's functions only."""
    s, levels = a.s, a.levels
    lo = max(s - a.degree, 0)
    tri_cols = tuple(heading(f"N{i}", f"N_{{{i},d}}", 3) for i in range(lo, s + 1))

    def triangle() -> Iterator[tuple[Any, ...]]:
        for d, row in enumerate(levels):
            yield (d, *(row[i] if s - d <= i < len(row) else None for i in range(lo, s + 1)))

    return Table(
        f"Cox–de Boor at t = {value_text(a.t)}: N_(i,d) for d = 0 .. {a.degree} (only the "
        "span's functions can be non-zero)",
        (heading("d", "d"), *tri_cols),
        triangle,
    )


def _weighted_table(a: _At) -> Table:
    """The non-zero terms N_(i,p)(t) · P_i of the point."""
    w, pts = a.w, a.pts

    def weighted() -> Iterator[tuple[Any, ...]]:
        for i in a.nz:
            yield (i, w[i], pts[i], (norm_value(w[i] * pts[i][0]), norm_value(w[i] * pts[i][1])))

    return Table(
        "Weighted sum of the non-zero terms",
        (
            heading("i", "i", role="label"),
            heading("N", f"N_{{i,{a.degree}}}(t)", 3),
            heading("point_P", "P_i"),
            heading("point_NP", f"N_{{i,{a.degree}}}(t) \\cdot P_i"),
        ),
        weighted,
    )


def bspline_at_solution(
    points: Sequence[Point], degree: int, knots: str | Sequence[Number], t: Value
) -> Solution:
    """One ``t``: the Cox–de Boor triangle, the non-zero ``N_{i,p}(t)``, their weighted sum.

    >>> from fractions import Fraction
    >>> sol = bspline_at_solution([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", Fraction(3, 2))
    >>> sol.derived[-1].text
    'C(1.5) = 0.125·(1, 2) + 0.75·(3, 3) + 0.125·(4, 0) = (2.875, 2.5) → pixel (3, 3)'
    """
    a = _evaluate(points, degree, knots, t)
    ts = value_text(a.t)
    marks = control_marks(a.pts)
    return Solution(
        primitive="curve",
        algorithm="bspline-at",
        title=f"B-spline of degree {degree} at t = {ts}: knots {knot_text(a.u)}",
        given=(*given_points(a.pts), worked("t", a.t, f"t = {ts}")),
        derived=_at_derived(a),
        notes=(*_BSPLINE_NOTES, ROUND_NOTE),
        walk=Walk(tables=(_triangle_table(a), _weighted_table(a))),
        plot=Plot(
            pixels=lambda: iter((a.pixel,)),
            bbox=bbox((*marks, a.pixel)),
            marks=marks,
            ideal=(
                Polyline([(float(a.point[0]), float(a.point[1]))]),
                ControlPolygon(float_points(a.pts)),
            ),
        ),
    )


def check_knot_list(degree: int, knots: Sequence[Number]) -> tuple[tuple[Number, ...], int, int]:
    """A degree and an explicit knot vector alone, checked: ``(u, m, n)`` with ``u_0 .. u_m``
    and ``n + 1 = m - p`` basis functions.

    >>> check_knot_list(2, [0, 1, 2, 3, 4])
    ((0, 1, 2, 3, 4), 4, 1)
    """
    if not 1 <= degree <= MAX_DEGREE:
        raise InputError(f"degree must satisfy 1 <= p <= {MAX_DEGREE}, got p = {degree}", "degree")
    u = tuple(norm_value(Fraction(v)) for v in knots)
    m = len(u) - 1
    n = m - degree - 1
    if n < 0:
        raise InputError(
            f"a degree-{degree} basis needs at least p + 2 = {degree + 2} knots, got {len(u)}",
            "knots",
        )
    for i in range(m):
        if u[i] > u[i + 1]:
            raise InputError(
                f"knot vector must be non-decreasing: u_{i} = {value_text(u[i])} > "
                f"u_{i + 1} = {value_text(u[i + 1])}",
                "knots",
            )
    if any(u.count(v) > degree + 1 for v in set(u)):
        raise InputError(f"a knot may repeat at most p + 1 = {degree + 1} times", "knots")
    return u, m, n


def bspline_basis_knots_solution(
    degree: int, knots: Sequence[Number], samples: int | None = None
) -> Solution:
    """The basis functions ``N_{i,p}(t)`` of a degree and a knot vector alone (no control
    points), tabulated over the whole knot range ``[u_0, u_m]``, as textbooks print them.

    ``n + 1 = m - p`` functions; the rows sum to 1 only on the domain ``[u_p, u_{n+1}]``.

    >>> from fractions import Fraction as F
    >>> sol = bspline_basis_knots_solution(2, [0, F(1, 4), F(1, 2), F(3, 4), 1], 4)
    >>> [tuple(str(v) for v in row[2:]) for row in sol.tables[0].rows()][1:4]
    [('1/2', '0', '1/2'), ('1/2', '1/2', '1'), ('0', '1/2', '1/2')]
    """
    u, m, n = check_knot_list(degree, knots)
    t0, t1 = u[0], u[-1]
    samples = 2 * m if samples is None else check_samples(samples)
    check_weights(samples, n + 1)
    ts = [norm_value(t0 + (t1 - t0) * Fraction(k, samples)) for k in range(samples + 1)]

    def rows() -> Iterator[tuple[Any, ...]]:
        for k, t in enumerate(ts):
            w = basis_levels(u, degree, m - 1, t)[degree][: n + 1]
            yield (k, t, *w, norm_value(sum(w)))

    basis_cols = tuple(heading(f"N{i}", f"N_{{{i},{degree}}}", 3) for i in range(n + 1))
    d0, d1 = domain(u, degree, n)
    derived = (
        worked("p", degree, f"p = {degree}"),
        worked("knots", tuple(u), f"U = {knot_text(u)},\\ m = {m}"),
        worked(
            "n",
            n,
            f"n + 1 = m - p = {m} - {degree} = {n + 1} \\text{{ basis functions }} "
            f"N_{{0,{degree}}} \\ldots N_{{{n},{degree}}}",
        ),
        worked(
            "range",
            (t0, t1),
            f"t \\text{{ from }} u_0 = {value_text(t0)} \\text{{ to }} u_{{{m}}} = "
            f"{value_text(t1)} \\text{{ in {samples} steps; the rows sum to 1 on the domain }} "
            f"[u_{{{degree}}}, u_{{{n + 1}}}] = [{value_text(d0)}, {value_text(d1)}]",
        ),
    )
    return Solution(
        primitive="curve",
        algorithm="bspline-basis",
        title=f"B-spline basis functions of degree {degree} on the knots {knot_text(u)}",
        given=(worked("p", degree, f"p = {degree}"),),
        derived=derived[1:],
        notes=(
            *_BSPLINE_NOTES,
            "No control points: the table is the basis alone, over [u_0, u_m]; outside the "
            "domain [u_p, u_(n+1)] fewer than p + 1 functions are non-zero and the sum is below 1.",
        ),
        walk=Walk(
            tables=(
                Table(
                    f"Basis functions N_(i,{degree})(t) over the whole knot range",
                    (*K_T_COLUMNS, *basis_cols, heading("sum", r"\sum_i N_{i,p}", 3)),
                    rows,
                ),
            )
        ),
    )
