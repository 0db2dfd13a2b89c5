"""Line drawing: the basic (direct) method, the simple and the symmetric DDA and Bresenham's
algorithm.

Each algorithm is a generator of :class:`~scanconv.core.records.Step` records, valid in all eight
octants; :func:`line_solution` wraps one of them with the given and derived values an exam
answer writes above the table. Coordinates are ``(x, y)`` with y up (see
:mod:`scanconv.core.records`).
"""

import math
from collections.abc import Iterator
from fractions import Fraction
from typing import NamedTuple, Protocol

from ..core.numeric import (
    Number,
    normalize,
    round_half_up,
)
from ..core.records import Move, Step, new_step
from .choices import LineAlgorithm
from .conventions import rounder


def bresenham_terms(dmaj: int, dmin: int, tie: str = "step") -> tuple[int, int, int, int]:
    """Bresenham's arithmetic, once for the generators here and the marking model
    (:class:`scanconv.marking.models.BresenhamLine`): ``(p0, inc_keep, inc_step, t)`` with
    ``p0 = 2 Δminor - Δmajor``, ``p_{k+1} = p_k + inc_keep`` when ``p_k < t`` (the minor
    coordinate kept) and ``p_k + inc_step`` otherwise. ``t`` is 0, or 1 with ``tie="keep"``
    (``p <= 0`` is ``p < 1``: every p is an integer).

    >>> bresenham_terms(8, 4), bresenham_terms(8, 4, "keep")
    ((0, 8, -8, 0), (0, 8, -8, 1))
    """
    return 2 * dmin - dmaj, 2 * dmin, 2 * dmin - 2 * dmaj, 1 if tie == "keep" else 0


def bresenham(
    x1: int, y1: int, x2: int, y2: int, tie: str = "step", start: str = "swap"
) -> Iterator[Step]:
    """Bresenham's line algorithm, textbook form, all octants.

    Yields one step per unit of the major axis; ``Step.pixel`` is ``(x_{k+1}, y_{k+1})`` and
    ``Step.extra`` is ``(p_{k+1},)``. The start pixel is not a step: it is plotted before the
    loop (see :func:`line_solution`, whose ``pixels()`` include it).

    Notes
    -----
    Hearn & Baker's form, generalised by symmetry. The major axis is x when |Δy| <= |Δx|
    (so 45 degree lines step in x), otherwise y. The walk starts at the end point with the
    smaller major coordinate; the end points are swapped if needed, as the notes say. With
    Δmajor and Δminor the absolute differences:

    * ``p0 = 2 Δminor - Δmajor``
    * ``p_k < 0``: keep the minor coordinate, ``p_{k+1} = p_k + 2 Δminor``
    * ``p_k >= 0``: step the minor coordinate toward the far end point,
      ``p_{k+1} = p_k + 2 Δminor - 2 Δmajor``

    A tie (``p_k = 0``, the ideal line exactly half-way between two pixels) steps the minor
    axis with ``tie="step"`` (the notes' and Hearn & Baker's ``if p < 0``) and keeps it with
    ``tie="keep"`` (the widely copied ``if p <= 0``). Integers only.

    ``start="given"`` walks from P1 as given instead, the major coordinate decreasing when P2
    has the smaller one (Wikipedia's all-octant ``plotLine``): the same p values, so the same
    pixels except where a tie is met walking the other way. See :func:`bresenham_from_p1`.

    References: Bresenham, IBM Systems Journal 4(1), 1965; Hearn & Baker, *Computer Graphics*,
    section 3-5.

    Examples
    --------
    The notes' example (their printed table is wrong; see ``docs/errata.md``):

    >>> for s in bresenham(2, 2, 10, 6):
    ...     print(s.k, s.p, s.decision.value, s.pixel, s.extra[0])
    0 0 NE (3, 3) -8
    1 -8 E (4, 3) 0
    2 0 NE (5, 4) -8
    3 -8 E (6, 4) 0
    4 0 NE (7, 5) -8
    5 -8 E (8, 5) 0
    6 0 NE (9, 6) -8
    7 -8 E (10, 6) 0
    """
    # bresenham(2, 2, 10, 6) -> p: 0 -8 0 -8 0 -8 0 -8 ; pixels (3,3) (4,3) (5,4) ... (10,6)
    # bresenham(2, 2, 5, 10) -> steep: p: -2 4 -6 0 -10 -4 2 -8 ; moves N/NE
    if start == "given" and (y2 - y1 if abs(y2 - y1) > abs(x2 - x1) else x2 - x1) < 0:
        yield from bresenham_from_p1(x1, y1, x2, y2, tie)
        return
    x1, y1, x2, y2, steep, dmaj, dmin, s, stay, move = orient(x1, y1, x2, y2)
    p, inc_keep, inc_step, t = bresenham_terms(dmaj, dmin, tie)
    x, y = x1, y1
    # The hot path of every long table (benchmarks/bench.py measures it): one loop per major
    # axis so no step tests `steep`, and the record constructor bound to local names.
    make, cls = new_step, Step
    # Each record holds p_k, then p becomes p_{k+1} inside the tuple (the `:=`).
    if steep:
        for k in range(dmaj):
            y += 1
            if p < t:
                yield make(cls, (k, p, stay, (x, y), (p := p + inc_keep,)))
            else:
                x += s
                yield make(cls, (k, p, move, (x, y), (p := p + inc_step,)))
        return
    for k in range(dmaj):
        x += 1
        if p < t:
            yield make(cls, (k, p, stay, (x, y), (p := p + inc_keep,)))
        else:
            y += s
            yield make(cls, (k, p, move, (x, y), (p := p + inc_step,)))


