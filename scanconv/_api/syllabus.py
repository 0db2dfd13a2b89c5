"""The Python API: the rest of the syllabus (``scanconv inside``, ``framebuffer``,
``linestyle``, ``thickline``, ``char``; dithering is :mod:`scanconv._api.dither`). See
:mod:`scanconv._api`."""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, Literal

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt, words
from ..display import answers
from .params import X1, X2, Y1, Y2
from .values import (
    NumberLike,
    PointLike,
    PointsLike,
    _choice,
    _flat,
    _numbers,
    _optional,
    _pair,
    _whole,
)
from .words import inside_words

if TYPE_CHECKING:
    from ..answers.image import framebuffer as answers_framebuffer
    from ..answers.primitives import attributes as answers_attributes
    from ..answers.primitives import characters as answers_characters
    from ..answers.process.fill import inside as answers_inside
    from ..core.choices import (
        BitOrderName,
        BoundaryName,
        DitherCountName,
        InsideRuleName,
        MajorName,
        RowZeroName,
        StrokeAlgorithmName,
    )
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_attributes = lazy.module("scanconv.answers.primitives.attributes")
    answers_characters = lazy.module("scanconv.answers.primitives.characters")
    answers_framebuffer = lazy.module("scanconv.answers.image.framebuffer")
    answers_inside = lazy.module("scanconv.answers.process.fill.inside")

CHAR = Arg("The character (A-Z, 0-9).", "CHAR")
AT = Opt(
    "--at",
    metavar="X Y",
    help="The character's bottom-left corner (default 0 0).",
    show_default=False,
)
SCALE = Opt("--scale", help="Scale factor, 1..16 (default 1).", show_default=False)

MAX_GLYPH = 64
"""The largest glyph drawn from rows given (64 x 64 bits; scaled at most 16 times)."""


@answers
@words(
    "The polygon's vertices in order, then --points and the points to test.",
    "X1 Y1 X2 Y2 X3 Y3 ... --points X Y ...",
    inside_words,
)
def inside(
    vertices: PointsLike,
    points: PointsLike,
    *,
    rule: Annotated[
        InsideRuleName,
        Opt(
            "--rule",
            help="even-odd, nonzero winding, or both.",
            choices=("both", "even-odd", "nonzero"),
        ),
    ] = "both",
    boundary: Annotated[
        BoundaryName,
        Opt(
            "--boundary",
            help="A point on the boundary is inside, outside, or as the count says "
            "(left-bottom: on a left or bottom edge inside, a right or top edge outside).",
            choices=("inside", "outside", "left-bottom"),
        ),
    ] = "inside",
) -> Solution:
    """Whether points are inside a polygon (``scanconv inside``), by the even-odd rule, the nonzero
    winding rule or both.

    Parameters
    ----------
    vertices : sequence of (x, y), or flat numbers
        The polygon's vertices in order.
    points : sequence of (x, y), or flat numbers
        The points tested.
    rule : {"both", "even-odd", "nonzero"}, default "both"
        The rule: crossings of a ray from the point (odd: inside), the winding number (nonzero:
        inside), or both side by side.
    boundary : {"inside", "outside", "left-bottom"}, default "inside"
        What a point on the boundary counts as: inside, outside, or what the half-open count
        gives (``left-bottom``: on a left or bottom edge inside, on a right or top edge
        outside, the scan-line fill's pixel rule).

    Returns
    -------
    Answer
        For each point the ray ``y = y_P, x > x_P`` and the edges it crosses (with their
        signs), then the verdicts: ``point, boundary, crossings, even_odd, winding,
        nonzero``.

    Examples
    --------
    >>> sol = inside([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [(3, 1), (3, 4)])
    >>> for row in sol.tables[-1].rows():
    ...     print(row)
    ('P1 (3, 1)', '-', 1, 'inside (odd)', 1, 'inside')
    ('P2 (3, 4)', '-', 2, 'outside (even)', 0, 'outside')
    """
    return answers_inside.inside_solution(
        _flat(vertices, "vertices"),
        _flat(points, "points"),
        rule_name=_choice(rule, "rule"),
        boundary=_choice(boundary, "boundary"),
    )


