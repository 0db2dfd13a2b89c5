"""``scanconv color``: colour-model conversions with the working (RGB, CMY, HSV, HSI, grey)."""

from __future__ import annotations

from fractions import Fraction
from typing import Annotated

import typer

from ..core.records import Solution
from ..questions import commands
from .application import app
from .command import answers
from .options import NUMERIC_ARGS, num_option

_MODELS = "rgb, cmy, hsv, hsi, grey"


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def color(
    model: Annotated[str, typer.Argument(metavar="MODEL", help=f"The model given: {_MODELS}.")],
    values: Annotated[
        list[str],
        typer.Argument(
            metavar="VALUES...",
            help="Its components: R G B (0..255; 0..1 with --unit), C M Y (0..1), H S V or "
            "H S I (H in degrees, S, V, I in 0..1), or one grey level Y.",
        ),
    ],
    to: Annotated[
        list[str] | None,
        typer.Option(
            "--to",
            metavar="MODEL...",
            help=f"The models to convert to ({_MODELS}; several: --to cmy hsv hsi). "
            "Default: every other one.",
        ),
    ] = None,
    unit: Annotated[
        bool, typer.Option("--unit", help="RGB and grey are in 0..1 (default: 0..2^bits - 1).")
    ] = False,
    bits: Annotated[
        Fraction | None,
        num_option("--bits", help="Bits per RGB channel (default 8: 0..255, 24-bit colour)."),
    ] = None,
) -> Solution:
    """Convert a colour between RGB, CMY, HSV, HSI and grey, formulas worked with its numbers.

    The RGB answer adds the true-colour breakdown: each channel's bits, the hex code, bits
    per pixel.
    Example: scanconv color rgb 51 102 153 --to cmy hsv hsi
    """
    return commands.color(model, values, to, unit, bits)
