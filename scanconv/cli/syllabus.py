"""The rest of the syllabus: ``dither``, ``halftone``, ``inside``, ``framebuffer``,
``linestyle``, ``thickline`` and ``char``."""

from __future__ import annotations

from .application import app, char_app, dither_app
from .declared import command

command(
    dither_app,
    ("dither", "threshold"),
    help="""Thresholding: each pixel on (TOP) when its value passes one threshold, else 0.

    Example: scanconv dither threshold --image "10 200; 60 90" --at 128
    """,
)


command(
    dither_app,
    ("dither", "ordered"),
    help="""Ordered dither: the threshold matrix tiled over the image, one comparison per pixel.

    Example: scanconv dither ordered --image "10 200; 60 90" --matrix 2
    """,
)
command(
    dither_app,
    ("dither", "lookup"),
    help="""A pixel's dither threshold from its screen position: T[y mod n][x mod n].

    Example: scanconv dither lookup 5 2 --matrix 4 --value 100
    """,
)


command(
    app,
    ("inside",),
    help="""Inside-outside test: each point against each edge, the crossings and the winding number.

    Example: scanconv inside 0 0 6 0 6 6 3 2 0 6 --points 3 1 3 4
    """,
)


# --- declared by their library functions (scanconv._api.dither, scanconv._api.syllabus) ----

command(
    dither_app,
    ("dither", "floyd-steinberg"),
    help="""Error diffusion (Floyd-Steinberg): each pixel set to 0 or TOP, its error shared out.

    Example: scanconv dither floyd-steinberg --image "100 100; 100 100"
    """,
)
command(
    app,
    ("framebuffer",),
    help="""Frame-buffer arithmetic: pixels, size, bit planes, a look-up table, load and refresh
    times, retrace, and a pixel's address.

    Example: scanconv framebuffer 640 480 8 --pixel 340 150
    """,
)
command(
    app,
    ("linestyle",),
    help="""A dashed or dotted line: Bresenham's pixels, each drawn when its mask bit is 1.

    Example: scanconv linestyle 0 0 12 4 --mask 1110
    """,
)
command(
    app,
    ("thickline",),
    help="""A thick line by pixel replication across the minor axis, or by a square brush.

    Example: scanconv thickline 0 0 8 3 --width 3
    """,
)
command(
    char_app,
    ("char", "bitmap"),
    help="""A character drawn from its bitmap: each row's pixels, placed and scaled, and the glyph
    packed into bytes row by row.

    Example: scanconv char bitmap A --at 2 1
    """,
)
command(
    char_app,
    ("char", "stroke"),
    help="""A stroke character: each of its line segments drawn by a line algorithm.

    Example: scanconv char stroke T --scale 2
    """,
)


command(
    char_app,
    ("char", "storage"),
    help="""A bitmap font's storage: the bytes per glyph and for the whole font, and the font
    table: each glyph's address, one after another.

    Example: scanconv char storage 128 5 7
    """,
)
