"""The storage of an image: ``M × N × k`` bits with ``k = ⌈log2 L⌉`` bits per pixel, and the
same size in bytes, KB/MB (1000) and KiB/MiB (1024). Exact integer arithmetic only."""

from __future__ import annotations

from fractions import Fraction

from ..core.numeric import Number

UNITS: tuple[tuple[str, int], ...] = (
    ("KB", 1000),
    ("MB", 1000**2),
    ("KiB", 1024),
    ("MiB", 1024**2),
)
"""The size units and their bytes: decimal (1000, 1000²) and binary (1024, 1024²)."""


def bits_per_pixel(levels: int) -> int:
    """``⌈log2 L⌉``, computed exactly: the bits a pixel of L levels needs.

    >>> bits_per_pixel(256), bits_per_pixel(100), bits_per_pixel(2)
    (8, 7, 1)
    """
    return (levels - 1).bit_length()


def storage_bits(m: int, n: int, bits: int, frames: int = 1) -> int:
    """``M × N × k × F`` bits.

    >>> storage_bits(1024, 768, 8)
    6291456
    """
    return m * n * bits * frames


def sizes(bits: int) -> dict[str, Number]:
    """A size of ``bits`` bits in bits, bytes and each of :data:`UNITS`, exactly.

    >>> {unit: str(v) for unit, v in sizes(6291456).items()}
    {'bits': '6291456', 'bytes': '786432', 'KB': '98304/125', 'MB': '12288/15625', 'KiB': '768', 'MiB': '3/4'}
    """
    nbytes = Fraction(bits, 8)
    return {"bits": bits, "bytes": nbytes, **{u: nbytes / d for u, d in UNITS}}
