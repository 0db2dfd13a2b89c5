"""Character generation: bitmap fonts (storage, and a character drawn from its bitmap, scaled
by pixel replication) and stroke fonts (a character as line segments, each drawn by a line
algorithm).

Conventions, named and settable: a glyph is ``packed`` by ``rows`` (each row padded to whole
bytes, the usual bitmap font) or by ``columns`` (each column padded, as column-scanned LCD
fonts are), or not at all (``bits``); ``kilo`` is 1000 or 1024 bytes.

References: Hearn & Baker, *Computer Graphics with OpenGL*, 3rd ed., §4-11 (character
primitives: bitmap and outline fonts); Foley et al., *Computer Graphics*, 2nd ed., §3.16.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from typing import NamedTuple

from ..core.checks import InputError
from ..core.records import Pixel, Step, new_step
from .lines import bresenham, dda, orient

FONT_5X7: dict[str, tuple[str, ...]] = {
    "A": ("01110", "10001", "10001", "11111", "10001", "10001", "10001"),
    "B": ("11110", "10001", "10001", "11110", "10001", "10001", "11110"),
    "C": ("01110", "10001", "10000", "10000", "10000", "10001", "01110"),
    "D": ("11110", "10001", "10001", "10001", "10001", "10001", "11110"),
    "E": ("11111", "10000", "10000", "11110", "10000", "10000", "11111"),
    "F": ("11111", "10000", "10000", "11110", "10000", "10000", "10000"),
    "G": ("01110", "10001", "10000", "10111", "10001", "10001", "01111"),
    "H": ("10001", "10001", "10001", "11111", "10001", "10001", "10001"),
    "I": ("01110", "00100", "00100", "00100", "00100", "00100", "01110"),
    "J": ("00111", "00010", "00010", "00010", "00010", "10010", "01100"),
    "K": ("10001", "10010", "10100", "11000", "10100", "10010", "10001"),
    "L": ("10000", "10000", "10000", "10000", "10000", "10000", "11111"),
    "M": ("10001", "11011", "10101", "10101", "10001", "10001", "10001"),
    "N": ("10001", "10001", "11001", "10101", "10011", "10001", "10001"),
    "O": ("01110", "10001", "10001", "10001", "10001", "10001", "01110"),
    "P": ("11110", "10001", "10001", "11110", "10000", "10000", "10000"),
    "Q": ("01110", "10001", "10001", "10001", "10101", "10010", "01101"),
    "R": ("11110", "10001", "10001", "11110", "10100", "10010", "10001"),
    "S": ("01111", "10000", "10000", "01110", "00001", "00001", "11110"),
    "T": ("11111", "00100", "00100", "00100", "00100", "00100", "00100"),
    "U": ("10001", "10001", "10001", "10001", "10001", "10001", "01110"),
    "V": ("10001", "10001", "10001", "10001", "10001", "01010", "00100"),
    "W": ("10001", "10001", "10001", "10101", "10101", "10101", "01010"),
    "X": ("10001", "10001", "01010", "00100", "01010", "10001", "10001"),
    "Y": ("10001", "10001", "01010", "00100", "00100", "00100", "00100"),
    "Z": ("11111", "00001", "00010", "00100", "01000", "10000", "11111"),
    "0": ("01110", "10001", "10011", "10101", "11001", "10001", "01110"),
    "1": ("00100", "01100", "00100", "00100", "00100", "00100", "01110"),
    "2": ("01110", "10001", "00001", "00010", "00100", "01000", "11111"),
    "3": ("11111", "00010", "00100", "00010", "00001", "10001", "01110"),
    "4": ("00010", "00110", "01010", "10010", "11111", "00010", "00010"),
    "5": ("11111", "10000", "11110", "00001", "00001", "10001", "01110"),
    "6": ("00110", "01000", "10000", "11110", "10001", "10001", "01110"),
    "7": ("11111", "00001", "00010", "00100", "01000", "01000", "01000"),
    "8": ("01110", "10001", "10001", "01110", "10001", "10001", "01110"),
    "9": ("01110", "10001", "10001", "01111", "00001", "00010", "01100"),
}
"""A 5 x 7 bitmap font: each glyph's rows, top row first, 1 = on."""

