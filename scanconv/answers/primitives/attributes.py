"""The worked answers of line attributes: a dashed or dotted line from a pixel mask, and a
thick line by pixel replication or by a rectangular brush, each step of Bresenham's centre
line with what the attribute does there (:mod:`scanconv.algorithms.attributes`)."""

from __future__ import annotations

from collections.abc import Iterator

from ...algorithms import attributes as at
from ...algorithms.lines import orient
from ...core.checks import check_integer
from ...core.ideal import IdealLine
from ...core.numeric import Number, fmt_pixel
from ...core.records import (
    Pixel,
    PixelFigure,
    Plot,
    Quantity,
    Solution,
    Step,
    Walk,
    heading,
    rule,
    worked,
)

_GIVEN_KEYS = ("x1", "y1", "x2", "y2")


def _ends(x1: Number, y1: Number, x2: Number, y2: Number) -> tuple[int, int, int, int]:
    a, b, c, d = (
        check_integer(v, k, param=k) for v, k in zip((x1, y1, x2, y2), _GIVEN_KEYS, strict=True)
    )
    return a, b, c, d


def _given(ends: tuple[int, int, int, int]) -> list[Quantity]:
    x1, y1, x2, y2 = ends
    return [
        worked("P1", (x1, y1), f"P_1 = ({x1}, {y1})"),
        worked("P2", (x2, y2), f"P_2 = ({x2}, {y2})"),
    ]


def _bbox(pixels: list[Pixel]) -> tuple[int, int, int, int]:
    xs, ys = [p[0] for p in pixels], [p[1] for p in pixels]
    return min(xs), min(ys), max(xs), max(ys)


def _thick_bbox(
    ends: tuple[int, int, int, int], span: range, brush: bool, steep: bool
) -> tuple[int, int, int, int]:
    """The bounding box of a thick line's pixels, from its ends alone: the centre line keeps
    within its ends' box and reaches both, and each of its pixels is widened by the same
    offsets (across the minor axis, or both axes for a brush).

    >>> _thick_bbox((0, 0, 4, 1), range(-1, 2), False, False)
    (0, -1, 4, 2)
    >>> _thick_bbox((0, 0, 1, 4), range(0, 2), True, True)
    (0, 0, 2, 5)
    """
    lo, hi = span[0], span[-1]
    wide_x, wide_y = brush or steep, brush or not steep
    x1, y1, x2, y2 = ends
    return (
        min(x1, x2) + (lo if wide_x else 0),
        min(y1, y2) + (lo if wide_y else 0),
        max(x1, x2) + (hi if wide_x else 0),
        max(y1, y2) + (hi if wide_y else 0),
    )


def line_style_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, mask: str, *, bits: str = "msb", repeat: int = 1
) -> Solution:
    """A styled line: Bresenham's pixels, each drawn when its mask bit is 1.

    >>> sol = line_style_solution(0, 0, 7, 2, "110")
    >>> list(sol.pixels())
    [(0, 0), (1, 0), (3, 1), (4, 1), (6, 2), (7, 2)]
    """
    ends = _ends(x1, y1, x2, y2)
    m = at.parse_mask(mask, bits, repeat)
    steps = list(at.styled(*ends, m))
    drawn = [s.pixel for s in steps if s.extra[1]]
    skipped = tuple(s.pixel for s in steps if not s.extra[1])
    n = len(m.bits)
    shown = "".join(map(str, m.bits))
    written = shown if bits == "msb" else shown[::-1]
    hex_digits = -(-n // 4)
    as_hex = f"0x{int(written, 2):0{hex_digits}X}"
    first, last = (n - 1, 0) if bits == "msb" else (0, n - 1)
    written_q = (
        worked(
            "written",
            written,
            f"\\text{{mask as written}} = {written} = {as_hex} "
            f"\\ (\\text{{bit {n - 1} on the left, bit 0 on the right}})",
        ),
    )
    derived = [
        worked(
            "mask",
            shown,
            f"\\text{{read {bits} first (bit {first} to bit {last}): in the order applied}} = {shown}",
        ),
        rule(
            "bit",
            f"\\text{{pixel }} k \\text{{ uses bit }} \\lfloor k / {m.repeat} \\rfloor \\bmod {n}",
        ),
        worked("drawn", len(drawn), f"\\text{{drawn: }} {len(drawn)} \\text{{ of }} {len(steps)}"),
    ]
    pixels = drawn

    def rows() -> Iterator[Step]:
        for s in steps:
            yield s._replace(extra=(*s.extra, "draw" if s.extra[1] else "skip"))

    box = _bbox([s.pixel for s in steps])
    return Solution(
        primitive="line",
        algorithm="style",
        title=f"Line style {written} (read {bits} first, x{m.repeat}): ({ends[0]}, {ends[1]}) to ({ends[2]}, {ends[3]})",
        given=(*_given(ends), *written_q),
        derived=tuple(derived),
        notes=(
            f"Bits read {bits} first (msb: as written; lsb: OpenGL's glLineStipple, bit 0 "
            f"first), each bit for {m.repeat} pixel(s); the centre line is Bresenham's, from "
            "the end with the smaller major coordinate.",
            "bit: the bit's place in the order applied (0 first); value: that bit.",
        ),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("pixel", "(x_k, y_k)"),
                heading("bit_index", r"\text{bit}"),
                heading("bit", r"\text{value}"),
                heading("action", r"\text{action}"),
            ),
            extra_keys=("bit_index", "bit", "action"),
            steps=rows,
        ),
        plot=Plot(
            pixels=lambda: iter(pixels),
            bbox=box,
            marks=skipped,
            marks_label="skipped pixel",
            ideal=(IdealLine(*ends),),
        ),
        data=dict(mask=list(m.bits), repeat=m.repeat, bits=bits),
    )


