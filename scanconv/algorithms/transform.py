"""2D transformations in homogeneous coordinates, and the window-to-viewport mapping.

Points are **column vectors** ``[x, y, 1]ᵀ`` and a matrix acts from the left, ``P' = M·P``,
so a composite of M1 (applied first), then M2, ..., then Mn is ``M = Mn···M2·M1`` (Hearn &
Baker's convention). Every entry is exact: ``int``, :class:`~fractions.Fraction` or a
:class:`~scanconv.algorithms.radical.Radical` (sin and cos at multiples of 15 degrees).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from fractions import Fraction

from ..core.numeric import Number, normalize, round_half_up
from .lines import bresenham
from .radical import Radical, Scalar, simplify

Matrix = tuple[tuple[Scalar, Scalar, Scalar], ...]
"""A 3 x 3 matrix, row by row (the last row of an affine matrix is ``(0, 0, 1)``)."""

Point = tuple[Scalar, Scalar]
"""An exact point ``(x, y)``."""

TRIG_PLACES = 6
"""Decimals of sin and cos at angles that are not multiples of 15 degrees (rounded half up);
everything after that rounding is exact."""


def matrix(rows: Iterable[Iterable[Scalar]]) -> Matrix:
    """A matrix with its entries simplified (radicals without roots become rationals)."""
    return tuple(tuple(simplify(v) for v in r) for r in rows)  # type: ignore[misc]


IDENTITY: Matrix = ((1, 0, 0), (0, 1, 0), (0, 0, 1))


def translation(tx: Scalar, ty: Scalar) -> Matrix:
    """``T(tx, ty)``.

    >>> translation(3, -1)
    ((1, 0, 3), (0, 1, -1), (0, 0, 1))
    """
    return matrix(((1, 0, tx), (0, 1, ty), (0, 0, 1)))


def scaling(sx: Scalar, sy: Scalar) -> Matrix:
    """``S(sx, sy)`` about the origin."""
    return matrix(((sx, 0, 0), (0, sy, 0), (0, 0, 1)))


def rotation(cos: Scalar, sin: Scalar) -> Matrix:
    """``R(θ)`` about the origin, counter-clockwise (y up), from ``cos θ`` and ``sin θ``.

    >>> rotation(0, 1)
    ((0, -1, 0), (1, 0, 0), (0, 0, 1))
    """
    return matrix(((cos, -sin, 0), (sin, cos, 0), (0, 0, 1)))


def shearing(shx: Scalar, shy: Scalar) -> Matrix:
    """``Sh(shx, shy)``: ``x' = x + shx·y``, ``y' = shy·x + y``."""
    return matrix(((1, shx, 0), (shy, 1, 0), (0, 0, 1)))


#: Reflections about the axes and diagonals, by name.
REFLECTIONS: dict[str, Matrix] = {
    "x-axis": ((1, 0, 0), (0, -1, 0), (0, 0, 1)),
    "y-axis": ((-1, 0, 0), (0, 1, 0), (0, 0, 1)),
    "origin": ((-1, 0, 0), (0, -1, 0), (0, 0, 1)),
    "y=x": ((0, 1, 0), (1, 0, 0), (0, 0, 1)),
    "y=-x": ((0, -1, 0), (-1, 0, 0), (0, 0, 1)),
}


def reflection_through_origin(dx: Number, dy: Number) -> Matrix:
    """Reflection about the line through the origin with direction ``(dx, dy)``:
    ``[[cos 2θ, sin 2θ], [sin 2θ, -cos 2θ]]`` with ``cos 2θ = (dx² - dy²)/(dx² + dy²)`` and
    ``sin 2θ = 2·dx·dy/(dx² + dy²)``, exact for any rational direction.

    >>> reflection_through_origin(1, 1) == REFLECTIONS["y=x"]
    True
    """
    n = Fraction(dx * dx + dy * dy)
    c2, s2 = (dx * dx - dy * dy) / n, 2 * dx * dy / n
    return matrix(((c2, s2, 0), (s2, -c2, 0), (0, 0, 1)))


def matmul(a: Matrix, b: Matrix) -> Matrix:
    """``a·b``.

    >>> matmul(translation(1, 2), scaling(2, 3))
    ((2, 0, 1), (0, 3, 2), (0, 0, 1))
    """
    return matrix(
        (sum((a[i][k] * b[k][j] for k in range(3)), start=0) for j in range(3)) for i in range(3)
    )


def compose(factors: Sequence[Matrix]) -> Matrix:
    """The composite of ``factors`` applied in the order given: ``Mn···M2·M1``.

    >>> compose([translation(-2, -1), rotation(0, 1), translation(2, 1)])
    ((0, -1, 3), (1, 0, -1), (0, 0, 1))
    """
    m = IDENTITY
    for f in factors:
        m = matmul(f, m)
    return m


def determinant(m: Matrix) -> Scalar:
    """The determinant of an affine matrix: ``a·e - b·d`` of its 2 x 2 part."""
    return simplify(m[0][0] * m[1][1] - m[0][1] * m[1][0])


def inverse(m: Matrix) -> Matrix:
    """The inverse of an affine matrix; ``ZeroDivisionError`` if it is singular.

    >>> m = compose([scaling(2, 3), rotation(0, 1), translation(5, -1)])
    >>> matmul(inverse(m), m) == IDENTITY
    True
    """
    (a, b, c), (d, e, f), _ = m
    det = determinant(m)
    if det == 0:
        raise ZeroDivisionError("singular matrix")
    inv = 1 / Radical.of(det)
    return matrix(
        (
            (e * inv, -b * inv, (b * f - c * e) * inv),
            (-d * inv, a * inv, (c * d - a * f) * inv),
            (0, 0, 1),
        )
    )


def apply(m: Matrix, point: Point) -> Point:
    """``M·[x, y, 1]ᵀ`` as ``(x', y')``.

    >>> apply(compose([translation(-2, -1), rotation(0, 1), translation(2, 1)]), (4, 0))
    (3, 3)
    """
    x, y = point
    return (
        simplify(m[0][0] * x + m[0][1] * y + m[0][2]),
        simplify(m[1][0] * x + m[1][1] * y + m[1][2]),
    )


# --- angles -----------------------------------------------------------------------------------

_HALF = Fraction(1, 2)
#: (cos, sin) at 0, 15, ..., 75 degrees.
_FIRST_QUADRANT: tuple[tuple[Scalar, Scalar], ...] = (
    (1, 0),
    (Radical(0, Fraction(1, 4), 0, Fraction(1, 4)), Radical(0, Fraction(-1, 4), 0, Fraction(1, 4))),
    (Radical(0, 0, _HALF), _HALF),
    (Radical(0, _HALF), Radical(0, _HALF)),
    (_HALF, Radical(0, 0, _HALF)),
    (Radical(0, Fraction(-1, 4), 0, Fraction(1, 4)), Radical(0, Fraction(1, 4), 0, Fraction(1, 4))),
)


def cos_sin(degrees: Fraction) -> tuple[Scalar, Scalar, bool]:
    """``(cos θ, sin θ, exact)``: exact at multiples of 15 degrees, otherwise each rounded half
    up to :data:`TRIG_PLACES` decimals (``exact`` is then False).

    >>> cos_sin(Fraction(90)), cos_sin(Fraction(-90))[:2]
    ((0, 1, True), (0, -1))
    >>> cos_sin(Fraction(45))[0], cos_sin(Fraction(20))
    (Radical(0, 1/2, 0, 0), (Fraction(939693, 1000000), Fraction(17101, 50000), False))
    """
    turn = degrees % 360
    if (turn / 15).denominator == 1:
        k = int(turn / 15)
        quadrant, r = divmod(k, 6)
        c, s = _FIRST_QUADRANT[r]
        for _ in range(quadrant):  # rotating by 90 degrees: (c, s) -> (-s, c)
            c, s = -s, c
        return simplify(c), simplify(s), True
    rad = float(turn) * math.pi / 180
    scale = 10**TRIG_PLACES

    def rounded(v: float) -> Fraction:
        return Fraction(round_half_up(Fraction(v) * scale), scale)

    return normalize(rounded(math.cos(rad))), normalize(rounded(math.sin(rad))), False


# --- window to viewport -----------------------------------------------------------------------

Rect = tuple[Number, Number, Number, Number]
"""``(xmin, ymin, xmax, ymax)``."""


def viewport_scale(window: Rect, viewport: Rect) -> tuple[Number, Number, Number, Number]:
    """``(sx, sy, tx, ty)`` of the window-to-viewport mapping ``xv = sx·xw + tx``,
    ``yv = sy·yw + ty``.

    Notes
    -----
    ``sx = (xvmax - xvmin)/(xwmax - xwmin)``, ``sy = (yvmax - yvmin)/(ywmax - ywmin)``,
    ``tx = xvmin - sx·xwmin``, ``ty = yvmin - sy·ywmin``: the composite
    ``T(xvmin, yvmin)·S(sx, sy)·T(-xwmin, -ywmin)``, so the window's corners go to the
    viewport's corners.

    References: Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-3.

    >>> viewport_scale((0, 0, 10, 10), (100, 100, 150, 200))
    (Fraction(5, 1), Fraction(10, 1), 100, 100)
    """
    wx0, wy0, wx1, wy1 = window
    vx0, vy0, vx1, vy1 = viewport
    sx = Fraction(vx1 - vx0) / (wx1 - wx0)
    sy = Fraction(vy1 - vy0) / (wy1 - wy0)
    return sx, sy, normalize(vx0 - sx * wx0), normalize(vy0 - sy * wy0)


def map_to_viewport(point: tuple[Number, Number], window: Rect, viewport: Rect) -> Point:
    """The viewport point of a window point.

    >>> map_to_viewport((5, 5), (0, 0, 10, 10), (100, 100, 150, 200))
    (125, 150)
    """
    sx, sy, tx, ty = viewport_scale(window, viewport)
    return normalize(sx * point[0] + tx), normalize(sy * point[1] + ty)


# --- outlines for the figures -----------------------------------------------------------------


def outline(vertices: Sequence[tuple[int, int]], closed: bool = True) -> Iterator[tuple[int, int]]:
    """The pixels of a polygon's (or polyline's) edges by Bresenham's line, each once.

    >>> sorted(outline([(0, 0), (2, 0), (2, 1)]))
    [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1)]
    """
    seen: set[tuple[int, int]] = set()
    n = len(vertices)
    pairs = [(vertices[i], vertices[(i + 1) % n]) for i in range(n if closed and n > 2 else n - 1)]
    for start in vertices[:1]:
        seen.add(start)
        yield start
    for (x1, y1), (x2, y2) in pairs:
        for p in ((x1, y1), (x2, y2), *(s.pixel for s in bresenham(x1, y1, x2, y2))):
            if p not in seen:
                seen.add(p)
                yield p


def rect_outline(rect: tuple[int, int, int, int]) -> Iterator[tuple[int, int]]:
    """The cells on the border of an integer rectangle ``(xmin, ymin, xmax, ymax)``."""
    x0, y0, x1, y1 = rect
    return outline([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
