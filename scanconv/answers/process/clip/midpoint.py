"""The worked answer of midpoint subdivision clipping: every piece with its end codes, the AND
of the codes and what is done (accept, reject, split at the midpoint with its code), then the
visible part (:mod:`scanconv.algorithms.midpoint_clip`)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from ....algorithms.clipping import Rect
from ....algorithms.midpoint_clip import Piece, subdivide, visible
from ....core.checks import InputError
from ....core.ideal import IdealLine
from ....core.numeric import Number, fmt_short, normalize
from ....core.records import Plot, Quantity, Solution, Table, Walk, heading, rule, worked
from .._shared import pt

if TYPE_CHECKING:
    from ...asked import ClipLineQuestion


def _code(c: int | None) -> str:
    return "-" if c is None else f"{c:04b}"


def _table(pieces: list[Piece]) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for p in pieces:
            yield (
                p.k,
                f"{pt(p.a)} to {pt(p.b)}",
                _code(p.code_a),
                _code(p.code_b),
                _code(p.code_a & p.code_b),
                p.action,
                "-" if p.mid is None else pt(p.mid),
                _code(p.code_mid),
            )

    return Table(
        "Pieces (depth first, the half nearer P1 first; codes TBRL)",
        (
            heading("k", "k", role="label"),
            heading("piece", r"\text{piece}"),
            heading("code_a", r"\text{code}_1"),
            heading("code_b", r"\text{code}_2"),
            heading("and", r"\text{AND}"),
            heading("action", r"\text{action}"),
            heading("mid", r"\text{midpoint}"),
            heading("code_mid", r"\text{its code}"),
        ),
        rows,
    )


def _rules(midpoint: str, stop: str) -> tuple[Quantity, ...]:
    """The rules the subdivision follows, with its midpoint and stop conventions."""
    how = {
        "rounded": r"\text{rounded half up}",
        "floor": r"\text{floor: the hardware shift, } \lfloor (a + b)/2 \rfloor",
        "exact": r"\text{exact}",
    }[midpoint]
    edge = rule(
        "edge",
        r"\text{a piece from a point on an edge to a point beyond that edge: "
        r"the point is the clipped end}",
    )
    return (
        rule(
            "accept",
            r"\text{both codes } 0000: \text{accept}; \ \text{AND} \ne 0000: \text{reject}",
        ),
        rule("split", f"\\text{{else split at }} P_m = ((x_1 + x_2)/2, (y_1 + y_2)/2), {how}"),
        rule("stop", r"\text{a piece one unit long keeps its inside end}"),
        *((edge,) if stop == "edge" else ()),
    )


def midpoint_answer(q: ClipLineQuestion) -> Solution:
    """:func:`midpoint_clip_solution` of the question (the record's ``answer``)."""
    midpoint, stop = q.midpoint or "rounded", q.stop or "length"
    return midpoint_clip_solution(*q.p1, *q.p2, q.window, midpoint=midpoint, stop=stop)


def midpoint_clip_solution(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    window: tuple[Number, ...] | list[Number],
    *,
    midpoint: str = "rounded",
    stop: str = "length",
) -> Solution:
    """Midpoint subdivision of ``(x1, y1)``-``(x2, y2)`` against ``(xmin, ymin, xmax, ymax)``.

    >>> midpoint_clip_solution(-4, 2, 4, 2, [0, 0, 8, 8]).data["visible"]
    [[[0, 2], [4, 2]]]
    """
    if len(window) != 4:
        raise InputError(f"the window is xmin ymin xmax ymax, got {len(window)} numbers", "window")
    w: Rect = (
        normalize(window[0]),
        normalize(window[1]),
        normalize(window[2]),
        normalize(window[3]),
    )
    if not (w[0] < w[2] and w[1] < w[3]):
        raise InputError("the window needs xmin < xmax and ymin < ymax", "window")
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    pieces = list(subdivide(p1, p2, w, midpoint, stop))
    parts = visible(pieces)
    shown = "; ".join(f"{pt(a)} to {pt(b)}" for a, b in parts) or "none"
    return Solution(
        primitive="clip",
        algorithm="midpoint-subdivision",
        title=f"Midpoint subdivision clipping: {pt(p1)} to {pt(p2)}",
        given=(
            worked("P1", p1, f"P_1 = {pt(p1)}"),
            worked("P2", p2, f"P_2 = {pt(p2)}"),
            worked(
                "window",
                w,
                f"x_{{\\min}} = {fmt_short(w[0])}, y_{{\\min}} = {fmt_short(w[1])}, "
                f"x_{{\\max}} = {fmt_short(w[2])}, y_{{\\max}} = {fmt_short(w[3])}",
            ),
        ),
        derived=(
            *_rules(midpoint, stop),
            worked(
                "visible", [[list(a), list(b)] for a, b in parts], f"\\text{{visible: {shown}}}"
            ),
        ),
        notes=(
            f"Midpoints {midpoint} (rounded: half up; floor: (a + b) >> 1; exact: fractions).",
            "Stop rule: "
            + (
                "edge (a midpoint on the window's edge is the clipped end: the piece beyond it "
                "is not split further; length, the other rule, splits until one unit long)."
                if stop == "edge"
                else "length (split until decided or one unit long; edge, the other rule, "
                "stops where a midpoint lands on the window's edge)."
            ),
            "Region codes are TBRL: top, bottom, right, left, 1 where the point is beyond that "
            "edge; the window's edges are inside.",
        ),
        walk=Walk(tables=(_table(pieces),)),
        plot=Plot(ideal=(IdealLine(*p1, *p2),)),
        data={"visible": [[list(a), list(b)] for a, b in parts], "pieces": len(pieces)},
    )
