"""Anti-aliasing by unweighted area sampling and by uniform supersampling.

A pixel ``(i, j)`` is the unit square ``[i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]`` (centres on
integers, as in :mod:`scanconv.algorithms.polygon`). Its intensity is the part of it the shape
covers:

* **area sampling** (unweighted): the exact covered area. For a polygon (and a line, drawn as
  a polygon) the filled region is cut into trapezoids between consecutive *events* (vertex
  y's, the y's where two edges cross, and the pixel rows' boundaries ``j + 1/2``); each
  trapezoid is clipped to each pixel column exactly, with fractions. Between two events the
  edges keep their order, so the fill rule (even-odd or nonzero) picks the trapezoids and a
  self-intersecting polygon is measured correctly. A circle's ring involves arcsin: its areas
  are computed in floating point from the closed form, the only inexact values here.
* **supersampling**: ``N x N`` samples per pixel, at the centres of an ``N x N`` subdivision;
  the intensity is the fraction inside (exact). A polygon's samples use the scan-line rule of
  :func:`~scanconv.algorithms.polygon.spans_at`, so ``N = 1`` gives exactly the scan-line fill.

A line of width one pixel is the parallelogram one pixel thick along the minor axis (see
:func:`line_strip`): its area is exact, and every column of an x-major line is covered by
exactly 1 in total, as in Wu's algorithm.

References
----------
Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 4-8 (antialiasing:
supersampling, area sampling); Foley et al., *Computer Graphics: Principles and Practice*, 2nd
ed., section 3.17 (unweighted area sampling).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from fractions import Fraction
from itertools import pairwise

from ..core.checks import InputError, check_count
from ..core.numeric import Number, normalize, round_half_up
from ..core.records import Pixel
from .polygon import Edge, Point, check_polygon, check_rule, edge_table, fill_rule, spans_at

MAX_SAMPLES = 16
"""Largest N of N x N supersampling (256 samples per pixel)."""

MAX_AA_CELLS = 10_000
"""Largest pixel bounding box (columns x rows) of an anti-aliased shape: one row per pixel."""

HALF = Fraction(1, 2)


def check_samples(n: int) -> int:
    """``n`` if ``1 <= n <= MAX_SAMPLES``, else :class:`InputError`."""
    return check_count(n, "samples per pixel side N", 1, MAX_SAMPLES, param="samples")


def check_cells(xmin: Number, ymin: Number, xmax: Number, ymax: Number) -> tuple[int, ...]:
    """The pixel box ``(i0, j0, i1, j1)`` that can meet the region ``[xmin, xmax] x [ymin,
    ymax]``, refused beyond :data:`MAX_AA_CELLS`.

    >>> check_cells(0, 0, 4, Fraction(5, 2))
    (0, 0, 4, 3)
    """
    i0, i1 = round_half_up(xmin), round_half_up(xmax)
    j0, j1 = round_half_up(ymin), round_half_up(ymax)
    cells = (i1 - i0 + 1) * (j1 - j0 + 1)
    if cells > MAX_AA_CELLS:
        raise InputError(
            f"the shape covers {cells:,} pixel cells; at most {MAX_AA_CELLS:,} are anti-aliased",
            "shape",
        )
    return i0, j0, i1, j1


def quantize(intensity: Number | float, levels: int) -> int:
    """The level ``round_half_up(I (L - 1))`` of an intensity ``0 <= I <= 1``.

    >>> quantize(Fraction(1, 2), 8), quantize(Fraction(1, 4), 8)
    (4, 2)
    """
    return round_half_up(Fraction(intensity) * (levels - 1))


ACROSS = {
    "minor": "the strip w thick along the minor axis (y when |dy| <= |dx|), ends cut along it "
    "at the end points: a parallelogram of area w·max(|dx|, |dy|), each column covered by w",
    "perpendicular": "the rectangle w wide measured perpendicular to the line, ends cut square "
    "at the end points: area w·L, L = sqrt(dx² + dy²)",
}
"""How a line's width is measured (the ``across`` convention), the default first."""


def exact_sqrt(v: Number) -> Fraction | None:
    """``sqrt(v)`` if it is rational, else ``None``.

    >>> exact_sqrt(Fraction(25, 4)), exact_sqrt(2)
    (Fraction(5, 2), None)
    """
    q = Fraction(v)
    n, d = math.isqrt(q.numerator), math.isqrt(q.denominator)
    return Fraction(n, d) if n * n == q.numerator and d * d == q.denominator else None


