"""The Python API: halftoning and dithering (``scanconv dither``, ``halftone``). See
:mod:`scanconv._api`."""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, Literal

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .values import NumberLike, PointsLike, _choice, _flat, _number, _optional, _whole

if TYPE_CHECKING:
    from ..answers.image import dither as answers_dither
    from ..answers.image import halftone as answers_halftone
    from ..core.choices import (
        ArithmeticName,
        CarryName,
        CellOrderName,
        CompareName,
        DitherBaseName,
        DitherCountName,
        DitherScaleName,
        KernelName,
        LevelCountName,
        PrinterDotsName,
        ScanOrderName,
    )
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # the command's answer module, loaded by its first call
    answers_dither = lazy.module("scanconv.answers.image.dither")
    answers_halftone = lazy.module("scanconv.answers.image.halftone")


MatrixLike = str | Sequence[Sequence[NumberLike]]
"""An image or a dither matrix: rows of numbers, or text with the rows separated by ``;`` or
``/`` and the values by spaces or commas (``"10 200; 60 90"``); with ``;`` a value may be a
fraction (``"1/2 0; 1 1"``)."""

IMAGE = Opt(
    "--image",
    "-i",
    metavar="ROWS",
    help="The image's values, rows separated by ';' (or '/'), values by spaces or commas: "
    "'10 200; 60 90'.",
    kind="text",
)
TOP = Opt("--top", help="The top of the scale: values run 0..TOP, an on pixel is TOP.")
COMPARE = Opt(
    "--compare",
    help="A pixel is on when its value is > or >= the threshold.",
    choices=(">", ">="),
)
MATRIX = Opt(
    "--matrix",
    "-m",
    metavar="N|ROWS",
    help="The Bayer matrix of order 2, 4, 8 or 16, or a matrix's rows as --image's.",
    kind="text",
)
SCALE = Opt(
    "--scale",
    help="Thresholds: raw (D x TOP / n^2), centered ((D + 1/2) x TOP / n^2), or given "
    "(the matrix's entries are thresholds already, in the image's units).",
    choices=("raw", "centered", "given"),
)
BASE = Opt("--base", help="The matrix's entries count from 0 or from 1.", choices=("0", "1"))
TRANSPOSE = Opt("--transpose", help="Index the matrix by x first (its transpose).")


def _matrix(value: MatrixLike, param: str) -> list[list[Number]]:
    """The rows of an image or a matrix, as exact numbers.

    >>> _matrix("10 200 / 60, 90", "image") == _matrix("10 200; 60 90", "image") == [[10, 200], [60, 90]]
    True
    >>> _matrix("1/2 0; 1 1", "image")[0]
    [Fraction(1, 2), Fraction(0, 1)]
    >>> _matrix([[1, "1/2"]], "image")
    [[1, Fraction(1, 2)]]
    """
    if isinstance(value, str):
        if not value.strip():
            raise InputError(f"the {param} is empty ('')", param)
        rows: Sequence[Sequence[NumberLike]] = [
            [v for v in re.split(r"[\s,]+", row.strip()) if v]
            for row in value.split(";" if ";" in value else "/")
            if row.strip()
        ]
    else:
        rows = value
    out: list[list[Number]] = []
    for row in rows:
        if isinstance(row, str) or not isinstance(row, Sequence):
            raise InputError(f"{param}: a row is a list of numbers, got {row!r}", param)
        out.append([_number(v, param) for v in row])
    return out


