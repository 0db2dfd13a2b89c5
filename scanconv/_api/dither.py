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
from .values import NumberLike, _choice, _number, _optional, _whole

if TYPE_CHECKING:
    from ..answers.image import dither as answers_dither
    from ..core.choices import (
        ArithmeticName,
        CarryName,
        CompareName,
        DitherBaseName,
        DitherScaleName,
        KernelName,
        ScanOrderName,
    )
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # the command's answer module, loaded by its first call
    answers_dither = lazy.module("scanconv.answers.image.dither")


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
    image: MatrixLike,
    matrix: int | MatrixLike = 2,
    top: NumberLike = 255,
    *,
    compare: CompareName = ">",
    scale: DitherScaleName = "raw",
    base: DitherBaseName | Literal[0, 1] = "0",
    transpose: bool = False,
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
    scale : {"raw", "centered"}, default "raw"
        Entry d's threshold: the intensity scaled to 0 .. n² compared with d (``raw``, Hearn &
        Baker's form), or ``(d + 1/2) top / n²`` (``centered``, the middle of its band).
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
def dither_diffusion(
    image: Annotated[MatrixLike, IMAGE],
    top: Annotated[NumberLike, TOP] = 255,
    *,
    kernel: Annotated[
        KernelName,
        Opt(
            "--kernel",
            help="floyd-steinberg (7, 3, 5, 1)/16 or simple (3, 3, 2)/8.",
            choices=("floyd-steinberg", "simple"),
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
    kernel : {"floyd-steinberg", "simple"}, default "floyd-steinberg"
        The shares of the error: Floyd-Steinberg's 7/16 right, 3/16, 5/16, 1/16 below, or the
        simple 3/8 right, 3/8 below, 2/8 diagonal taught under the same name.
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
    n: Annotated[NumberLike, Arg("N, the halftone cell's width: 2, 4, 8 or 16.", "N")],
    *,
    level: Annotated[
        NumberLike | None, Opt("--level", "-l", help="Only the pattern of this level.")
    ] = None,
    bits: Annotated[
        NumberLike,
        Opt("--bits", help="Bits per pixel of the device (default 1).", show_default=False),
    ] = 1,
) -> Solution:
    """The n x n halftone patterns (``scanconv halftone``): the levels they give and the pattern of
    each level, or of one.

    Parameters
    ----------
    n : int
        The pattern's side.
    level : int, optional
        Only this level's pattern.
    bits : int, default 1
        Bits a cell (more than 1: grey cells, ``n² (2**bits - 1) + 1`` levels).

    Returns
    -------
    Answer
        The table ``level, pattern (rows top first), cells on``; ``.data`` holds the number of
        ``levels`` and the ``patterns``.

    Examples
    --------
    >>> sol = halftone(2)
    >>> sol.data["levels"], sol.data["patterns"][2]
    (5, [[1, 0], [0, 1]])
    >>> list(halftone(2, level=3).tables[-1].rows())
    [(3, '1 1 / 0 1', 3)]
    """
    return answers_dither.pattern_solution(
        _whole(n, "n"),
        None if level is None else _whole(level, "level"),
        _whole(bits, "bits"),
    )
