"""Image representation: storage, quantization, sampling and the notes' grayscale ramp.

The IMAGE REPRESENTATION section of the notes, as worked answers:

* :func:`storage_solution`: the storage formula ``M × N × k`` bits with ``k = ⌈log2 L⌉`` bits per
  pixel (``--binary``: 1 bit, ``--color rgb24``: 24 bits), in bits, bytes, KB/MB (1000) and
  KiB/MiB (1024);
* :func:`quantization_rows` / :func:`quantize_solution`: the quantization table (decimal value,
  binary code, gray-level name) with, for an input range, each level's interval of inputs and
  its reconstruction value (:class:`Quantizer`);
* :func:`sample_levels` / :func:`sample_solution`: sample ``f(x, y)`` on an M × N grid and
  quantize the samples to L levels (numpy, in blocks of rows);
* :func:`ramp` / :func:`ramp_solution`: the notes' 8 × 8 grayscale example (L = 8), for any
  size and L.

Matrices are indexed like the notes' example: row ``i`` (0 at the top), column ``j`` (0 at the
left). A sampled image puts x along the columns (to the right) and y along the rows, up by
default, as everywhere in scanconv. Nothing here prints; the solutions are rendered by
:mod:`scanconv.render`.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

from ..core.numeric import (
    Number,
    as_int,
    check_between,
    fmt,
    fmt_paren,
    fmt_short,
    normalize,
    paren,
)
from ..core.records import MAX_GRID_CELLS as PICTURE_LIMIT
from ..core.records import Column, Quantity, ShadedMatrix, Solution, Table

if TYPE_CHECKING:  # numpy is imported where arrays are made: storage and quantize start faster
    import numpy as np

MAX_BITS = 24
"""Most bits per pixel accepted (the notes' 24-bit true colour)."""

MAX_LEVELS = 1 << MAX_BITS
"""Most gray levels accepted: ``2**24``."""

MAX_SIDE = 4096
"""The matrix limit of ``sample`` and ``ramp`` is ``MAX_SIDE × MAX_SIDE`` cells."""

MAX_CELLS = MAX_SIDE * MAX_SIDE
"""Most cells in a sampled or ramp matrix (16,777,216: a 4096 × 4096 image).

Checked before anything is allocated. At the limit the levels take at most 64 MiB (one to four
bytes a cell), the samples are evaluated in blocks of :data:`BLOCK_SAMPLES`, and the printed
matrix is already 35 MB of text or more; a larger matrix is not an exam answer.
"""

BLOCK_SAMPLES = 1 << 20
"""Samples of f evaluated at once (8 MiB of float64 per temporary array)."""

GRAY_NAMES: dict[int, tuple[str, ...]] = {
    1: ("Black", "White"),
    2: ("Black", "Dark Gray", "Light Gray", "White"),
    3: (
        "Black",
        "Very Dark Gray",
        "Dark Gray",
        "Gray",
        "Light Gray",
        "Very Light Gray",
        "Almost White",
        "White",
    ),
}
"""Gray-level names by bits: 3 bits are the notes' table; 1 and 2 bits name the same ends."""

RECON = ("midpoint", "lower")
"""Reconstruction conventions of :class:`Quantizer`."""


# --- validation -----------------------------------------------------------------------------


def positive(value: Number, what: str) -> int:
    """``value`` as an integer >= 1, or ``ValueError`` naming ``what``.

    >>> positive(Fraction(8), "M")
    8
    >>> positive(0, "M")
    Traceback (most recent call last):
    ...
    ValueError: M must be a positive integer, got 0
    """
    n = as_int(value, what)
    if n < 1:
        raise ValueError(f"{what} must be a positive integer, got {n}")
    return n


def check_levels(value: Number) -> int:
    """The number of gray levels L as an ``int`` in ``2 .. 2**24``.

    >>> check_levels(1)
    Traceback (most recent call last):
    ...
    ValueError: L must be at least 2 (a binary image has L = 2), got 1
    """
    levels = as_int(value, "L")
    if levels < 2:
        raise ValueError(f"L must be at least 2 (a binary image has L = 2), got {levels}")
    if levels > MAX_LEVELS:
        raise ValueError(
            f"L = {levels:,} needs {bits_per_pixel(levels)} bits per pixel; at most {MAX_BITS} "
            f"bits (L <= {MAX_LEVELS:,})"
        )
    return levels


def check_bits(value: Number) -> int:
    """Bits per pixel as an ``int`` in ``1 .. 24``.

    >>> check_bits(25)
    Traceback (most recent call last):
    ...
    ValueError: bits per pixel must be at most 24, got 25
    """
    return check_between(as_int(value, "bits per pixel"), "bits per pixel", 1, MAX_BITS)


def check_cells(m: int, n: int) -> None:
    """Refuse an M × N matrix beyond :data:`MAX_CELLS`, before anything is allocated.

    >>> check_cells(8192, 8192)
    Traceback (most recent call last):
    ...
    ValueError: 8192 x 8192 = 67,108,864 cells is too large (at most 4096 x 4096 = 16,777,216 cells)
    """
    if m * n > MAX_CELLS:
        raise ValueError(
            f"{m} x {n} = {m * n:,} cells is too large "
            f"(at most {MAX_SIDE} x {MAX_SIDE} = {MAX_CELLS:,} cells)"
        )


def parse_size(text: str) -> tuple[int, int]:
    """``"8x6"`` -> ``(8, 6)`` (M rows, N columns); ``"8"`` -> ``(8, 8)``.

    >>> parse_size("8x6"), parse_size("5")
    ((8, 6), (5, 5))
    >>> parse_size("0x4")
    Traceback (most recent call last):
    ...
    ValueError: M (rows) must be a positive integer, got 0
    """
    parts = text.strip().lower().replace("×", "x").split("x")
    if len(parts) > 2 or not all(p.strip().isdecimal() and len(p.strip()) <= 12 for p in parts):
        raise ValueError(f"size must be M x N in positive integers, like 8x8 or 8 (got {text!r})")
    m = positive(int(parts[0]), "M (rows)")
    n = positive(int(parts[-1]), "N (columns)")
    return m, n


# --- storage --------------------------------------------------------------------------------


def bits_per_pixel(levels: int) -> int:
    """``⌈log2 L⌉``, computed exactly: the bits a pixel of L levels needs.

    >>> bits_per_pixel(256), bits_per_pixel(100), bits_per_pixel(2)
    (8, 7, 1)
    """
    return (levels - 1).bit_length()


def _int(n: int) -> str:
    """``6,291,456``; numbers below 10,000 stay as they are (``1024``)."""
    return f"{n:,}" if abs(n) >= 10_000 else str(n)


def _tex_int(n: int) -> str:
    """``6{,}291{,}456`` (a comma in math mode without the space after it)."""
    return _int(n).replace(",", "{,}")


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
    return ("≈ " if approx else "") + _int(int(whole)) + dot + frac


UNITS: tuple[tuple[str, int], ...] = (
    ("KB", 1000),
    ("MB", 1000**2),
    ("KiB", 1024),
    ("MiB", 1024**2),
)
"""The size units and their bytes: decimal (1000, 1000²) and binary (1024, 1024²)."""


def storage_bits(m: int, n: int, bits: int, frames: int = 1) -> int:
    """``M × N × k × F`` bits.

    >>> storage_bits(1024, 768, 8)
    6291456
    """
    return m * n * bits * frames


def storage_quantity(m: int, n: int, levels: int) -> Quantity:
    """The storage of one M × N image of L levels, in one line of working.

    >>> print(storage_quantity(8, 8, 8).text)
    storage = M × N × ⌈log2 L⌉ = 8 × 8 × 3 = 192 bits = 24 bytes
    """
    k = bits_per_pixel(levels)
    b = storage_bits(m, n, k)
    unit = "bit" if b == 1 else "bits"
    by = size_text(Fraction(b, 8))
    return Quantity(
        "storage_bits",
        b,
        f"storage = M × N × ⌈log2 L⌉ = {m} × {n} × {k} = {_int(b)} {unit} = {by} bytes",
        f"\\text{{storage}} = M \\times N \\times \\lceil \\log_2 L \\rceil = {m} \\times {n} "
        f"\\times {k} = {_tex_int(b)} \\text{{ {unit}}} = {_tex(by)} \\text{{ bytes}}",
    )


def _tex(s: str) -> str:
    """A size from :func:`size_text` as math: ``≈`` and thousands commas."""
    return s.replace("≈", "\\approx").replace(",", "{,}")


def _depth_quantities(
    levels: Number | None, bits: Number | None, binary: bool, color: str | None
) -> tuple[int, list[Quantity], list[str]]:
    """Bits per pixel, with the working and notes, for the one depth option given."""
    chosen = [levels is not None, bits is not None, binary, color is not None]
    if sum(chosen) != 1:
        raise ValueError("give exactly one of --levels L, --bits B, --binary, --color rgb24")
    if binary:
        return (
            1,
            [
                Quantity(
                    "k",
                    1,
                    "k = 1 bit per pixel (binary image: L = 2, 0 = black, 1 = white)",
                    r"k = 1 \text{ bit per pixel (binary image: } L = 2\text{, 0 = black, "
                    r"1 = white)}",
                )
            ],
            [],
        )
    if color is not None:
        if color != "rgb24":
            raise ValueError(f"unknown colour format {color!r} (choose from rgb24)")
        return (
            24,
            [
                Quantity(
                    "k",
                    24,
                    "k = 3 × 8 = 24 bits per pixel (R, G, B: 8 bits each, true colour)",
                    r"k = 3 \times 8 = 24 \text{ bits per pixel (R, G, B: 8 bits each, "
                    r"true colour)}",
                ),
                Quantity(
                    "L",
                    MAX_LEVELS,
                    f"L = 2^24 = {_int(MAX_LEVELS)} colours",
                    f"L = 2^{{24}} = {_tex_int(MAX_LEVELS)} \\text{{ colours}}",
                ),
            ],
            [],
        )
    if bits is not None:
        b = check_bits(bits)
        return (
            b,
            [
                Quantity(
                    "L",
                    1 << b,
                    f"L = 2^B = 2^{b} = {_int(1 << b)} levels",
                    f"L = 2^B = 2^{{{b}}} = {_tex_int(1 << b)} \\text{{ levels}}",
                ),
                Quantity(
                    "k",
                    b,
                    f"k = B = {b} bits per pixel",
                    f"k = B = {b} \\text{{ bits per pixel}}",
                ),
            ],
            [],
        )
    assert levels is not None
    L = check_levels(levels)
    k = bits_per_pixel(L)
    if L == 1 << k:
        return (
            k,
            [
                Quantity(
                    "k",
                    k,
                    f"k = log2 L = log2 {_int(L)} = {k} bits per pixel",
                    f"k = \\log_2 L = \\log_2 {_tex_int(L)} = {k} \\text{{ bits per pixel}}",
                )
            ],
            [],
        )
    log = fmt(Fraction(math.log2(L)), 3)
    note = (
        f"L = {_int(L)} is not a power of two: 2^{k - 1} = {_int(1 << (k - 1))} < {_int(L)} "
        f"< {_int(1 << k)} = 2^{k}, so a pixel needs ⌈log2 L⌉ = {k} bits (log2 L = {log} is "
        f"not a whole number of bits; {k} bits could hold {_int(1 << k)} levels)."
    )
    return (
        k,
        [
            Quantity(
                "k",
                k,
                f"k = ⌈log2 L⌉ = ⌈log2 {_int(L)}⌉ = ⌈{log}⌉ = {k} bits per pixel",
                f"k = \\lceil \\log_2 L \\rceil = \\lceil \\log_2 {_tex_int(L)} \\rceil = "
                f"\\lceil {log} \\rceil = {k} \\text{{ bits per pixel}}",
            )
        ],
        [note],
    )


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
    k = log2 L = log2 256 = 8 bits per pixel
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
    M, N = positive(m, "M"), positive(n, "N")
    F = positive(frames, "F (frames)")
    k, depth, notes = _depth_quantities(levels, bits, binary, color)
    b = storage_bits(M, N, k, F)
    unit = "bit" if b == 1 else "bits"
    nbytes = Fraction(b, 8)
    frame_t, frame_x = (" × F", f" × {_int(F)}") if F > 1 else ("", "")
    frame_tt, frame_tx = (r" \times F", f" \\times {_tex_int(F)}") if F > 1 else ("", "")
    given = [
        Quantity("M", M, f"M = {_int(M)}", f"M = {_tex_int(M)}"),
        Quantity("N", N, f"N = {_int(N)}", f"N = {_tex_int(N)}"),
    ]
    if levels is not None:
        L = int(levels)  # checked by _depth_quantities
        given.append(Quantity("L", L, f"L = {_int(L)}", f"L = {_tex_int(L)}"))
    if F > 1:
        given.append(Quantity("F", F, f"F = {_int(F)} frames", f"F = {F} \\text{{ frames}}"))
    by = size_text(nbytes)
    derived = [
        *depth,
        Quantity(
            "bits",
            b,
            f"b = M × N × k{frame_t} = {_int(M)} × {_int(N)} × {k}{frame_x} = {_int(b)} {unit}",
            f"b = M \\times N \\times k{frame_tt} = {_tex_int(M)} "
            f"\\times {_tex_int(N)} \\times {k}{frame_tx} = "
            f"{_tex_int(b)} \\text{{ {unit}}}",
        ),
        Quantity(
            "bytes",
            normalize(nbytes),
            f"bytes = b / 8 = {_int(b)} / 8 = {by} bytes",
            f"\\text{{bytes}} = b / 8 = {_tex_int(b)} / 8 = {_tex(by)} \\text{{ bytes}}",
        ),
    ]
    if nbytes.denominator != 1:
        notes.append(
            f"{by} bytes is not a whole number of bytes: {math.ceil(nbytes)} bytes when "
            "rounded up to whole bytes."
        )
    sizes = {"bits": b, "bytes": nbytes, **{u: nbytes / d for u, d in UNITS}}

    def rows() -> Iterator[tuple[str, Number, str]]:
        # storage 1024 768 --levels 256 -> bits 6291456 ; bytes 786432 ; KB 786.432 ; ...
        yield ("bits", Fraction(1, 8), str(b))
        yield ("bytes", 1, size_text(nbytes, cell=True))
        for unit, divisor in UNITS:
            yield (unit, divisor, size_text(nbytes / divisor, cell=True))

    what = (
        "binary"
        if binary
        else "24-bit colour"
        if color
        else f"{int(bits)}-bit"
        if bits is not None
        else f"L = {levels}"
    )
    frames_title = f", {F} frames" if F > 1 else ""
    return Solution(
        primitive="image",
        algorithm="storage",
        title=f"Storage of a {M} x {N} image ({what}{frames_title})",
        given=tuple(given),
        derived=tuple(derived),
        notes=tuple(notes),
        tables=(
            Table(
                "Size in each unit",
                (
                    Column("unit", "unit", r"\text{unit}"),
                    Column("bytes_per_unit", "bytes per unit", r"\text{bytes per unit}"),
                    Column("size", "size", r"\text{size}"),
                ),
                rows,
            ),
        ),
        data={"sizes": sizes},
    )


# --- quantization ---------------------------------------------------------------------------


def gray_name(k: int, levels: int) -> str:
    """The name of gray level ``k`` of ``levels``: the notes' names for 8 levels.

    1 to 3 bits use :data:`GRAY_NAMES`; more levels are ``Black``, ``Gray k/(L-1)`` and
    ``White``.

    >>> gray_name(6, 8), gray_name(1, 4), gray_name(5, 16), gray_name(15, 16)
    ('Almost White', 'Dark Gray', 'Gray 5/15', 'White')
    """
    names = GRAY_NAMES.get(bits_per_pixel(levels))
    if names is not None and len(names) == levels:
        return names[k]
    if k == 0:
        return "Black"
    if k == levels - 1:
        return "White"
    return f"Gray {k}/{levels - 1}"


@dataclass(frozen=True, slots=True)
class Quantizer:
    """A uniform quantizer of the input range ``[lo, hi]`` onto ``levels`` levels.

    ``integer=True``: the inputs are the integers ``lo .. hi`` (an 8-bit image is 0 .. 255),
    so the range holds ``hi - lo + 1`` values; ``integer=False``: any real value in
    ``[lo, hi]``. With the width ``W`` (``hi - lo + 1`` or ``hi - lo``) and ``Δ = W / L``,
    level ``k`` is ``⌊(v - lo) / Δ⌋``, clamped to ``0 .. L - 1`` (so ``hi`` itself is the top
    level of a real range). The reconstruction value of level ``k`` is the midpoint
    ``lo + (k + 1/2) Δ`` of its cell ``[lo + kΔ, lo + (k + 1)Δ)`` (``recon="midpoint"``, a
    mid-rise quantizer) or its lower end ``lo + kΔ`` (``recon="lower"``).

    >>> q = Quantizer.make(0, 255, 4)
    >>> q.step, [q.level(v) for v in (0, 63, 64, 255)], [q.reconstruction(k) for k in range(4)]
    (64, [0, 0, 1, 3], [32, 96, 160, 224])
    """

    lo: Number
    hi: Number
    levels: int
    integer: bool = True
    recon: str = "midpoint"

    @classmethod
    def make(
        cls,
        lo: Number | float,
        hi: Number | float,
        levels: Number,
        *,
        integer: bool = True,
        recon: str = "midpoint",
    ) -> Quantizer:
        """A checked quantizer: ``lo < hi``, integer bounds for integer inputs, L >= 2."""
        L = check_levels(levels)
        if recon not in RECON:
            raise ValueError(f"unknown reconstruction {recon!r} (choose from {', '.join(RECON)})")
        flo, fhi = normalize(Fraction(lo)), normalize(Fraction(hi))
        if not flo < fhi:
            raise ValueError(
                f"the input range must have LO < HI, got {fmt_short(flo)} and {fmt_short(fhi)}"
            )
        if integer:
            if not (isinstance(flo, int) and isinstance(fhi, int)):
                raise ValueError(
                    f"integer inputs need integer LO and HI, got {fmt_short(flo)} and "
                    f"{fmt_short(fhi)} (use --input real for a continuous range)"
                )
            if fhi - flo + 1 < L:
                raise ValueError(
                    f"the integers {flo} .. {fhi} are only {fhi - flo + 1} input values, "
                    f"fewer than L = {L} levels (use --input real for a continuous range)"
                )
        return cls(flo, fhi, L, integer, recon)

    @property
    def width(self) -> Number:
        """``hi - lo + 1`` for integer inputs, ``hi - lo`` for real ones."""
        return self.hi - self.lo + (1 if self.integer else 0)

    @property
    def step(self) -> Number:
        """``Δ = W / L``, the width of one level's cell."""
        return normalize(Fraction(self.width) / self.levels)

    def level(self, v: Number | float) -> int:
        """The level of input ``v``, exactly: ``⌊(v - lo) L / W⌋`` clamped to ``0 .. L - 1``."""
        k = math.floor((Fraction(v) - self.lo) * self.levels / self.width)
        return min(max(k, 0), self.levels - 1)

    def levels_of(self, values: np.ndarray) -> np.ndarray:
        """:meth:`level` of every value of a float array, in float64 (monotonic, clamped)."""
        import numpy as np

        lo, width = float(self.lo), float(self.width)
        k = np.floor((values - lo) * self.levels / width)
        return np.clip(k, 0, self.levels - 1).astype(level_dtype(self.levels))

    def interval(self, k: int) -> tuple[Number, Number]:
        """The inputs of level ``k``: first and last integer, or the cell ``[from, to)``."""
        if self.integer:
            W, L = int(self.width), self.levels
            first = int(self.lo) + -(-k * W // L)
            last = int(self.lo) + -(-(k + 1) * W // L) - 1
            return first, last
        return (
            normalize(self.lo + k * Fraction(self.step)),
            normalize(self.lo + (k + 1) * Fraction(self.step)),
        )

    def reconstruction(self, k: int) -> Number:
        """The value level ``k`` stands for (the midpoint or lower end of its cell)."""
        offset = Fraction(1, 2) if self.recon == "midpoint" else 0
        return normalize(self.lo + (k + offset) * Fraction(self.step))


def level_dtype(levels: int) -> type[np.unsignedinteger]:
    """The smallest unsigned integer type that holds ``0 .. levels - 1``.

    >>> level_dtype(256).__name__, level_dtype(257).__name__
    ('uint8', 'uint16')
    """
    import numpy as np

    if levels <= 1 << 8:
        return np.uint8
    if levels <= 1 << 16:
        return np.uint16
    return np.uint32


def quantization_rows(bits: int, quantizer: Quantizer | None = None) -> Iterator[tuple]:
    """The rows of the quantization table of ``bits`` bits: one per level, in order.

    Each row is ``(k, binary code, gray-level name)``, plus ``(from, to, reconstruction)``
    with a quantizer.

    Notes
    -----
    ``L = 2**bits`` levels ``0 .. L - 1``; the code is ``k`` in ``bits`` binary digits. Names
    are the notes' for 3 bits (:data:`GRAY_NAMES`), see :func:`gray_name`.

    Examples
    --------
    The notes' 3-bit table, with the 8-bit inputs 0 .. 255 (Δ = 32, midpoints):

    >>> q = Quantizer.make(0, 255, 8)
    >>> for row in quantization_rows(3, q):
    ...     print(*row, sep=" | ")
    0 | 000 | Black | 0 | 31 | 16
    1 | 001 | Very Dark Gray | 32 | 63 | 48
    2 | 010 | Dark Gray | 64 | 95 | 80
    3 | 011 | Gray | 96 | 127 | 112
    4 | 100 | Light Gray | 128 | 159 | 144
    5 | 101 | Very Light Gray | 160 | 191 | 176
    6 | 110 | Almost White | 192 | 223 | 208
    7 | 111 | White | 224 | 255 | 240
    """
    levels = 1 << bits
    # quantization_rows(3) -> (0, '000', 'Black'), (1, '001', 'Very Dark Gray'), ... (7, '111', 'White')
    for k in range(levels):
        row: tuple = (k, format(k, f"0{bits}b"), gray_name(k, levels))
        if quantizer is not None:
            row = (*row, *quantizer.interval(k), quantizer.reconstruction(k))
        yield row


def quantize_solution(
    bits: Number,
    value_range: tuple[Number | float, Number | float] | None = None,
    *,
    integer: bool = True,
    recon: str = "midpoint",
) -> Solution:
    """The quantization table for ``bits`` bits, optionally over an input range.

    Examples
    --------
    >>> sol = quantize_solution(2, (0, 255))
    >>> for q in sol.derived:
    ...     print(q.text)
    L = 2^B = 2^2 = 4 levels, 0 to 3
    Δ = (HI − LO + 1) / L = (255 − 0 + 1) / 4 = 64
    level = ⌊(v − LO) / Δ⌋ = ⌊(v − 0) / 64⌋
    r_k = LO + (k + 1/2)·Δ = 0 + (k + 1/2)·64
    >>> [row[-1] for row in sol.tables[0].rows()]
    [32, 96, 160, 224]
    """
    B = check_bits(bits)
    L = 1 << B
    derived = [
        Quantity(
            "L",
            L,
            f"L = 2^B = 2^{B} = {_int(L)} levels, 0 to {_int(L - 1)}",
            f"L = 2^B = 2^{{{B}}} = {_tex_int(L)} \\text{{ levels, 0 to }} {_tex_int(L - 1)}",
        )
    ]
    notes: list[str] = []
    if B in GRAY_NAMES and B != 3:
        notes.append(
            "Gray-level names: the notes name the 3-bit levels only; these names keep its ends "
            "(Black, White) and its Dark Gray / Light Gray."
        )
    elif B not in GRAY_NAMES:
        notes.append(
            "Gray-level names: the notes name the 3-bit levels only; level k of L is named "
            f"Gray k/{L - 1} here, with 0 Black and {L - 1} White."
        )
    columns = [
        Column("decimal", "Decimal value", r"\text{Decimal value}"),
        Column("binary", f"Binary ({B} bits)", f"\\text{{Binary ({B} bits)}}"),
        Column("gray_level", "Gray level", r"\text{Gray level}"),
    ]
    q = None
    if value_range is not None:
        q = Quantizer.make(value_range[0], value_range[1], L, integer=integer, recon=recon)
        derived.extend(_quantizer_working(q))
        notes.append(_quantizer_note(q))
        edges = None if q.integer else _places(q.lo, q.step)
        columns += [
            Column("from", "from", r"\text{from}", edges),
            Column("to", "to", r"\text{to}", edges),
            Column(
                "reconstruction",
                "reconstruction r_k",
                r"\text{reconstruction } r_k",
                _places(q.reconstruction(0), q.step),
            ),
        ]
    names = {1: "Binary", 2: "2-bit", 3: "3-bit"}
    return Solution(
        primitive="image",
        algorithm="quantize",
        title=f"{names.get(B, f'{B}-bit')} quantization ({_int(L)} gray levels)",
        given=(Quantity("B", B, f"B = {B} bits", f"B = {B} \\text{{ bits}}"),),
        derived=tuple(derived),
        notes=tuple(notes),
        tables=(Table("Quantization table", tuple(columns), lambda: quantization_rows(B, q)),),
        data=(
            {}
            if q is None
            else {"range": [q.lo, q.hi], "input": "integer" if q.integer else "real"}
            | {"reconstruction": q.recon}
        ),
    )


def _places(*values: Number) -> int | None:
    """Decimals that show every value of ``lo + k·step`` exactly (at most 6, else 3).

    ``None`` when they are all integers.

    >>> _places(0, Fraction(1, 16)), _places(16, 32), _places(Fraction(1, 3))
    (4, None, 3)
    """
    places = 0
    for v in values:
        q = Fraction(v)
        p = next((p for p in range(7) if (q * 10**p).denominator == 1), None)
        if p is None:
            return 3
        places = max(places, p)
    return places or None


def _quantizer_working(q: Quantizer) -> list[Quantity]:
    lo, hi, step = fmt_short(q.lo), fmt_paren(q.hi), fmt_paren(q.step)
    plus1, plus1_t = (" + 1", " + 1") if q.integer else ("", "")
    off, off_t = ("(k + 1/2)", r"(k + \tfrac{1}{2})") if q.recon == "midpoint" else ("k", "k")
    return [
        Quantity(
            "step",
            q.step,
            f"Δ = (HI − LO{plus1}) / L = ({hi} − {fmt_paren(q.lo)}{plus1}) / {q.levels} = "
            f"{fmt_short(q.step)}",
            f"\\Delta = \\frac{{HI - LO{plus1_t}}}{{L}} = \\frac{{{hi} - {fmt_paren(q.lo)}"
            f"{plus1_t}}}{{{q.levels}}} = {fmt_short(q.step)}",
        ),
        Quantity(
            "level",
            None,
            f"level = ⌊(v − LO) / Δ⌋ = ⌊(v − {fmt_paren(q.lo)}) / {step}⌋"
            + ("" if q.integer else f", at most L − 1 = {q.levels - 1}"),
            f"\\text{{level}} = \\lfloor (v - LO) / \\Delta \\rfloor = \\lfloor (v - "
            f"{fmt_paren(q.lo)}) / {step} \\rfloor"
            + ("" if q.integer else f", \\text{{ at most }} L - 1 = {q.levels - 1}"),
        ),
        Quantity(
            "reconstruction",
            None,
            f"r_k = LO + {off}·Δ = {lo} + {off}·{step}",
            f"r_k = LO + {off_t} \\cdot \\Delta = {lo} + {off_t} \\cdot {step}",
        ),
    ]


def _quantizer_note(q: Quantizer) -> str:
    if q.integer:
        inputs = (
            f"Inputs are the integers {fmt_short(q.lo)} .. {fmt_short(q.hi)}; "
            "'from' and 'to' are the first and last input of each level."
        )
    else:
        inputs = (
            f"Inputs are real values in [{fmt_short(q.lo)}, {fmt_short(q.hi)}]; level k takes "
            f"[from, to), the top level also takes {fmt_short(q.hi)}."
        )
    if q.recon == "midpoint":
        rule = "the midpoint of the level's cell [LO + kΔ, LO + (k + 1)Δ) (--recon lower: its lower end)"
    else:
        rule = "the lower end LO + kΔ of the level's cell (the default, --recon midpoint, is its midpoint)"
    return f"{inputs} Reconstruction value: {rule}."


# --- matrices: the shaded picture and the table ---------------------------------------------


def matrix_columns(n: int) -> tuple[Column, ...]:
    """Columns of a level matrix: the row index ``i``, then one per column ``j = 0 .. N-1``."""
    return (Column("i", "i", "i"), *(Column(str(j), str(j), str(j)) for j in range(n)))


def _picture_note(m: int, n: int) -> str | None:
    if m > PICTURE_LIMIT or n > PICTURE_LIMIT:
        return (
            f"Shaded picture left out: {m} x {n} is more than {PICTURE_LIMIT} "
            f"{'columns' if n > PICTURE_LIMIT else 'rows'}; the matrix is complete."
        )
    return None


# --- the grayscale ramp ---------------------------------------------------------------------


def ramp_row(i: int, n: int, levels: int) -> np.ndarray:
    """Row ``i`` of the ramp: ``i + j`` folded back at ``L - 1``, for ``j = 0 .. n - 1``.

    >>> ramp_row(1, 8, 8).tolist()
    [1, 2, 3, 4, 5, 6, 7, 6]
    """
    import numpy as np

    period = 2 * (levels - 1)
    s = (i + np.arange(n, dtype=np.int64)) % period
    return np.where(s > levels - 1, period - s, s).astype(level_dtype(levels))


def ramp(m: Number, n: Number, levels: Number) -> np.ndarray:
    """The notes' grayscale ramp as an M × N matrix of L levels.

    Notes
    -----
    Row ``i``, column ``j`` holds ``s = (i + j) mod 2(L - 1)`` if ``s <= L - 1``, else
    ``2(L - 1) - s``: the sum ``i + j`` rises to ``L - 1`` and folds back (a triangle wave of
    period ``2(L - 1)`` along each row and column). For 8 × 8 and L = 8 this is the notes'
    example matrix exactly.

    Examples
    --------
    >>> print(ramp(8, 8, 8))
    [[0 1 2 3 4 5 6 7]
     [1 2 3 4 5 6 7 6]
     [2 3 4 5 6 7 6 5]
     [3 4 5 6 7 6 5 4]
     [4 5 6 7 6 5 4 3]
     [5 6 7 6 5 4 3 2]
     [6 7 6 5 4 3 2 1]
     [7 6 5 4 3 2 1 0]]
    """
    import numpy as np

    M, N, L = positive(m, "M (rows)"), positive(n, "N (columns)"), check_levels(levels)
    check_cells(M, N)
    out = np.empty((M, N), dtype=level_dtype(L))
    # ramp(8, 8, 8) -> row 0: 0 1 2 3 4 5 6 7 ; row 1: 1 2 3 4 5 6 7 6 ; ... row 7: 7 6 5 ... 0
    for i in range(M):
        out[i] = ramp_row(i, N, L)
    return out


def ramp_solution(m: Number, n: Number, levels: Number) -> Solution:
    """The notes' grayscale example (``i + j`` folded at ``L - 1``) as a worked answer.

    Rows are computed as they are printed (constant memory in M).

    >>> sol = ramp_solution(8, 8, 8)
    >>> print(sol.derived[1].text)
    f(i, j) = s if s ≤ L − 1, else 2(L − 1) − s = 14 − s, where s = (i + j) mod 2(L − 1) = (i + j) mod 14
    >>> next(iter(sol.tables[0].rows()))
    (0, 0, 1, 2, 3, 4, 5, 6, 7)
    """
    M, N, L = positive(m, "M (rows)"), positive(n, "N (columns)"), check_levels(levels)
    check_cells(M, N)
    P = 2 * (L - 1)
    k = bits_per_pixel(L)

    def rows() -> Iterator[tuple[int, ...]]:
        # ramp_solution(8, 8, 8) -> (0, 0 1 2 3 4 5 6 7), (1, 1 2 3 4 5 6 7 6), ...
        for i in range(M):
            yield (i, *ramp_row(i, N, L).tolist())

    bits_q = Quantity(
        "k",
        k,
        f"k = ⌈log2 L⌉ = ⌈log2 {L}⌉ = {k} bits per pixel (levels 0 to {L - 1})",
        f"k = \\lceil \\log_2 L \\rceil = \\lceil \\log_2 {L} \\rceil = {k} \\text{{ bits per "
        f"pixel (levels 0 to {L - 1})}}",
    )
    rule = Quantity(
        "rule",
        None,
        f"f(i, j) = s if s ≤ L − 1, else 2(L − 1) − s = {P} − s, where s = (i + j) mod "
        f"2(L − 1) = (i + j) mod {P}",
        f"f(i, j) = s \\text{{ if }} s \\le L - 1, \\text{{ else }} 2(L - 1) - s = {P} - s, "
        f"\\quad s = (i + j) \\bmod 2(L - 1) = (i + j) \\bmod {P}",
    )
    note = _picture_note(M, N)
    return Solution(
        primitive="image",
        algorithm="ramp",
        title=f"Grayscale ramp image: {M} x {N}, L = {L}",
        given=(
            Quantity("M", M, f"M = {M} rows", f"M = {M} \\text{{ rows}}"),
            Quantity("N", N, f"N = {N} columns", f"N = {N} \\text{{ columns}}"),
            Quantity("L", L, f"L = {L} gray levels", f"L = {L} \\text{{ gray levels}}"),
        ),
        derived=(bits_q, rule, storage_quantity(M, N, L)),
        notes=(
            "Row i from the top, column j from the left; 0 is black and L − 1 white.",
            *((note,) if note else ()),
        ),
        tables=(Table("Gray levels f(i, j)", matrix_columns(N), rows),),
        figures=() if note else (ShadedMatrix(tuple(tuple(r[1:]) for r in rows()), L, N),),
    )


# --- sampling and quantizing f(x, y) --------------------------------------------------------


def _num(v: Number | float) -> tuple[str, bool]:
    """A value for the working and whether it is exact: a short decimal, or 3 decimals.

    >>> _num(Fraction(7, 4)), _num(2 / 3)
    (('1.75', True), ('0.667', False))
    """
    q = Fraction(v)
    s = fmt_short(q)
    return (fmt(q), False) if "/" in s else (s, True)


def _show(v: Number | float) -> str:
    return _num(v)[0]


def _paren_show(v: Number | float) -> str:
    return paren(_show(v))


def _rel(*values: Number | float) -> tuple[str, str]:
    """``=`` if every value shows exactly, else ``≈``; as text and as TeX."""
    exact = all(_num(v)[1] for v in values)
    return ("=", "=") if exact else ("≈", r"\approx")


@dataclass(frozen=True, slots=True)
class Sampled:
    """The result of :func:`sample_levels`."""

    levels: np.ndarray
    """The M × N matrix of levels (row 0 at the top)."""
    x: np.ndarray
    """The sample x of each column, left to right."""
    y: np.ndarray
    """The sample y of each row, top to bottom."""
    quantizer: Quantizer | None
    """The quantizer of the f range; ``None`` when f is constant (every sample level 0)."""
    f_min: float
    """The smallest sample of f."""
    f_max: float
    """The largest sample of f."""
    clipped: int
    """Samples outside a given range, clamped to level 0 or L - 1."""
    expr: str
    """The expression f(x, y) as given."""
    domain: tuple[Number | float, Number | float, Number | float, Number | float]
    """``(X0, X1, Y0, Y1)`` as given (or the default)."""
    range_given: bool
    """True if the quantized range was given rather than the samples' min and max."""
    origin: str
    """``bottom-left`` (y up) or ``top-left`` (y down)."""
    L: int
    """The number of levels."""


def _axis(lo: Number | float, hi: Number | float, count: int, name: str) -> np.ndarray:
    import numpy as np

    if hi < lo or (hi == lo and count > 1):
        raise ValueError(
            f"the domain of {name} must have {name}0 < {name}1, got {_show(lo)} and {_show(hi)}"
        )
    return np.linspace(float(lo), float(hi), count)


def sample_levels(
    expr: str,
    m: Number,
    n: Number,
    levels: Number,
    *,
    domain: tuple[Number | float, Number | float, Number | float, Number | float] | None = None,
    value_range: tuple[Number | float, Number | float] | None = None,
    origin: str = "bottom-left",
) -> Sampled:
    """Sample ``f(x, y)`` on an M × N grid and quantize the samples to L levels.

    Notes
    -----
    ``domain = (X0, X1, Y0, Y1)`` (default ``(0, N - 1, 0, M - 1)``: one sample per pixel at
    integer coordinates). Column ``j`` samples ``x_j = X0 + j Δx`` with ``Δx = (X1 - X0)/(N - 1)``;
    row ``i`` samples ``y_i = Y1 - i Δy`` (row 0 at the top, y up) or, with
    ``origin="top-left"``, ``y_i = Y0 + i Δy`` (y down, screen addressing). f is evaluated in
    float64 by the safe evaluator :func:`scanconv.core.expr.compile_expr`, in blocks of
    :data:`BLOCK_SAMPLES` samples. The samples are quantized over ``value_range`` (default: the
    smallest and largest sample) by a real :class:`Quantizer`:
    ``level = min(⌊(f - f_min) L / (f_max - f_min)⌋, L - 1)``; samples outside a given range
    are clamped. A constant f gives level 0 everywhere. The size is checked against
    :data:`MAX_CELLS` before anything is allocated.

    Examples
    --------
    >>> s = sample_levels("x + y", 4, 4, 4, origin="top-left")
    >>> print(s.levels)
    [[0 0 1 2]
     [0 1 2 2]
     [1 2 2 3]
     [2 2 3 3]]
    """
    import numpy as np

    from ..core.expr import compile_expr

    M, N, L = positive(m, "M (rows)"), positive(n, "N (columns)"), check_levels(levels)
    check_cells(M, N)
    if origin not in ("bottom-left", "top-left"):
        raise ValueError(f"unknown origin {origin!r} (choose from bottom-left, top-left)")
    f = compile_expr(expr, ("x", "y"))
    x0, x1, y0, y1 = domain if domain is not None else (0, N - 1, 0, M - 1)
    xs = _axis(x0, x1, N, "x")
    ys = _axis(y0, y1, M, "y")
    if origin == "bottom-left":
        ys = ys[::-1].copy()
    per_block = max(1, BLOCK_SAMPLES // N)

    def blocks() -> Iterator[tuple[int, np.ndarray]]:
        # sample "x + y" 4x4, top-left -> rows of f: 0 1 2 3 ; 1 2 3 4 ; 2 3 4 5 ; 3 4 5 6
        for start in range(0, M, per_block):
            yield start, np.asarray(f(x=xs[None, :], y=ys[start : start + per_block, None]))

    lo_f, hi_f = math.inf, -math.inf
    for _, block in blocks():
        lo_f, hi_f = min(lo_f, float(block.min())), max(hi_f, float(block.max()))
    out = np.zeros((M, N), dtype=level_dtype(L))
    if value_range is not None:
        q: Quantizer | None = Quantizer.make(*value_range, L, integer=False)
    elif hi_f > lo_f:
        q = Quantizer.make(lo_f, hi_f, L, integer=False)
    else:
        q = None
    clipped = 0
    if q is not None:
        lo, hi = float(q.lo), float(q.hi)
        for start, block in blocks():
            if value_range is not None:
                clipped += int(np.count_nonzero((block < lo) | (block > hi)))
            out[start : start + block.shape[0]] = q.levels_of(block)
    return Sampled(
        out,
        xs,
        ys,
        q,
        lo_f,
        hi_f,
        clipped,
        expr,
        (x0, x1, y0, y1),
        value_range is not None,
        origin,
        L,
    )


def sample_solution(s: Sampled) -> Solution:
    """Sampling and quantization of ``f(x, y)`` as a worked answer, from :func:`sample_levels`.

    >>> sol = sample_solution(sample_levels("x + y", 8, 8, 8))
    >>> for q in sol.derived[4:]:
    ...     print(q.text)
    f_min = 0, f_max = 14 (over the 64 samples)
    Δ = (f_max − f_min) / L = (14 − 0) / 8 = 1.75
    level = min(⌊(f − f_min) / Δ⌋, L − 1)
    storage = M × N × ⌈log2 L⌉ = 8 × 8 × 3 = 192 bits = 24 bytes
    >>> next(iter(sol.tables[0].rows()))
    (0, 4, 4, 5, 5, 6, 6, 7, 7)
    """
    M, N = s.levels.shape
    L, origin, expr = s.L, s.origin, s.expr
    x0, x1, y0, y1 = s.domain
    from ..core.working import tex_text

    shown = " ".join(expr.split())
    dom = f"x ∈ [{_show(x0)}, {_show(x1)}], y ∈ [{_show(y0)}, {_show(y1)}]"
    given = (
        Quantity("f", shown, f"f(x, y) = {shown}", f"f(x, y) = \\texttt{{{tex_text(shown)}}}"),
        Quantity("M", M, f"M = {M} rows", f"M = {M} \\text{{ rows}}"),
        Quantity("N", N, f"N = {N} columns", f"N = {N} \\text{{ columns}}"),
        Quantity("L", L, f"L = {L} levels", f"L = {L} \\text{{ levels}}"),
        Quantity("domain", (x0, x1, y0, y1), dom, dom.replace("∈", "\\in")),
    )
    top = "y down" if origin == "top-left" else "y up"
    y_rule = ("y0 + i·Δy", "y_0 + i \\cdot \\Delta y")
    if origin != "top-left":
        y_rule = ("y1 − i·Δy", "y_1 - i \\cdot \\Delta y")
    derived = [
        _spacing("x", x0, x1, N, "N"),
        _spacing("y", y0, y1, M, "M"),
        Quantity(
            "x_j",
            None,
            f"x_j = x0 + j·Δx, j = 0 … {N - 1} (columns, left to right)",
            f"x_j = x_0 + j \\cdot \\Delta x,\\ j = 0 \\ldots {N - 1} "
            "\\text{ (columns, left to right)}",
        ),
        Quantity(
            "y_i",
            None,
            f"y_i = {y_rule[0]}, i = 0 … {M - 1} (row 0 at the top, {top})",
            f"y_i = {y_rule[1]},\\ i = 0 \\ldots {M - 1} \\text{{ (row 0 at the top, {top})}}",
        ),
    ]
    notes = []
    q = s.quantizer
    r_min, t_min = _rel(s.f_min)
    r_max, t_max = _rel(s.f_max)
    samples = f"{M * N:,}"
    noun = "sample" if M * N == 1 else "samples"
    if not s.range_given:
        derived.append(
            Quantity(
                "f_range",
                (s.f_min, s.f_max),
                f"f_min {r_min} {_show(s.f_min)}, f_max {r_max} {_show(s.f_max)} "
                f"(over the {samples} {noun})",
                f"f_{{\\min}} {t_min} {_show(s.f_min)},\\ f_{{\\max}} {t_max} "
                f"{_show(s.f_max)} \\text{{ (over the {samples.replace(',', '{,}')} {noun})}}",
            )
        )
    else:
        assert q is not None
        derived.append(
            Quantity(
                "f_range",
                (q.lo, q.hi),
                f"f_min = {_show(q.lo)}, f_max = {_show(q.hi)} (given; the samples lie in "
                f"[{_show(s.f_min)}, {_show(s.f_max)}])",
                f"f_{{\\min}} = {_show(q.lo)},\\ f_{{\\max}} = {_show(q.hi)} \\text{{ (given; "
                f"the samples lie in }} [{_show(s.f_min)}, {_show(s.f_max)}])",
            )
        )
        if s.clipped:
            notes.append(
                f"{s.clipped:,} samples lie outside [{_show(q.lo)}, {_show(q.hi)}] and are "
                "clamped to level 0 or L − 1."
            )
    if q is None:
        notes.append(f"f is constant ({_show(s.f_min)}) on the grid: every sample is level 0.")
    else:
        lo_s, hi_s, step = _paren_show(q.lo), _paren_show(q.hi), _show(q.step)
        rel, trel = _rel(q.lo, q.hi, q.step)
        derived += [
            Quantity(
                "step",
                q.step,
                f"Δ = (f_max − f_min) / L = ({hi_s} − {lo_s}) / {L} {rel} {step}",
                f"\\Delta = \\frac{{f_{{\\max}} - f_{{\\min}}}}{{L}} = \\frac{{{hi_s} - {lo_s}}}"
                f"{{{L}}} {trel} {step}",
            ),
            Quantity(
                "level",
                None,
                "level = min(⌊(f − f_min) / Δ⌋, L − 1)",
                r"\text{level} = \min(\lfloor (f - f_{\min}) / \Delta \rfloor, L - 1)",
            ),
        ]
    derived.append(storage_quantity(M, N, L))
    picture_note = _picture_note(M, N)
    if picture_note:
        notes.append(picture_note)
    levels_m = s.levels

    def rows() -> Iterator[tuple[int, ...]]:
        # sample "x + y" 8x8 L=8 -> (0, 4 4 5 5 6 6 7 7), (1, 3 4 4 5 5 6 6 7), ...
        for i in range(M):
            yield (i, *levels_m[i].tolist())

    return Solution(
        primitive="image",
        algorithm="sample",
        title=f"Sampling and quantization of f(x, y) = {shown}: {M} x {N} samples, L = {L}",
        given=given,
        derived=tuple(derived),
        notes=tuple(notes),
        tables=(Table("Quantized levels (row i, column j)", matrix_columns(N), rows),),
        figures=()
        if picture_note
        else (ShadedMatrix(tuple(tuple(r) for r in levels_m.tolist()), L, N),),
        data={"x": s.x.tolist(), "y": s.y.tolist()},
    )


def _spacing(name: str, lo: Number | float, hi: Number | float, count: int, cname: str) -> Quantity:
    """``Δx = (x1 − x0) / (N − 1) = (7 − 0) / 7 = 1``."""
    if count == 1:
        return Quantity(
            f"d{name}",
            0,
            f"{cname} = 1: one sample, {name} = {name}0 = {_show(lo)}",
            f"{cname} = 1: \\text{{ one sample, }} {name} = {name}_0 = {_show(lo)}",
        )
    exact = not isinstance(lo, float) and not isinstance(hi, float)
    step: Number | float = (
        normalize(Fraction(hi - lo) / (count - 1))
        if exact
        else (float(hi) - float(lo)) / (count - 1)
    )
    a, b, d = _paren_show(hi), _paren_show(lo), _show(step)
    rel, trel = _rel(lo, hi, step)
    return Quantity(
        f"d{name}",
        step,
        f"Δ{name} = ({name}1 − {name}0) / ({cname} − 1) = ({a} − {b}) / {count - 1} {rel} {d}",
        f"\\Delta {name} = \\frac{{{name}_1 - {name}_0}}{{{cname} - 1}} = \\frac{{{a} - {b}}}"
        f"{{{count - 1}}} {trel} {d}",
    )
