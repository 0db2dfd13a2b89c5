"""Theory answers of the notes' first section: scan conversion, its need, its process, the
two kinds of technique and the raster display."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from ....core import lazy
from ....core.numeric import fmt_short
from ....core.records import Solution, Table, heading
from ._build import Example, Topic, answer, embed, text_table

if TYPE_CHECKING:
    from ...primitives import line
    from ...process import pipeline
    from ...process.antialias import sampling as antialias
else:
    antialias = lazy.module("scanconv.answers.process.antialias.sampling")
    line = lazy.module("scanconv.answers.primitives.line")
    pipeline = lazy.module("scanconv.answers.process.pipeline")

SECTION = "scan-conversion"

_PRIMITIVES = text_table(
    "Common primitives for scan conversion (the notes' table)",
    ["primitive", "purpose"],
    [
        ("Line", "the edges of objects"),
        ("Circle", "circular shapes"),
        ("Curve", "smooth shapes"),
        ("Polygon", "filled areas and shapes"),
    ],
)


def define() -> Solution:
    return answer(
        "scan-conversion",
        "Define scan conversion",
        definition=(
            "scan conversion is the process of converting geometric primitives (lines, circles, "
            "curves, polygons), described mathematically in a device-independent (world) form, "
            "into the set of discrete pixels of a raster display that best approximates them. "
            "In other words, it decides which pixels of the device are turned on, and with what "
            "intensity, to show the object."
        ),
        paragraphs=(
            "Basic idea: the line between $(x_1, y_1)$ and $(x_2, y_2)$ is continuous, but the "
            "screen is a grid of discrete pixels; scan conversion selects the pixels nearest to "
            "the line to represent it.",
        ),
        points=(
            "It converts mathematical objects into pixels.",
            "It is essential for every raster display system.",
            "Accuracy and speed are its main criteria.",
            "DDA, Bresenham and the other drawing algorithms are scan-conversion methods.",
        ),
        tables=(_PRIMITIVES,),
        examples=(
            embed(
                "the line (2, 2) to (10, 6) scan converted by Bresenham's algorithm",
                line.line_solution("bresenham", 2, 2, 10, 6),
                working=False,
            ),
        ),
    )


def need() -> Solution:
    return answer(
        "need-for-scan-conversion",
        "Explain the need for scan conversion",
        definition=(
            "scan conversion turns a mathematical description of an object into the pixel "
            "intensities a raster device can show."
        ),
        paragraphs=(
            "Why it is needed: the computer stores an object in mathematical form (end points, "
            "a centre and a radius, control points), while a raster display can only switch "
            "individual pixels on or off (or set their intensity). Something must translate the "
            "one into the other for every object drawn, and that translation is scan conversion.",
            "The example below shows the gap it bridges: the exact line gives y = 2.5, 3.5, ... "
            "between pixel rows, and scan conversion rounds each to the nearest row.",
        ),
        points=(
            "The computer stores objects in mathematical form.",
            "Display devices are raster based (pixel based).",
            "Scan conversion converts the description into pixel intensity values.",
            "It is necessary for displaying any object on the screen.",
        ),
        points_title="The need, point by point",
        examples=(
            embed(
                "the notes' line (2, 2) to (8, 5) by the basic concept, y = 2 + 0.5(x - 2)",
                line.line_solution("basic", 2, 2, 8, 5),
            ),
        ),
    )


_STAGES = (
    ("1. Geometric description", "objects defined by equations (lines, circles, ...)"),
    ("2. Geometric transformation", "world coordinates mapped to device coordinates"),
    ("3. Clipping", "only the visible part of each object is kept"),
    ("4. Scan conversion", "the object becomes pixel positions and intensities"),
    ("5. Display", "the pixels go to the frame buffer and the screen"),
)


def _pair(p: Sequence[Any]) -> str:
    return "(" + ", ".join(fmt_short(v) for v in p) + ")"


def process() -> Solution:
    line = pipeline.pipeline_line(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10))
    sol, clipped, device, rounded = line
    assert clipped is not None and device is not None and rounded is not None  # accepted
    count = sum(1 for _ in sol.pixels()) if sol.pixels else 0
    here = (
        "line (-5, 0) to (15, 10), world coordinates",
        f"window to viewport: {_pair(device[0])} to {_pair(device[1])}",
        f"clipped: {_pair(clipped[0])} to {_pair(clipped[1])}",
        f"{_pair(rounded[0])} to {_pair(rounded[1])}: {count} pixels (Bresenham)",
        "the pixels in the frame buffer (the grid below)",
    )
    stages = text_table(
        "The five stages, with the example's numbers",
        ["stage", "in the example"],
        [(s, h) for (s, _), h in zip(_STAGES, here, strict=True)],
    )
    return answer(
        "scan-conversion-process",
        "Describe the scan conversion process",
        definition=(
            "the scan conversion process is the sequence of stages that takes an object from "
            "its mathematical description to pixels on the screen."
        ),
        paragraphs=(
            "The stages, in the notes' order: (1) geometric description, the object given by "
            "equations; (2) geometric transformation, from world to device coordinates; "
            "(3) clipping, keeping only the visible portion; (4) scan conversion proper, "
            "producing the pixel positions and intensity values; (5) display, sending the "
            "pixels to the frame buffer for visualisation.",
            "scanconv runs the example below end to end (scanconv pipeline line -5 0 15 10 "
            "--window 0 0 10 10 --viewport 0 0 20 10). It clips against the window in world "
            "coordinates before mapping to the viewport: clipping before or after the "
            "window-to-viewport mapping keeps the same part of the line, because the mapping "
            "sends the window onto the viewport.",
        ),
        tables=(stages,),
        examples=(
            Example(
                notes=("Example: the whole process for one line; its pixels are plotted below.",),
                plot=sol,
            ),
        ),
    )


def techniques() -> Solution:
    dda = line.line_solution("dda", 2, 2, 10, 6)
    area = antialias.antialias_solution("line", [2, 2, 10, 6], method="area")
    cover: dict[int, list[str]] = {}
    for row in area.tables[0].rows():
        (i, j), value = row[0], row[1]
        cover.setdefault(i, []).append(f"y={j}: {fmt_short(value)}")
    dda_y = {x: y for x, y in dda.pixels()} if dda.pixels else {}
    rows = [(x, dda_y[x], "; ".join(cover.get(x, []))) for x in sorted(dda_y)]
    side = Table(
        "DDA row beside the area-sampled column, for each x",
        (
            heading("x", "x"),
            heading("dda", r"\text{DDA: } y"),
            heading("reason", r"\text{area sampling: coverage } I \text{ of each pixel}"),
        ),
        lambda: rows,
    )
    kinds = text_table(
        "The two kinds (the notes' classification)",
        ["technique", "based on", "examples"],
        [
            ("Analytical (mathematical)", "mathematical calculations", "DDA, Bresenham"),
            ("Geometric (sampling)", "geometric considerations", "uniform, area sampling"),
        ],
    )
    return answer(
        "techniques",
        "Explain analytical and geometric techniques",
        definition=(
            "scan-conversion techniques are of two kinds. Analytical (mathematical) techniques "
            "compute the pixels from the primitive's equation, step by step (DDA, Bresenham's "
            "algorithm). Geometric (sampling) techniques decide each pixel from the geometry "
            "of the shape over the pixel grid, by sampling it (uniform sampling, area sampling)."
        ),
        paragraphs=(
            "An analytical method answers 'which single pixel is nearest to the line in this "
            "column?' and turns it fully on. A geometric method asks 'how much of this pixel "
            "does the shape cover?' (area sampling) or 'which sample points fall inside?' "
            "(uniform sampling), and can give partial intensities, which smooths jagged edges.",
            "Example: the line (2, 2) to (10, 6). The DDA plots one pixel per column; unweighted "
            "area sampling of the line one pixel wide spreads each column's coverage (summing "
            "to 1) over the pixels it crosses (scanconv antialias line 2 2 10 6 --method area).",
        ),
        tables=(kinds, side),
        examples=(Example(plot=dda),),
    )


def _addressing(top_left: bool, pixel: tuple[int, int]) -> Table:
    x0, y0 = pixel
    rows = []
    for row in range(5):
        y = row if top_left else 4 - row
        cells = tuple("#" if (x, y) == (x0, y0) else "." for x in range(5))
        rows.append((y, *cells))
    origin = "top-left, y down (screen)" if top_left else "bottom-left, y up (the notes' grid)"
    return Table(
        f"5 x 5 pixel grid, origin {origin}",
        (heading("y", "y"), *(heading(f"point_{x}", f"x = {x}") for x in range(5))),
        lambda: rows,
    )


def raster() -> Solution:
    return answer(
        "raster-display",
        "What is raster display? Explain",
        definition=(
            "a raster display divides the screen into a grid of small picture elements, the "
            "pixels, arranged in rows (scan lines) and columns. Each pixel has a position "
            "(x, y) and an intensity (or colour), held in the frame buffer, and the screen "
            "is refreshed from it row by row."
        ),
        paragraphs=(
            "Pixel intensity stands for brightness or colour. Because a picture exists only as "
            "the pixels' values, every object must be scan converted before it can be shown.",
            "Pixel addressing: the notes draw the 5 x 5 grid with the origin at the bottom "
            "left (x to the right, y up), and then give screen addressing, where the top-left "
            "corner is (0, 0), x increases to the right and y increases downwards. The same "
            "pixel has two addresses: the pixel (3, 1) of the y-up grid is (3, 3) on the "
            "screen, since $y_{screen} = (N - 1) - y = 4 - 1 = 3$ for N = 5 rows.",
        ),
        points=(
            "The screen is divided into small picture elements called pixels.",
            "Each pixel has a position (x, y) and an intensity (colour).",
            "Pixel intensity represents brightness or colour.",
            "The frame buffer stores the intensity of every pixel.",
        ),
        tables=(_addressing(False, (3, 1)), _addressing(True, (3, 3))),
    )


TOPICS = (
    Topic(
        "scan-conversion", SECTION, "Define scan conversion", ("Define scan conversion.",), define
    ),
    Topic(
        "need-for-scan-conversion",
        SECTION,
        "Explain the need for scan conversion",
        ("Explain the need for scan conversion.",),
        need,
    ),
    Topic(
        "scan-conversion-process",
        SECTION,
        "Describe the scan conversion process",
        ("Describe the scan conversion process.",),
        process,
    ),
    Topic(
        "techniques",
        SECTION,
        "Explain analytical and geometric techniques",
        ("Explain analytical and geometric techniques.",),
        techniques,
    ),
    Topic(
        "raster-display",
        SECTION,
        "What is raster display? Explain",
        ("What is raster display? Explain.",),
        raster,
    ),
)