def line_strip(
    x1: Number, y1: Number, x2: Number, y2: Number, width: Number = 1, across: str = "minor"
) -> tuple[Point, ...]:
    """The line of width ``width`` as a polygon: ``across="minor"`` (the default) thickens the
    segment by w/2 on each side along the minor axis (y when ``|Δy| <= |Δx|``), ending at the
    end points; ``"perpendicular"`` by w/2 on each side along the line's unit normal. Where
    ``sqrt(Δx² + Δy²)`` is irrational the normal's corners are the nearest doubles, as exact
    fractions (:func:`exact_sqrt` says which).

    >>> line_strip(0, 0, 4, 1)
    ((0, Fraction(-1, 2)), (4, Fraction(1, 2)), (4, Fraction(3, 2)), (0, Fraction(1, 2)))
    >>> line_strip(0, 0, 4, 3, 1, "perpendicular")
    ((Fraction(3, 10), Fraction(-2, 5)), (Fraction(43, 10), Fraction(13, 5)), (Fraction(37, 10), Fraction(17, 5)), (Fraction(-3, 10), Fraction(2, 5)))
    """
    if (x1, y1) == (x2, y2):
        raise InputError("a line of length zero covers no area", "line")
    if across not in ACROSS:
        raise InputError(f"unknown across {across!r} (choose from {', '.join(ACROSS)})", "across")
    if not width > 0:
        raise InputError(f"the line width must be positive, got {width}", "width")
    half = Fraction(width) / 2
    dx, dy = Fraction(x2 - x1), Fraction(y2 - y1)
    pts: tuple[tuple[Number, Number], ...]
    if across == "perpendicular":
        length = exact_sqrt(dx * dx + dy * dy)
        if length is None:
            inv = Fraction(1 / math.sqrt(float(dx * dx + dy * dy)))
            nx, ny = -dy * half * inv, dx * half * inv
        else:
            nx, ny = -dy * half / length, dx * half / length
        pts = ((x1 - nx, y1 - ny), (x2 - nx, y2 - ny), (x2 + nx, y2 + ny), (x1 + nx, y1 + ny))
    elif abs(dy) <= abs(dx):
        pts = ((x1, y1 - half), (x2, y2 - half), (x2, y2 + half), (x1, y1 + half))
    else:
        pts = ((x1 + half, y1), (x2 + half, y2), (x2 - half, y2), (x1 - half, y1))
    return tuple((normalize(x), normalize(y)) for x, y in pts)


# --- exact area of a polygon's filled region ---------------------------------------------


def _crossing_ys(edges: Sequence[Edge]) -> set[Number]:
    """The y's strictly inside two edges' common y range where they cross."""
    out: set[Number] = set()
    for a_i, a in enumerate(edges):
        for b in edges[a_i + 1 :]:
            lo, hi = max(a.y_min, b.y_min), min(a.y_max, b.y_max)
            if lo >= hi or a.inv_m == b.inv_m:
                continue
            da, db = a.x_at(lo) - b.x_at(lo), a.x_at(hi) - b.x_at(hi)
            if (da < 0 < db) or (db < 0 < da):
                out.add(normalize(lo + (hi - lo) * Fraction(da) / (da - db)))
    return out


def _under(c: Number, h: Number, xa: Number, xb: Number) -> Fraction:
    """``∫ min(c, x(y)) dy`` over a band of height h where x runs linearly from xa to xb."""
    if xa <= c and xb <= c:
        return h * Fraction(xa + xb) / 2
    if xa >= c and xb >= c:
        return Fraction(h * c)
    t = Fraction(c - xa) / (xb - xa)
    first = h * t * (Fraction(xa + c) / 2 if xa < c else c)
    second = h * (1 - t) * (Fraction(c + xb) / 2 if xb < c else c)
    return first + second


