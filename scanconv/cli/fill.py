"""The notes' other primitives: ``polygon`` (scan-line fill), ``fill boundary`` and
``fill flood`` (seed fills), ``antialias line``, ``antialias circle`` and
``antialias polygon``."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Annotated

import typer

from ..algorithms.process_choices import AAMethod, Across, Divide, FillRule, Order, Subgrid, WuEnds
from ..core.records import Solution
from ..questions import commands
from .application import _subapp, app
from .command import answers
from .declared import command
from .options import NUMERIC_ARGS, choice, integer, num_option, number

fill_app = _subapp(
    "fill", "Seed fills from a pixel: boundary fill and flood fill, 4- or 8-connected."
)
antialias_app = _subapp(
    "antialias", "Anti-aliasing: Wu's line, unweighted area sampling and supersampling."
)

Rule = Annotated[
    FillRule, choice("--rule", help="Fill rule: even-odd (alternate) or nonzero winding.")
]
Levels = Annotated[
    int,
    typer.Option(
        "--levels", "-L", parser=integer, help="Intensity levels L (level = round(I (L - 1)))."
    ),
]
Samples = Annotated[
    int,
    typer.Option(
        "--samples", "-n", parser=integer, help="Supersampling: N x N samples per pixel (1-16)."
    ),
]
Method = Annotated[
    AAMethod,
    choice(
        "--method",
        "-m",
        help="area: exact covered area; supersample: N x N samples; wu: Wu's line; subpixel: "
        "Hearn & Baker's Bresenham on sub-pixels (wu and subpixel: lines only).",
    ),
]
Ends = Annotated[
    WuEnds | None,
    choice(
        "--ends",
        help="wu: end points at full intensity (full, the default) or weighted by the part of "
        "the end column the line covers (coverage, as Wikipedia's pseudocode).",
    ),
]

Width = Annotated[
    Fraction,
    num_option(
        "--width",
        "-w",
        help="area, supersample: the line's width w (default 1 pixel).",
        metavar="W",
    ),
]
AcrossOpt = Annotated[
    Across,
    choice(
        "--across",
        help="area, supersample: w measured along the minor axis (minor, the default: a "
        "parallelogram) or perpendicular to the line (a rectangle).",
    ),
]
SubgridOpt = Annotated[
    Subgrid | None,
    choice(
        "--subgrid",
        help="subpixel: the sub-pixel line from P1's first sub-pixel over every sub-column of "
        "the end pixels (span, the default) or between the end pixels' centre sub-pixels "
        "(centre).",
    ),
]
DivideOpt = Annotated[
    Divide | None,
    choice(
        "--divide",
        help="subpixel: intensity c / n (n, the default: n levels above zero) or c / n^2 (n2: "
        "the fraction of the pixel's sub-pixels).",
    ),
]
LineSamples = Annotated[
    int | None,
    typer.Option(
        "--samples",
        "-n",
        parser=integer,
        help="N x N samples (supersample, 1-16, default 4) or sub-pixels (subpixel, default 3) "
        "per pixel.",
        show_default=False,
    ),
]


command(
    app,
    ("polygon",),
    help="""Scan-line polygon fill: the edge table, then per scan line the active edge table, the
    intersections, the spans and pixels filled (pixel centres; half-open spans and edges).

    Example: scanconv polygon 2 3 7 1 13 5 13 11 7 7 2 9
    """,
)


OptVertices = Annotated[
    list[Fraction] | None,
    typer.Argument(
        parser=number,
        metavar="[X1 Y1 X2 Y2 X3 Y3 ...]",
        help="A polygon whose Bresenham outline is the boundary (or give --rows).",
        show_default=False,
    ),
]
Seed = Annotated[
    tuple[int, int],
    typer.Option("--seed", "-s", parser=integer, metavar="X Y", help="The seed pixel."),
]
Rows = Annotated[
    str | None,
    typer.Option(
        "--rows",
        "-r",
        metavar="ROWS",
        help="The grid as text rows, top row first, separated by '/': '#' boundary, '.' "
        "empty, '*' fill colour, other letters other colours; the bottom row is y = 0.",
        show_default=False,
    ),
]
Connectivity = Annotated[
    int,
    typer.Option("--connectivity", "-k", parser=integer, help="Neighbours: 4 or 8."),
]
OrderOpt = Annotated[
    Order, choice("--order", help="stack: last in first out; queue: first in first out.")
]
Span = Annotated[
    bool,
    typer.Option("--span", help="The span (scan-line seed) fill: a whole run per seed."),
]


def _seed_command(kind: str, doc: str) -> Callable[..., Solution]:
    """The ``fill boundary`` or ``fill flood`` command: both take the same options."""

    def command(
        seed: Seed,
        vertices: OptVertices = None,
        rows: Rows = None,
        connectivity: Connectivity = 4,
        order: OrderOpt = Order.stack,
        span: Span = False,
    ) -> Solution:
        return commands.BODIES[f"fill_{kind}"](seed, vertices, rows, connectivity, order, span)

    command.__name__ = command.__qualname__ = f"fill_{kind}"
    command.__doc__ = doc
    return command


fill_boundary = fill_app.command("boundary", context_settings=NUMERIC_ARGS)(
    answers(figures=True)(
        _seed_command(
            "boundary",
            """Boundary fill from a seed: fill every pixel that is neither the boundary nor filled,
    with the trace of the stack or queue and the filled grid.

    Example: scanconv fill boundary 4 1 7 4 4 7 1 4 --seed 4 4 --connectivity 8

    """,
        )
    )
)
fill_flood = fill_app.command("flood", context_settings=NUMERIC_ARGS)(
    answers(figures=True)(
        _seed_command(
            "flood",
            """Flood fill from a seed: replace the seed's colour in its connected region, with the
    trace of the stack or queue and the filled grid.

    Example: scanconv fill flood --rows '#####/#...#/#.x.#/#####' --seed 1 1

    """,
        )
    )
)


command(
    antialias_app,
    ("antialias", "line"),
    help="""An anti-aliased line: Wu's algorithm (the two pixels of each step and their
    intensities), a line w wide by area sampling or supersampling, or Hearn & Baker's
    supersampling (Bresenham on a 3 x 3 sub-pixel grid, the sub-pixels counted per pixel).

    Example: scanconv antialias line 0 0 8 3 --method wu
    """,
)


command(
    antialias_app,
    ("antialias", "circle"),
    help="""An anti-aliased circle one pixel wide (the ring r - 1/2 <= d <= r + 1/2): each pixel's
    covered area, or the fraction of its N x N samples inside.

    Example: scanconv antialias circle 5 --method supersample --samples 4
    """,
)


command(
    antialias_app,
    ("antialias", "polygon"),
    help="""An anti-aliased polygon: each pixel's exactly covered area, or the fraction of its
    N x N samples inside.

    Example: scanconv antialias polygon 0 0 7 2 4 6
    """,
)
