"""The scan-conversion process around scan conversion: ``transform``, ``viewport``,
``clip line``, ``clip polygon`` and ``pipeline line``."""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from typing import Annotated

import typer

from .. import _api as api
from ..algorithms.choices import LineAlgorithm
from ..algorithms.process_choices import FillRule, LineClipMethod, PolygonClipMethod
from ..core.records import Solution
from ..questions import commands
from .application import app, clip_app, pipeline_app
from .command import answers
from .options import NUMERIC_ARGS, Num, Vertices, number

Rect = tuple[Fraction, Fraction, Fraction, Fraction]

Window = Annotated[
    Rect,
    typer.Option(
        "--window",
        "-w",
        parser=number,
        metavar="XMIN YMIN XMAX YMAX",
        show_default=False,
        help="The clipping window in world coordinates (closed: its edges are inside).",
    ),
]
Viewport = Annotated[
    Rect,
    typer.Option(
        "--viewport",
        parser=number,
        metavar="XMIN YMIN XMAX YMAX",
        show_default=False,
        help="The viewport in device coordinates.",
    ),
]

TRANSFORM_HELP = """Compose 2D transformations (homogeneous coordinates, column vectors) and
apply them to the points X1 Y1 X2 Y2 ..., in the order given.

Transformations, composed left to right:
--translate TX TY; --scale S [SY]; --rotate ANGLE; --shear SHX SHY (each of these three may be
followed by --about X Y); --reflect x-axis|y-axis|origin|y=x|y=-x; --reflect line X1 Y1 X2 Y2.
ANGLE is in degrees (90, -30) or radians (pi/4, 3pi/2, 1.2rad); multiples of 15 degrees are
exact (sqrt(2)/2), other angles are rounded to 6 decimals.

Example: scanconv transform 0 0 4 0 4 3 --rotate 90 --about 2 1 --translate 3 0
"""


class Normals(str, Enum):
    """Cyrus-Beck: the edges' normals point out of the window or into it."""

    outward = "outward"
    inward = "inward"


class Ends(str, Enum):
    """Cyrus-Beck: the clipped end points kept exact or truncated to integers."""

    exact = "exact"
    truncated = "truncated"


class Midpoint(str, Enum):
    """Midpoint subdivision: the midpoints rounded, floored or exact."""

    rounded = "rounded"
    floor = "floor"
    exact = "exact"


class MidpointStop(str, Enum):
    """Midpoint subdivision's stop rule: one unit long, or a midpoint on the window's edge."""

    length = "length"
    edge = "edge"


NormalsOpt = Annotated[
    Normals | None,
    typer.Option(
        "--normals",
        case_sensitive=False,
        help="cyrus-beck: the edge normals point outward (default) or inward.",
    ),
]
EndsOpt = Annotated[
    Ends | None,
    typer.Option(
        "--ends",
        case_sensitive=False,
        help="cyrus-beck: the clipped end points exact (default) or truncated.",
    ),
]


@app.command(context_settings=NUMERIC_ARGS, help=TRANSFORM_HELP)
@answers()
def transform(
    words: Annotated[
        list[str],
        typer.Argument(
            metavar="X1 Y1 ... --TRANSFORMATION ARGS ...",
            help="The points, then the transformations in the order they are applied.",
            show_default=False,
        ),
    ],
    inverse: Annotated[
        bool,
        typer.Option("--inverse", help="Also show the inverse of the composite matrix."),
    ] = False,
) -> Solution:
    return commands.transform(words, inverse)


@app.command(context_settings=NUMERIC_ARGS)
@answers()
def viewport(
    window: Window,
    viewport: Viewport,
    points: Annotated[
        list[Fraction] | None,
        typer.Argument(
            parser=number,
            metavar="[X1 Y1 ...]",
            help="World points to map (default: the window's four corners).",
            show_default=False,
        ),
    ] = None,
) -> Solution:
    """Window-to-viewport mapping: sx, sy, tx, ty with the numbers substituted, the composite
    matrix, each point mapped, and the distortion when sx != sy.

    Example: scanconv viewport 0 0 2 1 --window 0 0 4 4 --viewport 10 10 20 16
    """
    return api.viewport(window, viewport, points or [])


@clip_app.command("line", context_settings=NUMERIC_ARGS)
@answers()
def clip_line(
    x1: Num,
    y1: Num,
    x2: Num,
    y2: Num,
    window: Window,
    method: Annotated[
        LineClipMethod,
        typer.Option("--method", "-m", case_sensitive=False, help="Line clipping method."),
    ] = LineClipMethod.cohen_sutherland,
    normals: NormalsOpt = None,
    ends: EndsOpt = None,
    midpoint: Annotated[
        Midpoint | None,
        typer.Option(
            "--midpoint",
            case_sensitive=False,
            help="midpoint-subdivision: each midpoint rounded (default), floored or exact.",
        ),
    ] = None,
    stop: Annotated[
        MidpointStop | None,
        typer.Option(
            "--stop",
            case_sensitive=False,
            help="midpoint-subdivision: split until one unit long (length, default), or also "
            "stop where a midpoint lands on the window's edge (edge).",
        ),
    ] = None,
) -> Solution:
    """Clip the segment (X1, Y1)-(X2, Y2) against the window: region codes (T B R L) and one
    row per iteration (Cohen-Sutherland), the p_k, q_k table and u1, u2 (Liang-Barsky), t per
    edge (Cyrus-Beck), each midpoint and its outcode (midpoint subdivision) or P1's region, the
    slope tests against the rays to the corners and P2's region (Nicholl-Lee-Nicholl).

    Example: scanconv clip line 7 9 11 4 --window 4 4 10 8 --method cohen-sutherland
    """
    return commands.clip_line(x1, y1, x2, y2, window, method, normals, ends, midpoint, stop)


