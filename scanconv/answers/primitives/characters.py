"""The worked answers of character generation: a font's storage, a character drawn from its
bitmap (scaled by pixel replication), and a stroke character drawn segment by segment
(:mod:`scanconv.algorithms.characters`)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from typing import Any

from ...algorithms import characters as ch
from ...core.checks import InputError, check_integer
from ...core.numeric import fmt_pixel
from ...core.records import (
    Pixel,
    Plot,
    Quantity,
    Solution,
    Step,
    Table,
    Walk,
    heading,
    rule,
    worked,
)
from ...core.working import tex_text
from ..image._shared import int_tex
from ..image.storage import size_text


def _bbox(pixels: Sequence[Pixel]) -> tuple[int, int, int, int]:
    xs, ys = [p[0] for p in pixels] or [0], [p[1] for p in pixels] or [0]
    return min(xs), min(ys), max(xs), max(ys)


def _address(bits: int) -> str:
    """A bit offset as a byte address: ``520 (0x208)``, or with its bit where a glyph does
    not start on a byte (packed bits)."""
    byte, bit = divmod(bits, 8)
    return f"{byte} (0x{byte:X})" + (f", bit {bit}" if bit else "")


def _char_name(code: int) -> str:
    """A character as a font table names it: ``'A'``, or ``code 127`` where it is not a
    printable ASCII character."""
    return f"'{chr(code)}'" if 32 <= code < 127 else f"code {code}"


def font_table(count: int, per_glyph: int, first: int, base: int, char: str | None) -> Table:
    """The font table: each glyph's number, character, and start address, one after another
    from ``base`` (the first three, the one asked for, and the last)."""
    shown = sorted({*range(min(count, 3)), count - 1} | ({ord(char) - first} if char else set()))

    def rows() -> Iterator[tuple[Any, ...]]:
        for i in shown:
            name = _char_name(first + i)
            yield (i, name, f"{base} + {i}*{per_glyph}/8", _address(base * 8 + i * per_glyph))

    return Table(
        "The font table: each glyph stored after the one before",
        (
            heading("glyph", r"\text{glyph}", role="label"),
            heading("char", r"\text{character}", role="given"),
            heading("work", r"\text{start}", role="working"),
            heading("address", r"\text{byte address}"),
        ),
        rows,
    )


def _glyph_quantity(
    char: str, count: int, per_glyph: int, first: int, base: int
) -> tuple[Quantity, ...]:
    index = ord(char) - first
    if not 0 <= index < count:
        raise InputError(
            f"{char!r} (code {ord(char)}) is not among the font's {count} glyphs from code {first}",
            "char",
        )
    at = base * 8 + index * per_glyph
    return (
        worked(
            "index",
            index,
            f"\\text{{glyph of {tex_text(_char_name(ord(char)))}}} = {ord(char)} - {first} = {index}",
        ),
        worked(
            "address",
            at // 8,
            f"\\text{{its address}} = {base} + {index} \\times {per_glyph}/8 = "
            + _address(at).replace(" (", " \\ (").replace("bit", "\\text{bit}"),
        ),
    )


def font_storage_solution(
    count: int,
    width: int,
    height: int,
    packing: str = "rows",
    *,
    char: str | None = None,
    first: int = 0,
    base: int = 0,
) -> Solution:
    """The storage of a bitmap font of ``count`` glyphs of ``width`` x ``height`` pixels, and
    its font table: glyph ``i`` (character code ``first + i``) starts at ``base`` plus ``i``
    glyphs.

    >>> sol = font_storage_solution(128, 5, 7)
    >>> print(sol.derived[1].text)
    font = 128 × 56 = 7168 bits = 896 bytes
    >>> print(font_storage_solution(128, 8, 8, char="A", base=4096).derived[-1].text)
    its address = 4096 + 65 × 64/8 = 4616 (0x1208)
    """
    s = ch.storage(count, width, height, packing)
    for v, name in ((first, "first"), (base, "base")):
        if v < 0:
            raise InputError(f"the {name} must be at least 0, got {v}", name)
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
            *(() if char is None else _glyph_quantity(char, count, s.per_glyph, first, base)),
        ),
        notes=(
            f"Packed by {packing}: rows padded to whole bytes is the usual bitmap font; the "
            "table gives every packing, as published answers differ.",
            f"The font table: the glyphs one after another from address {base}, glyph i the "
            f"character of code {first} + i (a glyph of {s.per_glyph} bits takes "
            f"{Fraction(s.per_glyph, 8)} bytes).",
        ),
        walk=Walk(
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
                font_table(count, s.per_glyph, first, base, char),
            )
        ),
        data={"bits": s.total_bits, "per_glyph": s.per_glyph, "packing": packing},
    )


_BIT_ORDER_TEXT = {
    "msb": "the leftmost pixel is the most significant bit",
    "lsb": "the leftmost pixel is the least significant bit",
}


def _bytes(n: int) -> str:
    return f"{n} byte" if n == 1 else f"{n} bytes"


def bytes_table(rows: Sequence[str], bit_order: str = "msb") -> Table:
    """A glyph packed into bytes row by row: each row as written, padded with 0 to whole
    bytes, and its bytes in binary, hexadecimal and decimal."""
    packed = ch.row_bytes(rows, bit_order)

    def table() -> Iterator[tuple[Any, ...]]:
        for i, (r, packed_row) in enumerate(zip(rows, packed, strict=True)):
            values = packed_row.values
            yield (
                i,
                r,
                " ".join(f"{v:08b}" for v in values),
                " ".join(f"0x{v:02X}" for v in values),
                " ".join(str(v) for v in values),
            )

    return Table(
        f"The glyph as bytes, row by row (top first; each row padded with 0 to whole bytes, "
        f"{_BIT_ORDER_TEXT[bit_order]})",
        (
            heading("row", "i", role="label"),
            heading("pixels", r"\text{pixels}", role="given"),
            heading("bits", r"\text{byte bits}", role="working"),
            heading("hex", r"\text{hex}"),
            heading("decimal", r"\text{decimal}"),
        ),
        table,
    )


def bitmap_solution(
    char: str,
    *,
    rows: Sequence[str] | None = None,
    x0: int = 0,
    y0: int = 0,
    scale: int = 1,
    bit_order: str = "msb",
) -> Solution:
    """A character drawn from its bitmap, bottom-left corner at ``(x0, y0)``, scaled.

    >>> sol = bitmap_solution("L", scale=2)
    >>> len(list(sol.pixels())), sol.bbox
    (44, (0, 0, 9, 13))
    """
    x0, y0 = check_integer(x0, "x0", param="x0"), check_integer(y0, "y0", param="y0")
    g = ch.glyph(char, rows)
    glyph_bytes = bytes_table(g, bit_order)
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
        notes=(
            "Rows are stored top first; the screen's y grows upward, so row i lands at "
            "y0 + (h - 1 - i) * s.",
            f"Stored row by row in whole bytes ({len(g)} rows x {_bytes(-(-w // 8))} = "
            f"{_bytes(len(g) * -(-w // 8))}), each row padded with 0 on the right; bit order "
            f"{bit_order}: {_BIT_ORDER_TEXT[bit_order]}"
            + (
                " (a row reads as written: the usual bitmap font; lsb puts it in the least)."
                if bit_order == "msb"
                else " (msb, the usual bitmap font, puts it in the most)."
            ),
        ),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("row", "i"),
                heading("column", "j"),
                heading("pixels", r"\text{pixels}"),
            ),
            extra_keys=("row", "column", "pixels"),
            steps=table,
            tables=(glyph_bytes,),
        ),
        plot=Plot(pixels=lambda: iter(pixels), bbox=_bbox(pixels)),
        data={
            "rows": list(g),
            "scale": scale,
            "bytes": [list(b.values) for b in ch.row_bytes(g, bit_order)],
        },
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
        notes=(
            "A stroke font stores each character as line segments on a small grid; scaling "
            "multiplies the end points, so the strokes stay one pixel wide.",
        ),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("pixel", r"\text{start}"),
                heading("segment", r"\text{segment}"),
                heading("pixels", r"\text{pixels (" + algo + ")}"),
            ),
            extra_keys=("segment", "pixels"),
            steps=table,
        ),
        plot=Plot(pixels=lambda: iter(pixels), bbox=_bbox(pixels)),
        data={"segments": [list(s.extra[0]) for s in steps]},
    )
