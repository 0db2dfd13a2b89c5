"""``scanconv line``."""

from fractions import Fraction
from typing import Annotated

import typer

from .. import _api as api
from ..algorithms.choices import (
    Convention,
    Layout,
    LineAlgorithm,
    LineScale,
    Rounding,
    Start,
    Tie,
    WuEnds,
)
from ..core.records import Solution
from .application import app
from .command import answers
from .options import NUMERIC_ARGS, choice, num_arg

ConventionOpt = Annotated[
    Convention | None,
    choice(
        "--convention",
        help="A named preset of the conventions: notes (default), hearn-baker, foley, "
        "wikipedia (lines only); single options override it.",
    ),
]
LayoutOpt = Annotated[
    Layout,
    choice("--layout", help="Table rows as the notes print them, or the textbook's."),
]
DeriveOpt = Annotated[
    bool, typer.Option("--derive", help="Add the derivation with this input's numbers.")
]
CodeOpt = Annotated[
    bool,
    typer.Option("--algorithm", help="Add the pseudocode of the variant used for this input."),
]
RoundingOpt = Annotated[
    Rounding | None,
    choice(
        "--rounding",
        help="How computed coordinates become pixels: half-up floor(v + 1/2), trunc, half-even "
        "(Python round), c-cast (int)(v + 0.5), half-away (C round).",
    ),
]
TieOpt = Annotated[
    Tie | None,
    choice(
        "--tie",
        help="A decision parameter of 0: step the minor coordinate (if p < 0 keep) or keep it "
        "(if p <= 0 keep).",
    ),
]
StartOpt = Annotated[
    Start | None,
    choice(
        "--start",
        help="Which point is plotted first: swap (the end with the smaller major coordinate; "
        "Bresenham's default) or given (P1, stepping toward P2; the DDA's default).",
    ),
]


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def line(
    x1: Annotated[Fraction, num_arg("x of the first end point P1.", "X1")],
    y1: Annotated[Fraction, num_arg("y of the first end point P1.", "Y1")],
    x2: Annotated[Fraction, num_arg("x of the second end point P2.", "X2")],
    y2: Annotated[Fraction, num_arg("y of the second end point P2.", "Y2")],
    algo: Annotated[
        LineAlgorithm, choice("--algo", "-a", help="Line algorithm.")
    ] = LineAlgorithm.bresenham,
    rounding: RoundingOpt = None,
    tie: TieOpt = None,
    start: StartOpt = None,
    scale: Annotated[
        LineScale | None,
        choice(
            "--scale",
            help="midpoint: d = 2F(M), integers (integer, the default) or d = F(M), halves (half).",
        ),
    ] = None,
    ends: Annotated[
        WuEnds | None,
        choice(
            "--ends",
            help="wu: end points at full intensity (full, the default) or weighted by the "
            "part of the end column the line covers (coverage, as Wikipedia's pseudocode).",
        ),
    ] = None,
    convention: ConventionOpt = None,
    layout: LayoutOpt = Layout.notes,
    derive: DeriveOpt = False,
    pseudocode: CodeOpt = False,
) -> Solution:
    """Draw the line from (X1, Y1) to (X2, Y2), with the step table of the chosen algorithm.

    Example: scanconv line 2 2 10 6 --algo bresenham --svg line.svg
    """
    return api.line(
        x1,
        y1,
        x2,
        y2,
        algo=algo,
        rounding=rounding,
        tie=tie,
        start=start,
        scale=scale,
        ends=ends,
        convention=convention,
        layout=layout,
        derive=derive,
        pseudocode=pseudocode,
    )
