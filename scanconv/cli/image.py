"""Image representation: ``storage``, ``quantize``, ``sample`` and ``image ramp`` (all but
``quantize`` declared by their library functions, :mod:`scanconv._api.image`)."""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from typing import Annotated

from .. import _api as api
from ..core.records import Solution
from .application import app, image_app
from .command import answers
from .declared import command
from .options import NUMERIC_ARGS, choice, num_option


class InputKind(str, Enum):
    """What the input range of ``quantize --range`` holds."""

    integer = "integer"
    real = "real"


class Recon(str, Enum):
    """Reconstruction value of a quantization level."""

    mid = "midpoint"
    low = "lower"  # not ``lower``: that name is str.lower


_BITS = num_option("--bits", help="Bits per pixel B (1-24; storage also 32, 48, 64).")
"""``quantize --bits`` (storage's is declared with it: :data:`scanconv._api.params.BITS`)."""


command(
    app,
    ("storage",),
    help="""Storage of an M x N image: M x N x ceil(log2 L) bits, in bytes, KB/MB and KiB/MiB.

    Give exactly one of --levels, --bits, --binary, --color.
    Example: scanconv storage 1024 768 --levels 256
    """,
)


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def quantize(
    bits: Annotated[Fraction, _BITS],
    value_range: Annotated[
        tuple[Fraction, Fraction] | None,
        num_option(
            "--range",
            metavar="LO HI",
            help="Input range: add each level's inputs and reconstruction value.",
        ),
    ] = None,
    kind: Annotated[
        InputKind,
        choice(
            "--input",
            help="integer: the inputs are the integers LO..HI (8-bit: --range 0 255); "
            "real: any value in [LO, HI].",
        ),
    ] = InputKind.integer,
    recon: Annotated[
        Recon,
        choice(
            "--recon",
            help="Reconstruction value: the midpoint of each level's cell or its lower end.",
        ),
    ] = Recon.mid,
) -> Solution:
    """The quantization table: decimal value, binary code and gray-level name of each level.

    Example: scanconv quantize --bits 3 --range 0 255
    """
    return api.quantize(bits, value_range, integer=kind is InputKind.integer, recon=recon.value)


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
