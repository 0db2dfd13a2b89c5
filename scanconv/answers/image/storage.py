"""The worked answer of an image's storage: ``M × N × k × F`` bits with ``k = ⌈log2 L⌉`` bits per
pixel (1 for a binary image, 24 for RGB true colour), in bits, bytes, KB/MB (1000) and KiB/MiB
(1024)."""

from __future__ import annotations

import math
from collections.abc import Iterator
from fractions import Fraction
from typing import NamedTuple

from ...algorithms.image_limits import MAX_LEVELS, check_levels, check_storage_bits
from ...algorithms.storage import UNITS, bits_per_pixel, sizes, storage_bits
from ...core.checks import InputError, check_positive
from ...core.numeric import Number, fmt, fmt_short, normalize
from ...core.records import Quantity, Solution, Table, Walk, heading, worked
from ._shared import int_tex, int_text


def size_text(value: Number, *, cell: bool = False) -> str:
    """A size exactly when it has at most 6 decimals, else ``≈`` and 4 significant digits.

    ``cell=True``: for a table cell, ASCII and ungrouped (``~2.861``, ``1048576``).

    >>> size_text(Fraction(786432, 1000)), size_text(Fraction(3000000, 2**20)), size_text(1024**2)
    ('786.432', '≈ 2.861', '1,048,576')
    >>> size_text(Fraction(24, 10**6)), size_text(Fraction(3000000, 2**20), cell=True)
    ('0.000024', '~2.861')
    >>> size_text(Fraction(9, 8 * 2**20))
    '≈ 0.000001073'
    """
    v = Fraction(value)
    s = fmt_short(v)
    approx = "/" in s
    if approx:
        places = 3
        while v * 10**places < 1000 and places < 15:
            places += 1
        s = fmt(v, places)
    if cell:
        return ("~" if approx else "") + s
    whole, dot, frac = s.partition(".")
    return ("≈ " if approx else "") + int_text(int(whole)) + dot + frac


def storage_quantity(m: int, n: int, levels: int) -> Quantity:
    """The storage of one M × N image of L levels, in one line of working.

    >>> print(storage_quantity(8, 8, 8).text)
    storage = M × N × ⌈log₂ L⌉ = 8 × 8 × 3 = 192 bits = 24 bytes
    """
    k = bits_per_pixel(levels)
    b = storage_bits(m, n, k)
    unit = "bit" if b == 1 else "bits"
    by = size_text(Fraction(b, 8))
    return worked(
        "storage_bits",
        b,
        f"\\text{{storage}} = M \\times N \\times \\lceil \\log_2 L \\rceil = {m} \\times {n} "
        f"\\times {k} = {int_tex(b)} \\text{{ {unit}}} = {_tex(by)} \\text{{ bytes}}",
    )


def _tex(s: str) -> str:
    """A size from :func:`size_text` as math: ``≈`` and thousands commas.

    >>> print(_tex("≈ 1,048.6"))
    \\approx 1{,}048.6
    """
    return s.replace("≈", "\\approx").replace(",", "{,}")


class _Depth(NamedTuple):
    """Bits per pixel, with its working and notes."""

    k: int
    working: list[Quantity]
    notes: list[str]


def _binary_depth() -> _Depth:
    return _Depth(
        1,
        [
            worked(
                "k",
                1,
                r"k = 1 \text{ bit per pixel (binary image: } L = 2\text{, 0 = black, "
                r"1 = white)}",
            )
        ],
        [],
    )


def _colour_depth(color: str) -> _Depth:
    if color != "rgb24":
        raise InputError(f"unknown colour format {color!r} (choose from rgb24)", "color")
    return _Depth(
        24,
        [
            worked(
                "k",
                24,
                r"k = 3 \times 8 = 24 \text{ bits per pixel (R, G, B: 8 bits each, "
                r"true colour)}",
            ),
            worked("L", MAX_LEVELS, f"L = 2^{{24}} = {int_tex(MAX_LEVELS)} \\text{{ colours}}"),
        ],
        [],
    )