# the frame buffer's address, retrace and screen-size options (declared once, here)
_FB_DPI = Opt("--dpi", help="Dots per inch: W and H are the screen's size in inches.")
_FB_PIXEL = Opt("--pixel", metavar="X Y", help="The pixel whose frame-buffer address is wanted.")
_FB_ADDRESS = Opt("--address", help="A byte address: the pixel stored there.")
_FB_BASE = Opt("--base", help="The frame buffer's first byte (default 0).", show_default=False)
_FB_MAJOR = Opt(
    "--major",
    help="The buffer holds rows (row-major) or columns.",
    choices=("row", "column"),
)
_FB_ROW0 = Opt(
    "--row0",
    help="y = 0 is the top scan line or the bottom one.",
    choices=("top", "bottom"),
)
_FB_COUNT = Opt("--count", help="x and y counted from 0 or from 1.", choices=("0", "1"))
_FB_HRETRACE = Opt("--hretrace", help="Horizontal retrace time, seconds (with --refresh).")
_FB_VRETRACE = Opt("--vretrace", help="Vertical retrace time, seconds.")
_FB_PIXEL_TIME = Opt("--pixel-time", help="Seconds a pixel gets: the frame rate follows.")


@answers
def framebuffer(
    width: Annotated[NumberLike, Arg("W, pixels across.", "W")],
    height: Annotated[NumberLike, Arg("H, pixels down.", "H")],
    bits: Annotated[NumberLike, Arg("B, bits per pixel (bit planes).", "BITS")],
    *,
    lut: Annotated[
        NumberLike | None,
        Opt("--lut", help="Bits of a colour look-up-table entry: the table's size."),
    ] = None,
    rate: Annotated[
        NumberLike | None,
        Opt("--rate", help="Transfer rate in bits per second: the time to load a frame."),
    ] = None,
    refresh: Annotated[
        NumberLike | None,
        Opt("--refresh", help="Refresh rate in Hz: the time to access a pixel."),
    ] = None,
    interlaced: Annotated[
        bool, Opt("--interlaced", help="Interlaced: --refresh counts fields.")
    ] = False,
    dpi: Annotated[NumberLike | None, _FB_DPI] = None,
    pixel: Annotated[PointLike | None, _FB_PIXEL] = None,
    address: Annotated[NumberLike | None, _FB_ADDRESS] = None,
    base: Annotated[NumberLike, _FB_BASE] = 0,
    major: Annotated[MajorName, _FB_MAJOR] = "row",
    row0: Annotated[RowZeroName, _FB_ROW0] = "top",
    count: Annotated[DitherCountName | Literal[0, 1], _FB_COUNT] = "0",
    hretrace: Annotated[NumberLike | None, _FB_HRETRACE] = None,
    vretrace: Annotated[NumberLike | None, _FB_VRETRACE] = None,
    pixel_time: Annotated[NumberLike | None, _FB_PIXEL_TIME] = None,
) -> Solution:
    """Frame-buffer arithmetic (``scanconv framebuffer``).

    Parameters
    ----------
    width, height : number
        The raster, in pixels (with ``dpi``: the screen's size in inches).
    bits : int
        Bits a pixel (``2**bits`` colours at once).
    lut : int, optional
        Bits an entry of a colour look-up table (the palette is ``2**lut`` colours).
    rate : number, optional
        Bits a second: the time to load the frame buffer.
    refresh : number, optional
        The refresh rate in Hz: the pixel rate, the time for a scan line and for one pixel.
    interlaced : bool, default False
        An interlaced display: each refresh draws one field (half the lines), so the frames
        per second are half the refresh rate.
    dpi : number, optional
        Dots per inch: ``width`` and ``height`` are inches, the pixels across and down
        ``inches x dpi`` (rounded down).
    pixel : (x, y), optional
        The pixel whose address in the buffer is wanted.
    address : number, optional
        A byte address (fractional inside a byte): the pixel stored there.
    base : int, default 0
        The buffer's first byte.
    major : {"row", "column"}, default "row"
        The buffer holds the rows one after another (``k = y W + x``) or the columns.
    row0 : {"top", "bottom"}, default "top"
        y = 0 is the top scan line (the usual frame-buffer order) or the bottom one.
    count : {"0", "1"}, default "0"
        x and y counted from 0 or from 1.
    hretrace, vretrace : number, optional
        The horizontal and vertical retrace times in seconds: the share of the refresh time
        spent in retrace (with ``refresh``) and the frame rate (with ``pixel_time``).
    pixel_time : number, optional
        The time a pixel gets, in seconds: the frame rate ``1 / (H (W t_p + t_h) + t_v)``.

    Returns
    -------
    Answer
        The working; ``.data`` holds ``pixels``, ``size_bits``, ``colours`` and, as asked,
        ``lut_entries``, ``lut_bits``, ``palette``, ``load_time``, ``pixel_rate``,
        ``line_time``, ``pixel_time``, ``index``, ``address``, ``pixel_at``,
        ``retrace_fraction``, ``line_time_traced``, ``pixel_time_traced`` and ``frame_rate``,
        exact.

    Examples
    --------
    >>> framebuffer(640, 480, 8).data["size_bits"]
    2457600
    >>> data = framebuffer(640, 480, 8, lut=24, rate=10**6, refresh=60).data
    >>> data["palette"], data["load_time"], data["pixel_time"]
    (16777216, Fraction(1536, 625), Fraction(1, 18432000))
    >>> framebuffer(640, 480, 8, pixel=(340, 150)).data["address"]
    96340
    >>> framebuffer(1280, 1024, 1, refresh=60, hretrace="5e-6", vretrace="5e-4").data["retrace_fraction"]
    Fraction(843, 2500)
    """
    return answers_framebuffer.framebuffer_solution(
        *_numbers(width=width, height=height, bits=bits),
        lut=_optional(lut, "lut"),
        rate=_optional(rate, "rate"),
        refresh=_optional(refresh, "refresh"),
        interlaced=bool(interlaced),
        dpi=_optional(dpi, "dpi"),
        pixel=None if pixel is None else _whole_pair(pixel, "pixel"),
        address=_optional(address, "address"),
        base=_whole(base, "base"),
        conventions={
            "major": _choice(major, "major"),
            "row0": _choice(row0, "row0"),
            "count": _choice(str(count) if isinstance(count, int) else count, "count"),
        },
        hretrace=_optional(hretrace, "hretrace"),
        vretrace=_optional(vretrace, "vretrace"),
        pixel_time=_optional(pixel_time, "pixel_time"),
    )