def bresenham_from_p1(x1: int, y1: int, x2: int, y2: int, tie: str = "step") -> Iterator[Step]:
    """Bresenham's line walked from P1 when the major coordinate decreases to P2 (no swap).

    The decision is the same as :func:`bresenham`'s (``p0 = 2 Δminor - Δmajor``, the same two
    increments); the major coordinate steps by -1 and the minor one toward P2. A tie now keeps
    or steps the minor coordinate as seen from P1, so the pixels can differ from the swapped
    walk's exactly where p = 0.

    >>> [(s.p, s.decision.value, s.pixel) for s in bresenham_from_p1(4, 2, 0, 0)]
    [(0, 'SW', (3, 1)), (-4, 'W', (2, 1)), (0, 'SW', (1, 0)), (-4, 'W', (0, 0))]
    >>> [s.pixel for s in bresenham(4, 2, 0, 0)]
    [(1, 1), (2, 1), (3, 2), (4, 2)]
    """
    steep, dmaj, dmin, s, stay, move = orient_from_p1(x1, y1, x2, y2)
    p, inc_keep, inc_step, t = bresenham_terms(dmaj, dmin, tie)
    x, y = x1, y1
    for k in range(dmaj):
        if steep:
            y -= 1
        else:
            x -= 1
        if p < t:
            yield Step(k, p, stay, (x, y), (p := p + inc_keep,))
        else:
            if steep:
                x += s
            else:
                y += s
            yield Step(k, p, move, (x, y), (p := p + inc_step,))


class Walk(NamedTuple):
    """A walk's major axis, its two differences and its two moves (:func:`orient_from_p1`)."""

    steep: bool
    dmaj: int
    dmin: int
    sign: int
    stay: Move
    move: Move


class Octant(NamedTuple):
    """A line's end points ordered so the major coordinate increases, and its moves
    (:func:`orient`)."""

    x1: int
    y1: int
    x2: int
    y2: int
    steep: bool
    dmaj: int
    dmin: int
    sign: int
    stay: Move
    move: Move


def orient_from_p1(x1: int, y1: int, x2: int, y2: int) -> Walk:
    """:func:`orient` for a walk from P1 with the major coordinate decreasing (no swap).

    Returns ``(steep, dmaj, dmin, s, stay, move)``: ``s`` the sign of the minor step toward P2,
    ``stay`` the move when p_k < 0, ``move`` the move when p_k >= 0.

    >>> orient_from_p1(4, 2, 0, 0)[3:]
    (-1, <Move.W: 'W'>, <Move.SW: 'SW'>)
    """
    dx, dy = x2 - x1, y2 - y1
    steep = abs(dy) > abs(dx)
    dmaj, dmin = (abs(dy), abs(dx)) if steep else (abs(dx), abs(dy))
    if steep:
        s = 1 if dx >= 0 else -1
        return Walk(True, dmaj, dmin, s, Move.from_delta(0, -1), Move.from_delta(s, -1))
    s = 1 if dy >= 0 else -1
    return Walk(False, dmaj, dmin, s, Move.from_delta(-1, 0), Move.from_delta(-1, s))


