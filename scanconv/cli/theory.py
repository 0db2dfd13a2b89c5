"""``scanconv theory``: the model answer to a define / explain / describe question of the notes,
with a live example (declared on :func:`scanconv._api.theory`; ``--list`` lists the topics)."""

from __future__ import annotations

from .application import app
from .declared import command

command(
    app,
    ("theory",),
    help="""The model answer to a theory question of the notes, with a live example.

    Definition, key points, the notes' tables, advantages and limitations, and an example
    computed by scanconv (a grid, a step table, a pixel's bits).
    Example: scanconv theory raster-display
    """,
)
