"""Weiler–Atherton polygon clipping: a subject polygon (concave allowed) against a clip polygon,
with exact intersections.

Both polygons are taken counter-clockwise (a clockwise one is reversed, and the answer says
so). Every crossing of a subject edge with a clip edge is inserted in both vertex lists, in
order along each edge, and labelled ``in`` (the subject enters the clip region there) or
``out`` (it leaves). The walk starts at an unvisited ``in`` point, follows the subject list to
the next ``out`` point, switches to the clip list and follows it to the next ``in`` point,
switches back, and so on until it returns to its start: one output polygon; it repeats while
an ``in`` point is unvisited.

Polygons that touch are clipped too: a vertex on the other polygon's edge, two vertices
together, edges along each other. Every point where the boundaries meet is inserted, and its
label is read from the subject's pieces on either side of it (each piece kept when its
midpoint is inside the clip polygon, or on its boundary running the same way): ``in`` where
the piece before is not kept and the one after is, ``out`` the other way round, ``touch``
where neither changes (the walk does not switch lists there). With no ``in`` point the answer
is the subject (inside the clip region), the clip polygon (inside the subject) or nothing.

References: K. Weiler and P. Atherton, "Hidden surface removal using polygon area sorting",
SIGGRAPH 1977; Hearn & Baker, *Computer Graphics*, C version, 2nd ed., §6-8.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .inside import on_segment, verdict

Point = tuple[Number, Number]

MAX_VERTICES = 64


class Entry(NamedTuple):
    """One entry of a vertex list: a vertex, or a crossing with its label and number."""

    point: Point
    label: str
    """``vertex``, ``in`` or ``out``."""
    crossing: int | None
    """The crossing's number (I1, I2, ...), shared by both lists; ``None`` for a vertex."""
    vertex: int | None = None
    """The polygon's vertex number (1, 2, ...) when the entry is one of its vertices (a
    vertex where the boundaries meet is a crossing too); ``None`` for a point inside an edge."""


class WAResult(NamedTuple):
    subject: tuple[Entry, ...]
    clip: tuple[Entry, ...]
    walks: tuple[tuple[str, ...], ...]
    """Each output polygon's walk, as names (``I1``, ``S2``, ``C3``, ...)."""
    polygons: tuple[tuple[Point, ...], ...]
    reversed: tuple[str, ...]
    """Which polygons were given clockwise and reversed."""


def _area2(pts: Sequence[Point]) -> Number:
    n = len(pts)
    return sum(
        (pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1] for i in range(n)),
        Fraction(0),
    )


def _ccw(pts: Sequence[Point], name: str) -> tuple[list[Point], bool]:
    if not 3 <= len(pts) <= MAX_VERTICES:
        raise InputError(f"the {name} polygon has 3 to {MAX_VERTICES} vertices", name)
    a = _area2(pts)
    if a == 0:
        raise InputError(f"the {name} polygon has no area", name)
    return (list(pts), False) if a > 0 else (list(reversed(pts)), True)


def _meet(a: Point, b: Point, c: Point, d: Point) -> list[tuple[Fraction, Fraction]]:
    """Where the segments ``ab`` and ``cd`` meet, as parameters ``(t, u)`` along each: one
    point for a crossing or a touch (an end on the other segment, two ends together), the
    two ends of the shared part where they overlap, none where they do not meet."""
    r = (b[0] - a[0], b[1] - a[1])
    s = (d[0] - c[0], d[1] - c[1])
    den = r[0] * s[1] - r[1] * s[0]
    qp = (c[0] - a[0], c[1] - a[1])
    if den != 0:
        t = Fraction(qp[0] * s[1] - qp[1] * s[0]) / den
        u = Fraction(qp[0] * r[1] - qp[1] * r[0]) / den
        return [(t, u)] if 0 <= t <= 1 and 0 <= u <= 1 else []
    if qp[0] * r[1] - qp[1] * r[0] != 0:
        return []  # parallel, apart
    tc, td = _proj(c, a, r), _proj(d, a, r)  # collinear: the shared part, if any
    lo, hi = max(Fraction(0), min(tc, td)), min(Fraction(1), max(tc, td))
    if lo > hi:
        return []
    return [(t, (t - tc) / (td - tc)) for t in sorted({lo, hi})]


