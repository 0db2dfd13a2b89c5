"""``scanconv compare line`` and ``scanconv compare circle``: every method side by side."""

from __future__ import annotations

from .. import _api as api
from ..core.records import Solution
from .application import compare_app
from .command import answers
from .options import NUMERIC_ARGS, Num


@compare_app.command("line", context_settings=NUMERIC_ARGS)
@answers()
def compare_line(x1: Num, y1: Num, x2: Num, y2: Num) -> Solution:
    """The basic method, DDA and Bresenham for one line: one row per major-axis coordinate.

    Example: scanconv compare line 2 8 10 4
    """
    return api.compare_lines(x1, y1, x2, y2)


@compare_app.command("circle", context_settings=NUMERIC_ARGS)
@answers()
def compare_circle(r: Num) -> Solution:
    """Every circle method over the first octant (one row per x), against the midpoint method.

    Example: scanconv compare circle 10
    """
    return api.compare_circles(r)
