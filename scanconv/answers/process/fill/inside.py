"""The worked answer of the inside–outside test: for each point, every edge against the ray
toward +x (straddles? where it meets the ray's line, a crossing? its sign), then the even–odd
count and the winding number, from :mod:`scanconv.algorithms.inside`."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Any, NamedTuple

from ....algorithms import inside as io
from ....algorithms.polygon import check_polygon, vertices_from_coords
from ....core.checks import InputError
from ....core.ideal import Polyline
from ....core.numeric import Number, fmt_short, normalize
from ....core.records import (
    Column,
    PixelFigure,
    Plot,
    Solution,
    Table,
    Walk,
    heading,
    rule,
    worked,
)
from .._shared import pt

RULES = ("both", "even-odd", "nonzero")
"""Which rule an answer applies."""


def _label(i: int) -> str:
    return chr(ord("A") + i) if i < 26 else f"V{i + 1}"


def _edge_name(i: int, n: int) -> str:
    return _label(i) + _label((i + 1) % n)


def _edge_table(vertices: Sequence[io.Point], point: io.Point, number: int) -> Table:
    n = len(vertices)
    tests = tuple(io.edge_tests(vertices, point))

    def rows() -> Iterator[tuple[Any, ...]]:
        for t in tests:
            yield (
                _edge_name(t.edge, n),
                f"{pt(t.a)} to {pt(t.b)}",
                "yes" if t.straddles else "no",
                "-" if t.x is None else fmt_short(t.x),
                "yes" if t.crossing else "no",
                {1: "+1 (up)", -1: "-1 (down)", 0: "0"}[t.sign],
            )

    return Table(
        f"P{number} = {pt(point)}: the ray y = {fmt_short(point[1])}, x > {fmt_short(point[0])}",
        (
            heading("edge", r"\text{edge}", role="label"),
            heading("ends", r"\text{from, to}", role="given"),
            heading("straddles", r"\text{straddles the ray's line}"),
            heading("x", r"x \text{ at the line}"),
            heading("crossing", r"x > x_P"),
            heading("sign", r"\text{winding}"),
        ),
        rows,
    )


class _Rule(NamedTuple):
    """A rule's verdict column: the rule, its heading, and its cell of a point's row (``why``:
    the boundary, or the parity of the crossings)."""

    name: str
    column: Column
    cell: Callable[[io.Verdict, str], str]


def _word(inside: bool) -> str:
    return "inside" if inside else "outside"


_EVEN_ODD = _Rule(
    "even-odd",
    heading("even_odd", r"\text{even-odd}"),
    lambda v, why: f"{_word(v.even_odd)} ({why})",
)
_NONZERO = _Rule("nonzero", heading("nonzero", r"\text{nonzero}"), lambda v, why: _word(v.nonzero))


def _applied(rule_name: str) -> tuple[_Rule, ...]:
    """The rules ``rule_name`` applies (``both``: each): the even-odd verdict goes before the
    winding number, the nonzero verdict after it."""
    return tuple(r for r in (_EVEN_ODD, _NONZERO) if rule_name in ("both", r.name))


def _verdicts_table(
    verdicts: Sequence[io.Verdict], rules: Sequence[_Rule], n: int, boundary: str = "inside"
) -> Table:
    before = [r for r in rules if r is _EVEN_ODD]
    after = [r for r in rules if r is not _EVEN_ODD]

    def rows() -> Iterator[tuple[Any, ...]]:
        for i, v in enumerate(verdicts, 1):
            on = "-" if v.on_boundary is None else f"on {_edge_name(v.on_boundary, n)}"
            parity = "odd" if v.crossings % 2 else "even"
            why = "boundary" if v.on_boundary is not None and boundary != "left-bottom" else parity
            yield (
                f"P{i} {pt(v.point)}",
                on,
                v.crossings,
                *(r.cell(v, why) for r in before),
                v.winding,
                *(r.cell(v, why) for r in after),
            )

    columns = (
        heading("point", r"\text{point}"),
        heading("boundary", r"\text{boundary}"),
        heading("crossings", r"\text{crossings}"),
        *(r.column for r in before),
        heading("winding", r"\text{winding number}"),
        *(r.column for r in after),
    )
    return Table("Verdicts", columns, rows)


def _points(coords: Sequence[Number]) -> tuple[io.Point, ...]:
    if not coords or len(coords) % 2:
        raise InputError(f"points are x y pairs, got {len(coords)} numbers", "points")
    pts = tuple((normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, len(coords), 2))
    if len(pts) > io.MAX_POINTS:
        raise InputError(f"at most {io.MAX_POINTS} points are tested, got {len(pts)}", "points")
    return pts


_INSIDE_RULES = (
    rule("ray", r"\text{ray from } P \text{ toward } +x"),
    rule(
        "straddle",
        r"\text{an edge counts when one end has } y > y_P \text{ and the other } y \le y_P",
    ),
    rule("x", r"x = x_a + (y_P - y_a)(x_b - x_a) / (y_b - y_a)"),
    rule("even_odd", r"\text{even-odd: inside when the number of crossings is odd}"),
    rule("nonzero", r"\text{nonzero: winding} = \sum (+1 \text{ up}, -1 \text{ down}) \ne 0"),
)
_INSIDE_NOTES = (
    "A ray through a vertex: each edge counts only when one end is strictly above the ray "
    "(half-open), so the vertex counts once where the boundary passes through and not at "
    "all where it only touches; horizontal edges never count.",
    "On a simple polygon the two rules agree; they differ where a self-intersecting "
    "polygon winds twice (even-odd: outside, nonzero: inside).",
)


def _points_figure(
    pts: Sequence[io.Point], tested: Sequence[io.Point], verdicts: Sequence[io.Verdict]
) -> tuple[PixelFigure, ...]:
    """The points tested, inside and outside, when they are integers and fit a grid."""
    xs = [p[0] for p in (*pts, *tested)]
    ys = [p[1] for p in (*pts, *tested)]
    bbox = (int(min(xs)) - 1, int(min(ys)) - 1, int(max(xs)) + 1, int(max(ys)) + 1)
    whole = all(p[0] == int(p[0]) and p[1] == int(p[1]) for p in tested)
    if not whole or bbox[2] - bbox[0] >= 60 or bbox[3] - bbox[1] >= 60:
        return ()
    ins = tuple((int(p[0]), int(p[1])) for p, v in zip(tested, verdicts, strict=True) if v.nonzero)
    outs = tuple(
        (int(p[0]), int(p[1])) for p, v in zip(tested, verdicts, strict=True) if not v.nonzero
    )
    return (PixelFigure(ins, outs, bbox, "# = inside (nonzero), o = outside", "The points:"),)


def inside_solution(
    vertices: Sequence[Number],
    points: Sequence[Number],
    *,
    rule_name: str = "both",
    boundary: str = "inside",
) -> Solution:
    """Whether each point is inside the polygon ``x1 y1 x2 y2 ...``, by the even–odd rule and
    the nonzero winding rule, with every edge's test.

    >>> sol = inside_solution([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [3, 1, 3, 4])
    >>> [r[3] for r in sol.tables[-1].rows()]
    ['inside (odd)', 'outside (even)']
    """
    if rule_name not in RULES:
        raise InputError(f"unknown rule {rule_name!r} (choose from {', '.join(RULES)})", "rule")
    pts, _ = check_polygon(vertices_from_coords(vertices))
    tested = _points(points)
    verdicts = [io.verdict(pts, p, boundary) for p in tested]
    n = len(pts)
    given = (
        *(worked(_label(i), p, f"{_label(i)} = {pt(p)}") for i, p in enumerate(pts)),
        *(worked(f"P{i}", p, f"P_{{{i}}} = {pt(p)}") for i, p in enumerate(tested, 1)),
    )
    derived = _INSIDE_RULES
    notes = (
        *_INSIDE_NOTES[:1],
        (
            "A point on the boundary is as the count gives (left-bottom): on a left or bottom "
            "edge inside, on a right or top edge outside, the scan-line fill's rule for pixels "
            "on an edge."
            if boundary == "left-bottom"
            else f"A point on the boundary is {boundary} (found exactly before counting)."
        ),
        *_INSIDE_NOTES[1:],
    )
    figures = _points_figure(pts, tested, verdicts)
    return Solution(
        primitive="inside",
        algorithm=rule_name,
        title=f"Inside-outside test ({rule_name}): {len(tested)} point(s), polygon of {n} vertices",
        given=given,
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(
            tables=(
                *(_edge_table(pts, p, i) for i, p in enumerate(tested, 1)),
                _verdicts_table(verdicts, _applied(rule_name), n, boundary),
            )
        ),
        plot=Plot(
            figures=figures,
            ideal=(Polyline([(float(x), float(y)) for x, y in (*pts, pts[0])], "polygon"),),
        ),
        data={
            "vertices": [list(p) for p in pts],
            "verdicts": [
                dict(
                    point=list(v.point),
                    crossings=v.crossings,
                    winding=v.winding,
                    even_odd=v.even_odd,
                    nonzero=v.nonzero,
                    on_edge=v.on_boundary,
                )
                for v in verdicts
            ],
        },
    )
