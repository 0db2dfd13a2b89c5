"""Theory answers beyond the course notes, on questions the papers and textbooks ask with
numbers: clipping a polygon against a window of any convex shape (Sutherland-Hodgman), and
how a bitmap font is stored (a glyph's bytes row by row, the font table's addresses). Each
has a live example computed by scanconv; they follow :mod:`.syllabus` in ``scanconv theory
--list``."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, text_table
from .syllabus import SECTION, embed

if TYPE_CHECKING:
    from ...primitives import characters
    from ...process.clip import sutherland_hodgman
else:
    characters = lazy.module("scanconv.answers.primitives.characters")
    sutherland_hodgman = lazy.module("scanconv.answers.process.clip.sutherland_hodgman")


def convex_window() -> Solution:
    return answer(
        "sutherland-hodgman",
        "Explain Sutherland-Hodgman polygon clipping against a convex window",
        definition=(
            "Sutherland-Hodgman clips a polygon against a convex window one window edge at a "
            "time: the polygon's vertex list is clipped against the first edge's line, the "
            "result against the next edge's, and so on; what is left after the last edge is "
            "the clipped polygon."
        ),
        paragraphs=(
            "A window of any convex shape works the same way as a rectangle: take its edges "
            "C1 -> C2, C2 -> C3, ... counter-clockwise; a point P is inside an edge when "
            "$(C_2 - C_1) \\times (P - C_1) \\ge 0$ (on the window's side of the edge's line, "
            "or on it).",
            "Each polygon edge S -> P gives: in -> in, P; in -> out, the crossing I; out -> in, "
            "I and then P; out -> out, nothing. The crossing is where S + t(P - S) meets the "
            "edge's line.",
        ),
        points=(
            "The window must be convex: each edge's inside is a half-plane.",
            "A rectangle's four edges are the same rule with x or y alone.",
            "A concave polygon may come out joined by edges along the window.",
            "Weiler-Atherton clips against any polygon, concave too.",
        ),
        tables=(
            text_table(
                "The four cases of a polygon edge S -> P",
                ["S", "P", "output"],
                [
                    ("inside", "inside", "P"),
                    ("inside", "outside", "the crossing I"),
                    ("outside", "inside", "I, then P"),
                    ("outside", "outside", "nothing"),
                ],
            ),
        ),
        examples=(
            embed(
                "a square clipped against a triangle (scanconv clip polygon 0 0 4 0 4 4 0 4 "
                "--window-vertices 1 -1 6 4 1 4)",
                sutherland_hodgman.clip_polygon_window_solution(
                    [0, 0, 4, 0, 4, 4, 0, 4], [1, -1, 6, 4, 1, 4]
                ),
                plot=False,
            ),
        ),
    )


def font_storage() -> Solution:
    return answer(
        "font-storage",
        "How is a bitmap font stored? A glyph's bytes and the font table",
        definition=(
            "a bitmap font stores each glyph as its rows of pixels, top row first, each row "
            "padded with 0 to whole bytes; the glyphs are stored one after another, so a "
            "glyph's address follows from its number."
        ),
        paragraphs=(
            "A glyph of $w \\times h$ pixels takes $h \\lceil w/8 \\rceil$ bytes; a font of "
            "$n$ glyphs, $n h \\lceil w/8 \\rceil$ bytes. A row's byte reads the row as a "
            "binary number, its leftmost pixel the most significant bit (msb, the usual font) "
            "or the least (lsb).",
            "The glyph of character code $c$ in a font whose first glyph has code $f$ is glyph "
            "number $c - f$, at address base $+ (c - f) \\times$ the bytes a glyph takes.",
        ),
        points=(
            "Papers pack rows in whole bytes, by columns, or as packed bits: say which.",
            "State the bit order: msb puts the leftmost pixel in bit 7.",
            "Addresses are often given in hexadecimal: 0x1000 = 4096.",
        ),
        examples=(
            embed(
                "the 5 x 7 'L' as bytes (scanconv char bitmap L)",
                _steps_hidden(characters.bitmap_solution("L")),
                plot=False,
            ),
            embed(
                "96 glyphs of 5 x 7 from 0x1000, the first the space (scanconv char storage 96 5 "
                "7 --char A --first 32 --base 0x1000)",
                characters.font_storage_solution(96, 5, 7, char="A", first=32, base=0x1000),
            ),
        ),
    )


TOPICS = (
    Topic(
        "sutherland-hodgman",
        SECTION,
        "Explain Sutherland-Hodgman polygon clipping against a convex window",
        ("Explain Sutherland-Hodgman polygon clipping against a convex window.",),
        convex_window,
    ),
    Topic(
        "font-storage",
        SECTION,
        "How is a bitmap font stored? A glyph's bytes and the font table",
        ("How is a bitmap font stored? A glyph's bytes and the font table.",),
        font_storage,
    ),
)
"""Clipping against a convex window, and a font's bytes."""


def _steps_hidden(sol: Solution) -> Solution:
    """``sol`` with its step table left out of the text formats (its tables show the rows)."""
    return Solution(**{**sol.fields(), "walk": sol.walk._replace(shown=False)})
