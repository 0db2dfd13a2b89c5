"""Nicholl–Lee–Nicholl line clipping against a closed rectangular window, with exact slopes.

The region of P1 is found first: inside the window, an edge region (beyond one edge: ``L``,
``R``, ``B`` or ``T``) or a corner region (beyond two: ``TL``, ``TR``, ``BL``, ``BR``). Then:

- **P1 outside.** If P2 is beyond one of the same edges, the segment is rejected. Otherwise the
  rays from P1 to the four window corners divide the plane, and P2's region is found by
  comparing the slope of P1P2 with the slopes of those rays: beyond the two outer rays the
  line misses the window (rejected); a corner region's nearest corner splits the entry edge
  (top or left, for ``TL``); the far corners split the exit edge. The region is named by the
  edges crossed (``LT``: in through the left edge, out through the top); when P2 is inside the
  window only the entry edge is named (``L``).
- **P1 inside.** If P2 is inside too, the segment is accepted whole. Otherwise, on P2's side
  (``x2 > x1``: the right; ``x2 < x1``: the left), the slope is compared with the rays to that
  side's two corners: the region ``T``, ``B`` or the side edge names the edge crossed.

Slopes: ``m = Δy/Δx`` when P1 is left or right of the window (every ray then has ``Δx`` of one
sign, so ``m`` orders the rays by angle); above or below it (an edge region ``T`` or ``B``)
the inverse slope ``m' = Δx/Δy``, for the same reason. This is Hearn & Baker's presentation
(P2's region from the slopes, then the crossings) worked for all nine regions in place,
without the rotations and reflections to the three canonical cases the original paper uses;
the comparisons are the same, measured in the given coordinates.

Ties: a line exactly along a corner ray passes through that corner, and either edge at the
corner gives the same point; the edge the line is not parallel to is used (so a line along the
top edge leaves through the right edge, never by dividing by a zero slope). The window is
closed, so a line touching only a corner is kept as that single point, as Liang–Barsky keeps
it (``tests/test_nll.py`` checks the two agree exactly on random lines).

References: T. M. Nicholl, D. T. Lee and R. A. Nicholl, "An efficient new algorithm for 2-D
line clipping: its development and analysis", *Computer Graphics* (SIGGRAPH '87) 21(4),
253-262, 1987; Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 6-7.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import NamedTuple

from ..core.numeric import Number, normalize
from .clipping import Edge, Point, Rect, boundary, crossing, region_code

CORNER_NAMES = ("TL", "TR", "BR", "BL")
EDGE_OF = {"L": Edge.LEFT, "R": Edge.RIGHT, "B": Edge.BOTTOM, "T": Edge.TOP}
EDGE_CORNERS = {"L": ("TL", "BL"), "T": ("TL", "TR"), "R": ("TR", "BR"), "B": ("BR", "BL")}
"""Each edge's two corners."""
REGION_NAMES = {
    "": "inside the window",
    "L": "the left edge region",
    "R": "the right edge region",
    "B": "the bottom edge region",
    "T": "the top edge region",
    "TL": "the top-left corner region",
    "TR": "the top-right corner region",
    "BL": "the bottom-left corner region",
    "BR": "the bottom-right corner region",
}


Value = Number | str
"""A compared value: a number, or a region code (``0110``)."""


class NLLTest(NamedTuple):
    """One comparison NLL makes, with its numbers: ``left relation right``."""

    k: int
    test: str
    """What is asked, in words (``P2 beyond the left edge too?``)."""
    left: str
    """The name of the left value: ``x2``, ``m``, ``m'``."""
    left_value: Value
    right: str
    """The name of the right value: ``xmin``, ``m_TR``."""
    right_value: Value
    relation: str
    """``<``, ``=`` or ``>`` (``=`` or ``≠`` for region codes)."""
    so: str
    """What the comparison decides."""


class Crossing(NamedTuple):
    """An intersection NLL computes: the segment meets ``edge`` at ``point``."""

    role: str
    """``entry`` or ``exit``."""
    edge: Edge
    point: Point


class NLLResult(NamedTuple):
    region1: str
    """P1's region: ``""`` (inside), an edge letter or a corner (``TL``)."""
    uses_inverse: bool
    """True when the slopes are ``Δx/Δy`` (P1 above or below the window)."""
    slopes: tuple[tuple[str, Number], ...]
    """The rays' slopes used, by corner name, and P2's (``P2``)."""
    tests: tuple[NLLTest, ...]
    region2: str
    """P2's region, named by the edges crossed (``LT``, ``L``), or ``""`` when rejected."""
    crossings: tuple[Crossing, ...]
    accepted: bool
    segment: tuple[Point, Point] | None


def point_region(p: Point, window: Rect) -> str:
    """``TL``, ``T``, ... or ``""`` (inside; the edges are inside).

    >>> point_region((30, 60), (10, 10, 50, 50)), point_region((0, 0), (10, 10, 50, 50))
    ('T', 'BL')
    """
    xmin, ymin, xmax, ymax = window
    v = "T" if p[1] > ymax else "B" if p[1] < ymin else ""
    h = "L" if p[0] < xmin else "R" if p[0] > xmax else ""
    return v + h