STROKES: dict[str, tuple[tuple[int, int, int, int], ...]] = {
    "A": ((0, 0, 2, 6), (2, 6, 4, 0), (1, 3, 3, 3)),
    "E": ((4, 0, 0, 0), (0, 0, 0, 6), (0, 6, 4, 6), (0, 3, 3, 3)),
    "F": ((0, 0, 0, 6), (0, 6, 4, 6), (0, 3, 3, 3)),
    "H": ((0, 0, 0, 6), (4, 0, 4, 6), (0, 3, 4, 3)),
    "I": ((2, 0, 2, 6), (1, 0, 3, 0), (1, 6, 3, 6)),
    "K": ((0, 0, 0, 6), (0, 2, 4, 6), (1, 3, 4, 0)),
    "L": ((0, 6, 0, 0), (0, 0, 4, 0)),
    "M": ((0, 0, 0, 6), (0, 6, 2, 3), (2, 3, 4, 6), (4, 6, 4, 0)),
    "N": ((0, 0, 0, 6), (0, 6, 4, 0), (4, 0, 4, 6)),
    "T": ((0, 6, 4, 6), (2, 6, 2, 0)),
    "V": ((0, 6, 2, 0), (2, 0, 4, 6)),
    "W": ((0, 6, 1, 0), (1, 0, 2, 4), (2, 4, 3, 0), (3, 0, 4, 6)),
    "X": ((0, 0, 4, 6), (0, 6, 4, 0)),
    "Y": ((0, 6, 2, 3), (4, 6, 2, 3), (2, 3, 2, 0)),
    "Z": ((0, 6, 4, 6), (4, 6, 0, 0), (0, 0, 4, 0)),
    "1": ((1, 5, 2, 6), (2, 6, 2, 0), (1, 0, 3, 0)),
    "4": ((3, 0, 3, 6), (3, 6, 0, 2), (0, 2, 4, 2)),
    "7": ((0, 6, 4, 6), (4, 6, 1, 0)),
}
"""Stroke characters on a 5 x 7 grid (y up, origin bottom left): each a list of segments
``(x1, y1, x2, y2)``; the letters made of straight strokes."""

PACKINGS = ("rows", "columns", "bits")
STROKE_ALGORITHMS = ("bresenham", "dda")
"""The line methods a stroke is drawn with."""
MAX_SCALE = 16
MAX_CHARACTERS = 1 << 20


class Storage(NamedTuple):
    """A font's storage: bits per glyph as stored, and the whole font in bits."""

    per_glyph: int
    total_bits: int


def storage(count: int, width: int, height: int, packing: str = "rows") -> Storage:
    """The storage of ``count`` glyphs of ``width`` x ``height`` pixels.

    >>> storage(128, 5, 7), storage(128, 5, 7, "bits"), storage(256, 9, 14, "columns")
    (Storage(per_glyph=56, total_bits=7168), Storage(per_glyph=35, total_bits=4480), Storage(per_glyph=144, total_bits=36864))
    """
    if packing not in PACKINGS:
        raise InputError(f"packing is rows, columns or bits, got {packing!r}", "packing")
    for v, name in ((count, "count"), (width, "width"), (height, "height")):
        if v < 1:
            raise InputError(f"the {name} must be at least 1, got {v}", name)
    if count > MAX_CHARACTERS or width > 256 or height > 256:
        raise InputError("a font is at most 2^20 glyphs of 256 x 256 pixels", "count")
    if packing == "rows":
        per = height * 8 * math.ceil(width / 8)
    elif packing == "columns":
        per = width * 8 * math.ceil(height / 8)
    else:
        per = width * height
    return Storage(per, per * count)


BIT_ORDERS = ("msb", "lsb")
"""How a glyph row's pixels go into a byte: the leftmost pixel in the most significant bit
(``msb``, the usual bitmap font: a row reads as written) or in the least (``lsb``)."""


class RowBytes(NamedTuple):
    """One glyph row packed into whole bytes."""

    row: str
    """The row as written, padded on the right with 0 to whole bytes."""
    values: tuple[int, ...]
    """Its bytes, first byte first."""


