"""Exact numbers with square roots: ``a + b√2 + c√3 + d√6`` with rational a, b, c, d.

These are the values sin and cos take at every multiple of 15 degrees (``cos 45° = √2/2``,
``sin 60° = √3/2``, ``cos 15° = (√6 + √2)/4``), and the set is closed under +, -, x and /,
so a composite of such rotations with rational translations, scalings, shears and
reflections stays exact. A value whose roots cancel is returned as an ``int`` or
:class:`~fractions.Fraction` (:func:`simplify`), so rational answers stay rational.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Union

from ..core.numeric import Number, normalize

ROOTS = (1, 2, 3, 6)
"""The basis: a :class:`Radical` is ``sum(coef[i] * sqrt(ROOTS[i]))``."""

#: (i, j) -> (factor, k): sqrt(ROOTS[i]) * sqrt(ROOTS[j]) = factor * sqrt(ROOTS[k]).
_PRODUCT = {
    (0, 0): (1, 0), (0, 1): (1, 1), (0, 2): (1, 2), (0, 3): (1, 3),
    (1, 1): (2, 0), (1, 2): (1, 3), (1, 3): (2, 2),
    (2, 2): (3, 0), (2, 3): (3, 1),
    (3, 3): (6, 0),
}  # fmt: skip


class Radical:
    """``a + b√2 + c√3 + d√6``, exactly.

    >>> r2 = Radical(0, 1)
    >>> simplify(r2 * r2), simplify(r2 / 2 * r2), Radical(0, 1) * Radical(0, 0, 1)
    (2, 1, Radical(0, 0, 0, 1))
    >>> x = Radical(1, 1, 1, 1)
    >>> simplify(x * (1 / x))
    1
    """

    __slots__ = ("coef",)

    def __init__(self, a: Number = 0, b: Number = 0, c: Number = 0, d: Number = 0) -> None:
        self.coef = (Fraction(a), Fraction(b), Fraction(c), Fraction(d))

    @classmethod
    def of(cls, value: Scalar) -> Radical:
        """``value`` as a :class:`Radical`."""
        return value if isinstance(value, Radical) else cls(value)

    def __repr__(self) -> str:
        return "Radical(" + ", ".join(str(normalize(c)) for c in self.coef) + ")"

    def __add__(self, other: Scalar) -> Radical:
        o = Radical.of(other).coef
        return Radical(*(x + y for x, y in zip(self.coef, o, strict=True)))

    __radd__ = __add__

    def __neg__(self) -> Radical:
        return Radical(*(-x for x in self.coef))

    def __sub__(self, other: Scalar) -> Radical:
        return self + (-Radical.of(other))

    def __rsub__(self, other: Scalar) -> Radical:
        return Radical.of(other) - self

    def __mul__(self, other: Scalar) -> Radical:
        o = Radical.of(other).coef
        out = [Fraction(0)] * 4
        for i, x in enumerate(self.coef):
            if not x:
                continue
            for j, y in enumerate(o):
                if y:
                    f, k = _PRODUCT[(i, j) if i <= j else (j, i)]
                    out[k] += f * x * y
        return Radical(*out)

    __rmul__ = __mul__

    def inverse(self) -> Radical:
        """``1 / self``: two conjugations (√3 then √2) make the denominator rational."""
        a, b, c, d = self.coef
        conj3 = Radical(a, b, -c, -d)  # (p + q√3)(p - q√3) = p² - 3q², p, q in Q(√2)
        e, f, _, _ = (self * conj3).coef
        conj2 = Radical(e, -f)
        den = e * e - 2 * f * f
        if den == 0:
            raise ZeroDivisionError("division by zero")
        return conj3 * conj2 * Radical(1 / den)

    def __truediv__(self, other: Scalar) -> Radical:
        return self * Radical.of(other).inverse()

    def __rtruediv__(self, other: Scalar) -> Radical:
        return Radical.of(other) * self.inverse()

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (int, Fraction, Radical)):
            return self.coef == Radical.of(other).coef
        return NotImplemented

    def __hash__(self) -> int:
        value = simplify(self)
        return hash(value) if not isinstance(value, Radical) else hash(self.coef)

    def __float__(self) -> float:
        return float(approx(self, 64))

    @property
    def rational(self) -> bool:
        """True if the roots cancel."""
        return not any(self.coef[1:])


Scalar = Union[int, Fraction, Radical]  # noqa: UP007 - a runtime alias, used in isinstance-free hints
"""An exact matrix entry or coordinate."""


def simplify(value: Scalar) -> Scalar:
    """A :class:`Radical` without roots as an ``int`` or ``Fraction``; anything else as is.

    >>> simplify(Radical(Fraction(4, 2))), simplify(Radical(1, 1))
    (2, Radical(1, 1, 0, 0))
    """
    if isinstance(value, Radical):
        return normalize(value.coef[0]) if value.rational else value
    return normalize(value)


def _bounds(value: Radical, bits: int) -> tuple[Fraction, Fraction]:
    """Exact lower and upper bounds of ``value`` from square roots to ``bits`` bits."""
    lo = hi = value.coef[0]
    scale = 1 << bits
    for root, c in zip(ROOTS[1:], value.coef[1:], strict=True):
        if not c:
            continue
        s = math.isqrt(root * scale * scale)  # floor(sqrt(root) * 2^bits)
        low, high = Fraction(s, scale), Fraction(s + 1, scale)
        lo, hi = (lo + c * low, hi + c * high) if c > 0 else (lo + c * high, hi + c * low)
    return lo, hi


def approx(value: Scalar, bits: int = 64) -> Fraction:
    """A rational within ``2**-bits`` times the coefficients of ``value``.

    >>> float(approx(Radical(0, 1)))
    1.4142135623730951
    """
    if not isinstance(value, Radical):
        return Fraction(value)
    lo, hi = _bounds(value, bits)
    return (lo + hi) / 2


def floor_exact(value: Scalar) -> int:
    """``floor(value)`` exactly: bounds are refined until they agree (an irrational value is
    never an integer, so they always do).

    >>> floor_exact(Radical(0, 1)), floor_exact(Radical(0, -1)), floor_exact(Fraction(7, 2))
    (1, -2, 3)
    """
    value = simplify(value)
    if not isinstance(value, Radical):
        return math.floor(value)
    bits = 64
    while True:
        lo, hi = _bounds(value, bits)
        if math.floor(lo) == math.floor(hi):
            return math.floor(lo)
        bits *= 2


def round_half_up_exact(value: Scalar) -> int:
    """``floor(value + 1/2)``, the project's one rounding rule, for radicals too.

    >>> round_half_up_exact(Radical(0, Fraction(3, 2))), round_half_up_exact(Fraction(5, 2))
    (2, 3)
    """
    return floor_exact(value + Fraction(1, 2))


def sign(value: Scalar) -> int:
    """-1, 0 or 1.

    >>> sign(Radical(1, -1)), sign(Radical(0)), sign(Fraction(1, 3))
    (-1, 0, 1)
    """
    value = simplify(value)
    if not isinstance(value, Radical):
        return (value > 0) - (value < 0)
    bits = 64
    while True:
        lo, hi = _bounds(value, bits)
        if lo > 0:
            return 1
        if hi < 0:
            return -1
        bits *= 2
