"""Practice questions on the topics beyond the notes (:mod:`.practice` registers them):
dithering, inside-outside tests, clipping (Cohen-Sutherland, Liang-Barsky, Cyrus-Beck,
midpoint subdivision, Weiler-Atherton, Nicholl-Lee-Nicholl), the frame buffer, line
attributes (dashed and dotted lines, thick lines), character generation (bitmap, stroke,
storage), the midpoint line and anti-aliasing (Wu's line with either end-point convention,
area sampling, Hearn & Baker's sub-pixel supersampling) and the 3D chapter (transformations
and projections of a solid). Each topic walks its kinds as the
notes' topics do, so a few questions show every method; every question is worded with the
method's own name (:mod:`.methods`)."""

from __future__ import annotations

import random
from typing import Any

from ..algorithms import space_conventions
from ..answers.methods import method, methods_of
from . import windows
from .records import PracticeQuestion, line_question
from .visible import visible


def _image(rng: random.Random, rows: int, cols: int) -> str:
    return "; ".join(" ".join(str(rng.randrange(0, 256)) for _ in range(cols)) for _ in range(rows))


def dither(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    if kind == "halftone":
        n = {"easy": 2, "exam": rng.choice((2, 3)), "hard": rng.choice((4, 5))}[difficulty]
        return PracticeQuestion(
            "dither",
            ("halftone", str(n)),
            f"How many gray levels does a {n} x {n} halftone cell of a bilevel display give? "
            "Draw the pattern of each level (from the Bayer matrix): which pixels are on.",
            6 if n == 2 else 10,
            frozenset({kind}),
        )
    if kind == "printer":
        return _printer(rng)
    if kind == "lookup":
        return _lookup(rng, difficulty)
    rows, cols = {"easy": (2, 2), "exam": (2, 4), "hard": (4, 4)}[difficulty]
    if kind == "kernel":
        rows += 1  # the kernels reaching two rows down show their third row
    image = _image(rng, rows, cols)
    command = "floyd-steinberg" if kind == "kernel" else kind
    argv: tuple[str, ...] = ("dither", command, "--image", image, "--top", "255")
    if kind == "ordered":
        n = 4 if difficulty == "hard" else 2
        argv += ("--matrix", str(n))
        how = f"the {n} x {n} Bayer matrix"
    elif kind == "threshold":
        how = "a threshold of 128"
        argv += ("--at", "128")
    elif kind == "kernel":
        kernel = rng.choice(_KERNELS)
        argv += ("--kernel", kernel)
        how = f"error diffusion with the {_KERNEL_NAMES[kernel]} kernel"
    else:
        how = "Floyd-Steinberg error diffusion (7/16, 3/16, 5/16, 1/16)"
    return PracticeQuestion(
        "dither",
        argv,
        f"Dither the {rows} x {cols} image [{image}] (gray levels 0 to 255) to black and white "
        f"with {how}: give the table and the output.",
        6 if difficulty == "easy" else 8,
        frozenset({kind}),
    )


_KERNEL_NAMES = {
    "jarvis-judice-ninke": "Jarvis-Judice-Ninke (weights over 48)",
    "stucki": "Stucki (over 42)",
    "burkes": "Burkes (over 32)",
    "sierra": "Sierra (three rows, over 32)",
    "two-row-sierra": "two-row Sierra (over 16)",
    "sierra-lite": "Sierra Lite (2/4 right, 1/4 below left, 1/4 below)",
    "one-dimensional": "one-dimensional (all of the error to the next pixel)",
}
_KERNELS = tuple(_KERNEL_NAMES)


def _printer(rng: random.Random) -> PracticeQuestion:
    """A printer's halftone arithmetic, asked forward (dpi, lpi) or back (dpi, levels)."""
    dpi = rng.choice((300, 600, 1200, 2400))
    if rng.random() < 0.5:
        lpi = rng.choice((50, 60, 75, 100, 150))
        argv: tuple[str, ...] = ("printer", "--dpi", str(dpi), "--lpi", str(lpi))
        ask = (
            f"prints a halftone screen of {lpi} lines per inch: how many dots a side has a "
            "halftone cell, and how many gray levels does it give?"
        )
    else:
        levels = rng.choice((17, 26, 65, 101, 257))
        argv = ("printer", "--dpi", str(dpi), "--levels", str(levels))
        ask = (
            f"must print at least {levels} gray levels: what is the smallest halftone cell, and "
            "how many lines per inch does the screen have?"
        )
    return PracticeQuestion(
        "dither",
        argv,
        f"A {dpi} dpi printer {ask} (an n x n cell gives n^2 + 1 levels)",
        4,
        frozenset({"printer"}),
    )


def _lookup(rng: random.Random, difficulty: str) -> PracticeQuestion:
    """A pixel's ordered-dither threshold from its screen position."""
    n = 2 if difficulty == "easy" else 4
    count = "1" if difficulty == "hard" else "0"
    pixels = [(rng.randrange(int(count), 20), rng.randrange(int(count), 20)) for _ in range(2)]
    value = rng.randrange(0, 256)
    argv = (
        "dither", "lookup", *(str(v) for p in pixels for v in p), "--matrix", str(n),
        "--value", str(value), "--count", count,
    )  # fmt: skip
    where = " and ".join(f"({x}, {y})" for x, y in pixels)
    return PracticeQuestion(
        "dither",
        argv,
        f"With the {n} x {n} Bayer matrix tiled over the screen (positions counted from "
        f"{count}, thresholds D x 255 / {n * n}), find the threshold of the pixels at {where} "
        f"(x across, y down) and say whether a pixel of intensity {value} is on there.",
        4,
        frozenset({"lookup"}),
    )


_POLYGONS = (
    ((0, 0, 8, 0, 8, 8, 4, 3, 0, 8), "concave"),
    ((0, 0, 8, 0, 8, 6, 0, 6), "convex"),
    ((0, 0, 8, 6, 8, 0, 0, 6), "self-intersecting"),
    ((1, 1, 9, 1, 5, 9), "convex"),
)


def inside(rng: random.Random, difficulty: str, kind: int | str) -> PracticeQuestion:
    if kind == "left-bottom":
        return _on_the_boundary(rng, difficulty)
    coords, shape = _POLYGONS[int(kind)]
    count = {"easy": 1, "exam": 2, "hard": 3}[difficulty]
    points = [str(rng.randrange(0, 9)) for _ in range(2 * count)]
    rule = "both" if difficulty != "easy" else rng.choice(("even-odd", "nonzero"))
    name = (  # each rule's record words it
        "the odd-even and the nonzero winding rules"
        if rule == "both"
        else method("inside", rule).fact("practice")
    )
    pairs = ", ".join(f"({points[i]}, {points[i + 1]})" for i in range(0, len(points), 2))
    return PracticeQuestion(
        "inside",
        ("inside", *map(str, coords), "--points", *points, "--rule", rule),
        f"Is each point {pairs} inside the {shape} polygon "
        f"{', '.join(f'({coords[i]}, {coords[i + 1]})' for i in range(0, len(coords), 2))}? "
        f"Use {name}, with each edge's test.",
        6,
        frozenset({shape, rule}),
    )


def _on_the_boundary(rng: random.Random, difficulty: str) -> PracticeQuestion:
    """Points on a rectangle's edges (one on a left or bottom edge, one on a right or top
    edge) and one inside, by the left-bottom boundary rule."""
    w, h = (rng.randrange(4, 9) * {"easy": 1, "exam": 2, "hard": 3}[difficulty] for _ in "wh")
    near = rng.choice(((0, rng.randrange(1, h)), (rng.randrange(1, w), 0)))
    far = rng.choice(((w, rng.randrange(1, h)), (rng.randrange(1, w), h)))
    points = [near, far, (rng.randrange(1, w), rng.randrange(1, h))]
    rng.shuffle(points)
    coords = (0, 0, w, 0, w, h, 0, h)
    return PracticeQuestion(
        "inside",
        (
            "inside",
            *map(str, coords),
            "--points",
            *(str(v) for p in points for v in p),
            "--rule",
            "even-odd",
            "--boundary",
            "left-bottom",
        ),
        f"Is each point {_pairs(tuple(v for p in points for v in p))} inside the rectangle "
        f"{_pairs(coords)} by the odd-even rule? A point on the boundary is inside on a left "
        "or bottom edge and outside on a right or top edge (the scan-line fill's rule): give "
        "each point's crossings and verdict.",
        6,
        frozenset({"left-bottom", "rectangle"}),
    )


_CLIP_WINDOW = {"easy": (2, 2, 8, 6), "exam": (10, 10, 50, 40), "hard": (-10, -5, 30, 25)}


_SHAPED = {
    "sutherland-hodgman triangle": windows.triangle_window,
    "sutherland-hodgman hexagon": windows.hexagon_window,
    "weiler-atherton touching": windows.touching,
    "midpoint-subdivision edge stop": windows.edge_stop,
}
"""The clipping kinds against a window of any shape (:mod:`.windows`)."""


def clipping(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    if kind in _SHAPED:
        return _SHAPED[kind](rng, difficulty, kind)
    xmin, ymin, xmax, ymax = _CLIP_WINDOW[difficulty]
    span = xmax - xmin
    window = tuple(map(str, (xmin, ymin, xmax, ymax)))
    title = method("clip", kind).title
    if kind == "weiler-atherton":
        # a concave polygon with a notch through the window's top edge
        cx = (xmin + xmax) // 2
        poly = (xmin - span // 4, ymin + 1, xmax + span // 4, ymin + 1, xmax + span // 4,
                ymax + span // 3, cx, ymin + (ymax - ymin) // 2, xmin - span // 4,
                ymax + span // 3)  # fmt: skip
        argv: tuple[str, ...] = ("clip", "polygon", *map(str, poly), "--window", *window)
        return PracticeQuestion(
            "clip",
            (*argv, "--method", kind),
            f"Clip the polygon {_pairs(poly)} against the window ({xmin}, {ymin})-({xmax}, "
            f"{ymax}) by {title}: give both vertex lists, the walks and the output.",
            8,
            frozenset({kind}),
        )
    x1 = rng.randrange(xmin - span // 2, xmin)
    y1 = rng.randrange(ymin, ymax)
    if kind == "nicholl-lee-nicholl":  # P1 in an edge or a corner region, by the seed
        y1 = rng.randrange(ymin, ymax + (ymax - ymin) // 2)
    x2 = rng.randrange(xmax + 1, xmax + span // 2 + 1)
    y2 = rng.randrange(ymin - (ymax - ymin) // 2, ymax + (ymax - ymin) // 2)
    ends = (str(x1), str(y1), str(x2), str(y2))
    return PracticeQuestion(
        "clip",
        ("clip", "line", *ends, "--window", *window, "--method", kind),
        f"Clip the line ({x1}, {y1})-({x2}, {y2}) against the window ({xmin}, {ymin})-({xmax}, "
        f"{ymax}) by {title}.",
        8,
        frozenset({kind}),
    )


def _pairs(flat: tuple[int, ...]) -> str:
    return ", ".join(f"({flat[i]}, {flat[i + 1]})" for i in range(0, len(flat), 2))


_RESOLUTIONS = ((640, 480), (800, 600), (1024, 768), (1280, 1024), (1920, 1080))


def framebuffer(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    w, h = rng.choice(_RESOLUTIONS)
    bits = rng.choice((4, 8, 12, 24))
    argv: tuple[str, ...] = ("framebuffer", str(w), str(h), str(bits))
    if kind == "load":
        rate = rng.choice((10**5, 10**6, 10**7))
        argv += ("--rate", str(rate))
        ask = f"how long does loading it take at {rate:,} bits per second?"
    elif kind == "lut":
        argv += ("--lut", "24")
        ask = "with a 24-bit colour look-up table, how large is the table and how many colours?"
    elif kind == "address":
        x, y = rng.randrange(w), rng.randrange(h)
        argv += ("--pixel", str(x), str(y))
        ask = (
            f"stored row by row from the top-left (from 0, at address 0), at which byte is pixel "
            f"({x}, {y})?"
        )
    elif kind == "retrace":
        argv += ("--refresh", "60", "--hretrace", "5e-6", "--vretrace", "5e-4")
        ask = (
            "at 60 Hz non-interlaced, with a horizontal retrace of 5 us and a vertical retrace of "
            "500 us, what share of the refresh time is spent in retrace, and how long does a scan "
            "line get?"
        )
    else:
        interlaced = kind == "interlaced"
        argv += ("--refresh", "60", *(("--interlaced",) if interlaced else ()))
        ask = f"at 60 Hz{' interlaced' if interlaced else ''}, how long does each pixel get?"
    return PracticeQuestion(
        "framebuffer",
        argv,
        f"A raster system has a {w} x {h} frame buffer of {bits} bits per pixel: what is its "
        f"size, and {ask}",
        4,
        frozenset({kind}),
    )


def attributes(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    length = {"easy": 6, "exam": 10, "hard": 16}[difficulty]
    x1, y1 = rng.randrange(0, 5), rng.randrange(0, 5)
    x2, y2 = x1 + length, y1 + rng.randrange(1, length // 2 + 1)
    ends = tuple(map(str, (x1, y1, x2, y2)))
    line = f"the line from ({x1}, {y1}) to ({x2}, {y2})"
    if kind == "mask lsb":  # the mask as written, its bit 0 applied first
        mask = rng.choice(("1100", "11000", "111000", "11110000"))
        return PracticeQuestion(
            "attributes",
            ("linestyle", *ends, "--mask", mask, "--bits", "lsb"),
            f"Draw {line} with the line mask {mask} (bit {len(mask) - 1} on the left, bit 0 "
            "on the right), applied from its least significant bit (Bresenham's line "
            "algorithm): give each pixel, its mask bit and whether it is drawn.",
            6,
            frozenset({kind, "dashed"}),
        )
    if kind in ("dashed", "dotted"):
        mask = rng.choice(("1110", "11100", "111000")) if kind == "dashed" else "10"
        return PracticeQuestion(
            "attributes",
            ("linestyle", *ends, "--mask", mask),
            f"Draw {line} {kind} with the pixel mask {mask} (Bresenham's line algorithm): "
            "give each pixel, its mask bit and whether it is drawn.",
            6,
            frozenset({kind}),
        )
    width = rng.choice((3, 5)) if difficulty != "easy" else 3
    thick = method("thickline", kind)  # its record words the question and names its flag
    how = thick.fact("practice").format(width=width)
    return PracticeQuestion(
        "attributes",
        ("thickline", *ends, "--width", str(width), *thick.fact("words").split()),
        f"Draw {line} {width} pixels thick by {how}: give the pixels each step adds.",
        6,
        frozenset({kind}),
    )


def antialias(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    length = {"easy": 3, "exam": 6, "hard": 9}[difficulty]
    x1, y1 = rng.randrange(0, 5), rng.randrange(0, 5)
    x2, y2 = x1 + length, y1 + rng.randrange(1, length)
    if rng.random() < 0.5:  # steep half the time
        x2, y2 = x1 + (y2 - y1), y1 + length
    name = "wu" if kind == "wu-coverage" else kind
    argv: tuple[str, ...] = ("antialias", "line", str(x1), str(y1), str(x2), str(y2))
    argv += ("--method", name, *(("--ends", "coverage") if kind == "wu-coverage" else ()))
    record = method("antialias", name)  # its record words the question
    how = record.fact("practice").format(title=record.title)
    if kind == "wu-coverage":
        how += ", the end points weighted by the part of their column the line covers"
    return PracticeQuestion(
        "antialias",
        argv,
        f"Draw the line from ({x1}, {y1}) to ({x2}, {y2}) {how}: give {record.fact('asks')}.",
        8 if difficulty == "easy" else 10,
        frozenset({kind, *(("steep",) if y2 - y1 > x2 - x1 else ())}),
    )


_GLYPHS = "AEFHLTXZ"


def characters(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    ch = rng.choice(_GLYPHS)
    scale = {"easy": 1, "exam": 2, "hard": 3}[difficulty]
    if kind == "font table":
        return windows.font_table(rng, difficulty, kind, ch)
    if kind == "glyph bytes":
        return windows.glyph_bytes(rng, difficulty, kind, ch)
    if kind == "storage":
        count = rng.choice((96, 128, 256))
        w, h = rng.choice(((5, 7), (7, 9), (8, 8), (9, 14)))
        return PracticeQuestion(
            "characters",
            ("char", "storage", str(count), str(w), str(h)),
            f"A bitmap font holds {count} characters of {w} x {h} pixels, each row stored in "
            "whole bytes: how many bytes does a character need, and the whole font?",
            4,
            frozenset({kind}),
        )
    x, y = rng.randrange(0, 6), rng.randrange(0, 6)
    if kind == "bitmap":
        return PracticeQuestion(
            "characters",
            (
                "char",
                "bitmap",
                ch,
                "--at",
                str(x),
                str(y),
                *(("--scale", str(scale)) if scale > 1 else ()),
            ),
            f"Draw the character {ch} from its 5 x 7 bitmap with its bottom-left corner at "
            f"({x}, {y}){f', scaled by {scale}' if scale > 1 else ''}: give the pixels of each set bit.",
            6,
            frozenset({kind}),
        )
    return PracticeQuestion(
        "characters",
        ("char", "stroke", ch, "--at", str(x), str(y), "--scale", str(scale + 1)),
        f"Draw the stroke character {ch} at ({x}, {y}), scaled by {scale + 1}, each stroke by "
        "Bresenham's line algorithm: give each stroke's end points and pixels.",
        6,
        frozenset({kind}),
    )


def midpoint_line(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """``kind``: ``octant 2, tie`` (a tie: d = 0 at some step)."""
    q = line_question(rng, difficulty, (int(kind.split()[1].rstrip(",")), kind.endswith("tie")))
    algo = q.argv.index("--algo") + 1
    x1, y1, x2, y2 = q.argv[1:5]
    return PracticeQuestion(
        "midpoint-line",
        (*q.argv[:algo], "midpoint"),
        f"Scan-convert the line from ({x1}, {y1}) to ({x2}, {y2}) with the midpoint line "
        "algorithm (d = F(M) at the midpoint): give d, the pixel chosen and the next d at "
        "each step.",
        q.marks,
        (q.features - {"dda", "bresenham"}) | {"midpoint", kind},
    )


def line_methods(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """``kind``: a line method whose record words a practice question (:data:`LINE_METHODS`),
    in an octant drawn at random."""
    q = line_question(rng, difficulty, (rng.randrange(1, 9), False), algo=kind)
    return q._replace(topic="line-methods")


LINE_METHODS = [n for n in methods_of("line") if method("line", n).practice]
"""The line methods the ``line-methods`` topic draws: every line record with a practice
wording (a new method's record that names one is drawn with no change here)."""


_AXES_3D = ((1, 1, 1), (0, 1, 1), (1, 0, 1), (1, 1, 0), (1, 2, 2), (2, 1, 2))
_SOLIDS_3D = ("unit-cube", "pyramid", "tetrahedron")


def space3d(rng: random.Random, difficulty: str, kind: str) -> PracticeQuestion:
    """A 3D question: a transformation of a solid, or a projection of one."""
    solid = "unit-cube" if difficulty == "easy" else rng.choice(_SOLIDS_3D)
    what = {"unit-cube": "the unit cube", "pyramid": "the square pyramid"}.get(
        solid, "the tetrahedron"
    )
    angle = rng.choice((30, 45, 60, 90) if difficulty != "hard" else (15, 30, 45, 120))
    if kind == "rotate-axis":
        p1 = (0, 0, 0) if difficulty == "easy" else tuple(rng.randrange(0, 3) for _ in range(3))
        v = rng.choice(_AXES_3D)
        p2 = tuple(a + b for a, b in zip(p1, v, strict=True))
        words = ("--rotate-axis", *map(str, (*p1, *p2)), str(angle))
        how = f"rotate {what} by {angle}° about the axis through {p1} and {p2}"
        marks = 14
    elif kind == "fixed-point":
        k, c = rng.choice((2, 3)), tuple(rng.randrange(0, 3) for _ in range(3))
        words = ("--scale", str(k), "--about", *map(str, c), "--rotate-z", str(angle))
        how = f"scale {what} by {k} about {c}, then rotate it by {angle}° about the z axis"
        marks = 8
    elif kind == "reflect-plane":
        n = rng.choice(((1, 1, 1), (1, 0, 1), (0, 1, 1)))
        d = -rng.randrange(1, 4)
        words = ("--reflect", "plane", *map(str, (*n, d)))
        plane = " + ".join(v for c, v in zip(n, "xyz", strict=True) if c)
        how = f"reflect {what} about the plane {plane} - {-d} = 0"
        marks = 8
    else:  # a projection: the kinds of the 3d method records
        return _projection_3d(rng, difficulty, kind, solid, what)
    return PracticeQuestion(
        "3d",
        ("3d", "transform", "--solid", solid, *words),
        f"In homogeneous coordinates, {how}: give each matrix, the composite and the vertices "
        "after.",
        marks,
        frozenset({kind}),
    )


def _projection_3d(
    rng: random.Random, difficulty: str, kind: str, solid: str, what: str
) -> PracticeQuestion:
    """A projection question: its options are those the kind's builder reads (its method
    record's), so a perspective asks for d and the vanishing points."""
    from ..answers.space.project import projection_question  # the 3d answers: only here

    record = method("3d", kind)
    asked = projection_question(kind, space_conventions.resolve(None, {}), 1)  # nothing given
    built = record.load("generator")(asked)
    argv: tuple[str, ...] = ("--perspective" if built.vanishing else "--parallel", kind)
    how = f"the {record.title} of {what}"
    marks = 8
    if built.vanishing:
        d = rng.choice((2, 4, 5, 10))
        argv += ("--d", str(d), "--cop", "minus-d")
        how += f" onto z = 0 with the centre of projection at (0, 0, -{d})"
        marks = 14 if difficulty != "easy" else 8
    if "angle" in built.reads:
        phi = rng.choice((30, 45, 60) if built.vanishing else (30, 45))
        argv += ("--angle", str(phi))
        how += (
            f", the solid first turned by {phi}° about y"
            if built.vanishing
            else f" with a receding angle of {phi}°"
        )
    if built.vanishing:
        how += "; find the vanishing points"
    return PracticeQuestion(
        "3d",
        ("3d", "project", "--solid", solid, *argv),
        f"Find {how}: give the projection matrix and the projected vertices, and draw it.",
        marks,
        frozenset({kind}),
    )


KINDS: dict[str, list[Any]] = {
    "dither": [
        "ordered",
        "floyd-steinberg",
        "threshold",
        "halftone",
        "kernel",
        "lookup",
        "printer",
    ],
    "inside": [0, 1, 2, 3, "left-bottom"],
    "clip": [
        "cohen-sutherland",
        "liang-barsky",
        "cyrus-beck",
        "midpoint-subdivision",
        "weiler-atherton",
        "nicholl-lee-nicholl",
        "sutherland-hodgman triangle",
        "weiler-atherton touching",
        "sutherland-hodgman hexagon",
        "midpoint-subdivision edge stop",
    ],
    "framebuffer": ["load", "lut", "refresh", "interlaced", "address", "retrace"],
    "attributes": ["dashed", "replication", "dotted", "brush", "mask lsb"],
    "characters": ["bitmap", "stroke", "storage", "font table", "glyph bytes"],
    "antialias": ["wu", "area", "subpixel", "wu-coverage"],
    "line-methods": LINE_METHODS,
    "midpoint-line": [
        f"octant {o}{', tie' if tie else ''}"
        for o, tie in (
            (1, False),
            (2, True),
            (8, False),
            (7, True),
            (3, True),
            (4, False),
            (5, True),
            (6, False),
        )
    ],  # a tie: d = 0 at some step (the tie convention decides)
    "visible": ["backface", "zbuffer", "scanline", "depth-sort", "warnock"],
    "3d": [
        "rotate-axis",
        "cavalier",
        "one-point",
        "fixed-point",
        "cabinet",
        "isometric",
        "reflect-plane",
        "two-point",
    ],
}
"""Each topic's kinds, walked in a seeded rotation."""

MAKERS = {
    "dither": dither,
    "inside": inside,
    "clip": clipping,
    "framebuffer": framebuffer,
    "attributes": attributes,
    "characters": characters,
    "midpoint-line": midpoint_line,
    "antialias": antialias,
    "line-methods": line_methods,
    "visible": visible,
    "3d": space3d,
}
