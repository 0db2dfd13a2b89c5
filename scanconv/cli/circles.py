"""``scanconv circle`` and ``scanconv ellipse``: their parameters are the declarations of
:func:`scanconv._api.shapes.circle` and :func:`~scanconv._api.shapes.ellipse`."""

from .application import app
from .declared import command

command(
    app,
    ("circle",),
    help="""Draw the circle of radius R: one octant's step table, the 8-way symmetry, the pixels.

    Example: scanconv circle 8 --center 10 10 --method bresenham
    """,
)
command(
    app,
    ("ellipse",),
    help="""Draw the ellipse with semi-axes RX, RY by the midpoint method (regions 1 and 2).

    Example: scanconv ellipse 8 6 --center 0 0
    """,
)