def _whole_pair(point: PointLike, param: str) -> tuple[int, int]:
    x, y = _pair(point, param)
    if x != int(x) or y != int(y):
        raise InputError(f"{param}: a pixel's x and y are whole numbers", param)
    return int(x), int(y)


@answers
def line_style(
    x1: Annotated[NumberLike, X1],
    y1: Annotated[NumberLike, Y1],
    x2: Annotated[NumberLike, X2],
    y2: Annotated[NumberLike, Y2],
    mask: Annotated[str, Opt("--mask", metavar="BITS", help="The pixel mask, e.g. 1110 (dashes).")],
    *,
    bits: Annotated[
        BitOrderName,
        Opt(
            "--bits",
            help="Read the mask from its most (msb) or least (lsb) significant bit.",
            choices=("msb", "lsb"),
        ),
    ] = "msb",
    repeat: Annotated[
        NumberLike,
        Opt("--repeat", help="Use each bit for N pixels (default 1).", show_default=False),
    ] = 1,
) -> Solution:
    """A dashed or dotted line (``scanconv linestyle``): Bresenham's pixels, each drawn when its bit
    of the mask is 1.

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The end points, integers.
    mask : str
        The pattern, 1s and 0s (``"110"``: two on, one off), repeated along the line.
    bits : {"msb", "lsb"}, default "msb"
        The mask read from its most or its least significant bit.
    repeat : int, default 1
        Each bit used for this many pixels.

    Returns
    -------
    Answer
        Bresenham's steps with each pixel's bit, and the pixels drawn.

    Examples
    --------
    >>> list(line_style(0, 0, 7, 2, "110").pixels())
    [(0, 0), (1, 0), (3, 1), (4, 1), (6, 2), (7, 2)]
    >>> list(line_style(0, 0, 7, 2, "10", repeat=2).pixels())
    [(0, 0), (1, 0), (4, 1), (5, 1)]
    >>> print(line_style(0, 0, 7, 2, "110").grid(), end="")  # o: the pixels its mask leaves off
     3 | .  .  .  .  .  .  .  .  .  .
     2 | .  .  .  .  .  .  .  #  #  .
     1 | .  .  .  o  #  #  o  .  .  .
     0 | .  #  #  .  .  .  .  .  .  .
    -1 | .  .  .  .  .  .  .  .  .  .
       +------------------------------
         -1 0  1  2  3  4  5  6  7  8
    # = plotted pixel, o = marked point, @ = both; x to the right, y up
    """
    if not isinstance(mask, str):
        raise InputError(f"mask must be a string of 1s and 0s, got {mask!r}", "mask")
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_attributes.line_style_solution(
        a,
        b,
        c,
        d,
        mask,
        bits=_choice(bits, "bits"),
        repeat=_whole(repeat, "repeat"),
    )