@answers
def dither_threshold(
    image: Annotated[MatrixLike, IMAGE],
    top: Annotated[NumberLike, TOP] = 255,
    *,
    at: Annotated[
        NumberLike | None, Opt("--at", "-t", help="The threshold T (default TOP / 2).")
    ] = None,
    compare: Annotated[CompareName, COMPARE] = ">=",
) -> Solution:
    """Thresholding (``scanconv dither threshold``): each pixel on when its value passes one
    threshold.

    Parameters
    ----------
    image : str or rows of numbers
        The image, row 0 first (drawn at the top): rows of numbers, or text with the rows
        separated by ``;`` or ``/`` and the values by spaces or commas (``"10 200; 60 90"``).
    top : number, default 255
        The largest intensity.
    at : number, optional
        The threshold T; default ``top / 2``.
    compare : {">=", ">"}, default ">="
        A pixel is on when ``I >= T`` (or ``I > T``).

    Returns
    -------
    Answer
        The output image (1 = on) and ``.data["output"]``, row 0 first.

    Examples
    --------
    >>> dither_threshold("10 200; 128 127", at=128).data["output"]
    [[0, 1], [1, 0]]
    >>> dither_threshold("10 200; 128 127", at=128, compare=">").data["output"]
    [[0, 1], [0, 0]]
    """
    return answers_dither.threshold_solution(
        _matrix(image, "image"),
        _number(top, "top"),
        _optional(at, "at"),
        compare=_choice(compare, "compare"),
    )


def _dither_matrix(matrix: int | MatrixLike) -> int | list[list[Number]]:
    """A Bayer order (``2``, ``"4"``) or the rows of a matrix given."""
    if isinstance(matrix, int) or (isinstance(matrix, str) and len(matrix.split()) == 1):
        return _whole(matrix, "matrix")
    return _matrix(matrix, "matrix")


@answers
def dither_ordered(
    image: Annotated[MatrixLike, IMAGE],
    matrix: Annotated[int | MatrixLike, MATRIX] = 2,
    top: Annotated[NumberLike, TOP] = 255,
    *,
    compare: Annotated[CompareName, COMPARE] = ">",
    scale: Annotated[DitherScaleName, SCALE] = "raw",
    base: Annotated[DitherBaseName | Literal[0, 1], BASE] = "0",
    transpose: Annotated[bool, TRANSPOSE] = False,
) -> Solution:
    """Ordered dither (``scanconv dither ordered``) with a Bayer matrix or a matrix given.

    Parameters
    ----------
    image : str or rows of numbers
        The image, row 0 first (drawn at the top): rows of numbers, or text with the rows
        separated by ``;`` or ``/`` and the values by spaces or commas (``"10 200; 60 90"``).
    matrix : int, str or rows of numbers, default 2
        The Bayer matrix's order n (2, 4, 8, 16), or the matrix itself (rows, or text as
        ``image``).
    top : number, default 255
        The largest intensity.
    compare : {">", ">="}, default ">"
        A pixel is on when its value is ``>`` the threshold (Hearn & Baker's "if I > D_n(j, k)")
        or ``>=`` it.
    scale : {"raw", "centered", "given"}, default "raw"
        Entry d's threshold: the intensity scaled to 0 .. n² compared with d (``raw``, Hearn &
        Baker's form), ``(d + 1/2) top / n²`` (``centered``, the middle of its band), or d
        itself, a matrix given already in the image's units (``given``).
    base : {"0", "1"}, default "0"
        The matrix entries counted from 0 (``0 .. n² - 1``, the usual Bayer matrix) or from 1.
    transpose : bool, default False
        Read the matrix as ``D[j mod n][i mod n]`` (Hearn & Baker index D by x first) instead of
        ``D[i mod n][j mod n]``.

    Returns
    -------
    Answer
        The thresholds, the output image (1 = on); ``.data`` holds ``matrix``, ``thresholds`` and
        ``output``.

    Notes
    -----
    B. E. Bayer, "An optimum method for two-level rendition of continuous-tone pictures", ICC
    1973; the conventions are :data:`scanconv.algorithms.dither.DITHER_KNOBS`.

    Examples
    --------
    >>> sol = dither_ordered([[1, 2], [3, 4]], 2, 4)
    >>> sol.data["matrix"], sol.data["output"]
    ([[0, 2], [3, 1]], [[1, 0], [0, 1]])
    >>> dither_ordered([[1, 2], [3, 4]], 2, 4, compare=">=").data["output"]
    [[1, 1], [1, 1]]
    """
    return answers_dither.ordered_solution(
        _matrix(image, "image"),
        _dither_matrix(matrix),
        _number(top, "top"),
        compare=_choice(compare, "compare"),
        scale=_choice(scale, "scale"),
        base=_choice(str(base) if isinstance(base, int) else base, "base"),
        transpose=bool(transpose),
    )


