"""``scanconv compare line``, ``compare circle`` and ``compare curves``: every method side by
side, and (with ``--theory``) the points of the notes' comparison questions; declared by
their library functions (:mod:`scanconv._api.shapes`)."""

from .application import compare_app
from .declared import command

command(
    compare_app,
    ("compare", "line"),
    help="""The basic method, DDA and Bresenham for one line: one row per major-axis coordinate.

    Example: scanconv compare line 2 8 10 4 --theory
    """,
)
command(
    compare_app,
    ("compare", "circle"),
    help="""Every circle method over the first octant (one row per x), against the midpoint method.

    Example: scanconv compare circle 10 --theory
    """,
)
command(
    compare_app,
    ("compare", "curves"),
    help="""Bezier vs B-spline curves: the points the notes' comparison question expects.

    Example: scanconv compare curves
    """,
)