def row_bytes(rows: Sequence[str], bit_order: str = "msb") -> tuple[RowBytes, ...]:
    """Each row of a glyph (``"01110"``) packed into whole bytes, row by row: padded on the
    right with 0 to a multiple of 8 pixels, then each 8 pixels one byte, the leftmost pixel
    its most significant bit (``msb``) or its least (``lsb``).

    >>> row_bytes(["01110", "10001"])
    (RowBytes(row='01110000', values=(112,)), RowBytes(row='10001000', values=(136,)))
    >>> row_bytes(["01110"], "lsb")[0].values  # 0b00001110 read backwards: 0x0E
    (14,)
    >>> row_bytes(["111111111"])[0].values  # 9 pixels: two bytes
    (255, 128)
    """
    if bit_order not in BIT_ORDERS:
        raise InputError(f"the bit order is msb or lsb, got {bit_order!r}", "bit_order")
    out = []
    for r in rows:
        padded = r + "0" * (-len(r) % 8)
        chunks = [padded[i : i + 8] for i in range(0, len(padded), 8)]
        values = tuple(int(c if bit_order == "msb" else c[::-1], 2) for c in chunks)
        out.append(RowBytes(padded, values))
    return tuple(out)


def glyph_offset(index: int, per_glyph_bits: int, base: int = 0) -> int:
    """The byte address of glyph number ``index`` (0 first) in a font table of glyphs of
    ``per_glyph_bits`` each, stored one after another from ``base``.

    >>> glyph_offset(65, 64, 0x1000)  # 'A' in an 8 x 8 font: 0x1000 + 65 x 8
    4616
    """
    return base + index * per_glyph_bits // 8


def glyph(char: str, rows: Sequence[str] | None = None) -> tuple[str, ...]:
    """The rows of ``char`` (from :data:`FONT_5X7`) or the ``rows`` given (1/0 or #/.).

    >>> glyph("T")[:2]
    ('11111', '00100')
    >>> glyph("?", ["#.#", ".#."])
    ('101', '010')
    """
    if rows is not None:
        out = tuple(r.replace("#", "1").replace(".", "0") for r in rows)
        if not out or any(len(r) != len(out[0]) or set(r) - {"0", "1"} for r in out):
            raise InputError("a glyph's rows are equal-length strings of 1/0 or #/.", "rows")
        return out
    if char not in FONT_5X7:
        raise InputError(f"no 5 x 7 glyph for {char!r} (A-Z, 0-9, or give its rows)", "char")
    return FONT_5X7[char]


def draw_bitmap(rows: Sequence[str], x0: int = 0, y0: int = 0, scale: int = 1) -> Iterator[Step]:
    """The glyph drawn with its bottom-left corner at ``(x0, y0)``, y up, each bit a
    ``scale`` x ``scale`` block: one step per set bit, ``extra`` = ``(row, column, pixels)``.

    >>> [s.extra[2] for s in draw_bitmap(["10", "01"], 0, 0, 1)]
    [((0, 1),), ((1, 0),)]
    """
    if not 1 <= scale <= MAX_SCALE:
        raise InputError(f"the scale is 1..{MAX_SCALE}, got {scale}", "scale")
    h = len(rows)
    k = 0
    for i, row in enumerate(rows):
        for j, bit in enumerate(row):
            if bit != "1":
                continue
            bx, by = x0 + j * scale, y0 + (h - 1 - i) * scale
            block = tuple((bx + dx, by + dy) for dy in range(scale) for dx in range(scale))
            yield new_step(Step, (k, None, None, (bx, by), (i, j, block)))
            k += 1


def draw_strokes(
    char: str, x0: int = 0, y0: int = 0, scale: int = 1, algo: str = "bresenham"
) -> Iterator[Step]:
    """The stroke character, each segment scaled and drawn by ``algo`` (bresenham or dda):
    one step per segment, ``extra`` = ``(segment, pixels)``.

    >>> [len(s.extra[1]) for s in draw_strokes("L")]
    [7, 5]
    """
    if char not in STROKES:
        raise InputError(
            f"no stroke character {char!r} (choose from {''.join(sorted(STROKES))})", "char"
        )
    if not 1 <= scale <= MAX_SCALE:
        raise InputError(f"the scale is 1..{MAX_SCALE}, got {scale}", "scale")
    if algo not in STROKE_ALGORITHMS:
        raise InputError(f"strokes are drawn by bresenham or dda, got {algo!r}", "algo")
    for k, (a, b, c, d) in enumerate(STROKES[char]):
        seg = (x0 + a * scale, y0 + b * scale, x0 + c * scale, y0 + d * scale)
        yield new_step(Step, (k, None, None, seg[:2], (seg, _segment(seg, algo))))


def _segment(seg: tuple[int, int, int, int], algo: str) -> tuple[Pixel, ...]:
    if algo == "dda":
        return tuple(dict.fromkeys(s.pixel for s in dda(*seg)))
    o = orient(*seg)
    return ((o.x1, o.y1), *(s.pixel for s in bresenham(*seg)))
