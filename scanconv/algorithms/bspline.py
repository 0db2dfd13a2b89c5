"""B-splines: knot vectors, the Cox–de Boor recurrence and the curve tabulated over its domain.

``n + 1`` control points, degree ``p`` and ``m + 1 = n + p + 2`` knots ``u_0 .. u_m``; the curve
``C(t) = sum_i N_{i,p}(t) P_i`` runs over the domain ``u_p <= t <= u_{n+1}``. Everything is exact
for rational points and knots.

References
----------
C. de Boor, "On calculating with B-splines", *J. Approximation Theory* 6 (1972), 50–62;
M. G. Cox, "The numerical evaluation of B-splines", *IMA J. Appl. Math.* 10 (1972), 134–149;
L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997 (knot span search and the
basis functions).
"""

from __future__ import annotations

import bisect
from collections.abc import Callable, Iterator, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, fmt_short, normalize, parse_number
from ..core.records import Step
from .curve_limits import (
    DEFAULT_SAMPLES,
    MAX_DEGREE,
    Point,
    Value,
    check_points,
    check_samples,
    norm_value,
)
from .sampling import combine, curve_pixel, sample_ts


class NamedKnots(NamedTuple):
    """A knot vector named by its kind, declared once: its name, its knots for ``n + 1``
    points of degree ``p``, whether it is clamped (``p + 1`` equal knots at each end) and
    what it is, in words."""

    name: str
    vector: Callable[[int, int], tuple[int, ...]]
    clamped: bool
    words: str


def _open(n: int, p: int) -> tuple[int, ...]:
    inner = n - p + 1
    return (0,) * p + tuple(range(inner + 1)) + (inner,) * p


def _uniform(n: int, p: int) -> tuple[int, ...]:
    return tuple(range(n + p + 2))


NAMED_KNOTS = (
    NamedKnots("open", _open, True, "equal end knots, uniform inside"),
    NamedKnots("uniform", _uniform, False, "equally spaced, not clamped"),
)
"""The named knot vectors (an explicit list is the third choice)."""

KNOTS = tuple(k.name for k in NAMED_KNOTS)
"""Their names."""


def named_knots(kind: str) -> NamedKnots | None:
    """The named knot vector ``kind`` (``None``: no such name, or ``"explicit"``).

    >>> named_knots("open").clamped, named_knots("explicit")
    (True, None)
    """
    return next((k for k in NAMED_KNOTS if k.name == kind), None)


def knot_vector(kind: str | Sequence[Number], n: int, p: int) -> tuple[Number, ...]:
    """The knot vector ``u_0 .. u_m`` (``m = n + p + 1``) for ``n + 1`` points of degree ``p``.

    ``open``: clamped uniform, ``p + 1`` equal knots at each end and integer steps inside;
    ``uniform``: ``0, 1, ..., m``; or an explicit sequence, which is validated: ``m = n + p + 1``,
    non-decreasing, no knot repeated more than ``p + 1`` times, a non-empty domain
    ``u_p < u_{n+1}``. Also checks ``1 <= p <= n``.

    >>> knot_vector("open", 4, 2)
    (0, 0, 0, 1, 2, 3, 3, 3)
    >>> knot_vector([0, 0, 1, 1], 3, 3)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: knot vector needs m + 1 = n + p + 2 = 8 values (m = n + p + 1 with n = 3, p = 3), got 4
    """
    if not 1 <= p <= n:
        raise InputError(
            f"degree must satisfy 1 <= p <= n = {n} (n + 1 = {n + 1} control points), got p = {p}",
            "degree",
        )
    if p > MAX_DEGREE:
        raise InputError(f"degree p = {p} is too high (at most {MAX_DEGREE})", "degree")
    m = n + p + 1
    if isinstance(kind, str):
        named = named_knots(kind)
        if named is None:
            raise InputError(
                f"unknown knot vector {kind!r} (open, uniform or a comma list)", "knots"
            )
        return named.vector(n, p)
    knots = tuple(normalize(Fraction(u)) for u in kind)
    if len(knots) != m + 1:
        raise InputError(
            f"knot vector needs m + 1 = n + p + 2 = {m + 1} values "
            f"(m = n + p + 1 with n = {n}, p = {p}), got {len(knots)}",
            "knots",
        )
    for i in range(m):
        if knots[i] > knots[i + 1]:
            raise InputError(
                f"knot vector must be non-decreasing: u_{i} = {fmt_short(knots[i])} > "
                f"u_{i + 1} = {fmt_short(knots[i + 1])}",
                "knots",
            )
    for u in set(knots):
        if knots.count(u) > p + 1:
            raise InputError(
                f"a knot may repeat at most p + 1 = {p + 1} times: {fmt_short(u)} appears "
                f"{knots.count(u)} times",
                "knots",
            )
    if knots[p] == knots[n + 1]:
        raise InputError(
            f"the domain u_p <= t <= u_(n+1) is empty: u_{p} = u_{n + 1} = {fmt_short(knots[p])}",
            "knots",
        )
    return knots


