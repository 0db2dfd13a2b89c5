"""The rest of the syllabus: ``dither``, ``halftone``, ``inside``, ``framebuffer``,
``linestyle``, ``thickline`` and ``char``."""

from __future__ import annotations

from enum import Enum
from fractions import Fraction
from typing import Annotated

import typer

from ..core.records import Solution
from ..questions import commands
from .application import app, char_app, dither_app
from .command import answers
from .declared import command
from .options import NUMERIC_ARGS, choice, num_arg, num_option


class Compare(str, Enum):
    """When a dithered pixel is on: its value above the threshold, or at least it."""

    gt = ">"
    ge = ">="


class DitherScale(str, Enum):
    """How a dither matrix's entries become thresholds."""

    raw = "raw"
    centered = "centered"
    given = "given"


class Base(str, Enum):
    """Whether a dither matrix's entries count from 0 or from 1."""

    zero = "0"
    one = "1"


class Packing(str, Enum):
    """How a glyph's bits are packed into bytes."""

    rows = "rows"
    columns = "columns"
    bits = "bits"


Image = Annotated[
    str,
    typer.Option(
        "--image",
        "-i",
        metavar="ROWS",
        help="The image's values, rows separated by ';' (or '/'), values by spaces or commas: "
        "'10 200; 60 90'.",
    ),
]
Top = Annotated[
    Fraction,
    num_option("--top", help="The top of the scale: values run 0..TOP, an on pixel is TOP."),
]
CompareOpt = Annotated[
    Compare, choice("--compare", help="A pixel is on when its value is > or >= the threshold.")
]
TOP = Fraction(255)


command(
    dither_app,
    ("dither", "threshold"),
    help="""Thresholding: each pixel on (TOP) when its value passes one threshold, else 0.

    Example: scanconv dither threshold --image "10 200; 60 90" --at 128
    """,
)


MatrixOpt = Annotated[
    str,
    typer.Option(
        "--matrix",
        "-m",
        metavar="N|ROWS",
        help="The Bayer matrix of order 2, 4, 8 or 16, or a matrix's rows as --image's.",
    ),
]
ScaleOpt = Annotated[
    DitherScale,
    choice(
        "--scale",
        help="Thresholds: raw (D x TOP / n^2), centered ((D + 1/2) x TOP / n^2), or given "
        "(the matrix's entries are thresholds already, in the image's units).",
    ),
]
BaseOpt = Annotated[Base, choice("--base", help="The matrix's entries count from 0 or from 1.")]
TransposeOpt = Annotated[
    bool, typer.Option("--transpose", help="Index the matrix by x first (its transpose).")
]


@dither_app.command("ordered", context_settings=NUMERIC_ARGS)
@answers(picture=True, origin=False)
def dither_ordered(
    image: Image,
    top: Top = TOP,
    matrix: MatrixOpt = "2",
    compare: CompareOpt = Compare.gt,
    scale: ScaleOpt = DitherScale.raw,
    base: BaseOpt = Base.zero,
    transpose: TransposeOpt = False,
) -> Solution:
    """Ordered dither: the threshold matrix tiled over the image, one comparison per pixel.

    Example: scanconv dither ordered --image "10 200; 60 90" --matrix 2
    """
    return commands.dither_ordered(image, top, matrix, compare, scale, base, transpose)


@dither_app.command("lookup", context_settings=NUMERIC_ARGS)
@answers(grid=False)
def dither_lookup(
    pixels: Annotated[
        list[str],
        typer.Argument(
            metavar="X Y ...",
            help="The pixels' screen positions: x across, y down (row y), in pairs.",
            show_default=False,
        ),
    ],
    matrix: MatrixOpt = "4",
    top: Top = TOP,
    value: Annotated[
        Fraction | None,
        num_option("--value", help="The pixels' intensity: each is on when it passes T."),
    ] = None,
    count: Annotated[
        Base, choice("--count", help="Screen positions count from 0 or from 1.")
    ] = Base.zero,
    compare: CompareOpt = Compare.gt,
    scale: ScaleOpt = DitherScale.raw,
    base: BaseOpt = Base.zero,
    transpose: TransposeOpt = False,
) -> Solution:
    """A pixel's dither threshold from its screen position: T[y mod n][x mod n].

    Example: scanconv dither lookup 5 2 --matrix 4 --value 100
    """
    return commands.dither_lookup(
        pixels, matrix, top, value, count, compare, scale, base, transpose
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


@char_app.command("storage", context_settings=NUMERIC_ARGS)
@answers(grid=False)
def char_storage(
    count: Annotated[Fraction, num_arg("How many characters the font holds.", "COUNT")],
    width: Annotated[Fraction, num_arg("A glyph's width in pixels.", "WIDTH")],
    height: Annotated[Fraction, num_arg("A glyph's height in pixels.", "HEIGHT")],
    packing: Annotated[
        Packing,
        choice("--packing", help="A glyph in whole bytes per row, per column, or packed bits."),
    ] = Packing.rows,
    char: Annotated[
        str | None,
        typer.Option(
            "--char",
            metavar="C",
            help="A character whose glyph's number and address the font table gives.",
        ),
    ] = None,
    first: Annotated[
        Fraction | None,
        num_option(
            "--first", metavar="CODE", help="The code of the font's first glyph (default 0)."
        ),
    ] = None,
    base: Annotated[
        str | None,
        typer.Option(
            "--base",
            metavar="ADDRESS",
            help="The first glyph's byte address, decimal or 0x hexadecimal (default 0).",
        ),
    ] = None,
) -> Solution:
    """A bitmap font's storage: the bytes per glyph and for the whole font, and the font
    table: each glyph's address, one after another.

    Example: scanconv char storage 128 5 7
    """
    return commands.char_storage(count, width, height, packing, char, first, base)
