"""The scan-conversion process around scan conversion: ``transform``, ``viewport``,
``clip line``, ``clip polygon`` and ``pipeline line``."""

from __future__ import annotations

from .application import app, clip_app, pipeline_app
from .declared import command

command(
    app,
    ("transform",),
    help="""Compose 2D transformations (homogeneous coordinates, column vectors) and
apply them to the points X1 Y1 X2 Y2 ..., in the order given.

Transformations, composed left to right:
--translate TX TY; --scale S [SY]; --rotate ANGLE; --shear SHX SHY (each of these three may be
followed by --about X Y); --reflect x-axis|y-axis|origin|y=x|y=-x; --reflect line X1 Y1 X2 Y2.
ANGLE is in degrees (90, -30) or radians (pi/4, 3pi/2, 1.2rad); multiples of 15 degrees are
exact (sqrt(2)/2), other angles are rounded to 6 decimals.

Example: scanconv transform 0 0 4 0 4 3 --rotate 90 --about 2 1 --translate 3 0
""",
)


command(
    app,
    ("viewport",),
    help="""Window-to-viewport mapping: sx, sy, tx, ty with the numbers substituted, the composite
    matrix, each point mapped, and the distortion when sx != sy.

    Example: scanconv viewport 0 0 2 1 --window 0 0 4 4 --viewport 10 10 20 16
    """,
)


command(
    clip_app,
    ("clip", "line"),
    help="""Clip the segment (X1, Y1)-(X2, Y2) against the window: region codes (T B R L) and one
    row per iteration (Cohen-Sutherland), the p_k, q_k table and u1, u2 (Liang-Barsky), t per
    edge (Cyrus-Beck), each midpoint and its outcode (midpoint subdivision) or P1's region, the
    slope tests against the rays to the corners and P2's region (Nicholl-Lee-Nicholl).

    Example: scanconv clip line 7 9 11 4 --window 4 4 10 8 --method cohen-sutherland
    """,
)


command(
    clip_app,
    ("clip", "convex"),
    help="""Cyrus-Beck: clip the segment against any convex window, with each edge's normal, t,
    entering or leaving, and tE, tL.

    Example: scanconv clip convex -1 2 9 2 --window-vertices 0 0 8 0 0 8
    """,
)


command(
    clip_app,
    ("clip", "polygon"),
    help="""Clip a polygon against the window edge by edge (left, right, bottom, top; a polygon
    window's edges in order): one table per edge, the clipped polygon, and the degenerate
    edges a concave polygon leaves.

    Example: scanconv clip polygon 100 150 200 250 300 200 --window 150 150 200 200

    Against a triangle: scanconv clip polygon 0 0 4 0 4 4 0 4 --window-vertices 1 -1 6 4 1 4
    """,
)


command(
    pipeline_app,
    ("pipeline", "line"),
    help="""A world-coordinate line through the whole process: clip against the window, map to the
    viewport, round the end points, scan convert, and show the frame buffer.

    Example: scanconv pipeline line -5 0 15 10 --window 0 0 10 10 --viewport 0 0 20 10
    """,
)


command(
    pipeline_app,
    ("pipeline", "polygon"),
    help="""A world-coordinate polygon through the process: Sutherland-Hodgman against the window,
    the vertices mapped to the viewport, then its edges (Bresenham) or its scan-line fill.

    Example: scanconv pipeline polygon -2 0 6 0 2 6 --window 0 0 4 4 --viewport 0 0 8 8 --fill
    """,
)
