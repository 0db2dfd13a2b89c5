"""Theory answers on visible-surface detection (the papers' 3D chapter, beyond the notes):
the z-buffer explained, and object-space against image-space methods. Each has a live example
computed by scanconv (``scanconv 3d``); they follow :mod:`.windows` in ``scanconv theory
--list``."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, text_table
from .syllabus import SECTION, embed

if TYPE_CHECKING:
    from ...visible import backface, zbuffer
else:
    backface = lazy.module("scanconv.answers.visible.backface")
    zbuffer = lazy.module("scanconv.answers.visible.zbuffer")

_TWO = [0, 0, 2, 5, 0, 2, 0, 5, 2, ":", 1, 1, 4, 5, 1, 0, 1, 5, 0]
"""Two triangles: A in z = 2, B in x + y + z = 6 (the z-buffer's golden example)."""


def z_buffer() -> Solution:
    return answer(
        "z-buffer",
        "Explain the z-buffer (depth-buffer) algorithm",
        definition=(
            "the z-buffer method is an image-space method that keeps, beside the frame buffer, "
            "a depth buffer holding for each pixel the depth of the nearest surface drawn there "
            "so far; a surface's pixel is written only when it is nearer than that depth."
        ),
        paragraphs=(
            "Initialise every depth to the farthest value (Hearn & Baker and Foley: 0, the back "
            "clipping plane, depths running up to z_max at the front) and every pixel to the "
            "background. "
            "Then for each polygon, for each pixel (x, y) it covers, compute its depth z; if z "
            "is nearer than depth(x, y) (with a larger z nearer: z > depth(x, y)), set "
            "depth(x, y) = z and frame(x, y) to the polygon's colour.",
            "A planar polygon $Ax + By + Cz + D = 0$ has $z = (-Ax - By - D)/C$; along a scan "
            "line $z(x + 1) = z(x) - A/C$, and down an edge, where x changes by $-1/m$, "
            "$z' = z + (A/m + B)/C$: one addition a pixel.",
        ),
        points=(
            "Polygons may come in any order: no sorting, no comparison between polygons.",
            "Memory: one depth value a pixel (often 16 to 32 bits).",
            "Equal depths: > keeps the first drawn (Hearn & Baker), >= the later (Foley).",
            "Say which z is nearer: a larger (Hearn & Baker, C) or a smaller (OpenGL).",
        ),
        advantages=(
            "Simple, and done in hardware on every graphics card.",
            "Any number of polygons, any order; handles interpenetrating surfaces.",
        ),
        limitations=(
            "A depth buffer as large as the screen.",
            "Depth resolution is finite: nearly equal depths may flicker (z-fighting).",
            "Transparency needs the surfaces sorted after all.",
        ),
        examples=(
            embed(
                "two triangles on a 5 x 5 grid (scanconv 3d zbuffer 0 0 2 5 0 2 0 5 2 : 1 1 4 5 "
                "1 0 1 5 0 --size 5)",
                zbuffer.zbuffer_solution(_TWO, size="5"),
                plot=False,
            ),
        ),
    )


def object_image_space() -> Solution:
    return answer(
        "object-image-space",
        "Differentiate object-space and image-space methods of visible-surface detection",
        definition=(
            "an object-space method compares the objects (faces, polygons) with one another in "
            "the scene's own coordinates to decide which are seen; an image-space method "
            "decides, pixel by pixel of the projected image, which surface is visible there."
        ),
        paragraphs=(
            "Back-face detection and depth sorting work in object space: back-face detection "
            "tests each face's normal against the view vector, $V \\cdot N > 0$ for a back "
            "face (Hearn & Baker), once per face, whatever the screen's size.",
            "The z-buffer, the scan-line method and Warnock's area subdivision work in image "
            "space: their work grows with the pixels (the z-buffer: every covered pixel of "
            "every polygon).",
        ),
        tables=(
            text_table(
                "Object space against image space",
                ["", "object space", "image space"],
                [
                    ("compares", "objects with objects", "depths at each pixel"),
                    ("precision", "the scene's (exact geometry)", "the screen's resolution"),
                    ("work grows with", "the objects (n^2 pairs)", "the pixels (and objects)"),
                    ("examples", "back-face, depth sort", "z-buffer, scan-line, Warnock"),
                    ("output", "visible parts, any resolution", "one image"),
                ],
            ),
        ),
        points=(
            "Depth sort mixes both: it sorts in object space and paints in image space.",
            "Back-face removal halves the work of the others on closed solids.",
        ),
        examples=(
            embed(
                "object space: the unit cube's back faces (scanconv 3d backface --solid cube)",
                backface.backface_solution(solid="cube"),
                plot=False,
            ),
        ),
    )


TOPICS = (
    Topic(
        "z-buffer",
        SECTION,
        "Explain the z-buffer (depth-buffer) algorithm",
        ("Explain the z-buffer (depth-buffer) algorithm.",),
        z_buffer,
    ),
    Topic(
        "object-image-space",
        SECTION,
        "Differentiate object-space and image-space methods of visible-surface detection",
        ("Differentiate object-space and image-space methods of visible-surface detection.",),
        object_image_space,
    ),
)
"""The z-buffer explained; object space against image space."""