def bresenham_notes(
    x1: int, y1: int, x2: int, y2: int, tie: str = "step", start: str = "swap"
) -> Iterator[Step]:
    """:func:`bresenham` in the notes' row shape: row k plots ``(x_k, y_k)`` (row 0 the start
    pixel) and shows the ``p_k`` and decision taken there and ``p_{k+1}``; a last row plots the
    end pixel, with ``p`` and no decision (the loop has ended).

    >>> for s in bresenham_notes(2, 2, 5, 3):
    ...     print(s.k, s.p, s.decision and s.decision.value, s.pixel, s.extra[0])
    0 -1 E (2, 2) 1
    1 1 NE (3, 2) -3
    2 -3 E (4, 3) -1
    3 -1 None (5, 3) None
    """
    o = orient(x1, y1, x2, y2)
    pixel, k, p = (o.x1, o.y1), 0, bresenham_terms(o.dmaj, o.dmin)[0]
    if start == "given":
        pixel = (x1, y1)
    for s in bresenham(x1, y1, x2, y2, tie, start):
        yield Step(s.k, s.p, s.decision, pixel, s.extra)
        pixel, k, p = s.pixel, s.k + 1, s.extra[0]
    yield Step(k, p, None, pixel, (None,))


def orient(x1: int, y1: int, x2: int, y2: int) -> Octant:
    """Swap the end points so the major coordinate increases; name the two moves.

    Returns ``(x1, y1, x2, y2, steep, dmaj, dmin, s, stay, move)`` where ``s`` is the sign of
    the minor step, ``stay`` the move when p_k < 0 and ``move`` the move when p_k >= 0.

    >>> orient(10, 6, 2, 2)[:4], orient(0, 0, -3, 7)[-2:]
    ((2, 2, 10, 6), (<Move.N: 'N'>, <Move.NW: 'NW'>))
    """
    dx, dy = x2 - x1, y2 - y1
    steep = abs(dy) > abs(dx)
    if (dy if steep else dx) < 0:
        x1, y1, x2, y2, dx, dy = x2, y2, x1, y1, -dx, -dy
    if steep:
        s = 1 if dx >= 0 else -1
        return Octant(x1, y1, x2, y2, True, dy, abs(dx), s, Move.N, Move.from_delta(s, 1))
    s = 1 if dy >= 0 else -1
    return Octant(x1, y1, x2, y2, False, dx, abs(dy), s, Move.E, Move.from_delta(1, s))


def dda(
    x1: Number, y1: Number, x2: Number, y2: Number, rounding: str = "half-up"
) -> Iterator[Step]:
    """The simple DDA, from P1 to P2 as given, with exact increments.

    ``Step.extra`` is ``(x_k, y_k, round_half_up(x_k), round_half_up(y_k))``; there are
    ``steps + 1`` rows, the first plotting P1 and the last P2.

    Notes
    -----
    ``steps = max(|Δx|, |Δy|)`` (rounded up to an integer if the end points are not integers),
    ``x_inc = Δx / steps``, ``y_inc = Δy / steps``; ``x_{k+1} = x_k + x_inc`` and
    ``y_{k+1} = y_k + y_inc`` as exact fractions, so no rounding error accumulates. Pixels are
    ``floor(v + 1/2)`` (round half up) of each coordinate. P1 = P2 gives one row.

    Examples
    --------
    >>> from scanconv.core.numeric import fmt
    >>> for s in dda(2, 2, 10, 6):
    ...     print(s.k, *(fmt(v, 3) for v in s.extra[:2]), s.pixel)
    0 2.000 2.000 (2, 2)
    1 3.000 2.500 (3, 3)
    2 4.000 3.000 (4, 3)
    3 5.000 3.500 (5, 4)
    4 6.000 4.000 (6, 4)
    5 7.000 4.500 (7, 5)
    6 8.000 5.000 (8, 5)
    7 9.000 5.500 (9, 6)
    8 10.000 6.000 (10, 6)
    """
    # dda(2, 2, 10, 6) -> y: 2 2.5 3 3.5 4 4.5 5 5.5 6 ; rounded: 2 3 3 4 4 5 5 6 6
    return walk_increments(x1, y1, x2, y2, dda_steps(x1, y1, x2, y2), rounding)


