"""The visible-surface tests' independent oracle: which triangle is nearest at each pixel,
worked per pixel by brute force (the half-open inside rule and the plane's depth written out
here, never the product's arithmetic), shared by the z-buffer, scan-line, Warnock and depth-sort
tests."""

from __future__ import annotations

from fractions import Fraction

Triangle = tuple[tuple[int, int, int], ...]


def inside(poly: list[tuple[Fraction, Fraction]], x: int, y: int) -> bool:
    """The half-open rule written out: edges with one end at or below y and the other above,
    crossing at x_e <= x, counted; odd is inside."""
    count = 0
    for (xa, ya), (xb, yb) in zip(poly, poly[1:] + poly[:1], strict=True):
        if (ya <= y) != (yb <= y):
            xe = xa + (y - ya) * (xb - xa) / (yb - ya)
            count += xe <= x
    return count % 2 == 1


def depth(tri: list[tuple[int, int, int]], x: int, y: int) -> Fraction:
    """z on the plane through the triangle, by Cramer's rule on barycentric weights."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = tri
    det = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1)
    s = Fraction((x - x1) * (y3 - y1) - (x3 - x1) * (y - y1), det)
    t = Fraction((x2 - x1) * (y - y1) - (x - x1) * (y2 - y1), det)
    return z1 + s * (z2 - z1) + t * (z3 - z1)


def as_words(triangles: list[Triangle]) -> tuple[list[Triangle], list[object]]:
    """The triangles that are not degenerate (zero area in x, y: seen edge-on, refused), and
    their vertices as the API takes them (``":"`` before each)."""
    kept = [
        t
        for t in triangles
        if (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) != (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])
    ]
    flat: list[object] = []
    for t in kept:
        flat += [":", *[c for p in t for c in p]]
    return kept, flat


def covering(triangles: list[Triangle], x: int, y: int) -> list[tuple[int, Fraction]]:
    """Each triangle covering the pixel ``(x, y)``, with its depth there, in the given order."""
    return [
        (i, depth(list(t), x, y))
        for i, t in enumerate(triangles)
        if inside([(Fraction(p[0]), Fraction(p[1])) for p in t], x, y)
    ]


def nearest(
    triangles: list[Triangle], width: int, height: int, nearer: str, ties: str
) -> dict[tuple[int, int], tuple[int, Fraction]]:
    """Each covered pixel's nearest triangle and its depth: ``nearer`` says which z is nearer
    (``larger-nearer`` or ``smaller-nearer``), ``ties`` whether an equal depth keeps the first
    (``keep``) or takes the later (``replace``)."""
    out = {}
    for y in range(height):
        for x in range(width):
            best: tuple[int, Fraction] | None = None
            for i, z in covering(triangles, x, y):
                closer = best is None or (z > best[1] if nearer == "larger-nearer" else z < best[1])
                if closer or (best is not None and z == best[1] and ties == "replace"):
                    best = (i, z)
            if best is not None:
                out[(x, y)] = best
    return out


def frame_rows(data: dict[str, object], width: int, height: int) -> list[str]:
    """An answer's ``data["frame"]`` as text rows, top row first (``.``: background)."""
    frame = data["frame"]
    assert isinstance(frame, dict)
    return [
        "".join(frame.get(f"{x},{y}", ".") for x in range(width)) for y in range(height - 1, -1, -1)
    ]
