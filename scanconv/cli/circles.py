"""``scanconv circle`` and ``scanconv ellipse``."""

from __future__ import annotations

from fractions import Fraction
from typing import Annotated

from .. import _api as api
from ..algorithms.choices import Layout
from ..algorithms.circle_choices import P0, CircleMethod, EllipseP0, Loop, Update, XStep
from ..core.records import Solution
from .application import app
from .command import answers
from .lines import CodeOpt, ConventionOpt, DeriveOpt, LayoutOpt, RoundingOpt, TieOpt
from .options import NUMERIC_ARGS, Center, choice, num_arg

LoopOpt = Annotated[
    Loop | None,
    choice("--loop", help="The octant (region-1) loop: strict (x < y) or inclusive (x <= y)."),
]


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def circle(
    r: Annotated[Fraction, num_arg("The radius r (a whole number).", "R")],
    center: Center = None,
    method: Annotated[
        CircleMethod,
        choice(
            "--method",
            "-m",
            help="Circle method: midpoint (the notes' Topic 9 'Bresenham', p0 = 1 - r), "
            "bresenham (d0 = 3 - 2r), general (the notes' p0 = 0 at the point), polynomial "
            "(square root), trig, symmetric-dda.",
        ),
    ] = CircleMethod.midpoint,
    rounding: RoundingOpt = None,
    tie: TieOpt = None,
    p0: Annotated[
        P0 | None, choice("--p0", help="midpoint: p0 printed as 1-r (integers) or 5/4-r.")
    ] = None,
    loop: LoopOpt = None,
    update: Annotated[
        Update | None,
        choice("--update", help="midpoint: increments written with the new x or the old x."),
    ] = None,
    xstep: Annotated[
        XStep | None,
        choice(
            "--xstep",
            help="bresenham: d updated before x += 1 (last, Bresenham's own) or after it "
            "(first, as widely copied code does).",
        ),
    ] = None,
    convention: ConventionOpt = None,
    layout: LayoutOpt = Layout.notes,
    derive: DeriveOpt = False,
    pseudocode: CodeOpt = False,
) -> Solution:
    """Draw the circle of radius R: one octant's step table, the 8-way symmetry, the pixels.

    Example: scanconv circle 8 --center 10 10 --method bresenham
    """
    return api.circle(
        r,
        center or (0, 0),
        method=method,
        rounding=rounding,
        tie=tie,
        p0=p0,
        loop=loop,
        update=update,
        xstep=xstep,
        convention=convention,
        layout=layout,
        derive=derive,
        pseudocode=pseudocode,
    )


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def ellipse(
    rx: Annotated[Fraction, num_arg("The semi-axis rx along x (a whole number).", "RX")],
    ry: Annotated[Fraction, num_arg("The semi-axis ry along y (a whole number).", "RY")],
    center: Center = None,
    loop: LoopOpt = None,
    tie: TieOpt = None,
    p0: Annotated[
        EllipseP0 | None,
        choice(
            "--p0",
            help="Each region's first p: exact (quarters) or rounded as Hearn & Baker's code does, "
            "int(p + 0.5).",
        ),
    ] = None,
    convention: ConventionOpt = None,
    derive: DeriveOpt = False,
    pseudocode: CodeOpt = False,
) -> Solution:
    """Draw the ellipse with semi-axes RX, RY by the midpoint method (regions 1 and 2).

    Example: scanconv ellipse 8 6 --center 0 0
    """
    return api.ellipse(
        rx,
        ry,
        center or (0, 0),
        loop=loop,
        tie=tie,
        p0=p0,
        convention=convention,
        derive=derive,
        pseudocode=pseudocode,
    )
