"""The worked answer of Cyrus–Beck line clipping against a convex window: each edge's normal,
``N·D``, ``N·(P0 - E)``, ``t`` and whether the segment enters or leaves there, then ``tE``,
``tL`` and the clipped segment (:mod:`scanconv.algorithms.cyrus_beck`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Any

from ....algorithms.cyrus_beck import CBResult, cyrus_beck
from ....core.checks import InputError
from ....core.ideal import IdealLine, Polyline
from ....core.numeric import Number, fmt_short, normalize
from ....core.records import Plot, Quantity, Solution, Table, Walk, heading, rule, worked
from .._shared import Clipped, pt
from ._shared import corners

if TYPE_CHECKING:
    from ...asked import ClipLineQuestion


def _vertices(coords: Sequence[Number], param: str) -> list[tuple[Number, Number]]:
    if len(coords) % 2 or len(coords) < 6:
        raise InputError(f"a window is at least 3 vertices x y, got {len(coords)} numbers", param)
    return [(normalize(coords[i]), normalize(coords[i + 1])) for i in range(0, len(coords), 2)]


def _edge_table(result: CBResult, n: int) -> Table:
    def name(i: int) -> str:
        return f"V{i + 1}V{(i + 1) % n + 1}"

    def rows() -> Iterator[tuple[Any, ...]]:
        for r in result.rows:
            yield (
                name(r.edge),
                pt(r.normal),
                pt(r.point),
                fmt_short(r.n_dot_d),
                fmt_short(r.n_dot_w),
                "-" if r.t is None else fmt_short(r.t),
                r.kind,
                fmt_short(r.t_enter),
                fmt_short(r.t_leave),
            )

    return Table(
        "Edges (N: the normal, E: the edge's first vertex)",
        (
            heading("edge", r"\text{edge}"),
            heading("normal", "N"),
            heading("point", "E"),
            heading("n_dot_d", r"N \cdot D"),
            heading("n_dot_w", r"N \cdot (P_0 - E)"),
            heading("t", "t"),
            heading("kind", r"\text{type}"),
            heading("t_enter", "t_E"),
            heading("t_leave", "t_L"),
        ),
        rows,
    )


def cyrus_beck_clipped(
    p0: tuple[Number, Number],
    p1: tuple[Number, Number],
    win: list[tuple[Number, Number]],
    normals: str = "outward",
    ends: str = "exact",
    result: CBResult | None = None,
) -> Clipped:
    """Cyrus-Beck's working (without its last line), its edge table and the clipped segment
    (``result``: the run, if it is done already)."""
    result = result or cyrus_beck(p0, p1, win, normals, ends)
    d = (normalize(p1[0] - p0[0]), normalize(p1[1] - p0[1]))
    sign = "-" if normals == "outward" else ""
    working: list[Quantity] = [
        worked("D", d, f"D = P_1 - P_0 = {pt(d)}"),
        rule("P", r"P(t) = P_0 + t D, \quad 0 \le t \le 1"),
        rule("t", f"t = N \\cdot (P_0 - E) / ({sign}N \\cdot D)"),
        rule(
            "kind",
            f"N \\cdot D {'<' if normals == 'outward' else '>'} 0: \\text{{entering}} "
            f"(t_E = \\max), \\quad N \\cdot D {'>' if normals == 'outward' else '<'} 0: "
            "\\text{leaving} (t_L = \\min)",
        ),
    ]
    return Clipped(working, [_edge_table(result, len(win))], result.segment)


def _outcome(result: CBResult) -> Quantity:
    """The last line: the clipped end points at t_E and t_L, or why the line is rejected."""
    last = result.rows[-1]
    if result.accepted and result.segment is not None:
        a, b = result.segment
        return worked(
            "clipped",
            (a, b),
            f"t_E = {fmt_short(last.t_enter)}, t_L = {fmt_short(last.t_leave)}: "
            f"P(t_E) = {pt(a)}, P(t_L) = {pt(b)}",
        )
    why = (
        "parallel to an edge and outside it"
        if any(r.kind == "parallel, outside" for r in result.rows)
        else f"t_E = {fmt_short(last.t_enter)} > t_L = {fmt_short(last.t_leave)}"
    )
    return rule("rejected", f"\\text{{rejected: {why}}}")


def cyrus_beck_solution(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    window: Sequence[Number],
    *,
    normals: str = "outward",
    ends: str = "exact",
) -> Solution:
    """Cyrus–Beck clipping of the segment ``(x1, y1)``–``(x2, y2)`` against the convex window
    with vertices ``x y x y ...``.

    >>> sol = cyrus_beck_solution(-2, 1, 6, 3, [0, 0, 4, 0, 4, 4, 0, 4])
    >>> sol.data["clipped"]
    [[0, Fraction(3, 2)], [4, Fraction(5, 2)]]
    """
    p0 = (normalize(x1), normalize(y1))
    p1 = (normalize(x2), normalize(y2))
    win = _vertices(window, "window")
    result = cyrus_beck(p0, p1, win, normals, ends)
    given = (
        worked("P0", p0, f"P_0 = {pt(p0)}"),
        worked("P1", p1, f"P_1 = {pt(p1)}"),
        *(worked(f"V{i}", v, f"V_{{{i}}} = {pt(v)}") for i, v in enumerate(win, 1)),
    )
    clipped = cyrus_beck_clipped(p0, p1, win, normals, ends, result)
    derived = [*clipped.working, _outcome(result)]
    last = result.rows[-1]
    notes = (
        f"Conventions: {normals} normals (inward normals flip the sign of every $N \\cdot D$ "
        f"and $N \\cdot (P_0 - E)$, never $t$), clipped ends {ends}.",
        "The normals are not normalised: any positive multiple gives the same t.",
    )
    return Solution(
        primitive="clip",
        algorithm="cyrus-beck",
        title=f"Cyrus-Beck clipping: {pt(p0)} to {pt(p1)}, a window of {len(win)} vertices",
        given=given,
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=tuple(clipped.tables)),
        plot=Plot(
            ideal=(
                IdealLine(*p0, *p1),
                Polyline([(float(x), float(y)) for x, y in (*win, win[0])], "window"),
            )
        ),
        data={
            "accepted": result.accepted,
            "clipped": None if result.segment is None else [list(p) for p in result.segment],
            "t_enter": last.t_enter,
            "t_leave": last.t_leave,
        },
    )


def rectangle_clipped(q: ClipLineQuestion) -> Clipped:
    """Cyrus-Beck with the question's rectangle as its convex window (the record's
    ``stage``)."""
    normals, ends = q.normals or "outward", q.ends or "exact"
    return cyrus_beck_clipped(q.p1, q.p2, corners(q.window), normals, ends)


def rectangle_solution(q: ClipLineQuestion) -> Solution:
    """:func:`cyrus_beck_solution` with the question's rectangle as the convex window (the
    record's ``answer``)."""
    flat = [c for p in corners(q.window) for c in p]
    normals, ends = q.normals or "outward", q.ends or "exact"
    return cyrus_beck_solution(*q.p1, *q.p2, flat, normals=normals, ends=ends)
