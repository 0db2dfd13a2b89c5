"""Practice questions on visible-surface detection (``scanconv 3d``): back faces of a named
solid seen from a point, and two triangles through the z-buffer, the scan-line method, depth
sort and Warnock's subdivision, each worded with its method's name."""

from __future__ import annotations

import random

from ..answers.methods import method
from .records import PracticeQuestion

_EYES = ((0, 0, 5), (5, 1, 1), (3, 4, 6), (-4, 1, 2), (1, 6, -3))
_SOLIDS = ("cube", "pyramid", "tetrahedron")
_SIDE = {"easy": 5, "exam": 6, "hard": 8}


def _triangle(rng: random.Random, side: int, z: tuple[int, int]) -> tuple[int, ...]:
    """A triangle in the grid whose projection has an area, with depths in ``z``."""
    while True:
        pts = [(rng.randrange(side), rng.randrange(side)) for _ in range(3)]
        (x1, y1), (x2, y2), (x3, y3) = pts
        if (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1) != 0:
            return tuple(c for x, y in pts for c in (x, y, rng.randint(*z)))


_GRID_KINDS = (
    (
        "zbuffer",
        "give the depth at each pixel, the comparisons and the final frame and depth buffers",
        False,
    ),
    ("scanline", "give each scan line's active edges, the flags and the depth comparisons", False),
    ("depth-sort", "give the tests of each pair in order and the painting order", False),
    ("warnock", "give each window's classification and the final pixels", True),
)
"""The grid methods: what a question asks, and whether the grid is 2^n square (Warnock's)."""


def visible(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """``kind``: ``backface`` or a method of :data:`_GRID_KINDS`."""
    title = method("3d", kind).title
    grid = {k: (ask, square) for k, ask, square in _GRID_KINDS}
    if kind not in grid:  # back faces of a named solid
        solid, eye = rng.choice(_SOLIDS), rng.choice(_EYES)
        argv: tuple[str, ...] = ("3d", kind, "--solid", solid, "--eye", *map(str, eye))
        wording = (
            f"For the {solid} of scanconv's named solids seen from the eye at {eye}, find each "
            f"face's normal and decide by {title} which faces are visible."
        )
        return PracticeQuestion("visible", argv, wording, 5, frozenset({kind}))
    ask, square = grid[kind]
    side = 8 if square else _SIDE[difficulty]
    a, b = _triangle(rng, side, (0, 3)), _triangle(rng, side, (1, 5))
    argv = ("3d", kind, *map(str, a), ":", *map(str, b), "--size", str(side))
    wording = (
        f"Triangles A {_points(a)} and B {_points(b)} (x, y, z; larger z nearer) are drawn on a "
        f"{side} x {side} grid by the {title}: {ask}."
    )
    return PracticeQuestion("visible", argv, wording, 6, frozenset({kind}))


def _points(flat: tuple[int, ...]) -> str:
    return ", ".join(f"({flat[i]}, {flat[i + 1]}, {flat[i + 2]})" for i in range(0, len(flat), 3))
