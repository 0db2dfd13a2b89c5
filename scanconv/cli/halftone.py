"""Halftoning: ``halftone`` (the patterns of an N x N cell) and ``printer`` (a printer's
halftone arithmetic: dots per inch, lines per inch, the cell and its levels)."""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from typing import Annotated

import typer

from ..core.records import Solution
from ..questions import commands
from .application import app
from .command import answers
from .options import NUMERIC_ARGS, choice, num_arg, num_option


class CellOrder(str, Enum):
    """How a halftone cell fills."""

    bayer = "bayer"
    clustered = "clustered"


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def halftone(
    n: Annotated[Fraction, num_arg("N, the halftone cell's width: 1 to 16.", "N")],
    level: Annotated[
        Fraction | None, num_option("--level", "-l", help="Only the pattern of this level.")
    ] = None,
    bits: Annotated[
        Fraction | None, num_option("--bits", help="Bits per pixel of the device (default 1).")
    ] = None,
    order: Annotated[
        CellOrder,
        choice(
            "--order",
            help="bayer: the cell fills in the Bayer matrix's order (dispersed); clustered: a "
            "dot grows from the centre.",
        ),
    ] = CellOrder.bayer,
    matrix: Annotated[
        str | None,
        typer.Option(
            "--matrix",
            "-m",
            metavar="ROWS",
            help="The cell's order given: N x N rows holding 0..N^2-1 (or 1..N^2) once each.",
        ),
    ] = None,
) -> Solution:
    """Halftone patterns: the N^2 + 1 levels an N x N cell gives and the pattern of each level.

    Example: scanconv halftone 3 --order clustered
    """
    return commands.halftone(n, level, bits, order, matrix)


class LevelCount(str, Enum):
    """An n x n halftone cell's levels: n^2 + 1 or n^2."""

    plus_one = "n2+1"
    squares = "n2"


class PrinterDots(str, Enum):
    """The cell from dpi / lpi: whole dots, or the ratio itself."""

    whole = "whole"
    exact = "exact"


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def printer(
    dpi: Annotated[
        Fraction | None, num_option("--dpi", help="The printer's dots per inch.")
    ] = None,
    lpi: Annotated[
        Fraction | None,
        num_option("--lpi", help="The halftone screen's lines (cells) per inch."),
    ] = None,
    cell: Annotated[
        Fraction | None, num_option("--cell", help="The halftone cell's side N, in dots.")
    ] = None,
    levels: Annotated[
        Fraction | None,
        num_option("--levels", help="The grey levels wanted: the smallest cell giving them."),
    ] = None,
    count: Annotated[
        LevelCount,
        choice("--count", help="An N x N cell's levels: n2+1 (0..N^2 dots on) or n2."),
    ] = LevelCount.plus_one,
    dots: Annotated[
        PrinterDots,
        choice("--dots", help="The cell from dpi / lpi: whole dots (rounded down) or exact."),
    ] = PrinterDots.whole,
) -> Solution:
    """Halftone printing: from two of dpi, lpi and the cell (or the levels), the rest.

    Example: scanconv printer --dpi 300 --lpi 60
    """
    return commands.printer(dpi, lpi, cell, levels, count, dots)
