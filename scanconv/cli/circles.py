"""``scanconv circle`` and ``scanconv ellipse``."""

from __future__ import annotations

from typing import Annotated

from .. import _api as api
from ..algorithms.circles import CircleMethod, Rounding
from ..core.records import Solution
from .application import app
from .command import answers
from .options import NUMERIC_ARGS, Center, Num, choice


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def circle(
    r: Num,
    center: Center = None,
    method: Annotated[
        CircleMethod, choice("--method", "-m", help="Circle method.")
    ] = CircleMethod.midpoint,
    rounding: Annotated[
        Rounding,
        choice(
            "--rounding",
            help="polynomial, trig and symmetric-dda: round half up, floor(v + 1/2), or "
            "truncate like a C (int) cast.",
        ),
    ] = Rounding.half_up,
) -> Solution:
    """Draw the circle of radius R: one octant's step table, the 8-way symmetry, the pixels.

    Example: scanconv circle 8 --center 10 10 --method bresenham
    """
    return api.circle(r, center or (0, 0), method=method, rounding=rounding)


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def ellipse(rx: Num, ry: Num, center: Center = None) -> Solution:
    """Draw the ellipse with semi-axes RX, RY by the midpoint method (regions 1 and 2).

    Example: scanconv ellipse 8 6 --center 0 0
    """
    return api.ellipse(rx, ry, center or (0, 0))