def _bits_depth(bits: Number) -> _Depth:
    b = check_storage_bits(bits)
    return _Depth(
        b,
        [
            worked("L", 1 << b, f"L = 2^B = 2^{{{b}}} = {int_tex(1 << b)} \\text{{ levels}}"),
            worked("k", b, f"k = B = {b} \\text{{ bits per pixel}}"),
        ],
        [],
    )


def _levels_depth(levels: Number) -> _Depth:
    """``k = log2 L`` bits, or ``⌈log2 L⌉`` (with a note) when L is not a power of two."""
    L = check_levels(levels)
    k = bits_per_pixel(L)
    if L == 1 << k:
        return _Depth(
            k,
            [
                worked(
                    "k",
                    k,
                    f"k = \\log_2 L = \\log_2 {int_tex(L)} = {k} \\text{{ bits per pixel}}",
                )
            ],
            [],
        )
    log = fmt(Fraction(math.log2(L)), 3)
    note = (
        f"L = {int_text(L)} is not a power of two: 2^{k - 1} = {int_text(1 << (k - 1))} < {int_text(L)} "
        f"< {int_text(1 << k)} = 2^{k}, so a pixel needs ⌈log2 L⌉ = {k} bits (log2 L = {log} is "
        f"not a whole number of bits; {k} bits could hold {int_text(1 << k)} levels)."
    )
    return _Depth(
        k,
        [
            worked(
                "k",
                k,
                f"k = \\lceil \\log_2 L \\rceil = \\lceil \\log_2 {int_tex(L)} \\rceil = "
                f"\\lceil {log} \\rceil = {k} \\text{{ bits per pixel}}",
            )
        ],
        [note],
    )


def _depth_quantities(
    levels: Number | None, bits: Number | None, binary: bool, color: str | None
) -> _Depth:
    """Bits per pixel, with the working and notes, for the one depth option given."""
    chosen = [levels is not None, bits is not None, binary, color is not None]
    if sum(chosen) != 1:
        raise InputError(
            "give exactly one pixel depth: the levels L, the bits B, binary (1 bit) or rgb24 "
            "colour (24 bits)"
        )
    if binary:
        return _binary_depth()
    if color is not None:
        return _colour_depth(color)
    if bits is not None:
        return _bits_depth(bits)
    assert levels is not None
    return _levels_depth(levels)


def _storage_given(M: int, N: int, levels: Number | None, F: int) -> tuple[Quantity, ...]:
    L = int(levels) if levels is not None else 0  # checked by _depth_quantities
    return (
        worked("M", M, f"M = {int_tex(M)}"),
        worked("N", N, f"N = {int_tex(N)}"),
        *((worked("L", L, f"L = {int_tex(L)}"),) if levels is not None else ()),
        *((worked("F", F, f"F = {int_tex(F)} \\text{{ frames}}"),) if F > 1 else ()),
    )


def _size_quantities(M: int, N: int, k: int, F: int, b: int) -> tuple[Quantity, ...]:
    """``b = M × N × k (× F)`` bits and ``b / 8`` bytes."""
    unit = "bit" if b == 1 else "bits"
    frame_t, frame_x = (r" \times F", f" \\times {int_tex(F)}") if F > 1 else ("", "")
    by = size_text(Fraction(b, 8))
    return (
        worked(
            "bits",
            b,
            f"b = M \\times N \\times k{frame_t} = {int_tex(M)} "
            f"\\times {int_tex(N)} \\times {k}{frame_x} = "
            f"{int_tex(b)} \\text{{ {unit}}}",
        ),
        worked(
            "bytes",
            normalize(Fraction(b, 8)),
            f"\\text{{bytes}} = b / 8 = {int_tex(b)} / 8 = {_tex(by)} \\text{{ bytes}}",
        ),
    )


