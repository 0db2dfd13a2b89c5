"""What the clipping answers of one window share, kept below them so that each method's module
can use it without importing another's: why a point has its region code (Cohen-Sutherland's and
Nicholl-Lee-Nicholl's tables) and the last line of a line-clipping answer, the clipped segment
or its rejection."""

from __future__ import annotations

from collections.abc import Sequence

from ....algorithms.clipping import Point, Rect
from ....core.numeric import Number, fmt_short
from ....core.records import Quantity
from .._shared import pt, pt_approx

__all__ = ["clipped_quantity", "code_reason", "corners"]


def code_reason(p: Point, w: Rect) -> str:
    """Why a point has its code: ``y = 9 > ymax = 8 (T)``; ``inside`` for 0000."""
    x, y = p
    why = []
    if y > w[3]:
        why.append(f"y = {fmt_short(y)} > ymax = {fmt_short(w[3])} (T)")
    if y < w[1]:
        why.append(f"y = {fmt_short(y)} < ymin = {fmt_short(w[1])} (B)")
    if x > w[2]:
        why.append(f"x = {fmt_short(x)} > xmax = {fmt_short(w[2])} (R)")
    if x < w[0]:
        why.append(f"x = {fmt_short(x)} < xmin = {fmt_short(w[0])} (L)")
    return ", ".join(why) if why else "inside (on an edge counts as inside)"


def clipped_quantity(seg: tuple[Point, Point] | None) -> Quantity:
    """The last line of a clipping answer: the clipped segment, or that it is rejected."""
    if seg is None:
        return Quantity(
            "clipped",
            None,
            "the segment is rejected: no part of it is inside the window",
            r"\text{rejected}",
        )
    return Quantity(
        "clipped",
        [list(seg[0]), list(seg[1])],
        f"clipped segment: {pt_approx(seg[0])} to {pt_approx(seg[1])}",
        f"\\text{{clipped segment: }} {pt(seg[0])} \\text{{ to }} {pt(seg[1])}",
    )


def corners(w: Sequence[Number]) -> list[Point]:
    """The corners of the rectangle ``(xmin, ymin, xmax, ymax)``, counter-clockwise from
    ``(xmin, ymin)``: the rectangle as a polygon window.

    >>> corners((0, 1, 4, 3))
    [(0, 1), (4, 1), (4, 3), (0, 3)]
    """
    x0, y0, x1, y1 = w
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