@answers
def thick_line(
    x1: Annotated[NumberLike, X1],
    y1: Annotated[NumberLike, Y1],
    x2: Annotated[NumberLike, X2],
    y2: Annotated[NumberLike, Y2],
    width: Annotated[NumberLike, Opt("--width", "-W", help="The line's width in pixels.")],
    *,
    brush: Annotated[
        bool, Opt("--brush", help="A square brush instead of pixel replication.")
    ] = False,
) -> Solution:
    """A thick line (``scanconv thickline``): at each pixel of Bresenham's line, a span of pixels
    across the minor axis, or a square brush.

    Parameters
    ----------
    x1, y1, x2, y2 : number
        The end points, integers.
    width : int
        The width w in pixels.
    brush : bool, default False
        A ``w x w`` square brush at each pixel instead of a span across the minor axis.

    Returns
    -------
    Answer
        Bresenham's steps with the pixels each adds, and every pixel once.

    Examples
    --------
    >>> sol = thick_line(0, 0, 4, 1, 3)
    >>> [s.extra[0] for s in sol.steps()][:2]
    ['(0, -1), (0, 0), (0, 1)', '(1, -1), (1, 0), (1, 1)']
    >>> len(list(sol.pixels())), len(list(thick_line(0, 0, 4, 1, 3, brush=True).pixels()))
    (15, 23)
    >>> print(thick_line(0, 0, 4, 1, 3).grid(), end="")
     3 | .  .  .  .  .  .  .
     2 | .  .  .  #  #  #  .
     1 | .  #  #  #  #  #  .
     0 | .  #  #  #  #  #  .
    -1 | .  #  #  .  .  .  .
    -2 | .  .  .  .  .  .  .
       +---------------------
         -1 0  1  2  3  4  5
    # = plotted pixel; x to the right, y up
    """
    a, b, c, d = _numbers(x1=x1, y1=y1, x2=x2, y2=y2)
    return answers_attributes.thick_line_solution(
        a, b, c, d, _whole(width, "width"), brush=bool(brush)
    )


def _at(at: PointLike) -> tuple[int, int]:
    x, y = _pair(at, "at")
    return _whole(x, "at"), _whole(y, "at")


def _char(char: str) -> str:
    if not isinstance(char, str) or len(char) != 1:
        raise InputError(f"a character is one letter or digit, got {char!r}", "char")
    return char