def _trapezoids(
    vertices: Sequence[Point], rule: str, rows: bool
) -> Iterator[tuple[Number, Number, tuple[Number, Number], tuple[Number, Number]]]:
    """``(y_a, y_b, left, right)`` trapezoids of the filled region: ``left`` and ``right`` are
    ``(x at y_a, x at y_b)``. With ``rows`` the bands also stop at every ``j + 1/2``."""
    alternates = fill_rule(rule).alternates
    edges, _ = edge_table(vertices)
    ys: set[Number] = {e.y_min for e in edges} | {e.y_max for e in edges} | _crossing_ys(edges)
    if rows:
        lo, hi = min(ys), max(ys)
        ys |= {normalize(j + HALF) for j in range(math.floor(lo - HALF), math.ceil(hi))}
        ys = {y for y in ys if lo <= y <= hi}
    events = sorted(ys)
    for ya, yb in pairwise(events):
        mid = (Fraction(ya) + yb) / 2
        active = [e for e in edges if e.y_min <= ya and e.y_max >= yb]
        active.sort(key=lambda e: e.x_at(mid))
        winding, inside_from = 0, None
        for n, e in enumerate(active):
            before = winding
            winding = (n + 1) % 2 if alternates else winding + e.direction
            if before == 0 and winding != 0:
                inside_from = e
            elif before != 0 and winding == 0 and inside_from is not None:
                yield ya, yb, (inside_from.x_at(ya), inside_from.x_at(yb)), (e.x_at(ya), e.x_at(yb))


def region_area(vertices: Sequence[Sequence[Number]], rule: str = "even-odd") -> Number:
    """The exact area the rule fills (the absolute shoelace area for a simple polygon).

    >>> region_area([(0, 0), (4, 0), (0, 4), (4, 4)])   # a bow tie: two triangles of area 4
    8
    """
    check_rule(rule)
    pts, _ = check_polygon(vertices)
    total = Fraction(0)
    for ya, yb, (la, lb), (ra, rb) in _trapezoids(pts, rule, rows=False):
        total += (yb - ya) * Fraction(ra + rb - la - lb) / 2
    return normalize(total)


def area_coverage(
    vertices: Sequence[Sequence[Number]], rule: str = "even-odd"
) -> dict[Pixel, Number]:
    """Each pixel's exactly covered area (unweighted area sampling); pixels with none left out.

    >>> cov = area_coverage([(0, 0), (2, 0), (2, 1), (0, 1)])
    >>> [(p, str(v)) for p, v in sorted(cov.items())]
    [((0, 0), '1/4'), ((0, 1), '1/4'), ((1, 0), '1/2'), ((1, 1), '1/2'), ((2, 0), '1/4'), ((2, 1), '1/4')]
    """
    check_rule(rule)
    pts, _ = check_polygon(vertices)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    check_cells(min(xs), min(ys), max(xs), max(ys))
    cov: dict[Pixel, Fraction] = {}
    for ya, yb, (la, lb), (ra, rb) in _trapezoids(pts, rule, rows=True):
        h = yb - ya
        j = round_half_up((Fraction(ya) + yb) / 2)
        lo, hi = min(la, lb), max(ra, rb)
        prev = _under(round_half_up(lo) - HALF, h, ra, rb) - _under(
            round_half_up(lo) - HALF, h, la, lb
        )
        for i in range(round_half_up(lo), math.floor(hi + HALF) + 1):
            c = i + HALF
            now = _under(c, h, ra, rb) - _under(c, h, la, lb)
            if now != prev:
                cov[(i, j)] = cov.get((i, j), Fraction(0)) + now - prev
            prev = now
    return {p: normalize(v) for p, v in sorted(cov.items(), key=lambda t: (t[0][1], t[0][0])) if v}


