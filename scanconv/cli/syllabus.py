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
from .options import NUMERIC_ARGS, choice, num_arg, num_option


class Compare(str, Enum):
    """When a dithered pixel is on: its value above the threshold, or at least it."""

    gt = ">"
    ge = ">="


class DitherScale(str, Enum):
    """How a dither matrix's entries become thresholds."""

    raw = "raw"
    centered = "centered"


class Base(str, Enum):
    """Whether a dither matrix's entries count from 0 or from 1."""

    zero = "0"
    one = "1"


class Kernel(str, Enum):
    """The error-diffusion kernels."""

    floyd_steinberg = "floyd-steinberg"
    simple = "simple"


class ScanOrder(str, Enum):
    """The order error diffusion visits the pixels in."""

    raster = "raster"
    serpentine = "serpentine"


class Arithmetic(str, Enum):
    """Error shares kept exact or truncated to integers."""

    exact = "exact"
    integer = "integer"


class Carry(str, Enum):
    """What a neighbour does with a negative carried value."""

    kept = "kept"
    clamped = "clamped"


class InsideRule(str, Enum):
    """The inside-outside rules."""

    both = "both"
    even_odd = "even-odd"
    nonzero = "nonzero"


class Boundary(str, Enum):
    """What a point on the polygon's boundary is."""

    inside = "inside"
    outside = "outside"
    left_bottom = "left-bottom"


class BitOrder(str, Enum):
    """Which end of a line mask is applied first; which bit of a byte a glyph row's leftmost
    pixel is."""

    msb = "msb"
    lsb = "lsb"


class StrokeAlgo(str, Enum):
    """The line algorithms a stroke character is drawn with."""

    bresenham = "bresenham"
    dda = "dda"


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


@dither_app.command("threshold", context_settings=NUMERIC_ARGS)
@answers(picture=True, origin=False)
def dither_threshold(
    image: Image,
    top: Top = TOP,
    at: Annotated[
        Fraction | None, num_option("--at", "-t", help="The threshold T (default TOP / 2).")
    ] = None,
    compare: CompareOpt = Compare.ge,
) -> Solution:
    """Thresholding: each pixel on (TOP) when its value passes one threshold, else 0.

    Example: scanconv dither threshold --image "10 200; 60 90" --at 128
    """
    return commands.dither_threshold(image, top, at, compare)


@dither_app.command("ordered", context_settings=NUMERIC_ARGS)
@answers(picture=True, origin=False)
def dither_ordered(
    image: Image,
    top: Top = TOP,
    matrix: Annotated[
        str,
        typer.Option(
            "--matrix",
            "-m",
            metavar="N|ROWS",
            help="The Bayer matrix of order 2, 4, 8 or 16, or a matrix's rows as --image's.",
        ),
    ] = "2",
    compare: CompareOpt = Compare.gt,
    scale: Annotated[
        DitherScale,
        choice(
            "--scale",
            help="Thresholds: raw (D x TOP / n^2) or centered ((D + 1/2) x TOP / n^2).",
        ),
    ] = DitherScale.raw,
    base: Annotated[
        Base, choice("--base", help="The matrix's entries count from 0 or from 1.")
    ] = Base.zero,
    transpose: Annotated[
        bool, typer.Option("--transpose", help="Index the matrix by x first (its transpose).")
    ] = False,
) -> Solution:
    """Ordered dither: the threshold matrix tiled over the image, one comparison per pixel.

    Example: scanconv dither ordered --image "10 200; 60 90" --matrix 2
    """
    return commands.dither_ordered(image, top, matrix, compare, scale, base, transpose)