def walk_increments(
    x1: Number, y1: Number, x2: Number, y2: Number, steps: int, rounding: str = "half-up"
) -> Iterator[Step]:
    """The DDA family's walk: ``steps + 1`` rows from P1 to P2, both coordinates stepped by
    :func:`increments` (exact), each rounded by ``rounding``; ``Step.extra`` is
    ``(x_k, y_k, round(x_k), round(y_k))``.

    >>> [s.pixel for s in walk_increments(0, 0, 2, 1, 4)]
    [(0, 0), (1, 0), (1, 1), (2, 1), (2, 1)]
    """
    rnd = rounder(rounding)
    xi, yi = increments(x1, y1, x2, y2, steps)
    for k in range(steps + 1):
        x = normalize(x1 + k * xi)  # exact: k * inc, not repeated addition
        y = normalize(y1 + k * yi)
        px, py = rnd(x), rnd(y)
        yield Step(k, None, None, (px, py), (x, y, px, py))


def symmetric_dda(
    x1: Number, y1: Number, x2: Number, y2: Number, rounding: str = "half-up"
) -> Iterator[Step]:
    """The symmetric DDA: both coordinates stepped by ``ε Δx`` and ``ε Δy`` with ``ε = 2^-n``,
    ``2^(n-1) <= max(|Δx|, |Δy|) < 2^n``, from P1 to P2 as given, exact; ``Step.extra`` is
    ``(x_k, y_k, round(x_k), round(y_k))``, ``2^n + 1`` rows.

    Notes
    -----
    Rogers, *Procedural Elements for Computer Graphics*, the symmetric DDA: ε a power of 2, so
    that a machine steps by a shift, each increment at most 1 (half a pixel or more along the
    major axis, so that pixels repeat, about half of them). With exact fractions no error
    accumulates; pixels are rounded half up (``floor(v + 1/2)``). A line shorter than a pixel
    takes one step, a point none (:func:`symmetric_dda_steps`).

    Examples
    --------
    Hand-worked: (0, 0) to (5, 2), n = 3 (4 <= 5 < 8), ε = 1/8:

    >>> from scanconv.core.numeric import fmt
    >>> for s in symmetric_dda(0, 0, 5, 2):
    ...     print(s.k, fmt(s.extra[0], 3), fmt(s.extra[1], 3), s.pixel)
    0 0.000 0.000 (0, 0)
    1 0.625 0.250 (1, 0)
    2 1.250 0.500 (1, 1)
    3 1.875 0.750 (2, 1)
    4 2.500 1.000 (3, 1)
    5 3.125 1.250 (3, 1)
    6 3.750 1.500 (4, 2)
    7 4.375 1.750 (4, 2)
    8 5.000 2.000 (5, 2)
    """
    return walk_increments(x1, y1, x2, y2, symmetric_dda_steps(x1, y1, x2, y2), rounding)


def symmetric_dda_steps(x1: Number, y1: Number, x2: Number, y2: Number) -> int:
    """``2^n`` with ``2^(n-1) <= max(|Δx|, |Δy|) < 2^n``; 1 for a line shorter than a pixel
    (n = 0), 0 for a point.

    >>> symmetric_dda_steps(0, 0, 5, 2), symmetric_dda_steps(2, 2, 10, 6), symmetric_dda_steps(0, 0, "1/2", 0)
    (8, 16, 1)
    """
    longest = max(abs_value(Fraction(x2) - Fraction(x1)), abs_value(Fraction(y2) - Fraction(y1)))
    return 0 if longest == 0 else 1 << math.floor(longest).bit_length()


