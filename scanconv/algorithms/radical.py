"""Exact numbers with square roots: ``a + b√2 + c√3 + d√6`` with rational a, b, c, d (and any
other square-free root where a 3D axis or an axonometric angle needs one: ``√5``).

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


def squarefree(n: int) -> tuple[int, int]:
    """``(k, s)`` with ``n = k²·s`` and ``s`` square-free (``n >= 0``; trial division, so a
    caller bounds ``n``: :data:`MAX_ROOT`).

    >>> squarefree(12), squarefree(50), squarefree(0), squarefree(7)
    ((2, 3), (5, 2), (0, 1), (1, 7))
    """
    if n == 0:
        return 0, 1
    k, s, p = 1, 1, 2
    while p * p <= n:
        while n % (p * p) == 0:
            n //= p * p
            k *= p
        if n % p == 0:
            n //= p
            s *= p
        p += 1 if p == 2 else 2
    return k, s * n


def _primes(n: int) -> list[int]:
    out, p = [], 2
    while p * p <= n:
        if n % p == 0:
            out.append(p)
            n //= p
        p += 1 if p == 2 else 2
    return [*out, n] if n > 1 else out


def root_primes(value: Scalar) -> set[int]:
    """The primes under the square roots of ``value``: ``k`` of them make products of such
    values sums of up to ``2**k`` roots.

    >>> sorted(root_primes(Radical(1, 1, 0, 1))), root_primes(Fraction(1, 2))
    ([2, 3], set())
    """
    if not isinstance(value, Radical):
        return set()
    return {p for r, _ in value.terms for p in _primes(r)}


MAX_ROOT = 10**12
"""The largest number whose square root is taken exactly (:meth:`Radical.sqrt`): its
square-free part is found by trial division."""


class Radical:
    """``a + b√2 + c√3 + d√6``, exactly; any other square-free root by ``roots`` (``√5``:
    ``Radical(roots={5: 1})``, the direction cosines of an axis such as (1, 2, 0)).

    >>> r2 = Radical(0, 1)
    >>> simplify(r2 * r2), simplify(r2 / 2 * r2), Radical(0, 1) * Radical(0, 0, 1)
    (2, 1, Radical(0, 0, 0, 1))
    >>> x = Radical(1, 1, 1, 1)
    >>> simplify(x * (1 / x))
    1
    >>> r5 = Radical.sqrt(Fraction(1, 5))
    >>> r5, simplify(r5 * r5), simplify((1 + r5) * (1 / (1 + r5)))
    (Radical(roots={5: 1/5}), Fraction(1, 5), 1)
    """

    __slots__ = ("terms",)

    def __init__(
        self,
        a: Number = 0,
        b: Number = 0,
        c: Number = 0,
        d: Number = 0,
        *,
        roots: dict[int, Number] | None = None,
    ) -> None:
        t: dict[int, Fraction] = {}
        for root, v in (*zip(ROOTS, (a, b, c, d), strict=True), *(roots or {}).items()):
            if v:
                t[root] = t.get(root, Fraction(0)) + Fraction(v)
        self.terms = tuple(sorted((r, v) for r, v in t.items() if v))

    @classmethod
    def of(cls, value: Scalar) -> Radical:
        """``value`` as a :class:`Radical`."""
        return value if isinstance(value, Radical) else cls(value)

    @classmethod
    def sqrt(cls, value: Number) -> Scalar:
        """``√value`` of a rational ``value >= 0`` exactly: ``√(p/q) = k√s / q`` with
        ``p·q = k²·s`` (``ValueError`` past :data:`MAX_ROOT`).

        >>> Radical.sqrt(Fraction(9, 4)), Radical.sqrt(8), Radical.sqrt(Fraction(2, 3))
        (Fraction(3, 2), Radical(0, 2, 0, 0), Radical(0, 0, 0, 1/3))
        """
        q = Fraction(value)
        if q < 0:
            raise ValueError("square root of a negative number")
        n = q.numerator * q.denominator
        if n > MAX_ROOT:
            raise ValueError(f"square root of a number past {MAX_ROOT} (exact roots)")
        k, s = squarefree(n)
        return simplify(cls(roots={s: Fraction(k, q.denominator)}))

    @property
    def coef(self) -> tuple[Fraction, Fraction, Fraction, Fraction]:
        """The coefficients of 1, √2, √3 and √6 (other roots left out: :attr:`terms`)."""
        t = dict(self.terms)
        return (
            t.get(1, Fraction(0)),
            t.get(2, Fraction(0)),
            t.get(3, Fraction(0)),
            t.get(6, Fraction(0)),
        )

    def __repr__(self) -> str:
        if all(r in ROOTS for r, _ in self.terms):
            return "Radical(" + ", ".join(str(normalize(c)) for c in self.coef) + ")"
        return "Radical(roots={" + ", ".join(f"{r}: {c}" for r, c in self.terms) + "})"

    def __add__(self, other: Scalar) -> Radical:
        return _sum(self, Radical.of(other))

    __radd__ = __add__

    def __neg__(self) -> Radical:
        return Radical(roots={r: -v for r, v in self.terms})

    def __sub__(self, other: Scalar) -> Radical:
        return self + (-Radical.of(other))

    def __rsub__(self, other: Scalar) -> Radical:
        return Radical.of(other) - self

    def __mul__(self, other: Scalar) -> Radical:
        out: dict[int, Fraction] = {}
        for r, x in self.terms:
            for s, y in Radical.of(other).terms:
                g = math.gcd(r, s)
                k = (r // g) * (s // g)
                out[k] = out.get(k, Fraction(0)) + g * x * y
        return Radical(roots=out)  # type: ignore[arg-type]

    __rmul__ = __mul__

    def inverse(self) -> Radical:
        """``1 / self``: one conjugation per prime of the roots (√p to -√p) makes the
        denominator rational."""
        num, den = Radical(1), self
        primes = sorted({p for r, _ in self.terms for p in _primes(r)})
        for p in primes:
            conj = Radical(roots={r: (-v if r % p == 0 else v) for r, v in den.terms})
            num, den = num * conj, den * conj
        if not den.terms:
            raise ZeroDivisionError("division by zero")
        return num * Radical(1 / den.coef[0])

    def __truediv__(self, other: Scalar) -> Radical:
        return self * Radical.of(other).inverse()

    def __rtruediv__(self, other: Scalar) -> Radical:
        return Radical.of(other) * self.inverse()

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (int, Fraction, Radical)):
            return self.terms == Radical.of(other).terms
        return NotImplemented

    def __hash__(self) -> int:
        value = simplify(self)
        return hash(value) if not isinstance(value, Radical) else hash(self.terms)

    def __float__(self) -> float:
        return float(approx(self, 64))

    @property
    def rational(self) -> bool:
        """True if the roots cancel."""
        return all(r == 1 for r, _ in self.terms)


def _sum(x: Radical, y: Radical) -> Radical:
    out = dict(x.terms)
    for r, v in y.terms:
        out[r] = out.get(r, Fraction(0)) + v
    return Radical(roots=out)  # type: ignore[arg-type]


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
    for root, c in value.terms:
        if root == 1:
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