def parse_knots(text: str) -> str | tuple[Fraction, ...]:
    """``open``, ``uniform`` or a comma list ``0,0,0,1,2,2,2`` of exact numbers.

    >>> parse_knots("0, 1/2,1")
    (Fraction(0, 1), Fraction(1, 2), Fraction(1, 1))
    """
    s = text.strip().lower()
    if s in KNOTS:
        return s
    if "," not in s and not s.replace(".", "").replace("/", "").lstrip("+-").isdigit():
        raise InputError(f"unknown knot vector {text!r} (open, uniform or a comma list)", "knots")
    try:
        return tuple(parse_number(u) for u in s.split(","))
    except ValueError as err:
        raise InputError(f"bad knot vector {text!r}: {err}", "knots") from None


def domain(knots: Sequence[Number], p: int, n: int) -> tuple[Number, Number]:
    """The curve's parameter range ``(u_p, u_{n+1})``.

    >>> domain((0, 0, 0, 1, 2, 3, 3, 3), 2, 4)
    (0, 3)
    """
    return knots[p], knots[n + 1]


def last_span(knots: Sequence[Any], n: int) -> int:
    """The last non-empty span ``[u_s, u_{s+1})`` with ``s <= n`` (closed at the domain's end).

    >>> last_span((0, 0, 0, 1, 2, 2, 2), 3)
    3
    """
    s = n
    while knots[s] == knots[s + 1]:
        s -= 1
    return s


def span(knots: Sequence[Number], n: int, t: Value) -> int:
    """The index ``s`` with ``u_s <= t < u_{s+1}``; at ``t = u_{n+1}`` the last non-empty span.

    References
    ----------
    L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997 (algorithm A2.1,
    FindSpan).

    Examples
    --------
    >>> span((0, 0, 0, 1, 2, 2, 2), 3, 1), span((0, 0, 0, 1, 2, 2, 2), 3, 2)
    (3, 3)
    """
    if t >= knots[n + 1]:
        return last_span(knots, n)
    return bisect.bisect_right(knots, t) - 1


def raise_degree(
    knots: Sequence[Any], d: int, t: Any, row: Sequence[Any], window: range | None = None
) -> list[Any]:
    """Cox–de Boor: the degree-``d`` basis row from the degree ``d - 1`` row, with 0/0 = 0.

    Only the entries in ``window`` are computed (the others are 0); all of them by default.

    >>> raise_degree((0, 0, 1, 1), 1, Fraction(1, 4), [0, 1, 0])
    [Fraction(3, 4), Fraction(1, 4)]
    """
    out: list[Any] = [0] * (len(row) - 1)
    for i in range(len(out)) if window is None else window:
        a = knots[i + d] - knots[i]
        b = knots[i + d + 1] - knots[i + 1]
        left = (t - knots[i]) / a * row[i] if a else 0
        right = (knots[i + d + 1] - t) / b * row[i + 1] if b else 0
        out[i] = left + right
    return out


def basis_levels(knots: Sequence[Number], p: int, n: int, t: Value) -> list[list[Value]]:
    """Every row of Cox–de Boor at ``t``: ``N_{i,d}(t)`` for ``d = 0 .. p``.

    Row ``d`` has ``len(knots) - 1 - d`` entries; only ``N_{s-d,d} .. N_{s,d}`` (``s`` the span
    of ``t``) can be non-zero, so only those are computed. ``t`` must lie in the domain
    ``[u_p, u_{n+1}]``.

    References
    ----------
    C. de Boor, "On calculating with B-splines", *J. Approximation Theory* 6 (1972), 50–62;
    L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997 (algorithm A2.2,
    BasisFuns, which computes the same triangle).

    Examples
    --------
    >>> [[str(v) for v in row] for row in basis_levels((0, 0, 0, 1, 1, 1), 2, 2, Fraction(1, 2))]
    [['0', '0', '1', '0', '0'], ['0', '1/2', '1/2', '0'], ['1/4', '1/2', '1/4']]
    """
    s = span(knots, n, t)
    row: list[Any] = [1 if i == s else 0 for i in range(len(knots) - 1)]
    if not isinstance(t, float):
        t = Fraction(t)
    levels = [row]
    for d in range(1, p + 1):
        row = raise_degree(knots, d, t, row, range(max(s - d, 0), min(s, len(row) - 2) + 1))
        levels.append(row)
    return [[norm_value(v) for v in r] for r in levels]