def _corners(window: Rect) -> dict[str, Point]:
    xmin, ymin, xmax, ymax = window
    return {"TL": (xmin, ymax), "TR": (xmax, ymax), "BR": (xmax, ymin), "BL": (xmin, ymin)}


def _parallel(p1: Point, p2: Point, edge: str) -> bool:
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    return dy == 0 if edge in "TB" else dx == 0


def _edge(c1: str, c2: str) -> str:
    """The edge between two corners."""
    return next(e for e, cs in EDGE_CORNERS.items() if set(cs) == {c1, c2})


def _cross(p1: Point, p2: Point, edge: str, window: Rect) -> Point:
    return crossing(p1, p2, EDGE_OF[edge], boundary(EDGE_OF[edge], window))


def _code(p: Point, window: Rect) -> str:
    return f"{region_code(p, window):04b}"


def nicholl_lee_nicholl(p1: Point, p2: Point, window: Rect) -> NLLResult:
    """NLL clipping of ``p1``–``p2`` against ``(xmin, ymin, xmax, ymax)``.

    The notes' past-paper line (Mumbai University), P1 in the top edge region:

    >>> r = nicholl_lee_nicholl((30, 60), (60, 25), (10, 10, 50, 50))
    >>> r.region1, r.region2, r.segment
    ('T', 'TR', ((Fraction(270, 7), 50), (50, Fraction(110, 3))))
    >>> [(t.left_value, t.relation, t.right, t.right_value) for t in r.tests][1:4]
    [(Fraction(-6, 7), '<', "m'_TL", 2), (Fraction(-6, 7), '>', "m'_TR", -2), (Fraction(-6, 7), '<', "m'_BL", Fraction(2, 5))]
    """
    region1 = point_region(p1, window)
    run = _Run(p1, p2, window)
    if not region1:
        return _from_inside(run)
    return _from_outside(run, region1)


class _Run:
    """The comparisons of one clipping, numbered as they are made."""

    def __init__(self, p1: Point, p2: Point, window: Rect) -> None:
        self.p1, self.p2, self.window = p1, p2, window
        self.tests: list[NLLTest] = []

    def test(self, test: str, left: tuple[str, Value], right: tuple[str, Value]) -> str:
        a, b = left[1], right[1]
        rel = (
            ("=" if a == b else "≠")
            if isinstance(a, str) or isinstance(b, str)
            else "<"
            if a < b
            else ">"
            if a > b
            else "="
        )
        self.tests.append(NLLTest(len(self.tests) + 1, test, left[0], a, right[0], b, rel, ""))
        return rel

    def so(self, text: str) -> None:
        """What the last comparison decided."""
        self.tests[-1] = self.tests[-1]._replace(so=text)

    def beyond(self, edge: str) -> bool:
        """Is P2 beyond ``edge``? (the comparison recorded)"""
        i, limit_name, out = {
            "L": (0, "xmin", "<"), "R": (0, "xmax", ">"), "B": (1, "ymin", "<"),
            "T": (1, "ymax", ">"),
        }[edge]  # fmt: skip
        limit = boundary(EDGE_OF[edge], self.window)
        rel = self.test(
            f"P2 beyond the {EDGE_OF[edge].value} edge?", (f"{'xy'[i]}2", self.p2[i]),
            (limit_name, limit),
        )  # fmt: skip
        self.so("yes" if rel == out else "no")
        return rel == out


def _from_inside(run: _Run) -> NLLResult:
    p1, p2, window = run.p1, run.p2, run.window
    code = _code(p2, window)
    run.test("P2 inside the window?", ("code(P2)", code), ("inside", "0000"))
    if code == "0000":
        run.so("yes: accepted whole")
        return NLLResult("", False, (), tuple(run.tests), "inside", (), True, (p1, p2))
    run.so("no: P2 is outside, one crossing")
    (x1, y1), (x2, y2) = p1, p2
    xmin, ymin, xmax, ymax = window
    slopes: tuple[tuple[str, Number], ...] = ()
    if x2 == x1:  # vertical: no slope, the direction decides
        edge = "T" if y2 > y1 else "B"
        run.test("vertical, going up?", ("y2", y2), ("y1", y1))
        run.so(f"P2 in region {edge}")
    else:
        side, top, bottom = ("R", "TR", "BR") if x2 > x1 else ("L", "TL", "BL")
        dx = (xmax if side == "R" else xmin) - x1
        m = normalize(Fraction(y2 - y1) / (x2 - x1))
        edge = side  # P1 on that edge, P2 beyond it: the line leaves at P1
        if dx != 0:
            m_top = normalize(Fraction(ymax - y1) / dx)
            m_bottom = normalize(Fraction(ymin - y1) / dx)
            slopes = (("P2", m), (top, m_top), (bottom, m_bottom))
            up = ">" if side == "R" else "<"  # steeper upward than the ray, on that side
            down = {"<": ">", ">": "<"}[up]
            if run.test(f"steeper up than the ray to {top}?", ("m", m), (f"m_{top}", m_top)) == up:
                edge = "T"
            else:
                run.so("no")
                bottom_ray = (f"m_{bottom}", m_bottom)
                if (
                    run.test(f"steeper down than the ray to {bottom}?", ("m", m), bottom_ray)
                    == down
                ):
                    edge = "B"
            run.so(f"P2 in region {edge}")
        else:
            slopes = (("P2", m),)
    point = _cross(p1, p2, edge, window)
    return NLLResult(
        "", False, slopes, tuple(run.tests), edge, (Crossing("exit", EDGE_OF[edge], point),),
        True, (p1, point),
    )  # fmt: skip


