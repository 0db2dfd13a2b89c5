"""Hearn & Baker's supersampling of a line: Bresenham's algorithm on an n x n sub-pixel grid,
and each pixel's intensity from the number of its sub-pixels on the path.

Sub-pixel ``(U, V)`` lies in pixel ``(U // n, V // n)`` (sub-columns ``n x .. n x + n - 1`` of
pixel column x, left to right). With the end points' pixels P1 and P2, the major axis x
(|Δy| <= |Δx|; y otherwise, by swapping the roles) and P1 the left end:

* ``subgrid="span"`` (the default; the published form of Hearn & Baker's figure as taught,
  e.g. a line (0, 0) to (2, 1) drawn on the micro grid from (0, 0) to (8, 4)): the sub-pixel
  line starts at P1's first sub-pixel ``(n x1, n y1)`` and runs over every sub-column of the
  pixels from x1 to x2, ``ΔU = n Δx + n - 1``, with the line's slope, ``ΔV = m ΔU`` (exact;
  a fraction where m ΔU is not whole);
* ``subgrid="centre"`` (n odd): from the sub-pixel at P1's pixel centre to the one at P2's,
  ``(n x + (n - 1)/2, n y + (n - 1)/2)``: the same geometric line, ``ΔU = n Δx``.

The walk is Bresenham's, exact: ``p0 = 2ΔV - ΔU``; ``p < 0`` keeps V (``p += 2ΔV``), else V
steps toward the far end (``p += 2ΔV - 2ΔU``). Each pixel's count c of path sub-pixels gives
its intensity ``c / n`` (at most n sub-pixels per pixel column on an x-major path: n
intensity levels above zero, Hearn & Baker's "three intensity settings above zero").

References
----------
Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., section 4-8, "Supersampling straight
line segments" and Fig. 4-38 (nine sub-pixels per pixel, Bresenham on the sub-pixel grid).
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import Number, normalize
from ..core.records import Pixel

SUBGRIDS = {
    "span": "the sub-pixel line from P1's first sub-pixel (n x1, n y1) over every sub-column "
    "of the end pixels, dU = n dx + n - 1, with the line's slope (the taught form)",
    "centre": "the sub-pixel line between the sub-pixels at the end pixels' centres, "
    "(n x + (n - 1)/2, n y + (n - 1)/2): the same line (n odd)",
}
"""Where the sub-pixel line starts and ends (the ``subgrid`` convention), the default first."""


class SubLine(NamedTuple):
    """The sub-pixel line: its start, ``ΔU`` (whole), ``ΔV`` (exact, signed), the roles."""

    steep: bool
    u0: int
    v0: int
    du: int
    dv: Number


def sub_line(x1: int, y1: int, x2: int, y2: int, n: int, subgrid: str = "span") -> SubLine:
    """The sub-pixel line of the pixels P1, P2 on an ``n x n`` grid.

    >>> sub_line(0, 0, 2, 1, 3)
    SubLine(steep=False, u0=0, v0=0, du=8, dv=4)
    >>> sub_line(0, 0, 2, 1, 3, "centre")
    SubLine(steep=False, u0=1, v0=1, du=6, dv=3)
    """
    if subgrid not in SUBGRIDS:
        raise InputError(
            f"unknown subgrid {subgrid!r} (choose from {', '.join(SUBGRIDS)})", "subgrid"
        )
    steep = abs(y2 - y1) > abs(x2 - x1)
    a1, b1, a2, b2 = (y1, x1, y2, x2) if steep else (x1, y1, x2, y2)
    if a2 < a1:
        a1, b1, a2, b2 = a2, b2, a1, b1
    da, db = a2 - a1, b2 - b1
    if subgrid == "centre":
        if n % 2 == 0:
            raise InputError(
                f"subgrid centre needs an odd n (no centre sub-pixel), got {n}", "samples"
            )
        c = (n - 1) // 2
        return SubLine(steep, n * a1 + c, n * b1 + c, n * da, n * db)
    du = n * da + n - 1
    dv = normalize(Fraction(db, da) * du) if da else 0
    return SubLine(steep, n * a1, n * b1, du, dv)


def walk(line: SubLine) -> Iterator[tuple[int, Number, int, int]]:
    """Bresenham on the sub-pixel line: ``(k, p_k, U_k, V_k)``, ``p_k`` the decision taken at
    ``(U_k, V_k)`` (``None``-free: the last row's p is the one after the last step).

    >>> [(k, p, u, v) for k, p, u, v in walk(sub_line(0, 0, 2, 1, 3))][:4]
    [(0, 0, 0, 0), (1, -8, 1, 1), (2, 0, 2, 1), (3, -8, 3, 2)]
    """
    s = 1 if line.dv >= 0 else -1
    dv = abs(Fraction(line.dv))
    p: Number = normalize(2 * dv - line.du)
    v = line.v0
    for k in range(line.du + 1):
        yield k, p, line.u0 + k, v
        if p < 0:
            p = normalize(p + 2 * dv)
        else:
            v += s
            p = normalize(p + 2 * dv - 2 * line.du)


def pixel_of(line: SubLine, u: int, v: int, n: int) -> Pixel:
    """The pixel (x, y) holding sub-pixel (U, V) of the walk (roles swapped back if steep).

    >>> pixel_of(sub_line(0, 0, 2, 1, 3), 5, 3, 3)
    (1, 1)
    """
    a, b = u // n, v // n
    return (b, a) if line.steep else (a, b)


def counts(line: SubLine, n: int) -> dict[Pixel, int]:
    """Each pixel's number of path sub-pixels, in walk order.

    >>> counts(sub_line(0, 0, 2, 1, 3), 3)
    {(0, 0): 3, (1, 0): 2, (1, 1): 1, (2, 1): 3}
    """
    out: dict[Pixel, int] = {}
    for _, _, u, v in walk(line):
        p = pixel_of(line, u, v, n)
        out[p] = out.get(p, 0) + 1
    return out
