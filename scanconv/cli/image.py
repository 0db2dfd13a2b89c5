"""Image representation: ``storage``, ``quantize``, ``sample`` and ``image ramp``, declared by
their library functions (:mod:`scanconv._api.image`)."""

from __future__ import annotations

from .application import app, image_app
from .declared import command

command(
    app,
    ("storage",),
    help="""Storage of an M x N image: M x N x ceil(log2 L) bits, in bytes, KB/MB and KiB/MiB.

    Give exactly one of --levels, --bits, --binary, --color.
    Example: scanconv storage 1024 768 --levels 256
    """,
)


command(
    app,
    ("quantize",),
    help="""The quantization table: decimal value, binary code and gray-level name of each level.

    Example: scanconv quantize --bits 3 --range 0 255
    """,
)
command(
    app,
    ("sample",),
    help="""Sample f(x, y) on an M x N grid, quantize to L levels: the matrix and a shaded picture.

    Example: scanconv sample "x + y" --size 8x8 --levels 8
    """,
)
command(
    image_app,
    ("image", "ramp"),
    help="""The notes' grayscale example: level i + j folded back at L - 1, for any size and L.

    Example: scanconv image ramp --size 8 --levels 8
    """,
)
