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

When S' fails all six it is moved before S, marked, and the tests start again from it. A
marked polygon that would move again means a cyclic overlap (two polygons that pierce each
other, or three or more that overlap in a ring): S' is split along the plane of S (Hearn &
Baker: "we divide it into two parts"; when that plane does not cut S', S is split along the
plane of S', and failing both, the first polygon of the list cut by the plane of another).
The two pieces, the part on the viewer's side of the plane first, replace it in the list,
each before the first polygon whose farthest depth is nearer than its own; the marks are
cleared and the tests start again from the front of the list. At most :data:`MAX_SPLITS`
splits: a scene that needs more is refused. Far and near follow the ``depth`` convention (a
larger z nearer, the viewer on +z, by default).

>>> polys = (("A", ((0, 0, 3), (4, 0, 3), (0, 4, 3))), ("B", ((0, 0, 1), (4, 0, 1), (0, 4, 1))))
>>> result = depth_sort(polys)
>>> [p for p in result.painted], [(t.first, t.second, t.passed) for t in result.tests]
([1, 0], [(1, 0, 'z')])
>>> cut = depth_sort((("A", ((0, 0, 0), (4, 0, 4), (0, 4, 0))), ("B", ((0, 0, 4), (4, 0, 0), (0, 4, 4)))))
>>> [(p.name, p.origin) for p in cut.polygons[2:]], cut.splits[0].line
([('B1', 1), ('B2', 1)], ((2, 0, 2), (2, 2, 2)))
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .visible import Face, Plane, Vec
from .visible_warnock import Pt, _cross, check_convex
from .visible_zbuffer import MAX_POLYGONS, Named, check_plane

TESTS = ("z", "x", "y", "behind", "front", "apart")
"""The tests of a pair, in the order they are tried."""

MAX_SPLITS = 8
"""The most polygon splits one depth sort makes (the cyclic overlaps it resolves)."""


def max_pair_tests(polygons: int = MAX_POLYGONS, splits: int = MAX_SPLITS) -> int:
    """The most pair tests a sort of ``polygons`` polygons with at most ``splits`` splits
    makes: at most ``n = polygons + splits`` in the list, and ``splits + 1`` runs between the
    splits; each pass over the list (at most ``n - 1`` tests) ends in a painting (``n`` in
    all), a move (in each run at most ``n``: the marks are distinct), or a split.

    >>> max_pair_tests()
    2535
    """
    n = polygons + splits
    return ((splits + 2) * n + splits + 1) * (n - 1)


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
    """S, the polygon to be painted next (an index of :attr:`DepthSort.polygons`)."""
    second: int
    """S'."""
    results: tuple[tuple[str, bool], ...]
    """``(test, passed)`` in order, up to the first that passed."""
    passed: str | None
    """The test that passed; ``None``: all failed (S' moves before S)."""
    cycle: bool = False
    """S' failed and had moved before: a cyclic overlap (see :attr:`split`)."""
    split: int | None = None
    """The split this cyclic overlap made (an index of :attr:`DepthSort.splits`)."""


class Piece(NamedTuple):
    """A polygon of the sort: one given (``A``, ``B``, ...) or a piece of one (``B1``, ``B2``,
    a piece of ``B1``: ``B11``, ...)."""

    name: str
    face: Face
    origin: int
    """The given polygon it is (part of)."""


class Split(NamedTuple):
    """One polygon cut in two by another's plane."""

    k: int
    """The pair test that found the cyclic overlap."""
    polygon: int
    """The polygon split."""
    by: int
    """The polygon whose plane cuts it."""
    sides: tuple[Number, ...]
    """Each vertex's ``A x + B y + C z + D`` on that plane, the viewer's side positive."""
    line: tuple[Vec, Vec]
    """The two points where the plane crosses the polygon's boundary: the split line."""
    pieces: tuple[int, int]
    """The two pieces: the part on the viewer's side of the plane, then the far part."""


class DepthSort(NamedTuple):
    """The sort's outcome."""

    initial: tuple[int, ...]
    """The polygons by farthest depth, the farthest first."""
    tests: tuple[PairTest, ...]
    painted: tuple[int, ...]
    """The painting order (the farthest first); a split polygon is painted as its pieces."""
    cycle: bool
    """A cyclic overlap was met (and resolved by the :attr:`splits`)."""
    polygons: tuple[Piece, ...] = ()
    """The given polygons, then each piece in the order the splits made them."""
    splits: tuple[Split, ...] = ()


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