class Asked(Protocol):
    """A line question as a row estimate reads it (:class:`scanconv.answers.asked.LineQuestion`)."""

    @property
    def points(self) -> tuple[Number, Number, Number, Number]: ...


def symmetric_dda_rows(q: Asked) -> int:
    """The symmetric DDA's rows (its record's estimate, exact): ``2^n + 1``.

    >>> from scanconv.answers.asked import LineQuestion
    >>> symmetric_dda_rows(LineQuestion("symmetric-dda", 0, 0, 1500000, 1))
    2097153
    """
    return symmetric_dda_steps(*q.points) + 1


def abs_value(v: Number) -> Fraction:
    """``|v|`` as a Fraction (keeps the type checker exact about ``int | Fraction``)."""
    return abs(Fraction(v))


def dda_steps(x1: Number, y1: Number, x2: Number, y2: Number) -> int:
    """``max(|Δx|, |Δy|)``, rounded up for non-integer end points.

    >>> dda_steps(2, 2, 5, 10)
    8
    """
    return math.ceil(max(abs_value(x2 - x1), abs_value(y2 - y1)))


def dda_increments(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[Number, Number]:
    """``(Δx / steps, Δy / steps)``; ``(0, 0)`` for a single point.

    >>> dda_increments(2, 2, 5, 10)
    (Fraction(3, 8), 1)
    """
    return increments(x1, y1, x2, y2, dda_steps(x1, y1, x2, y2))


def increments(x1: Number, y1: Number, x2: Number, y2: Number, steps: int) -> tuple[Number, Number]:
    """``(Δx / steps, Δy / steps)``, the increments of any DDA-family walk; ``(0, 0)`` for a
    single point.

    >>> increments(2, 2, 10, 6, 16)
    (Fraction(1, 2), Fraction(1, 4))
    """
    if steps == 0:
        return 0, 0
    return normalize(Fraction(x2 - x1) / steps), normalize(Fraction(y2 - y1) / steps)


def basic(
    x1: Number, y1: Number, x2: Number, y2: Number, rounding: str = "half-up"
) -> Iterator[Step]:
    """The direct method: step the major axis by 1, solve the line equation, round.

    ``Step.extra`` is ``(major, minor_exact, minor_rounded)``: ``(x, y, round_half_up(y))``
    when x is the major axis, ``(y, x, round_half_up(x))`` when y is.

    Notes
    -----
    The major coordinate runs over the pixel centres from ``round_half_up(P1)`` to
    ``round_half_up(P2)`` in the direction given; the minor coordinate is computed exactly from
    ``y = y1 + m (x - x1)`` (or ``x = x1 + (y - y1) / m`` on steep lines) and rounded half up.

    Examples
    --------
    The notes' example (2, 2) -> (8, 5):

    >>> from scanconv.core.numeric import fmt
    >>> for s in basic(2, 2, 8, 5):
    ...     print(s.extra[0], fmt(s.extra[1], 1), s.pixel)
    2 2.0 (2, 2)
    3 2.5 (3, 3)
    4 3.0 (4, 3)
    5 3.5 (5, 4)
    6 4.0 (6, 4)
    7 4.5 (7, 5)
    8 5.0 (8, 5)
    """
    # basic(2, 2, 8, 5) -> y: 2 2.5 3 3.5 4 4.5 5 ; rounded: 2 3 3 4 4 5 5
    rnd = rounder(rounding)
    dx, dy = x2 - x1, y2 - y1
    steep = abs_value(dy) > abs_value(dx)
    a1, b1, a2, db, da = (y1, x1, y2, dx, dy) if steep else (x1, y1, x2, dy, dx)
    start, end = round_half_up(a1), round_half_up(a2)
    direction = 1 if end >= start else -1
    slope = Fraction(db) / da if da else Fraction(0)
    for k, a in enumerate(range(start, end + direction, direction)):
        b = normalize(b1 + slope * (a - a1))
        rb = rnd(b)
        pixel = (rb, a) if steep else (a, rb)
        yield Step(k, None, None, pixel, (a, b, rb))


ALGORITHMS = tuple(a.value for a in LineAlgorithm)
"""The line algorithms' names, :class:`~scanconv.algorithms.choices.LineAlgorithm`'s values."""
