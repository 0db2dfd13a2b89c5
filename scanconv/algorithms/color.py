"""Colour-model conversions: RGB, CMY, HSV, HSI and a grey level, as exact numbers.

Every component here is on the unit scale (RGB, CMY, saturation, value and intensity in
``[0, 1]``, hue in degrees in ``[0, 360)``); the answer layer scales 8-bit (or ``--bits``)
input to it. Values are :class:`~fractions.Fraction` wherever the model is rational (CMY,
HSV, the grey levels, HSI's S and I); HSI's hue needs an arc cosine and is a ``float`` unless
its cosine is one of the few rational cosines of a whole-degree angle (0, 30, 60, 90, ...),
when it is exact. Nothing here formats a number.

The formulas (one source for the working the answer writes):

* CMY: ``C = 1 - R, M = 1 - G, Y = 1 - B`` (and back).
* HSV (Smith 1978): ``V = max``, ``S = (max - min) / max``, ``H = 60 (G - B)/(max - min)``
  (mod 360) if R is the largest, ``120 + 60 (B - R)/Δ`` if G, ``240 + 60 (R - G)/Δ`` if B.
* HSI (Gonzalez & Woods): ``I = (R + G + B)/3``, ``S = 1 - 3 min/(R + G + B)``,
  ``θ = arccos(½[(R - G) + (R - B)] / √((R - G)² + (R - B)(G - B)))``, ``H = θ`` if
  ``B ≤ G`` else ``360 - θ``.
* grey: the plain average ``(R + G + B)/3`` and ITU-R BT.601 luma
  ``0.299 R + 0.587 G + 0.114 B``.

>>> rgb_to_hsv(Fraction(1, 5), Fraction(2, 5), Fraction(3, 5)).h
Fraction(210, 1)
>>> rgb_to_hsi(Fraction(1, 5), Fraction(2, 5), Fraction(3, 5)).h
Fraction(210, 1)
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import NamedTuple

Value = Fraction | float
"""A component: exact where the model is rational, a float where an arc cosine is needed."""

MODELS = ("rgb", "cmy", "hsv", "hsi", "grey")
"""The models, in the order an answer lists them."""

LUMA_601 = (Fraction(299, 1000), Fraction(587, 1000), Fraction(114, 1000))
"""ITU-R BT.601 luma weights of R, G and B (they sum to 1)."""


class HSV(NamedTuple):
    """Hue (degrees), saturation and value, with how the hue was found."""

    h: Fraction
    s: Fraction
    v: Fraction
    largest: str
    """``"R"``, ``"G"`` or ``"B"``: the component that is largest (the hue formula used);
    ``""``: all three are equal, so the hue is undefined (taken as 0)."""


class HSI(NamedTuple):
    """Hue (degrees), saturation and intensity, with the arc cosine's pieces."""

    h: Value
    s: Fraction
    i: Fraction
    numerator: Fraction
    """``½[(R - G) + (R - B)]``."""
    radicand: Fraction
    """``(R - G)² + (R - B)(G - B)`` (the denominator is its square root)."""
    theta: Value | None
    """``θ`` in degrees; ``None`` when R = G = B (the hue is undefined, taken as 0)."""


def rgb_to_cmy(r: Fraction, g: Fraction, b: Fraction) -> tuple[Fraction, Fraction, Fraction]:
    """``(1 - R, 1 - G, 1 - B)``.

    >>> rgb_to_cmy(Fraction(1), Fraction(0), Fraction(1, 4))
    (Fraction(0, 1), Fraction(1, 1), Fraction(3, 4))
    """
    return 1 - r, 1 - g, 1 - b


def cmy_to_rgb(c: Fraction, m: Fraction, y: Fraction) -> tuple[Fraction, Fraction, Fraction]:
    """``(1 - C, 1 - M, 1 - Y)``: CMY is RGB's complement both ways."""
    return 1 - c, 1 - m, 1 - y


def rgb_to_hsv(r: Fraction, g: Fraction, b: Fraction) -> HSV:
    """Smith's hexcone: exact hue in degrees, saturation and value.

    >>> rgb_to_hsv(Fraction(0), Fraction(1, 2), Fraction(0))
    HSV(h=Fraction(120, 1), s=Fraction(1, 1), v=Fraction(1, 2), largest='G')
    """
    hi, lo = max(r, g, b), min(r, g, b)
    delta = hi - lo
    s = delta / hi if hi else Fraction(0)
    if delta == 0:
        return HSV(Fraction(0), s, hi, "")
    if hi == r:
        h, largest = 60 * (g - b) / delta, "R"
    elif hi == g:
        h, largest = 120 + 60 * (b - r) / delta, "G"
    else:
        h, largest = 240 + 60 * (r - g) / delta, "B"
    return HSV(h % 360, s, hi, largest)


def hsv_to_rgb(h: Fraction, s: Fraction, v: Fraction) -> tuple[Fraction, Fraction, Fraction]:
    """Back from the hexcone, exactly: sector ``i = ⌊H/60⌋``, ``f = H/60 - i``.

    >>> hsv_to_rgb(Fraction(210), Fraction(2, 3), Fraction(3, 5))
    (Fraction(1, 5), Fraction(2, 5), Fraction(3, 5))
    """
    h = h % 360
    i = math.floor(h / 60)
    f = h / 60 - i
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    return [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)][i]