def cut(face: Face, sides: Sequence[Number]) -> tuple[Face, Face, tuple[Vec, Vec]]:
    """The convex ``face`` cut where ``sides`` (each vertex's signed value on a plane, some
    positive and some negative) changes sign: the positive piece, the negative piece, and the
    two points of the cut, in the face's order. A crossing on the edge from ``V_i`` to ``V_j``
    is ``V_i + (V_j - V_i) d_i / (d_i - d_j)``.

    >>> cut(((0, 0, 0), (4, 0, 4), (0, 4, 0)), (-2, 2, -2))
    (((2, 0, 2), (4, 0, 4), (2, 2, 2)), ((0, 0, 0), (2, 0, 2), (2, 2, 2), (0, 4, 0)), ((2, 0, 2), (2, 2, 2)))
    """
    front: list[Vec] = []
    back: list[Vec] = []
    line: list[Vec] = []
    n = len(face)
    for i in range(n):
        v, d = face[i], sides[i]
        if d >= 0:
            front.append(v)
        if d <= 0:
            back.append(v)
        if d == 0:
            line.append(v)
        w, e = face[(i + 1) % n], sides[(i + 1) % n]
        if d * e < 0:
            t = Fraction(d) / (d - e)
            p: Vec = tuple(normalize(a + (b - a) * t) for a, b in zip(v, w, strict=True))  # type: ignore[assignment]
            front.append(p)
            back.append(p)
            line.append(p)
    return tuple(front), tuple(back), (line[0], line[1])


def _crosses(sides: Sequence[Number]) -> bool:
    return any(d > 0 for d in sides) and any(d < 0 for d in sides)


class _State:
    """The sort's working: the polygons so far, the list still to paint, the marks."""

    def __init__(self, polygons: Named, depth: str) -> None:
        self.depth = depth
        self.pieces = [Piece(n, f, i) for i, (n, f) in enumerate(polygons)]
        self.polys = [_Poly(f, check_plane(n, f), check_convex(n, f)) for n, f in polygons]
        self.order = sorted(range(len(self.polys)), key=self.farthest)
        self.marked: set[int] = set()
        self.splits: list[Split] = []

    def farthest(self, i: int) -> tuple[Fraction, int]:
        zs = [Fraction(v[2]) for v in self.polys[i].face]
        return (min(zs) if self.depth == "larger-nearer" else -max(zs), i)

    def sides(self, i: int, by: int) -> tuple[Number, ...]:
        return tuple(side(self.polys[by].plane, v, self.depth) for v in self.polys[i].face)

    def choose(self, s: int, t: int) -> tuple[int, int] | None:
        """Which polygon to split along whose plane: S' by S, else S by S', else the first
        of the list cut by another's plane."""
        pairs = [(t, s), (s, t)]
        pairs += [(i, j) for i in self.order for j in self.order if i != j]
        return next((p for p in pairs if _crosses(self.sides(*p))), None)

    def split(self, k: int, i: int, by: int) -> Split:
        if len(self.splits) == MAX_SPLITS:
            raise InputError(
                f"these polygons' cyclic overlaps need more than {MAX_SPLITS} splits; "
                f"the depth sort makes at most {MAX_SPLITS}"
            )
        sides = self.sides(i, by)
        front, back, line = cut(self.polys[i].face, sides)
        made = []
        for suffix, face in (("1", front), ("2", back)):
            name = f"{self.pieces[i].name}{suffix}"
            self.pieces.append(Piece(name, face, self.pieces[i].origin))
            self.polys.append(_Poly(face, self.polys[i].plane, check_convex(name, face)))
            made.append(len(self.polys) - 1)
        self.order.remove(i)
        for j in made:
            key = self.farthest(j)
            at = next((n for n, o in enumerate(self.order) if self.farthest(o) > key), None)
            self.order.insert(len(self.order) if at is None else at, j)
        self.marked.clear()
        done = Split(k, i, by, sides, line, (made[0], made[1]))
        self.splits.append(done)
        return done


def depth_sort(polygons: Named, knobs: Mapping[str, str] | None = None) -> DepthSort:
    """The depth sort of the polygons: the initial order, every pair's tests, the splits of
    any cyclic overlap, the painting order."""
    st = _State(polygons, {"depth": "larger-nearer", **(knobs or {})}["depth"])
    initial = tuple(st.order)
    tests: list[PairTest] = []
    painted: list[int] = []
    while st.order:
        s = st.order[0]
        for t in st.order[1:]:
            results = _tests(st.polys[s], st.polys[t], st.depth)
            passed = results[-1][0] if results[-1][1] else None
            cycle = passed is None and t in st.marked
            chosen = st.choose(s, t) if cycle else None
            split = None if chosen is None else len(st.splits)
            tests.append(PairTest(len(tests), s, t, results, passed, cycle, split))
            if chosen is not None:
                st.split(len(tests) - 1, *chosen)
                break
            if cycle:  # no plane cuts a polygon of the list: paint it in the list's order
                return _result(st, initial, tests, (*painted, *st.order))
            if passed is None:
                st.marked.add(t)
                st.order.remove(t)
                st.order.insert(0, t)
                break
        else:
            painted.append(st.order.pop(0))
    return _result(st, initial, tests, tuple(painted))


def _result(
    st: _State, initial: tuple[int, ...], tests: list[PairTest], painted: Sequence[int]
) -> DepthSort:
    cycle = any(t.cycle for t in tests)
    return DepthSort(
        initial, tuple(tests), tuple(painted), cycle, tuple(st.pieces), tuple(st.splits)
    )