def _from_outside(run: _Run, region1: str) -> NLLResult:
    p1, p2, window = run.p1, run.p2, run.window
    for edge in region1:
        if run.beyond(edge):
            run.so(f"yes: P2 is beyond the {EDGE_OF[edge].value} edge too: rejected")
            return NLLResult(region1, False, (), tuple(run.tests), "", (), False, None)
    inverse = region1 in ("T", "B")
    name = "m'" if inverse else "m"

    def slope(q: Point) -> Number:
        dx, dy = q[0] - p1[0], q[1] - p1[1]
        return normalize(Fraction(dx) / dy if inverse else Fraction(dy) / dx)

    key = {c: slope(q) for c, q in _corners(window).items()}
    m = slope(p2)
    slopes = (("P2", m), *((c, key[c]) for c in CORNER_NAMES))

    def towards(c: str, sides: tuple[tuple[str, str], tuple[str, str]], what: str) -> str:
        """Compare with the ray to ``c``; ``sides``: ``(edge, a corner on its side)`` for the
        two edges at ``c``. On the ray itself, the edge the line is not parallel to."""
        run.test(f"{what} the ray to {c}?", (name, m), (f"{name}_{c}", key[c]))
        (e1, ref1), (e2, _) = sides
        if m == key[c]:
            return e2 if _parallel(p1, p2, e1) else e1
        return e1 if (m - key[c]) * (key[ref1] - key[c]) > 0 else e2

    near = region1 if len(region1) == 2 else None
    if near is None:
        a, b = EDGE_CORNERS[region1]
    else:
        a, b = (next(c for c in EDGE_CORNERS[e] if c != near) for e in region1)
    for c, other in ((a, b), (b, a)):
        run.test(f"outside the ray to {c}?", (name, m), (f"{name}_{c}", key[c]))
        if (m - key[c]) * (key[other] - key[c]) < 0:
            run.so("yes: the line misses the window: rejected")
            return NLLResult(region1, inverse, slopes, tuple(run.tests), "", (), False, None)
        run.so("no")
    if near is None:
        entry = region1
    else:
        e1, e2 = region1[0], region1[1]
        entry = towards(near, ((e1, a), (e2, b)), "which side of")
        run.so(f"enters through the {EDGE_OF[entry].value} edge")
    exit_edge = _exit(towards, run.so, a, b, near)
    run.so(f"leaves through the {EDGE_OF[exit_edge].value} edge")
    start = _cross(p1, p2, entry, window)
    crossings = [Crossing("entry", EDGE_OF[entry], start)]
    end = p2
    beyond = run.beyond(exit_edge)
    region2 = entry + exit_edge if beyond else entry
    run.so(f"{'yes' if beyond else 'no'}: P2 in region {region2}")
    if beyond:
        end = _cross(p1, p2, exit_edge, window)
        crossings.append(Crossing("exit", EDGE_OF[exit_edge], end))
    return NLLResult(
        region1, inverse, slopes, tuple(run.tests), region2, tuple(crossings), True,
        (start, end),
    )  # fmt: skip


def _exit(
    towards: Callable[..., str], so: Callable[[str], None], a: str, b: str, near: str | None
) -> str:
    """The exit edge, from the far corners: the ones not on the edges P1 is beyond."""
    if near is not None:
        f = next(c for c in CORNER_NAMES if c not in (near, a, b))
        return towards(f, ((_edge(a, f), a), (_edge(f, b), b)), "which side of")
    fa = next(c for c in CORNER_NAMES if c not in (a, b) and _is_edge(a, c))
    fb = next(c for c in CORNER_NAMES if c not in (a, b, fa))
    first = towards(fa, ((_edge(a, fa), a), (_edge(fa, fb), fb)), "which side of")
    if first == _edge(a, fa):
        return first
    so(f"not the {EDGE_OF[_edge(a, fa)].value} edge")
    return towards(fb, ((_edge(fb, b), b), (_edge(fa, fb), fa)), "which side of")


def _is_edge(c1: str, c2: str) -> bool:
    return any(set(cs) == {c1, c2} for cs in EDGE_CORNERS.values())
