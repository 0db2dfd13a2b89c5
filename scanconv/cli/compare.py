"""``scanconv compare line`` and ``compare circle``: every method side by side, and (with
``--theory``) the points of the notes' comparison questions."""

from __future__ import annotations

from typing import Annotated

import typer

from .. import _api as api
from ..core.records import Solution
from .application import compare_app
from .command import answers
from .options import NUMERIC_ARGS, Num

TheoryOpt = Annotated[
    bool,
    typer.Option("--theory", help="Add the points the notes' comparison questions expect."),
]


@compare_app.command("line", context_settings=NUMERIC_ARGS)
@answers()
def compare_line(x1: Num, y1: Num, x2: Num, y2: Num, theory: TheoryOpt = False) -> Solution:
    """The basic method, DDA and Bresenham for one line: one row per major-axis coordinate.

    Example: scanconv compare line 2 8 10 4 --theory
    """
    return api.compare_lines(x1, y1, x2, y2, theory=theory)


@compare_app.command("circle", context_settings=NUMERIC_ARGS)
@answers()
def compare_circle(r: Num, theory: TheoryOpt = False) -> Solution:
    """Every circle method over the first octant (one row per x), against the midpoint method.

    Example: scanconv compare circle 10 --theory
    """
    return api.compare_circles(r, theory=theory)


@compare_app.command("curves")
@answers(grid=False, origin=False)
def compare_curves() -> Solution:
    """Bezier vs B-spline curves: the points the notes' comparison question expects.

    Example: scanconv compare curves
    """
    return api.compare_curves()