def _depth_name(levels: Number | None, bits: Number | None, binary: bool, color: str | None) -> str:
    if binary:
        return "binary"
    if color:
        return "24-bit colour"
    return f"{int(bits)}-bit" if bits is not None else f"L = {levels}"


_SIZE_COLUMNS = (
    heading("unit", r"\text{unit}", role="label"),
    heading("bytes_per_unit", r"\text{bytes per unit}"),
    heading("size", r"\text{size}"),
)


def _size_rows(b: int) -> Iterator[tuple[str, Number, str]]:
    # storage of 1024 x 768, L = 256 -> bits 6291456 ; bytes 786432 ; KB 786.432 ; ...
    nbytes = Fraction(b, 8)
    yield ("bits", Fraction(1, 8), str(b))
    yield ("bytes", 1, size_text(nbytes, cell=True))
    for unit, divisor in UNITS:
        yield (unit, divisor, size_text(nbytes / divisor, cell=True))


def storage_solution(
    m: Number,
    n: Number,
    *,
    levels: Number | None = None,
    bits: Number | None = None,
    binary: bool = False,
    color: str | None = None,
    frames: Number = 1,
) -> Solution:
    """The storage an M × N image (or F frames of it) needs: ``M × N × k × F`` bits.

    Exactly one of ``levels`` (L gray levels, ``k = ⌈log2 L⌉``), ``bits`` (``k = B``,
    ``L = 2**B``), ``binary`` (``k = 1``) or ``color="rgb24"`` (``k = 24``) gives the depth.

    Notes
    -----
    The notes' formula is ``M × N × log2 L`` bits; for L not a power of two a pixel still needs
    a whole number of bits, ``k = ⌈log2 L⌉`` (computed exactly as ``(L - 1).bit_length()``),
    and the answer says so. Sizes are given in bytes (8 bits), KB and MB (1000 and 1000²
    bytes) and KiB and MiB (1024 and 1024² bytes), because published examples disagree on the
    divisor; a size that is not a terminating decimal within 6 places is shown with ``≈``.

    Examples
    --------
    >>> sol = storage_solution(1024, 768, levels=256)
    >>> for q in sol.derived:
    ...     print(q.text)
    k = log₂ L = log₂ 256 = 8 bits per pixel
    b = M × N × k = 1024 × 768 × 8 = 6,291,456 bits
    bytes = b / 8 = 6,291,456 / 8 = 786,432 bytes
    >>> for row in sol.tables[0].rows():
    ...     print(*row, sep=" | ")
    bits | 1/8 | 6291456
    bytes | 1 | 786432
    KB | 1000 | 786.432
    MB | 1000000 | 0.786432
    KiB | 1024 | 768
    MiB | 1048576 | 0.75
    """
    M, N = check_positive(m, "M", param="m"), check_positive(n, "N", param="n")
    F = check_positive(frames, "F (frames)", param="frames")
    k, depth, notes = _depth_quantities(levels, bits, binary, color)
    b = storage_bits(M, N, k, F)
    nbytes = Fraction(b, 8)
    if nbytes.denominator != 1:
        notes.append(
            f"{size_text(nbytes)} bytes is not a whole number of bytes: {math.ceil(nbytes)} "
            "bytes when rounded up to whole bytes."
        )
    frames_title = f", {F} frames" if F > 1 else ""
    return Solution(
        primitive="image",
        algorithm="storage",
        title=f"Storage of a {M} x {N} image ({_depth_name(levels, bits, binary, color)}{frames_title})",
        given=_storage_given(M, N, levels, F),
        derived=(*depth, *_size_quantities(M, N, k, F, b)),
        notes=tuple(notes),
        walk=Walk(tables=(Table("Size in each unit", _SIZE_COLUMNS, lambda: _size_rows(b)),)),
        data={"sizes": sizes(b)},
    )