@answers
def char_bitmap(
    char: Annotated[str, CHAR],
    *,
    rows: Annotated[
        str | Sequence[str] | None,
        Opt(
            "--rows",
            "-r",
            metavar="ROWS",
            help="The glyph's rows, top first, separated by '/': 01110/10001/... (default: "
            "the 5 x 7 font's).",
        ),
    ] = None,
    at: Annotated[PointLike, AT] = (0, 0),
    scale: Annotated[NumberLike, SCALE] = 1,
    bit_order: Annotated[
        BitOrderName,
        Opt(
            "--bit-order",
            help="The glyph's bytes: a row's leftmost pixel the most significant bit (msb, "
            "the usual font: a row reads as written) or the least (lsb).",
            choices=("msb", "lsb"),
        ),
    ] = "msb",
) -> Solution:
    """A character drawn from its bitmap, and the glyph packed into bytes
    (``scanconv char bitmap``).

    Parameters
    ----------
    char : str
        One letter or digit.
    rows : str or sequence of str, optional
        The glyph's rows, top row first (``"01110/10001/..."`` or a list); default the 5 x 7
        font's glyph. At most 64 x 64 bits.
    at : (x, y), default (0, 0)
        The glyph's bottom-left corner.
    scale : int, default 1
        Each bit drawn as a ``scale x scale`` block.
    bit_order : {"msb", "lsb"}, default "msb"
        How a row goes into its bytes (padded with 0 on the right to whole bytes): the
        leftmost pixel the most significant bit (a row reads as written, the usual bitmap
        font) or the least.

    Returns
    -------
    Answer
        The bitmap, row by row, the pixels it sets (y up), and the glyph's bytes
        (``.data["bytes"]``, a list per row).

    Examples
    --------
    >>> sol = char_bitmap("L")
    >>> sol.data["rows"]
    ['10000', '10000', '10000', '10000', '10000', '10000', '11111']
    >>> sorted(sol.pixels())[:3]
    [(0, 0), (0, 1), (0, 2)]
    >>> sol.data["bytes"][-1], char_bitmap("L", bit_order="lsb").data["bytes"][-1]  # 11111
    ([248], [31])
    >>> print(char_bitmap("L").grid(), end="")
     7 | .  .  .  .  .  .  .
     6 | .  #  .  .  .  .  .
     5 | .  #  .  .  .  .  .
     4 | .  #  .  .  .  .  .
     3 | .  #  .  .  .  .  .
     2 | .  #  .  .  .  .  .
     1 | .  #  .  .  .  .  .
     0 | .  #  #  #  #  #  .
    -1 | .  .  .  .  .  .  .
       +---------------------
         -1 0  1  2  3  4  5
    # = plotted pixel; x to the right, y up
    """
    x0, y0 = _at(at)
    if isinstance(rows, str):
        rows = [r.strip() for r in re.split(r"[/;]", rows) if r.strip()]
    if rows is not None and (len(rows) > MAX_GLYPH or any(len(r) > MAX_GLYPH for r in rows)):
        raise InputError(f"a glyph is at most {MAX_GLYPH} x {MAX_GLYPH} bits", "rows")
    return answers_characters.bitmap_solution(
        _char(char),
        rows=None if rows is None else list(rows),
        x0=x0,
        y0=y0,
        scale=_whole(scale, "scale"),
        bit_order=_choice(bit_order, "bit_order"),
    )


@answers
def char_stroke(
    char: Annotated[str, CHAR],
    *,
    at: Annotated[PointLike, AT] = (0, 0),
    scale: Annotated[NumberLike, SCALE] = 1,
    algo: Annotated[
        StrokeAlgorithmName,
        Opt(
            "--algo",
            "-a",
            help="The line algorithm each stroke is drawn with.",
            choices=("bresenham", "dda"),
        ),
    ] = "bresenham",
) -> Solution:
    """A stroke (vector) character (``scanconv char stroke``): each segment scaled, placed and
    drawn by a line algorithm.

    Parameters
    ----------
    char : str
        One letter or digit of the stroke font.
    at : (x, y), default (0, 0)
        Where the glyph's origin is placed.
    scale : int, default 1
        The factor each stroke's end points are multiplied by.
    algo : {"bresenham", "dda"}, default "bresenham"
        The line algorithm drawing each stroke.

    Returns
    -------
    Answer
        One row per stroke (its end points and its pixels) and the pixels.

    Examples
    --------
    >>> sol = char_stroke("T")
    >>> [s.extra for s in sol.steps()]
    [('(0, 6) to (4, 6)', '(0, 6), (1, 6), (2, 6), (3, 6), (4, 6)'), ('(2, 6) to (2, 0)', '(2, 0), (2, 1), (2, 2), (2, 3), (2, 4), (2, 5), (2, 6)')]
    >>> len(list(sol.pixels()))
    11
    """
    x0, y0 = _at(at)
    return answers_characters.stroke_solution(
        _char(char), x0=x0, y0=y0, scale=_whole(scale, "scale"), algo=_choice(algo, "algo")
    )
