"""Frame-buffer arithmetic: where a pixel is stored, and how the refresh time is spent.

The address of pixel (x, y) in a W x H frame buffer of b bits per pixel starting at ``base``:
its index ``k = y'·W + x'`` (row-major) or ``k = x'·H + y'`` (column-major), with ``x', y'``
counted from 0 and ``y'`` from the top row (``y' = y``) or from the bottom row (``y' = H - 1 -
y``); then the bit address ``k·b`` and the byte address ``base + k·b / 8`` (the most common
published form: ``base + (y·W + x)·b/8``, row-major from the top-left, counted from 0 —
G. S. Owen, SIGGRAPH HyperGraph, "Setting a pixel"). The conventions are named and settable
(:data:`ADDRESS_KNOBS`); :func:`pixel_of` inverts :func:`address`.

The refresh of a non-interlaced raster scan: a frame takes ``H·(W·t_p + t_h) + t_v`` — each of
H scan lines W pixel times and a horizontal retrace, then a vertical retrace.
"""

from __future__ import annotations

from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError

ADDRESS_KNOBS: dict[str, tuple[str, ...]] = {
    "major": ("row", "column"),
    "row0": ("top", "bottom"),
    "count": ("0", "1"),
}
"""Each convention of a pixel's address and its values, the default first: ``major`` (the
buffer stores rows one after another, or columns), ``row0`` (y = 0 is the top scan line, or
the bottom one) and ``count`` (x and y counted from 0 or from 1)."""


def knob(name: str, value: str) -> str:
    """``value`` if it is one of the knob's values, else :class:`InputError` naming them."""
    values = ADDRESS_KNOBS[name]
    if value not in values:
        raise InputError(f"unknown {name} {value!r} (choose from {', '.join(values)})", name)
    return value


class Address(NamedTuple):
    """Where a pixel is stored: its position counted from 0 from the buffer's first row, its
    index, its first bit and its byte (with the bit inside that byte)."""

    x0: int
    y0: int
    k: int
    bit: int
    byte: Fraction
    bit_in_byte: int


def address(
    x: int,
    y: int,
    width: int,
    height: int,
    bits: int,
    base: int = 0,
    *,
    major: str = "row",
    row0: str = "top",
    count: str = "0",
) -> Address:
    """The address of pixel (x, y).

    >>> address(340, 150, 640, 480, 8).byte  # SIGGRAPH HyperGraph: base + 96,340
    Fraction(96340, 1)
    >>> address(6, 10, 101, 101, 1).k
    1016
    >>> address(1, 1, 4, 3, 2, major="column", row0="bottom", count="1")[:3]
    (0, 2, 2)
    """
    c = int(knob("count", count))
    knob("major", major)
    knob("row0", row0)
    if not (c <= x < width + c and c <= y < height + c):
        raise InputError(
            f"pixel ({x}, {y}) is outside the {width} x {height} buffer (positions from {c})",
            "pixel",
        )
    x0 = x - c
    y0 = y - c if row0 == "top" else height - 1 - (y - c)
    index = y0 * width + x0 if major == "row" else x0 * height + y0
    bit = index * bits
    return Address(x0, y0, index, bit, base + Fraction(bit, 8), bit % 8)


def pixel_of(
    byte: Fraction,
    width: int,
    height: int,
    bits: int,
    base: int = 0,
    *,
    major: str = "row",
    row0: str = "top",
    count: str = "0",
) -> tuple[int, int]:
    """The pixel whose first bit is at ``byte`` (a byte address, fractional for a pixel that
    starts inside a byte): the inverse of :func:`address`.

    >>> pixel_of(Fraction(96340), 640, 480, 8)
    (340, 150)
    """
    bit = (Fraction(byte) - base) * 8
    if bit < 0 or bit.denominator != 1 or bit % bits:
        raise InputError(f"address {byte} is not the start of a pixel", "address")
    index = int(bit) // bits
    if index >= width * height:
        raise InputError(f"address {byte} is past the buffer's last pixel", "address")
    if knob("major", major) == "row":
        y0, x0 = divmod(index, width)
    else:
        x0, y0 = divmod(index, height)
    c = int(knob("count", count))
    y = y0 if knob("row0", row0) == "top" else height - 1 - y0
    return x0 + c, y + c


def frame_time(width: int, height: int, pixel: Fraction, h: Fraction, v: Fraction) -> Fraction:
    """The time of one frame: ``H·(W·t_p + t_h) + t_v``.

    >>> frame_time(2, 2, Fraction(1), Fraction(1), Fraction(3))
    Fraction(9, 1)
    """
    return height * (width * pixel + h) + v
