"""Parallel and perspective projections as 4 x 4 matrices, exact (column vectors,
``P' = M·P``; :mod:`scanconv.algorithms.space`).

- orthographic onto a principal plane: the coordinate along the view axis set to 0;
- oblique onto z = 0 (Hearn & Baker, 12-3): ``x' = x + L1·z·cos φ``, ``y' = y + L1·z·sin φ``
  with ``L1 = cot α`` (α: the projectors' angle with the view plane): cavalier ``L1 = 1``
  (α = 45°), cabinet ``L1 = 1/2`` (tan α = 2);
- axonometric onto z = 0 after a rotation about y by φ and then about x by θ (Rogers & Adams,
  3-9): isometric ``φ = 45°, sin θ = 1/√3`` (θ ≈ 35.26°), dimetric with the z axis foreshortened
  to ``f``: ``sin θ = f/√2``, ``sin φ = f/√(2 - f²)``, trimetric at any φ and θ;
- perspective (one-, two- and three-point: the object turned about y, then x, so that one, two
  or three of its principal axes meet the view plane) with the centre of projection at
  (0, 0, -d), (0, 0, d) or the origin (:mod:`scanconv.algorithms.space_conventions`).

A vanishing point is the image of a direction: ``M·[dx, dy, dz, 0]ᵀ = (X, Y, Z, W)``, at
``(X/W, Y/W)`` when ``W != 0`` (no vanishing point when the direction is parallel to the view
plane).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from .radical import Radical, Scalar, simplify
from .space import Matrix4, Point3, homogeneous, matrix

VIEWS = {"xy": (0, 1), "yz": (1, 2), "zx": (0, 2)}
"""The principal planes of an orthographic view, and the coordinates drawn (u, v): front
(xy: x, y), side (yz: y, z), top (zx: x, z)."""

PARALLEL = ("orthographic", "oblique", "cavalier", "cabinet", "isometric", "dimetric", "trimetric")
PERSPECTIVE = ("one-point", "two-point", "three-point")


def orthographic(view: str) -> Matrix4:
    """The orthographic projection onto the plane ``view`` (xy: z = 0; yz: x = 0; zx: y = 0).

    >>> orthographic("yz")[0]
    (0, 0, 0, 0)
    """
    keep = VIEWS[view]
    return matrix(
        [*([int(i == j and i in keep) for j in range(4)] for i in range(3)), (0, 0, 0, 1)]
    )


def oblique(ratio: Scalar, cos: Scalar, sin: Scalar) -> Matrix4:
    """The oblique projection onto z = 0: ``x' = x + L1·cos φ·z``, ``y' = y + L1·sin φ·z``.

    >>> oblique(Fraction(1, 2), 0, 1)[:3]
    ((1, 0, 0, 0), (0, 1, Fraction(1, 2), 0), (0, 0, 0, 0))
    """
    return matrix(((1, 0, ratio * cos, 0), (0, 1, ratio * sin, 0), (0, 0, 0, 0), (0, 0, 0, 1)))


def onto_z0() -> Matrix4:
    """The orthographic projection onto z = 0 (after an axonometric rotation)."""
    return orthographic("xy")


ISOMETRIC: tuple[tuple[Scalar, Scalar], tuple[Scalar, Scalar]] = (
    (Radical(0, Fraction(1, 2)), Radical(0, Fraction(1, 2))),  # φ = 45° about y
    (Radical(0, 0, 0, Fraction(1, 3)), Radical(0, 0, Fraction(1, 3))),  # sin θ = 1/√3 about x
)
"""``((cos φ, sin φ), (cos θ, sin θ))`` of the isometric projection."""


def dimetric(f: Fraction) -> tuple[tuple[Scalar, Scalar], tuple[Scalar, Scalar]]:
    """``((cos φ, sin φ), (cos θ, sin θ))`` of the dimetric projection that foreshortens the z
    axis to ``f`` (``0 < f <= 1``) and x and y alike: ``sin² θ = f²/2``,
    ``sin² φ = f²/(2 - f²)``.

    >>> dimetric(Fraction(1, 2))[1]
    (Radical(roots={14: 1/4}), Radical(0, 1/4, 0, 0))
    """
    s_theta = Fraction(f * f, 2)
    s_phi = f * f / (2 - f * f)
    return (
        (Radical.sqrt(1 - s_phi), Radical.sqrt(s_phi)),
        (Radical.sqrt(1 - s_theta), Radical.sqrt(s_theta)),
    )


def perspective(cop: str, d: Fraction) -> Matrix4:
    """The perspective projection with the centre ``cop`` (minus-d, plus-d, origin) at
    distance ``d``.

    >>> perspective("minus-d", Fraction(2))[3], perspective("origin", Fraction(2))[2:]
    ((0, 0, Fraction(1, 2), 1), ((0, 0, 1, 0), (0, 0, Fraction(1, 2), 0)))
    """
    inv = 1 / Fraction(d)
    if cop == "origin":
        return matrix(((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, inv, 0)))
    sign = 1 if cop == "minus-d" else -1
    return matrix(((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 0, 0), (0, 0, sign * inv, 1)))


class Projected(NamedTuple):
    """A vertex projected: ``M·P = (X, Y, Z, W)`` and the point ``(X/W, Y/W, Z/W)``."""

    homogeneous: tuple[Scalar, ...]
    point: Point3


def project(m: Matrix4, p: Point3) -> Projected:
    """``p`` through ``m`` (``ZeroDivisionError`` where ``W = 0``: at the centre's plane)."""
    h = homogeneous(m, p)
    w = h[3]
    if w == 0:
        raise ZeroDivisionError("w = 0")
    inv = 1 / Radical.of(w)
    return Projected(h, (simplify(h[0] * inv), simplify(h[1] * inv), simplify(h[2] * inv)))


AXES: tuple[tuple[str, Point3], ...] = (("x", (1, 0, 0)), ("y", (0, 1, 0)), ("z", (0, 0, 1)))


def vanishing_points(m: Matrix4) -> list[tuple[str, tuple[Scalar, ...], Point3 | None]]:
    """Each principal axis's direction through ``m``: ``(axis, (X, Y, Z, W), VP or None)``.

    >>> [vp for _, _, vp in vanishing_points(perspective("minus-d", Fraction(4)))]
    [None, None, (0, 0, 0)]
    """
    out: list[tuple[str, tuple[Scalar, ...], Point3 | None]] = []
    for name, e in AXES:
        h = homogeneous(m, e, 0)
        if h[3] == 0:
            out.append((name, h, None))
        else:
            inv = 1 / Radical.of(h[3])
            out.append(
                (name, h, (simplify(h[0] * inv), simplify(h[1] * inv), simplify(h[2] * inv)))
            )
    return out


def foreshortening(m: Matrix4) -> list[Scalar]:
    """``f²`` of each principal axis: the squared length of the unit vector's image on z = 0.

    >>> foreshortening(onto_z0())
    [1, 1, 0]
    """
    out = []
    for _, e in AXES:
        x, y, _, _ = homogeneous(m, e, 0)
        out.append(simplify(x * x + y * y))
    return out


def drawn(points: Sequence[Point3], uv: tuple[int, int]) -> list[tuple[Scalar, Scalar]]:
    """The 2D coordinates drawn of each projected point."""
    return [(p[uv[0]], p[uv[1]]) for p in points]
