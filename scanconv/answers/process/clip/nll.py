"""The worked answer of Nicholl–Lee–Nicholl line clipping: the region of P1, the slopes of the
rays to the window's corners, each comparison with its numbers, the region of P2, the
crossings and the clipped segment (:mod:`scanconv.algorithms.nll`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ....algorithms.clipping import Edge, Point, Rect
from ....algorithms.nll import EDGE_OF, REGION_NAMES, NLLResult, nicholl_lee_nicholl
from ....core.numeric import Number, fmt_paren, fmt_short, normalize
from ....core.records import Plot, Quantity, Solution, Table, Walk, heading, rule, worked
from .._shared import (
    Clipped,
    check_rect,
    clip_figure,
    factor,
    point_quantity,
    pt,
    rect_quantity,
)
from ._shared import clipped_quantity, code_reason

if TYPE_CHECKING:
    from ...asked import ClipLineQuestion

_LIMIT = {"L": "x_{\\min}", "R": "x_{\\max}", "B": "y_{\\min}", "T": "y_{\\max}"}


def _value(v: Number | str) -> str:
    return v if isinstance(v, str) else fmt_short(v)


def _tex_name(name: str) -> str:
    """``m'_TL`` as TeX: ``m'_{TL}``; ``xmin``: ``x_{\\min}``."""
    if name in ("xmin", "xmax", "ymin", "ymax"):
        return f"{name[0]}_{{\\{name[1:]}}}"
    if name in ("x2", "y2"):
        return f"{name[0]}_2"
    base, _, sub = name.partition("_")
    return f"{base}_{{{sub}}}" if sub else base


def _tests_table(result: NLLResult) -> Table:
    def rows() -> Iterator[tuple[Any, ...]]:
        for t in result.tests:
            yield (
                t.k, t.test, t.left, _value(t.left_value), t.relation, t.right,
                _value(t.right_value), t.so,
            )  # fmt: skip

    return Table(
        "Comparisons, in the order they are made",
        (
            heading("k", "k", role="label"),
            heading("test", r"\text{test}", role="given"),
            heading("left", r"\text{compare}"),
            heading("left_value", r"\text{value}"),
            heading("relation", r"\text{relation}"),
            heading("right", r"\text{with}"),
            heading("right_value", r"\text{value}"),
            heading("so", r"\text{so}"),
        ),
        rows,
    )


def _corners(w: Rect) -> dict[str, Point]:
    return {"TL": (w[0], w[3]), "TR": (w[2], w[3]), "BR": (w[2], w[1]), "BL": (w[0], w[1])}


def _slope_lines(p1: Point, p2: Point, w: Rect, result: NLLResult) -> list[Quantity]:
    if not result.slopes:
        return []
    inverse = result.uses_inverse
    name = "m'" if inverse else "m"
    if inverse:
        where = (
            r"P_1 \text{ is above or below the window: every ray has } \Delta y \text{ of one sign}"
        )
    elif result.region1:
        where = r"P_1 \text{ is left or right of the window: every ray has } \Delta x \text{ of one sign}"
    else:
        side = "TR and BR" if p2[0] > p1[0] else "TL and BL"
        where = f"\\text{{the rays on the side of P2: to {side}}}"
    lines = [
        rule(
            "slope",
            f"{name} = \\Delta x / \\Delta y \\quad ({where})"
            if inverse
            else f"m = \\Delta y / \\Delta x \\quad ({where})",
        )
    ]
    points = {"P2": p2, **_corners(w)}
    for label, value in result.slopes:
        q = points[label]
        dx, dy = q[0] - p1[0], q[1] - p1[1]
        num, den = (dx, dy) if inverse else (dy, dx)
        ia, ib = (0, 1) if inverse else (1, 0)
        sub = "" if label == "P2" else f"_{{{label}}}"
        lines.append(
            worked(
                f"{name}_{label}",
                value,
                f"{name}{sub} = ({fmt_short(q[ia])} - {fmt_paren(p1[ia])}) / "
                f"({fmt_short(q[ib])} - {fmt_paren(p1[ib])}) = "
                f"{fmt_short(normalize(Fraction(num) / den))}",
            )
        )
    return lines


def _crossing_line(p1: Point, p2: Point, role: str, edge: Edge, point: Point) -> Quantity:
    letter = {v: k for k, v in EDGE_OF.items()}[edge]
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    if letter in "LR":
        value = point[0]
        tex = (
            f"x = {_LIMIT[letter]} = {fmt_short(value)}: \\ y = y_1 + (x - x_1) \\Delta y/\\Delta x"
            f" = {fmt_short(p1[1])} + ({fmt_short(value)} - {fmt_paren(p1[0])}) \\cdot "
            f"{factor(normalize(Fraction(dy) / dx))} = {fmt_short(point[1])}"
        )
    elif dx == 0:
        tex = f"y = {_LIMIT[letter]} = {fmt_short(point[1])}: \\ x = x_1 = {fmt_short(point[0])}"
    else:
        value = point[1]
        tex = (
            f"y = {_LIMIT[letter]} = {fmt_short(value)}: \\ x = x_1 + (y - y_1) \\Delta x/\\Delta y"
            f" = {fmt_short(p1[0])} + ({fmt_short(value)} - {fmt_paren(p1[1])}) \\cdot "
            f"{factor(normalize(Fraction(dx) / dy))} = {fmt_short(point[0])}"
        )
    return worked(f"{role}_{letter}", point, f"\\text{{{role}, {edge.value} edge: }} {tex}")


def nll_clipped(q: ClipLineQuestion) -> Clipped:
    """NLL's working against the question's rectangle (the record's ``stage``)."""
    return _clipped(q.p1, q.p2, q.window, nicholl_lee_nicholl(q.p1, q.p2, q.window))


def _clipped(p1: Point, p2: Point, w: Rect, result: NLLResult) -> Clipped:
    """NLL's working (P1's region, the slopes, P2's region, the crossings), its tests table and
    the clipped segment of the run ``result``."""
    why = code_reason(p1, w) if result.region1 else "code 0000"
    derived: list[Quantity] = [
        worked("region1", result.region1 or "inside",
               f"P_1: \\text{{{why}: {REGION_NAMES[result.region1]}}}"),
        *_slope_lines(p1, p2, w, result),
    ]  # fmt: skip
    if result.accepted:
        region2 = result.region2
        derived.append(
            worked(
                "region2",
                region2,
                f"P_2 \\text{{ is in region {region2}: {_says(region2, not result.region1)}}}",
            )
        )
        derived += [_crossing_line(p1, p2, c.role, c.edge, c.point) for c in result.crossings]
    return Clipped(derived, [_tests_table(result)], result.segment)


def nll_answer(q: ClipLineQuestion) -> Solution:
    """:func:`nll_solution` of the question (the record's ``answer``)."""
    return nll_solution(*q.p1, *q.p2, q.window)


def nll_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, window: Sequence[Number]
) -> Solution:
    """Nicholl–Lee–Nicholl clipping of ``(x1, y1)``–``(x2, y2)`` against
    ``(xmin, ymin, xmax, ymax)``.

    >>> nll_solution(30, 60, 60, 25, (10, 10, 50, 50)).data["clipped"]
    [[Fraction(270, 7), 50], [50, Fraction(110, 3)]]
    """
    w = check_rect(window, "window", "window")
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    result = nicholl_lee_nicholl(p1, p2, w)
    clipped = _clipped(p1, p2, w, result)
    seg = clipped.segment
    derived = [*clipped.working, clipped_quantity(seg)]
    notes = (
        "P1's region: inside, an edge region (beyond one edge: L, R, B, T) or a corner region "
        "(beyond two: TL, TR, BL, BR). P2's region is named by the edges the segment crosses "
        "(LT: in through the left edge, out through the top); inside the window it names the "
        "entry edge only.",
        "Hearn & Baker's form: P2's region from the slopes of the rays to the corners "
        "(m = dy/dx; m' = dx/dy when P1 is above or below the window), worked in the given "
        "coordinates for every region (the paper rotates and reflects to three cases). A line "
        "along a corner ray takes the edge it is not parallel to; the same point either way.",
        "The window is closed: a point on an edge is inside, so a line touching a corner keeps "
        "that point.",
    )
    return Solution(
        primitive="clip",
        algorithm="nicholl-lee-nicholl",
        title=f"Nicholl-Lee-Nicholl line clipping: {pt(p1)} to {pt(p2)}, window "
        f"({fmt_short(w[0])}, {fmt_short(w[1])})-({fmt_short(w[2])}, {fmt_short(w[3])})",
        given=(point_quantity("P1", p1), point_quantity("P2", p2), rect_quantity("window", w)),
        derived=tuple(derived),
        notes=notes,
        walk=Walk(tables=tuple(clipped.tables)),
        plot=Plot(figures=clip_figure(list(seg) if seg else [], w, [p1, p2], "clipped segment")),
        data={
            "region1": result.region1 or "inside",
            "region2": result.region2 or None,
            "clipped": None if seg is None else [list(seg[0]), list(seg[1])],
        },
    )


def _says(region: str, from_inside: bool) -> str:
    """``in through the top edge, out through the right edge``."""
    if region == "inside":
        return "both ends inside, nothing to clip"
    if from_inside:
        return f"out through the {EDGE_OF[region].value} edge"
    said = f"in through the {EDGE_OF[region[0]].value} edge"
    if len(region) == 1:
        return said + ", P2 inside the window"
    return f"{said}, out through the {EDGE_OF[region[1]].value} edge"
