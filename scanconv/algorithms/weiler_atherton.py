"""Weiler–Atherton polygon clipping: a subject polygon (concave allowed) against a clip polygon,
with exact intersections.

Both polygons are taken counter-clockwise (a clockwise one is reversed, and the answer says
so). Every crossing of a subject edge with a clip edge is inserted in both vertex lists, in
order along each edge, and labelled ``in`` (the subject enters the clip region there) or
``out`` (it leaves). The walk starts at an unvisited ``in`` point, follows the subject list to
the next ``out`` point, switches to the clip list and follows it to the next ``in`` point,
switches back, and so on until it returns to its start: one output polygon; it repeats while
an ``in`` point is unvisited.

A crossing exactly at a vertex, or edges that overlap, make the labels ambiguous; they are
refused with a line naming the point (move the polygon by a fraction to answer). With no
crossing the answer is the subject (inside the clip region), the clip polygon (inside the
subject) or nothing.

References: K. Weiler and P. Atherton, "Hidden surface removal using polygon area sorting",
SIGGRAPH 1977; Hearn & Baker, *Computer Graphics*, C version, 2nd ed., §6-8.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .inside import verdict

Point = tuple[Number, Number]

MAX_VERTICES = 64


class Entry(NamedTuple):
    """One entry of a vertex list: a vertex, or a crossing with its label and number."""

    point: Point
    label: str
    """``vertex``, ``in`` or ``out``."""
    crossing: int | None
    """The crossing's number (I1, I2, ...), shared by both lists; ``None`` for a vertex."""


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


def _cross(a: Point, b: Point, c: Point, d: Point) -> tuple[Fraction, Fraction] | None:
    """The parameters ``(t, u)`` where ``ab`` meets ``cd`` inside both (``None`` if they do
    not); an :class:`InputError` for a touching or overlapping case."""
    r = (b[0] - a[0], b[1] - a[1])
    s = (d[0] - c[0], d[1] - c[1])
    den = r[0] * s[1] - r[1] * s[0]
    qp = (c[0] - a[0], c[1] - a[1])
    if den == 0:
        if qp[0] * r[1] - qp[1] * r[0] == 0:  # collinear: overlap or touch
            lo, hi = sorted((_proj(c, a, r), _proj(d, a, r)))
            if hi > 0 and lo < 1:
                raise InputError(f"edges overlap along {_show(a)}-{_show(b)}", "subject")
            if hi == 0 or lo == 1:
                touch = a if hi == 0 else b
                raise InputError(
                    f"the polygons cross at a vertex, {_show(touch)}: move one slightly", "subject"
                )
        return None
    t = Fraction(qp[0] * s[1] - qp[1] * s[0]) / den
    u = Fraction(qp[0] * r[1] - qp[1] * r[0]) / den
    if not (0 <= t <= 1 and 0 <= u <= 1):
        return None
    if t in (0, 1) or u in (0, 1):
        p = (normalize(a[0] + t * r[0]), normalize(a[1] + t * r[1]))
        raise InputError(
            f"the polygons cross at a vertex, {_show(p)}: move one slightly", "subject"
        )
    return t, u


def _proj(p: Point, a: Point, r: tuple[Number, Number]) -> Fraction:
    return Fraction((p[0] - a[0]) * r[0] + (p[1] - a[1]) * r[1]) / (r[0] * r[0] + r[1] * r[1])


def _show(p: Point) -> str:
    return f"({normalize(p[0])}, {normalize(p[1])})"


def _lists(subject: list[Point], clip: list[Point]) -> tuple[list[Entry], list[Entry], int]:
    """Both vertex lists with the crossings inserted and labelled."""
    ns, nc = len(subject), len(clip)
    on_subject: list[list[tuple[Fraction, Point, int]]] = [[] for _ in range(ns)]
    on_clip: list[list[tuple[Fraction, Point, int]]] = [[] for _ in range(nc)]
    count = 0
    for i in range(ns):
        a, b = subject[i], subject[(i + 1) % ns]
        for j in range(nc):
            hit = _cross(a, b, clip[j], clip[(j + 1) % nc])
            if hit is not None:
                t, u = hit
                p = (normalize(a[0] + t * (b[0] - a[0])), normalize(a[1] + t * (b[1] - a[1])))
                on_subject[i].append((t, p, count))
                on_clip[j].append((u, p, count))
                count += 1
    labels: dict[int, str] = {}
    subject_list: list[Entry] = []
    for i in range(ns):
        start_inside = verdict(clip, subject[i]).even_odd
        subject_list.append(Entry(subject[i], "vertex", None))
        inside = start_inside
        for _, p, c in sorted(on_subject[i]):
            labels[c] = "out" if inside else "in"
            inside = not inside
            subject_list.append(Entry(p, labels[c], c))
    clip_list: list[Entry] = []
    for j in range(nc):
        clip_list.append(Entry(clip[j], "vertex", None))
        clip_list.extend(Entry(p, labels[c], c) for _, p, c in sorted(on_clip[j]))
    return subject_list, clip_list, count


def weiler_atherton(subject: Sequence[Point], clip: Sequence[Point]) -> WAResult:
    """Clip ``subject`` by ``clip``.

    >>> r = weiler_atherton([(1, 1), (5, 1), (5, 5), (3, 2), (1, 5)], [(0, 0), (6, 0), (6, 4), (0, 4)])
    >>> r.walks
    (('I2', 'S4', 'I3', 'I4', 'S1', 'S2', 'I1'),)
    """
    subj, rs = _ccw(subject, "subject")
    clp, rc = _ccw(clip, "clip")
    s_list, c_list, count = _lists(subj, clp)
    flipped = tuple(n for n, r in (("subject", rs), ("clip", rc)) if r)
    if count == 0:
        if verdict(clp, subj[0]).even_odd:
            return WAResult(tuple(s_list), tuple(c_list), (), (tuple(subj),), flipped)
        if verdict(subj, clp[0]).even_odd:
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
    out, n = {}, 0
    for i, e in enumerate(entries):
        if e.crossing is None:
            n += 1
            out[(prefix.lower(), i)] = f"{prefix}{n}"
        else:
            out[(prefix.lower(), i)] = f"I{e.crossing + 1}"
    return out


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
        if e.crossing is not None and (e.label == "out") == (side == "s"):
            side = "c" if side == "s" else "s"
            i = where[(side, e.crossing)]
        i = (i + 1) % len(lists[side])
    raise AssertionError("the walk did not close")  # pragma: no cover