@answers
def dither_lookup(
    pixels: Annotated[
        PointsLike,
        Arg(
            "The pixels' screen positions: x across, y down (row y), in pairs.",
            "X Y ...",
            kind="text",
        ),
    ],
    matrix: Annotated[int | MatrixLike, MATRIX] = 4,
    top: Annotated[NumberLike, TOP] = 255,
    *,
    value: Annotated[
        NumberLike | None,
        Opt("--value", help="The pixels' intensity: each is on when it passes T."),
    ] = None,
    count: Annotated[
        DitherCountName | Literal[0, 1],
        Opt("--count", help="Screen positions count from 0 or from 1.", choices=("0", "1")),
    ] = "0",
    compare: Annotated[CompareName, COMPARE] = ">",
    scale: Annotated[DitherScaleName, SCALE] = "raw",
    base: Annotated[DitherBaseName | Literal[0, 1], BASE] = "0",
    transpose: Annotated[bool, TRANSPOSE] = False,
) -> Solution:
    """Each pixel's dither threshold from its screen position (``scanconv dither lookup``):
    ``T[(y - c) mod n][(x - c) mod n]``, and whether a pixel of intensity ``value`` is on there.

    Parameters
    ----------
    pixels : sequence of (x, y), or flat numbers
        The screen positions: x across, y down (row y of the image).
    matrix : int, str or rows of numbers, default 4
        The Bayer matrix's order n (2, 4, 8, 16), or the matrix itself.
    top : number, default 255
        The largest intensity.
    value : number, optional
        The intensity of the pixels: each is on when it passes its threshold.
    count : {"0", "1"}, default "0"
        Positions counted from 0 or from 1 (then ``(x - 1) mod n``).
    compare, scale, base, transpose : str, str, str, bool
        As :func:`dither_ordered` takes them (``compare`` default ``">"``).

    Returns
    -------
    Answer
        One row per pixel: ``x, y, i, j, i mod n, j mod n, T`` (and ``I, output`` with a
        value); ``.data["lookups"]`` holds the thresholds.

    Examples
    --------
    >>> dither_lookup([(5, 2)], 4, 16).data["lookups"]
    [11]
    >>> dither_lookup([6, 3], 4, 16, count=1, value=12).data["output"]
    [1]
    """
    flat = _flat(pixels, "pixels")
    if len(flat) % 2 or not all(v == int(v) for v in flat):
        raise InputError("pixels are whole X Y pairs", "pixels")
    pairs = [(int(flat[k]), int(flat[k + 1])) for k in range(0, len(flat), 2)]
    return answers_dither.lookup_solution(
        pairs,
        _dither_matrix(matrix),
        _number(top, "top"),
        value=_optional(value, "value"),
        count=_choice(str(count) if isinstance(count, int) else count, "count"),
        compare=_choice(compare, "compare"),
        scale=_choice(scale, "scale"),
        base=_choice(str(base) if isinstance(base, int) else base, "base"),
        transpose=bool(transpose),
    )