#: Angles whose cosine is rational enough to be found exactly from ``cos² θ`` and its sign.
_EXACT_ANGLES = {
    (Fraction(1), 1): 0,
    (Fraction(3, 4), 1): 30,
    (Fraction(1, 4), 1): 60,
    (Fraction(0), 0): 90,
    (Fraction(1, 4), -1): 120,
    (Fraction(3, 4), -1): 150,
    (Fraction(1), -1): 180,
}


def _sign(v: Fraction) -> int:
    return (v > 0) - (v < 0)


def arccos_degrees(numerator: Fraction, radicand: Fraction) -> Value:
    """``arccos(numerator / √radicand)`` in degrees: exact for the angles whose cosine is
    ``0, ±½, ±√3/2, ±1``, else a float.

    >>> arccos_degrees(Fraction(-3, 10), Fraction(3, 25)), round(arccos_degrees(Fraction(1), Fraction(3)), 6)
    (Fraction(150, 1), 54.73561)
    """
    cos_sq = numerator * numerator / radicand
    exact = _EXACT_ANGLES.get((cos_sq, _sign(numerator)))
    if exact is not None:
        return Fraction(exact)
    ratio = float(numerator) / math.sqrt(radicand)
    return math.degrees(math.acos(max(-1.0, min(1.0, ratio))))


def rgb_to_hsi(r: Fraction, g: Fraction, b: Fraction) -> HSI:
    """Gonzalez & Woods' HSI: ``I`` and ``S`` exact, ``H`` from the arc cosine.

    >>> x = rgb_to_hsi(Fraction(0), Fraction(1), Fraction(0))
    >>> x.h, x.s, x.i
    (Fraction(120, 1), Fraction(1, 1), Fraction(1, 3))
    """
    total = r + g + b
    i = total / 3
    s = 1 - 3 * min(r, g, b) / total if total else Fraction(0)
    numerator = ((r - g) + (r - b)) / 2
    radicand = (r - g) ** 2 + (r - b) * (g - b)
    if radicand == 0:  # R = G = B: a grey, no hue
        return HSI(Fraction(0), s, i, numerator, radicand, None)
    theta = arccos_degrees(numerator, radicand)
    h = theta if b <= g else 360 - theta
    return HSI(h, s, i, numerator, radicand, theta)


#: ``cos H / cos(60° - H)`` for the hues (within a 120° sector) where it is rational.
_EXACT_RATIOS = {0: Fraction(2), 30: Fraction(1), 60: Fraction(1, 2), 90: Fraction(0)}


def hsi_sector(h: Value) -> tuple[int, Value]:
    """The 120° sector of a hue (0: RG, 1: GB, 2: BR) and the hue within it.

    >>> hsi_sector(Fraction(210))
    (1, Fraction(90, 1))
    """
    h = h % 360
    sector = min(int(h // 120), 2)
    return sector, h - 120 * sector


def hsi_ratio(h: Value) -> Value:
    """``cos H / cos(60° - H)`` for a hue ``0 <= H < 120``: exact where it is rational."""
    if isinstance(h, Fraction) and h.denominator == 1 and int(h) in _EXACT_RATIOS:
        return _EXACT_RATIOS[int(h)]
    return math.cos(math.radians(h)) / math.cos(math.radians(60 - h))


def hsi_to_rgb(h: Value, s: Fraction, i: Fraction) -> tuple[Value, Value, Value]:
    """Back from HSI: in the hue's sector, the first colour is ``I(1 + S cos H/cos(60 - H))``,
    the next ``3I - (the other two)``, the last ``I(1 - S)``.

    >>> hsi_to_rgb(Fraction(210), Fraction(1, 2), Fraction(2, 5))
    (Fraction(1, 5), Fraction(2, 5), Fraction(3, 5))
    """
    sector, hh = hsi_sector(h)
    low = i * (1 - s)
    first = i * (1 + s * hsi_ratio(hh))
    second = 3 * i - (low + first)
    if sector == 0:  # RG: B is the lowest
        return first, second, low
    if sector == 1:  # GB: R is the lowest
        return low, first, second
    return second, low, first  # BR: G is the lowest


def grey_average(r: Fraction, g: Fraction, b: Fraction) -> Fraction:
    """``(R + G + B) / 3``."""
    return (r + g + b) / 3


def grey_luma(r: Fraction, g: Fraction, b: Fraction) -> Fraction:
    """BT.601 luma ``0.299 R + 0.587 G + 0.114 B``.

    >>> grey_luma(Fraction(1), Fraction(1), Fraction(1))
    Fraction(1, 1)
    """
    wr, wg, wb = LUMA_601
    return wr * r + wg * g + wb * b


def pack(components: tuple[int, int, int], bits: int) -> int:
    """The pixel word ``R << 2b | G << b | B``.

    >>> hex(pack((51, 102, 153), 8))
    '0x336699'
    """
    r, g, b = components
    return (r << (2 * bits)) | (g << bits) | b
