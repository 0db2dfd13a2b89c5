"""Plain implementations of the notes' algorithms, written from their definitions (not from
scanconv's code): the independent side of the tests that compare scanconv's pixels, tables
and clipped ends with them (the fuzz with oracles, thick lines, the symmetry tables)."""

from __future__ import annotations

import math
from fractions import Fraction as F


def sign(v):
    return (v > 0) - (v < 0)


def bresenham_ref(x1, y1, x2, y2, tie="step", start="swap"):
    steep = abs(y2 - y1) > abs(x2 - x1)
    if steep:
        a, b = (y1, x1), (y2, x2)
    else:
        a, b = (x1, y1), (x2, y2)
    if start == "swap" and a[0] > b[0]:
        a, b = b, a
    dM, dm = abs(b[0] - a[0]), abs(b[1] - a[1])
    sM, sm = sign(b[0] - a[0]) or 1, sign(b[1] - a[1]) or 1
    M, m = a
    p = 2 * dm - dM
    out = []
    for _ in range(dM + 1):
        out.append((m, M) if steep else (M, m))
        if p < 0 or (tie == "keep" and p == 0):
            p += 2 * dm
        else:
            m += sm
            p += 2 * dm - 2 * dM
        M += sM
    return out


RULES = {
    "half-up": lambda v: math.floor(v + F(1, 2)),
    "trunc": lambda v: int(v),
    "half-even": lambda v: round(v),
    "c-cast": lambda v: int(v + F(1, 2)),
    "half-away": lambda v: sign(v) * math.floor(abs(v) + F(1, 2)),
}


def dda_ref(x1, y1, x2, y2, rounding="half-up", start="given"):
    steep = abs(y2 - y1) > abs(x2 - x1)
    if start == "swap" and ((y1 > y2) if steep else (x1 > x2)):
        x1, y1, x2, y2 = x2, y2, x1, y1
    steps = max(abs(x2 - x1), abs(y2 - y1))
    r = RULES[rounding]
    if steps == 0:
        return [(r(F(x1)), r(F(y1)))]
    xi, yi = F(x2 - x1, steps), F(y2 - y1, steps)
    return [(r(x1 + k * xi), r(y1 + k * yi)) for k in range(steps + 1)]


def midpoint_circle_ref(r, tie="step", loop="strict"):
    """The octant from (0, r): p0 = 1 - r; E when p < 0 (or p <= 0 with tie keep), else SE;
    p += 2x + 1 (E) or 2x + 1 - 2y (SE) with the new x and y; the loop runs while x < y
    (strict) or x <= y (inclusive) before each step."""
    x, y, p = 0, r, 1 - r
    out = [(x, y)]
    while (x < y) if loop == "strict" else (x <= y):
        x += 1
        if p < 0 or (tie == "keep" and p == 0):
            p += 2 * x + 1
        else:
            y -= 1
            p += 2 * x + 1 - 2 * y
        out.append((x, y))
    return out


def liang_barsky_ref(x1, y1, x2, y2, xmin, ymin, xmax, ymax):
    """The exact clipped segment ((x, y), (x, y)) as Fractions, or None (outside)."""
    dx, dy = F(x2 - x1), F(y2 - y1)
    t0, t1 = F(0), F(1)
    for p, q in ((-dx, x1 - xmin), (dx, xmax - x1), (-dy, y1 - ymin), (dy, ymax - y1)):
        if p == 0:
            if q < 0:
                return None
            continue
        t = F(q) / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    if t0 > t1:
        return None
    return ((x1 + t0 * dx, y1 + t0 * dy), (x1 + t1 * dx, y1 + t1 * dy))