def supersample_coverage(
    vertices: Sequence[Sequence[Number]], n: int, rule: str = "even-odd"
) -> dict[Pixel, Number]:
    """The fraction of each pixel's ``n x n`` sample points inside (the scan-line rule).

    >>> cov = supersample_coverage([(0, 0), (2, 0), (2, 1), (0, 1)], 2)
    >>> [(p, str(v)) for p, v in sorted(cov.items())]
    [((0, 0), '1/4'), ((0, 1), '1/4'), ((1, 0), '1/2'), ((1, 1), '1/2'), ((2, 0), '1/4'), ((2, 1), '1/4')]
    """
    check_rule(rule)
    check_samples(n)
    pts, _ = check_polygon(vertices)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    _, j0, _, j1 = check_cells(min(xs), min(ys), max(xs), max(ys))
    edges, _ = edge_table(pts)
    counts: dict[Pixel, int] = {}
    for m in range(j0 * n, (j1 + 1) * n):
        y = Fraction(2 * m + 1, 2 * n) - HALF
        j = m // n
        for xa, xb in spans_at(edges, y, rule):
            k0 = math.ceil((n * (2 * Fraction(xa) + 1) - 1) / 2)
            k1 = math.ceil((n * (2 * Fraction(xb) + 1) - 1) / 2) - 1
            for i in range(k0 // n, k1 // n + 1):
                got = min(k1, i * n + n - 1) - max(k0, i * n) + 1
                if got > 0:
                    counts[(i, j)] = counts.get((i, j), 0) + got
    return {
        p: normalize(Fraction(c, n * n))
        for p, c in sorted(counts.items(), key=lambda t: (t[0][1], t[0][0]))
    }


# --- a circle drawn one pixel wide: the ring r - 1/2 <= d <= r + 1/2 ----------------------


def _disk_rect(big: float, x0: float, x1: float, y0: float, y1: float) -> float:
    """Area of the disk of radius ``big`` (centre 0) inside ``[x0, x1] x [y0, y1]``, from the
    closed form ``∫ sqrt(R² - x²) dx = (x sqrt(R² - x²) + R² asin(x / R)) / 2``."""
    if big <= 0:
        return 0.0
    r2 = big * big

    def s(x: float) -> float:
        return math.sqrt(max(r2 - x * x, 0.0))

    def prim(x: float) -> float:
        x = min(max(x, -big), big)
        return (x * s(x) + r2 * math.asin(x / big)) / 2

    cuts = {x0, x1, -big, big}
    for y in (y0, y1):
        if abs(y) <= big:
            cuts |= {s(y), -s(y)}
    pts = sorted(c for c in cuts if x0 <= c <= x1)
    total = 0.0
    for a, b in pairwise(pts):
        m = (a + b) / 2
        if abs(m) >= big:
            continue
        top_s, bot_s = s(m) < y1, -s(m) > y0
        hi = prim(b) - prim(a) if top_s else y1 * (b - a)
        lo = -(prim(b) - prim(a)) if bot_s else y0 * (b - a)
        if (s(m) if top_s else y1) > (-s(m) if bot_s else y0):
            total += hi - lo
    return total


def ring_area(r: int, xc: int = 0, yc: int = 0) -> dict[Pixel, float]:
    """Each pixel's area inside the ring ``r - 1/2 <= d <= r + 1/2`` around ``(xc, yc)``
    (floating point: the closed form has arcsin); pixels with none left out.

    >>> cov = ring_area(1)
    >>> round(sum(cov.values()), 12) == round(2 * math.pi, 12)
    True
    """
    check_cells(xc - r - 1, yc - r - 1, xc + r + 1, yc + r + 1)
    out: dict[Pixel, float] = {}
    outer, inner = r + 0.5, max(r - 0.5, 0.0)
    for j in range(-r - 1, r + 2):
        for i in range(-r - 1, r + 2):
            box = (i - 0.5, i + 0.5, j - 0.5, j + 0.5)
            a = _disk_rect(outer, *box) - _disk_rect(inner, *box)
            if a > 1e-12:
                out[(xc + i, yc + j)] = min(a, 1.0)
    return out


def ring_supersample(r: int, n: int, xc: int = 0, yc: int = 0) -> dict[Pixel, Number]:
    """The fraction of each pixel's ``n x n`` samples with ``(r - 1/2)² <= d² < (r + 1/2)²``.

    >>> ring_supersample(1, 1)[(1, 0)], (0, 0) in ring_supersample(1, 1)
    (1, False)
    """
    check_samples(n)
    check_cells(xc - r - 1, yc - r - 1, xc + r + 1, yc + r + 1)
    lo, hi = (r - HALF) ** 2, (r + HALF) ** 2
    offsets = [Fraction(2 * a + 1, 2 * n) - HALF for a in range(n)]
    out: dict[Pixel, Number] = {}
    for j in range(-r - 1, r + 2):
        for i in range(-r - 1, r + 2):
            inside = sum(
                1 for dy in offsets for dx in offsets if lo <= (i + dx) ** 2 + (j + dy) ** 2 < hi
            )
            if inside:
                out[(xc + i, yc + j)] = normalize(Fraction(inside, n * n))
    return out
