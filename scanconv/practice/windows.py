"""Practice questions on clipping against a window of any shape and on a font's bytes
(:mod:`.beyond` routes its ``clip`` and ``characters`` kinds here): Sutherland-Hodgman against
a triangle or a hexagon, Weiler-Atherton where the polygons only touch (a vertex on the other's
edge, or an edge along the other's), midpoint subdivision stopping where a midpoint lands on
the window's edge, a glyph packed into bytes row by row, and a font table's address of one
glyph.

Every question is built so that it has an answer worth asking: the window is convex and
counter-clockwise, the subject polygon holds a point inside the window and a vertex outside
it (so something is clipped and something is left), and a touching case touches by
construction (the touching vertex or the shared edge is placed on the window's edge).
"""

from __future__ import annotations

import random

from ..answers.methods import method
from .records import PracticeQuestion

__all__ = [
    "edge_stop",
    "font_table",
    "glyph_bytes",
    "hexagon_window",
    "touching",
    "triangle_window",
]

_SCALE = {"easy": 1, "exam": 2, "hard": 3}
"""How much larger an exam or a hard question's coordinates are."""


def _pairs(flat: tuple[int, ...]) -> str:
    return ", ".join(f"({flat[i]}, {flat[i + 1]})" for i in range(0, len(flat), 2))


def _origin(rng: random.Random, difficulty: str) -> tuple[int, int]:
    """Where the window sits: small non-negative coordinates, negative ones when hard."""
    lo, hi = (-10, 0) if difficulty == "hard" else (0, 6)
    return rng.randrange(lo, hi + 1), rng.randrange(lo, hi + 1)


def _sutherland_hodgman(
    kind: str, shape: str, poly: tuple[int, ...], window: tuple[int, ...]
) -> PracticeQuestion:
    title = method("clip", "sutherland-hodgman").title
    argv = ("clip", "polygon", *map(str, poly), "--window-vertices", *map(str, window))
    return PracticeQuestion(
        "clip",
        (*argv, "--method", "sutherland-hodgman"),
        f"Clip the polygon {_pairs(poly)} against the {shape} window {_pairs(window)} "
        f"(counter-clockwise) by {title}: clip against each window edge in turn, giving each "
        "polygon edge's case and output, and the clipped polygon.",
        10,
        frozenset({kind, "sutherland-hodgman", f"{shape} window"}),
    )


