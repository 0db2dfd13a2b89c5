"""Visible-surface detection, the shared part and back-face detection: 3D vectors and faces
in exact arithmetic, the named solids, a face's normal and plane, and the back-face test.

A face is a planar polygon given by its vertices ``(x, y, z)`` in order. Its normal is
Hearn & Baker's ``N = (V2 - V1) x (V3 - V1)`` (*Computer Graphics, C version*, 2nd ed.,
§13-2, and §10-1 for the plane ``Ax + By + Cz + D = 0`` with ``(A, B, C) = N`` and
``D = -N . V1``): with right-handed axes and the vertices counter-clockwise seen from outside
the solid it points outward. The conventions (:mod:`scanconv.algorithms.conventions`,
``KNOBS``), named in every answer:

- ``direction``: ``into-scene`` (the default, Hearn & Baker): V is the viewing direction, from the
  viewer into the scene, and a face is a back face when ``V . N > 0``; ``to-viewer``: V points
  from the face toward the viewer (the line of sight), a back face has ``V . N < 0``;
- ``edge-on``: a face seen edge-on (``V . N = 0``) is ``hidden`` (the default: Hearn & Baker's
  ``C <= 0`` for V along -z) or ``visible``;
- ``handed``: ``right`` (the default): the viewer on +z looking along -z, so the default
  V is ``(0, 0, -1)`` into the scene; ``left``: Hearn & Baker's left-handed viewing system,
  the vertices clockwise seen from outside and the viewer looking along +z, ``V = (0, 0, 1)``.

>>> tests = list(backface(SOLIDS["cube"]))
>>> [(t.name, t.normal, t.dot, t.back) for t in tests][:2]
[('front', (0, 0, 1), -1, False), ('back', (0, 0, -1), 1, True)]
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize

Vec = tuple[Number, Number, Number]
"""A point or a vector ``(x, y, z)``, exact."""
Face = tuple[Vec, ...]
"""A planar polygon's vertices, in order."""

MAX_FACES = 24
"""The most faces (or polygons) one answer takes."""
MAX_VERTICES = 16
"""The most vertices of one face."""

VISIBLE_KNOBS = ("direction", "edge-on", "handed", "depth", "ties")
"""The knobs of :mod:`scanconv.algorithms.conventions` the visible-surface methods read."""


def sub(a: Vec, b: Vec) -> Vec:
    """``a - b``."""
    return (normalize(a[0] - b[0]), normalize(a[1] - b[1]), normalize(a[2] - b[2]))


def cross(a: Vec, b: Vec) -> Vec:
    """The cross product ``a x b``.

    >>> cross((1, 0, 0), (0, 1, 0))
    (0, 0, 1)
    """
    return (
        normalize(a[1] * b[2] - a[2] * b[1]),
        normalize(a[2] * b[0] - a[0] * b[2]),
        normalize(a[0] * b[1] - a[1] * b[0]),
    )


def dot(a: Vec, b: Vec) -> Number:
    """The dot product ``a . b``."""
    return normalize(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])


def _cube() -> dict[str, Face]:
    p = {
        "A": (0, 0, 1), "B": (1, 0, 1), "C": (1, 1, 1), "D": (0, 1, 1),
        "E": (0, 0, 0), "F": (1, 0, 0), "G": (1, 1, 0), "H": (0, 1, 0),
    }  # fmt: skip
    faces = {
        "front": "ABCD", "back": "FEHG", "left": "EADH",
        "right": "BFGC", "top": "DCGH", "bottom": "EFBA",
    }  # fmt: skip
    return {name: tuple(p[c] for c in word) for name, word in faces.items()}


def _pyramid() -> dict[str, Face]:
    a, b, c, d, apex = (0, 0, 2), (2, 0, 2), (2, 0, 0), (0, 0, 0), (1, 2, 1)
    return {
        "base": (d, c, b, a),
        "front": (a, b, apex),
        "right": (b, c, apex),
        "back": (c, d, apex),
        "left": (d, a, apex),
    }


def _tetrahedron() -> dict[str, Face]:
    o, x, y, z = (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)
    return {"xy": (o, y, x), "yz": (o, z, y), "zx": (o, x, z), "slant": (x, y, z)}


SOLIDS: dict[str, dict[str, Face]] = {
    "cube": _cube(),
    "pyramid": _pyramid(),
    "tetrahedron": _tetrahedron(),
}
"""The named solids, each face counter-clockwise seen from outside (outward normals with
right-handed axes): the unit cube ``[0, 1]^3``; a square pyramid, base ``[0, 2] x {0} x
[0, 2]``, apex ``(1, 2, 1)``; the tetrahedron of the origin and the three unit points."""


