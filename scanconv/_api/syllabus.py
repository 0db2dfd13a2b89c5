"""The Python API: the rest of the syllabus (``scanconv dither``, ``halftone``, ``inside``,
``framebuffer``, ``linestyle``, ``thickline``, ``char``). See :mod:`scanconv._api`."""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Literal

from ..core import lazy
from ..core.checks import InputError
from ..core.choices import (
    ArithmeticName,
    BitOrderName,
    BoundaryName,
    CarryName,
    CompareName,
    DitherBaseName,
    DitherScaleName,
    InsideRuleName,
    KernelName,
    PackingName,
    ScanOrderName,
    StrokeAlgorithmName,
)
from ..display import answers
from .values import (
    NumberLike,
    PointLike,
    PointsLike,
    _choice,
    _flat,
    _number,
    _numbers,
    _optional,
    _pair,
    _whole,
)

if TYPE_CHECKING:
    from ..answers import attributes as answers_attributes
    from ..answers import characters as answers_characters
    from ..answers import dither as answers_dither
    from ..answers import framebuffer as answers_framebuffer
    from ..answers import inside as answers_inside
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_attributes = lazy.module("scanconv.answers.attributes")
    answers_characters = lazy.module("scanconv.answers.characters")
    answers_dither = lazy.module("scanconv.answers.dither")
    answers_framebuffer = lazy.module("scanconv.answers.framebuffer")
    answers_inside = lazy.module("scanconv.answers.inside")

MAX_GLYPH = 64
"""The largest glyph drawn from rows given (64 x 64 bits; scaled at most 16 times)."""

