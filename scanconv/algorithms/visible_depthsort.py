"""The depth-sort (painter's) method, Newell, Newell and Sancha's, in exact arithmetic (Hearn &
Baker, *Computer Graphics, C version*, 2nd ed., §13-5).

The polygons (convex, planar, seen along z) are sorted by their farthest depth, the farthest
first. The first one, S, is painted once every other polygon S' passes one of the tests
against it, tried in order:

1. ``z``: their depth extents do not overlap (S wholly farther);
2. ``x``, 3. ``y``: their x extents, or their y extents, do not overlap;
4. ``behind``: every vertex of S is on the far side of S''s plane (or on it);
5. ``front``: every vertex of S' is on the near side of S's plane (or on it);
6. ``apart``: their projections onto the xy plane do not overlap (no interior point in common).

When S' fails all six it is moved before S, marked, and the tests start again from it; a
marked polygon that would move again means a cyclic overlap (the polygons would have to be
split, which this method does not do here): the sort stops, saying so. Far and near follow
the ``depth`` convention (a larger z nearer, the viewer on +z, by default).

>>> polys = (("A", ((0, 0, 3), (4, 0, 3), (0, 4, 3))), ("B", ((0, 0, 1), (4, 0, 1), (0, 4, 1))))
>>> result = depth_sort(polys)
>>> [p for p in result.painted], [(t.first, t.second, t.passed) for t in result.tests]
([1, 0], [(1, 0, 'z')])
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.numeric import Number, normalize
from .visible import Face, Plane
from .visible_warnock import Pt, _cross, check_convex
from .visible_zbuffer import Named, check_plane

TESTS = ("z", "x", "y", "behind", "front", "apart")
"""The tests of a pair, in the order they are tried."""


def _extent(values: Sequence[Number]) -> tuple[Number, Number]:
    return min(values), max(values)


def _apart(p: Sequence[Pt], q: Sequence[Pt]) -> bool:
    """No interior point in common: an edge of one with the whole other on its outer side
    (both convex, counter-clockwise)."""
    for a, b in ((p, q), (q, p)):
        n = len(a)
        for i in range(n):
            if all(_cross(a[i], a[(i + 1) % n], v) <= 0 for v in b):
                return True
    return False


def side(plane: Plane, v: Sequence[Number], depth: str) -> Number:
    """``A x + B y + C z + D`` signed so that the viewer's side is positive."""
    f = plane.a * v[0] + plane.b * v[1] + plane.c * v[2] + plane.d
    toward = 1 if (plane.c > 0) == (depth == "larger-nearer") else -1
    return normalize(f * toward)


class PairTest(NamedTuple):
    """One polygon S against one S': each test's outcome until one passes."""

    k: int
    first: int
    """S, the polygon to be painted next."""
    second: int
    """S'."""
    results: tuple[tuple[str, bool], ...]
    """``(test, passed)`` in order, up to the first that passed."""
    passed: str | None
    """The test that passed; ``None``: all failed (S' moves before S)."""
    cycle: bool = False


class DepthSort(NamedTuple):
    """The sort's outcome."""

    initial: tuple[int, ...]
    """The polygons by farthest depth, the farthest first."""
    tests: tuple[PairTest, ...]
    painted: tuple[int, ...]
    """The painting order (the farthest first)."""
    cycle: bool
    """A cyclic overlap stopped the sort (the rest painted in the list's order)."""


class _Poly(NamedTuple):
    face: Face
    plane: Plane
    proj: tuple[Pt, ...]


def _tests(s: _Poly, t: _Poly, depth: str) -> tuple[tuple[str, bool], ...]:
    zs, zt = _extent([v[2] for v in s.face]), _extent([v[2] for v in t.face])
    near_s = zs[1] if depth == "larger-nearer" else zs[0]
    far_t = zt[0] if depth == "larger-nearer" else zt[1]
    checks = {
        "z": lambda: near_s < far_t if depth == "larger-nearer" else near_s > far_t,
        "x": lambda: _disjoint(_extent([v[0] for v in s.face]), _extent([v[0] for v in t.face])),
        "y": lambda: _disjoint(_extent([v[1] for v in s.face]), _extent([v[1] for v in t.face])),
        "behind": lambda: all(side(t.plane, v, depth) <= 0 for v in s.face),
        "front": lambda: all(side(s.plane, v, depth) >= 0 for v in t.face),
        "apart": lambda: _apart(s.proj, t.proj),
    }
    out = []
    for name in TESTS:
        ok = bool(checks[name]())
        out.append((name, ok))
        if ok:
            break
    return tuple(out)


def _disjoint(a: tuple[Number, Number], b: tuple[Number, Number]) -> bool:
    return a[1] <= b[0] or b[1] <= a[0]


def depth_sort(polygons: Named, knobs: Mapping[str, str] | None = None) -> DepthSort:
    """The depth sort of the polygons: the initial order, every pair's tests, the painting
    order."""
    depth = {"depth": "larger-nearer", **(knobs or {})}["depth"]
    polys = [_Poly(f, check_plane(n, f), check_convex(n, f)) for n, f in polygons]

    def farthest(i: int) -> tuple[Fraction, int]:
        zs = [Fraction(v[2]) for v in polys[i].face]
        return (min(zs) if depth == "larger-nearer" else -max(zs), i)

    order = sorted(range(len(polys)), key=farthest)
    initial = tuple(order)
    tests: list[PairTest] = []
    painted: list[int] = []
    marked: set[int] = set()
    while order:
        s = order[0]
        for t in order[1:]:
            results = _tests(polys[s], polys[t], depth)
            passed = results[-1][0] if results[-1][1] else None
            cycle = passed is None and t in marked
            tests.append(PairTest(len(tests), s, t, results, passed, cycle))
            if cycle:
                return DepthSort(initial, tuple(tests), (*painted, *order), True)
            if passed is None:
                marked.add(t)
                order.remove(t)
                order.insert(0, t)
                break
        else:
            painted.append(order.pop(0))
    return DepthSort(initial, tuple(tests), tuple(painted), False)