@answers
def dither_diffusion(
    image: Annotated[MatrixLike, IMAGE],
    top: Annotated[NumberLike, TOP] = 255,
    *,
    kernel: Annotated[
        KernelName,
        Opt(
            "--kernel",
            help="floyd-steinberg (7, 3, 5, 1)/16, simple (3, 3, 2)/8, jarvis-judice-ninke /48, "
            "stucki /42, burkes /32, sierra /32, two-row-sierra /16, sierra-lite /4, or "
            "one-dimensional (all to the next pixel).",
            choices=(
                "floyd-steinberg",
                "simple",
                "jarvis-judice-ninke",
                "stucki",
                "burkes",
                "sierra",
                "two-row-sierra",
                "sierra-lite",
                "one-dimensional",
            ),
        ),
    ] = "floyd-steinberg",
    order: Annotated[
        ScanOrderName,
        Opt(
            "--order",
            help="raster: every row left to right; serpentine: alternate rows.",
            choices=("raster", "serpentine"),
        ),
    ] = "raster",
    arithmetic: Annotated[
        ArithmeticName,
        Opt(
            "--arithmetic",
            help="Error shares kept exact or truncated to integers.",
            choices=("exact", "integer"),
        ),
    ] = "exact",
    carry: Annotated[
        CarryName,
        Opt(
            "--carry",
            help="Negative carried values kept, or clamped at 0.",
            choices=("kept", "clamped"),
        ),
    ] = "kept",
    compare: Annotated[CompareName, COMPARE] = ">=",
) -> Solution:
    """Error diffusion to two levels, 0 and ``top`` (``scanconv dither floyd-steinberg``).

    Parameters
    ----------
    image : str or rows of numbers
        The image, row 0 first (drawn at the top): rows of numbers, or text with the rows
        separated by ``;`` or ``/`` and the values by spaces or commas (``"10 200; 60 90"``).
    top : number, default 255
        The largest intensity; a pixel's error is its value minus the level it is given.
    kernel : str, default "floyd-steinberg"
        The shares of the error: Floyd-Steinberg's 7/16 right, 3/16, 5/16, 1/16 below, the
        simple 3/8 right, 3/8 below, 2/8 diagonal taught under the same name,
        ``"jarvis-judice-ninke"`` (/48), ``"stucki"`` (/42), ``"burkes"`` (/32), ``"sierra"``
        (/32), ``"two-row-sierra"`` (/16), ``"sierra-lite"`` (/4) or ``"one-dimensional"``
        (all of the error to the next pixel); each source is named in the answer's notes
        (:data:`scanconv.algorithms.dither.KERNELS`).
    order : {"raster", "serpentine"}, default "raster"
        Every row left to right, or alternate rows right to left.
    arithmetic : {"exact", "integer"}, default "exact"
        Exact fractions, or each share truncated toward zero (C's integer division).
    carry : {"kept", "clamped"}, default "kept"
        Negative errors kept, or clamped at 0.
    compare : {">=", ">"}, default ">="
        A pixel is on when its value (with the errors received) passes ``top / 2``.

    Returns
    -------
    Answer
        One row per pixel in the scan order (``received``, ``value``, ``output``, ``error``
        and the shares ``carries`` to the neighbours) and the output image.

    Notes
    -----
    R. W. Floyd and L. Steinberg, "An adaptive algorithm for spatial greyscale", Proc. SID 17
    (1976).

    Examples
    --------
    >>> dither_diffusion("100 100; 100 100").data["output"]
    [[0, 1], [0, 0]]
    >>> dither_diffusion("100 100; 100 100", kernel="simple").data["output"]
    [[0, 1], [1, 0]]
    """
    return answers_dither.diffusion_solution(
        _matrix(image, "image"),
        _number(top, "top"),
        kernel=_choice(kernel, "kernel"),
        order=_choice(order, "order"),
        arithmetic=_choice(arithmetic, "arithmetic"),
        carry=_choice(carry, "carry"),
        compare=_choice(compare, "compare"),
    )