def basis(knots: Sequence[Number], p: int, n: int, t: Value) -> tuple[Value, ...]:
    """``N_{i,p}(t)`` for ``i = 0 .. n`` (Cox–de Boor, 0/0 = 0, right end closed).

    References
    ----------
    C. de Boor, "On calculating with B-splines", *J. Approximation Theory* 6 (1972), 50–62;
    L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997.

    Examples
    --------
    >>> basis((0, 0, 0, 0, 1, 1, 1, 1), 3, 3, 1)
    (0, 0, 0, 1)
    """
    return tuple(basis_levels(knots, p, n, t)[p][: n + 1])


def basis_float(knots: Sequence[Number], p: int, n: int, t: float) -> list[float]:
    """The same basis in float64 at a float ``t`` (dense sampling for the figure): every
    entry of every row computed, the right end closed.

    >>> [basis_float((0, 0, 1, 1), 1, 1, t) for t in (0.0, 0.25, 1.0)]
    [[1.0, 0.0], [0.75, 0.25], [0.0, 1.0]]
    """
    kf = [float(u) for u in knots]
    s = last_span(kf, n) if t >= kf[n + 1] else bisect.bisect_right(kf, t) - 1
    row: list[Any] = [float(s == i) for i in range(len(kf) - 1)]
    for d in range(1, p + 1):
        row = raise_degree(kf, d, t, row)
    return row[: n + 1]


def bspline_samples(knots: Sequence[Number], p: int, n: int) -> int:
    """The default steps of t for a B-spline: the same power of two in every knot span.

    The smallest power of two per non-empty span that gives at least
    :data:`~scanconv.algorithms.curve_limits.DEFAULT_SAMPLES` steps in all, so that with integer
    knots every t is a short decimal.

    >>> bspline_samples((0, 0, 0, 1, 2, 3, 3, 3), 2, 4), bspline_samples((0,) * 4 + (1,) * 4, 3, 3)
    (24, 16)
    """
    spans = sum(1 for i in range(p, n + 1) if knots[i] < knots[i + 1])
    per = 1
    while spans * per < DEFAULT_SAMPLES:
        per *= 2
    return spans * per


def bspline(
    points: Sequence[Point],
    degree: int = 3,
    knots: str | Sequence[Number] = "open",
    samples: int | None = None,
) -> Iterator[Step]:
    """Tabulate the B-spline ``C(t) = sum_i N_{i,p}(t) P_i`` over its domain.

    ``t_k = u_p + k (u_{n+1} - u_p) / samples`` (default: :func:`bspline_samples`);
    ``Step.extra`` is
    ``(t, N_{0,p}(t), ..., N_{n,p}(t), x(t), y(t))``, exact for rational points and knots.

    Notes
    -----
    Cox–de Boor: ``N_{i,0}(t) = 1`` on ``u_i <= t < u_{i+1}``, else 0, and
    ``N_{i,d} = (t - u_i)/(u_{i+d} - u_i) N_{i,d-1} + (u_{i+d+1} - t)/(u_{i+d+1} - u_{i+1})
    N_{i+1,d-1}`` with a term whose denominator is 0 taken as 0. At ``t = u_{n+1}`` (the right
    end of the domain) the last non-empty span is closed, so a clamped curve ends exactly on
    its last control point; the half-open rule alone would give all-zero basis values there.

    References
    ----------
    C. de Boor, "On calculating with B-splines", *J. Approximation Theory* 6 (1972), 50–62;
    L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer, 1997.

    Examples
    --------
    A quadratic with open knots (0, 0, 0, 1, 2, 3, 3, 3), starting on P0 and ending on P4:

    >>> for s in bspline([(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)], 2, "open", 2):
    ...     print(s.k, *(str(v) for v in s.extra), s.pixel)
    0 0 1 0 0 0 0 0 0 (0, 0)
    1 3/2 0 1/8 3/4 1/8 0 23/8 5/2 (3, 3)
    2 3 0 0 0 0 1 5 2 (5, 2)
    """
    pts = check_points(points, 2, "a B-spline")
    n = len(pts) - 1
    u = knot_vector(knots, n, degree)
    t0, t1 = domain(u, degree, n)
    # bspline(4 points, p=3, open knots 0,0,0,0,1,1,1,1, 2) -> t = 1/2: N = 1/8 3/8 3/8 1/8
    #   (a clamped B-spline with no inner knot is the Bezier curve) ; point (2, 1.875)
    steps = bspline_samples(u, degree, n) if samples is None else check_samples(samples)
    for k, t in enumerate(sample_ts(t0, t1, steps)):
        w = basis(u, degree, n, t)
        x, y = combine(w, pts)
        yield Step(k, None, None, curve_pixel(x, y), (t, *w, x, y))
