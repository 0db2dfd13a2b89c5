"""The worked answers of character generation: a font's storage, a character drawn from its
bitmap (scaled by pixel replication), and a stroke character drawn segment by segment
(:mod:`scanconv.algorithms.characters`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms import characters as ch
from ...core.checks import check_integer
from ...core.numeric import fmt_pixel
from ...core.records import Pixel, Solution, Step, Table, heading, rule, worked
from ..image._shared import int_tex
from ..image.storage import size_text


def _bbox(pixels: Sequence[Pixel]) -> tuple[int, int, int, int]:
    xs, ys = [p[0] for p in pixels] or [0], [p[1] for p in pixels] or [0]
    return min(xs), min(ys), max(xs), max(ys)


def font_storage_solution(count: int, width: int, height: int, packing: str = "rows") -> Solution:
    """The storage of a bitmap font of ``count`` glyphs of ``width`` x ``height`` pixels.

    >>> sol = font_storage_solution(128, 5, 7)
    >>> print(sol.derived[-1].text)
    font = 128 × 56 = 7168 bits = 896 bytes
    """
    s = ch.storage(count, width, height, packing)
    how = {
        "rows": f"{height} \\text{{ rows}} \\times \\lceil {width}/8 \\rceil \\text{{ bytes}}",
        "columns": f"{width} \\text{{ columns}} \\times \\lceil {height}/8 \\rceil \\text{{ bytes}}",
        "bits": f"{width} \\times {height} \\text{{ bits, packed}}",
    }[packing]

    def rows() -> Iterator[tuple[Any, ...]]:
        for p in ch.PACKINGS:
            t = ch.storage(count, width, height, p)
            yield p, t.per_glyph, t.total_bits, size_text(Fraction(t.total_bits, 8), cell=True)

    return Solution(
        primitive="characters",
        algorithm="storage",
        title=f"Bitmap font storage: {count} glyphs of {width} x {height}",
        given=(
            worked("count", count, f"{count} \\text{{ glyphs}}"),
            worked("size", (width, height), f"{width} \\times {height} \\text{{ pixels each}}"),
        ),
        derived=(
            worked(
                "per_glyph",
                s.per_glyph,
                f"\\text{{a glyph}} = {how} = {s.per_glyph} \\text{{ bits}}",
            ),
            worked(
                "total",
                s.total_bits,
                f"\\text{{font}} = {count} \\times {s.per_glyph} = {int_tex(s.total_bits)} "
                f"\\text{{ bits}} = {size_text(Fraction(s.total_bits, 8)).replace(',', '{,}')} \\text{{ bytes}}",
            ),
        ),
        notes=(
            f"Packed by {packing}: rows padded to whole bytes is the usual bitmap font; the "
            "table gives every packing, as published answers differ.",
        ),
        tables=(
            Table(
                "Every packing",
                (
                    heading("packing", r"\text{packing}"),
                    heading("glyph", r"\text{bits a glyph}"),
                    heading("bits", r"\text{bits}"),
                    heading("bytes", r"\text{bytes}"),
                ),
                rows,
            ),
        ),
        data={"bits": s.total_bits, "per_glyph": s.per_glyph, "packing": packing},
    )


def bitmap_solution(
    char: str, *, rows: Sequence[str] | None = None, x0: int = 0, y0: int = 0, scale: int = 1
) -> Solution:
    """A character drawn from its bitmap, bottom-left corner at ``(x0, y0)``, scaled.

    >>> sol = bitmap_solution("L", scale=2)
    >>> len(list(sol.pixels())), sol.bbox
    (44, (0, 0, 9, 13))
    """
    x0, y0 = check_integer(x0, "x0", param="x0"), check_integer(y0, "y0", param="y0")
    g = ch.glyph(char, rows)
    steps = list(ch.draw_bitmap(g, x0, y0, scale))
    pixels = [p for s in steps for p in s.extra[2]]
    h, w = len(g), len(g[0])

    def table() -> Iterator[Step]:
        for s in steps:
            i, j, block = s.extra
            yield s._replace(extra=(i, j, ", ".join(fmt_pixel(p) for p in block)))

    return Solution(
        primitive="characters",
        algorithm="bitmap",
        title=f"Bitmap character {char!r} ({w} x {h}), scale {scale}, at ({x0}, {y0})",
        given=(
            worked("glyph", list(g), "\\text{glyph rows (top first): } " + " / ".join(g)),
            worked("s", scale, f"\\text{{scale}} = {scale}"),
        ),
        derived=(
            rule(
                "pixel", f"\\text{{bit (i, j)}} \\to x = {x0} + j s, \\ y = {y0} + ({h} - 1 - i) s"
            ),
            rule(
                "block", f"\\text{{each set bit fills a }} {scale} \\times {scale} \\text{{ block}}"
            ),
            worked("pixels", len(pixels), f"\\text{{pixels: }} {len(pixels)}"),
        ),
        columns=(
            heading("k", "k"),
            heading("row", "i"),
            heading("column", "j"),
            heading("pixels", r"\text{pixels}"),
        ),
        extra_keys=("row", "column", "pixels"),
        steps=table,
        pixels=lambda: iter(pixels),
        bbox=_bbox(pixels),
        notes=(
            "Rows are stored top first; the screen's y grows upward, so row i lands at "
            "y0 + (h - 1 - i) * s.",
        ),
        data={"rows": list(g), "scale": scale},
    )


def stroke_solution(
    char: str, *, x0: int = 0, y0: int = 0, scale: int = 1, algo: str = "bresenham"
) -> Solution:
    """A stroke character: each segment scaled, placed and drawn by ``algo``.

    >>> sol = stroke_solution("T")
    >>> [s.pixel for s in sol.steps()]
    [(0, 6), (2, 6)]
    """
    x0, y0 = check_integer(x0, "x0", param="x0"), check_integer(y0, "y0", param="y0")
    steps = list(ch.draw_strokes(char, x0, y0, scale, algo))
    pixels = list(dict.fromkeys(p for s in steps for p in s.extra[1]))

    def table() -> Iterator[Step]:
        for s in steps:
            (a, b, c, d), px = s.extra
            yield s._replace(
                extra=(f"({a}, {b}) to ({c}, {d})", ", ".join(fmt_pixel(p) for p in px))
            )

    return Solution(
        primitive="characters",
        algorithm="stroke",
        title=f"Stroke character {char!r}, scale {scale}, at ({x0}, {y0}), drawn by {algo}",
        given=(worked("s", scale, f"\\text{{scale}} = {scale}"),),
        derived=(
            rule("place", f"(x, y) \\to ({x0} + {scale} x, {y0} + {scale} y)"),
            worked("pixels", len(pixels), f"\\text{{pixels: }} {len(pixels)}"),
        ),
        columns=(
            heading("k", "k"),
            heading("pixel", r"\text{start}"),
            heading("segment", r"\text{segment}"),
            heading("pixels", r"\text{pixels (" + algo + ")}"),
        ),
        extra_keys=("segment", "pixels"),
        steps=table,
        pixels=lambda: iter(pixels),
        bbox=_bbox(pixels),
        notes=(
            "A stroke font stores each character as line segments on a small grid; scaling "
            "multiplies the end points, so the strokes stay one pixel wide.",
        ),
        data={"segments": [list(s.extra[0]) for s in steps]},
    )
