"""3D transformations in homogeneous coordinates (4 x 4), and the named solids.

Points are **column vectors** ``[x, y, z, 1]ᵀ`` and a matrix acts from the left,
``P' = M·P``, so a composite of M1 (applied first), then M2, ..., then Mn is ``Mn···M2·M1``
(Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., chapter 11); an answer written with
row vectors shows the transposes (:mod:`scanconv.algorithms.space_conventions`). Axes are
right-handed and a positive angle turns y toward z about x, z toward x about y and x toward
y about z (counter-clockwise looking from the positive axis toward the origin). Every entry is
exact: ``int``, :class:`~fractions.Fraction` or a
:class:`~scanconv.algorithms.radical.Radical` (sin and cos at multiples of 15 degrees, the
direction cosines of an axis).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction
from typing import NamedTuple

from .radical import Radical, Scalar, simplify

Matrix4 = tuple[tuple[Scalar, ...], ...]
"""A 4 x 4 matrix, row by row."""

Point3 = tuple[Scalar, Scalar, Scalar]
"""An exact point ``(x, y, z)``."""


def matrix(rows: Iterable[Iterable[Scalar]]) -> Matrix4:
    """A matrix with its entries simplified (radicals without roots become rationals)."""
    return tuple(tuple(simplify(v) for v in r) for r in rows)


IDENTITY: Matrix4 = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))


def translation(tx: Scalar, ty: Scalar, tz: Scalar) -> Matrix4:
    """``T(tx, ty, tz)``.

    >>> translation(1, 2, 3)[0], translation(1, 2, 3)[2]
    ((1, 0, 0, 1), (0, 0, 1, 3))
    """
    return matrix(((1, 0, 0, tx), (0, 1, 0, ty), (0, 0, 1, tz), (0, 0, 0, 1)))


def scaling(sx: Scalar, sy: Scalar, sz: Scalar) -> Matrix4:
    """``S(sx, sy, sz)`` about the origin."""
    return matrix(((sx, 0, 0, 0), (0, sy, 0, 0), (0, 0, sz, 0), (0, 0, 0, 1)))


def rotation(axis: str, cos: Scalar, sin: Scalar) -> Matrix4:
    """``Rx(θ)``, ``Ry(θ)`` or ``Rz(θ)`` from ``cos θ`` and ``sin θ`` (``axis``: x, y or z).

    >>> rotation("z", 0, 1)[:2], rotation("x", 0, 1)[1:3], rotation("y", 0, 1)[0]
    (((0, -1, 0, 0), (1, 0, 0, 0)), ((0, 0, -1, 0), (0, 1, 0, 0)), (0, 0, 1, 0))
    """
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]  # the plane turned: i toward j
    m: list[list[Scalar]] = [list(r) for r in IDENTITY]
    m[i][i], m[i][j], m[j][i], m[j][j] = cos, -sin, sin, cos
    return matrix(m)


#: Reflections about the coordinate planes, by name (the coordinate that changes sign).
REFLECTIONS: dict[str, Matrix4] = {
    "xy": ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, -1, 0), (0, 0, 0, 1)),
    "yz": ((-1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)),
    "zx": ((1, 0, 0, 0), (0, -1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)),
}


def reflection_plane(normal: Sequence[Fraction]) -> Matrix4:
    """Reflection about the plane through the origin with normal ``n``: ``I - 2·n·nᵀ/(n·n)``,
    rational for any rational normal.

    >>> reflection_plane((0, 0, 1)) == REFLECTIONS["xy"]
    True
    """
    nn = sum((Fraction(v) * v for v in normal), start=Fraction(0))
    rows: list[tuple[Scalar, ...]] = []
    for i in range(3):
        rows.append((*(int(i == j) - 2 * normal[i] * normal[j] / nn for j in range(3)), 0))
    return matrix([*rows, (0, 0, 0, 1)])


#: The shears, by the axis whose coordinate moves the other two: ``z``: x' = x + a·z,
#: y' = y + b·z (Hearn & Baker's z-axis shear); ``x``: y' = y + a·x, z' = z + b·x;
#: ``y``: x' = x + a·y, z' = z + b·y.
SHEAR_AXES = {"x": ((1, 0), (2, 0)), "y": ((0, 1), (2, 1)), "z": ((0, 2), (1, 2))}


def shearing(axis: str, a: Scalar, b: Scalar) -> Matrix4:
    """The shear along ``axis`` (:data:`SHEAR_AXES`).

    >>> shearing("z", 2, 3)[:2]
    ((1, 0, 2, 0), (0, 1, 3, 0))
    """
    m: list[list[Scalar]] = [list(r) for r in IDENTITY]
    (i1, j1), (i2, j2) = SHEAR_AXES[axis]
    m[i1][j1], m[i2][j2] = a, b
    return matrix(m)


def transpose(m: Matrix4) -> Matrix4:
    return tuple(tuple(m[j][i] for j in range(len(m))) for i in range(len(m[0])))


def matmul(a: Matrix4, b: Matrix4) -> Matrix4:
    """``a·b``.

    >>> matmul(translation(1, 2, 3), scaling(2, 2, 2))[0]
    (2, 0, 0, 1)
    """
    n = len(b)
    return matrix(
        (sum((a[i][k] * b[k][j] for k in range(n)), start=0) for j in range(len(b[0])))
        for i in range(len(a))
    )


def compose(factors: Sequence[Matrix4]) -> Matrix4:
    """The composite of ``factors`` applied in the order given: ``Mn···M2·M1``."""
    m = IDENTITY
    for f in factors:
        m = matmul(f, m)
    return m


def determinant(m: Matrix4) -> Scalar:
    """The determinant by cofactors along the first row (exact, radicals too).

    >>> determinant(rotation("x", 0, 1)), determinant(scaling(2, 3, 4))
    (1, 24)
    """
    if len(m) == 1:
        return m[0][0]
    total: Scalar = 0
    for j, v in enumerate(m[0]):
        if v == 0:
            continue
        minor = tuple(tuple(r[k] for k in range(len(m)) if k != j) for r in m[1:])
        total = total + (-1) ** j * v * determinant(minor)
    return simplify(total)


def homogeneous(m: Matrix4, point: Point3, w: Scalar = 1) -> tuple[Scalar, ...]:
    """``M·[x, y, z, w]ᵀ`` (``w = 0``: a direction)."""
    v = (*point, w)
    return tuple(simplify(sum((m[i][k] * v[k] for k in range(4)), start=0)) for i in range(4))


def apply(m: Matrix4, point: Point3) -> Point3:
    """``M·[x, y, z, 1]ᵀ`` as ``(x', y', z')``, divided by ``w`` when ``w != 1``.

    >>> apply(rotation("z", 0, 1), (1, 0, 0))
    (0, 1, 0)
    """
    x, y, z, w = homogeneous(m, point)
    if w == 1:
        return x, y, z
    inv = 1 / Radical.of(w)
    return simplify(x * inv), simplify(y * inv), simplify(z * inv)


# --- rotation about an arbitrary axis ---------------------------------------------------------


class AxisRotation(NamedTuple):
    """The steps of a rotation about the axis through P1 and P2 (Hearn & Baker, 11-2): the
    direction ``v = P2 - P1``, its length, the unit vector ``u = (a, b, c)``,
    ``d = √(b² + c²)``, and the factors in the order applied, each ``(name, matrix)``:
    T(-P1), Rx(α), Ry(β), R(θ) about z, Ry(-β), Rx(-α), T(P1) (Rx left out where d = 0)."""

    v: Point3
    length: Scalar
    u: Point3
    d: Scalar
    factors: tuple[tuple[str, Matrix4], ...]


RationalPoint = tuple[Fraction, Fraction, Fraction]
"""A point with rational coordinates (an axis's end points)."""


def axis_rotation(p1: RationalPoint, p2: RationalPoint, cos: Scalar, sin: Scalar) -> AxisRotation:
    """The factors of the rotation by θ about the axis from ``p1`` to ``p2``: the axis is
    moved to the origin, turned into the xz plane about x (``cos α = c/d``, ``sin α = b/d``),
    onto the z axis about y (``cos β = d``, ``sin β = -a``), turned by θ about z, then back.

    >>> r = axis_rotation((0, 0, 0), (0, 0, 2), 0, 1)
    >>> r.u, r.d, [name for name, _ in r.factors], compose([m for _, m in r.factors])[0]
    ((0, 0, 1), 1, ['Rz(θ)'], (0, -1, 0, 0))
    """
    v = (Fraction(p2[0] - p1[0]), Fraction(p2[1] - p1[1]), Fraction(p2[2] - p1[2]))
    nn = v[0] ** 2 + v[1] ** 2 + v[2] ** 2
    if nn == 0:
        raise ValueError("the axis needs two different points")
    length = Radical.sqrt(nn)
    inv = 1 / Radical.of(length)
    a, b, c = (simplify(x * inv) for x in v)
    d = Radical.sqrt((v[1] ** 2 + v[2] ** 2) / nn)
    factors: list[tuple[str, Matrix4]] = []
    if any(p1):
        factors.append(("T(-P1)", translation(-p1[0], -p1[1], -p1[2])))
    turn_x = d != 0 and not (b == 0 and c == d)
    if turn_x:
        dinv = 1 / Radical.of(d)
        ca, sa = simplify(c * dinv), simplify(b * dinv)
        factors.append(("Rx(α)", rotation("x", ca, sa)))
    if a != 0:
        factors.append(("Ry(β)", rotation("y", d, -a)))
    factors.append(("Rz(θ)", rotation("z", cos, sin)))
    if a != 0:
        factors.append(("Ry(-β)", rotation("y", d, a)))
    if turn_x:
        factors.append(("Rx(-α)", rotation("x", ca, -sa)))
    if any(p1):
        factors.append(("T(P1)", translation(*p1)))
    return AxisRotation(v, length, (a, b, c), d, tuple(factors))


# --- the named solids -------------------------------------------------------------------------


class Solid(NamedTuple):
    """A solid: its vertices (labelled), its edges (pairs of vertex indices) and its faces
    (vertex indices counter-clockwise seen from outside, so a face's normal
    ``(V2 - V1) × (V3 - V1)`` points out of the solid: right-handed axes)."""

    name: str
    title: str
    labels: tuple[str, ...]
    vertices: tuple[Point3, ...]
    edges: tuple[tuple[int, int], ...]
    faces: tuple[tuple[int, ...], ...]


def _edges_of(faces: Sequence[Sequence[int]]) -> tuple[tuple[int, int], ...]:
    seen: list[tuple[int, int]] = []
    for f in faces:
        for i, j in zip(f, (*f[1:], f[0]), strict=True):
            e = (min(i, j), max(i, j))
            if e not in seen:
                seen.append(e)
    return tuple(seen)


def _box(name: str, title: str, lo: int, hi: int) -> Solid:
    # A B C D on the face z = lo (counter-clockwise from +z), E F G H above them at z = hi
    corners = ((lo, lo), (hi, lo), (hi, hi), (lo, hi))
    vertices = tuple((x, y, z) for z in (lo, hi) for x, y in corners)
    faces = (
        (0, 3, 2, 1),  # bottom z = lo (seen from -z)
        (4, 5, 6, 7),  # top z = hi
        (0, 1, 5, 4),  # front y = lo
        (2, 3, 7, 6),  # back y = hi
        (1, 2, 6, 5),  # right x = hi
        (3, 0, 4, 7),  # left x = lo
    )
    return Solid(name, title, tuple("ABCDEFGH"), vertices, _edges_of(faces), faces)


def _pyramid() -> Solid:
    vertices: tuple[Point3, ...] = ((0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (1, 1, 2))
    faces = ((0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4))
    title = "the square pyramid, base (0, 0, 0)-(2, 2, 0) on z = 0 and apex E(1, 1, 2)"
    return Solid("pyramid", title, tuple("ABCDE"), vertices, _edges_of(faces), faces)


def _tetrahedron() -> Solid:
    vertices: tuple[Point3, ...] = ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    faces = ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3))
    title = "the tetrahedron O(0, 0, 0), A(1, 0, 0), B(0, 1, 0), C(0, 0, 1)"
    return Solid("tetrahedron", title, tuple("OABC"), vertices, _edges_of(faces), faces)


SOLIDS: dict[str, Solid] = {
    s.name: s
    for s in (
        _box("unit-cube", "the unit cube [0, 1]³, A(0, 0, 0) to G(1, 1, 1)", 0, 1),
        _box("cube", "the cube [-1, 1]³ centred on the origin, A(-1, -1, -1) to G(1, 1, 1)", -1, 1),
        _pyramid(),
        _tetrahedron(),
    )
}
"""The named solids (``--solid``)."""


def given_solid(vertices: Sequence[Point3]) -> Solid:
    """The vertices given, as a polygon: each joined to the next, the last to the first (one
    edge for two points, none for one)."""
    n = len(vertices)
    edges = tuple((i, (i + 1) % n) for i in range(n if n > 2 else n - 1))
    return Solid(
        "points",
        "the points given",
        tuple(f"P{i}" for i in range(1, n + 1)),
        tuple(vertices),
        edges,
        (),
    )
