"""Visible-surface detection: ``3d backface`` (the sign test of each face's normal),
``3d zbuffer`` (the depth buffer on a small grid), ``3d scanline`` (the scan-line method), ``3d depth-sort`` (the painter's method) and
``3d warnock`` (area subdivision)."""

from __future__ import annotations

from .application import three_d_app
from .declared import command

command(
    three_d_app,
    ("3d", "backface"),
    help="""Back-face detection: each face's normal N = (V2 - V1) x (V3 - V1) with its numbers,
    the view vector V, the sign of V.N and the table of faces, visible or hidden.

    Example: scanconv 3d backface --solid cube
    """,
)
command(
    three_d_app,
    ("3d", "zbuffer"),
    help="""The z-buffer on a small grid: each polygon's plane and depth increments (-A/C along a
    scan line, (A/m + B)/C down an edge), the depth comparisons and buffer updates, the final
    frame and depth buffers.

    Example: scanconv 3d zbuffer 0 0 2 5 0 2 0 5 2 : 1 1 4 5 1 0 1 5 0 --size 5
    """,
)
command(
    three_d_app,
    ("3d", "warnock"),
    help="""Warnock's area subdivision: the windows depth first (the quadtree), each polygon's
    class against each window (surrounding, intersecting, contained, disjoint), the test that
    decides it, and the final frame.

    Example: scanconv 3d warnock 0 0 1 6 0 1 0 6 1 : 2 2 3 7 2 3 2 7 3 --size 8
    """,
)
command(
    three_d_app,
    ("3d", "scanline"),
    help="""The scan-line method: the edge and polygon tables, each scan line's active edge list
    with the polygons' in/out flags, the depth comparison where two flags are on, the frame.

    Example: scanconv 3d scanline 0 0 1 4 0 1 0 4 1 : 1 0 2 4 0 2 4 3 2 --size 5
    """,
)
command(
    three_d_app,
    ("3d", "depth-sort"),
    help="""The depth-sort (painter's) method: the polygons by farthest depth, each pair's tests
    in order (z, x and y extents, behind the other's plane, in front of it, the projections),
    the painting order and the frame painted.

    Example: scanconv 3d depth-sort 0 0 1 4 0 1 0 4 1 : 1 1 3 5 1 3 1 5 3 --size 6
    """,
)