def _proj(p: Point, a: Point, r: tuple[Number, Number]) -> Fraction:
    return Fraction((p[0] - a[0]) * r[0] + (p[1] - a[1]) * r[1]) / (r[0] * r[0] + r[1] * r[1])


def _at(a: Point, b: Point, t: Fraction) -> Point:
    return (normalize(a[0] + t * (b[0] - a[0])), normalize(a[1] + t * (b[1] - a[1])))


def _points(
    subject: list[Point], clip: list[Point]
) -> tuple[
    dict[Point, int], list[list[tuple[Fraction, Point]]], list[list[tuple[Fraction, Point]]]
]:
    """Every point where the two boundaries meet, numbered in the order found (each subject
    edge against each clip edge), and the points on each edge with their parameter."""
    ns, nc = len(subject), len(clip)
    number: dict[Point, int] = {}
    on_s: list[list[tuple[Fraction, Point]]] = [[] for _ in range(ns)]
    on_c: list[list[tuple[Fraction, Point]]] = [[] for _ in range(nc)]
    for i in range(ns):
        a, b = subject[i], subject[(i + 1) % ns]
        for j in range(nc):
            c, d = clip[j], clip[(j + 1) % nc]
            for t, u in _meet(a, b, c, d):
                p = _at(a, b, t)
                number.setdefault(p, len(number))
                on_s[i].append((t, p))
                on_c[j].append((u, p))
    return number, on_s, on_c


def _boundary_list(
    vertices: list[Point], on: list[list[tuple[Fraction, Point]]], number: dict[Point, int]
) -> list[tuple[Point, int | None, int | None]]:
    """A polygon's boundary in order: each vertex, then the meeting points inside its edge;
    a point where the boundaries meet carries its number (a vertex on the other polygon's
    boundary too)."""
    out: list[tuple[Point, int | None, int | None]] = []
    for i, v in enumerate(vertices):
        out.append((v, number.get(v), i + 1))
        nxt = vertices[(i + 1) % len(vertices)]
        for _, p in sorted(set(on[i])):
            if p not in (v, nxt):
                out.append((p, number[p], None))
    return out


def _kept(a: Point, b: Point, other: list[Point], shared: bool) -> bool:
    """Whether the piece ``a -> b`` of one boundary lies inside the other polygon; a piece
    along the other's boundary counts when ``shared`` and the two run the same way (the
    subject's pieces: a shared edge is the clipped polygon's once)."""
    m = (Fraction(a[0] + b[0]) / 2, Fraction(a[1] + b[1]) / 2)
    n = len(other)
    for j in range(n):
        c, d = other[j], other[(j + 1) % n]
        if on_segment(m, c, d):
            same = (b[0] - a[0]) * (d[0] - c[0]) + (b[1] - a[1]) * (d[1] - c[1]) > 0
            return shared and same
    return verdict(other, m).even_odd


def _lists(subject: list[Point], clip: list[Point]) -> tuple[list[Entry], list[Entry], int]:
    """Both vertex lists with the meeting points inserted and labelled: ``in`` where the
    subject's boundary enters the clipped polygon's, ``out`` where it leaves it, ``touch``
    where it meets the clip polygon without either (a vertex touching, an edge along)."""
    number, on_s, on_c = _points(subject, clip)
    s_pts = _boundary_list(subject, on_s, number)
    c_pts = _boundary_list(clip, on_c, number)
    n = len(s_pts)
    kept = [_kept(s_pts[k][0], s_pts[(k + 1) % n][0], clip, True) for k in range(n)]
    labels: dict[int, str] = {}
    for k, (_, c, _) in enumerate(s_pts):
        if c is not None:
            came, goes = kept[k - 1], kept[k]
            labels[c] = "in" if goes and not came else "out" if came and not goes else "touch"
    subject_list = [Entry(p, "vertex" if c is None else labels[c], c, v) for p, c, v in s_pts]
    clip_list = [Entry(p, "vertex" if c is None else labels[c], c, v) for p, c, v in c_pts]
    return subject_list, clip_list, len(number)


