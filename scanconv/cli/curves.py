"""Curves: ``parametric ...``, ``bezier``, ``bspline``, ``continuity`` and ``local-control``."""

from __future__ import annotations

from fractions import Fraction
from typing import Annotated

import typer

from .. import _api as api
from ..core.checks import InputError
from ..core.records import Solution
from ..questions import commands
from .application import app, parametric_app
from .command import answers
from .declared import command
from .options import (
    NUMERIC_ARGS,
    ORIGIN,
    CurveCenter,
    Degree,
    Knots,
    Points,
    Samples,
    Segments,
    TRange,
    num_option,
    number,
)

# --- parametric -------------------------------------------------------------------------------


@parametric_app.command("circle", context_settings=NUMERIC_ARGS)
@answers(figures=True)
def parametric_circle(
    r: Annotated[
        Fraction | None,
        typer.Argument(
            parser=number, show_default=False, help="Radius r, as in circle (or --radius)."
        ),
    ] = None,
    center: CurveCenter = ORIGIN,
    radius: Annotated[
        Fraction | None, num_option("--radius", "-r", help="Radius r (default 1).")
    ] = None,
    t_range: TRange = None,
    samples: Samples = None,
) -> Solution:
    """x = xc + r cos t, y = yc + r sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric circle 5 --center 0 0 --samples 16
    """
    if r is not None and radius is not None and r != radius:
        raise InputError(
            f"unexpected extra argument {r}: the radius is already given by --radius {radius}"
        )
    chosen = r if r is not None else radius if radius is not None else Fraction(1)
    return api.parametric_circle(center, chosen, t_range=t_range, samples=samples)


command(
    parametric_app,
    ("parametric", "ellipse"),
    help="""x = xc + a cos t, y = yc + b sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric ellipse --center 0 0 --a 8 --b 4
    """,
)


command(
    parametric_app,
    ("parametric", "parabola"),
    help="""x = h + t, y = k + a t^2 (the notes' x = t, y = t^2 by default), -3 <= t <= 3.

    Example: scanconv parametric parabola --t-range -3 3
    """,
)


command(
    parametric_app,
    ("parametric", "line"),
    help="""x = x0 + t (x1 - x0), y = y0 + t (y1 - y0), 0 <= t <= 1.

    Example: scanconv parametric line 0 0 10 4
    """,
)


command(
    parametric_app,
    ("parametric", "custom"),
    help="""Your own x(t) and y(t): numbers, t, + - * / **, pi, e, sin cos tan sqrt exp log abs.

    Example: scanconv parametric custom --x "3*cos(t)" --y "2*sin(t)" --t-range 0 2*pi
    """,
)


# --- Bezier and B-spline curves ---------------------------------------------------------------

BezierAt = Annotated[
    str | None,
    typer.Option("--at", metavar="T", help="De Casteljau's construction at this t in [0, 1]."),
]
BsplineAt = Annotated[
    str | None,
    typer.Option(
        "--at", metavar="T", help="Evaluate one t: Cox-de Boor, the non-zero terms, C(t)."
    ),
]


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def bezier(
    points: Points,
    samples: Samples = None,
    t: BezierAt = None,
) -> Solution:
    """Bezier curve of the control points P0 .. Pn: Bernstein weights per t, pixels, grid.

    Example: scanconv bezier 0 0 1 2 3 3 4 0 --samples 8   (or --at 0.5)
    """
    if t is not None:
        return api.bezier_at(points, t)
    return api.bezier(points, samples)


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def bspline(
    points: Annotated[
        list[Fraction] | None,
        typer.Argument(
            parser=number,
            metavar="[X0 Y0 X1 Y1 ...]",
            show_default=False,
            help="Control points as x y pairs (none with --basis and an explicit --knots list).",
        ),
    ] = None,
    degree: Degree = 3,
    knots: Knots = "open",
    basis: Annotated[
        bool, typer.Option("--basis", help="Print only the table of basis values N_i,p(t).")
    ] = False,
    t: BsplineAt = None,
    samples: Samples = None,
) -> Solution:
    """B-spline of degree p (Cox-de Boor): basis values N_i,p(t) per t, the curve, pixels.

    Example: scanconv bspline 0 0 1 2 3 3 4 0 5 2 --degree 2 --knots open
    (the basis alone: scanconv bspline --basis --degree 2 --knots 0,.25,.5,.75,1)
    """
    return commands.bspline(points, degree, knots, basis, t, samples)


@app.command(context_settings=NUMERIC_ARGS)
@answers(figures=True)
def continuity(values: Segments, samples: Samples = None) -> Solution:
    """Continuity (C0, C1, C2) at the join of two Bezier segments, with the derivatives.

    Example: scanconv continuity 0 0 1 2 3 3 4 0 : 4 0 5 -3 7 -2 8 0
    """
    return commands.continuity(values, samples)


@app.command("local-control", context_settings=NUMERIC_ARGS)
@answers()
def local_control(
    points: Points,
    move: Annotated[
        tuple[Fraction, Fraction, Fraction],
        typer.Option(
            "--move",
            parser=number,
            metavar="I X Y",
            help="Move control point P_I to (X, Y).",
            show_default=False,
        ),
    ],
    degree: Degree = 3,
    knots: Knots = "open",
    samples: Samples = None,
) -> Solution:
    """Bezier vs B-spline: move one control point, see which samples and pixels change.

    Example: scanconv local-control 0 0 1 2 3 3 4 0 5 2 7 1 --move 5 7 5 --degree 2
    """
    index, x, y = move
    return api.local_control(points, index, (x, y), degree, knots, samples)
