"""The notes' other primitives: ``polygon`` (scan-line fill), ``fill boundary`` and
``fill flood`` (seed fills), ``antialias line``, ``antialias circle`` and
``antialias polygon``."""

from __future__ import annotations

from .application import _subapp, app
from .declared import command

fill_app = _subapp(
    "fill", "Seed fills from a pixel: boundary fill and flood fill, 4- or 8-connected."
)
antialias_app = _subapp(
    "antialias", "Anti-aliasing: Wu's line, unweighted area sampling and supersampling."
)

command(
    app,
    ("polygon",),
    help="""Scan-line polygon fill: the edge table, then per scan line the active edge table, the
    intersections, the spans and pixels filled (pixel centres; half-open spans and edges).

    Example: scanconv polygon 2 3 7 1 13 5 13 11 7 7 2 9
    """,
)
command(
    fill_app,
    ("fill", "boundary"),
    help="""Boundary fill from a seed: fill every pixel that is neither the boundary nor filled,
    with the trace of the stack or queue and the filled grid.

    Example: scanconv fill boundary 4 1 7 4 4 7 1 4 --seed 4 4 --connectivity 8

    """,
)
command(
    fill_app,
    ("fill", "flood"),
    help="""Flood fill from a seed: replace the seed's colour in its connected region, with the
    trace of the stack or queue and the filled grid.

    Example: scanconv fill flood --rows '#####/#...#/#.x.#/#####' --seed 1 1

    """,
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