def _inside_parts(entries: list[Entry], other: list[Point], shared: bool) -> bool:
    n = len(entries)
    return any(_kept(entries[k].point, entries[(k + 1) % n].point, other, shared) for k in range(n))


def weiler_atherton(subject: Sequence[Point], clip: Sequence[Point]) -> WAResult:
    """Clip ``subject`` by ``clip``.

    >>> r = weiler_atherton([(1, 1), (5, 1), (5, 5), (3, 2), (1, 5)], [(0, 0), (6, 0), (6, 4), (0, 4)])
    >>> r.walks
    (('I2', 'S4', 'I3', 'I4', 'S1', 'S2', 'I1'),)
    """
    subj, rs = _ccw(subject, "subject")
    clp, rc = _ccw(clip, "clip")
    s_list, c_list, _ = _lists(subj, clp)
    flipped = tuple(n for n, r in (("subject", rs), ("clip", rc)) if r)
    if not any(e.label == "in" for e in s_list):  # the boundaries never cross
        if _inside_parts(s_list, clp, True):
            return WAResult(tuple(s_list), tuple(c_list), (), (tuple(subj),), flipped)
        if _inside_parts(c_list, subj, False):
            return WAResult(tuple(s_list), tuple(c_list), (), (tuple(clp),), flipped)
        return WAResult(tuple(s_list), tuple(c_list), (), (), flipped)
    where = {("s", e.crossing): i for i, e in enumerate(s_list) if e.crossing is not None} | {
        ("c", e.crossing): i for i, e in enumerate(c_list) if e.crossing is not None
    }
    names = _names(s_list, "S") | _names(c_list, "C")
    visited: set[int] = set()
    walks, polygons = [], []
    for e in s_list:
        if e.crossing is None or e.label != "in" or e.crossing in visited:
            continue
        walk, poly = _walk(e.crossing, s_list, c_list, where, names, visited)
        walks.append(tuple(walk))
        polygons.append(tuple(poly))
    return WAResult(tuple(s_list), tuple(c_list), tuple(walks), tuple(polygons), flipped)


def _names(entries: list[Entry], prefix: str) -> dict[tuple[str, int], str]:
    """Each entry's name in the walks: ``I1``, ``I2``, ... for a point where the boundaries
    meet, ``S3`` (``C3``) for the polygon's third vertex."""
    return {
        (prefix.lower(), i): f"{prefix}{e.vertex}" if e.crossing is None else f"I{e.crossing + 1}"
        for i, e in enumerate(entries)
    }


def _walk(
    start: int,
    s_list: list[Entry],
    c_list: list[Entry],
    where: dict[tuple[str, int], int],
    names: dict[tuple[str, int], str],
    visited: set[int],
) -> tuple[list[str], list[Point]]:
    """One output polygon: from the ``in`` crossing ``start`` along the subject; at an ``out``
    crossing onto the clip list, at an ``in`` crossing back onto the subject."""
    lists = {"s": s_list, "c": c_list}
    side, i = "s", where[("s", start)]
    walk: list[str] = []
    poly: list[Point] = []
    for _ in range(2 * (len(s_list) + len(c_list))):
        e = lists[side][i]
        if e.crossing is not None:
            if e.crossing == start and walk:
                return walk, poly
            visited.add(e.crossing)
        walk.append(names[(side, i)])
        poly.append(e.point)
        if e.crossing is not None and e.label == ("out" if side == "s" else "in"):
            side = "c" if side == "s" else "s"
            i = where[(side, e.crossing)]
        i = (i + 1) % len(lists[side])
    raise AssertionError("the walk did not close")  # pragma: no cover
