"""The limits of the image computations and the checks that enforce them before any work.

A check raises :class:`~scanconv.core.checks.InputError` naming the library parameter it is
about (``levels``, ``bits``, ``m``, ...); the message states the rule, never a command-line flag.
"""

from __future__ import annotations

from ..core.checks import InputError, check_count, check_positive, check_whole
from ..core.numeric import Number
from .storage import bits_per_pixel

MAX_BITS = 24
"""Most bits per pixel accepted (the notes' 24-bit true colour)."""

MAX_LEVELS = 1 << MAX_BITS
"""Most gray levels accepted: ``2**24``."""

MAX_SIDE = 4096
"""The matrix limit of sampling and the ramp is ``MAX_SIDE × MAX_SIDE`` cells."""

MAX_CELLS = MAX_SIDE * MAX_SIDE
"""Most cells in a sampled or ramp matrix (16,777,216: a 4096 × 4096 image).

Checked before anything is allocated. At the limit the levels take at most 64 MiB (one to four
bytes a cell), the samples are evaluated in blocks
(:data:`~scanconv.algorithms.sample.BLOCK_SAMPLES`), and the printed matrix is already 35 MB of
text or more; a larger matrix is not an exam answer.
"""


def check_levels(value: Number) -> int:
    """The number of gray levels L as an ``int`` in ``2 .. 2**24``.

    >>> check_levels(1)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: L must be at least 2 (a binary image has L = 2), got 1
    """
    levels = check_whole(value, "L", param="levels")
    if levels < 2:
        raise InputError(f"L must be at least 2 (a binary image has L = 2), got {levels}", "levels")
    if levels > MAX_LEVELS:
        raise InputError(
            f"L = {levels:,} needs {bits_per_pixel(levels)} bits per pixel; at most {MAX_BITS} "
            f"bits (L <= {MAX_LEVELS:,})",
            "levels",
        )
    return levels


def check_bits(value: Number) -> int:
    """Bits per pixel as an ``int`` in ``1 .. 24``.

    >>> check_bits(25)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: bits per pixel must be at most 24, got 25
    """
    bits = check_whole(value, "bits per pixel", param="bits")
    return check_count(bits, "bits per pixel", 1, MAX_BITS, param="bits")


FRAME_BUFFER_BITS = (32, 48, 64)
"""Pixel depths of frame buffers that :func:`check_storage_bits` accepts beyond :data:`MAX_BITS`
(RGBA 8 bits each, 16-bit RGB, 16-bit RGBA): storage exercises only, no level table."""


def check_storage_bits(value: Number) -> int:
    """Bits per pixel of a stored image: ``1 .. 24``, or a frame-buffer depth 32, 48 or 64.

    >>> check_storage_bits(32), check_storage_bits(64)
    (32, 64)
    >>> check_storage_bits(25)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: bits per pixel must be at most 24, or a frame-buffer depth of 32, 48 or 64, got 25
    """
    bits = check_whole(value, "bits per pixel", param="bits")
    if bits in FRAME_BUFFER_BITS:
        return bits
    if bits > MAX_BITS:
        raise InputError(
            f"bits per pixel must be at most {MAX_BITS}, or a frame-buffer depth of "
            f"{', '.join(map(str, FRAME_BUFFER_BITS[:-1]))} or {FRAME_BUFFER_BITS[-1]}, "
            f"got {bits}",
            "bits",
        )
    return check_count(bits, "bits per pixel", 1, MAX_BITS, param="bits")


def check_cells(m: int, n: int) -> None:
    """Refuse an M × N matrix beyond :data:`MAX_CELLS`, before anything is allocated.

    >>> check_cells(8192, 8192)
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: 8192 x 8192 = 67,108,864 cells is too large (at most 4096 x 4096 = 16,777,216 cells)
    """
    if m * n > MAX_CELLS:
        raise InputError(
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
    scanconv.core.checks.InputError: M (rows) must be a positive integer, got 0
    """
    parts = text.strip().lower().replace("×", "x").split("x")
    if len(parts) > 2 or not all(p.strip().isdecimal() and len(p.strip()) <= 12 for p in parts):
        raise InputError(
            f"size must be M x N in positive integers, like 8x8 or 8 (got {text!r})", "size"
        )
    m = check_positive(int(parts[0]), "M (rows)", param="size")
    n = check_positive(int(parts[-1]), "N (columns)", param="size")
    return m, n