@answers
def halftone(
    n: Annotated[NumberLike, Arg("N, the halftone cell's width: 1 to 16.", "N")],
    *,
    level: Annotated[
        NumberLike | None, Opt("--level", "-l", help="Only the pattern of this level.")
    ] = None,
    bits: Annotated[
        NumberLike,
        Opt("--bits", help="Bits per pixel of the device (default 1).", show_default=False),
    ] = 1,
    order: Annotated[
        CellOrderName,
        Opt(
            "--order",
            help="bayer: the cell fills in the Bayer matrix's order (dispersed); clustered: a "
            "dot grows from the centre.",
            choices=("bayer", "clustered"),
        ),
    ] = "bayer",
    matrix: Annotated[
        MatrixLike | None,
        Opt(
            "--matrix",
            "-m",
            metavar="ROWS",
            help="The cell's order given: N x N rows holding 0..N^2-1 (or 1..N^2) once each.",
        ),
    ] = None,
) -> Solution:
    """The n x n halftone patterns (``scanconv halftone``): the levels they give and the pattern of
    each level, or of one.

    Parameters
    ----------
    n : int
        The cell's side, 1 to 16: n² + 1 nested levels.
    level : int, optional
        Only this level's pattern.
    bits : int, default 1
        Bits a cell (more than 1: grey cells, ``n² (2**bits - 1) + 1`` levels).
    order : {"bayer", "clustered"}, default "bayer"
        How the cell fills: in the order of the Bayer matrix (for n not a power of 2, the
        top-left n x n block of the next Bayer matrix, ranked), or a dot growing from the
        centre.
    matrix : str or rows of numbers, optional
        The order given instead: an n x n matrix holding 0 .. n² - 1 (or 1 .. n²) once each.

    Returns
    -------
    Answer
        The table ``level, pattern (rows top first), cells on``; ``.data`` holds the number of
        ``levels``, the cell's ``order`` and the ``patterns``.

    Examples
    --------
    >>> sol = halftone(2)
    >>> sol.data["levels"], sol.data["patterns"][2]
    (5, [[1, 0], [0, 1]])
    >>> list(halftone(2, level=3).tables[-1].rows())
    [(3, '1 1 / 0 1', 3)]
    >>> halftone(5).data["levels"], halftone(3, matrix="6 8 4; 1 0 3; 5 2 7").data["patterns"][1]
    (26, [[0, 0, 0], [0, 1, 0], [0, 0, 0]])
    """
    return answers_dither.pattern_solution(
        _whole(n, "n"),
        None if level is None else _whole(level, "level"),
        _whole(bits, "bits"),
        order=_choice(order, "order"),
        matrix=None if matrix is None else _matrix(matrix, "matrix"),
    )


@answers
def printer(
    dpi: Annotated[NumberLike | None, Opt("--dpi", help="The printer's dots per inch.")] = None,
    lpi: Annotated[
        NumberLike | None,
        Opt("--lpi", help="The halftone screen's lines (cells) per inch."),
    ] = None,
    *,
    cell: Annotated[
        NumberLike | None, Opt("--cell", help="The halftone cell's side N, in dots.")
    ] = None,
    levels: Annotated[
        NumberLike | None,
        Opt("--levels", help="The grey levels wanted: the smallest cell giving them."),
    ] = None,
    count: Annotated[
        LevelCountName,
        Opt(
            "--count",
            help="An N x N cell's levels: n2+1 (0..N^2 dots on) or n2.",
            choices=("n2+1", "n2"),
        ),
    ] = "n2+1",
    dots: Annotated[
        PrinterDotsName,
        Opt(
            "--dots",
            help="The cell from dpi / lpi: whole dots (rounded down) or exact.",
            choices=("whole", "exact"),
        ),
    ] = "whole",
) -> Solution:
    """A printer's halftone arithmetic (``scanconv printer``): from any two of the printer's dots
    per inch, the screen's lines per inch and the cell (or the levels wanted), the rest.

    Parameters
    ----------
    dpi : number, optional
        The printer's resolution in dots per inch.
    lpi : number, optional
        The halftone screen's lines (cells) per inch.
    cell : int, optional
        The cell's side n in dots.
    levels : int, optional
        The grey levels wanted: the smallest cell giving them.
    count : {"n2+1", "n2"}, default "n2+1"
        An n x n cell's levels: n² + 1 (0 to n² dots on) or n² (the shades printed).
    dots : {"whole", "exact"}, default "whole"
        The cell from dpi / lpi: whole dots (rounded down) or the ratio itself.

    Returns
    -------
    Answer
        The working; ``.data`` holds ``n``, ``levels``, ``dpi``, ``lpi`` and ``cell_inches``.

    Examples
    --------
    >>> printer(300, 60).data["levels"]
    26
    >>> printer(lpi=150, cell=16).data["dpi"]
    2400
    """
    return answers_halftone.printer_solution(
        _optional(dpi, "dpi"),
        _optional(lpi, "lpi"),
        cell=None if cell is None else _whole(cell, "cell"),
        levels=None if levels is None else _whole(levels, "levels"),
        count=_choice(count, "count"),
        dots=_choice(dots, "dots"),
    )
