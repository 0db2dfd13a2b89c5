"""Warnock's area subdivision on a square grid of 2^n pixels, in exact arithmetic (Hearn &
Baker, *Computer Graphics, C version*, 2nd ed., §13-7).

A window is a square of pixels; as a region of the plane it is the pixels' squares, each
pixel centred on its integer point (``[x0 - 1/2, x0 + s - 1/2]`` across). Each polygon
(convex, planar, projected orthographically onto xy) is, with respect to a window:
``surrounding`` (it holds the whole window), ``intersecting`` (it crosses the window's
boundary), ``contained`` (it lies inside the window) or ``disjoint`` (it meets no interior
point of it). The tests, in order:

1. every polygon disjoint: the window is the background;
2. one polygon not disjoint: the window shows it, on the pixels whose centres it covers
   (all of them when it surrounds the window);
3. a surrounding polygon nearer than every other one over the whole window (its farthest
   depth at the window's corners nearer than each other's nearest: the depths are planes,
   so their extremes over the square are at its corners): the window shows it;
4. a window of one pixel: the polygon nearest at the pixel's centre (``depth`` and
   ``ties`` conventions, as the z-buffer's);
5. otherwise the window is divided into four: 1 top left, 2 top right, 3 bottom left,
   4 bottom right (y up).

>>> polys = (("A", ((0, 0, 1), (4, 0, 1), (0, 4, 1))), ("B", ((0, 0, 2), (2, 0, 2), (0, 2, 2))))
>>> [(w.label, w.decision) for w in warnock(polys, 4)][:3]
[('W', 'subdivide'), ('W1', 'subdivide'), ('W11', 'one')]
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from .polygon import fill_pixels
from .visible import Face, Plane
from .visible_zbuffer import MAX_SIDE, Named, check_plane, depth_at, nearer

CLASSES = ("surrounding", "intersecting", "contained", "disjoint")
"""A polygon's relation to a window (Hearn & Baker's surrounding, overlapping, inside and
outside surfaces)."""

DECISIONS = {
    "background": "every polygon disjoint: background",
    "one": "one polygon meets the window: it is shown where it covers the pixels",
    "obscures": "a surrounding polygon is nearer than every other over the window: it is shown",
    "pixel": "one pixel: the polygon nearest at its centre",
    "subdivide": "none of the tests decides: divide into four",
}
"""What each decision means, as an answer states it."""

Pt = tuple[Fraction, Fraction]


def _cross(o: Pt, a: Pt, b: Pt) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def check_convex(name: str, face: Face) -> tuple[Pt, ...]:
    """The polygon's projection counter-clockwise; :class:`InputError` if it is not convex."""
    pts = [(Fraction(v[0]), Fraction(v[1])) for v in face]
    n = len(pts)
    turns = {(_cross(pts[i], pts[(i + 1) % n], pts[(i + 2) % n]) > 0) for i in range(n)
             if _cross(pts[i], pts[(i + 1) % n], pts[(i + 2) % n]) != 0}  # fmt: skip
    if len(turns) > 1:
        raise InputError(f"polygon {name} is not convex: Warnock's tests here take convex polygons")
    if turns == {False}:
        pts.reverse()
    return tuple(pts)


class Window(NamedTuple):
    """One window: a row of the table."""

    k: int
    label: str
    """``W``, its quadrants ``W1`` to ``W4``, theirs ``W11`` ... (the quadtree's path)."""
    x0: int
    y0: int
    size: int
    classes: tuple[str, ...]
    """Each polygon's class, in order."""
    decision: str
    """A key of :data:`DECISIONS`."""
    shown: int | None
    """The polygon the window shows (``one``, ``obscures``, ``pixel``); ``None``: background
    or subdivided."""
    depths: tuple[tuple[int, Number], ...] = ()
    """``pixel``: each covering polygon's depth at the centre; ``obscures``: the surrounding
    polygon's farthest and the others' nearest corner depths."""


def _corners(x0: int, y0: int, s: int) -> tuple[Pt, ...]:
    h = Fraction(1, 2)
    lo_x, lo_y, hi_x, hi_y = x0 - h, y0 - h, x0 + s - h, y0 + s - h
    return ((lo_x, lo_y), (hi_x, lo_y), (hi_x, hi_y), (lo_x, hi_y))


