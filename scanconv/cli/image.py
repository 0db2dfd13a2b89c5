"""Image representation: ``storage``, ``quantize``, ``sample`` and ``image ramp``."""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from typing import Annotated

import typer

from .. import _api as api
from ..core.records import Solution
from .application import app, image_app
from .command import answers
from .options import (
    NUMERIC_ARGS,
    Origin,
    Size,
    choice,
    num_arg,
    num_option,
)


class ColorModel(str, Enum):
    """Colour pixel formats of ``storage --color``."""

    rgb24 = "rgb24"


class InputKind(str, Enum):
    """What the input range of ``quantize --range`` holds."""

    integer = "integer"
    real = "real"


class Recon(str, Enum):
    """Reconstruction value of a quantization level."""

    mid = "midpoint"
    low = "lower"  # not ``lower``: that name is str.lower


_BITS = num_option("--bits", help="Bits per pixel B (1-24; storage also 32, 48, 64).")


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def storage(
    m: Annotated[
        Fraction, num_arg("M, the first size (1024 in 1024 x 768; 1024x768 works too).", "M")
    ],
    n: Annotated[Fraction, num_arg("N, the second size (768 in 1024 x 768).", "N")],
    levels: Annotated[
        Fraction | None, num_option("--levels", "-L", help="Gray levels L (k = ceil(log2 L)).")
    ] = None,
    bits: Annotated[Fraction | None, _BITS] = None,
    binary: Annotated[
        bool, typer.Option("--binary", help="Binary image: 1 bit per pixel.")
    ] = False,
    color: Annotated[
        ColorModel | None, choice("--color", help="Colour image: rgb24 = 24 bits.")
    ] = None,
    frames: Annotated[
        Fraction | None, num_option("--frames", help="Number of frames F (default 1).")
    ] = None,
) -> Solution:
    """Storage of an M x N image: M x N x ceil(log2 L) bits, in bytes, KB/MB and KiB/MiB.

    Give exactly one of --levels, --bits, --binary, --color.
    Example: scanconv storage 1024 768 --levels 256
    """
    return api.storage(
        m,
        n,
        levels=levels,
        bits=bits,
        binary=binary,
        color=None if color is None else color.value,
        frames=1 if frames is None else frames,
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


@app.command(context_settings=NUMERIC_ARGS)
@answers(picture=True)
def sample(
    expr: Annotated[
        str, typer.Argument(metavar="EXPR", help="f(x, y), e.g. 'x + y' or 'sin(x)*cos(y)'.")
    ],
    size: Size,
    levels: Annotated[Fraction, num_option("--levels", "-L", help="Gray levels L.")],
    domain: Annotated[
        tuple[str, str, str, str] | None,
        typer.Option(
            "--domain",
            metavar="X0 X1 Y0 Y1",
            help="Sample x from X0 to X1 and y from Y0 to Y1 (default: 0..N-1, 0..M-1).",
        ),
    ] = None,
    value_range: Annotated[
        tuple[str, str] | None,
        typer.Option(
            "--range",
            metavar="LO HI",
            help="Range of f quantized onto the levels (default: the samples' min and max).",
        ),
    ] = None,
    origin: Annotated[
        Origin,
        choice(
            "--origin", help="Row 0 is the top: bottom-left: y up (row 0 is y1); top-left: y down."
        ),
    ] = Origin.bottom_left,
) -> Solution:
    """Sample f(x, y) on an M x N grid, quantize to L levels: the matrix and a shaded picture.

    Example: scanconv sample "x + y" --size 8x8 --levels 8
    """
    return api.sample(
        expr, size, levels, domain=domain, value_range=value_range, origin=origin.value
    )


@image_app.command("ramp")
@answers(picture=True, origin=False)
def image_ramp(
    size: Size = "8",
    levels: Annotated[
        Fraction | None, num_option("--levels", "-L", help="Gray levels L (default 8).")
    ] = None,
) -> Solution:
    """The notes' grayscale example: level i + j folded back at L - 1, for any size and L.

    Example: scanconv image ramp --size 8 --levels 8
    """
    return api.ramp(size, 8 if levels is None else levels)