MatrixLike = str | Sequence[Sequence[NumberLike]]
"""An image or a dither matrix: rows of numbers, or text with the rows separated by ``;`` or
``/`` and the values by spaces or commas (``"10 200; 60 90"``); with ``;`` a value may be a
fraction (``"1/2 0; 1 1"``)."""


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
    image: MatrixLike,
    top: NumberLike = 255,
    *,
    at: NumberLike | None = None,
    compare: CompareName = ">=",
) -> Solution:
    """Thresholding (``scanconv dither threshold``): a pixel is on when its value ``compare``
    the threshold ``at`` (default ``top / 2``).

    >>> dither_threshold("10 200; 128 127", at=128).data["output"]
    [[0, 1], [1, 0]]
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
    """Ordered dither (``scanconv dither ordered``) with the Bayer matrix of order ``matrix``
    (2, 4, 8, 16) or a matrix given (rows, or text as ``image``).

    >>> dither_ordered([[1, 2], [3, 4]], 2, 4).data["output"]
    [[1, 0], [0, 1]]
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
    image: MatrixLike,
    top: NumberLike = 255,
    *,
    kernel: KernelName = "floyd-steinberg",
    order: ScanOrderName = "raster",
    arithmetic: ArithmeticName = "exact",
    carry: CarryName = "kept",
    compare: CompareName = ">=",
) -> Solution:
    """Error diffusion (``scanconv dither floyd-steinberg``) to two levels, 0 and ``top``.

    >>> dither_diffusion("100 100; 100 100").data["output"]
    [[0, 1], [0, 0]]
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
def halftone(n: NumberLike, *, level: NumberLike | None = None, bits: NumberLike = 1) -> Solution:
    """The ``n`` x ``n`` halftone patterns (``scanconv halftone``): the levels they give and
    the pattern of each level, or of one ``level``.

    >>> [r[0] for r in halftone(2).tables[0].rows()]
    [0, 1, 2, 3, 4]
    """
    return answers_dither.pattern_solution(
        _whole(n, "n"),
        None if level is None else _whole(level, "level"),
        _whole(bits, "bits"),
    )


@answers
def inside(
    vertices: PointsLike,
    points: PointsLike,
    *,
    rule: InsideRuleName = "both",
    boundary: BoundaryName = "inside",
) -> Solution:
    """Whether each of ``points`` is inside the polygon ``vertices`` (``scanconv inside``), by
    the even-odd rule, the nonzero winding rule or ``both``; a point on the boundary counts as
    ``boundary``.

    >>> [r[3] for r in inside([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [(3, 1), (3, 4)]).tables[-1].rows()]
    ['inside (odd)', 'outside (even)']
    """
    return answers_inside.inside_solution(
        _flat(vertices, "vertices"),
        _flat(points, "points"),
        rule_name=_choice(rule, "rule"),
        boundary=_choice(boundary, "boundary"),
    )


@answers
def framebuffer(
    width: NumberLike,
    height: NumberLike,
    bits: NumberLike,
    *,
    lut: NumberLike | None = None,
    rate: NumberLike | None = None,
    refresh: NumberLike | None = None,
    interlaced: bool = False,
) -> Solution:
    """Frame-buffer arithmetic (``scanconv framebuffer``): the size of a ``width`` x
    ``height`` raster of ``bits`` bits per pixel, its look-up table of ``lut`` bits an entry,
    the time to load it at ``rate`` bits per second and the pixel time at ``refresh`` Hz.

    >>> framebuffer(640, 480, 8).data["size_bits"]
    2457600
    """
    return answers_framebuffer.framebuffer_solution(
        *_numbers(width=width, height=height, bits=bits),
        lut=_optional(lut, "lut"),
        rate=_optional(rate, "rate"),
        refresh=_optional(refresh, "refresh"),
        interlaced=bool(interlaced),
    )


@answers
def line_style(
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    mask: str,
    *,
    bits: BitOrderName = "msb",
    repeat: NumberLike = 1,
) -> Solution:
    """A dashed or dotted line (``scanconv linestyle``): Bresenham's pixels, each drawn when its
    bit of ``mask`` is 1 (read from the most or the least significant bit, each bit used
    ``repeat`` times).

    >>> list(line_style(0, 0, 7, 2, "110").pixels())
    [(0, 0), (1, 0), (3, 1), (4, 1), (6, 2), (7, 2)]
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
    x1: NumberLike,
    y1: NumberLike,
    x2: NumberLike,
    y2: NumberLike,
    width: NumberLike,
    *,
    brush: bool = False,
) -> Solution:
    """A thick line (``scanconv thickline``): ``width`` pixels across the minor axis at each
    pixel of Bresenham's line, or a ``width`` x ``width`` square ``brush``.

    >>> len(list(thick_line(0, 0, 4, 1, 3).pixels()))
    15
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
    char: str,
    *,
    rows: str | Sequence[str] | None = None,
    at: PointLike = (0, 0),
    scale: NumberLike = 1,
) -> Solution:
    """A character drawn from its bitmap (``scanconv char bitmap``): the 5 x 7 font's glyph or
    the ``rows`` given (``"01110/10001/..."``, top row first), bottom-left corner ``at``,
    each bit a ``scale`` x ``scale`` block.

    >>> len(list(char_bitmap("L").pixels()))
    11
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
    )


@answers
def char_stroke(
    char: str,
    *,
    at: PointLike = (0, 0),
    scale: NumberLike = 1,
    algo: StrokeAlgorithmName = "bresenham",
) -> Solution:
    """A stroke character (``scanconv char stroke``): each segment scaled, placed ``at`` and
    drawn by ``algo`` (bresenham or dda).

    >>> [s.pixel for s in char_stroke("T").steps()]
    [(0, 6), (2, 6)]
    """
    x0, y0 = _at(at)
    return answers_characters.stroke_solution(
        _char(char), x0=x0, y0=y0, scale=_whole(scale, "scale"), algo=_choice(algo, "algo")
    )


@answers
def char_storage(
    count: NumberLike, width: NumberLike, height: NumberLike, *, packing: PackingName = "rows"
) -> Solution:
    """The storage of a bitmap font of ``count`` glyphs of ``width`` x ``height`` pixels
    (``scanconv char storage``), packed by ``rows``, ``columns`` or ``bits``.

    >>> char_storage(128, 5, 7).data["bits"]
    7168
    """
    return answers_characters.font_storage_solution(
        _whole(count, "count"),
        _whole(width, "width"),
        _whole(height, "height"),
        packing=_choice(packing, "packing"),
    )