def classify(poly: Sequence[Pt], corners: Sequence[Pt]) -> str:
    """The polygon's class against the window whose corners are given (both convex,
    counter-clockwise)."""
    lo_x, lo_y = corners[0]
    hi_x, hi_y = corners[2]
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    if max(xs) <= lo_x or min(xs) >= hi_x or max(ys) <= lo_y or min(ys) >= hi_y:
        return "disjoint"
    n = len(poly)
    for i in range(n):  # an edge of the polygon with every corner on its outer side
        a, b = poly[i], poly[(i + 1) % n]
        if all(_cross(a, b, c) <= 0 for c in corners):
            return "disjoint"
    if all(all(_cross(poly[i], poly[(i + 1) % n], c) >= 0 for i in range(n)) for c in corners):
        return "surrounding"
    if all(lo_x <= x <= hi_x for x in xs) and all(lo_y <= y <= hi_y for y in ys):
        return "contained"
    return "intersecting"


def _farthest(p: Plane, corners: Sequence[Pt], depth: str, far: bool) -> Number:
    zs = [depth_at(p, c[0], c[1]) for c in corners]
    pick_min = (depth == "larger-nearer") == far
    return normalize(min(zs) if pick_min else max(zs))


class _Scene(NamedTuple):
    polys: tuple[tuple[Pt, ...], ...]
    planes: tuple[Plane, ...]
    pixels: tuple[frozenset[tuple[int, int]], ...]
    knobs: Mapping[str, str]


def _decide(
    scene: _Scene, x0: int, y0: int, s: int, classes: tuple[str, ...]
) -> tuple[str, int | None, tuple[tuple[int, Number], ...]]:
    met = [i for i, c in enumerate(classes) if c != "disjoint"]
    depth = scene.knobs["depth"]
    if not met:
        return "background", None, ()
    if len(met) == 1:
        return "one", met[0], ()
    corners = _corners(x0, y0, s)
    for i in met:
        if classes[i] != "surrounding":
            continue
        mine = _farthest(scene.planes[i], corners, depth, far=True)
        theirs = [(j, _farthest(scene.planes[j], corners, depth, far=False)) for j in met if j != i]
        if all(nearer(mine, z, depth, "keep") and mine != z for _, z in theirs):
            return "obscures", i, ((i, mine), *theirs)
    if s == 1:
        best: tuple[int, Number] | None = None
        depths = []
        for i in met:
            if (x0, y0) not in scene.pixels[i]:
                continue
            z = depth_at(scene.planes[i], x0, y0)
            depths.append((i, z))
            if best is None or nearer(z, best[1], depth, scene.knobs["ties"]):
                best = (i, z)
        return "pixel", None if best is None else best[0], tuple(depths)
    return "subdivide", None, ()


def warnock(polygons: Named, size: int, knobs: Mapping[str, str] | None = None) -> Iterator[Window]:
    """The windows, depth first from the whole grid (``size`` a power of two)."""
    k = {"depth": "larger-nearer", "ties": "keep", **(knobs or {})}
    if size < 1 or size > MAX_SIDE or size & (size - 1):
        raise InputError(
            f"Warnock's grid is 2^n pixels square, 1 to {MAX_SIDE}; got {size}", "size"
        )
    scene = _Scene(
        tuple(check_convex(n, f) for n, f in polygons),
        tuple(check_plane(n, f) for n, f in polygons),
        tuple(frozenset(fill_pixels([(v[0], v[1]) for v in f])) for _, f in polygons),
        k,
    )
    count = 0
    stack = [("W", 0, 0, size)]
    while stack:
        label, x0, y0, s = stack.pop()
        corners = _corners(x0, y0, s)
        classes = tuple(classify(p, corners) for p in scene.polys)
        decision, shown, depths = _decide(scene, x0, y0, s, classes)
        yield Window(count, label, x0, y0, s, classes, decision, shown, depths)
        count += 1
        if decision == "subdivide":
            h = s // 2
            quads = ((1, x0, y0 + h), (2, x0 + h, y0 + h), (3, x0, y0), (4, x0 + h, y0))
            stack.extend((f"{label}{q}", x, y, h) for q, x, y in reversed(quads))


def frame_of(
    windows: Sequence[Window], pixels: Sequence[frozenset[tuple[int, int]]]
) -> dict[tuple[int, int], int]:
    """The final frame buffer: pixel to polygon index (the background left out)."""
    frame: dict[tuple[int, int], int] = {}
    for w in windows:
        if w.shown is None:
            continue
        for x in range(w.x0, w.x0 + w.size):
            for y in range(w.y0, w.y0 + w.size):
                if w.decision != "one" or (x, y) in pixels[w.shown]:
                    frame[(x, y)] = w.shown
    return frame