def triangle_window(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """A rectangle clipped against a triangle: the rectangle is centred near the triangle's
    centroid, half as wide and tall as a third of the triangle, so its bottom edge lies below
    the triangle's base (clipped) and the centroid is inside it (something is left)."""
    s = _SCALE[difficulty]
    a, b = _origin(rng, difficulty)
    w, h = rng.randrange(6, 10) * s, rng.randrange(5, 9) * s
    p = rng.randrange(1, w)  # the apex over the base, strictly between its ends
    window = (a, b, a + w, b, a + p, b + h)
    cx, cy = a + (w + p) // 3, b + h // 3
    hw, hh = w // 3 + 1, h // 3 + 1
    poly = (cx - hw, cy - hh, cx + hw, cy - hh, cx + hw, cy + hh, cx - hw, cy + hh)
    return _sutherland_hodgman(kind, "triangular", poly, window)


def hexagon_window(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """A rectangle clipped against a hexagon: the rectangle holds the hexagon's centre and
    reaches past its right and top, so it crosses more than one window edge."""
    s = _SCALE[difficulty]
    cx, cy = _origin(rng, difficulty)
    cx, cy = cx + 6 * s, cy + 6 * s
    r, h = 2 * rng.randrange(2, 4) * s, rng.randrange(3, 6) * s
    window = (cx + r, cy, cx + r // 2, cy + h, cx - r // 2, cy + h,
              cx - r, cy, cx - r // 2, cy - h, cx + r // 2, cy - h)  # fmt: skip
    left, below = rng.randrange(0, r // 2 + 1), rng.randrange(0, h // 2 + 1)
    right, above = cx + r + rng.randrange(1, 3) * s, cy + h // 2 + rng.randrange(1, h + 1)
    poly = (cx - left, cy - below, right, cy - below, right, above, cx - left, above)
    return _sutherland_hodgman(kind, "hexagonal", poly, window)


def touching(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """Weiler-Atherton where the polygons only touch somewhere: a triangle with a vertex on
    the clip rectangle's left edge (its two edges from there both run into the window), or a
    triangle with an edge along the rectangle's bottom edge (from outside the window)."""
    s = _SCALE[difficulty]
    x0, y0 = _origin(rng, difficulty)
    x1, y1 = x0 + rng.randrange(6, 9) * s, y0 + rng.randrange(4, 7) * s
    clip = (x0, y0, x1, y0, x1, y1, x0, y1)
    if rng.randrange(2):  # a vertex on the left edge, the triangle reaching right and down
        ym = rng.randrange(y0 + 1, y1)
        poly = (x0, ym, rng.randrange(x0 + 1, x1), y0 - s, x1 + s, rng.randrange(y0 + 1, y1 + 1))
        how = "a vertex on the clip polygon's edge"
    else:  # an edge along the bottom edge, from outside the window to inside it
        xb = rng.randrange(x0 + 1, x1)
        poly = (x0 - 2 * s, y0, xb, y0, xb, rng.randrange(y0 + 1, y1 + s))
        how = "an edge along the clip polygon's edge"
    title = method("clip", "weiler-atherton").title
    argv = ("clip", "polygon", *map(str, poly), "--window-vertices", *map(str, clip))
    return PracticeQuestion(
        "clip",
        (*argv, "--method", "weiler-atherton"),
        f"Clip the polygon {_pairs(poly)} against the clip polygon {_pairs(clip)} by {title}. "
        f"The polygons touch ({how}): give both vertex lists with each inserted point labelled "
        "in, out or touch, the walks and the output.",
        10,
        frozenset({kind, "weiler-atherton", how}),
    )


def edge_stop(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """Midpoint subdivision stopping where a midpoint lands on the window's edge: the line
    runs from as far left of the window's left edge as its inside end is right of it, so the
    first midpoint is on that edge."""
    s = _SCALE[difficulty]
    x0, y0 = _origin(rng, difficulty)
    x1, y1 = x0 + rng.randrange(6, 9) * 2 * s, y0 + rng.randrange(4, 7) * 2 * s
    d = rng.randrange(1, x1 - x0)
    ya, yb = rng.randrange(y0, y1 + 1), rng.randrange(y0, y1 + 1)
    ends = (x0 - d, ya, x0 + d, yb)
    title = method("clip", "midpoint-subdivision").title
    return PracticeQuestion(
        "clip",
        (
            "clip",
            "line",
            *map(str, ends),
            "--window",
            *map(str, (x0, y0, x1, y1)),
            "--method",
            "midpoint-subdivision",
            "--stop",
            "edge",
        ),
        f"Clip the line ({ends[0]}, {ends[1]})-({ends[2]}, {ends[3]}) against the window "
        f"({x0}, {y0})-({x1}, {y1}) by {title}, stopping where a midpoint lands on the window's "
        "edge: give each piece's codes, their AND, the action and the midpoint.",
        8,
        frozenset({kind, "midpoint-subdivision"}),
    )


_FONTS = ((96, 32, 5, 7), (128, 0, 8, 8), (256, 0, 8, 16), (96, 32, 8, 8), (95, 32, 7, 9))
"""Fonts as the papers give them: (glyphs, first code, width, height)."""
_BASES = (0, 256, 1024, 4096, 0x2000)


def font_table(rng: random.Random, difficulty: str, kind: str, char: str) -> PracticeQuestion:
    """The address of one glyph in a font table stored glyph after glyph from a base address
    (given in hexadecimal when hard)."""
    count, first, w, h = rng.choice(_FONTS)
    base = rng.choice(_BASES)
    written = f"0x{base:X}" if difficulty == "hard" else str(base)
    argv: tuple[str, ...] = ("char", "storage", str(count), str(w), str(h))
    argv += ("--char", char, "--first", str(first), "--base", written)
    return PracticeQuestion(
        "characters",
        argv,
        f"A bitmap font of {count} glyphs of {w} x {h} pixels, each row stored in whole bytes, "
        f"is stored glyph after glyph from address {written}, its first glyph the character of "
        f"code {first}. How many bytes does a glyph take and the whole font, and at which "
        f"address does the glyph of '{char}' (code {ord(char)}) start?",
        6,
        frozenset({kind}),
    )


def glyph_bytes(rng: random.Random, difficulty: str, kind: str, char: str) -> PracticeQuestion:
    """A glyph packed into bytes row by row, its leftmost pixel the most significant bit (the
    usual font) or, half the time beyond the easy questions, the least."""
    order = "msb" if difficulty == "easy" else rng.choice(("msb", "lsb"))
    where = "most" if order == "msb" else "least"
    return PracticeQuestion(
        "characters",
        ("char", "bitmap", char, "--bit-order", order),
        f"Store the 5 x 7 bitmap of the character {char} row by row in bytes, top row first, "
        f"each row padded with 0 to a whole byte and its leftmost pixel the {where} "
        "significant bit: give each row's byte in binary, hexadecimal and decimal.",
        6,
        frozenset({kind, f"bit order {order}"}),
    )