@dither_app.command("floyd-steinberg", context_settings=NUMERIC_ARGS)
@answers(picture=True, origin=False)
def dither_diffusion(
    image: Image,
    top: Top = TOP,
    kernel: Annotated[
        Kernel,
        choice("--kernel", help="floyd-steinberg (7, 3, 5, 1)/16 or simple (3, 3, 2)/8."),
    ] = Kernel.floyd_steinberg,
    order: Annotated[
        ScanOrder,
        choice("--order", help="raster: every row left to right; serpentine: alternate rows."),
    ] = ScanOrder.raster,
    arithmetic: Annotated[
        Arithmetic,
        choice("--arithmetic", help="Error shares kept exact or truncated to integers."),
    ] = Arithmetic.exact,
    carry: Annotated[
        Carry, choice("--carry", help="Negative carried values kept, or clamped at 0.")
    ] = Carry.kept,
    compare: CompareOpt = Compare.ge,
) -> Solution:
    """Error diffusion (Floyd-Steinberg): each pixel set to 0 or TOP, its error shared out.

    Example: scanconv dither floyd-steinberg --image "100 100; 100 100"
    """
    return commands.dither_diffusion(image, top, kernel, order, arithmetic, carry, compare)


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def halftone(
    n: Annotated[Fraction, num_arg("N, the halftone cell's width: 2, 4, 8 or 16.", "N")],
    level: Annotated[
        Fraction | None, num_option("--level", "-l", help="Only the pattern of this level.")
    ] = None,
    bits: Annotated[
        Fraction | None, num_option("--bits", help="Bits per pixel of the device (default 1).")
    ] = None,
) -> Solution:
    """Halftone patterns: the levels an N x N cell gives and the pattern of each level.

    Example: scanconv halftone 2
    """
    return commands.halftone(n, level, bits)


@app.command(context_settings=NUMERIC_ARGS)
@answers()
def inside(
    words: Annotated[
        list[str],
        typer.Argument(
            metavar="X1 Y1 X2 Y2 X3 Y3 ... --points X Y ...",
            help="The polygon's vertices in order, then --points and the points to test.",
            show_default=False,
        ),
    ],
    rule: Annotated[
        InsideRule, choice("--rule", help="even-odd, nonzero winding, or both.")
    ] = InsideRule.both,
    boundary: Annotated[
        Boundary,
        choice(
            "--boundary",
            help="A point on the boundary is inside, outside, or as the count says "
            "(left-bottom: on a left or bottom edge inside, a right or top edge outside).",
        ),
    ] = Boundary.inside,
) -> Solution:
    """Inside-outside test: each point against each edge, the crossings and the winding number.

    Example: scanconv inside 0 0 6 0 6 6 3 2 0 6 --points 3 1 3 4
    """
    return commands.inside(words, rule, boundary)


@app.command(context_settings=NUMERIC_ARGS)
@answers(grid=False)
def framebuffer(
    width: Annotated[Fraction, num_arg("W, pixels across.", "W")],
    height: Annotated[Fraction, num_arg("H, pixels down.", "H")],
    bits: Annotated[Fraction, num_arg("B, bits per pixel (bit planes).", "BITS")],
    lut: Annotated[
        Fraction | None,
        num_option("--lut", help="Bits of a colour look-up-table entry: the table's size."),
    ] = None,
    rate: Annotated[
        Fraction | None,
        num_option("--rate", help="Transfer rate in bits per second: the time to load a frame."),
    ] = None,
    refresh: Annotated[
        Fraction | None,
        num_option("--refresh", help="Refresh rate in Hz: the time to access a pixel."),
    ] = None,
    interlaced: Annotated[
        bool, typer.Option("--interlaced", help="Interlaced: --refresh counts fields.")
    ] = False,
) -> Solution:
    """Frame-buffer arithmetic: its size, bit planes and colours, a look-up table, load time.

    Example: scanconv framebuffer 1280 1024 8 --lut 24 --rate 1e6 --refresh 60
    """
    return commands.framebuffer(width, height, bits, lut, rate, refresh, interlaced)


