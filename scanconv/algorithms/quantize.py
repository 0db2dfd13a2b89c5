"""Uniform quantization: input values onto L levels, each level's cell and reconstruction
value (:class:`Quantizer`), and the smallest integer type that holds the levels."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

from ..core.checks import InputError
from ..core.numeric import Number, fmt_short, normalize
from .image_limits import check_levels

if TYPE_CHECKING:  # numpy is imported where arrays are made: storage and quantize start faster
    import numpy as np

RECON_OFFSETS = (("midpoint", Fraction(1, 2)), ("lower", Fraction(0)))
"""Each reconstruction convention of :class:`Quantizer` and where in its level's cell it
reconstructs: ``lo + (k + offset) Δ``."""

RECON = tuple(name for name, _ in RECON_OFFSETS)
"""Reconstruction conventions of :class:`Quantizer`."""

INPUTS = ("integer", "real")
"""What an input range holds: the integers ``lo .. hi``, or any real value in ``[lo, hi]``."""


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

    @property
    def offset(self) -> Fraction:
        """Where in its cell a level reconstructs: 1/2 (the midpoint) or 0 (the lower end).

        >>> Quantizer.make(0, 255, 4).offset, Quantizer.make(0, 255, 4, recon="lower").offset
        (Fraction(1, 2), Fraction(0, 1))
        """
        return next(offset for name, offset in RECON_OFFSETS if name == self.recon)

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
        """A checked quantizer: ``lo < hi``, integer bounds for integer inputs, L >= 2.

        >>> Quantizer.make(0, 3, 8)
        Traceback (most recent call last):
        ...
        scanconv.core.checks.InputError: the integers 0 .. 3 are only 4 input values, fewer than L = 8 levels (real inputs take a continuous range)
        """
        L = check_levels(levels)
        if recon not in RECON:
            raise InputError(
                f"unknown reconstruction {recon!r} (choose from {', '.join(RECON)})", "recon"
            )
        flo, fhi = normalize(Fraction(lo)), normalize(Fraction(hi))
        if not flo < fhi:
            raise InputError(
                f"the input range must have LO < HI, got {fmt_short(flo)} and {fmt_short(fhi)}",
                "value_range",
            )
        if integer:
            if not (isinstance(flo, int) and isinstance(fhi, int)):
                raise InputError(
                    f"integer inputs need integer LO and HI, got {fmt_short(flo)} and "
                    f"{fmt_short(fhi)} (real inputs take a continuous range)",
                    "value_range",
                )
            if fhi - flo + 1 < L:
                raise InputError(
                    f"the integers {flo} .. {fhi} are only {fhi - flo + 1} input values, "
                    f"fewer than L = {L} levels (real inputs take a continuous range)",
                    "value_range",
                )
        return cls(flo, fhi, L, integer, recon)

    @property
    def width(self) -> Number:
        """``hi - lo + 1`` for integer inputs, ``hi - lo`` for real ones.

        >>> Quantizer.make(0, 255, 4).width, Quantizer.make(0, 255, 4, integer=False).width
        (256, 255)
        """
        return self.hi - self.lo + (1 if self.integer else 0)

    @property
    def step(self) -> Number:
        """``Δ = W / L``, the width of one level's cell.

        >>> Quantizer.make(0, 255, 8).step, Quantizer.make(0, 1, 8, integer=False).step
        (32, Fraction(1, 8))
        """
        return normalize(Fraction(self.width) / self.levels)

    def level(self, v: Number | float) -> int:
        """The level of input ``v``, exactly: ``⌊(v - lo) L / W⌋`` clamped to ``0 .. L - 1``.

        >>> Quantizer.make(0, 1, 4, integer=False).level(Fraction(1, 2))
        2
        """
        k = math.floor((Fraction(v) - self.lo) * self.levels / self.width)
        return min(max(k, 0), self.levels - 1)

    def levels_of(self, values: np.ndarray) -> np.ndarray:
        """:meth:`level` of every value of a float array, in float64 (monotonic, clamped).

        >>> import numpy as np
        >>> Quantizer.make(0, 1, 4, integer=False).levels_of(np.array([-1.0, 0.3, 1.0])).tolist()
        [0, 1, 3]
        """
        import numpy as np

        lo, width = float(self.lo), float(self.width)
        k = np.floor((values - lo) * self.levels / width)
        return np.clip(k, 0, self.levels - 1).astype(level_dtype(self.levels))

    def interval(self, k: int) -> tuple[Number, Number]:
        """The inputs of level ``k``: first and last integer, or the cell ``[from, to)``.

        >>> Quantizer.make(0, 255, 8).interval(1), Quantizer.make(0, 1, 8, integer=False).interval(1)
        ((32, 63), (Fraction(1, 8), Fraction(1, 4)))
        """
        if self.integer:
            W, L = int(self.width), self.levels
            first = int(self.lo) + -(-k * W // L)
            last = int(self.lo) + -(-(k + 1) * W // L) - 1
            return first, last
        return (
            normalize(self.lo + k * Fraction(self.step)),
            normalize(self.lo + (k + 1) * Fraction(self.step)),
        )

    def cells(self) -> Iterator[tuple[Number, Number, Number]]:
        """``(*interval(k), reconstruction(k))`` of every level ``k = 0 .. L - 1``, in order.

        The same exact values as :meth:`interval` and :meth:`reconstruction`, computed with
        integers over one common denominator (a table of 2^24 levels builds no fraction for
        an integral value).

        >>> list(Quantizer.make(0, 255, 4).cells())
        [(0, 63, 32), (64, 127, 96), (128, 191, 160), (192, 255, 224)]
        >>> list(Quantizer.make(0, 1, 2, integer=False).cells())
        [(0, Fraction(1, 2), Fraction(1, 4)), (Fraction(1, 2), 1, Fraction(3, 4))]
        """
        L = self.levels
        lo, width = Fraction(self.lo), Fraction(self.width)
        # every value is lo + m·W/(2L) for an integer m: over D = 2L·den(lo)·den(W) it is an
        # integer numerator P + m·S
        D = 2 * L * lo.denominator * width.denominator
        P = lo.numerator * (D // lo.denominator)
        S = width.numerator * (D // width.denominator) // (2 * L)
        half = int(2 * self.offset)

        def exact(n: int) -> Number:
            q, r = divmod(n, D)
            return q if r == 0 else Fraction(n, D)

        if self.integer:
            first, W = int(self.lo), int(self.width)
            for k in range(L):
                last = int(self.lo) + -(-(k + 1) * W // L) - 1
                yield first, last, exact(P + (2 * k + half) * S)
                first = last + 1
        else:
            start = exact(P)
            for k in range(L):
                end = exact(P + 2 * (k + 1) * S)
                yield start, end, exact(P + (2 * k + half) * S)
                start = end

    def reconstruction(self, k: int) -> Number:
        """The value level ``k`` stands for (the midpoint or lower end of its cell).

        >>> Quantizer.make(0, 255, 4, recon="lower").reconstruction(1)
        64
        """
        return normalize(self.lo + (k + self.offset) * Fraction(self.step))
