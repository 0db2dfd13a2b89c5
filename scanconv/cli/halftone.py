"""Halftoning: ``halftone`` (the patterns of an N x N cell) and ``printer`` (a printer's
halftone arithmetic: dots per inch, lines per inch, the cell and its levels), declared by
their library functions (:mod:`scanconv._api.dither`)."""

from __future__ import annotations

from .application import app
from .declared import command

command(
    app,
    ("halftone",),
    help="""Halftone patterns: the N^2 + 1 levels an N x N cell gives and the pattern of each level.

    Example: scanconv halftone 3 --order clustered
    """,
)
command(
    app,
    ("printer",),
    help="""Halftone printing: from two of dpi, lpi and the cell (or the levels), the rest.

    Example: scanconv printer --dpi 300 --lpi 60
    """,
)