def thick_line_solution(
    x1: Number, y1: Number, x2: Number, y2: Number, width: int, *, brush: bool = False
) -> Solution:
    """A thick line by pixel replication across the minor axis, or by a square brush.

    >>> sol = thick_line_solution(0, 0, 4, 1, 3)
    >>> [len(s.extra[0].split("), (")) for s in sol.steps()]
    [3, 3, 3, 3, 3]
    """
    ends = _ends(x1, y1, x2, y2)

    def steps() -> Iterator[Step]:  # again for each use: a long line is never held
        return at.thick(*ends, width, brush)

    def pixels() -> Iterator[Pixel]:
        return (p for s in steps() for p in s.extra[0])

    count = sum(len(s.extra[0]) for s in steps())
    steep = orient(*ends).steep
    if brush:
        how = f"a {width} x {width} square brush around each pixel"
    else:
        axis = "x" if steep else "y"
        how = f"{width} pixels across {axis} (the minor axis) at each pixel"
    span = at.thick_offsets(width)
    derived = [
        rule("how", f"\\text{{{how}}}"),
        rule("offsets", f"\\text{{offsets }} {span[0]} \\ldots {span[-1]}"),
        worked("pixels", count, f"\\text{{pixels: }} {count}"),
    ]

    def rows() -> Iterator[Step]:
        for s in steps():
            added = ", ".join(fmt_pixel(p) for p in s.extra[0]) or "-"
            yield s._replace(extra=(added,))

    bbox = _thick_bbox(ends, span, brush, steep)
    figures: tuple[PixelFigure, ...] = ()
    if count <= 4000:
        centre = tuple(s.pixel for s in steps())
        figures = (PixelFigure(tuple(pixels()), centre, bbox, "# = drawn, @ = centre line"),)
    return Solution(
        primitive="line",
        algorithm="brush" if brush else "replication",
        title=f"Thick line, width {width} ({'brush' if brush else 'replication'}): "
        f"({ends[0]}, {ends[1]}) to ({ends[2]}, {ends[3]})",
        given=(*_given(ends), worked("w", width, f"w = {width}")),
        derived=tuple(derived),
        notes=(
            "An even width puts its extra pixel above (or to the right of) the centre line; "
            "a pixel already drawn is not added again.",
            "Replication leaves a line of slope near 1 thinner than w (by a factor of "
            "cos 45 degrees); a square brush keeps it at least w wide.",
        ),
        walk=Walk(
            columns=(
                heading("k", "k", role="label"),
                heading("pixel", "(x_k, y_k)"),
                heading("added", r"\text{pixels added}"),
            ),
            extra_keys=("added",),
            steps=rows,
        ),
        plot=Plot(pixels=pixels, bbox=bbox, figures=figures, ideal=(IdealLine(*ends),)),
        data=dict(width=width, brush=brush),
    )
