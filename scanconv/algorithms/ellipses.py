"""The midpoint ellipse algorithm, in its two regions, with 4-way symmetry.

The quadrant is computed for an ellipse centred at the origin, from ``(0, ry)`` clockwise to
``(rx, 0)``; the centre ``(xc, yc)`` is applied in the symmetry step. Coordinates are
``(x, y)`` with y up (see :mod:`scanconv.core.records`).

Pixel order
-----------
``Solution.pixels()`` (and :func:`symmetric_pixels`) yields, for each quadrant point in
plotting order (the start point ``(0, ry)``, then the points of region 1, then those of
region 2), its 4 images ``(xc+x, yc+y), (xc-x, yc+y), (xc+x, yc-y), (xc-x, yc-y)``, each pixel
only the first time it appears. Quadrant points are all different and lie in x >= 0, y >= 0,
so images coincide only for a point on an axis (x = 0 or y = 0); no set of pixels is kept.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from fractions import Fraction

from ..core.numeric import Number, round_c_cast
from ..core.records import (
    Move,
    Pixel,
    Step,
    new_step,
)


def quarter(v: int) -> Number:
    """``v / 4`` as an exact value (int when it divides)."""
    return v >> 2 if v & 3 == 0 else Fraction(v, 4)


def midpoint_ellipse(
    rx: int, ry: int, loop: str = "strict", tie: str = "step", p0: str = "exact"
) -> Iterator[Step]:
    """The midpoint ellipse algorithm (Hearn & Baker), one quadrant from ``(0, ry)``.

    Yields the steps of region 1, then of region 2; ``Step.pixel`` is ``(x_{k+1}, y_{k+1})``,
    ``Step.p`` the decision parameter p1_k or p2_k the move was chosen on (exact),
    ``Step.decision`` the move (``E``/``SE`` in region 1, ``S``/``SE`` in region 2) and
    ``Step.extra`` is ``(region, 2ry²x_{k+1}, 2rx²y_{k+1})``. k restarts at 0 in region 2.
    The start point ``(0, ry)`` is not a step: it is plotted before the loop.

    Notes
    -----
    Region 1 (slope magnitude below 1): ``p1_0 = ry² - rx²ry + rx²/4``; while
    ``2ry²x < 2rx²y``: if ``p1_k < 0`` the next point is ``(x+1, y)`` and
    ``p1_{k+1} = p1_k + 2ry²x_{k+1} + ry²``, else ``(x+1, y-1)`` and
    ``p1_{k+1} = p1_k + 2ry²x_{k+1} - 2rx²y_{k+1} + ry²``.

    Region 2, from the last region-1 point ``(x0, y0)``:
    ``p2_0 = ry²(x0 + 1/2)² + rx²(y0 - 1)² - rx²ry²``; while ``y > 0``: if ``p2_k > 0`` the next
    point is ``(x, y-1)`` and ``p2_{k+1} = p2_k - 2rx²y_{k+1} + rx²``, else ``(x+1, y-1)`` and
    ``p2_{k+1} = p2_k + 2ry²x_{k+1} - 2rx²y_{k+1} + rx²``. Ties (p = 0) choose SE in region 1
    and SE in region 2, as in Hearn & Baker.

    One addition to the textbook loops: a flat ellipse (rx much larger than ry², e.g. 10 by 1)
    reaches y = 0 while still in region 1, at some x < rx, and both loops stop there, leaving
    the pixels out to the tips (rx, 0) and (-rx, 0) unplotted. The walk then continues along
    y = 0 to x = rx as extra region-2 rows with decision E and no p (Zingl's "too early stop of
    flat ellipses"). Every quadrant therefore ends at ``(rx, 0)``. Both loops advance one
    coordinate per step, so the walk always ends after at most ``rx + ry`` steps.

    ``loop="inclusive"`` runs region 1 while ``2ry²x <= 2rx²y`` (the ``<=`` some sources print).
    ``tie="keep"``: a decision parameter of exactly 0 keeps the minor coordinate instead (region
    1: ``p1_k <= 0`` chooses E; region 2: ``p2_k >= 0`` chooses S). ``p0="rounded"`` starts
    each region from its p rounded as Hearn & Baker's C code does (``round(a) = int(a + 0.5)``,
    which truncates toward zero: -332 becomes -331); the increments are integers, so every p is then an integer
    and ties can occur (with the exact quarters they practically never do).

    >>> [s.p for s in midpoint_ellipse(3, 2, p0="rounded")]
    [-11, 1, 3]
    >>> [str(s.p) for s in midpoint_ellipse(3, 2)]
    ['-47/4', '1/4', '9/4']

    Exact arithmetic: the p values are multiples of 1/4 (kept as ``4p`` in integers).

    References: Hearn & Baker, *Computer Graphics*, section 3-10 and its example (rx = 8,
    ry = 6); A. Zingl, *A Rasterizing Algorithm for Drawing Curves*, 2012, section 2.

    Examples
    --------
    Hearn & Baker's example, rx = 8, ry = 6:

    >>> for s in midpoint_ellipse(8, 6):
    ...     print(s.extra[0], s.k, s.p, s.decision.value, s.pixel, *s.extra[1:])
    1 0 -332 E (1, 6) 72 768
    1 1 -224 E (2, 6) 144 768
    1 2 -44 E (3, 6) 216 768
    1 3 208 SE (4, 5) 288 640
    1 4 -108 E (5, 5) 360 640
    1 5 288 SE (6, 4) 432 512
    1 6 244 SE (7, 3) 504 384
    2 0 -23 SE (8, 2) 576 256
    2 1 361 S (8, 1) 576 128
    2 2 297 S (8, 0) 576 0
    """
    # midpoint_ellipse(8, 6) -> region 1 p: -332 -224 -44 208 -108 288 244 ; region 2: -23 361 297
    # midpoint_ellipse(10, 1) -> region 1 ends at (9, 0); the tip (10, 0) follows with decision E
    rx2, ry2 = rx * rx, ry * ry
    x, y = 0, ry
    tx, ty = 0, 2 * rx2 * ry  # 2ry²x and 2rx²y, kept incrementally
    p4 = start4(p1_4(rx, ry), p0)  # 4·p1_0
    k = 0
    inclusive = loop == "inclusive"
    t1, t2 = (1, -1) if tie == "keep" else (0, 0)  # p <= 0 is 4p < 1; p >= 0 is 4p > -1
    while tx < ty or (inclusive and tx == ty and y > 0):
        x += 1
        tx += 2 * ry2
        if p4 < t1:
            q4, move = p4 + increment4(rx, ry, x, y, 1, False), Move.E
        else:
            y -= 1
            ty -= 2 * rx2
            q4, move = p4 + increment4(rx, ry, x, y, 1, True), Move.SE
        yield new_step(Step, (k, quarter(p4), move, (x, y), (1, tx, ty)))
        p4, k = q4, k + 1
    p4 = start4(p2_4(rx, ry, x, y), p0)  # 4·p2_0
    k = 0
    while y > 0:
        y -= 1
        ty -= 2 * rx2
        if p4 > t2:
            q4, move = p4 + increment4(rx, ry, x, y, 2, False), Move.S
        else:
            x += 1
            tx += 2 * ry2
            q4, move = p4 + increment4(rx, ry, x, y, 2, True), Move.SE
        yield new_step(Step, (k, quarter(p4), move, (x, y), (2, tx, ty)))
        p4, k = q4, k + 1
    while x < rx:  # the tip of a flat ellipse, along y = 0
        x += 1
        tx += 2 * ry2
        yield new_step(Step, (k, None, Move.E, (x, 0), (2, tx, 0)))
        k += 1


MAX_AXIS = 10**6
"""Largest semi-axis of :func:`ellipse_solution`: its working (where region 2 starts, p2_0)
needs the end of region 1 before the first line is printed, and finding it runs region 1
(about rx²/sqrt(rx² + ry²) steps: well under a second at 10**6, hours at 10**9)."""


def p1_4(rx: int, ry: int) -> int:
    """``4 p1_0 = 4ry² - 4rx²ry + rx²``: region 1's first p (times 4, an integer).

    >>> p1_4(8, 6)
    -1328
    """
    return 4 * ry * ry - 4 * rx * rx * ry + rx * rx


def p2_4(rx: int, ry: int, x: int, y: int) -> int:
    """``4 p2_0 = ry²(2x + 1)² + 4rx²(y - 1)² - 4rx²ry²`` at region 1's last point ``(x, y)``.

    >>> p2_4(8, 6, 7, 3)
    -92
    """
    rx2, ry2 = rx * rx, ry * ry
    return ry2 * (2 * x + 1) ** 2 + 4 * rx2 * (y - 1) ** 2 - 4 * rx2 * ry2


def increment4(rx: int, ry: int, x: int, y: int, region: int, diagonal: bool) -> int:
    """``4 (p_{k+1} - p_k)`` with the new point ``(x, y)``: region 1 ``2ry²x + ry²`` (E) or
    ``2ry²x - 2rx²y + ry²`` (SE); region 2 ``-2rx²y + rx²`` (S) or ``2ry²x - 2rx²y + rx²``
    (SE). The one copy of the updates: :func:`midpoint_ellipse`, :func:`region1_end` and the
    marking model (:class:`scanconv.marking.models.MidpointEllipse`) all add it.

    >>> increment4(8, 6, 1, 6, 1, False), increment4(8, 6, 8, 2, 2, True)
    (432, 1536)
    """
    rx2, ry2 = rx * rx, ry * ry
    tx = 2 * ry2 * x if region == 1 or diagonal else 0
    ty = 2 * rx2 * y if region == 2 or diagonal else 0
    return 4 * (tx - ty + (ry2 if region == 1 else rx2))


def start4(p4: int, p0: str) -> int:
    """``4p`` of a region's first p: as computed (``"exact"``), or with p rounded as C's
    ``(int)(p + 0.5)`` (``"rounded"``, truncating toward zero after adding 1/2).

    >>> start4(-47, "exact"), start4(-47, "rounded"), start4(-45, "rounded")
    (-47, -44, -40)
    """
    return p4 if p0 == "exact" else 4 * round_c_cast(Fraction(p4, 4))


def region1_end(
    rx: int, ry: int, loop: str = "strict", tie: str = "step", p0: str = "exact"
) -> Pixel:
    """The last point of region 1 (where region 2 starts), without building any steps.

    >>> region1_end(8, 6)
    (7, 3)
    """
    rx2, ry2 = rx * rx, ry * ry
    x, y, tx, ty = 0, ry, 0, 2 * rx2 * ry
    p4 = start4(p1_4(rx, ry), p0)
    inclusive = loop == "inclusive"
    t1 = 1 if tie == "keep" else 0
    while tx < ty or (inclusive and tx == ty and y > 0):
        x += 1
        tx += 2 * ry2
        se = p4 >= t1
        if se:
            y -= 1
            ty -= 2 * rx2
        p4 += increment4(rx, ry, x, y, 1, se)
    return x, y


def images(x: int, y: int, xc: int = 0, yc: int = 0) -> tuple[Pixel, ...]:
    """The 4 symmetric images of ``(x, y)`` about ``(xc, yc)``.

    >>> images(2, 6, 1, 1)
    ((3, 7), (-1, 7), (3, -5), (-1, -5))
    """
    return ((xc + x, yc + y), (xc - x, yc + y), (xc + x, yc - y), (xc - x, yc - y))


def symmetric_pixels(points: Iterable[Pixel], xc: int = 0, yc: int = 0) -> Iterator[Pixel]:
    """The 4-way images of distinct quadrant points, once each, in the module's order.

    >>> list(symmetric_pixels([(0, 2), (1, 1), (2, 0)]))
    [(0, 2), (0, -2), (1, 1), (-1, 1), (1, -1), (-1, -1), (2, 0), (-2, 0)]
    """
    for x, y in points:
        a, b, c, d = images(x, y, xc, yc)
        yield a
        if x:
            yield b
        if y:
            yield c
            if x:
                yield d


def quadrant_points(rx: int, ry: int) -> Iterator[Pixel]:
    """The start point ``(0, ry)``, then every step's point.

    >>> list(quadrant_points(2, 1))
    [(0, 1), (1, 1), (2, 0)]
    """
    yield (0, ry)
    for s in midpoint_ellipse(rx, ry):
        yield s.pixel
