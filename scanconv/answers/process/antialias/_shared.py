"""What the anti-aliasing answers share: the intensity-to-level rule, the shaded picture and
its note, and a pixel box."""

from __future__ import annotations

from collections.abc import Sequence

from ....core.numeric import Number, fmt_short
from ....core.records import MAX_GRID_CELLS, Pixel, Quantity, ShadedMatrix, worked

SHADING = (
    "The picture draws the intensity as ink on white: shade = L - 1 - level, so a fully "
    "covered pixel is the darkest character."
)


def level_rule(levels: int) -> Quantity:
    """``level = ⌊I·7 + 1/2⌋ (L = 8)``: round half up of I (L - 1)."""
    return worked(
        "levels",
        levels,
        f"\\text{{level}} = \\lfloor I \\cdot (L - 1) + 1/2 \\rfloor = \\lfloor I \\cdot {levels - 1} "
        f"+ 1/2 \\rfloor \\quad (L = {levels})",
    )


def picture(values: dict[Pixel, int], levels: int) -> ShadedMatrix | None:
    """The shaded picture of ``pixel -> level`` (ink: shade L - 1 - level), row 0 the top."""
    if not values:
        return None
    xs, ys = [p[0] for p in values], [p[1] for p in values]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if x1 - x0 + 1 > MAX_GRID_CELLS or y1 - y0 + 1 > MAX_GRID_CELLS:
        return None
    rows = tuple(
        tuple(levels - 1 - values.get((x, y), 0) for x in range(x0, x1 + 1))
        for y in range(y1, y0 - 1, -1)
    )
    return ShadedMatrix(rows, levels, x1 - x0 + 1)


def pixel_box(pixels: Sequence[Pixel]) -> tuple[int, int, int, int]:
    if not pixels:
        return (0, 0, 0, 0)
    xs, ys = [p[0] for p in pixels], [p[1] for p in pixels]
    return min(xs), min(ys), max(xs), max(ys)


def paren_short(v: Number) -> str:
    s = fmt_short(v)
    return f"({s})" if s.startswith("-") else s
