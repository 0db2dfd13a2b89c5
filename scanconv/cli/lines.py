"""``scanconv line``."""

from __future__ import annotations

from typing import Annotated

from .. import _api as api
from ..algorithms.lines import LineAlgorithm
from ..core.records import Solution
from .application import app
from .command import answers
from .options import NUMERIC_ARGS, Num, choice


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def line(
    x1: Num,
    y1: Num,
    x2: Num,
    y2: Num,
    algo: Annotated[
        LineAlgorithm, choice("--algo", "-a", help="Line algorithm.")
    ] = LineAlgorithm.bresenham,
) -> Solution:
    """Draw the line from (X1, Y1) to (X2, Y2), with the step table of the chosen algorithm.

    Example: scanconv line 2 2 10 6 --algo bresenham --svg line.svg
    """
    return api.line(x1, y1, x2, y2, algo=algo)
