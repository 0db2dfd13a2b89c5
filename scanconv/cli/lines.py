"""``scanconv line``: its parameters are :func:`scanconv._api.shapes.line`'s declaration."""

from .application import app
from .declared import command

command(
    app,
    ("line",),
    help="""Draw the line from (X1, Y1) to (X2, Y2), with the step table of the chosen algorithm.

    Example: scanconv line 2 2 10 6 --algo bresenham --svg line.svg
    """,
)
