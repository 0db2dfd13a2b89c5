"""Circle drawing: the midpoint and Bresenham circles, the polynomial (general) method, the
parametric (trigonometric) method and the symmetric DDA, with 8-way symmetry.

Every method computes the points of one octant only, starting at ``(0, r)`` and moving
clockwise (x increasing, y decreasing) towards the 45 degree diagonal, for a circle centred at
the origin; the centre ``(xc, yc)`` is applied in the symmetry step. Coordinates are ``(x, y)``
with y up (see :mod:`scanconv.core.records`).

Pixel order
-----------
``Solution.pixels()`` (and :func:`symmetric_pixels`) yields, for each octant point in plotting
order (the start point ``(0, r)`` first, then each step's point), its 8 images in the notes'
order::

    (xc+x, yc+y), (xc-x, yc+y), (xc+x, yc-y), (xc-x, yc-y),
    (xc+y, yc+x), (xc-y, yc+x), (xc+y, yc-x), (xc-y, yc-x)

and each pixel only the FIRST time it appears. The 8 images of ``(x, y)`` depend only on the
unordered pair ``{x, y}``, so two octant points give either the same 8 images or disjoint
ones. Along every method's octant x never decreases and y never increases, so a pair can only
repeat at the very next point: a rounded point equal to the previous one, or the midpoint
method's last step, which may cross the diagonal from ``(a, a+1)`` to ``(a+1, a)``. Removing
duplicates therefore needs only the previous point and the images of the current one (points
on an axis or on the diagonal have fewer than 8 distinct images), never a set of all pixels.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Iterator
from fractions import Fraction

from ..core.numeric import Number
from ..core.records import Move, Pixel, Step, new_step
from .choices import Rounding
from .circle_choices import CircleMethod
from .conventions import ROUNDINGS, rounder

__all__ = ["ROUNDINGS", "Rounding", "rounder"]

ALIASES: dict[str, str] = {}
"""Other names accepted for a method (none since ``general`` is the notes' own method)."""

FLOAT_METHODS = ("polynomial", "trig", "symmetric-dda")
"""The methods that compute non-integer coordinates and so take a rounding rule."""

SDDA_MAX_RADIUS = 2**14 - 1
"""Largest radius for the symmetric DDA: its exact values gain about 2n bits per step."""

SQRT_PLACES = 10**6
# 64 digits of pi: bounds that decide floor(pi r / 4) exactly for every r <= COORD_LIMIT.
_PI_LO = Fraction("3.141592653589793238462643383279502884197169399375105820974944592")
_PI_HI = _PI_LO + Fraction(1, 10**63)


# --- the octant generators --------------------------------------------------------------------


def midpoint_increment(x: int, y: int, se: bool) -> int:
    """``p_{k+1} - p_k`` of the midpoint circle with the new point ``(x, y)``: ``2x + 1``
    (E) or ``2x + 1 - 2y`` (SE). The one copy of the update, shared by :func:`midpoint`,
    :func:`general` and the marking model (:class:`scanconv.marking.models.MidpointCircle`).

    >>> midpoint_increment(4, 9, True), midpoint_increment(1, 10, False)
    (-9, 3)
    """
    return 2 * x + 1 - 2 * y if se else 2 * x + 1


def bresenham_increment(x: int, y: int, se: bool, xstep: str = "last") -> int:
    """``d_{k+1} - d_k`` of Bresenham's circle from the point ``(x, y)`` the decision was taken
    at: ``4x + 6`` (E) or ``4(x - y) + 10`` (SE); with ``xstep="first"`` (x, and y, stepped
    before d is updated) the same with the new x and y, 4 (E) and 8 (SE) larger. Shared by
    :func:`bresenham` and :class:`scanconv.marking.models.BresenhamCircle`.

    >>> bresenham_increment(0, 10, False), bresenham_increment(0, 10, False, "first")
    (6, 10)
    """
    if xstep == "first":
        x, y = x + 1, y - 1 if se else y
    return 4 * (x - y) + 10 if se else 4 * x + 6


def midpoint(
    r: int, tie: str = "step", p0: str = "1-r", loop: str = "strict", update: str = "new"
) -> Iterator[Step]:
    """The midpoint circle algorithm (Hearn & Baker), first octant from ``(0, r)``.

    Yields one step per unit of x; ``Step.pixel`` is ``(x_{k+1}, y_{k+1})``, ``Step.p`` is
    ``p_k`` (the value the decision was taken on), ``Step.decision`` is ``E`` or ``SE`` and
    ``Step.extra`` is ``(2x_{k+1}, 2y_{k+1})``. The start point ``(0, r)`` is not a step: it is
    plotted before the loop.

    Notes
    -----
    ``p0 = 1 - r`` (the integer form of ``5/4 - r``: every p_k is then an integer and p_k < 0
    decides the same as with 5/4). While ``x < y``: if ``p_k < 0`` the next point is
    ``(x+1, y)`` and ``p_{k+1} = p_k + 2x_{k+1} + 1``; otherwise ``(x+1, y-1)`` and
    ``p_{k+1} = p_k + 2x_{k+1} + 1 - 2y_{k+1}`` (the new x and y). p_k is f(x+1, y-1/2) with
    f = x² + y² - r², so a midpoint exactly on the circle cannot occur. The last step may cross
    the diagonal (``(3, 4)`` then ``(4, 3)`` for r = 5); its 8 images repeat the previous
    point's. Integers only.

    References: Hearn & Baker, *Computer Graphics*, section 3-9 (midpoint circle algorithm).

    Examples
    --------
    Hearn & Baker's example, r = 10:

    >>> for s in midpoint(10):
    ...     print(s.k, s.p, s.decision.value, s.pixel, *s.extra)
    0 -9 E (1, 10) 2 20
    1 -6 E (2, 10) 4 20
    2 -1 E (3, 10) 6 20
    3 6 SE (4, 9) 8 18
    4 -3 E (5, 9) 10 18
    5 8 SE (6, 8) 12 16
    6 5 SE (7, 7) 14 14
    """
    # midpoint(10) -> p: -9 -6 -1 6 -3 8 5 ; points (1,10) (2,10) (3,10) (4,9) (5,9) (6,8) (7,7)
    # midpoint(5)  -> p: -4 -1 4 3 ; points (1,5) (2,5) (3,4) (4,3), the last past the diagonal
    # The knobs: tie "keep" decides E on p <= 0; p0 "5/4-r" starts 1/4 higher (exact);
    # loop "inclusive" runs while x <= y; update "old" writes the same increments with the old
    # x (2x_k + 3, 2x_k - 2y_k + 5), so it changes the working only, never a value.
    x, y, k = 0, r, 0
    p: Number = 1 - r if p0 == "1-r" else Fraction(5, 4) - r
    inclusive, keep = loop == "inclusive", tie == "keep"
    while x < y or (inclusive and x == y):
        x += 1
        if p < 0 or (keep and p == 0):
            q, move = p + midpoint_increment(x, y, False), Move.E
        else:
            y -= 1
            q, move = p + midpoint_increment(x, y, True), Move.SE
        yield new_step(Step, (k, p, move, (x, y), (2 * x, 2 * y)))
        p, k = q, k + 1


def bresenham(r: int, tie: str = "step", xstep: str = "last") -> Iterator[Step]:
    """Bresenham's circle algorithm with ``d0 = 3 - 2r``, first octant from ``(0, r)``.

    Yields one step per plotted point; ``Step.pixel`` is the point ``(x_k, y_k)`` plotted at
    this step, ``Step.p`` is ``d_k`` and ``Step.decision`` the move it chooses for the next
    point (``E`` or ``SE``).

    Notes
    -----
    ``d0 = 3 - 2r``. Plot ``(x, y)``; if ``d < 0`` then ``d += 4x + 6``, else
    ``d += 4(x - y) + 10`` and ``y -= 1`` (both updates with the old x and y); then ``x += 1``;
    continue while ``x <= y``. d_k = f(x+1, y) + f(x+1, y-1) = 2 f(x+1, y-1/2) + 1/2 with
    f = x² + y² - r², which is ``2 p_k + 1`` for the midpoint circle's p_k: the two make the
    same decisions and plot the same points (the tests check it for every radius up to 200 and
    random ones beyond).

    References: Bresenham, CACM 20(2), 1977; Foley, van Dam et al., *Computer Graphics*,
    section 3.3.

    Examples
    --------
    >>> for s in bresenham(5):
    ...     print(s.k, s.p, s.decision.value, s.pixel)
    0 -7 E (0, 5)
    1 -1 E (1, 5)
    2 9 SE (2, 5)
    3 7 SE (3, 4)
    """
    # bresenham(5) -> d: -7 -1 9 7 ; points (0,5) (1,5) (2,5) (3,4)
    if xstep == "first":
        yield from _bresenham_x_first(r, tie)
        return
    x, y, d, k = 0, r, 3 - 2 * r, 0
    t = 1 if tie == "keep" else 0  # tie "keep": d <= 0 chooses E
    while x <= y:
        if d < t:
            e, move, ny = d + bresenham_increment(x, y, False), Move.E, y
        else:
            e, move, ny = d + bresenham_increment(x, y, True), Move.SE, y - 1
        yield new_step(Step, (k, d, move, (x, y), ()))
        x, y, d, k = x + 1, ny, e, k + 1


def _bresenham_x_first(r: int, tie: str) -> Iterator[Step]:
    """The widely copied form of Bresenham's circle: ``x += 1`` (and ``y -= 1``) first, then
    ``d += 4x + 6`` or ``d += 4(x - y) + 10`` with the *new* x and y. It is not the same
    algorithm: the increments are 4 larger, so the decisions and the points can differ.

    >>> [s.p for s in _bresenham_x_first(10, "step")][:4]
    [-17, -7, 7, -7]
    """
    x, y, d, k = 0, r, 3 - 2 * r, 0
    t = 1 if tie == "keep" else 0
    while x <= y:
        if d < t:
            nx, ny, move = x + 1, y, Move.E
            e = d + bresenham_increment(x, y, False, "first")
        else:
            nx, ny, move = x + 1, y - 1, Move.SE
            e = d + bresenham_increment(x, y, True, "first")
        yield new_step(Step, (k, d, move, (x, y), ()))
        x, y, d, k = nx, ny, e, k + 1


def general(r: int, tie: str = "step", loop: str = "strict") -> Iterator[Step]:
    """The notes' general method, exactly as its algorithm box states it.

    Each row is the current point ``(x_k, y_k)`` (row 0 is ``(0, r)``) with ``Step.p`` the p
    there, ``Step.decision`` E or SE and ``Step.extra`` ``(x_k, y_k, next point)``; the last
    row is the point the loop stops at, with its p and no decision (``extra[2]`` is ``None``).

    Notes
    -----
    ``x = 0, y = r, p = 0``; while ``x < y``: if ``p < 0``: ``x = x + 1, p = p + 2x + 1``
    (E); else ``x = x + 1, y = y - 1, p = p + 2x - 2y + 1`` (SE), with the new x and y. p is
    x² + y² - r² at (0, r) only: the updates use the new x, so afterwards p is not the circle
    function of the point, and deciding at the point rather than at the midpoint pulls the
    octant inside the circle (see ``docs/errata.md``, E8). ``tie="keep"`` decides E on
    ``p <= 0``; ``loop="inclusive"`` runs while ``x <= y``.

    Examples
    --------
    >>> for s in general(5):
    ...     print(s.k, s.pixel, s.p, s.decision and s.decision.value, s.extra[2])
    0 (0, 5) 0 SE (1, 4)
    1 (1, 4) -5 E (2, 4)
    2 (2, 4) 0 SE (3, 3)
    3 (3, 3) 1 None None
    """
    x, y, p, k = 0, r, 0, 0
    inclusive, keep = loop == "inclusive", tie == "keep"
    while x < y or (inclusive and x == y):
        if p < 0 or (keep and p == 0):
            nx, ny, move = x + 1, y, Move.E
        else:
            nx, ny, move = x + 1, y - 1, Move.SE
        q = p + midpoint_increment(nx, ny, move is Move.SE)
        yield new_step(Step, (k, p, move, (x, y), (x, y, (nx, ny))))
        x, y, p, k = nx, ny, q, k + 1
    yield new_step(Step, (k, p, None, (x, y), (x, y, None)))


def polynomial(r: int, rounding: str = "half-up") -> Iterator[Step]:
    """The polynomial (general) method: ``y = sqrt(r² - x²)`` for ``x = 0, 1, ...``.

    ``Step.k`` is x, ``Step.extra[0]`` is y truncated to 6 decimals (an exact
    :class:`~fractions.Fraction`), ``Step.extra[1]`` the rounded y and ``Step.pixel`` the point
    ``(x, round(y))``.

    Notes
    -----
    x runs over 0, 1, ... while ``x <= y`` for the plotted point, i.e. ``x <= round(y)``: the
    octant ends on or next to the diagonal, so the point and its mirror image ``(y, x)`` touch.
    Testing the exact y instead (``2x² <= r²``) leaves a one-pixel gap at 45° for about one
    radius in four (r = 7 stops at (4, 6), whose image (6, 4) is two pixels away; with the
    rule here it plots (5, 5) too). With half-up rounding the pixels are then exactly the
    midpoint circle's (each column's nearest pixel). y is irrational unless
    ``r² - x²`` is a square, so it is computed with integer square roots
    (``isqrt((r² - x²)·10¹²) / 10⁶``): truncating to 6 decimals keeps every half-integer and
    every 4th-decimal threshold on its grid, so ``floor(y + 1/2)``, ``trunc(y)`` and the
    3-decimal display are all exactly those of the true square root (a float would round
    wrongly for radii near 10⁹). ``rounding`` is ``"half-up"`` (default) or ``"trunc"``.

    Examples
    --------
    >>> from scanconv.core.numeric import fmt
    >>> for s in polynomial(5):
    ...     print(s.k, fmt(s.extra[0], 3), s.extra[1], s.pixel)
    0 5.000 5 (0, 5)
    1 4.899 5 (1, 5)
    2 4.583 5 (2, 5)
    3 4.000 4 (3, 4)
    """
    # polynomial(5) -> y: 5 4.899 4.583 4 ; rounded: 5 5 5 4 (x = 4 stops: round(3) < 4)
    # polynomial(7) -> rounded y: 7 7 7 6 6 5 ; (5, 5) closes the octant on the diagonal
    rnd = rounder(rounding)
    r2 = r * r
    for x in range(r + 1):
        y = sqrt6(r2 - x * x)
        ry = rnd(y)
        if x > ry:
            return
        yield new_step(Step, (x, None, None, (x, ry), (y, ry)))


def trig(r: int, rounding: str = "half-up") -> Iterator[Step]:
    """The parametric (trigonometric) method: ``x = r cos θ``, ``y = r sin θ``.

    ``Step.extra`` is ``(θ in degrees, θ in radians, x, y)``, all four Python floats, and
    ``Step.pixel`` the rounded point.

    Notes
    -----
    θ runs from 90° down towards 45° in steps of ``Δθ = 1/r`` radians (about one pixel of arc
    per step): ``θ_k = π/2 - k/r`` for ``k = 0, 1, ...`` while the plotted point has
    ``x <= y``, and for at most one θ below 45°. That is every θ_k >= 45°
    (``k <= floor(π r / 4)``, decided exactly with rational bounds on π) and at most one more,
    whose rounded point still lies on the diagonal: the octant then ends next to its mirror image. Stopping at θ >= 45° instead can
    leave a gap at 45° (r = 10 would end at (6, 8), two pixels from its image (8, 6); the next
    row, θ = 44.2°, plots (7, 7)). cos and sin are transcendental, so x and y are computed as
    floats (the only floats in scanconv's tables; their error, about 10⁻¹⁶·r, is far below the
    3 decimals shown). Rounding goes through :func:`~scanconv.core.numeric.round_half_up` (or
    :func:`~scanconv.core.numeric.round_trunc`) applied to the float's exact value, so a value like
    0.49999999999999994 is not pushed over the half by a floating-point ``+ 0.5``. The notes'
    Topic 11 gives the parametric circle ``x = xc + r cos t, y = yc + r sin t``.

    Examples
    --------
    >>> from scanconv.core.numeric import fmt
    >>> for s in trig(5):
    ...     print(s.k, *(fmt(v, 3) for v in s.extra), s.pixel)
    0 90.000 1.571 0.000 5.000 (0, 5)
    1 78.541 1.371 0.993 4.900 (1, 5)
    2 67.082 1.171 1.947 4.605 (2, 5)
    3 55.623 0.971 2.823 4.127 (3, 4)
    >>> [s.pixel for s in trig(10)][-3:]   # k = 8 is θ = 44.2°, still plotted as (7, 7)
    [(6, 8), (6, 8), (7, 7)]
    """
    # trig(5) -> θ: 90 78.541 67.082 55.623 deg ; (x, y): (0, 5) (0.993, 4.900) (1.947, 4.605) ...
    rnd = rounder(rounding)
    if r == 0:
        yield new_step(Step, (0, None, None, (0, 0), (90.0, math.pi / 2, 0.0, 0.0)))
        return
    for k in range(trig_steps(r) + 2):  # never more than one step below 45°
        step = _trig_step(r, k, rnd)
        if step.pixel[0] > step.pixel[1]:
            return
        yield step


def _trig_step(r: int, k: int, rnd: Callable[[Number], int]) -> Step:
    theta = math.pi / 2 - k / r
    x, y = r * math.cos(theta), r * math.sin(theta)
    point = (rnd(Fraction(x)), rnd(Fraction(y)))
    return new_step(Step, (k, None, None, point, (90 - k * 180 / (math.pi * r), theta, x, y)))


def trig_last(r: int, rounding: str = "half-up") -> int:
    """The last k of :func:`trig`, without running it: ``floor(π r / 4)`` or one more.

    >>> trig_last(5), trig_last(10)
    (3, 8)
    """
    k = trig_steps(r)
    p = _trig_step(r, k + 1, rounder(rounding)).pixel
    return k + 1 if p[0] <= p[1] else k


def trig_steps(r: int) -> int:
    """The last k of the parametric method: ``floor(π r / 4)``, exactly.

    >>> trig_steps(5), trig_steps(10), trig_steps(10**9)
    (3, 7, 785398163)
    """
    lo, hi = math.floor(r * _PI_LO / 4), math.floor(r * _PI_HI / 4)
    if lo != hi:  # pragma: no cover - would need pi r / 4 within 10^-54 of an integer
        raise ValueError(f"cannot decide floor(pi r / 4) for r = {r}")
    return lo


def symmetric_dda(r: int, rounding: str = "half-up") -> Iterator[Step]:
    """The symmetric DDA with ``ε = 2^-n`` (``2^(n-1) <= r < 2^n``), exact fractions.

    ``Step.extra`` is ``(x_k, y_k)``, exact; ``Step.pixel`` is the rounded point.

    Notes
    -----
    From ``(x0, y0) = (0, r)``: ``x_{k+1} = x_k + ε y_k``, ``y_{k+1} = y_k - ε x_{k+1}`` (the new
    x, which makes each step a map of determinant 1: the points stay on the ellipse
    ``x² + y² + εxy = r²``, at most rε/4 < 1/4 inside the circle, instead of spiralling
    outward); rows while the plotted point has ``x <= y`` (``round(x_k) <= round(y_k)``): the
    octant then ends on or next to the diagonal, next to its mirror image. Testing the exact
    ``x_k <= y_k`` instead can stop one row early and leave a gap at 45° (r = 30 would end at
    (20, 22), two pixels from its image (22, 20); the next row plots (21, 21)). ε is a power of 2, so every value
    is a dyadic fraction, computed exactly; a value gains about 2n bits per step, which is why
    r is limited to :data:`SDDA_MAX_RADIUS`. ``rounding`` is ``"half-up"`` (default) or
    ``"trunc"``.

    Examples
    --------
    >>> from scanconv.core.numeric import fmt
    >>> for s in symmetric_dda(5):
    ...     print(s.k, fmt(s.extra[0], 3), fmt(s.extra[1], 3), s.pixel)
    0 0.000 5.000 (0, 5)
    1 0.625 4.922 (1, 5)
    2 1.240 4.767 (1, 5)
    3 1.836 4.537 (2, 5)
    4 2.403 4.237 (2, 4)
    5 2.933 3.870 (3, 4)
    6 3.417 3.443 (3, 3)
    """
    # symmetric_dda(5), ε = 1/8 -> x: 0 0.625 1.240 1.836 2.403 2.933 3.417 ; y: 5 4.922 ... 3.443
    rnd = rounder(rounding)
    if r == 0:
        yield new_step(Step, (0, None, None, (0, 0), (0, 0)))
        return
    n = r.bit_length()
    # x = xs / 2^s and y = ys / 2^s: shifts instead of Fraction arithmetic, whose gcds would
    # make this quadratically slower; the values yielded are the same exact fractions.
    xs, ys, s, k = 0, r, 0, 0
    while k <= 1 << n:  # a guard only: about π/4 · 2^n steps reach the diagonal
        x, y = _dyadic(xs, s), _dyadic(ys, s)
        point = (rnd(x), rnd(y))
        if point[0] > point[1]:
            return
        yield new_step(Step, (k, None, None, point, (x, y)))
        xs = (xs << n) + ys  # x + ε y, at scale s + n
        ys = (ys << (2 * n)) - xs  # y - ε x_new, at scale s + 2n
        xs <<= n
        s += 2 * n
        k += 1


# --- exact helpers ----------------------------------------------------------------------------


def sqrt6(n: int) -> Fraction:
    """``sqrt(n)`` truncated to 6 decimals, exactly: ``isqrt(n·10¹²) / 10⁶``.

    >>> sqrt6(24), sqrt6(16)
    (Fraction(4898979, 1000000), Fraction(4, 1))
    """
    return Fraction(math.isqrt(n * SQRT_PLACES * SQRT_PLACES), SQRT_PLACES)


def coprime_constructor(cls: type[Fraction] = Fraction) -> Callable[[int, int], Fraction]:
    """The fastest way to build a ``cls`` from a numerator and denominator already in lowest
    terms (and a positive denominator), skipping the gcd.

    Uses a private constructor where the running Python has one (3.12+:
    ``_from_coprime_ints``; 3.10 and 3.11: ``_normalize=False``), else the public one, which
    gives the same value at the cost of a gcd. Chosen once, when this module is imported.

    >>> coprime_constructor()(3, 4)
    Fraction(3, 4)
    """
    fast = getattr(cls, "_from_coprime_ints", None)
    if fast is not None:
        return fast  # type: ignore[no-any-return]
    try:
        cls(1, 2, _normalize=False)  # type: ignore[call-overload]
    except TypeError:
        return cls

    def unnormalized(num: int, den: int) -> Fraction:
        return cls(num, den, _normalize=False)  # type: ignore[call-overload, no-any-return]

    return unnormalized


_coprime = coprime_constructor()


def _dyadic(num: int, shift: int) -> Number:
    """``num / 2**shift`` in lowest terms, without a gcd (the denominator is a power of 2).

    >>> _dyadic(12, 4), _dyadic(8, 2), _dyadic(0, 9)
    (Fraction(3, 4), 2, 0)
    """
    if num == 0:
        return 0
    t = min((num & -num).bit_length() - 1, shift)
    num, shift = num >> t, shift - t
    return num if shift == 0 else _coprime(num, 1 << shift)


# --- symmetry ---------------------------------------------------------------------------------


def images(x: int, y: int, xc: int = 0, yc: int = 0) -> tuple[Pixel, ...]:
    """The 8 symmetric images of ``(x, y)`` about ``(xc, yc)``, in the notes' order.

    >>> images(1, 5, 10, 10)
    ((11, 15), (9, 15), (11, 5), (9, 5), (15, 11), (5, 11), (15, 9), (5, 9))
    """
    return (
        (xc + x, yc + y),
        (xc - x, yc + y),
        (xc + x, yc - y),
        (xc - x, yc - y),
        (xc + y, yc + x),
        (xc - y, yc + x),
        (xc + y, yc - x),
        (xc - y, yc - x),
    )


def symmetric_pixels(points: Iterable[Pixel], xc: int = 0, yc: int = 0) -> Iterator[Pixel]:
    """Every pixel of the 8-way images of an octant walk, once each, in the module's order.

    ``points`` must be a walk with x never decreasing and y never increasing (every method's
    octant is), so a repeated image set can only come from the point just before.

    >>> list(symmetric_pixels([(0, 2), (1, 2), (2, 1)]))
    [(0, 2), (0, -2), (2, 0), (-2, 0), (1, 2), (-1, 2), (1, -2), (-1, -2), (2, 1), (-2, 1), (2, -1), (-2, -1)]
    """
    last: tuple[int, int] | None = None
    for x, y in points:
        pair = (x, y) if x <= y else (y, x)
        if pair == last:
            continue
        last = pair
        if x == 0 or y == 0 or x == y:
            seen: list[Pixel] = []
            for p in images(x, y, xc, yc):
                if p not in seen:
                    seen.append(p)
                    yield p
        else:
            yield from images(x, y, xc, yc)


METHODS = tuple(m.value for m in CircleMethod if m.value not in ALIASES)
"""The circle methods' names: midpoint, bresenham, polynomial, general, trig, symmetric-dda."""