@clip_app.command("convex", context_settings=NUMERIC_ARGS)
@answers()
def clip_convex(
    words: Annotated[
        list[str],
        typer.Argument(
            metavar="X1 Y1 X2 Y2 --window-vertices X Y X Y X Y ...",
            help="The segment's end points, then --window-vertices and the convex window's "
            "vertices in order.",
            show_default=False,
        ),
    ],
    normals: NormalsOpt = None,
    ends: EndsOpt = None,
) -> Solution:
    """Cyrus-Beck: clip the segment against any convex window, with each edge's normal, t,
    entering or leaving, and tE, tL.

    Example: scanconv clip convex -1 2 9 2 --window-vertices 0 0 8 0 0 8
    """
    return commands.clip_convex(words, normals, ends)


@clip_app.command("polygon", context_settings=NUMERIC_ARGS)
@answers()
def clip_polygon(
    words: Annotated[
        list[str],
        typer.Argument(
            metavar="X1 Y1 X2 Y2 X3 Y3 ... [--window-vertices X Y X Y X Y ...]",
            help="The polygon's vertices in order; then, for a window of any shape, "
            "--window-vertices and its vertices in order (convex for Sutherland-Hodgman).",
            show_default=False,
        ),
    ],
    window: Annotated[
        Rect | None,
        typer.Option(
            "--window",
            "-w",
            parser=number,
            metavar="XMIN YMIN XMAX YMAX",
            show_default=False,
            help="A rectangular clipping window in world coordinates (closed: its edges are "
            "inside); or give --window-vertices after the polygon.",
        ),
    ] = None,
    method: Annotated[
        PolygonClipMethod,
        typer.Option("--method", "-m", case_sensitive=False, help="Polygon clipping method."),
    ] = PolygonClipMethod.sutherland_hodgman,
) -> Solution:
    """Clip a polygon against the window edge by edge (left, right, bottom, top; a polygon
    window's edges in order): one table per edge, the clipped polygon, and the degenerate
    edges a concave polygon leaves.

    Example: scanconv clip polygon 100 150 200 250 300 200 --window 150 150 200 200

    Against a triangle: scanconv clip polygon 0 0 4 0 4 4 0 4 --window-vertices 1 -1 6 4 1 4
    """
    return commands.clip_polygon(words, window, method)


@pipeline_app.command("line", context_settings=NUMERIC_ARGS)
@answers()
def pipeline_line(
    x1: Num,
    y1: Num,
    x2: Num,
    y2: Num,
    window: Window,
    viewport: Viewport,
    algo: Annotated[
        LineAlgorithm,
        typer.Option("--algo", "-a", case_sensitive=False, help="Line algorithm."),
    ] = LineAlgorithm.bresenham,
    clip: Annotated[
        LineClipMethod,
        typer.Option("--clip", case_sensitive=False, help="Line clipping method."),
    ] = LineClipMethod.cohen_sutherland,
) -> Solution:
    """A world-coordinate line through the whole process: clip against the window, map to the
    viewport, round the end points, scan convert, and show the frame buffer.

    Example: scanconv pipeline line -5 0 15 10 --window 0 0 10 10 --viewport 0 0 20 10
    """
    return api.pipeline_line(x1, y1, x2, y2, window, viewport, algo=algo, clip=clip)


@pipeline_app.command("polygon", context_settings=NUMERIC_ARGS)
@answers()
def pipeline_polygon(
    vertices: Vertices,
    window: Window,
    viewport: Viewport,
    fill: Annotated[
        bool,
        typer.Option("--fill/--outline", help="Scan-line fill the polygon, or draw its edges."),
    ] = False,
    rule: Annotated[
        FillRule, typer.Option("--rule", case_sensitive=False, help="Fill rule (with --fill).")
    ] = FillRule.even_odd,
) -> Solution:
    """A world-coordinate polygon through the process: Sutherland-Hodgman against the window,
    the vertices mapped to the viewport, then its edges (Bresenham) or its scan-line fill.

    Example: scanconv pipeline polygon -2 0 6 0 2 6 --window 0 0 4 4 --viewport 0 0 8 8 --fill
    """
    return api.pipeline_polygon(vertices, window, viewport, fill=fill, rule=rule)