_X1 = num_arg("x of the first end point P1.", "X1")
_Y1 = num_arg("y of the first end point P1.", "Y1")
_X2 = num_arg("x of the second end point P2.", "X2")
_Y2 = num_arg("y of the second end point P2.", "Y2")


@app.command("linestyle", context_settings=NUMERIC_ARGS)
@answers()
def line_style(
    x1: Annotated[Fraction, _X1],
    y1: Annotated[Fraction, _Y1],
    x2: Annotated[Fraction, _X2],
    y2: Annotated[Fraction, _Y2],
    mask: Annotated[
        str, typer.Option("--mask", metavar="BITS", help="The pixel mask, e.g. 1110 (dashes).")
    ],
    bits: Annotated[
        BitOrder,
        choice("--bits", help="Read the mask from its most (msb) or least (lsb) significant bit."),
    ] = BitOrder.msb,
    repeat: Annotated[
        Fraction | None, num_option("--repeat", help="Use each bit for N pixels (default 1).")
    ] = None,
) -> Solution:
    """A dashed or dotted line: Bresenham's pixels, each drawn when its mask bit is 1.

    Example: scanconv linestyle 0 0 12 4 --mask 1110
    """
    return commands.line_style(x1, y1, x2, y2, mask, bits, repeat)


@app.command("thickline", context_settings=NUMERIC_ARGS)
@answers()
def thick_line(
    x1: Annotated[Fraction, _X1],
    y1: Annotated[Fraction, _Y1],
    x2: Annotated[Fraction, _X2],
    y2: Annotated[Fraction, _Y2],
    width: Annotated[Fraction, num_option("--width", "-W", help="The line's width in pixels.")],
    brush: Annotated[
        bool, typer.Option("--brush", help="A square brush instead of pixel replication.")
    ] = False,
) -> Solution:
    """A thick line by pixel replication across the minor axis, or by a square brush.

    Example: scanconv thickline 0 0 8 3 --width 3
    """
    return commands.thick_line(x1, y1, x2, y2, width, brush)


Char = Annotated[
    str, typer.Argument(metavar="CHAR", help="The character (A-Z, 0-9).", show_default=False)
]
At = Annotated[
    tuple[Fraction, Fraction] | None,
    num_option("--at", metavar="X Y", help="The character's bottom-left corner (default 0 0)."),
]
Scale = Annotated[Fraction | None, num_option("--scale", help="Scale factor, 1..16 (default 1).")]


@char_app.command("bitmap", context_settings=NUMERIC_ARGS)
@answers()
def char_bitmap(
    char: Char,
    rows: Annotated[
        str | None,
        typer.Option(
            "--rows",
            "-r",
            metavar="ROWS",
            help="The glyph's rows, top first, separated by '/': 01110/10001/... (default: "
            "the 5 x 7 font's).",
        ),
    ] = None,
    at: At = None,
    scale: Scale = None,
    bit_order: Annotated[
        BitOrder,
        choice(
            "--bit-order",
            help="The glyph's bytes: a row's leftmost pixel the most significant bit (msb, "
            "the usual font: a row reads as written) or the least (lsb).",
        ),
    ] = BitOrder.msb,
) -> Solution:
    """A character drawn from its bitmap: each row's pixels, placed and scaled, and the glyph
    packed into bytes row by row.

    Example: scanconv char bitmap A --at 2 1
    """
    return commands.char_bitmap(char, rows, at, scale, bit_order)


@char_app.command("stroke", context_settings=NUMERIC_ARGS)
@answers()
def char_stroke(
    char: Char,
    at: At = None,
    scale: Scale = None,
    algo: Annotated[
        StrokeAlgo, choice("--algo", "-a", help="The line algorithm each stroke is drawn with.")
    ] = StrokeAlgo.bresenham,
) -> Solution:
    """A stroke character: each of its line segments drawn by a line algorithm.

    Example: scanconv char stroke T --scale 2
    """
    return commands.char_stroke(char, at, scale, algo)


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