def check_face(face: Sequence[Vec], name: str) -> Face:
    """The face, exact, if it has 3 to :data:`MAX_VERTICES` vertices, its first three not on
    one line and all on their plane; else :class:`InputError` naming it."""
    if len(face) < 3:
        raise InputError(f"face {name} needs at least 3 vertices (x y z each), got {len(face)}")
    if len(face) > MAX_VERTICES:
        raise InputError(f"face {name} has {len(face)} vertices; at most {MAX_VERTICES}")
    pts = tuple(tuple(normalize(Fraction(c)) for c in v) for v in face)
    n = normal(pts)  # type: ignore[arg-type]
    if n == (0, 0, 0):
        raise InputError(f"face {name}: its first three vertices lie on one line (N = 0)")
    for v in pts[3:]:
        if dot(n, sub(v, pts[0])) != 0:  # type: ignore[arg-type]
            raise InputError(f"face {name} is not planar: {v} is off the plane of V1, V2, V3")
    return pts  # type: ignore[return-value]


def normal(face: Sequence[Vec]) -> Vec:
    """``N = (V2 - V1) x (V3 - V1)``.

    >>> normal(((0, 0, 1), (1, 0, 1), (1, 1, 1)))
    (0, 0, 1)
    """
    return cross(sub(face[1], face[0]), sub(face[2], face[0]))


class Plane(NamedTuple):
    """``A x + B y + C z + D = 0``."""

    a: Number
    b: Number
    c: Number
    d: Number


def plane(face: Sequence[Vec]) -> Plane:
    """The face's plane: ``(A, B, C) = N`` and ``D = -N . V1``.

    >>> plane(((0, 0, 2), (4, 0, 2), (0, 4, 2)))
    Plane(a=0, b=0, c=16, d=-32)
    """
    n = normal(face)
    return Plane(n[0], n[1], n[2], normalize(-dot(n, face[0])))


def default_view(view: str, handed: str) -> Vec:
    """The default V of a convention: the viewer on +z looking along -z (right-handed) or
    looking along +z (left-handed), into the scene or toward the viewer.

    >>> default_view("into-scene", "right"), default_view("to-viewer", "right")
    ((0, 0, -1), (0, 0, 1))
    """
    into = -1 if handed == "right" else 1
    return (0, 0, into if view == "into-scene" else -into)


class FaceTest(NamedTuple):
    """The back-face test of one face: a row of the table."""

    name: str
    vertices: Face
    e1: Vec
    """``V2 - V1``."""
    e2: Vec
    """``V3 - V1``."""
    normal: Vec
    view: Vec
    """The view vector used for this face (per face when an eye point is given)."""
    dot: Number
    """``V . N``."""
    back: bool
    """Whether it is a back face (hidden)."""
    edge_on: bool
    """``V . N = 0``."""


def is_back(d: Number, view: str, edge_on: str) -> bool:
    """Whether ``V . N = d`` makes a back face under the conventions.

    >>> is_back(0, "into-scene", "hidden"), is_back(-2, "to-viewer", "visible")
    (True, True)
    """
    if d == 0:
        return edge_on == "hidden"
    return d > 0 if view == "into-scene" else d < 0


def backface(
    faces: Mapping[str, Face],
    view_vector: Vec | None = None,
    eye: Vec | None = None,
    knobs: Mapping[str, str] | None = None,
) -> Iterator[FaceTest]:
    """The back-face test of each face, in order: its normal, the view vector, ``V . N`` and
    the verdict. ``view_vector``: V for every face (default :func:`default_view`); ``eye``:
    the viewer's position instead, V per face from the eye to V1 (``into-scene``) or from
    V1 to the eye (``to-viewer``)."""
    k = {"direction": "into-scene", "edge-on": "hidden", "handed": "right", **(knobs or {})}
    for name, face in faces.items():
        e1, e2 = sub(face[1], face[0]), sub(face[2], face[0])
        n = cross(e1, e2)
        if eye is not None:
            v = sub(face[0], eye) if k["direction"] == "into-scene" else sub(eye, face[0])
        else:
            v = view_vector or default_view(k["direction"], k["handed"])
        d = dot(v, n)
        yield FaceTest(
            name, face, e1, e2, n, v, d, is_back(d, k["direction"], k["edge-on"]), d == 0
        )
